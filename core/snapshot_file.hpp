#pragma once
// Snapshot files (HDF5): the exact state of a simulation plus physical views for people.
//
// Layout (format "revsph-snapshot", version 1; see README "Snapshots"):
//   /                        attributes: format, format_version, model, dimension, arithmetic,
//                            case_name, case_source, case_text, overrides, step, time, dt,
//                            reference_energy (if known), state_hash, field_order, code_version,
//                            git_commit, build_type, build_flags; energy_accounts (names) and
//                            energy_account:NAME (values) if the model keeps energy accounts;
//                            run_end_step or run_end_time, and run_end_origin, if known
//   /inputs/N                uint8 (bytes,): the case's input files (point files, STL surfaces)
//                            byte for byte; attributes name (as the case writes it), path
//                            (absolute, where it was read) and sha256
//   /state/SET/VARIABLE      int64 (particles, components) or (particles,): the raw integers
//                            (IEEE bit patterns for float state); attributes unit, parity,
//                            components, scale_exponent, evolved, raw_kind
//   /particles/SET/NAME      float64 (particles, components) or (particles,): physical values of
//                            every state variable and of the model's derived views; attribute unit
//   /particles/SET/kind      float64 (particles,): the index of SET in the declaration order, so
//                            that merged point sets can be coloured by particle kind
// The layout follows each model's state declaration; nothing in here is written per model.

#include "core/arithmetic.hpp"
#include "core/case_inputs.hpp"
#include "core/energy.hpp"
#include "core/particle_view.hpp"
#include "core/state_snapshot.hpp"
#include "core/xdmf.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

inline constexpr const char* snapshot_format = "revsph-snapshot";
inline constexpr long long snapshot_format_version = 1;

class SnapshotError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct SnapshotMetadata {
  std::string model;
  int dimension = 2;
  Arithmetic arithmetic = Arithmetic::fixed;
  std::string case_name;
  std::string case_source;            // absolute file name, or built-in name, it came from
  std::string case_text;              // the case file as written
  std::vector<std::string> overrides; // --set key=value applied to it
  // The files the case reads besides itself, byte for byte: a restart reads these, not the disk.
  std::vector<InputFile> inputs;
  std::int64_t step = 0;
  double time = 0.0;
  double dt = 0.0;
  // Total energy at the first step of the run this state descends from (through restarts), so
  // that a restarted run reports its energy error against the original E(0).
  std::optional<double> reference_energy;
  // Energy exchanged with the outside so far (a heater's input, say; HasEnergyAccounts in
  // core/simulation.hpp), which the energy budget of a restarted run goes on from.
  std::vector<EnergyTerm> energy_accounts;
  // Where the run that wrote it ends, absolute (a step or a simulated time), and what said so
  // ("--steps 3000 given at step 0"): a run continued from it goes on to there. Unknown in files
  // written before snapshots kept it.
  std::optional<std::int64_t> run_end_step;
  std::optional<double> run_end_time;
  std::string run_end_origin;
  std::string state_hash;
  // Why the derived fields (density, forces, …) are missing, if they could not be computed for
  // this state (a restored state whose forces are not finite); empty normally.
  std::string derived_fields_error;
  std::string code_version;
  std::string git_commit;
  std::string build_type;
  std::string build_flags;
};

struct Snapshot {
  SnapshotMetadata metadata;
  StateSnapshot state;
};

// Writes `path` atomically: the file is written as `path` + ".tmp" and renamed into place, so a
// process killed while writing never leaves a partial file under the final name. Returns the
// particle sets and view datasets written (what an XDMF description of the file lists).
//
// The views come from `views(sink)`, written as they arrive. If that throws SimulationFault (the
// derived quantities of a state that cannot be evaluated), the file keeps the exact state and the
// views written so far, and its attribute derived_fields_error says why.
using ViewSource = std::function<void(const ViewSink&)>;
std::vector<XdmfParticleSet> write_snapshot(const std::filesystem::path& path,
                                            const SnapshotMetadata& metadata,
                                            const StateSnapshot& state, const ViewSource& views);
std::vector<XdmfParticleSet> write_snapshot(const std::filesystem::path& path,
                                            const SnapshotMetadata& metadata,
                                            const StateSnapshot& state,
                                            std::vector<ParticleView> views);

// Reads metadata and exact state. Throws SnapshotError, naming the file and what is wrong, for a
// missing, truncated or foreign file and for an incompatible format version. The state is not
// checked against the recorded hash here; verify/snapshot_check.hpp does that.
Snapshot read_snapshot(const std::filesystem::path& path);

// The step and time a snapshot file records, without its state (a continued run's series of
// earlier snapshots). Throws SnapshotError.
struct SnapshotClock {
  std::int64_t step = 0;
  double time = 0.0;
};
SnapshotClock read_snapshot_clock(const std::filesystem::path& path);

// True if the file starts with the HDF5 signature.
bool is_hdf5_file(const std::filesystem::path& path);
// True if these bytes (a file's, from its start) do.
bool has_hdf5_signature(std::string_view bytes);

// The physical-view dataset path of a set's variable: "/particles/SET/NAME".
std::string view_dataset(const std::string& particle_set, const std::string& name);

} // namespace revsph
