#include "verify/state_hash.hpp"

#include "core/distributed/index_order_stream.hpp"
#include "core/sha256.hpp"

#include <bit>
#include <stdexcept>

namespace revsph {

namespace {

void add_layout(Sha256& sha, const FieldSnapshot& field, std::uint64_t count) {
  sha.add_string(field.info.particle_set);
  sha.add_string(field.info.name);
  sha.add_integer(field.info.components);
  sha.add_integer(static_cast<std::int64_t>(count));
  sha.add_integer(field.info.scale.exponent());
  sha.add_integer(field.kind == RawKind::fixed_point ? 0 : 1);
}

void add_values(Sha256& sha, std::span<const std::int64_t> values) {
  if constexpr (std::endian::native == std::endian::little) {
    sha.add(values.data(), values.size() * sizeof(std::int64_t));
  } else {
    for (const std::int64_t value : values) {
      sha.add_integer(value);
    }
  }
}

} // namespace

std::string state_hash(const StateSnapshot& state) {
  Sha256 sha;
  if (state.pieces.empty()) {
    for (const FieldSnapshot& field : state.fields) {
      add_layout(sha, field, field.count);
      add_values(sha, field.raw());
    }
    return sha.hex_digest();
  }
  // Component-major, like the one-process hash: each component streamed in index order to
  // process 0, which alone hashes (the others' digest is discarded).
  constexpr std::size_t chunk = std::size_t{1} << 16;
  for (const FieldSnapshot& field : state.fields) {
    const SetRows* rows = state.rows_of(field.info.particle_set);
    if (rows == nullptr || rows->indices.size() != field.count) {
      throw std::invalid_argument("state_hash: no rows of particle set " + field.info.particle_set +
                                  " for field " + field.info.name);
    }
    add_layout(sha, field, rows->total);
    for (int c = 0; c < field.info.components; ++c) {
      distributed::stream_in_index_order(
          rows->indices,
          field.raw().subspan(static_cast<std::size_t>(c) * field.count, field.count), rows->total,
          chunk, [&sha](std::span<const std::int64_t> values) { add_values(sha, values); });
    }
  }
  return distributed::broadcast_from_first(sha.hex_digest());
}

} // namespace revsph
