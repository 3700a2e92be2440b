#pragma once
// A point file: a user's particles one per row, their positions and any initial values of their
// set's fields, each with its unit ([[particles]] shape = "points", core/particle_blocks.hpp).
//
// CSV: a header row of `name [unit]` columns, then one row of numbers per particle; lines that
// start with '#' are comments, a UTF-8 byte-order mark before the header is skipped. The positions are the columns x, y (2D), z (3D) in metres; every
// other column is one component of a field, named as core/field_components.hpp spells it
// (velocity_x [m/s], entropy [J/(kg K)], distortion_unimodular_xy [1]).
//
// HDF5: one dataset per field at the file's root, (N) for a scalar and (N, C) for C components,
// each with a string attribute `unit`; `position` (N, D) in m holds the positions. Its columns are
// the datasets' components, named by the same rule: a file written with h5py from a snapshot's
// arrays (edited) reads back as the same columns.

#include "core/case_inputs.hpp"
#include "core/geometry.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revsph {

// One line: the file (and the line or dataset) and what is wrong.
class PointFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct PointColumn {
  std::string name; // "velocity_x"
  std::string unit; // "m/s", as written
  std::vector<double> values;
};

template <int D>
struct PointFile {
  std::vector<Vec<D>> positions;
  std::vector<PointColumn> columns; // every column but the positions, in the file's order
  std::string source;               // the file's path, for messages
  std::vector<std::size_t> lines;   // CSV: the line of each particle's row; HDF5: empty
};

// Where particle `row`'s value of `column` is, for a message: "fluid.csv line 7, column mass"
// (HDF5: "fluid.h5 row 5, column mass", rows counted from 0).
template <int D>
std::string point_place(const PointFile<D>& file, std::size_t row, std::string_view column);

// Reads a CSV or HDF5 point file from its bytes (told apart by its first bytes; a file named .h5,
// .hdf5 or .hdf without HDF5's signature is refused rather than read as CSV). Every value must be
// finite; a position column in another unit than m, a missing or repeated column, a row of the
// wrong length, two rows at the same position (naming both) and an empty file are refused.
template <int D>
PointFile<D> read_point_file(const InputFile& file);
// The same, of the file at `path`.
template <int D>
PointFile<D> read_point_file(const std::filesystem::path& path);

// Writes `file` as CSV (for tests and examples made in C++).
template <int D>
void write_point_csv(const std::filesystem::path& path, const PointFile<D>& file);

} // namespace revsph
