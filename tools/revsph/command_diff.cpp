#include "tools/revsph/commands.hpp"
#include "verify/snapshot_check.hpp"
#include "verify/state_compare.hpp"

#include <iostream>

namespace revsph::cli {

namespace {

void describe(const char* label, const std::string& path, const SnapshotMetadata& metadata) {
  std::cout << label << path << ": " << metadata.case_name << " (" << metadata.model << ", "
            << to_string(metadata.arithmetic) << "), step " << metadata.step
            << ", t = " << metadata.time << " s, hash " << metadata.state_hash << "\n";
}

} // namespace

int diff_command(const std::string& first, const std::string& second) {
  const Snapshot a = read_checked_snapshot(first);
  const Snapshot b = read_checked_snapshot(second);
  describe("A ", first, a.metadata);
  describe("B ", second, b.metadata);
  const StateComparison comparison = compare_states(a.state, b.state);
  for (const std::string& line : comparison.details()) {
    std::cout << "  " << line << "\n";
  }
  std::cout << "verdict: " << comparison.verdict() << "\n";
  if (!comparison.layout_error.empty()) {
    return bad_input;
  }
  return comparison.identical ? success : not_reversible;
}

} // namespace revsph::cli
