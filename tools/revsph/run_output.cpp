#include "tools/revsph/run_output.hpp"

#include "core/build_info.hpp"
#include "core/case_file.hpp"
#include "core/distributed/processes.hpp"
#include "verify/state_hash.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <system_error>

#include <unistd.h>

namespace revsph::cli {

namespace {

namespace fs = std::filesystem;

// What a previous run leaves in its directory (and nothing else is removed by --force).
bool is_run_artifact(const fs::path& path) {
  const std::string name = path.filename().string();
  return name == "energy.csv" || name == "summary.json" || name == "run.xdmf" ||
         name == "run.xdmf.tmp" || name == "summary.json.tmp";
}

bool is_snapshot_artifact(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.starts_with("step_") && (name.ends_with(".h5") || name.ends_with(".h5.tmp"));
}

} // namespace

void RunOutput::check_creatable(const fs::path& directory, const std::string& case_source) {
  std::error_code error;
  if (fs::exists(directory, error)) {
    return;
  }
  fs::path ancestor = fs::absolute(directory, error).parent_path();
  while (!fs::exists(ancestor, error) && ancestor.has_parent_path() &&
         ancestor != ancestor.parent_path()) {
    ancestor = ancestor.parent_path();
  }
  if (!fs::is_directory(ancestor, error)) {
    throw CaseError(case_source, "--out",
                    directory.string() + " cannot be created: " + ancestor.string() +
                        " is not a directory");
  }
  if (access(ancestor.c_str(), W_OK | X_OK) != 0) {
    throw CaseError(case_source, "--out",
                    directory.string() + " cannot be created: no permission to write in " +
                        ancestor.string());
  }
  // Permissions do not tell everything (root may write anywhere, yet not in /proc or on a
  // read-only file system): make a directory there and remove it again.
  const fs::path probe = ancestor / (".revsph-out-check-" + std::to_string(getpid()));
  if (!fs::create_directory(probe, error) && error) {
    throw CaseError(case_source, "--out",
                    directory.string() + " cannot be created: " + error.message() + " in " +
                        ancestor.string());
  }
  fs::remove(probe, error);
}

void RunOutput::check_directory(const fs::path& directory, bool force,
                                const std::string& case_source) {
  check_creatable(directory, case_source);
  if (fs::exists(directory) && !fs::is_directory(directory)) {
    throw CaseError(case_source, "--out", directory.string() + " exists and is not a directory");
  }
  if (!fs::exists(directory) || fs::is_empty(directory)) {
    return;
  }
  if (!force) {
    throw CaseError(case_source, "--out",
                    "the output directory " + directory.string() +
                        " exists and is not empty; choose another with --out or overwrite it "
                        "with --force");
  }
  for (const auto& entry : fs::directory_iterator(directory)) {
    if (is_run_artifact(entry.path())) {
      fs::remove(entry.path());
    }
  }
  if (fs::is_directory(directory / "snapshots")) {
    for (const auto& entry : fs::directory_iterator(directory / "snapshots")) {
      if (is_snapshot_artifact(entry.path())) {
        fs::remove(entry.path());
      }
    }
  }
}

RunOutput::RunOutput(fs::path directory, SnapshotMetadata base, std::int64_t snapshot_every,
                     double snapshot_interval)
    : directory_(std::move(directory)), base_(std::move(base)), snapshot_every_(snapshot_every),
      snapshot_interval_(snapshot_interval) {
  // In a distributed run process 0 writes the files (the others take part in the snapshots).
  if (distributed::process_rank() == 0) {
    fs::create_directories(directory_ / "snapshots");
  }
}

namespace {
// The step of a snapshot file named step_N.h5, or none.
std::optional<std::int64_t> step_of_snapshot_name(const fs::path& path) {
  const std::string name = path.filename().string();
  if (!name.starts_with("step_") || !name.ends_with(".h5")) {
    return std::nullopt;
  }
  const std::string digits = name.substr(5, name.size() - 8);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  return std::stoll(digits);
}
} // namespace

void RunOutput::check_later_snapshots(const fs::path& directory, std::int64_t step, bool force,
                                      const std::string& snapshot) {
  std::size_t later = 0;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory / "snapshots", error)) {
    const std::optional<std::int64_t> snapshot_step = step_of_snapshot_name(entry.path());
    later += snapshot_step && *snapshot_step > step ? 1 : 0;
  }
  if (later > 0 && !force) {
    throw CaseError(snapshot, "--from",
                    std::to_string(later) + " later snapshot" + (later == 1 ? "" : "s") + " of " +
                        directory.string() + " (after step " + std::to_string(step) +
                        ") would be removed: --force replaces them, --out DIR continues elsewhere");
  }
}

