#pragma once
// gtest expectations shared by the models' system tests: a case returns bit for bit after N steps
// each way on 1 and 2 threads, and every sub-step alone is undone by itself, on the case's state
// or on a random one.

#include "core/threads.hpp"
#include "simulation_fixture.hpp"
#include "verify/reversibility.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace revsph::testing {

// body(threads) with the thread count set to 1, then to 2; the count is restored after each.
template <class Body>
void on_one_and_two_threads(Body&& body) {
  for (const int threads : {1, 2}) {
    const int previous = thread_count();
    set_thread_count(threads);
    body(threads);
    set_thread_count(previous);
  }
}

// verify_reversibility of `simulation` over `steps` steps each way.
inline VerifyReport reversal_of(Simulation& simulation, std::int64_t steps) {
  VerifyOptions options;
  options.steps = steps;
  return verify_reversibility(simulation, options);
}

// Each sub-step of `simulation` alone, the time reversal, the same sub-step and the reversal again
// return every bit (check_substeps, from the current state). `label` starts each message. Returns
// how many sub-steps were checked.
inline std::size_t expect_substeps_undo_themselves(Simulation& simulation,
                                                   const std::string& label = "") {
  const std::vector<SubstepCheck> checks = check_substeps(simulation, simulation.info().dt);
  for (const auto& check : checks) {
    EXPECT_TRUE(check.comparison.identical)
        << label << check.name << ": " << check.comparison.verdict();
  }
  return checks.size();
}

// On 1 and 2 threads: the built-in case `name` with `overrides` returns bit for bit after `steps`
// steps each way, and its state changed on the way; then `more` checks the returned simulation.
// `label`, then "<n> threads: ", start the message of a failed return; `moved` is the message of
// an unchanged state.
inline void
expect_returns_on_one_and_two_threads(const std::string& name, std::int64_t steps,
                                      const std::vector<Override>& overrides,
                                      const std::string& label, const std::string& moved,
                                      const std::function<void(Simulation&)>& more = {}) {
  on_one_and_two_threads([&](int threads) {
    auto simulation = make_simulation(name, overrides);
    const VerifyReport report = reversal_of(*simulation, steps);
    EXPECT_TRUE(report.identical())
        << label << threads << " threads: " << report.comparison.verdict();
    EXPECT_NE(report.initial_hash, report.turning_point_hash) << moved;
    if (more) {
      more(*simulation);
    }
  });
}

// The same, the messages naming the case.
inline void expect_returns_on_one_and_two_threads(const std::string& name, std::int64_t steps,
                                                  const std::vector<Override>& overrides = {}) {
  expect_returns_on_one_and_two_threads(name, steps, overrides, name + ", ", name + " did move");
}

// One change of a random state: each raw integer of `set`.`field` becomes (`add` false) or is
// moved by (`add` true) a uniform draw from [-2^bits, 2^bits] times `factor`.
struct RandomRaw {
  const char* set;
  const char* field;
  int bits;
  bool add = true;
  std::int64_t factor = 1;
};

// The state of `simulation` with `changes` made in order, drawn from one engine seeded with `seed`,
// is restored into it; then every sub-step alone must be undone by itself (`label` starts each
// message). Returns how many sub-steps were checked.
inline std::size_t
expect_substeps_undo_themselves_on_random_state(Simulation& simulation, std::uint64_t seed,
                                                const std::vector<RandomRaw>& changes,
                                                const std::string& label) {
  StateSnapshot state = simulation.capture_state();
  std::mt19937_64 engine(seed);
  for (const RandomRaw& change : changes) {
    std::uniform_int_distribution<std::int64_t> draw(-(std::int64_t{1} << change.bits),
                                                     std::int64_t{1} << change.bits);
    for (std::int64_t& bits : state.find(change.set, change.field)->bits) {
      bits = (change.add ? bits : 0) + draw(engine) * change.factor;
    }
  }
  simulation.restore_state(state);
  return expect_substeps_undo_themselves(simulation, label);
}

} // namespace revsph::testing

// TEST(suite, test): the built-in case `case_name` returns bit for bit after `steps` steps each way
// on 1 and 2 threads, and did move (expect_returns_on_one_and_two_threads). Written as a
// declaration: REVSPH_REVERSAL_TEST(...);
#define REVSPH_REVERSAL_TEST(suite, test, case_name, steps)                                        \
  TEST(suite, test) {                                                                              \
    ::revsph::testing::expect_returns_on_one_and_two_threads(case_name, steps);                    \
  }                                                                                                \
  static_assert(true)
