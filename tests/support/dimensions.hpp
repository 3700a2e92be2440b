#pragma once
// The dimensions a typed test runs in: TYPED_TEST_SUITE(Suite, revsph::testing::Dimensions), then
// TypeParam::value is 2 or 3.

#include <gtest/gtest.h>

#include <type_traits>

namespace revsph::testing {

using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;

// A typed-test fixture with nothing in it: the suites differ only by name.
template <class Dimension>
class DimensionTest : public ::testing::Test {};

} // namespace revsph::testing
