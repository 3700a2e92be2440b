// Writing snapshot files (core/snapshot_file.hpp). A state held in pieces by the processes of a
// distributed run (StateSnapshot::pieces) is written by process 0 alone, one chunk of one column
// at a time, each chunk streamed to it in global-index order (core/distributed/
// index_order_stream.hpp): the file is the one a one-process run writes, and no process ever
// holds the whole state.
#include "core/snapshot_file.hpp"

#include "core/distributed/index_order_stream.hpp"
#include "core/distributed/processes.hpp"
#include "core/fault.hpp"
#include "core/field_components.hpp"
#include "core/hdf5_handle.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <optional>
#include <span>

namespace revsph {

namespace {

using hdf5::Handle;
using hdf5::Hdf5Error;

constexpr std::size_t chunk_rows = std::size_t{1} << 16;

Handle open_or_create_group(hid_t parent, const std::string& name) {
  if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) {
    return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "cannot open " + name);
  }
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "cannot create group " + name);
}

// A dataset /GROUP/SET/NAME of (rows, components), or (rows,) for one component: the shape h5py
// users and XDMF expect. It is written a chunk of one column at a time (a hyperslab), from
// component-major values, so no transposed copy is made.
class ColumnDataset {
public:
  ColumnDataset(hid_t file, const std::string& group, const std::string& set,
                const std::string& name, hid_t file_type, std::size_t rows, int components)
      : name_(name) {
    const Handle outer = open_or_create_group(file, group);
    const Handle inner = open_or_create_group(outer.id(), set);
    const std::array<hsize_t, 2> dims{rows, static_cast<hsize_t>(components)};
    const Handle space(H5Screate_simple(components == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                       "cannot create a dataspace for " + name);
    dataset_ = Handle(H5Dcreate2(inner.id(), name.c_str(), file_type, space.id(), H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT),
                      H5Dclose, "cannot create dataset " + name);
  }

  // Rows [first, first + count) of column `component`.
  void write(int component, std::size_t first, hid_t memory_type, const void* values,
             std::size_t count) const {
    if (count == 0) {
      return;
    }
    const Handle space(H5Dget_space(dataset_.id()), H5Sclose, "unreadable dataset " + name_);
    const std::array<hsize_t, 2> start{first, static_cast<hsize_t>(component)};
    const std::array<hsize_t, 2> size{count, 1};
    if (H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start.data(), nullptr, size.data(),
                            nullptr) < 0) {
      throw Hdf5Error("cannot select rows of " + name_);
    }
    const hsize_t length = count;
    const Handle memory(H5Screate_simple(1, &length, nullptr), H5Sclose,
                        "cannot create a dataspace for " + name_);
    if (H5Dwrite(dataset_.id(), memory_type, memory.id(), space.id(), H5P_DEFAULT, values) < 0) {
      throw Hdf5Error("cannot write dataset " + name_);
    }
  }
  hid_t id() const { return dataset_.id(); }

private:
  std::string name_;
  Handle dataset_;
};

