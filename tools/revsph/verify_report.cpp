#include "tools/revsph/verify_report.hpp"

#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/distributed/processes.hpp"
#include "core/threads.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace revsph::cli {

namespace {

std::string scientific(double value, int digits = 1) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*e", digits, value);
  return text;
}

// "1.2e-05 m"; a dimensionless variable (unit "1") has no unit after its number.
std::string with_unit(double value, const std::string& unit) {
  return unit.empty() || unit == "1" ? scientific(value) : scientific(value) + " " + unit;
}

nlohmann::ordered_json distance_json(const StateDistance& distance) {
  nlohmann::ordered_json variables = nlohmann::ordered_json::object();
  for (const VariableDistance* d : distance.differing()) {
    variables[d->name()] = {{"unit", d->unit},
                            {"max", d->max_difference},
                            {"rms", d->rms_difference},
                            {"rms_value", d->reference_rms},
                            {"worst_particle", d->worst_particle},
                            {"max_units_in_last_place", d->max_units_in_last_place},
                            {"rms_units_in_last_place", d->rms_units_in_last_place},
                            {"differing_values", d->differing_values},
                            {"total_values", d->total_values}};
  }
  return variables;
}

} // namespace

std::string short_term_name(const std::string& term) {
  const std::size_t end = term.find_first_of(",(");
  std::string name = term.substr(0, end);
  while (!name.empty() && name.back() == ' ') {
    name.pop_back();
  }
  return name.empty() ? term : name;
}

void print_distance(const StateDistance& distance, Arithmetic arithmetic) {
  std::cout << "distance of the returned state from the initial state, per variable (physical: "
               "largest and RMS over the particles of the norm of the difference; last place: "
            << (arithmetic == Arithmetic::fixed
                    ? "raw integer units of the variable's fixed-point scale"
                    : "|difference| over the unit of the variable's fixed-point scale, rounded "
                      "up (not IEEE ULPs)")
            << "):\n";
  for (const std::string& line : distance.table()) {
    std::cout << "  " << line << "\n";
  }
}

void print_irreversible_findings(const SimulationInfo& info, const VerifyReport& report,
                                 const IrreversibleFindings& findings) {
  if (report.distance) {
    print_distance(*report.distance, info.arithmetic);
  } else if (report.identical()) {
    std::cout << "the state returned bit for bit: the irreversible terms left no trace in it\n";
  }
  const EnergyBudgetCheck& budget = findings.budget;
  std::printf("energy budget over both halves, every step: E(0) = %.6e, E(end) = %.6e, largest "
              "term %.6e, energy moved %.6e\n",
              budget.initial_total, budget.final_total, budget.largest_term,
              budget.mechanical_scale);
  std::printf("energy budget: max |E(t) - E(0)| / largest term = %.3e (tolerance %.1e); "
              "/ energy moved = %.3e\n",
              budget.max_relative_error, findings.tolerance, budget.max_mechanical_relative_error);
  if (findings.budget_closes() && budget.max_mechanical_relative_error > findings.tolerance) {
    // The largest term can be a reservoir that never moves (WCSPH's compressional energy): a
    // loss the model does not count among its terms then hides below the tolerance.
    std::printf("note: over the energy that moved the budget is off by %.1e, more than the "
                "tolerance: energy may leave through a term the model does not count (the pass "
                "criterion is the error over the largest term)\n",
                budget.max_mechanical_relative_error);
  }
  if (findings.entropy) {
    const ReversalEntropy& s = *findings.entropy;
    std::printf("entropy of the %s speeds (reduced Boltzmann, %d bins on [0, %.4g] m/s): start "
                "%.6f, turning point %.6f, end %.6f (change %+.3e forward, %+.3e backward, "
                "%+.3e overall)\n",
                s.particle_set.c_str(), s.bins, s.max_speed, s.start, s.turning_point, s.end,
                s.turning_point - s.start, s.end - s.turning_point, s.end - s.start);
  }
}

