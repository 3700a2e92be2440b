#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "tools/revsph/commands.hpp"
#include "tools/revsph/run_output.hpp"
#include "verify/energy_budget.hpp"
#include "verify/reversibility.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace revsph::cli {

namespace {

namespace fs = std::filesystem;

// With --out, the experiment keeps what `run` keeps, for each half:
//   OUT/forward/  and  OUT/backward/   energy.csv, snapshots/, run.xdmf
//   OUT/summary.json                   the verdict, hashes, energies, timing
struct ExperimentOutput {
  std::unique_ptr<RunOutput> forward;
  std::unique_ptr<RunOutput> backward;
  std::unique_ptr<EnergyLog> forward_energy;
  std::unique_ptr<EnergyLog> backward_energy;
};

void write_verify_summary(const fs::path& path, const Simulation& simulation,
                          const LoadedCase& loaded, std::int64_t steps, const VerifyReport& report,
                          const EnergyLog& forward, const EnergyLog& backward) {
  nlohmann::ordered_json summary;
  const SimulationInfo& info = simulation.info();
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
  summary["dt"] = info.dt;
  summary["steps_each_way"] = steps;
  summary["reversal_step"] = simulation.steps_taken() - steps;
  summary["identical"] = report.identical();
  summary["verdict"] = report.comparison.verdict();
  summary["initial_hash"] = report.initial_hash;
  summary["turning_point_hash"] = report.turning_point_hash;
  summary["final_hash"] = report.final_hash;
  summary["wall_seconds"] = report.wall_seconds;
  summary["particle_steps_per_second"] =
      report.wall_seconds > 0
          ? 2.0 * static_cast<double>(steps) * static_cast<double>(info.moving_particle_count()) /
                report.wall_seconds
          : 0.0;
  summary["threads"] = thread_count();
  summary["energy"]["max_relative_error_forward"] = forward.max_relative_error();
  summary["energy"]["max_relative_error_backward"] = backward.max_relative_error();
  summary["build"] = {{"version", build_info::version},
                      {"git_commit", build_info::git_commit},
                      {"compiler", build_info::compiler},
                      {"flags", build_info::flags}};
  write_file_atomically(path, summary.dump(2) + "\n");
}

// A case with irreversible terms (dissipation, an update without an exact inverse) cannot return bit for bit: its energy budget is checked instead,
// over the same number of steps forward (verify/energy_budget.hpp).
int verify_irreversible(Simulation& simulation, const VerifyCommandOptions& options,
                        std::int64_t steps, double progress_interval) {
  const SimulationInfo& info = simulation.info();
  std::cout << "irreversible case (dissipative or not exactly invertible):";
  for (const std::string& term : info.irreversible_terms) {
    std::cout << "\n  irreversible term: " << term;
  }
  std::cout << "\nit cannot return bit for bit; checking its energy budget instead, every step "
               "for "
            << steps << " steps (the energy terms include what was dissipated and, counted "
            << "negative, the work of driven boundaries)\n";
  if (!options.out_dir.empty()) {
    std::cout << "note: --out is for the reversal experiment; nothing is written for a "
                 "case with irreversible terms (use revsph run --out)\n";
  }
  ProgressReporter progress(stdout, "forward ", simulation.steps_taken() + steps, info.dt,
                            progress_interval);
  EnergyBudgetCheck check;
  try {
    check = check_energy_budget(simulation, steps, &progress);
  } catch (const SimulationFault& fault) {
    print_error(std::string("the run stopped: ") + fault.what());
    return simulation_failed;
  }
  std::printf("energy: E(0) = %.6e, E(end) = %.6e, largest term %.6e\n", check.initial_total,
              check.final_total, check.largest_term);
  std::printf("energy budget: max |E(t) - E(0)| / largest term = %.3e (tolerance %.1e)\n",
              check.max_relative_error, options.energy_tolerance);
  std::printf("wall time: %.2f s\n", check.wall_seconds);
  const bool closes = check.max_relative_error <= options.energy_tolerance;
  std::cout << "verdict: irreversible case, energy budget "
            << (closes ? "closes within the tolerance" : "does NOT close within the tolerance")
            << "\n";
  return closes ? success : not_reversible;
}

} // namespace

