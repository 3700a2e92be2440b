// revsph: the command line of the bitwise-reversible SPH engine.

#include "core/build_info.hpp"
#include "core/distributed/processes.hpp"
#include "core/progress.hpp"
#include "core/snapshot_file.hpp"
#include "fixedpoint/conversion.hpp"
#include "tools/revsph/commands.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>

namespace {

using namespace revsph::cli;

// CLI11's own range check prints the whole double range ("Value 0 not in range 0.000000 to
// 1797…"): these say what is wanted, in one line.
CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) {
          return "expected a number, got \"" + input + "\"";
        }
        return value > 0.0 ? std::string() : "must be > 0 (got " + input + ")";
      },
      "POSITIVE");
}

CLI::Validator thread_count_check() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        long long value = 0;
        if (!CLI::detail::lexical_cast(input, value)) {
          return "expected a whole number of threads, got \"" + input + "\"";
        }
        return value >= 1 ? std::string()
                          : "must be at least 1 (got " + input +
                                "); leave it out to use every hardware thread";
      },
      "N >= 1");
}

struct CaseOptionHandles {
  CLI::Option* case_path = nullptr;
  CLI::Option* arithmetic = nullptr;
};

CaseOptionHandles add_case_options(CLI::App& command, CaseOptions& options,
                                   const std::string& case_help) {
  CaseOptionHandles handles;
  handles.case_path = command.add_option("case", options.case_path, case_help);
  command
      .add_option("--set", options.overrides,
                  "override a case-file value: --set discretisation.dr=0.01 (repeatable)")
      ->allow_extra_args(false); // one value per --set, so a following CASE stays positional
  handles.arithmetic =
      command
          .add_option("--arithmetic", options.arithmetic,
                      "fixed (bitwise reversible, default) or float (the paper's FloPA)")
          ->check(CLI::IsMember({"fixed", "float"}));
  command
      .add_option("--threads", options.threads,
                  "number of threads (default: all); results do not depend on it")
      ->check(thread_count_check());
  return handles;
}

void add_from_option(CLI::App& command, CaseOptions& options) {
  command.add_option("--from", options.from_snapshot,
                     "start from this snapshot (its exact state, step and case) instead of a "
                     "case file");
}

void add_length_options(CLI::App& command, std::optional<std::int64_t>& steps,
                        std::optional<double>& t_end) {
  auto* steps_option = command.add_option(
      "--steps", steps, "number of time steps to take (after --from: this many more steps)");
  auto* t_end_option = command.add_option(
      "--t-end", t_end,
      "run until this simulated time (s), rounded to whole steps (absolute: after --from, the "
      "time the run ends at, not a duration)");
  steps_option->excludes(t_end_option);
}

// The options of a command that runs a case from a file or a snapshot for a length: run, verify.
template <class Options>
CaseOptionHandles add_running_options(CLI::App& command, Options& options,
                                      const std::string& case_help) {
  const CaseOptionHandles handles = add_case_options(command, options.case_options, case_help);
  add_from_option(command, options.case_options);
  add_length_options(command, options.steps, options.t_end);
  return handles;
}

void add_output_options(CLI::App& command, std::string& out_dir, bool& force,
                        const std::string& out_help) {
  command.add_option("--out", out_dir, out_help);
  command.add_flag("--force", force, "overwrite the files of a previous run in --out");
}

void record_given(const CaseOptionHandles& handles, CaseOptions& options) {
  options.case_given = handles.case_path->count() > 0;
  options.arithmetic_given = handles.arithmetic->count() > 0;
}

} // namespace

