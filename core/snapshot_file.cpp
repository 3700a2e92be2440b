#include "core/snapshot_file.hpp"

#include "core/fault.hpp"

#include "core/hdf5_handle.hpp"
#include "core/sha256.hpp"

#include <array>
#include <fstream>
#include <set>
#include <span>

namespace revsph {

namespace {

using hdf5::Handle;
using hdf5::Hdf5Error;

std::vector<std::int64_t> read_raw_matrix(hid_t group, const std::string& name, std::size_t count,
                                          int components) {
  const Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose,
                       "missing dataset " + name);
  const Handle space(H5Dget_space(dataset.id()), H5Sclose, "unreadable dataset " + name);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::array<hsize_t, 2> dims{0, 0};
  if (rank != (components == 1 ? 1 : 2) ||
      H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr) < 0 || dims[0] != count ||
      (rank == 2 && dims[1] != static_cast<hsize_t>(components))) {
    throw Hdf5Error("dataset " + name + " does not have the declared shape");
  }
  std::vector<std::int64_t> rows(count * static_cast<std::size_t>(components));
  if (!rows.empty() &&
      H5Dread(dataset.id(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()) < 0) {
    throw Hdf5Error("cannot read dataset " + name + " (truncated file?)");
  }
  std::vector<std::int64_t> component_major(rows.size());
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < components; ++c) {
      component_major[static_cast<std::size_t>(c) * count + i] =
          rows[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
    }
  }
  return component_major;
}

// The case's input files (/inputs/N), each checked against its recorded SHA-256.
std::vector<InputFile> read_inputs(hid_t file) {
  std::vector<InputFile> inputs;
  if (H5Lexists(file, "inputs", H5P_DEFAULT) <= 0) {
    return inputs;
  }
  const Handle group(H5Gopen2(file, "inputs", H5P_DEFAULT), H5Gclose, "unreadable group /inputs");
  H5G_info_t info{};
  if (H5Gget_info(group.id(), &info) < 0) {
    throw Hdf5Error("unreadable group /inputs");
  }
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const std::string where = "/inputs/" + std::to_string(i);
    const Handle dataset(H5Dopen2(group.id(), std::to_string(i).c_str(), H5P_DEFAULT), H5Dclose,
                         "missing dataset " + where);
    const Handle space(H5Dget_space(dataset.id()), H5Sclose, "unreadable dataset " + where);
    hsize_t size = 0;
    if (H5Sget_simple_extent_ndims(space.id()) != 1 ||
        H5Sget_simple_extent_dims(space.id(), &size, nullptr) < 0) {
      throw Hdf5Error("dataset " + where + " is not a list of bytes");
    }
    InputFile input;
    input.bytes.resize(size);
    if (size > 0 && H5Dread(dataset.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                            input.bytes.data()) < 0) {
      throw Hdf5Error("cannot read dataset " + where + " (truncated file?)");
    }
    input.name = hdf5::read_string_attribute(dataset.id(), "name");
    input.path = hdf5::read_string_attribute(dataset.id(), "path");
    input.sha256 = hdf5::read_string_attribute(dataset.id(), "sha256");
    if (sha256_hex(input.bytes) != input.sha256) {
      throw Hdf5Error(where + " (" + input.name + "): its bytes do not have their recorded sha256");
    }
    inputs.push_back(std::move(input));
  }
  return inputs;
}

SnapshotMetadata read_metadata(hid_t file) {
  using namespace hdf5;
  SnapshotMetadata m;
  m.model = read_string_attribute(file, "model");
  m.dimension = static_cast<int>(read_int_attribute(file, "dimension"));
  const std::string arithmetic = read_string_attribute(file, "arithmetic");
  if (arithmetic != "fixed" && arithmetic != "float") {
    throw Hdf5Error("unknown arithmetic '" + arithmetic + "'");
  }
  m.arithmetic = arithmetic == "fixed" ? Arithmetic::fixed : Arithmetic::floating;
  m.case_name = read_string_attribute(file, "case_name");
  m.case_source = read_string_attribute(file, "case_source");
  m.case_text = read_string_attribute(file, "case_text");
  m.overrides = read_strings_attribute(file, "overrides");
  m.inputs = read_inputs(file);
  m.step = read_int_attribute(file, "step");
  m.time = read_double_attribute(file, "time");
  m.dt = read_double_attribute(file, "dt");
  if (has_attribute(file, "reference_energy")) {
    m.reference_energy = read_double_attribute(file, "reference_energy");
  }
  if (has_attribute(file, "energy_accounts")) {
    for (const std::string& name : read_strings_attribute(file, "energy_accounts")) {
      // Every process reads the same file.
      m.energy_accounts.push_back({name, RunTotal::same_on_every_process(read_double_attribute(
                                             file, "energy_account:" + name))});
    }
  }
  if (has_attribute(file, "run_end_step")) {
    m.run_end_step = read_int_attribute(file, "run_end_step");
  }
  if (has_attribute(file, "run_end_time")) {
    m.run_end_time = read_double_attribute(file, "run_end_time");
  }
  if (has_attribute(file, "run_end_origin")) {
    m.run_end_origin = read_string_attribute(file, "run_end_origin");
  }
  m.state_hash = read_string_attribute(file, "state_hash");
  if (has_attribute(file, "derived_fields_error")) {
    m.derived_fields_error = read_string_attribute(file, "derived_fields_error");
  }
  m.code_version = read_string_attribute(file, "code_version");
  m.git_commit = read_string_attribute(file, "git_commit");
  m.build_type = read_string_attribute(file, "build_type");
  m.build_flags = read_string_attribute(file, "build_flags");
  return m;
}