int verify_command(const VerifyCommandOptions& options) {
  apply_thread_count(options.case_options.threads);
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const std::int64_t steps = resolve_steps(loaded, options.steps, options.t_end, true);
  const fs::path out(options.out_dir);
  if (!options.out_dir.empty()) {
    RunOutput::check_directory(out, options.force, loaded.case_file.source_name());
  }
  const SimulationInfo& info = simulation.info();
  std::cout << "revsph verify: " << info.case_name << " (" << info.model << ", " << info.dimension
            << "D, " << to_string(info.arithmetic) << "-point arithmetic), " << steps
            << " steps forward, time reversal, " << steps << " steps, time reversal; "
            << thread_count() << (thread_count() == 1 ? " thread\n" : " threads\n");
  print_setup_report(info);

  if (!info.irreversible_terms.empty()) {
    return verify_irreversible(simulation, options, steps, loaded.settings.progress_interval);
  }
  if (options.check_substeps) {
    for (const SubstepCheck& check : check_substeps(simulation, info.dt)) {
      std::cout << "sub-step " << check.name << ": " << check.comparison.verdict() << "\n";
    }
  }

  const std::int64_t start = simulation.steps_taken();
  ExperimentOutput output;
  std::optional<double> reference_energy;
  if (loaded.from_snapshot) {
    reference_energy = loaded.from_snapshot->metadata.reference_energy;
  }
  if (!out.empty()) {
    const SnapshotMetadata metadata = run_metadata(simulation, loaded.case_file, reference_energy);
    output.forward =
        std::make_unique<RunOutput>(out / "forward", metadata, loaded.settings.snapshot_every);
    output.backward =
        std::make_unique<RunOutput>(out / "backward", metadata, loaded.settings.snapshot_every);
  }
  output.forward_energy = std::make_unique<EnergyLog>(
      out.empty() ? std::nullopt : std::optional((out / "forward" / "energy.csv").string()),
      reference_energy);
  output.backward_energy = std::make_unique<EnergyLog>(
      out.empty() ? std::nullopt : std::optional((out / "backward" / "energy.csv").string()),
      reference_energy);

  ProgressReporter forward(stdout, "forward ", start + steps, info.dt,
                           loaded.settings.progress_interval);
  ProgressReporter backward(stdout, "backward", start + 2 * steps, info.dt,
                            loaded.settings.progress_interval);
  VerifyOptions verify;
  verify.steps = steps;
  verify.energy_every = loaded.settings.energy_every;
  verify.forward.progress = &forward;
  verify.forward.energy_log = output.forward_energy.get();
  verify.backward.progress = &backward;
  verify.backward.energy_log = output.backward_energy.get();
  // The backward half measures its energy error against E(0) of the forward half.
  verify.backward.at_start = [&](Simulation& s) {
    output.backward_energy->set_reference_total(output.forward_energy->initial_total());
    if (output.backward) {
      output.backward->set_reference_energy(output.forward_energy->initial_total());
      output.backward->write_snapshot(s);
    }
  };
  if (output.forward) {
    verify.forward.at_start = [&](Simulation& s) {
      if (!reference_energy) {
        output.forward->set_reference_energy(s.energy().total());
      }
      output.forward->write_snapshot(s);
    };
    verify.forward.at_end = [&](Simulation& s) { output.forward->write_snapshot(s); };
    verify.backward.at_end = [&](Simulation& s) { output.backward->write_snapshot(s); };
    verify.forward.after_step = [&](Simulation& s) {
      if (output.forward->snapshot_due(s.steps_taken())) {
        output.forward->write_snapshot(s);
      }
    };
    verify.backward.after_step = [&](Simulation& s) {
      if (output.backward->snapshot_due(s.steps_taken())) {
        output.backward->write_snapshot(s);
      }
    };
  }
  VerifyReport report;
  try {
    report = verify_reversibility(simulation, verify);
  } catch (const SimulationFault& fault) {
    print_error(std::string("the run stopped: ") + fault.what());
    return simulation_failed;
  }
  std::cout << "initial state hash:   " << report.initial_hash << "\n"
            << "turning-point hash:   " << report.turning_point_hash << "\n"
            << "returned state hash:  " << report.final_hash << "\n";
  std::printf("energy: max |E(t) - E(0)| / max(|E(0)|, |terms|) = %.3e forward, %.3e backward\n",
              output.forward_energy->max_relative_error(),
              output.backward_energy->max_relative_error());
  std::printf("wall time: %.2f s\n", report.wall_seconds);
  for (const std::string& line : report.comparison.details()) {
    std::cout << "  " << line << "\n";
  }
  std::cout << "verdict: " << report.comparison.verdict() << "\n";
  if (!out.empty()) {
    write_verify_summary(out / "summary.json", simulation, loaded, steps, report,
                         *output.forward_energy, *output.backward_energy);
    std::cout << "wrote " << out.string() << "/: forward/, backward/ (energy.csv, snapshots, "
              << "run.xdmf), summary.json\n";
  }
  return report.identical() ? success : not_reversible;
}

} // namespace revsph::cli
