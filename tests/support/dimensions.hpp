#pragma once
// The dimensions a typed test runs in: REVSPH_DIMENSION_TEST_SUITE(Suite) (below), then
// TypeParam::value is 2 or 3.

#include <gtest/gtest.h>

#include <type_traits>

namespace revsph::testing {

using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;

// A typed-test fixture with nothing in it: the suites differ only by name.
template <class Dimension>
class DimensionTest : public ::testing::Test {};

} // namespace revsph::testing

// Declares the typed suite `suite` over Dimensions: REVSPH_DIMENSION_TEST_SUITE(Suite); then
// TYPED_TEST(Suite, Name) { constexpr int D = TypeParam::value; ... }.
#define REVSPH_DIMENSION_TEST_SUITE(suite)                                                         \
  template <class Dimension>                                                                       \
  class suite : public ::revsph::testing::DimensionTest<Dimension> {};                             \
  TYPED_TEST_SUITE(suite, ::revsph::testing::Dimensions)
