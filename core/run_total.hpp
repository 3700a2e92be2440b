#pragma once
// A value the same on every process of a run: what energies and diagnostics are made of
// (core/energy.hpp). A model sums its own particles' terms into an ExactDoubleSum; only the run's
// total of that sum (global_total, core/global_totals.hpp), an extreme over the run, a constant of
// the case or arithmetic of these is a RunTotal. A budget term built from a plain double, such as
// a loop's sum over the particles this process holds, does not compile, so a model cannot report
// one process's part as the run's energy: models never see processes (issue 32, Build 3;
// docs/design/distributed.md). Reading one is implicit: a RunTotal is a double to its readers.

#include <cmath>

namespace revsph {

class RunTotal {
public:
  constexpr RunTotal() = default;

  // A value every process computes alike without a reduction: a constant of the case, a value
  // read from a snapshot, the result of a reduction made elsewhere. Named, so that it is seen.
  static constexpr RunTotal same_on_every_process(double value) { return RunTotal(value); }

  constexpr double value() const { return value_; }
  constexpr operator double() const { return value_; } // NOLINT: a RunTotal reads as a double

  constexpr RunTotal& operator+=(RunTotal other) {
    value_ += other.value_;
    return *this;
  }
  constexpr RunTotal& operator-=(RunTotal other) {
    value_ -= other.value_;
    return *this;
  }
  friend constexpr RunTotal operator-(RunTotal a) { return RunTotal(-a.value_); }
  friend constexpr RunTotal operator+(RunTotal a, RunTotal b) {
    return RunTotal(a.value_ + b.value_);
  }
  friend constexpr RunTotal operator-(RunTotal a, RunTotal b) {
    return RunTotal(a.value_ - b.value_);
  }
  friend constexpr RunTotal operator*(RunTotal a, RunTotal b) {
    return RunTotal(a.value_ * b.value_);
  }
  friend constexpr RunTotal operator/(RunTotal a, RunTotal b) {
    return RunTotal(a.value_ / b.value_);
  }
  // Scaled by a constant of the case (a parameter, a unit): the same on every process too.
  friend constexpr RunTotal operator*(RunTotal a, double constant) {
    return RunTotal(a.value_ * constant);
  }
  friend constexpr RunTotal operator*(double constant, RunTotal a) {
    return RunTotal(constant * a.value_);
  }
  friend constexpr RunTotal operator/(RunTotal a, double constant) {
    return RunTotal(a.value_ / constant);
  }
  friend RunTotal sqrt(RunTotal a) { return RunTotal(std::sqrt(a.value_)); }

private:
  constexpr explicit RunTotal(double value) : value_(value) {}
  double value_ = 0.0;
};

} // namespace revsph
