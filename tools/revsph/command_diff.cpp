#include "tools/revsph/commands.hpp"
#include "verify/state_compare.hpp"
#include "verify/state_hash.hpp"

#include <iostream>

namespace revsph::cli {

namespace {

void describe(const char* label, const std::string& path, const SnapshotMetadata& metadata) {
  std::cout << label << path << ": " << metadata.case_name << " (" << metadata.model << ", "
            << to_string(metadata.arithmetic) << "), step " << metadata.step
            << ", t = " << metadata.time << " s, hash " << metadata.state_hash << "\n";
}

// Unlike a restart, a comparison has a use for a damaged file: finding what was changed in it.
// So a state that no longer has its recorded hash is read with a warning, not refused.
Snapshot read_for_comparison(const std::string& path) {
  Snapshot snapshot = read_snapshot(path);
  const std::string computed = state_hash(snapshot.state);
  if (computed != snapshot.metadata.state_hash) {
    std::cerr << "revsph: warning: " << path
              << ": the state does not match the hash recorded in the file (damaged or edited): "
                 "recorded "
              << snapshot.metadata.state_hash << ", computed " << computed
              << "; comparing its contents as they are\n";
  }
  return snapshot;
}

} // namespace

int diff_command(const std::string& first, const std::string& second) {
  const Snapshot a = read_for_comparison(first);
  const Snapshot b = read_for_comparison(second);
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
