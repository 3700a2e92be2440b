#include "core/snapshot_file.hpp"

#include "core/fault.hpp"

#include "core/hdf5_handle.hpp"

#include <array>
#include <fstream>
#include <set>
#include <span>

namespace revsph {

namespace {

using hdf5::Handle;
using hdf5::Hdf5Error;

Handle create_group(hid_t parent, const std::string& name) {
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "cannot create group " + name);
}

Handle open_or_create_group(hid_t parent, const std::string& name) {
  if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) {
    return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "cannot open " + name);
  }
  return create_group(parent, name);
}

// Rows are particles: (count, components), or (count,) for scalars, the shape h5py users and
// XDMF expect. Storage is component-major: column(c) gives component c of every particle, and
// HDF5 writes it into its column of the dataset (a hyperslab), so no transposed copy is made.
template <class Value, class Column>
void write_matrix(hid_t group, const std::string& name, hid_t file_type, hid_t memory_type,
                  std::size_t count, int components, const Column& column) {
  const std::array<hsize_t, 2> dims{count, static_cast<hsize_t>(components)};
  const Handle space(H5Screate_simple(components == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                     "cannot create a dataspace for " + name);
  const Handle dataset(
      H5Dcreate2(group, name.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, "cannot create dataset " + name);
  if (count == 0) {
    return;
  }
  const hsize_t length = count;
  const Handle memory(H5Screate_simple(1, &length, nullptr), H5Sclose,
                      "cannot create a dataspace for " + name);
  for (int c = 0; c < components; ++c) {
    const std::span<const Value> values = column(c);
    if (components > 1) {
      const std::array<hsize_t, 2> start{0, static_cast<hsize_t>(c)};
      const std::array<hsize_t, 2> size{count, 1};
      if (H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start.data(), nullptr, size.data(),
                              nullptr) < 0) {
        throw Hdf5Error("cannot select column " + std::to_string(c) + " of " + name);
      }
    }
    if (H5Dwrite(dataset.id(), memory_type, memory.id(), space.id(), H5P_DEFAULT, values.data()) <
        0) {
      throw Hdf5Error("cannot write dataset " + name);
    }
  }
}

// Component c of a component-major array of `count` particles.
template <class Value>
std::span<const Value> component_of(std::span<const Value> component_major, std::size_t count,
                                    int c) {
  return component_major.subspan(static_cast<std::size_t>(c) * count, count);
}

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

void write_state_field(hid_t file, const FieldSnapshot& field) {
  const Handle state = open_or_create_group(file, "state");
  const Handle set = open_or_create_group(state.id(), field.info.particle_set);
  write_matrix<std::int64_t>(set.id(), field.info.name, H5T_STD_I64LE, H5T_NATIVE_INT64,
                             field.count, field.info.components,
                             [&](int c) { return component_of(field.raw(), field.count, c); });
  const Handle dataset(H5Dopen2(set.id(), field.info.name.c_str(), H5P_DEFAULT), H5Dclose,
                       "cannot reopen dataset " + field.info.name);
  hdf5::write_string_attribute(dataset.id(), "unit", field.info.unit);
  hdf5::write_string_attribute(dataset.id(), "parity",
                               field.info.parity == Parity::odd ? "odd" : "even");
  hdf5::write_int_attribute(dataset.id(), "components", field.info.components);
  hdf5::write_int_attribute(dataset.id(), "scale_exponent", field.info.scale.exponent());
  hdf5::write_int_attribute(dataset.id(), "evolved", field.info.evolved ? 1 : 0);
  hdf5::write_string_attribute(dataset.id(), "raw_kind",
                               field.kind == RawKind::fixed_point ? "fixed_point" : "ieee_double");
}

// A dataset /particles/SET/NAME of `components` columns given one at a time by column(c).
template <class Column>
void write_view_columns(hid_t file, const std::string& particle_set, const std::string& name,
                        const std::string& unit, std::size_t count, int components,
                        const Column& column) {
  const Handle particles = open_or_create_group(file, "particles");
  const Handle set = open_or_create_group(particles.id(), particle_set);
  write_matrix<double>(set.id(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, count, components,
                       column);
  const Handle dataset(H5Dopen2(set.id(), name.c_str(), H5P_DEFAULT), H5Dclose,
                       "cannot reopen dataset " + name);
  hdf5::write_string_attribute(dataset.id(), "unit", unit);
}

void write_view(hid_t file, const ParticleView& view, std::size_t count) {
  write_view_columns(
      file, view.particle_set, view.name, view.unit, count, view.components,
      [&](int c) { return component_of(std::span<const double>(view.values), count, c); });
}

// Physical values of a state field, for people, converted one component at a time.
void write_view_of_field(hid_t file, const FieldSnapshot& field) {
  std::vector<double> column(field.count);
  write_view_columns(file, field.info.particle_set, field.info.name, field.info.unit, field.count,
                     field.info.components, [&](int c) {
                       for (std::size_t i = 0; i < field.count; ++i) {
                         column[i] = field.real(c, i);
                       }
                       return std::span<const double>(column);
                     });
}

void write_metadata(hid_t file, const SnapshotMetadata& m, const StateSnapshot& state) {
  using namespace hdf5;
  write_string_attribute(file, "format", snapshot_format);
  write_int_attribute(file, "format_version", snapshot_format_version);
  write_string_attribute(file, "model", m.model);
  write_int_attribute(file, "dimension", m.dimension);
  write_string_attribute(file, "arithmetic", std::string(to_string(m.arithmetic)));
  write_string_attribute(file, "case_name", m.case_name);
  write_string_attribute(file, "case_source", m.case_source);
  write_string_attribute(file, "case_text", m.case_text);
  write_strings_attribute(file, "overrides", m.overrides);
  write_int_attribute(file, "step", m.step);
  write_double_attribute(file, "time", m.time);
  write_double_attribute(file, "dt", m.dt);
  if (m.reference_energy) {
    write_double_attribute(file, "reference_energy", *m.reference_energy);
  }
  if (!m.energy_accounts.empty()) {
    std::vector<std::string> names;
    for (const EnergyTerm& account : m.energy_accounts) {
      names.push_back(account.name);
      write_double_attribute(file, "energy_account:" + account.name, account.value);
    }
    write_strings_attribute(file, "energy_accounts", names);
  }
  write_string_attribute(file, "state_hash", m.state_hash);
  if (!m.derived_fields_error.empty()) {
    write_string_attribute(file, "derived_fields_error", m.derived_fields_error);
  }
  std::vector<std::string> order;
  for (const FieldSnapshot& field : state.fields) {
    order.push_back(field.info.particle_set + "/" + field.info.name);
  }
  write_strings_attribute(file, "field_order", order);
  write_string_attribute(file, "code_version", m.code_version);
  write_string_attribute(file, "git_commit", m.git_commit);
  write_string_attribute(file, "build_type", m.build_type);
  write_string_attribute(file, "build_flags", m.build_flags);
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
  m.step = read_int_attribute(file, "step");
  m.time = read_double_attribute(file, "time");
  m.dt = read_double_attribute(file, "dt");
  if (has_attribute(file, "reference_energy")) {
    m.reference_energy = read_double_attribute(file, "reference_energy");
  }
  if (has_attribute(file, "energy_accounts")) {
    for (const std::string& name : read_strings_attribute(file, "energy_accounts")) {
      m.energy_accounts.push_back({name, read_double_attribute(file, "energy_account:" + name)});
    }
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

bool is_hdf5_file(const std::filesystem::path& path) {
  static constexpr char signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  return in.read(head, 8) && std::equal(head, head + 8, signature);
}

std::vector<XdmfParticleSet> write_snapshot(const std::filesystem::path& path,
                                            const SnapshotMetadata& metadata,
                                            const StateSnapshot& state,
                                            std::vector<ParticleView> views) {
  return write_snapshot(path, metadata, state, [&](const ViewSink& sink) {
    for (ParticleView& view : views) {
      sink(std::move(view));
    }
  });
}

std::vector<XdmfParticleSet> write_snapshot(const std::filesystem::path& path,
                                            const SnapshotMetadata& metadata,
                                            const StateSnapshot& state, const ViewSource& views) {
  hdf5::silence_library_errors();
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  std::vector<XdmfParticleSet> sets;
  auto set_of = [&](const std::string& name, std::size_t count) -> XdmfParticleSet& {
    for (XdmfParticleSet& set : sets) {
      if (set.name == name) {
        return set;
      }
    }
    return sets.emplace_back(XdmfParticleSet{name, count, {}});
  };
  try {
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                "cannot create " + temporary.string());
    write_metadata(file.id(), metadata, state);
    for (const FieldSnapshot& field : state.fields) {
      write_state_field(file.id(), field);
      write_view_of_field(file.id(), field);
      set_of(field.info.particle_set, field.count)
          .fields.push_back({field.info.name, field.info.components});
    }
    try {
      views([&](ParticleView&& view) {
        XdmfParticleSet& set = set_of(view.particle_set, 0);
        if (view.values.size() != set.count * static_cast<std::size_t>(view.components)) {
          throw Hdf5Error("view " + view.particle_set + "/" + view.name +
                          " does not match its particle set");
        }
        write_view(file.id(), view, set.count);
        set.fields.push_back({view.name, view.components});
      });
    } catch (const SimulationFault& fault) {
      // The exact state is still worth keeping (it is what a run starts or stops from).
      hdf5::write_string_attribute(file.id(), "derived_fields_error", fault.what());
    }
    for (std::size_t k = 0; k < sets.size(); ++k) {
      XdmfParticleSet& set = sets[k];
      const ParticleView kind{set.name, "kind", "1", 1,
                              std::vector<double>(set.count, static_cast<double>(k))};
      write_view(file.id(), kind, set.count);
      set.fields.push_back({"kind", 1});
    }
    file.close("cannot finish writing " + temporary.string());
  } catch (const Hdf5Error& error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw SnapshotError("writing snapshot " + path.string() + ": " + error.what());
  }
  std::filesystem::rename(temporary, path);
  return sets;
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
