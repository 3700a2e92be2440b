// Palindromic composition of sub-steps: what the integrator accepts and rejects.

#include "core/step_composition.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

struct Recorder {
  std::vector<std::pair<char, double>> calls;
  void a(double dt) { calls.push_back({'a', dt}); }
  void b(double dt) { calls.push_back({'b', dt}); }
};

constexpr auto a = &Recorder::a;
constexpr auto b = &Recorder::b;

using Step = revsph::Substep<Recorder>;

TEST(StepComposition, AcceptsVerletAndAppliesFractionsOfTheStep) {
  const Step verlet[] = {{"kick", 0.5, a}, {"drift", 1.0, b}, {"kick", 0.5, a}};
  EXPECT_NO_THROW(revsph::require_palindrome<Recorder>(verlet));
  Recorder recorder;
  revsph::apply_step<Recorder>(recorder, verlet, 0.2);
  ASSERT_EQ(recorder.calls.size(), 3u);
  EXPECT_EQ(recorder.calls[0], (std::pair<char, double>{'a', 0.1}));
  EXPECT_EQ(recorder.calls[1], (std::pair<char, double>{'b', 0.2}));
  EXPECT_EQ(recorder.calls[2], (std::pair<char, double>{'a', 0.1}));
}

TEST(StepComposition, AcceptsLongerPalindromes) {
  const Step strang[] = {
      {"a", 0.25, a}, {"b", 0.5, b}, {"a", 0.5, a}, {"b", 0.5, b}, {"a", 0.25, a}};
  EXPECT_NO_THROW(revsph::require_palindrome<Recorder>(strang));
}

TEST(StepComposition, RejectsSequencesThatAreNotPalindromes) {
  const Step lopsided[] = {{"kick", 1.0, a}, {"drift", 1.0, b}};
  EXPECT_THROW(revsph::require_palindrome<Recorder>(lopsided), std::logic_error);
  const Step unequal[] = {{"kick", 0.4, a}, {"drift", 1.0, b}, {"kick", 0.6, a}};
  EXPECT_THROW(revsph::require_palindrome<Recorder>(unequal), std::logic_error);
  const Step short_step[] = {{"kick", 0.25, a}, {"drift", 1.0, b}, {"kick", 0.25, a}};
  EXPECT_THROW(revsph::require_palindrome<Recorder>(short_step), std::logic_error);
  const Step mismatched[] = {{"kick", 0.5, a}, {"drift", 1.0, b}, {"kick", 0.5, b}};
  EXPECT_THROW(revsph::require_palindrome<Recorder>(mismatched), std::logic_error);
}

} // namespace
