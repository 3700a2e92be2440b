// How Zoltan's two partitions split a real particle arrangement among the processes
// (docs/design/distributed.md, piece 6): per method, the largest process's share against the
// mean, how many ghosts the processes receive (a particle within the reach of another process's
// region, counted once per receiving process), and the time to balance. tools/bench/
// partition_ghosts.py makes the particle files from snapshots and runs this under mpiexec.
//
// Usage: mpiexec -n P partition_ghosts POSITIONS DIMENSION REACH
//   POSITIONS  raw little-endian doubles, particle after particle (DIMENSION each), in the run's
//              canonical order
//   REACH      the interaction reach in metres (support radius times cell_size_factor)
// Prints one JSON line per method (rank 0).

#include "core/distributed/processes.hpp"
#include "core/distributed/spatial_partition.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace revsph::distributed;

// This process's slice of the file: particles [rank n / P, (rank + 1) n / P).
std::vector<double> read_slice(const std::string& path, int dimension,
                               std::vector<std::uint64_t>& indices, std::uint64_t& total) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) {
    throw std::runtime_error("cannot open " + path);
  }
  const auto bytes = static_cast<std::uint64_t>(file.tellg());
  total = bytes / (sizeof(double) * static_cast<std::uint64_t>(dimension));
  const auto rank = static_cast<std::uint64_t>(process_rank());
  const auto count = static_cast<std::uint64_t>(process_count());
  const std::uint64_t first = rank * total / count;
  const std::uint64_t last = (rank + 1) * total / count;
  std::vector<double> coordinates((last - first) * static_cast<std::uint64_t>(dimension));
  file.seekg(static_cast<std::streamoff>(first * dimension * sizeof(double)));
  file.read(reinterpret_cast<char*>(coordinates.data()),
            static_cast<std::streamsize>(coordinates.size() * sizeof(double)));
  for (std::uint64_t i = first; i < last; ++i) {
    indices.push_back(i);
  }
  return coordinates;
}

void measure(PartitionMethod method, int dimension, double reach,
             const std::vector<double>& coordinates, const std::vector<std::uint64_t>& indices,
             std::uint64_t total) {
  const auto processes = static_cast<std::size_t>(process_count());
  SpatialPartition partition(dimension, method);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<int> owners = partition.balance(coordinates, indices);
  const double balance_seconds = max_over_processes(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::vector<std::int64_t> owned(processes, 0), ghosts(processes, 0);
  std::vector<int> near;
  const auto d = static_cast<std::size_t>(dimension);
  for (std::size_t i = 0; i < owners.size(); ++i) {
    ++owned[static_cast<std::size_t>(owners[i])];
    partition.processes_near({coordinates.data() + i * d, d}, reach, owners[i], near);
    for (const int receiver : near) {
      ++ghosts[static_cast<std::size_t>(receiver)];
    }
  }
  std::int64_t largest_owned = 0, ghost_total = 0, largest_ghosts = 0;
  double largest_ratio = 0.0;
  for (std::size_t p = 0; p < processes; ++p) {
    const std::int64_t owned_p = sum_over_processes(owned[p]);
    const std::int64_t ghosts_p = sum_over_processes(ghosts[p]);
    largest_owned = std::max(largest_owned, owned_p);
    largest_ghosts = std::max(largest_ghosts, ghosts_p);
    ghost_total += ghosts_p;
    largest_ratio =
        std::max(largest_ratio, static_cast<double>(ghosts_p) /
                                    static_cast<double>(std::max<std::int64_t>(owned_p, 1)));
  }
  if (process_rank() == 0) {
    const double mean = static_cast<double>(total) / static_cast<double>(processes);
    std::printf("{\"method\": \"%s\", \"processes\": %zu, \"particles\": %llu, \"dimension\": %d, "
                "\"reach\": %.6g, \"largest_share_over_mean\": %.4f, \"ghosts\": %lld, "
                "\"ghost_fraction\": %.5f, \"largest_ghosts_over_owned\": %.5f, "
                "\"largest_ghosts\": %lld, \"balance_seconds\": %.4f}\n",
                to_string(method).c_str(), processes, static_cast<unsigned long long>(total),
                dimension, reach, static_cast<double>(largest_owned) / mean,
                static_cast<long long>(ghost_total),
                static_cast<double>(ghost_total) / static_cast<double>(total), largest_ratio,
                static_cast<long long>(largest_ghosts), balance_seconds);
    std::fflush(stdout);
  }
}

} // namespace

int main(int argc, char** argv) {
  ProcessSession session(argc, argv);
  if (argc != 4) {
    if (process_rank() == 0) {
      std::cerr << "usage: mpiexec -n P partition_ghosts POSITIONS DIMENSION REACH\n";
    }
    return 2;
  }
  try {
    const int dimension = std::stoi(argv[2]);
    const double reach = std::stod(argv[3]);
    std::vector<std::uint64_t> indices;
    std::uint64_t total = 0;
    const std::vector<double> coordinates = read_slice(argv[1], dimension, indices, total);
    for (const PartitionMethod method :
         {PartitionMethod::coordinate_bisection, PartitionMethod::hilbert_curve}) {
      measure(method, dimension, reach, coordinates, indices, total);
    }
  } catch (const std::exception& error) {
    std::cerr << "partition_ghosts: " << error.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  return 0;
}
