// revsph verify: forward N steps, time reversal, forward N steps, time reversal, and what came
// back. Every case runs the same experiment; what passes differs (docs/verify.md):
//   - a reversible case (no irreversible terms) passes only if every raw integer returns;
//   - a case with irreversible terms (dissipation, an update without an exact inverse) is not
//     expected to return: it is told how far it landed, per variable, how its speeds' entropy
//     moved, and it passes if its energy budget (which counts what was dissipated and the work of
//     driven walls) closes within --energy-tolerance over both halves.

#include "core/distributed/processes.hpp"
#include "core/energy_log.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "tools/revsph/commands.hpp"
#include "tools/revsph/run_output.hpp"
#include "tools/revsph/state_speeds.hpp"
#include "tools/revsph/verify_report.hpp"
#include "verify/energy_budget.hpp"
#include "verify/reversibility.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

namespace revsph::cli {

namespace {

namespace fs = std::filesystem;

// With --out, the experiment keeps what `run` keeps, for each half:
//   OUT/forward/  and  OUT/backward/   energy.csv, snapshots/, run.xdmf
//   OUT/summary.json                   the verdict, hashes, distances, energies, timing
struct ExperimentOutput {
  std::unique_ptr<RunOutput> forward;
  std::unique_ptr<RunOutput> backward;
  std::unique_ptr<EnergyLog> forward_energy;
  std::unique_ptr<EnergyLog> backward_energy;
};

// What a case with irreversible terms measures during the experiment: its energy budget after
// every step of both halves, and its speeds at the start, the turning point and the end.
struct IrreversibleProbe {
  EnergyBudgetTracker budget;
  std::optional<std::string> particle_set;
  std::vector<ParticleSpeeds> speeds;

  void sample_speeds(Simulation& simulation) {
    if (!particle_set) {
      return;
    }
    try {
      speeds.push_back(particle_speeds(simulation.capture_state(), *particle_set));
    } catch (const std::invalid_argument& error) {
      std::cout << "note: no entropy: " << error.what() << "\n";
      particle_set.reset();
    }
  }

