#pragma once
// Which process owns which region of space (docs/design/distributed.md, piece 6), and which
// processes need a particle as a ghost: the geometry of a distributed run, never its results (a
// pair sum is exact whichever process adds it, so the partition changes only the speed).
//
// Built with -DREVSPH_MPI=ON the regions are Zoltan's (Trilinos, from Debian's
// libtrilinos-zoltan-dev): recursive coordinate bisection, whose regions are boxes, or the
// Hilbert space-filling curve; Zoltan keeps the cuts, so a point's owner and the processes whose
// regions a box touches are answered locally. Without MPI there is one process, which owns
// everything and needs ghosts only as periodic images of its own particles
// (spatial_partition_serial.cpp, docs/periodic.md).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace revsph::distributed {

enum class PartitionMethod {
  coordinate_bisection, // Zoltan's RCB: box regions, cuts along the longest extent
  hilbert_curve,        // Zoltan's HSFC: pieces of equal count along a Hilbert curve
};

inline std::string to_string(PartitionMethod method) {
  return method == PartitionMethod::coordinate_bisection ? "coordinate_bisection" : "hilbert_curve";
}

class SpatialPartition {
public:
  explicit SpatialPartition(int dimension, PartitionMethod method);
  ~SpatialPartition();
  SpatialPartition(const SpatialPartition&) = delete;
  SpatialPartition& operator=(const SpatialPartition&) = delete;

  // Cuts space into one region per process so that each owns about the same number of the
  // particles that the processes hold now (collective), or the same total of their `weights`
  // (one per particle: their estimated work) when given. `coordinates` holds this process's
  // particles point after point (dimension values each, metres), `global_indices` their indices
  // in the run's canonical order. Returns the rank that owns each of them from now on.
  std::vector<int> balance(std::span<const double> coordinates,
                           std::span<const std::uint64_t> global_indices,
                           std::span<const float> weights = {});

  // The process whose region holds the point (after balance).
  int owner_of(std::span<const double> point) const;

  // The processes other than `except` whose regions come within `reach` of the point (every
  // coordinate within reach: a box around it, so possibly a few more than a sphere would give):
  // where a particle there is needed as a ghost. Replaces the contents of `processes`.
  void processes_near(std::span<const double> point, double reach, int except,
                      std::vector<int>& processes) const;

  int dimension() const { return dimension_; }

private:
  struct Zoltan;
  int dimension_;
  std::unique_ptr<Zoltan> zoltan_;
};

} // namespace revsph::distributed
