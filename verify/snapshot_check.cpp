#include "verify/snapshot_check.hpp"

#include "verify/state_hash.hpp"

namespace revsph {

Snapshot read_checked_snapshot(const std::filesystem::path& path) {
  Snapshot snapshot = read_snapshot(path);
  const std::string computed = state_hash(snapshot.state);
  if (computed != snapshot.metadata.state_hash) {
    throw SnapshotError(path.string() +
                        ": the state does not match the hash recorded in the file (damaged): "
                        "recorded " +
                        snapshot.metadata.state_hash + ", computed " + computed);
  }
  return snapshot;
}

} // namespace revsph