// One column's values in index order, given to `write(first_row, values)` chunk after chunk on
// the writing process (process 0): the column itself for a whole state, or the processes' pieces
// streamed there (collective).
template <class Write>
void for_each_chunk(const SetRows* rows, std::span<const std::int64_t> column, const Write& write) {
  if (rows == nullptr) {
    if (distributed::process_rank() == 0) {
      write(0, column);
    }
    return;
  }
  std::size_t first = 0;
  distributed::stream_in_index_order(rows->indices, column, rows->total, chunk_rows,
                                     [&](std::span<const std::int64_t> values) {
                                       write(first, values);
                                       first += values.size();
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
  if (m.run_end_step) {
    write_int_attribute(file, "run_end_step", *m.run_end_step);
  }
  if (m.run_end_time) {
    write_double_attribute(file, "run_end_time", *m.run_end_time);
  }
  if (!m.run_end_origin.empty()) {
    write_string_attribute(file, "run_end_origin", m.run_end_origin);
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

// The case's input files, byte for byte, so that a restart needs none of them on disk.
void write_inputs(hid_t file, const std::vector<InputFile>& inputs) {
  if (inputs.empty()) {
    return;
  }
  const Handle group(H5Gcreate2(file, "inputs", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                     "cannot create group /inputs");
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const InputFile& input = inputs[i];
    const std::string name = std::to_string(i);
    const hsize_t size = input.bytes.size();
    const Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose,
                       "cannot describe /inputs/" + name);
    const Handle dataset(H5Dcreate2(group.id(), name.c_str(), H5T_STD_U8LE, space.id(), H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT),
                         H5Dclose, "cannot create /inputs/" + name);
    if (size > 0 && H5Dwrite(dataset.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                             input.bytes.data()) < 0) {
      throw Hdf5Error("cannot write /inputs/" + name + " (" + input.name + ")");
    }
    hdf5::write_string_attribute(dataset.id(), "name", input.name);
    hdf5::write_string_attribute(dataset.id(), "path", input.path);
    hdf5::write_string_attribute(dataset.id(), "sha256", input.sha256);
  }
}

// The order of a view's columns (core/field_components.hpp): x, y, z; a tensor's xx, xy, ...
void write_component_names(hid_t dataset, int dimension, int components) {
  if (components > 1) {
    hdf5::write_strings_attribute(dataset, "component_names",
                                  component_labels(dimension, components));
  }
}

void write_field_attributes(hid_t dataset, const FieldSnapshot& field) {
  hdf5::write_string_attribute(dataset, "unit", field.info.unit);
  hdf5::write_string_attribute(dataset, "parity",
                               field.info.parity == Parity::odd ? "odd" : "even");
  hdf5::write_int_attribute(dataset, "components", field.info.components);
  hdf5::write_int_attribute(dataset, "scale_exponent", field.info.scale.exponent());
  hdf5::write_int_attribute(dataset, "evolved", field.info.evolved ? 1 : 0);
  hdf5::write_string_attribute(dataset, "raw_kind",
                               field.kind == RawKind::fixed_point ? "fixed_point" : "ieee_double");
}

// The file on the writing process. Every HDF5 step goes through attempt(): after the first
// failure it does nothing more, so that process 0 keeps taking part in the streams the other
// processes are in (leaving them would leave those waiting), and the failure is reported at the
// end, on every process alike.
class SnapshotWriter {
public:
  template <class Step>
  void attempt(const Step& step) {
    if (distributed::process_rank() != 0 || !error_.empty()) {
      return;
    }
    try {
      step();
    } catch (const Hdf5Error& error) {
      error_ = error.what();
    }
  }
  // The failure, if any, known to every process (collective in a distributed run).
  std::string error() const {
    return distributed::process_count() > 1 ? distributed::broadcast_from_first(error_) : error_;
  }
  std::optional<Handle> file;

private:
  std::string error_;
};

} // namespace

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
  SnapshotWriter writer;
  writer.attempt([&] {
    writer.file.emplace(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                        H5Fclose, "cannot create " + temporary.string());
    write_metadata(writer.file->id(), metadata, state);
    write_inputs(writer.file->id(), metadata.inputs);
  });
  std::vector<XdmfParticleSet> sets;
  auto set_of = [&](const std::string& name, std::size_t count) -> XdmfParticleSet& {
    for (XdmfParticleSet& set : sets) {
      if (set.name == name) {
        return set;
      }
    }
    return sets.emplace_back(XdmfParticleSet{name, count, {}});
  };

  // The exact state, and its physical values for people, from one stream of each column.
  for (const FieldSnapshot& field : state.fields) {
    const std::size_t total = whole_count(state, field);
    const std::string& set = field.info.particle_set;
    std::optional<ColumnDataset> raw;
    std::optional<ColumnDataset> physical;
    writer.attempt([&] {
      raw.emplace(writer.file->id(), "state", set, field.info.name, H5T_STD_I64LE, total,
                  field.info.components);
      physical.emplace(writer.file->id(), "particles", set, field.info.name, H5T_IEEE_F64LE, total,
                       field.info.components);
    });
    std::vector<double> converted;
    for (int c = 0; c < field.info.components; ++c) {
      const auto column =
          field.raw().subspan(static_cast<std::size_t>(c) * field.count, field.count);
      for_each_chunk(
          state.rows_of(set), column, [&](std::size_t first, std::span<const std::int64_t> values) {
            writer.attempt([&] {
              raw->write(c, first, H5T_NATIVE_INT64, values.data(), values.size());
              converted.resize(values.size());
              for (std::size_t i = 0; i < values.size(); ++i) {
                converted[i] = field.real_of(values[i]);
              }
              physical->write(c, first, H5T_NATIVE_DOUBLE, converted.data(), converted.size());
            });
          });
    }
    writer.attempt([&] {
      write_field_attributes(raw->id(), field);
      hdf5::write_string_attribute(physical->id(), "unit", field.info.unit);
      write_component_names(physical->id(), metadata.dimension, field.info.components);
    });
    set_of(set, total).fields.push_back({field.info.name, field.info.components});
  }

  // The model's derived views, as they arrive (each process's rows of its sets, like the state).
  try {
    views([&](ParticleView&& view) {
      XdmfParticleSet& set = set_of(view.particle_set, 0);
      const SetRows* rows = state.rows_of(view.particle_set);
      const std::size_t own = rows != nullptr ? rows->indices.size() : set.count;
      const auto components = static_cast<std::size_t>(view.components);
      if (view.values.size() != own * components) {
        throw SnapshotError("writing snapshot " + path.string() + ": view " + view.particle_set +
                            "/" + view.name + " does not match its particle set");
      }
      std::optional<ColumnDataset> dataset;
      writer.attempt([&] {
        dataset.emplace(writer.file->id(), "particles", view.particle_set, view.name,
                        H5T_IEEE_F64LE, set.count, view.components);
        hdf5::write_string_attribute(dataset->id(), "unit", view.unit);
        write_component_names(dataset->id(), metadata.dimension, view.components);
      });
      std::vector<std::int64_t> bits(own);
      for (std::size_t c = 0; c < components; ++c) {
        for (std::size_t i = 0; i < own; ++i) {
          bits[i] = std::bit_cast<std::int64_t>(view.values[c * own + i]);
        }
        for_each_chunk(rows, bits, [&](std::size_t first, std::span<const std::int64_t> values) {
          writer.attempt([&] {
            // The doubles' own bits, back as doubles.
            dataset->write(static_cast<int>(c), first, H5T_NATIVE_DOUBLE, values.data(),
                           values.size());
          });
        });
      }
      set.fields.push_back({view.name, view.components});
    });
  } catch (const SimulationFault& fault) {
    // The exact state is still worth keeping (it is what a run starts or stops from). A
    // distributed run cannot go on writing: the other processes may be in the views' exchanges.
    if (!state.pieces.empty()) {
      throw;
    }
    writer.attempt([&] {
      hdf5::write_string_attribute(writer.file->id(), "derived_fields_error", fault.what());
    });
  }

  // Each set's index in the declaration order, so merged point sets can be coloured by kind.
  for (std::size_t k = 0; k < sets.size(); ++k) {
    XdmfParticleSet& set = sets[k];
    writer.attempt([&] {
      const ColumnDataset kind(writer.file->id(), "particles", set.name, "kind", H5T_IEEE_F64LE,
                               set.count, 1);
      hdf5::write_string_attribute(kind.id(), "unit", "1");
      const std::vector<double> values(std::min(set.count, chunk_rows), static_cast<double>(k));
      for (std::size_t first = 0; first < set.count; first += chunk_rows) {
        kind.write(0, first, H5T_NATIVE_DOUBLE, values.data(),
                   std::min(chunk_rows, set.count - first));
      }
    });
    set.fields.push_back({"kind", 1});
  }
  writer.attempt([&] { writer.file->close("cannot finish writing " + temporary.string()); });

  const std::string error = writer.error();
  if (!error.empty()) {
    writer.file.reset();
    if (distributed::process_rank() == 0) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
    }
    throw SnapshotError("writing snapshot " + path.string() + ": " + error);
  }
  if (distributed::process_rank() == 0) {
    std::filesystem::rename(temporary, path);
  }
  return sets;
}

} // namespace revsph
