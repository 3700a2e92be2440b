// revsph entropy: the reduced Boltzmann entropy of a run's particle speeds over time (paper 1,
// §6 and Appendix B; the formulas are in tools/analysis/boltzmann_entropy.hpp).

#include "core/atomic_file.hpp"
#include "core/xdmf.hpp"
#include "tools/analysis/boltzmann_entropy.hpp"
#include "tools/revsph/commands.hpp"
#include "tools/revsph/run_output.hpp"
#include "tools/revsph/state_speeds.hpp"
#include "verify/snapshot_check.hpp"

#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>

#ifndef REVSPH_SOURCE_DIR
#define REVSPH_SOURCE_DIR ""
#endif

namespace revsph::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* python_interpreter = "/usr/bin/python3";

struct Phase {
  std::string name; // forward, backward or run
  fs::path folder;  // holds snapshots/ and (written by revsph) run.xdmf
};

// What the analysis needs of one snapshot; the speeds are kept so that every histogram can use
// the largest speed of the whole run as its range.
struct SnapshotSpeeds {
  std::string phase;
  fs::path file;
  std::int64_t step = 0;
  double time = 0.0;
  double forward_equivalent_time = 0.0;
  int dimension = 2;
  std::vector<double> speeds;
  double kinetic_energy = 0.0; // Σ m v² / 2 (per unit depth in 2D)
  double mean_mass = 0.0;
};

struct EntropyRow {
  const SnapshotSpeeds* snapshot = nullptr;
  analysis::SpeedHistogram histogram;
  double theta_fit = 0.0;
  double theta_moment = 0.0;
  double entropy = 0.0;
  double entropy_equilibrium_theta = 0.0;
  double entropy_equilibrium_energy = 0.0;
};

// The run's snapshot series: the one its run.xdmf lists (the output cadence and the last, an
// earlier segment's off-cadence end left out: run_output.hpp), as the Python reader reads it;
// without run.xdmf, every snapshot file of the folder.
std::vector<fs::path> snapshot_files(const fs::path& run_folder) {
  std::vector<fs::path> files;
  std::ifstream xdmf(run_folder / "run.xdmf");
  if (xdmf) {
    const std::string document{std::istreambuf_iterator<char>(xdmf),
                               std::istreambuf_iterator<char>()};
    for (const std::string& file : xdmf_snapshot_files(document)) {
      files.push_back(run_folder / file);
    }
    return files;
  }
  for (const auto& entry : fs::directory_iterator(run_folder / "snapshots")) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.starts_with("step_") && name.ends_with(".h5")) {
      files.push_back(entry.path());
    }
  }
  // Zero-padded step numbers: the names sort in time order.
  std::sort(files.begin(), files.end());
  return files;
}

SnapshotSpeeds read_speeds(const fs::path& file, const std::string& phase,
                           const std::string& particle_set) {
  const Snapshot snapshot = read_checked_snapshot(file);
  SnapshotSpeeds result;
  try {
    ParticleSpeeds speeds = particle_speeds(snapshot.state, particle_set);
    result.dimension = speeds.dimension;
    result.speeds = std::move(speeds.speeds);
    result.kinetic_energy = speeds.kinetic_energy;
    result.mean_mass = speeds.mean_mass;
  } catch (const std::invalid_argument& error) {
    throw SnapshotError(file.string() + ": " + error.what());
  }
  result.phase = phase;
  result.file = file;
  result.step = snapshot.metadata.step;
  result.time = snapshot.metadata.time;
  result.forward_equivalent_time = result.time;
  return result;
}

// The time the backward phase reverses at: summary.json's reversal_step · dt, or (if a killed
// experiment left no summary) the time of the last forward snapshot, which verify writes there.
double reversal_time(const fs::path& run_dir, const std::vector<SnapshotSpeeds>& snapshots) {
  const fs::path summary_path = run_dir / "summary.json";
  std::ifstream summary_file(summary_path);
  if (summary_file) {
    const nlohmann::json summary = nlohmann::json::parse(summary_file, nullptr, false);
    if (!summary.is_discarded() && summary.contains("reversal_step") && summary.contains("dt") &&
        summary["reversal_step"].is_number() && summary["dt"].is_number()) {
      return summary["reversal_step"].get<double>() * summary["dt"].get<double>();
    }
  }
  double last_forward = 0.0;
  for (const SnapshotSpeeds& snapshot : snapshots) {
    if (snapshot.phase == "forward") {
      last_forward = snapshot.time;
    }
  }
  std::cout << "note: " << summary_path.string()
            << " has no reversal_step and dt; taking the reversal time from the last forward "
               "snapshot, t = "
            << last_forward << " s\n";
  return last_forward;
}

