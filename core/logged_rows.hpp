#pragma once
// The rows of a run's energy.csv or diagnostics.csv as numbers, for a run that continues another
// (docs/restart.md): the rows it keeps, and what its logs replay from them so that every running
// scale and extreme carries on as if the run had never stopped.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace revsph {

// A header cell: `name [unit]`, or the name alone without a unit.
std::string column_header(const std::string& name, const std::string& unit);
// The name of a header cell (what precedes " [unit]").
std::string column_name(const std::string& header_cell);

struct LoggedRows {
  std::vector<std::string> columns; // the header's names: "step", "time", ... (no units)
  std::vector<std::vector<double>> rows;
  std::string header_line;        // the text as read, written back unchanged
  std::vector<std::string> lines; // one per row
};

// Reads `path` (a header, then rows of numbers); a last line without its newline (a run killed
// while writing it) is left out, and an empty file has no columns. Throws std::runtime_error
// naming the file and line for a row that is not numbers or has another length than the header.
LoggedRows read_logged_rows(const std::filesystem::path& path);

// The rows a run that continues from step `step` keeps: those before it, and the one at it if
// the cadence `every` puts a row there (a row at a segment's end, off the cadence, is not one
// the run that never stopped wrote).
LoggedRows rows_before(const LoggedRows& logged, std::int64_t step, std::int64_t every);

// Writes `logged`'s lines as read, atomically.
void write_logged_rows(const std::filesystem::path& path, const LoggedRows& logged);

} // namespace revsph
