#include "core/distributed/index_blocks.hpp"

#include "core/distributed/migration.hpp"
#include "core/distributed/processes.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <stdexcept>

namespace revsph::distributed {

namespace {

// Rows [first, first + count) of a component-major field.
FieldSnapshot rows_from(const FieldSnapshot& field, std::uint64_t first, std::uint64_t count) {
  FieldSnapshot part{field.info, field.kind, count, {}, {}};
  part.bits.reserve(count * static_cast<std::size_t>(field.info.components));
  for (int c = 0; c < field.info.components; ++c) {
    const auto column =
        field.raw().subspan(static_cast<std::size_t>(c) * field.count + first, count);
    part.bits.insert(part.bits.end(), column.begin(), column.end());
  }
  return part;
}

// A component-major field's rows moved along `migration`.
FieldSnapshot moved(const FieldSnapshot& field, const Migration& migration) {
  const auto width = static_cast<std::size_t>(field.info.components);
  std::vector<std::int64_t> rows(field.count * width);
  for (std::size_t i = 0; i < field.count; ++i) {
    for (std::size_t c = 0; c < width; ++c) {
      rows[i * width + c] = field.at(static_cast<int>(c), i);
    }
  }
  const std::vector<std::int64_t> arrived =
      migration.move(std::span<const std::int64_t>(rows), width);
  FieldSnapshot result{field.info, field.kind, migration.count_after(), {}, {}};
  result.bits.resize(arrived.size());
  for (std::size_t i = 0; i < result.count; ++i) {
    for (std::size_t c = 0; c < width; ++c) {
      result.bits[c * result.count + i] = arrived[i * width + c];
    }
  }
  return result;
}

int block_of(std::uint64_t index, std::uint64_t total) {
  // The largest p with start(p) <= index.
  int p = static_cast<int>(index * static_cast<std::uint64_t>(process_count()) / total);
  while (p + 1 < process_count() && index_block_start(total, p + 1) <= index) {
    ++p;
  }
  while (p > 0 && index_block_start(total, p) > index) {
    --p;
  }
  return p;
}

} // namespace

std::uint64_t index_block_start(std::uint64_t total, int process) {
  // total * p / P without overflow for any particle count.
  const auto p = static_cast<fixedpoint::int128>(process);
  return static_cast<std::uint64_t>(p * static_cast<fixedpoint::int128>(total) / process_count());
}

StateSnapshot in_index_blocks(const StateSnapshot& snapshot) {
  const int me = process_rank();
  StateSnapshot result;
  if (snapshot.pieces.empty()) {
    for (const FieldSnapshot& field : snapshot.fields) {
      const std::uint64_t first = index_block_start(field.count, me);
      result.fields.push_back(
          rows_from(field, first, index_block_start(field.count, me + 1) - first));
      if (result.rows_of(field.info.particle_set) == nullptr) {
        SetRows& rows =
            result.pieces.emplace_back(SetRows{field.info.particle_set, {}, field.count});
        for (std::uint64_t i = first; i < first + result.fields.back().count; ++i) {
          rows.indices.push_back(i);
        }
      }
    }
    return result;
  }
  // One migration per set (collective, in the pieces' order, the same on every process), then
  // each field, in the snapshot's order, along its set's.
  std::vector<Migration> migrations;
  migrations.reserve(snapshot.pieces.size());
  for (const SetRows& rows : snapshot.pieces) {
    std::vector<int> owners(rows.indices.size());
    for (std::size_t i = 0; i < owners.size(); ++i) {
      owners[i] = block_of(rows.indices[i], rows.total);
    }
    const Migration& migration = migrations.emplace_back(owners, rows.indices);
    result.pieces.push_back({rows.set, migration.global_indices_after(), rows.total});
  }
  for (const FieldSnapshot& field : snapshot.fields) {
    std::size_t k = 0;
    while (k < snapshot.pieces.size() && snapshot.pieces[k].set != field.info.particle_set) {
      ++k;
    }
    if (k == snapshot.pieces.size() || field.count != snapshot.pieces[k].indices.size()) {
      throw std::invalid_argument("in_index_blocks: field " + field.info.particle_set + "." +
                                  field.info.name + " does not have its set's rows");
    }
    result.fields.push_back(moved(field, migrations[k]));
  }
  return result;
}

} // namespace revsph::distributed