  std::optional<ReversalEntropy> entropy() const {
    if (!particle_set || speeds.size() != 3) {
      return std::nullopt;
    }
    const std::vector<SpeedEntropy> entropies =
        shared_bin_entropies({&speeds[0], &speeds[1], &speeds[2]});
    return ReversalEntropy{
        *particle_set,        analysis::default_speed_bins, entropies[0].histogram.max_speed,
        entropies[0].entropy, entropies[1].entropy,         entropies[2].entropy};
  }
};

void print_irreversible_terms(const SimulationInfo& info) {
  std::cout << "irreversible case: " << info.irreversible_terms.size()
            << (info.irreversible_terms.size() == 1 ? " term" : " terms")
            << " without an exact inverse (dissipation or a rounded update):\n";
  for (const std::string& term : info.irreversible_terms) {
    std::cout << "  irreversible term: " << term << "\n";
  }
  std::cout << "it is not expected to return bit for bit: the same experiment measures how far "
               "it lands, its energy budget after every step (the terms include what was "
               "dissipated and, counted negative, the work of driven walls) and the entropy of "
               "its speeds\n";
}

} // namespace

int verify_command(const VerifyCommandOptions& options) {
  LoadedCase loaded = load_simulation(options.case_options);
  Simulation& simulation = *loaded.simulation;
  const RunEnd end = resolve_run_end(loaded, options.steps, options.t_end, true);
  const std::int64_t steps = end.steps;
  const fs::path out(options.out_dir);
  if (!options.out_dir.empty()) {
    check_on_first_process(
        [&] { RunOutput::check_directory(out, options.force, loaded.case_file.source_name()); });
  }
  const SimulationInfo& info = simulation.info();
  const bool reversible = info.irreversible_terms.empty();
  std::cout << "revsph verify: " << info.case_name << " (" << info.model << ", " << info.dimension
            << "D, " << to_string(info.arithmetic) << "-point arithmetic), " << steps
            << " steps forward, time reversal, " << steps << " steps, time reversal; "
            << thread_count() << (thread_count() == 1 ? " thread\n" : " threads\n");
  print_setup_report(info);
  if (!reversible) {
    print_irreversible_terms(info);
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
    const SnapshotMetadata metadata =
        run_metadata(simulation, loaded.case_file, reference_energy, end);
    output.forward =
        std::make_unique<RunOutput>(out / "forward", metadata, loaded.settings.snapshot_every,
                                    loaded.settings.snapshot_interval);
    output.backward =
        std::make_unique<RunOutput>(out / "backward", metadata, loaded.settings.snapshot_every,
                                    loaded.settings.snapshot_interval);
  }
  output.forward_energy = std::make_unique<EnergyLog>(
      out.empty() ? std::nullopt : file_of_first_process(out / "forward" / "energy.csv"),
      reference_energy);
  output.backward_energy = std::make_unique<EnergyLog>(
      out.empty() ? std::nullopt : file_of_first_process(out / "backward" / "energy.csv"),
      reference_energy);
  std::unique_ptr<IrreversibleProbe> probe;
  if (!reversible) {
    probe = std::make_unique<IrreversibleProbe>();
    probe->particle_set = moving_particle_set(simulation.capture_state());
  }

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
  verify.forward.at_start = [&](Simulation& s) {
    if (output.forward) {
      if (!reference_energy) {
        output.forward->set_reference_energy(s.energy().total());
      }
      output.forward->write_snapshot(s);
    }
    if (probe) {
      probe->budget.observe(s.energy());
      probe->sample_speeds(s);
    }
  };
  verify.forward.at_end = [&](Simulation& s) {
    if (output.forward) {
      output.forward->write_snapshot(s);
    }
    if (probe) {
      probe->sample_speeds(s);
    }
  };
  // The backward half measures its energy errors against E(0) of the forward half.
  verify.backward.at_start = [&](Simulation& s) {
    output.backward_energy->continue_from(*output.forward_energy);
    if (output.backward) {
      output.backward->set_reference_energy(output.forward_energy->initial_total());
      output.backward->write_snapshot(s);
    }
  };
  verify.backward.at_end = [&](Simulation& s) {
    if (output.backward) {
      output.backward->write_snapshot(s);
    }
  };
  auto after_step = [&](RunOutput* half_output) {
    return [&, half_output](Simulation& s) {
      if (half_output != nullptr && half_output->snapshot_due(s, s.steps_taken())) {
        half_output->write_snapshot(s);
      }
      if (probe) {
        probe->budget.observe(s.energy());
      }
    };
  };
  verify.forward.after_step = after_step(output.forward.get());
  verify.backward.after_step = after_step(output.backward.get());

  VerifyReport report;
  try {
    report = verify_reversibility(simulation, verify);
  } catch (const SimulationFault& fault) {
    return stop_on_fault(fault);
  }
  std::cout << "initial state hash:   " << report.initial_hash << "\n"
            << "turning-point hash:   " << report.turning_point_hash << "\n"
            << "returned state hash:  " << report.final_hash << "\n";
  std::printf("energy: max |E(t) - E(0)| / max(|E(0)|, |terms|) = %.3e forward, %.3e backward\n",
              output.forward_energy->max_relative_error(),
              output.backward_energy->max_relative_error());
  std::printf("energy: max |E(t) - E(0)| / energy moved = %.3e forward, %.3e backward (energy "
              "moved %.6e)\n",
              output.forward_energy->max_mechanical_relative_error(),
              output.backward_energy->max_mechanical_relative_error(),
              output.backward_energy->mechanical_scale());
  std::printf("wall time: %.2f s\n", report.wall_seconds);

  std::string verdict;
  int status = success;
  IrreversibleFindings findings;
  if (reversible) {
    for (const std::string& line : report.comparison.details()) {
      std::cout << "  " << line << "\n";
    }
    if (report.distance) {
      print_distance(*report.distance, info.arithmetic);
    }
    verdict = report.comparison.verdict();
    status = report.identical() ? success : not_reversible;
  } else {
    probe->sample_speeds(simulation);
    findings.budget = probe->budget.result();
    findings.budget.steps = 2 * steps;
    findings.budget.wall_seconds = report.wall_seconds;
    findings.tolerance = options.energy_tolerance;
    findings.entropy = probe->entropy();
    print_irreversible_findings(info, report, findings);
    verdict = irreversible_verdict(info, report, findings);
    status = findings.budget_closes() ? success : not_reversible;
  }
  std::cout << "verdict: " << verdict << "\n";
  if (!out.empty()) {
    VerifySummary summary;
    summary.loaded = &loaded;
    summary.steps = steps;
    summary.report = &report;
    summary.forward_energy = output.forward_energy.get();
    summary.backward_energy = output.backward_energy.get();
    summary.irreversible = reversible ? nullptr : &findings;
    summary.verdict = verdict;
    summary.exit_status = status;
    if (distributed::process_rank() == 0) {
      write_verify_summary(out / "summary.json", summary);
    }
    std::cout << "wrote " << out.string() << "/: forward/, backward/ (energy.csv, snapshots, "
              << "run.xdmf), summary.json\n";
  }
  return status;
}

} // namespace revsph::cli
