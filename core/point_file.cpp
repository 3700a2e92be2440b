#include "core/point_file.hpp"

#include "core/field_components.hpp"
#include "core/hdf5_handle.hpp"
#include "core/snapshot_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <set>
#include <sstream>

namespace revsph {

namespace {

constexpr const char* position_names[] = {"x", "y", "z"};

std::string trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) {
    return "";
  }
  const std::size_t last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) {
      return cells;
    }
    start = comma + 1;
  }
}

// Where the positions and the fields' columns are, from the names; checks them.
template <int D>
struct ColumnPlan {
  std::array<std::size_t, D> position{};
  std::vector<std::size_t> fields; // indices of the other columns, in order
};

template <int D>
ColumnPlan<D> plan_columns(const std::string& where, const std::vector<PointColumn>& columns) {
  ColumnPlan<D> plan;
  std::array<bool, D> found{};
  std::set<std::string> seen;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const PointColumn& column = columns[c];
    if (!seen.insert(column.name).second) {
      throw PointFileError(where + ": column " + column.name + " appears twice");
    }
    bool is_position = false;
    for (int k = 0; k < 3; ++k) {
      if (column.name == position_names[k]) {
        if (k >= D) {
          throw PointFileError(where + ": a column " + column.name + " in a " + std::to_string(D) +
                               "D case");
        }
        if (column.unit != "m") {
          throw PointFileError(where + ": position " + column.name + " is in [" + column.unit +
                               "]; positions are in [m]");
        }
        plan.position[k] = c;
        found[k] = true;
        is_position = true;
      }
    }
    if (!is_position) {
      plan.fields.push_back(c);
    }
  }
  for (int k = 0; k < D; ++k) {
    if (!found[k]) {
      throw PointFileError(where + ": no position column " + position_names[k] + " [m]");
    }
  }
  return plan;
}

// Two particles at one place would be one particle counted twice (and a file's values could
// reach only one of them): refused, naming both rows.
template <int D>
void refuse_repeated_positions(const PointFile<D>& file) {
  std::vector<std::size_t> order(file.positions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return file.positions[a] < file.positions[b];
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t first = order[k - 1];
    const std::size_t second = order[k];
    if (file.positions[first] == file.positions[second]) {
      const std::string row = file.lines.empty() ? "row " : "line ";
      const auto number = [&](std::size_t i) {
        return std::to_string(file.lines.empty() ? i : file.lines[i]);
      };
      throw PointFileError(file.source + " " + row + number(second) + ": the same position as " +
                           row + number(first) + " (two particles at one place)");
    }
  }
}

template <int D>
PointFile<D> assemble(const std::string& where, std::vector<PointColumn> columns,
                      std::vector<std::size_t> lines) {
  const ColumnPlan<D> plan = plan_columns<D>(where, columns);
  PointFile<D> file;
  file.source = where;
  file.lines = std::move(lines);
  const std::size_t count = columns.front().values.size();
  if (count == 0) {
    throw PointFileError(where + ": no particles (a header and no rows)");
  }
  file.positions.resize(count);
  for (int k = 0; k < D; ++k) {
    const std::vector<double>& values = columns[plan.position[k]].values;
    for (std::size_t i = 0; i < count; ++i) {
      file.positions[i][k] = values[i];
    }
  }
  for (const std::size_t c : plan.fields) {
    file.columns.push_back(std::move(columns[c]));
  }
  refuse_repeated_positions<D>(file);
  return file;
}

// "velocity_x [m/s]" -> name and unit; a column without a unit is refused, since a number alone
// does not say what it measures.
PointColumn column_of_header(const std::string& where, std::string_view cell) {
  const std::string text = trimmed(cell);
  const std::size_t open = text.find('[');
  if (open == std::string::npos || text.back() != ']') {
    throw PointFileError(where + ": header column \"" + text +
                         "\" has no unit: write name [unit], e.g. velocity_x [m/s]");
  }
  PointColumn column;
  column.name = trimmed(std::string_view(text).substr(0, open));
  column.unit = trimmed(std::string_view(text).substr(open + 1, text.size() - open - 2));
  if (column.name.empty()) {
    throw PointFileError(where + ": header column \"" + text + "\" has no name");
  }
  return column;
}