FieldSnapshot read_state_field(hid_t file, const std::string& set_and_name) {
  const std::size_t slash = set_and_name.find('/');
  if (slash == std::string::npos) {
    throw Hdf5Error("malformed field name '" + set_and_name + "'");
  }
  FieldSnapshot field;
  field.info.particle_set = set_and_name.substr(0, slash);
  field.info.name = set_and_name.substr(slash + 1);
  const std::string path = "/state/" + set_and_name;
  const Handle dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose,
                       "missing dataset " + path);
  field.info.unit = hdf5::read_string_attribute(dataset.id(), "unit");
  const std::string parity = hdf5::read_string_attribute(dataset.id(), "parity");
  if (parity != "odd" && parity != "even") {
    throw Hdf5Error(path + ": parity '" + parity + "'");
  }
  field.info.parity = parity == "odd" ? Parity::odd : Parity::even;
  const long long components = hdf5::read_int_attribute(dataset.id(), "components");
  if (components < 1 || components > 9) {
    throw Hdf5Error(path + ": " + std::to_string(components) + " components");
  }
  field.info.components = static_cast<int>(components);
  const long long exponent = hdf5::read_int_attribute(dataset.id(), "scale_exponent");
  if (exponent < -1100 || exponent > 1100) {
    throw Hdf5Error(path + ": scale exponent " + std::to_string(exponent));
  }
  field.info.scale = fixedpoint::Scale(static_cast<int>(exponent));
  field.info.evolved = hdf5::read_int_attribute(dataset.id(), "evolved") != 0;
  const std::string raw_kind = hdf5::read_string_attribute(dataset.id(), "raw_kind");
  if (raw_kind != "fixed_point" && raw_kind != "ieee_double") {
    throw Hdf5Error(path + ": raw kind '" + raw_kind + "'");
  }
  field.kind = raw_kind == "fixed_point" ? RawKind::fixed_point : RawKind::ieee_double;
  const Handle space(H5Dget_space(dataset.id()), H5Sclose, "unreadable dataset " + path);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(space.id()) < 1 ||
      H5Sget_simple_extent_dims(space.id(), dims, nullptr) < 0) {
    throw Hdf5Error("unreadable dataset " + path);
  }
  field.count = static_cast<std::size_t>(dims[0]);
  const Handle set(H5Gopen2(file, ("/state/" + field.info.particle_set).c_str(), H5P_DEFAULT),
                   H5Gclose, "missing group /state/" + field.info.particle_set);
  field.bits = read_raw_matrix(set.id(), field.info.name, field.count, field.info.components);
  return field;
}

} // namespace

std::string view_dataset(const std::string& particle_set, const std::string& name) {
  return "/particles/" + particle_set + "/" + name;
}

bool has_hdf5_signature(std::string_view bytes) {
  static constexpr char signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  return bytes.starts_with(std::string_view(signature, 8));
}

bool is_hdf5_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  return in.read(head, 8) && has_hdf5_signature(std::string_view(head, 8));
}

SnapshotClock read_snapshot_clock(const std::filesystem::path& path) {
  hdf5::silence_library_errors();
  try {
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                      "cannot open the file (truncated or damaged HDF5)");
    return {hdf5::read_int_attribute(file.id(), "step"),
            hdf5::read_double_attribute(file.id(), "time")};
  } catch (const Hdf5Error& error) {
    throw SnapshotError(path.string() + ": " + error.what());
  }
}

Snapshot read_snapshot(const std::filesystem::path& path) {
  hdf5::silence_library_errors();
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) {
    throw SnapshotError(name + ": no such snapshot file");
  }
  if (!is_hdf5_file(path)) {
    throw SnapshotError(name + ": not an HDF5 file (a revsph snapshot is one)");
  }
  try {
    Handle file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                "cannot open the file (truncated or damaged HDF5)");
    if (!hdf5::has_attribute(file.id(), "format") ||
        hdf5::read_string_attribute(file.id(), "format") != snapshot_format) {
      throw SnapshotError(name + ": not a revsph snapshot (no format attribute '" +
                          std::string(snapshot_format) + "')");
    }
    const long long version = hdf5::read_int_attribute(file.id(), "format_version");
    if (version != snapshot_format_version) {
      throw SnapshotError(name + ": written in snapshot format version " + std::to_string(version) +
                          "; this revsph reads version " + std::to_string(snapshot_format_version));
    }
    Snapshot snapshot;
    snapshot.metadata = read_metadata(file.id());
    std::set<std::string> seen;
    for (const std::string& field : hdf5::read_strings_attribute(file.id(), "field_order")) {
      if (!seen.insert(field).second) {
        throw Hdf5Error("field " + field + " listed twice");
      }
      snapshot.state.fields.push_back(read_state_field(file.id(), field));
    }
    return snapshot;
  } catch (const Hdf5Error& error) {
    throw SnapshotError(name + ": " + error.what());
  }
}

} // namespace revsph
