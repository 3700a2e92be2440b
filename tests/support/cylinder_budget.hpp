#pragma once
// The two-fluid rotating cylinder's energy budget, shared by the tests of the frozen and the
// rigidly turning walls: kinetic + internal + dissipated - wall work - force work against the work
// the turning walls put in. Halving dt at a fixed end time (viscous number 0.125 over 200 steps,
// 0.0625 over 400) must divide the budget's largest error by about four (the Verlet kick and
// drift's own second order), and that error must stay within 1 % of the walls' work.

#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace revsph::testing {

struct CylinderBudget {
  double worst = 0.0;     // the largest |E(t) - E(0)| at ten points of the run
  double wall_work = 0.0; // what the walls put in by the end
  double dissipated = 0.0;
  bool dissipated_only_grew = true;
};

inline CylinderBudget cylinder_budget(const char* viscous_number, std::int64_t steps,
                                      std::vector<Override> overrides) {
  overrides.push_back({"discretisation.viscous_number", viscous_number});
  auto simulation = make_simulation("rotating-cylinder-small", overrides);
  const double initial = simulation->energy().total();
  CylinderBudget result;
  for (std::int64_t s = 0; s < steps; s += steps / 10) {
    simulation->advance(steps / 10);
    const EnergyBudget budget = simulation->energy();
    const double now = named_value(budget.terms, "dissipated");
    result.dissipated_only_grew = result.dissipated_only_grew && now >= result.dissipated;
    result.dissipated = now;
    result.wall_work = -named_value(budget.terms, "wall_work");
    result.worst = std::max(result.worst, std::abs(budget.total() - initial));
  }
  std::printf("viscous number %s: %lld steps, dissipated %.4e, wall work %.4e, worst budget "
              "error %.4e\n",
              viscous_number, static_cast<long long>(steps), result.dissipated, result.wall_work,
              result.worst);
  EXPECT_GT(result.wall_work, 0.0) << "the turning wall drives the fluid";
  return result;
}

// Runs both time steps and checks the budget; returns the coarse run for further checks.
inline CylinderBudget expect_cylinder_budget_closes(const std::vector<Override>& overrides) {
  const CylinderBudget coarse = cylinder_budget("0.125", 200, overrides);
  const CylinderBudget fine = cylinder_budget("0.0625", 400, overrides);
  EXPECT_LT(coarse.worst, 0.01 * coarse.wall_work)
      << "the budget misses more than 1 % of the work put in";
  EXPECT_GT(coarse.worst / fine.worst, 3.0);
  EXPECT_LT(coarse.worst / fine.worst, 5.5);
  return coarse;
}

} // namespace revsph::testing