// Fixed notation with enough digits to reproduce the values; inf and nan spelt so that Python's
// float() reads them.
std::string number(double value) {
  if (std::isnan(value)) {
    return "nan";
  }
  if (std::isinf(value)) {
    return value > 0 ? "inf" : "-inf";
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.12g", value);
  return text;
}

std::string entropy_csv(const std::vector<EntropyRow>& rows) {
  std::string csv = "phase,step,time,forward_equivalent_time,particles,kinetic_energy,theta_fit,"
                    "theta_moment,S_reduced,S_eq_theta,S_eq_energy\n";
  for (const EntropyRow& row : rows) {
    const SnapshotSpeeds& s = *row.snapshot;
    csv += s.phase + "," + std::to_string(s.step) + "," + number(s.time) + "," +
           number(s.forward_equivalent_time) + "," + std::to_string(s.speeds.size()) + "," +
           number(s.kinetic_energy) + "," + number(row.theta_fit) + "," + number(row.theta_moment) +
           "," + number(row.entropy) + "," + number(row.entropy_equilibrium_theta) + "," +
           number(row.entropy_equilibrium_energy) + "\n";
  }
  return csv;
}

void append_histogram(std::string& csv, const std::string& label, const EntropyRow& row) {
  const SnapshotSpeeds& s = *row.snapshot;
  const analysis::SpeedHistogram& h = row.histogram;
  const bool fitted = !h.degenerate() && std::isfinite(row.theta_fit) && row.theta_fit > 0.0;
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    // The model averaged over the bin: what fit_theta compared the histogram with.
    const double model =
        fitted ? (analysis::maxwell_boltzmann_cdf(h.edges[i + 1], row.theta_fit, s.dimension) -
                  analysis::maxwell_boltzmann_cdf(h.edges[i], row.theta_fit, s.dimension)) /
                     h.bin_width
               : std::numeric_limits<double>::quiet_NaN();
    csv += label + "," + s.phase + "," + std::to_string(s.step) + "," + number(s.time) + "," +
           std::to_string(s.dimension) + "," + number(row.theta_fit) + "," + std::to_string(i) +
           "," + number(h.edges[i]) + "," + number(h.edges[i + 1]) + "," + number(h.centres[i]) +
           "," + std::to_string(h.counts[i]) + "," + number(h.density[i]) + "," + number(model) +
           "\n";
  }
}

void print_table(const std::vector<EntropyRow>& rows) {
  std::printf("%-9s %10s %9s %11s %11s %11s %11s\n", "phase", "step", "time (s)", "S_reduced",
              "theta_fit", "S_eq(theta)", "S_eq(E)");
  // About 20 rows: evenly spaced, plus the first and last row of every phase.
  const std::size_t stride = std::max<std::size_t>(1, (rows.size() + 19) / 20);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool phase_edge = i == 0 || i + 1 == rows.size() ||
                            rows[i - 1].snapshot->phase != rows[i].snapshot->phase ||
                            rows[i + 1].snapshot->phase != rows[i].snapshot->phase;
    if (i % stride != 0 && !phase_edge) {
      continue;
    }
    const EntropyRow& row = rows[i];
    std::printf("%-9s %10lld %9.4f %11.4f %11.4g %11.4f %11.4f\n", row.snapshot->phase.c_str(),
                static_cast<long long>(row.snapshot->step), row.snapshot->time, row.entropy,
                row.theta_fit, row.entropy_equilibrium_theta, row.entropy_equilibrium_energy);
  }
}

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
}

// The figures are a convenience on top of the CSV files: a missing interpreter, script or
// matplotlib is a note, not a failure.
void make_plots(const fs::path& out) {
  const fs::path script = fs::path(REVSPH_SOURCE_DIR) / "tools" / "plots" / "entropy.py";
  if (!fs::exists(python_interpreter) || !fs::exists(script)) {
    std::cout << "note: no plots: "
              << (fs::exists(python_interpreter) ? script.string() : python_interpreter)
              << " is missing; the CSV files are written (plot them with tools/plots/entropy.py "
                 "OUT_DIR)\n";
    return;
  }
  std::fflush(stdout);
  std::cout.flush();
  const std::string command = std::string(python_interpreter) + " " + shell_quote(script.string()) +
                              " " + shell_quote(out.string());
  const int status = std::system(command.c_str());
  if (status != 0) {
    std::cout << "note: " << command << " failed (exit status "
              << (WIFEXITED(status) ? WEXITSTATUS(status) : status)
              << "); the CSV files are written\n";
  }
}

} // namespace

