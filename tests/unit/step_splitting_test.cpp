// The core's placement of irreversible operators around a reversible palindrome
// (core/step_splitting.hpp): every splitting, the model's strang sites, several operators, and
// the palindrome left alone when no operator acts.

#include "core/step_splitting.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

struct Recorder {
  std::string calls; // one entry per call: name and the fraction of dt, e.g. "K.5 D1 K.5"
  void record(char name, double dt) {
    calls += (calls.empty() ? "" : " ") + std::string(1, name) +
             (dt == 1.0 ? "1" : (dt == 0.5 ? ".5" : "?"));
  }
  void kick(double dt) { record('K', dt); }
  void drift(double dt) { record('D', dt); }
  void viscosity(double dt) { record('V', dt); }
  void conduction(double dt) { record('C', dt); }
  static std::string acts(const Recorder&) { return "acts"; }
};

using Step = revsph::Substep<Recorder>;
using Operator = revsph::IrreversibleOperator<Recorder>;
using revsph::Splitting;

const Step verlet[] = {{"kick", 0.5, &Recorder::kick},
                       {"drift", 1.0, &Recorder::drift},
                       {"kick", 0.5, &Recorder::kick}};
const Operator viscosity[] = {{"viscosity", &Recorder::viscosity, &Recorder::acts}};
const Operator both[] = {{"viscosity", &Recorder::viscosity, &Recorder::acts},
                         {"conduction", &Recorder::conduction, &Recorder::acts}};

// The calls of one step of length 1 composed from `palindrome` and `acting`.
std::string one_step(std::span<const Step> palindrome, std::span<const Operator> acting,
                     Splitting splitting) {
  Recorder recorder;
  revsph::apply_step<Recorder>(recorder, revsph::compose_step(palindrome, acting, splitting), 1.0);
  return recorder.calls;
}

TEST(StepSplitting, PlacesOneOperatorByEachSplitting) {
  EXPECT_EQ(one_step(verlet, viscosity, Splitting::strang), "V.5 K.5 D1 K.5 V.5");
  EXPECT_EQ(one_step(verlet, viscosity, Splitting::midpoint), "K.5 D.5 V1 D.5 K.5");
  EXPECT_EQ(one_step(verlet, viscosity, Splitting::after_centre), "K.5 D1 V1 K.5");
  EXPECT_EQ(one_step(verlet, viscosity, Splitting::lie), "K.5 D1 K.5 V1");
}

TEST(StepSplitting, NestsSeveralOperatorsSymmetrically) {
  EXPECT_EQ(one_step(verlet, both, Splitting::strang), "V.5 C.5 K.5 D1 K.5 C.5 V.5");
  EXPECT_EQ(one_step(verlet, both, Splitting::midpoint), "K.5 D.5 V.5 C1 V.5 D.5 K.5");
  EXPECT_EQ(one_step(verlet, both, Splitting::lie), "K.5 D1 K.5 V.5 C1 V.5");
}

TEST(StepSplitting, StrangUsesTheSitesTheModelMarks) {
  const Step marked[] = {{"drift", 0.5, &Recorder::drift},
                         revsph::strang_site<Recorder>(),
                         {"kick", 1.0, &Recorder::kick},
                         revsph::strang_site<Recorder>(),
                         {"drift", 0.5, &Recorder::drift}};
  EXPECT_NO_THROW(revsph::require_palindrome<Recorder>(marked));
  EXPECT_EQ(one_step(marked, both, Splitting::strang), "D.5 V.5 C.5 K1 C.5 V.5 D.5");
  // Without an acting operator the marks are dropped: the palindrome itself.
  EXPECT_EQ(one_step(marked, {}, Splitting::strang), "D.5 K1 D.5");
  EXPECT_EQ(one_step(marked, viscosity, Splitting::midpoint), "D.5 K.5 V1 K.5 D.5");
}

TEST(StepSplitting, WithoutActingOperatorsTheStepIsThePalindrome) {
  for (const Splitting splitting :
       {Splitting::strang, Splitting::midpoint, Splitting::after_centre, Splitting::lie}) {
    EXPECT_EQ(one_step(verlet, {}, splitting), "K.5 D1 K.5");
  }
}

TEST(StepSplitting, RejectsWhatItCannotPlace) {
  const Step even[] = {{"kick", 0.5, &Recorder::kick}, {"kick", 0.5, &Recorder::kick}};
  EXPECT_THROW(revsph::compose_step<Recorder>(even, viscosity, Splitting::midpoint),
               std::logic_error);
  const Step one_mark[] = {revsph::strang_site<Recorder>(), {"drift", 1.0, &Recorder::drift}};
  EXPECT_THROW(revsph::compose_step<Recorder>(one_mark, viscosity, Splitting::strang),
               std::logic_error);
}

} // namespace
