// Space cut among MPI_COMM_WORLD's processes by Zoltan (spatial_partition.hpp), built with
// -DREVSPH_MPI=ON.
#include "core/distributed/spatial_partition.hpp"

#include "core/distributed/processes.hpp"

#include <mpi.h>
#include <zoltan.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph::distributed {

namespace {

void check(int status, const char* what) {
  if (status != ZOLTAN_OK && status != ZOLTAN_WARN) {
    throw std::runtime_error(std::string("Zoltan: ") + what + " failed");
  }
}

// What Zoltan's query functions read while balance() runs: this process's particles.
struct Particles {
  int dimension = 0;
  std::span<const double> coordinates;
  std::span<const std::uint64_t> global_indices;
  std::span<const float> weights; // empty: every particle alike
};

int particle_count(void* data, int* error) {
  *error = ZOLTAN_OK;
  return static_cast<int>(static_cast<const Particles*>(data)->global_indices.size());
}

void particle_list(void* data, int, int, ZOLTAN_ID_PTR global_ids, ZOLTAN_ID_PTR local_ids, int,
                   float* weights, int* error) {
  const auto& particles = *static_cast<const Particles*>(data);
  for (std::size_t i = 0; i < particles.global_indices.size(); ++i) {
    global_ids[i] = static_cast<ZOLTAN_ID_TYPE>(particles.global_indices[i]);
    local_ids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    weights[i] = particles.weights.empty() ? 1.0F : particles.weights[i];
  }
  *error = ZOLTAN_OK;
}

int dimension_of(void* data, int* error) {
  *error = ZOLTAN_OK;
  return static_cast<const Particles*>(data)->dimension;
}

void particle_coordinates(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local_ids,
                          int dimension, double* coordinates, int* error) {
  const auto& particles = *static_cast<const Particles*>(data);
  for (int i = 0; i < count; ++i) {
    const std::size_t local = local_ids[i];
    std::copy_n(particles.coordinates.begin() + static_cast<std::ptrdiff_t>(local * dimension),
                dimension, coordinates + static_cast<std::ptrdiff_t>(i) * dimension);
  }
  *error = ZOLTAN_OK;
}

} // namespace

struct SpatialPartition::Zoltan {
  Zoltan_Struct* handle = nullptr;
  Particles particles;
  // processes_near's answer space, one entry per process, kept: it runs once per particle.
  std::vector<int> parts;
  ~Zoltan() { Zoltan_Destroy(&handle); }
};

SpatialPartition::SpatialPartition(int dimension, PartitionMethod method)
    : dimension_(dimension), zoltan_(std::make_unique<Zoltan>()) {
  static const bool initialised = [] {
    float version = 0.0F;
    int argc = 0;
    check(Zoltan_Initialize(argc, nullptr, &version), "Zoltan_Initialize");
    return true;
  }();
  (void)initialised;
  zoltan_->particles.dimension = dimension;
  zoltan_->parts.resize(static_cast<std::size_t>(process_count()));
  zoltan_->handle = Zoltan_Create(MPI_COMM_WORLD);
  if (zoltan_->handle == nullptr) {
    throw std::runtime_error("Zoltan: Zoltan_Create failed");
  }
  Zoltan_Struct* zz = zoltan_->handle;
  const auto set = [zz](const char* name, const char* value) {
    check(Zoltan_Set_Param(zz, name, value), name);
  };
  set("DEBUG_LEVEL", "0");
  set("LB_METHOD", method == PartitionMethod::coordinate_bisection ? "RCB" : "HSFC");
  set("NUM_GID_ENTRIES", "1");
  set("NUM_LID_ENTRIES", "1");
  set("OBJ_WEIGHT_DIM", "1");   // the particles' estimated work (work_estimate.hpp)
  set("IMBALANCE_TOL", "1.01"); // Zoltan's default, 1.1, would leave up to 10 % idle time
  set("RETURN_LISTS", "NONE");  // owners come from the kept cuts (balance)
  set("KEEP_CUTS", "1");        // for owner_of and processes_near
  Zoltan_Set_Num_Obj_Fn(zz, &particle_count, &zoltan_->particles);
  Zoltan_Set_Obj_List_Fn(zz, &particle_list, &zoltan_->particles);
  Zoltan_Set_Num_Geom_Fn(zz, &dimension_of, &zoltan_->particles);
  Zoltan_Set_Geom_Multi_Fn(zz, &particle_coordinates, &zoltan_->particles);
}

