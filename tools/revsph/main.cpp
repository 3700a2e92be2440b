// revsph: the command line of the bitwise-reversible SPH engine.

#include "core/build_info.hpp"
#include "fixedpoint/conversion.hpp"
#include "tools/revsph/commands.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

namespace {

using namespace revsph::cli;

void add_case_options(CLI::App& command, CaseOptions& options, bool case_required) {
  auto* case_option =
      command.add_option("case", options.case_path,
                         "case file (TOML), or the name of a built-in case (list: revsph cases)");
  if (case_required) {
    case_option->required();
  } else {
    case_option->capture_default_str();
  }
  command
      .add_option("--set", options.overrides,
                  "override a case-file value: --set discretisation.dr=0.01 (repeatable)")
      ->allow_extra_args(false); // one value per --set, so a following CASE stays positional
  command
      .add_option("--arithmetic", options.arithmetic,
                  "fixed (bitwise reversible, default) or float (the paper's FloPA)")
      ->check(CLI::IsMember({"fixed", "float"}));
  command
      .add_option("--threads", options.threads,
                  "number of threads (default: all); results do not depend on it")
      ->check(CLI::PositiveNumber);
}

void add_length_options(CLI::App& command, std::optional<std::int64_t>& steps,
                        std::optional<double>& t_end) {
  auto* steps_option = command.add_option("--steps", steps, "number of time steps");
  auto* t_end_option =
      command.add_option("--t-end", t_end, "simulated time (s), rounded to whole steps");
  steps_option->excludes(t_end_option);
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"revsph: smoothed particle hydrodynamics whose simulations are bitwise reversible.\n"
               "Run forward, reverse the velocities, run forward again: every bit of the initial\n"
               "state comes back."};
  app.set_version_flag("--version", std::string("revsph ") + revsph::build_info::version + " (" +
                                        revsph::build_info::git_commit + ")");
  app.require_subcommand(1);

  RunOptions run;
  auto* run_command_app = app.add_subcommand(
      "run", "run a case; writes OUT/energy.csv and OUT/summary.json (default case: "
             "dambreak-small)");
  add_case_options(*run_command_app, run.case_options, false);
  add_length_options(*run_command_app, run.steps, run.t_end);
  run_command_app->add_option("--out", run.out_dir, "output directory (default: out/CASE_NAME)");
  run_command_app->add_flag("--force", run.force, "overwrite a non-empty output directory");

  VerifyCommandOptions verify;
  auto* verify_app = app.add_subcommand(
      "verify", "check bitwise reversibility: N steps, time reversal, N steps, time reversal, "
                "compare every raw integer with the initial state (exit status 0 only if "
                "identical)");
  add_case_options(*verify_app, verify.case_options, true);
  add_length_options(*verify_app, verify.steps, verify.t_end);
  verify_app->add_flag("--substeps", verify.check_substeps,
                       "also check each sub-step (kick, drift, …) on its own");

  HashOptions hash;
  auto* hash_app = app.add_subcommand("hash", "print the SHA-256 hash of the state after N steps");
  add_case_options(*hash_app, hash.case_options, true);
  add_length_options(*hash_app, hash.steps, hash.t_end);

  std::string case_name;
  auto* cases_app = app.add_subcommand("cases", "list the built-in cases, or print one");
  cases_app->add_option("name", case_name, "print this built-in case file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? success : bad_input;
  }

  try {
    revsph::fixedpoint::require_round_to_nearest();
    if (*run_command_app) {
      return run_command(run);
    }
    if (*verify_app) {
      if (!verify.steps && !verify.t_end) {
        print_error("verify needs --steps N or --t-end T");
        return bad_input;
      }
      return verify_command(verify);
    }
    if (*hash_app) {
      if (!hash.steps && !hash.t_end) {
        print_error("hash needs --steps N or --t-end T");
        return bad_input;
      }
      return hash_command(hash);
    }
    if (*cases_app) {
      return cases_command(case_name);
    }
  } catch (const revsph::CaseError& error) {
    print_error(error.what());
    return bad_input;
  } catch (const revsph::SimulationFault& fault) {
    print_error(std::string("the run stopped: ") + fault.what());
    return simulation_failed;
  } catch (const std::exception& error) {
    print_error(error.what());
    return simulation_failed;
  }
  return success;
}