template <int D>
PointFile<D> read_csv(const InputFile& input) {
  const std::string& path = input.path;
  std::istringstream in(input.bytes);
  std::vector<PointColumn> columns;
  std::vector<std::size_t> lines;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    // A byte-order mark, which spreadsheet programs write before UTF-8 text.
    if (line_number == 1 && line.starts_with("\xEF\xBB\xBF")) {
      line.erase(0, 3);
    }
    const std::string where = path + " line " + std::to_string(line_number);
    const std::string text = trimmed(line);
    if (text.empty() || text.front() == '#') {
      continue;
    }
    const std::vector<std::string_view> cells = split_commas(text);
    if (columns.empty()) {
      for (const std::string_view cell : cells) {
        columns.push_back(column_of_header(where, cell));
      }
      continue;
    }
    if (cells.size() != columns.size()) {
      throw PointFileError(where + ": " + std::to_string(cells.size()) + " values for " +
                           std::to_string(columns.size()) + " columns");
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string cell = trimmed(cells[c]);
      double value = 0.0;
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
      if (error != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value)) {
        throw PointFileError(where + ": " + columns[c].name + " is \"" + cell +
                             "\", not a finite number");
      }
      columns[c].values.push_back(value);
    }
    lines.push_back(line_number);
  }
  if (columns.empty()) {
    throw PointFileError(path + ": empty (no header row)");
  }
  return assemble<D>(path, std::move(columns), std::move(lines));
}

// The columns of one dataset (N) or (N, C), named by core/field_components.hpp.
template <int D>
void read_dataset_columns(hid_t file, const std::string& path, const std::string& name,
                          std::vector<PointColumn>& columns) {
  using hdf5::Handle;
  const std::string where = path + ": dataset " + name;
  const Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose,
                       where + " cannot be opened");
  if (!hdf5::has_attribute(dataset.id(), "unit")) {
    throw PointFileError(where + " has no string attribute unit");
  }
  const std::string unit = hdf5::read_string_attribute(dataset.id(), "unit");
  const Handle space(H5Dget_space(dataset.id()), H5Sclose, where + " has no shape");
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::array<hsize_t, 2> dims{0, 1};
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr) < 0) {
    throw PointFileError(where + " is not (N) or (N, components)");
  }
  const std::size_t count = dims[0];
  const int components = static_cast<int>(dims[1]);
  std::vector<double> rows(count * static_cast<std::size_t>(components));
  if (!rows.empty() &&
      H5Dread(dataset.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()) < 0) {
    throw PointFileError(where + " cannot be read as numbers");
  }
  for (int c = 0; c < components; ++c) {
    PointColumn column;
    column.name = name == "position" && components == D ? position_names[c]
                                                        : component_name(name, D, components, c);
    column.unit = unit;
    column.values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const double value = rows[i * static_cast<std::size_t>(components) + c];
      if (!std::isfinite(value)) {
        throw PointFileError(where + ": row " + std::to_string(i) + " is not finite");
      }
      column.values[i] = value;
    }
    columns.push_back(std::move(column));
  }
}

