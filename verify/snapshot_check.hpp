#pragma once
// Reading a snapshot and checking that its state still has the hash recorded when it was
// written: a damaged file is refused instead of silently restarting from wrong data.

#include "core/snapshot_file.hpp"

#include <filesystem>

namespace revsph {

// read_snapshot plus the hash check; throws SnapshotError.
Snapshot read_checked_snapshot(const std::filesystem::path& path);

} // namespace revsph
