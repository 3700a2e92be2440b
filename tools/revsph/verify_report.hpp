#pragma once
// What `revsph verify` prints and writes to summary.json once the experiment (forward N, time
// reversal, forward N, time reversal) has run: for every case the hashes and the bitwise
// comparison, and for a case with irreversible terms also how far the state landed from its
// start, its energy budget over both halves and the entropy of its speeds (docs/verify.md).

#include "core/energy_log.hpp"
#include "core/simulation.hpp"
#include "tools/revsph/common.hpp"
#include "verify/energy_budget.hpp"
#include "verify/reversibility.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace revsph::cli {

// The reduced Boltzmann entropy of the speeds of one particle set, on bins shared by the three
// states (tools/revsph/state_speeds.hpp).
struct ReversalEntropy {
  std::string particle_set;
  int bins = 0;
  double max_speed = 0.0;
  double start = 0.0;
  double turning_point = 0.0;
  double end = 0.0;
};

struct IrreversibleFindings {
  EnergyBudgetCheck budget; // evaluated after every step of both halves
  double tolerance = 0.0;
  std::optional<ReversalEntropy> entropy;

  bool budget_closes() const { return budget.max_relative_error <= tolerance; }
};

// "relaxation of the distortion" from "relaxation of the distortion, tau = … (paper 2 …)".
std::string short_term_name(const std::string& term);

// The per-variable distance table, indented, with a line saying what the units mean.
void print_distance(const StateDistance& distance, Arithmetic arithmetic);

// Distance, energy budget and entropy lines of a case with irreversible terms.
void print_irreversible_findings(const SimulationInfo& info, const VerifyReport& report,
                                 const IrreversibleFindings& findings);

// "not reversible by design: 1 irreversible term (relaxation of the distortion); returned to
// within 3.2e-04 m/s (material.velocity), …; energy budget closes to 4.7e-03 (tolerance 1e-02)".
std::string irreversible_verdict(const SimulationInfo& info, const VerifyReport& report,
                                 const IrreversibleFindings& findings);

struct VerifySummary {
  const LoadedCase* loaded = nullptr;
  std::int64_t steps = 0; // each way
  const VerifyReport* report = nullptr;
  const EnergyLog* forward_energy = nullptr;
  const EnergyLog* backward_energy = nullptr;
  const IrreversibleFindings* irreversible = nullptr; // only for a case with irreversible terms
  std::string verdict;
  int exit_status = 0;
};

// OUT/summary.json, written atomically.
void write_verify_summary(const std::filesystem::path& path, const VerifySummary& summary);

} // namespace revsph::cli