SpatialPartition::~SpatialPartition() = default;

std::vector<int> SpatialPartition::balance(std::span<const double> coordinates,
                                           std::span<const std::uint64_t> global_indices,
                                           std::span<const float> weights) {
  if (coordinates.size() != global_indices.size() * static_cast<std::size_t>(dimension_) ||
      (!weights.empty() && weights.size() != global_indices.size())) {
    throw std::invalid_argument("SpatialPartition::balance: coordinates, indices, weights differ");
  }
  zoltan_->particles.coordinates = coordinates;
  zoltan_->particles.global_indices = global_indices;
  zoltan_->particles.weights = weights;
  int changes = 0, gid_entries = 0, lid_entries = 0, imports = 0, exports = 0;
  ZOLTAN_ID_PTR import_gids = nullptr, import_lids = nullptr;
  ZOLTAN_ID_PTR export_gids = nullptr, export_lids = nullptr;
  int *import_procs = nullptr, *import_parts = nullptr;
  int *export_procs = nullptr, *export_parts = nullptr;
  const int status =
      Zoltan_LB_Partition(zoltan_->handle, &changes, &gid_entries, &lid_entries, &imports,
                          &import_gids, &import_lids, &import_procs, &import_parts, &exports,
                          &export_gids, &export_lids, &export_procs, &export_parts);
  Zoltan_LB_Free_Part(&import_gids, &import_lids, &import_procs, &import_parts);
  Zoltan_LB_Free_Part(&export_gids, &export_lids, &export_procs, &export_parts);
  zoltan_->particles = Particles{dimension_, {}, {}, {}};
  check(status, "Zoltan_LB_Partition");
  // The owner is the process whose region holds the point, by the kept cuts: the rule that
  // migration applies after every drift. (Zoltan's own lists may put a particle lying exactly on
  // a cut on the other side, to even the counts; measured on 3 processes.)
  std::vector<int> owners(global_indices.size());
  for (std::size_t i = 0; i < owners.size(); ++i) {
    owners[i] = owner_of(coordinates.subspan(i * static_cast<std::size_t>(dimension_),
                                             static_cast<std::size_t>(dimension_)));
  }
  return owners;
}

int SpatialPartition::owner_of(std::span<const double> point) const {
  std::array<double, 3> coordinates{};
  std::copy_n(point.begin(), dimension_, coordinates.begin());
  int process = -1;
  int part = -1;
  check(Zoltan_LB_Point_PP_Assign(zoltan_->handle, coordinates.data(), &process, &part),
        "Zoltan_LB_Point_PP_Assign");
  return process;
}

void SpatialPartition::processes_near(std::span<const double> point, double reach, int except,
                                      std::vector<int>& processes) const {
  std::array<double, 3> low{}, high{};
  for (int k = 0; k < dimension_; ++k) {
    low[static_cast<std::size_t>(k)] = point[static_cast<std::size_t>(k)] - reach;
    high[static_cast<std::size_t>(k)] = point[static_cast<std::size_t>(k)] + reach;
  }
  processes.resize(zoltan_->parts.size());
  int count = 0, part_count = 0;
  check(Zoltan_LB_Box_PP_Assign(zoltan_->handle, low[0], low[1], low[2], high[0], high[1], high[2],
                                processes.data(), &count, zoltan_->parts.data(), &part_count),
        "Zoltan_LB_Box_PP_Assign");
  processes.resize(static_cast<std::size_t>(count));
  std::erase(processes, except);
}

} // namespace revsph::distributed
