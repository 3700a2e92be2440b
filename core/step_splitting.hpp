#pragma once
// Where a model's irreversible operators (a dissipation, a relaxation) go in a time step. The
// model declares its reversible palindrome and its operators; the core places the operators
// around the palindrome by the case's `step.splitting`, so the reversible part stays a
// palindrome of exactly invertible sub-steps and no sub-step of it carries dissipation inside
// (design note §2). With I one full update by the operators and R the reversible step:
//   strang        I(h/2) R I(h/2): second order. The halves go to the step's ends, or to the
//                 two Strang sites the model marks in its palindrome (strang_site: superfluid
//                 puts them after the half drifts, where its copies are evaluated anyway).
//   midpoint      R's central sub-step halved, I(h) between the halves: second order, one
//                 update per step (paper 4's entropic model, "Strang the other way round").
//   after_centre  I(h) right after R's central sub-step: first order (paper 2, eq. 52).
//   lie           R then I(h): first order (paper 4 §5, the entropic paper's own placement).
// Several operators I1..In make one update as the nested Strang I1(h/2) .. In(h) .. I1(h/2); at
// the strang sites the first site gets I1(h/2) .. In(h/2), its mirror In(h/2) .. I1(h/2). Only
// the operators that act in the case are placed: without any, the step is the palindrome itself,
// bit for bit.

#include "core/step_composition.hpp"

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

enum class Splitting { strang, midpoint, after_centre, lie };

// An irreversible operator over a time `dt`, applied where the splitting places it. `acts` says
// what it does in this case ("" where it does nothing, as Substep::irreversible).
template <class Model>
struct IrreversibleOperator {
  std::string_view name;
  void (Model::*apply)(double dt);
  std::string (*acts)(const Model& model);
};

// A mark in a reversible palindrome where the strang splitting puts its half updates; the
// palindrome carries it twice, mirrored. It does nothing itself and is dropped from the step.
template <class Model>
constexpr Substep<Model> strang_site() {
  return {"(strang site)", 0.5, nullptr};
}

// How the placement reads in the irreversible terms ("dissipation: ..., half steps at ...").
inline std::string placement_text(Splitting splitting, bool at_marked_sites) {
  if (splitting == Splitting::strang && at_marked_sites) {
    return "half steps inside the step, at the sites the model marks";
  }
  // In the order of the enum.
  static constexpr std::string_view texts[] = {
      "half steps at the step's ends", "one update in the middle of the step",
      "one update after the step's central sub-step (first order)",
      "one update after each step (first order)"};
  return std::string(texts[static_cast<int>(splitting)]);
}

namespace splitting_detail {

template <class Model>
Substep<Model> operator_substep(const IrreversibleOperator<Model>& op, double dt_fraction) {
  return {op.name, dt_fraction, op.apply, op.acts};
}

// I1(h/2) .. In(h) .. I1(h/2): one full update by all the operators.
template <class Model>
void append_full_update(std::vector<Substep<Model>>& step,
                        std::span<const IrreversibleOperator<Model>> acting) {
  const std::size_t n = acting.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    step.push_back(operator_substep(acting[i], 0.5));
  }
  step.push_back(operator_substep(acting[n - 1], 1.0));
  for (std::size_t i = n - 1; i-- > 0;) {
    step.push_back(operator_substep(acting[i], 0.5));
  }
}

template <class Model>
void append_half_update(std::vector<Substep<Model>>& step,
                        std::span<const IrreversibleOperator<Model>> acting, bool mirrored) {
  for (std::size_t i = 0; i < acting.size(); ++i) {
    step.push_back(operator_substep(acting[mirrored ? acting.size() - 1 - i : i], 0.5));
  }
}

} // namespace splitting_detail

// The number of strang sites a palindrome marks: 0 (the ends) or 2 (one site and its mirror).
template <class Model>
std::size_t marked_strang_sites(std::span<const Substep<Model>> palindrome) {
  std::size_t marks = 0;
  for (const Substep<Model>& s : palindrome) {
    marks += s.apply == nullptr ? 1 : 0;
  }
  if (marks != 0 && marks != 2) {
    throw std::logic_error("a palindrome marks its strang sites once and mirrored (found " +
                           std::to_string(marks) + ")");
  }
  return marks;
}

// The step the core runs: the reversible palindrome with the acting operators placed.
template <class Model>
std::vector<Substep<Model>> compose_step(std::span<const Substep<Model>> palindrome,
                                         std::span<const IrreversibleOperator<Model>> acting,
                                         Splitting splitting) {
  using namespace splitting_detail;
  const bool marked = marked_strang_sites(palindrome) != 0;
  std::vector<Substep<Model>> reversible;
  for (const Substep<Model>& s : palindrome) {
    if (s.apply != nullptr) {
      reversible.push_back(s);
    }
  }
  if (acting.empty()) {
    return reversible;
  }
  std::vector<Substep<Model>> step;
  if (splitting == Splitting::strang) {
    if (!marked) {
      append_half_update(step, acting, false);
    }
    bool mirrored = false;
    for (const Substep<Model>& s : palindrome) {
      if (s.apply == nullptr) {
        append_half_update(step, acting, mirrored);
        mirrored = true;
      } else {
        step.push_back(s);
      }
    }
    if (!marked) {
      append_half_update(step, acting, true);
    }
    return step;
  }
  if (splitting == Splitting::lie) {
    step = reversible;
    append_full_update(step, acting);
    return step;
  }
  if (reversible.size() % 2 == 0) {
    throw std::logic_error("the midpoint and after_centre splittings need a palindrome with a "
                           "central sub-step");
  }
  const std::size_t centre = reversible.size() / 2;
  for (std::size_t i = 0; i < reversible.size(); ++i) {
    if (i != centre) {
      step.push_back(reversible[i]);
      continue;
    }
    Substep<Model> central = reversible[i];
    if (splitting == Splitting::midpoint) {
      central.dt_fraction *= 0.5;
      step.push_back(central);
      append_full_update(step, acting);
      step.push_back(central);
    } else {
      step.push_back(central);
      append_full_update(step, acting);
    }
  }
  return step;
}

} // namespace revsph