int main(int argc, char** argv) {
  // The processes of an MPI launch (one without MPI).
  revsph::distributed::ProcessSession session(argc, argv);
  CLI::App app{"revsph: smoothed particle hydrodynamics whose simulations are bitwise reversible.\n"
               "Run forward, reverse the velocities, run forward again: every bit of the initial\n"
               "state comes back."};
  app.set_version_flag("--version", std::string("revsph ") + revsph::build_info::version + " (" +
                                        revsph::build_info::git_commit + ")");
  app.require_subcommand(1);
  // Every refusal of the command line is one line, like those of case files (exit status 2).
  app.failure_message([](const CLI::App*, const CLI::Error& error) {
    return "revsph: error: " + std::string(error.what()) + " (see revsph --help)\n";
  });
  const std::string case_help =
      "case file (TOML), or the name of a built-in case (list: revsph cases)";
  // The exit statuses every command that runs a case shares.
  const std::string stopped_statuses =
      "2 bad input (command line, case, snapshot, --out); 3 the simulation stopped (a fault: the "
      "message names the particle, the variable and the step; the last snapshot is kept).";

  RunOptions run;
  auto* run_app = app.add_subcommand(
      "run", "run a case (default: dambreak-small) or continue from a snapshot; writes "
             "OUT/energy.csv, OUT/snapshots/*.h5, OUT/run.xdmf and OUT/summary.json.\n"
             "--from DIR/snapshots/step_N.h5 continues the run in DIR (unless --out names "
             "another folder): its files up to step N are kept and this run's follow them.\n"
             "SIGINT or SIGTERM ends the run after the step under way with a last snapshot to "
             "continue from (exit 130 or 143).\n"
             "Exit status: 0 the run reached its end (with --strict: and stayed healthy); " +
                 stopped_statuses + " With --strict, 3 also for an unhealthy run.");
  const auto run_handles = add_running_options(*run_app, run, case_help);
  add_output_options(*run_app, run.out_dir, run.force,
                     "output directory (default: out/CASE_NAME; after --from, the snapshot's "
                     "run folder)");
  run_app->add_flag("--strict", run.strict,
                    "exit with status 3 if the run was unhealthy: a health check of the case's "
                    "[health] limits crossed (energy error, max|v|/c, close pairs; "
                    "docs/running.md)");

  VerifyCommandOptions verify;
  auto* verify_app = app.add_subcommand(
      "verify",
      "run N steps, reverse time, run N steps, reverse time, and compare with the initial state "
      "(docs/verify.md). A reversible case must return every raw integer. A case with "
      "irreversible terms (dissipation, an inexact update) runs the same experiment and is told "
      "how far it landed (per variable, in physical units and units in the last place), its "
      "energy budget over both halves and the entropy of its speeds.\n"
      "Exit status: 0 a reversible case returned bit for bit, or a case with irreversible terms "
      "kept its energy budget within --energy-tolerance (its not returning is then expected); "
      "1 a reversible case did not return, or the energy budget did not close; " +
          stopped_statuses);
  const auto verify_handles = add_running_options(*verify_app, verify, case_help);
  verify_app->add_flag("--substeps", verify.check_substeps,
                       "also check each sub-step (kick, drift, …) on its own");
  add_output_options(*verify_app, verify.out_dir, verify.force,
                     "keep the experiment: OUT/forward/ and OUT/backward/ (energy.csv, "
                     "snapshots, run.xdmf) and OUT/summary.json");
  verify_app
      ->add_option("--energy-tolerance", verify.energy_tolerance,
                   "a case with irreversible terms (dissipation, an inexact update) passes if "
                   "its energy budget, max |E(t) - E(0)| over the largest energy term, checked "
                   "after every step of both halves, stays below this (default 1e-2)")
      ->check(positive_number());

  HashOptions hash;
  auto* hash_app = app.add_subcommand(
      "hash", "print the SHA-256 hash of a snapshot's state, or of a case's (or snapshot's) "
              "state after --steps N more steps");
  const auto hash_handles =
      add_case_options(*hash_app, hash.case_options, "case file, built-in case or snapshot (.h5)");
  hash_handles.case_path->required();
  add_length_options(*hash_app, hash.steps, hash.t_end);

  std::string first_snapshot;
  std::string second_snapshot;
  auto* diff_app = app.add_subcommand(
      "diff", "compare two snapshots bit for bit and locate the first difference (exit status 0 "
              "only if identical); a snapshot whose state does not match its recorded hash is "
              "compared anyway, after a warning");
  diff_app->add_option("a", first_snapshot, "first snapshot (.h5)")->required();
  diff_app->add_option("b", second_snapshot, "second snapshot (.h5)")->required();

  EntropyOptions entropy;
  bool no_plots = false;
  auto* entropy_app = app.add_subcommand(
      "entropy", "reduced Boltzmann entropy of the particle speeds in every snapshot of a run or "
                 "verify --out experiment (paper 1, Appendix B); writes OUT/entropy.csv, "
                 "OUT/histograms.csv, OUT/entropy.png and OUT/histogram.png");
  entropy_app
      ->add_option("run_dir", entropy.run_dir,
                   "output directory of `revsph run` or of `revsph verify --out`")
      ->required();
  entropy_app->add_option("--bins", entropy.bins, "number of speed bins (default 100)")
      ->check(positive_number());
  entropy_app
      ->add_option("--max-speed", entropy.max_speed,
                   "upper end of the speed bins in m/s (default: the largest speed in the run)")
      ->check(positive_number());
  entropy_app->add_option(
      "--particle-set", entropy.particle_set,
      "particle set whose speeds are analysed (default: fluid or material, else "
      "the first set with velocities or momenta)");
  entropy_app->add_option("--out", entropy.out_dir, "output directory (default RUN_DIR/analysis)");
  entropy_app->add_flag("--no-plots", no_plots,
                        "only the CSV files (no call of tools/plots/entropy.py)");

  std::string case_name;
  std::string keys_model;
  bool keys_markdown = false;
  auto* cases_app = app.add_subcommand(
      "cases", "list the built-in cases, print one, or list every case-file key of a model");
  cases_app->add_option("name", case_name, "print this built-in case file");
  auto* keys_option = cases_app->add_option(
      "--keys", keys_model,
      "print every key a case file of MODEL may have (type, unit, default, meaning); "
      "MODEL \"all\": every model");
  cases_app->add_flag("--markdown", keys_markdown, "with --keys: as Markdown (docs/case-keys.md)")
      ->needs(keys_option);
  keys_option->excludes("name");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? success : bad_input;
  }

  // A distributed run (docs/design/distributed.md): `run`, `verify` and `hash` hold the state in
  // pieces; `diff` and `entropy` read whole snapshot files and would only repeat each other.
  if (revsph::distributed::process_count() > 1) {
    if (*diff_app || *entropy_app) {
      print_error("started on " + std::to_string(revsph::distributed::process_count()) +
                  " processes; `revsph diff` and `revsph entropy` read snapshot files on one: "
                  "start one process");
      return bad_input;
    }
    // One process speaks for all: the others' reports are the same.
    if (revsph::distributed::process_rank() != 0 &&
        std::freopen("/dev/null", "w", stdout) == nullptr) {
      return stop_every_process("cannot silence the output of process " +
                                    std::to_string(revsph::distributed::process_rank()),
                                simulation_failed);
    }
  }
  try {
    revsph::fixedpoint::require_round_to_nearest();
    if (*run_app || *verify_app || *hash_app) {
      revsph::progress_setting(); // bad input, said before anything is written
    }
    if (*run_app) {
      record_given(run_handles, run.case_options);
      return run_command(run);
    }
    if (*verify_app) {
      record_given(verify_handles, verify.case_options);
      if (!verify.case_options.case_given && verify.case_options.from_snapshot.empty()) {
        print_error("verify needs a case or --from SNAPSHOT");
        return bad_input;
      }
      if (!verify.steps && !verify.t_end) {
        print_error("verify needs --steps N or --t-end T");
        return bad_input;
      }
      return verify_command(verify);
    }
    if (*hash_app) {
      record_given(hash_handles, hash.case_options);
      return hash_command(hash);
    }
    if (*diff_app) {
      return diff_command(first_snapshot, second_snapshot);
    }
    if (*entropy_app) {
      entropy.plots = !no_plots;
      return entropy_command(entropy);
    }
    if (*cases_app) {
      return cases_command(case_name, keys_model, keys_markdown);
    }
  } catch (const revsph::CaseError& error) {
    print_error(error.what());
    return bad_input;
  } catch (const revsph::SnapshotError& error) {
    print_error(error.what());
    return bad_input;
  } catch (const revsph::SimulationFault& fault) {
    return stop_on_fault(fault);
  } catch (const std::exception& error) {
    return stop_every_process(error.what(), simulation_failed);
  }
  return success;
}
