#pragma once
// SHA-256 of a state: every declared field, in declaration order, as its layout (particle set,
// name, components, count, scale exponent, raw kind) followed by its raw integers in little-endian
// byte order. Two states have the same hash exactly when they are bit for bit the same.

#include "core/state_snapshot.hpp"

#include <string>

namespace revsph {

// A state held in pieces (StateSnapshot::pieces, a distributed run) hashes like the whole state:
// every process returns the hash a one-process run computes (collective; each component is
// streamed to process 0 in global-index order, so no process holds the whole state).
std::string state_hash(const StateSnapshot& state);

} // namespace revsph
