#pragma once
// A model-independent copy of a state: every declared field with its raw bits.
//
// Fixed-point fields are stored as their int64 values; double fields (FloPA) as their IEEE bit
// patterns. Capture, restore and the time reversal are generic over any declared state
// (core/particle_sets.hpp).

#include "core/arithmetic.hpp"
#include "core/distributed/set_rows.hpp"
#include "core/particle_sets.hpp"
#include "core/state_field.hpp"

#include <bit>
#include <concepts>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace revsph {

enum class RawKind { fixed_point, ieee_double };

struct FieldSnapshot {
  VariableInfo info;
  RawKind kind = RawKind::fixed_point;
  std::size_t count = 0;
  std::vector<std::int64_t> bits; // component-major, like StateField (a copy; empty if borrowed)
  // The state's own storage instead of a copy (borrow_state): valid while the state is unchanged.
  std::span<const std::int64_t> borrowed;

  // The raw values, whether copied or borrowed.
  std::span<const std::int64_t> raw() const {
    return borrowed.data() != nullptr ? borrowed : std::span<const std::int64_t>(bits);
  }
  std::int64_t at(int component, std::size_t particle) const {
    return raw()[static_cast<std::size_t>(component) * count + particle];
  }
  // The physical value of one entry.
  double real(int component, std::size_t particle) const {
    return real_of(at(component, particle));
  }
  // The physical value of a raw value of this field.
  double real_of(std::int64_t raw) const;
};

struct StateSnapshot {
  std::vector<FieldSnapshot> fields;
  // A state held in pieces (a distributed run, docs/design/distributed.md): which rows of each
  // set this process's fields hold. Empty when the fields hold the whole state. Whatever takes a
  // snapshot with pieces (a hash, a comparison, a snapshot file) sees the whole state through
  // them, collectively.
  std::vector<SetRows> pieces;

  // This process's rows of `particle_set`, or null if the snapshot holds the whole state.
  const SetRows* rows_of(const std::string& particle_set) const;

  const FieldSnapshot* find(const std::string& particle_set, const std::string& name) const;
  FieldSnapshot* find(const std::string& particle_set, const std::string& name);
};

template <class Raw>
constexpr RawKind raw_kind_of() {
  if constexpr (std::same_as<Raw, double>) {
    return RawKind::ieee_double;
  } else {
    static_assert(std::same_as<Raw, std::int64_t>, "state fields hold int64 or double");
    return RawKind::fixed_point;
  }
}

template <class Raw>
FieldSnapshot snapshot_of(const StateField<Raw>& field) {
  FieldSnapshot snapshot{field.info(), raw_kind_of<Raw>(), field.count(), {}};
  snapshot.bits.reserve(field.all().size());
  for (const Raw value : field.all()) {
    snapshot.bits.push_back(std::bit_cast<std::int64_t>(value));
  }
  return snapshot;
}

template <DeclaredState State>
StateSnapshot capture_state(State& state) {
  StateSnapshot snapshot;
  for_each_field(state, [&](auto& field) { snapshot.fields.push_back(snapshot_of(field)); });
  return snapshot;
}

// The same without copying the fixed-point fields: each borrows its field's storage, so the
// snapshot is only valid while the state is unchanged (what a snapshot write or a hash needs; a
// copy of the whole state would be the peak of a run's memory). Double fields are copied (their
// bits are not int64 objects).
template <DeclaredState State>
StateSnapshot borrow_state(State& state) {
  StateSnapshot snapshot;
  for_each_field(state, [&](auto& field) {
    using Raw = typename std::remove_cvref_t<decltype(field)>::value_type;
    if constexpr (std::same_as<Raw, std::int64_t>) {
      FieldSnapshot borrowed{field.info(), RawKind::fixed_point, field.count(), {}, {}};
      borrowed.borrowed = std::span<const std::int64_t>(field.all());
      snapshot.fields.push_back(std::move(borrowed));
    } else {
      snapshot.fields.push_back(snapshot_of(field));
    }
  });
  return snapshot;
}

// The particles of `field`'s set over every process: its count, or the set's total when `state`
// holds this process's rows only (StateSnapshot::pieces).
std::uint64_t whole_count(const StateSnapshot& state, const FieldSnapshot& field);

// Throws std::invalid_argument if the snapshot does not have the same declared fields
// (set, name, components, scale, raw kind) in the same order.
void require_same_layout(const FieldSnapshot& expected, const FieldSnapshot& found);

template <DeclaredState State>
void restore_state(State& state, const StateSnapshot& snapshot) {
  std::size_t index = 0;
  for_each_field(state, [&](auto& field) {
    using Raw = typename std::remove_cvref_t<decltype(field)>::value_type;
    if (index >= snapshot.fields.size()) {
      throw std::invalid_argument("snapshot has fewer fields than the model declares");
    }
    const FieldSnapshot& source = snapshot.fields[index++];
    require_same_layout(FieldSnapshot{field.info(), raw_kind_of<Raw>(), field.count(), {}, {}},
                        source);
    auto values = field.all();
    for (std::size_t i = 0; i < values.size(); ++i) {
      values[i] = std::bit_cast<Raw>(source.raw()[i]);
    }
  });
  if (index != snapshot.fields.size()) {
    throw std::invalid_argument("snapshot has more fields than the model declares");
  }
}

// The time reversal R: negate every odd variable (design note §2). Throws on the one raw value
// whose negation overflows.
// The arithmetic follows from the stored values: doubles (the float variant) or fixed-point
// integers.
template <DeclaredState State>
void apply_time_reversal(State& state) {
  for_each_field(state, [](auto& field) {
    if (field.info().parity != Parity::odd) {
      return;
    }
    for (auto& value : field.all()) {
      using Arith =
          std::conditional_t<std::is_floating_point_v<std::remove_cvref_t<decltype(value)>>,
                             FloatArithmetic, FixedArithmetic>;
      if (!Arith::try_negate(value)) {
        throw std::overflow_error("time reversal: " + field.info().name +
                                  " holds INT64_MIN, whose negation does not fit");
      }
    }
  });
}

} // namespace revsph
