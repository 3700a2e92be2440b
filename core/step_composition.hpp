#pragma once
// A time step as a palindrome of exactly invertible sub-steps (design note §2).
//
// Each sub-step updates one group of variables by an increment computed from the others,
// G += Delta_G(others), with Delta_G(R y) = -R_G Delta_G(y); such a sub-step S satisfies
// R S R S = id in integers. A palindromic composition (kick(h/2) drift(h) kick(h/2)) then gives a
// step Phi with R Phi R Phi = id: bitwise time reversibility. The verifier can check each
// sub-step on its own (verify/reversibility.hpp).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

template <class Model>
struct Substep {
  std::string_view name;
  double dt_fraction; // this sub-step advances its group by dt_fraction * dt
  // Null for a mark in the palindrome that does nothing itself (strang_site,
  // core/step_splitting.hpp).
  void (Model::*apply)(double dt); // a member function of the model
  // The one declaration of an irreversible sub-step (an update without an exact inverse, such as
  // paper 2's Cayley update; dissipation is an IrreversibleOperator, core/step_splitting.hpp):
  // null for an exactly invertible one; otherwise what it does irreversibly in this case, or ""
  // where it does nothing irreversible. The verifier, info() and the output read this
  // (irreversible_terms below).
  std::string (*irreversible)(const Model& model) = nullptr;
};

// An operation after every full step, outside the palindrome (an active filter, say): always
// irreversible where it acts, so it says what it does in this case ("" where it does nothing).
template <class Model>
struct StepHook {
  std::string_view name;
  void (Model::*apply)(std::int64_t step);
  std::string (*irreversible)(const Model& model);
};

// "name: what it does" for every sub-step (each name once) and hook that acts irreversibly here.
template <class Model>
std::vector<std::string> irreversible_terms(const Model& model,
                                            std::span<const Substep<Model>> sequence,
                                            std::span<const StepHook<Model>> hooks) {
  std::vector<std::string> terms;
  std::vector<std::string_view> seen;
  for (const Substep<Model>& s : sequence) {
    if (s.irreversible == nullptr || std::find(seen.begin(), seen.end(), s.name) != seen.end()) {
      continue;
    }
    seen.push_back(s.name);
    if (const std::string what = s.irreversible(model); !what.empty()) {
      terms.push_back(std::string(s.name) + ": " + what);
    }
  }
  for (const StepHook<Model>& hook : hooks) {
    if (const std::string what = hook.irreversible(model); !what.empty()) {
      terms.push_back(std::string(hook.name) + ": " + what);
    }
  }
  return terms;
}

// Throws std::logic_error unless the sequence reads the same both ways (names, fractions and
// functions) and each named sub-step's fractions add up to one full step.
template <class Model>
void require_palindrome(std::span<const Substep<Model>> sequence) {
  const std::size_t n = sequence.size();
  if (n == 0) {
    throw std::logic_error("a time step needs at least one sub-step");
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Substep<Model>& a = sequence[i];
    const Substep<Model>& b = sequence[n - 1 - i];
    if (a.name != b.name || a.dt_fraction != b.dt_fraction || a.apply != b.apply) {
      throw std::logic_error("the sub-steps of a time step are not a palindrome: '" +
                             std::string(a.name) + "' faces '" + std::string(b.name) + "'");
    }
  }
  for (const Substep<Model>& s : sequence) {
    double total = 0.0;
    for (const Substep<Model>& t : sequence) {
      if (t.name == s.name) {
        total += t.dt_fraction;
      }
    }
    if (total != 1.0) {
      throw std::logic_error("sub-step '" + std::string(s.name) +
                             "' does not add up to one full time step");
    }
  }
}

// Velocity Verlet, kick(h/2) drift(h) kick(h/2): the palindrome of a model whose sub-steps are
// its members kick and drift.
template <class Model>
std::span<const Substep<Model>> kick_drift_kick() {
  static constexpr Substep<Model> sequence[] = {
      {"kick", 0.5, &Model::kick}, {"drift", 1.0, &Model::drift}, {"kick", 0.5, &Model::kick}};
  return sequence;
}

// One full step: the sub-steps in sequence.
template <class Model>
void apply_step(Model& model, std::span<const Substep<Model>> sequence, double dt) {
  for (const Substep<Model>& s : sequence) {
    (model.*s.apply)(s.dt_fraction * dt);
  }
}

} // namespace revsph