// The file opened from its bytes in memory (HDF5's core driver with a file image).
template <int D>
PointFile<D> read_hdf5(const InputFile& input) {
  hdf5::silence_library_errors();
  using hdf5::Handle;
  const std::string& path = input.path;
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, path + ": no HDF5 file access list");
  if (H5Pset_fapl_core(access.id(), 1 << 16, 0) < 0 ||
      H5Pset_file_image(access.id(), const_cast<char*>(input.bytes.data()), input.bytes.size()) <
          0) {
    throw PointFileError(path + ": cannot be opened as HDF5 in memory");
  }
  // HDF5 refuses an image under the name of a file that exists: a name no file can have.
  const Handle file(H5Fopen("/dev/null/revsph-point-file", H5F_ACC_RDONLY, access.id()), H5Fclose,
                    path + ": cannot be opened as HDF5");
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  if (H5Literate(file.id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0) {
    throw PointFileError(path + ": its datasets cannot be listed");
  }
  if (names.empty()) {
    throw PointFileError(path + ": no datasets at the root");
  }
  std::vector<PointColumn> columns;
  try {
    for (const std::string& name : names) {
      read_dataset_columns<D>(file.id(), path, name, columns);
    }
  } catch (const hdf5::Hdf5Error& error) {
    throw PointFileError(error.what());
  }
  for (const PointColumn& column : columns) {
    if (column.values.size() != columns.front().values.size()) {
      throw PointFileError(path + ": dataset rows differ (" + column.name + " has " +
                           std::to_string(column.values.size()) + ", " + columns.front().name +
                           " " + std::to_string(columns.front().values.size()) + ")");
    }
  }
  return assemble<D>(path, std::move(columns), {});
}

} // namespace

template <int D>
PointFile<D> read_point_file(const InputFile& file) {
  if (has_hdf5_signature(file.bytes)) {
    return read_hdf5<D>(file);
  }
  std::string extension = std::filesystem::path(file.path).extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".h5" || extension == ".hdf5" || extension == ".hdf") {
    throw PointFileError(file.path + ": named " + extension +
                         " but not an HDF5 file (it does not start with HDF5's signature)");
  }
  return read_csv<D>(file);
}

template <int D>
PointFile<D> read_point_file(const std::filesystem::path& path) {
  try {
    return read_point_file<D>(read_input_file(path, path.string()));
  } catch (const InputFileError& error) {
    throw PointFileError(error.what());
  }
}

template <int D>
std::string point_place(const PointFile<D>& file, std::size_t row, std::string_view column) {
  return file.source +
         (file.lines.empty() ? " row " + std::to_string(row)
                             : " line " + std::to_string(file.lines[row])) +
         ", column " + std::string(column);
}

template <int D>
void write_point_csv(const std::filesystem::path& path, const PointFile<D>& file) {
  std::ofstream out(path);
  out << std::setprecision(17);
  for (int k = 0; k < D; ++k) {
    out << (k ? ", " : "") << position_names[k] << " [m]";
  }
  for (const PointColumn& column : file.columns) {
    out << ", " << column.name << " [" << column.unit << "]";
  }
  out << "\n";
  for (std::size_t i = 0; i < file.positions.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      out << (k ? ", " : "") << file.positions[i][k];
    }
    for (const PointColumn& column : file.columns) {
      out << ", " << column.values[i];
    }
    out << "\n";
  }
  if (!out) {
    throw PointFileError(path.string() + ": cannot be written");
  }
}

template PointFile<1> read_point_file<1>(const InputFile&);
template PointFile<2> read_point_file<2>(const InputFile&);
template PointFile<3> read_point_file<3>(const InputFile&);
template std::string point_place<1>(const PointFile<1>&, std::size_t, std::string_view);
template std::string point_place<2>(const PointFile<2>&, std::size_t, std::string_view);
template std::string point_place<3>(const PointFile<3>&, std::size_t, std::string_view);
template PointFile<1> read_point_file<1>(const std::filesystem::path&);
template PointFile<2> read_point_file<2>(const std::filesystem::path&);
template PointFile<3> read_point_file<3>(const std::filesystem::path&);
template void write_point_csv<1>(const std::filesystem::path&, const PointFile<1>&);
template void write_point_csv<2>(const std::filesystem::path&, const PointFile<2>&);
template void write_point_csv<3>(const std::filesystem::path&, const PointFile<3>&);

} // namespace revsph
