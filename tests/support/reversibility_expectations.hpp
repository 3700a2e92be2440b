#pragma once
// A gtest expectation shared by the models' system tests: the built-in case `name` (with
// `overrides`) returns bit for bit after `steps` steps each way on 1 and 2 threads, and did
// move.

#include "core/threads.hpp"
#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace revsph::testing {

inline void expect_returns_on_one_and_two_threads(const std::string& name, std::int64_t steps,
                                                  const std::vector<Override>& overrides = {}) {
  for (const int threads : {1, 2}) {
    const int previous = thread_count();
    set_thread_count(threads);
    auto simulation = make_simulation(name, overrides);
    VerifyOptions options;
    options.steps = steps;
    const auto report = verify_reversibility(*simulation, options);
    EXPECT_TRUE(report.identical())
        << name << ", " << threads << " threads: " << report.comparison.verdict();
    EXPECT_NE(report.initial_hash, report.turning_point_hash) << name << " did move";
    set_thread_count(previous);
  }
}

} // namespace revsph::testing
