#pragma once
// The output directory of a run:
//   energy.csv            energy terms every output.energy_every steps
//   snapshots/step_N.h5   snapshots (core/snapshot_file.hpp), every output.snapshot_every steps,
//                         at the start and at the end; each written atomically
//   run.xdmf              the snapshot series for ParaView, rewritten after each snapshot
//   summary.json          what ran and how it ended, written at the end (also after a failure)

#include "core/case_file.hpp"
#include "core/run_settings.hpp"
#include "core/simulation.hpp"
#include "core/snapshot_file.hpp"
#include "core/xdmf.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace revsph::cli {

class RunOutput {
public:
  // Refuses (CaseError on key "--out") a path that is a file, or a non-empty directory unless
  // `force`; with `force`, removes the files a previous run left there. Nothing is created.
  static void check_directory(const std::filesystem::path& directory, bool force,
                              const std::string& case_source);
  // Refuses (CaseError on key "--from", naming `snapshot`) to continue the run of `directory` from
  // step `step` when it holds snapshots after that step, which the continuation would replace,
  // unless `force`. Touches nothing.
  static void check_later_snapshots(const std::filesystem::path& directory, std::int64_t step,
                                    bool force, const std::string& snapshot);
  // Refuses (CaseError on key "--out") a directory that cannot be created: its nearest existing
  // ancestor is not a directory, or this process may not write into it. Touches nothing, so the
  // run calls it before the case's set-up.
  static void check_creatable(const std::filesystem::path& directory,
                              const std::string& case_source);

  // Creates the directory. `base` carries what every snapshot records about the case and build.
  RunOutput(std::filesystem::path directory, SnapshotMetadata base, std::int64_t snapshot_every,
            double snapshot_interval = 0.0);

  // A run that continues the run of `directory` from step `step` (docs/restart.md): its
  // snapshots before that step stay and lead run.xdmf's series; those after it, which the
  // continuation replaces, are removed (how many: removed_later_snapshots()). The series lists
  // what the run that never stopped writes: the snapshots on the output cadence and the last;
  // an earlier segment's last snapshot off the cadence stays on disk, out of the series.
  // (check_later_snapshots, before, asks for --force to remove any.)
  void continue_run(const Simulation& simulation);
  std::size_t removed_later_snapshots() const { return removed_later_; }

  bool snapshot_due(const Simulation& simulation, std::int64_t step) const;
  // On the output cadence: step 0, every snapshot_every steps, and the first step past each
  // multiple of snapshot_interval in simulated time.
  bool on_cadence(const Simulation& simulation, std::int64_t step) const;
  // Writes the snapshot of the current state and rewrites run.xdmf. Throws SnapshotError.
  // If the model cannot compute its derived fields for this state, the snapshot holds the exact
  // state without them and says why (attribute derived_fields_error).
  void write_snapshot(Simulation& simulation);
  // E(0) of the run, recorded in every later snapshot.
  void set_reference_energy(double total) { base_.reference_energy = total; }

  const std::filesystem::path& directory() const { return directory_; }
  std::filesystem::path energy_csv() const { return directory_ / "energy.csv"; }
  std::filesystem::path summary_json() const { return directory_ / "summary.json"; }
  std::filesystem::path xdmf() const { return directory_ / "run.xdmf"; }
  std::optional<std::filesystem::path> last_snapshot() const;
  // Written by this run (a continued run's series also holds the earlier ones).
  std::size_t snapshot_count() const { return written_; }

private:
  std::filesystem::path directory_;
  SnapshotMetadata base_;
  std::int64_t snapshot_every_;
  double snapshot_interval_;
  std::optional<std::int64_t> last_step_;
  std::vector<XdmfSnapshot> series_;
  std::vector<XdmfSnapshot> earlier_; // a continued run's, their sets those of its first snapshot
  std::size_t removed_later_ = 0;
  std::size_t written_ = 0;
  std::optional<std::int64_t> continued_from_; // the step continued from, its snapshot on disk
};

// The run folder a snapshot belongs to: DIR for DIR/snapshots/step_N.h5 when DIR holds a run's
// energy.csv, none otherwise.
std::optional<std::filesystem::path> run_folder_of(const std::filesystem::path& snapshot);

// Snapshot metadata common to every snapshot of a run (everything but step, time and hash): the
// case with its source made absolute and its input files, and where the run ends.
SnapshotMetadata run_metadata(const Simulation& simulation, const CaseFile& case_file,
                              std::optional<double> reference_energy, const RunEnd& end);

} // namespace revsph::cli
