#pragma once
// SHA-256 of a state: every declared field, in declaration order, as its layout (particle set,
// name, components, count, scale exponent, raw kind) followed by its raw integers in little-endian
// byte order. Two states have the same hash exactly when they are bit for bit the same.

#include "core/distributed/set_rows.hpp"
#include "core/state_snapshot.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace revsph {

std::string state_hash(const StateSnapshot& state);

// The same hash of a state the processes hold in pieces (docs/design/distributed.md, piece 8):
// `local` has this process's rows of every field, `sets` says which. Every process returns the
// hash of the whole state, the one a one-process run computes (collective).
std::string state_hash(const StateSnapshot& local, std::span<const SetRows> sets);

} // namespace revsph
