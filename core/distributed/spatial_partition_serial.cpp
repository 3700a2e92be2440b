// One process owns all of space (spatial_partition.hpp, the build without MPI).
#include "core/distributed/spatial_partition.hpp"

namespace revsph::distributed {

struct SpatialPartition::Zoltan {};

SpatialPartition::SpatialPartition(int dimension, PartitionMethod) : dimension_(dimension) {}
SpatialPartition::~SpatialPartition() = default;

std::vector<int> SpatialPartition::balance(std::span<const double>,
                                           std::span<const std::uint64_t> global_indices,
                                           std::span<const float>) {
  return std::vector<int>(global_indices.size(), 0);
}

int SpatialPartition::owner_of(std::span<const double>) const {
  return 0;
}

void SpatialPartition::processes_near(std::span<const double>, double, int except,
                                      std::vector<int>& processes) const {
  // The one process, unless excepted: a periodic image of its own particle (ghost_plan.cpp).
  processes.clear();
  if (except != 0) {
    processes.push_back(0);
  }
}

} // namespace revsph::distributed
