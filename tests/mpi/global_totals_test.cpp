// The readings a model reports (core/global_totals.hpp) are the one-process readings on any
// number of processes: the value at the particle nearest a point, whichever process holds it,
// and, among equally near particles held by different processes, the lowest index's, as one
// process looping over the particles in index order keeps the first. CTest runs this program on
// 1, 2 and 3 processes (tests/mpi/CMakeLists.txt); built without MPI it is the one-process case.

#include "core/global_totals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using revsph::NearestParticle;
using revsph::distributed::process_count;
using revsph::distributed::process_rank;

struct Particle {
  double distance;
  double value;
};

// The holder of particle i: from the last process down, so that the nearest particle of a
// list that begins far away is often not process 0's.
bool held_here(std::size_t i) {
  const auto processes = static_cast<std::size_t>(process_count());
  return processes - 1 - i % processes == static_cast<std::size_t>(process_rank());
}

double one_process_reading(const std::vector<Particle>& particles) {
  double nearest = INFINITY, value = 0.0;
  for (const Particle& particle : particles) {
    if (particle.distance < nearest) {
      nearest = particle.distance;
      value = particle.value;
    }
  }
  return value;
}

double reading_on_processes(const std::vector<Particle>& particles) {
  NearestParticle own;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (held_here(i)) {
      own.offer(particles[i].distance, i, particles[i].value);
    }
  }
  return revsph::global_value_of_nearest(own);
}

TEST(GlobalTotals, NearestParticleIsTheOneProcessOnes) {
  const std::vector<Particle> unique{{3.0, 30.0}, {2.0, 20.0}, {0.5, 5.0}, {4.0, 40.0},
                                     {1.0, 10.0}, {0.7, 7.0},  {9.0, 90.0}};
  EXPECT_EQ(one_process_reading(unique), 5.0);
  EXPECT_EQ(reading_on_processes(unique), one_process_reading(unique));
  // Four particles at the same distance (a lattice around a probe point at t = 0): the first
  // in index order, whichever process holds each of them.
  const std::vector<Particle> ties{{2.0, 20.0}, {1.0, 11.0}, {1.0, 12.0},
                                   {1.0, 13.0}, {1.0, 14.0}, {5.0, 50.0}};
  EXPECT_EQ(one_process_reading(ties), 11.0);
  EXPECT_EQ(reading_on_processes(ties), one_process_reading(ties));
  // A process holding none of the particles (more processes than particles).
  const std::vector<Particle> single{{0.25, 2.5}};
  EXPECT_EQ(reading_on_processes(single), 2.5);
}

TEST(GlobalTotals, ExactTotalIsTheSameOnEveryProcessAndTheOneProcessSum) {
  revsph::ExactDoubleSum own, all;
  for (int i = 0; i < 1000; ++i) {
    const double term = std::ldexp(1.0 + i, (i % 40) - 20) * (i % 3 == 0 ? -1.0 : 1.0);
    all.add(term);
    if (held_here(static_cast<std::size_t>(i))) {
      own.add(term);
    }
  }
  const revsph::RunTotal total = revsph::global_total(own);
  EXPECT_EQ(total.value(), all.value());
  EXPECT_EQ(revsph::global_max(total.value()).value(), total.value())
      << "every process holds the same total";
}

} // namespace