std::string irreversible_verdict(const SimulationInfo& info, const VerifyReport& report,
                                 const IrreversibleFindings& findings) {
  const std::size_t count = info.irreversible_terms.size();
  std::string verdict = "not reversible by design: " + std::to_string(count) +
                        (count == 1 ? " irreversible term (" : " irreversible terms (");
  for (std::size_t i = 0; i < count; ++i) {
    verdict += (i == 0 ? "" : "; ") + short_term_name(info.irreversible_terms[i]);
  }
  verdict += "); ";
  if (report.distance) {
    // Positions and velocities in the verdict, the other variables in the table above it.
    std::vector<const VariableDistance*> named;
    const std::vector<const VariableDistance*> differing = report.distance->differing();
    for (const VariableDistance* d : differing) {
      if (d->variable == "position" || d->variable == "velocity") {
        named.push_back(d);
      }
    }
    if (named.empty()) {
      named = differing;
    }
    verdict += "returned to within ";
    for (std::size_t i = 0; i < named.size(); ++i) {
      verdict += (i == 0 ? "" : ", ") + with_unit(named[i]->max_difference, named[i]->unit) + " (" +
                 named[i]->name() + ")";
    }
    if (const std::size_t others = differing.size() - named.size(); others > 0) {
      verdict += " and " + std::to_string(others) + " more variable" + (others == 1 ? "" : "s") +
                 " (table above)";
    }
  } else if (report.identical()) {
    verdict += "returned bit for bit all the same";
  } else {
    verdict += "the states cannot be compared: " + report.comparison.layout_error;
  }
  verdict += "; energy budget ";
  verdict += findings.budget_closes()
                 ? "closes to " + scientific(findings.budget.max_relative_error) + " (tolerance " +
                       scientific(findings.tolerance) + ")"
                 : "does NOT close: " + scientific(findings.budget.max_relative_error) +
                       " > tolerance " + scientific(findings.tolerance);
  return verdict;
}

void write_verify_summary(const std::filesystem::path& path, const VerifySummary& input) {
  const LoadedCase& loaded = *input.loaded;
  const Simulation& simulation = *loaded.simulation;
  const VerifyReport& report = *input.report;
  const SimulationInfo& info = simulation.info();
  nlohmann::ordered_json summary;
  summary["experiment"] = "reversal";
  summary["case"] = info.case_name;
  summary["case_source"] = loaded.case_file.source_name();
  summary["overrides"] = loaded.case_file.overrides();
  summary["model"] = info.model;
  summary["dimension"] = info.dimension;
  summary["arithmetic"] = std::string(to_string(info.arithmetic));
  for (const auto& [name, value] : info.setup_report) {
    summary["setup"][name] = value;
  }
  for (const ParticleCount& p : info.particles) {
    summary["particles"][p.particle_set] = p.count;
  }
  summary["irreversible_terms"] = info.irreversible_terms;
  summary["dt"] = info.dt;
  summary["steps_each_way"] = input.steps;
  summary["reversal_step"] = simulation.steps_taken() - input.steps;
  summary["identical"] = report.identical();
  summary["comparison"] = report.comparison.verdict();
  summary["verdict"] = input.verdict;
  summary["exit_status"] = input.exit_status;
  summary["initial_hash"] = report.initial_hash;
  summary["turning_point_hash"] = report.turning_point_hash;
  summary["final_hash"] = report.final_hash;
  if (report.distance) {
    summary["distance"] = distance_json(*report.distance);
  }
  summary["wall_seconds"] = report.wall_seconds;
  summary["particle_steps_per_second"] =
      report.wall_seconds > 0
          ? 2.0 * static_cast<double>(input.steps) *
                static_cast<double>(info.moving_particle_count()) / report.wall_seconds
          : 0.0;
  summary["threads"] = thread_count();
  summary["processes"] = distributed::process_count();
  const EnergyLog& forward = *input.forward_energy;
  const EnergyLog& backward = *input.backward_energy;
  summary["energy"]["initial_total"] = forward.initial_total();
  summary["energy"]["max_relative_error_forward"] = forward.max_relative_error();
  summary["energy"]["max_relative_error_backward"] = backward.max_relative_error();
  summary["energy"]["mechanical_scale"] = backward.mechanical_scale();
  summary["energy"]["max_mechanical_relative_error_forward"] =
      forward.max_mechanical_relative_error();
  summary["energy"]["max_mechanical_relative_error_backward"] =
      backward.max_mechanical_relative_error();
  if (input.irreversible != nullptr) {
    const IrreversibleFindings& findings = *input.irreversible;
    const EnergyBudgetCheck& budget = findings.budget;
    summary["energy_budget"] = {
        {"evaluated", "after every step of both halves"},
        {"initial_total", budget.initial_total},
        {"final_total", budget.final_total},
        {"largest_term", budget.largest_term},
        {"max_relative_error", budget.max_relative_error},
        {"mechanical_scale", budget.mechanical_scale},
        {"max_mechanical_relative_error", budget.max_mechanical_relative_error},
        {"tolerance", findings.tolerance},
        {"closes", findings.budget_closes()}};
    if (findings.entropy) {
      const ReversalEntropy& s = *findings.entropy;
      summary["entropy"] = {{"particle_set", s.particle_set},   {"bins", s.bins},
                            {"max_speed", s.max_speed},         {"start", s.start},
                            {"turning_point", s.turning_point}, {"end", s.end}};
    }
  }
  summary["build"] = {{"version", build_info::version},
                      {"git_commit", build_info::git_commit},
                      {"compiler", build_info::compiler},
                      {"flags", build_info::flags}};
  write_file_atomically(path, summary.dump(2) + "\n");
}

} // namespace revsph::cli
