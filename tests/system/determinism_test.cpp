// Bitwise results must not depend on the thread count or the neighbour-search cell size (the
// committed hashes themselves: golden_hash_test.cpp).

#include "core/threads.hpp"
#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

// The hash after `steps` steps on `threads` threads with the given cell size factor.
std::string hash_with(const std::string& case_name, std::int64_t steps, int threads,
                      const std::string& cell_size_factor) {
  const int previous = revsph::thread_count();
  revsph::set_thread_count(threads);
  const std::string hash = revsph::testing::hash_after(
      case_name, steps, {{"discretisation.cell_size_factor", cell_size_factor}});
  revsph::set_thread_count(previous);
  return hash;
}

struct DeterminismCase {
  const char* name;
  std::int64_t steps;
};

class Determinism : public ::testing::TestWithParam<DeterminismCase> {};

// Every pair sum is exact in integers (core/pair_sum.hpp), so neither the thread count nor the
// cell size (which orders the particles and their pairs) may change a single bit.
TEST_P(Determinism, HashIsTheSameForThreadCountsAndCellSizes) {
  const DeterminismCase& c = GetParam();
  const std::string reference = hash_with(c.name, c.steps, 1, "1.0");
  for (const int threads : {1, 2, 3}) {
    for (const char* factor : {"1.0", "1.7", "2.3"}) {
      if (threads == 1 && std::string(factor) == "1.0") {
        continue;
      }
      EXPECT_EQ(hash_with(c.name, c.steps, threads, factor), reference)
          << threads << " threads, cell size factor " << factor;
    }
  }
}

// Both models, 1D, 2D and 3D: wcsph (fluid, walls; the settling dam break with its artificial
// viscosity, an irreversible operator summed exactly too), SHTC's elastic plate, its driven cavity
// (moving walls and relaxation) and its twisting column (3D).
INSTANTIATE_TEST_SUITE_P(
    BothModels, Determinism,
    ::testing::Values(
        DeterminismCase{"column-1d", 400}, DeterminismCase{"dambreak-small", 100},
        DeterminismCase{"dambreak-settling", 300}, DeterminismCase{"dambreak-3d-small", 15},
        DeterminismCase{"beryllium-plate-small", 40}, DeterminismCase{"cavity-re100-small", 25},
        DeterminismCase{"twisting-column-small", 8}, DeterminismCase{"expansion-small", 300},
        DeterminismCase{"box-small", 200}, DeterminismCase{"hyperbolic-small", 300},
        DeterminismCase{"cavity-small", 200}, DeterminismCase{"tube-1d", 300}),
    [](const ::testing::TestParamInfo<DeterminismCase>& param_info) {
      std::string name = param_info.param.name;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

} // namespace