int entropy_command(const EntropyOptions& options) {
  const fs::path run_dir(options.run_dir);
  if (!options.out_dir.empty()) {
    // Bad input, said before the snapshots are read.
    RunOutput::check_creatable(options.out_dir, run_dir.string());
  }
  std::vector<Phase> phases;
  if (fs::is_directory(run_dir / "forward" / "snapshots") &&
      fs::is_directory(run_dir / "backward" / "snapshots")) {
    phases = {{"forward", run_dir / "forward"}, {"backward", run_dir / "backward"}};
  } else if (fs::is_directory(run_dir / "snapshots")) {
    phases = {{"run", run_dir}};
  } else {
    print_error(run_dir.string() + ": neither a run directory (snapshots/) nor a verify --out "
                                   "directory (forward/snapshots/, backward/snapshots/)");
    return bad_input;
  }
  if (options.bins < 1) {
    print_error("--bins must be >= 1");
    return bad_input;
  }
  if (options.max_speed && !(*options.max_speed > 0.0 && std::isfinite(*options.max_speed))) {
    print_error("--max-speed must be a positive number");
    return bad_input;
  }

  std::vector<SnapshotSpeeds> snapshots;
  std::string particle_set = options.particle_set;
  for (const Phase& phase : phases) {
    const std::vector<fs::path> files = snapshot_files(phase.folder);
    if (files.empty()) {
      print_error((phase.folder / "snapshots").string() + ": no snapshots (step_*.h5)");
      return bad_input;
    }
    if (particle_set.empty()) {
      // The model's moving set, from the first snapshot (state_speeds.hpp).
      const std::optional<std::string> moving =
          moving_particle_set(read_checked_snapshot(files.front()).state);
      if (!moving) {
        print_error(files.front().string() +
                    ": no particle set has a mass with velocities or momenta");
        return bad_input;
      }
      particle_set = *moving;
    }
    for (const fs::path& file : files) {
      snapshots.push_back(read_speeds(file, phase.name, particle_set));
    }
  }
  const bool reversal = phases.size() == 2;
  if (reversal) {
    const double t_rev = reversal_time(run_dir, snapshots);
    for (SnapshotSpeeds& snapshot : snapshots) {
      if (snapshot.phase == "backward") {
        snapshot.forward_equivalent_time = t_rev - (snapshot.time - t_rev);
      }
    }
  }

  // One range for the whole run, so that the entropies of different times share their bins and
  // differ only through the distribution (the histogram entropy depends on the bin width).
  double run_max_speed = 0.0;
  for (const SnapshotSpeeds& snapshot : snapshots) {
    for (const double speed : snapshot.speeds) {
      run_max_speed = std::max(run_max_speed, speed);
    }
  }
  std::optional<double> max_speed = options.max_speed;
  if (!max_speed && run_max_speed > 0.0) {
    max_speed = run_max_speed;
  }

  std::vector<EntropyRow> rows;
  std::size_t snapshots_above_max = 0;
  for (const SnapshotSpeeds& snapshot : snapshots) {
    EntropyRow row;
    row.snapshot = &snapshot;
    const int d = snapshot.dimension;
    row.histogram = analysis::speed_histogram(snapshot.speeds, options.bins, max_speed);
    row.entropy = analysis::reduced_entropy(row.histogram, d);
    row.theta_fit = analysis::fit_theta(row.histogram, d);
    row.theta_moment = analysis::moment_theta(snapshot.speeds, d);
    row.entropy_equilibrium_theta = analysis::equilibrium_entropy(row.theta_fit, d);
    row.entropy_equilibrium_energy = analysis::equilibrium_entropy_from_energy(
        snapshot.kinetic_energy, static_cast<double>(snapshot.speeds.size()), snapshot.mean_mass,
        d);
    snapshots_above_max += row.histogram.above_max > 0 ? 1 : 0;
    rows.push_back(std::move(row));
  }

  const fs::path out = options.out_dir.empty() ? run_dir / "analysis" : fs::path(options.out_dir);
  fs::create_directories(out);
  write_file_atomically(out / "entropy.csv", entropy_csv(rows));
  std::string histograms = "snapshot,phase,step,time,dimension,theta_fit,bin,v_low,v_high,"
                           "v_centre,count,density,mb_density\n";
  if (reversal) {
    const auto last_forward = std::find_if(rows.rbegin(), rows.rend(), [](const EntropyRow& row) {
      return row.snapshot->phase == "forward";
    });
    append_histogram(histograms, "turning_point", *last_forward);
  }
  append_histogram(histograms, "final", rows.back());
  write_file_atomically(out / "histograms.csv", histograms);

  const SnapshotSpeeds& first = snapshots.front();
  std::cout << "revsph entropy: " << run_dir.string() << ": " << snapshots.size() << " snapshots, "
            << first.speeds.size() << " " << particle_set << " particles, " << first.dimension
            << "D; " << options.bins << " speed bins on [0, " << number(max_speed.value_or(0.0))
            << "] m/s"
            << (options.max_speed ? " (--max-speed)\n" : " (the largest speed of the run)\n");
  print_table(rows);
  if (!max_speed) {
    std::cout << "note: every speed of every snapshot is 0: no histogram can be made, the "
                 "reduced entropy is -inf (its limit for a distribution concentrated at v = 0)\n";
  }
  if (snapshots_above_max > 0) {
    std::cout << "note: in " << snapshots_above_max
              << " snapshots some speeds exceed --max-speed; they are left out of the histogram "
                 "(its density integrates to less than 1) and its entropy; S_reduced is nan "
                 "where no speed is left\n";
  }
  std::cout << "wrote " << (out / "entropy.csv").string() << ", "
            << (out / "histograms.csv").string() << "\n";
  if (options.plots) {
    make_plots(out);
  }
  return success;
}

} // namespace revsph::cli
