// The state hash of a state held in pieces (verify/state_hash.hpp, StateSnapshot::pieces) is the
// one-process hash of the whole state, on whatever number of processes CTest starts (1, 2, 3):
// two particle sets of different sizes, fixed-point and double fields of 1 and 2 components, the
// rows dealt to the processes by a scrambled rule, in chunks smaller and larger than a set.
// Changing one raw value on one process changes the hash.

#include "core/distributed/processes.hpp"
#include "verify/state_hash.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace revsph;

FieldSnapshot field(const std::string& set, const std::string& name, int components,
                    std::size_t count, RawKind kind, std::mt19937_64& generator) {
  VariableInfo info;
  info.particle_set = set;
  info.name = name;
  info.components = components;
  FieldSnapshot snapshot{info, kind, count, {}, {}};
  for (std::size_t i = 0; i < count * static_cast<std::size_t>(components); ++i) {
    snapshot.bits.push_back(
        kind == RawKind::fixed_point
            ? static_cast<std::int64_t>(generator())
            : std::bit_cast<std::int64_t>(static_cast<double>(generator()) * 1e-12));
  }
  return snapshot;
}

int holder(std::uint64_t i) {
  return static_cast<int>((i * 40503U + 17U) % 7U %
                          static_cast<std::uint64_t>(distributed::process_count()));
}

// This process's rows of the whole state, and their indices per set.
StateSnapshot local_part(const StateSnapshot& whole, std::vector<std::vector<std::uint64_t>>& rows,
                         const std::vector<std::string>& sets) {
  rows.assign(sets.size(), {});
  StateSnapshot local;
  for (const FieldSnapshot& full : whole.fields) {
    const std::size_t s = static_cast<std::size_t>(
        std::find(sets.begin(), sets.end(), full.info.particle_set) - sets.begin());
    std::vector<std::uint64_t> mine;
    for (std::uint64_t i = 0; i < full.count; ++i) {
      if (holder(i) == distributed::process_rank()) {
        mine.push_back(i);
      }
    }
    FieldSnapshot part{full.info, full.kind, mine.size(), {}, {}};
    for (int c = 0; c < full.info.components; ++c) {
      for (const std::uint64_t i : mine) {
        part.bits.push_back(full.at(c, i));
      }
    }
    rows[s] = mine;
    local.fields.push_back(std::move(part));
  }
  return local;
}

TEST(DistributedHash, PiecesHashLikeTheWholeState) {
  std::mt19937_64 generator(5);
  StateSnapshot whole;
  whole.fields.push_back(field("fluid", "position", 2, 150001, RawKind::fixed_point, generator));
  whole.fields.push_back(field("fluid", "velocity", 2, 150001, RawKind::fixed_point, generator));
  whole.fields.push_back(field("wall", "position", 2, 3001, RawKind::fixed_point, generator));
  whole.fields.push_back(field("wall", "mass", 1, 3001, RawKind::ieee_double, generator));
  const std::vector<std::string> sets{"fluid", "wall"};
  std::vector<std::vector<std::uint64_t>> rows;
  StateSnapshot local = local_part(whole, rows, sets);
  local.pieces = {{"fluid", rows[0], 150001}, {"wall", rows[1], 3001}};
  const std::string expected = state_hash(whole);
  EXPECT_EQ(state_hash(local), expected);
  // One bit changed on the last process changes every process's hash.
  if (distributed::process_rank() == distributed::process_count() - 1 &&
      !local.fields[1].bits.empty()) {
    local.fields[1].bits.back() ^= 1;
  }
  EXPECT_NE(state_hash(local), expected);
}

} // namespace
