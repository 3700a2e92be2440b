#pragma once
// The revsph subcommands. Each returns the process exit status (common.hpp).

#include "tools/analysis/boltzmann_entropy.hpp"
#include "tools/revsph/common.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace revsph::cli {

struct RunOptions {
  CaseOptions case_options;
  std::string out_dir; // default out/<case name>
  std::optional<std::int64_t> steps;
  std::optional<double> t_end;
  bool force = false;
  bool strict = false; // an unhealthy run (core/run_health.hpp) exits with simulation_failed
};

struct VerifyCommandOptions {
  CaseOptions case_options;
  std::optional<std::int64_t> steps;
  std::optional<double> t_end;
  bool check_substeps = false;
  std::string out_dir; // empty: no output files
  bool force = false;
  // A dissipative case passes if its energy budget closes to this (verify/energy_budget.hpp).
  double energy_tolerance = 1e-2;
};

struct HashOptions {
  CaseOptions case_options;
  std::optional<std::int64_t> steps;
  std::optional<double> t_end;
};

struct EntropyOptions {
  std::string run_dir; // a `run` output directory or a `verify --out` experiment directory
  int bins = analysis::default_speed_bins;
  std::optional<double> max_speed; // default: the largest speed over all snapshots of the run
  std::string particle_set;        // empty: moving_particle_set of the first snapshot
  std::string out_dir;             // default RUN_DIR/analysis
  bool plots = true;
};

int run_command(const RunOptions& options);
int verify_command(const VerifyCommandOptions& options);
int hash_command(const HashOptions& options);
// Lists the built-in cases, prints one (`name`), or prints the case-key reference of a model
// (`keys_model`: a model or "all"), as text or as Markdown (docs/case-keys.md).
int cases_command(const std::string& name, const std::string& keys_model = "",
                  bool markdown = false);
// Bit-for-bit comparison of two snapshots: 0 identical, 1 different, 2 not comparable. A snapshot
// whose state no longer has its recorded hash is compared all the same, after a warning on stderr.
int diff_command(const std::string& first, const std::string& second);
// Reduced Boltzmann entropy of every snapshot of a run: entropy.csv, histograms.csv and (unless
// disabled, through tools/plots/entropy.py) entropy.png and histogram.png.
int entropy_command(const EntropyOptions& options);

} // namespace revsph::cli
