#pragma once
// Golden hashes: the state of a built-in case after N steps, computed by this engine and stored in
// the test. They must change only on purpose (a change of physics, scales or the case); to
// regenerate one deliberately: build/bin/revsph hash CASE --steps N.

#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

// TEST(suite, test): the built-in case `case_name` has the state hash `hash` after `steps` steps.
// Written as a declaration: REVSPH_GOLDEN_HASH_TEST(...);
#define REVSPH_GOLDEN_HASH_TEST(suite, test, case_name, steps, hash)                               \
  TEST(suite, test) {                                                                              \
    EXPECT_EQ(::revsph::testing::hash_after(case_name, steps), hash);                              \
  }                                                                                                \
  static_assert(true)
