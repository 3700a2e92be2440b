#include "core/logged_rows.hpp"

#include "core/atomic_file.hpp"

#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace revsph {

namespace {

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) {
    cells.push_back(cell);
  }
  return cells;
}

} // namespace

std::string column_header(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

std::string column_name(const std::string& header_cell) {
  const std::size_t bracket = header_cell.find(" [");
  return bracket == std::string::npos ? header_cell : header_cell.substr(0, bracket);
}

LoggedRows read_logged_rows(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw std::runtime_error(path.string() + ": cannot be read");
  }
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  // A run killed while writing a row leaves it without its newline: it was never written.
  text.erase(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);
  LoggedRows logged;
  if (text.empty()) {
    return logged; // killed before its first row
  }
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) {
      continue;
    }
    const std::vector<std::string> cells = cells_of(line);
    if (logged.columns.empty()) {
      for (const std::string& cell : cells) {
        logged.columns.push_back(column_name(cell));
      }
      logged.header_line = line;
      continue;
    }
    if (cells.size() != logged.columns.size()) {
      throw std::runtime_error(path.string() + " line " + std::to_string(number) + ": " +
                               std::to_string(cells.size()) + " values for " +
                               std::to_string(logged.columns.size()) + " columns");
    }
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      // "inf" and "nan" are what the logs print for those values: strtod reads them back.
      char* end = nullptr;
      row[c] = std::strtod(cells[c].c_str(), &end);
      if (end == cells[c].c_str() || *end != '\0') {
        throw std::runtime_error(path.string() + " line " + std::to_string(number) + ": \"" +
                                 cells[c] + "\" is not a number");
      }
    }
    logged.rows.push_back(std::move(row));
    logged.lines.push_back(line);
  }
  if (logged.columns.empty() || logged.columns.front() != "step") {
    throw std::runtime_error(path.string() + ": no header starting with step");
  }
  return logged;
}

LoggedRows rows_before(const LoggedRows& logged, std::int64_t step, std::int64_t every) {
  LoggedRows kept{logged.columns, {}, logged.header_line, {}};
  for (std::size_t r = 0; r < logged.rows.size(); ++r) {
    const auto row_step = static_cast<std::int64_t>(logged.rows[r].front());
    if (row_step < step || (row_step == step && (step == 0 || step % every == 0))) {
      kept.rows.push_back(logged.rows[r]);
      kept.lines.push_back(logged.lines[r]);
    }
  }
  return kept;
}

void write_logged_rows(const std::filesystem::path& path, const LoggedRows& logged) {
  std::string text = logged.header_line + "\n";
  for (const std::string& line : logged.lines) {
    text += line + "\n";
  }
  write_file_atomically(path, text);
}

} // namespace revsph