void RunOutput::continue_run(const Simulation& simulation) {
  const std::int64_t step = simulation.steps_taken();
  std::vector<std::pair<std::int64_t, fs::path>> earlier;
  for (const auto& entry : fs::directory_iterator(directory_ / "snapshots")) {
    const std::optional<std::int64_t> snapshot_step = step_of_snapshot_name(entry.path());
    if (!snapshot_step) {
      continue;
    }
    if (*snapshot_step > step) {
      if (distributed::process_rank() == 0) {
        fs::remove(entry.path());
      }
      ++removed_later_;
    } else if (*snapshot_step < step && on_cadence(simulation, *snapshot_step)) {
      earlier.emplace_back(*snapshot_step, entry.path());
    }
  }
  std::sort(earlier.begin(), earlier.end());
  continued_from_ = step;
  for (const auto& [snapshot_step, path] : earlier) {
    const SnapshotClock clock = read_snapshot_clock(path);
    earlier_.push_back(
        {snapshot_step, clock.time, (fs::path("snapshots") / path.filename()).string(), {}});
  }
}

std::optional<fs::path> run_folder_of(const fs::path& snapshot) {
  const fs::path folder = fs::absolute(snapshot).parent_path();
  if (folder.filename() != "snapshots" ||
      !fs::is_regular_file(folder.parent_path() / "energy.csv")) {
    return std::nullopt;
  }
  return folder.parent_path();
}

bool RunOutput::on_cadence(const Simulation& simulation, std::int64_t step) const {
  if (step == 0 || (snapshot_every_ > 0 && step % snapshot_every_ == 0)) {
    return true;
  }
  // Which interval a time falls in, a step landing a rounding error short of a multiple counting
  // as on it (750 steps of 1e-4 s make 0.07499999999999999 s, three intervals of 0.025 s).
  const auto interval = [&](std::int64_t s) {
    return std::floor(simulation.time_at(s) / snapshot_interval_ + 1e-9);
  };
  return snapshot_interval_ > 0.0 && step > 0 && interval(step) > interval(step - 1);
}

bool RunOutput::snapshot_due(const Simulation& simulation, std::int64_t step) const {
  return last_step_ != step && step != 0 && on_cadence(simulation, step);
}

void RunOutput::write_snapshot(Simulation& simulation) {
  const std::int64_t step = simulation.steps_taken();
  if (last_step_ == step) {
    return;
  }
  if (continued_from_ == step && !on_cadence(simulation, step)) {
    // The snapshot continued from, an earlier segment's last: on disk already, not in the series.
    last_step_ = step;
    return;
  }
  const StateSnapshot state = simulation.borrow_state();
  SnapshotMetadata metadata = base_;
  metadata.step = step;
  metadata.time = simulation.time();
  metadata.state_hash = state_hash(state);
  metadata.energy_accounts = simulation.energy_accounts();
  char name[64];
  std::snprintf(name, sizeof name, "step_%09lld.h5", static_cast<long long>(step));
  const fs::path relative = fs::path("snapshots") / name;
  XdmfSnapshot entry{step, metadata.time, relative.string(), {}};
  entry.sets =
      revsph::write_snapshot(directory_ / relative, metadata, state,
                             [&](const ViewSink& sink) { simulation.derived_views(sink); });
  if (series_.empty()) {
    for (XdmfSnapshot& earlier : earlier_) {
      earlier.sets = entry.sets; // the same sets, fields and counts all along
      series_.push_back(std::move(earlier));
    }
    earlier_.clear();
  }
  series_.push_back(std::move(entry));
  ++written_;
  if (distributed::process_rank() == 0) {
    write_xdmf(xdmf(), simulation.info().dimension, series_);
  }
  last_step_ = step;
}

std::optional<fs::path> RunOutput::last_snapshot() const {
  if (series_.empty()) {
    return std::nullopt;
  }
  return directory_ / series_.back().file;
}

SnapshotMetadata run_metadata(const Simulation& simulation, const CaseFile& case_file,
                              std::optional<double> reference_energy, const RunEnd& end) {
  const SimulationInfo& info = simulation.info();
  SnapshotMetadata metadata;
  metadata.model = info.model;
  metadata.dimension = info.dimension;
  metadata.arithmetic = info.arithmetic;
  metadata.case_name = info.case_name;
  // Absolute, so that a restart from another folder names the same file (a built-in case keeps
  // its name); the inputs travel in the snapshot, which restarts without any of them.
  const fs::path source = case_file.source_name();
  std::error_code error;
  metadata.case_source =
      fs::is_regular_file(source, error) ? fs::absolute(source).string() : source.string();
  metadata.case_text = case_file.text();
  metadata.overrides = case_file.overrides();
  metadata.inputs = case_file.inputs().used();
  for (InputFile& input : metadata.inputs) {
    input.path = fs::absolute(input.path, error).string();
  }
  metadata.run_end_step = end.length.steps;
  metadata.run_end_time = end.length.t_end;
  metadata.run_end_origin = end.origin;
  metadata.dt = info.dt;
  metadata.reference_energy = reference_energy;
  metadata.code_version = build_info::version;
  metadata.git_commit = build_info::git_commit;
  metadata.build_type = build_info::build_type;
  metadata.build_flags = build_info::flags;
  return metadata;
}

} // namespace revsph::cli
