#pragma once
// Particle sets: how a model declares its state (design note §5 and style anchors: one table per
// model drives snapshots, restarts, the time reversal, hashes and diffs).
//
// A particle set is a struct whose members are all StateFields, declared with designated
// initialisers, plus the set's name and motion and a fields() that ties every member:
//
//   template <int D, class Raw>
//   struct Fluid {
//     static constexpr SetInfo set{.name = "fluid", .motion = Motion::moving};
//     StateField<Raw> position{{.name = "position", .unit = "m", .components = D}};
//     StateField<Raw> velocity{{.name = "velocity", .unit = "m/s", .parity = Parity::odd,
//                               .components = D}};
//     auto fields() { return std::tie(position, velocity); }
//   };
//
// A model's state is a struct of sets with a sets() that ties them, in the order snapshots and
// hashes list them. declare_state() stamps each field with its set's name and checks at compile
// time that fields() lists every member (a field left out would otherwise be silently not saved,
// hashed or reversed); require_complete() checks at setup that every field got a scale and that
// the fields of a set agree on its particle count.

#include "core/state_field.hpp"

#include <concepts>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace revsph {

enum class Motion { moving, fixed };

struct SetInfo {
  std::string_view name;
  Motion motion = Motion::moving;
};

template <class Set>
concept ParticleSet = requires(Set& set) {
  { Set::set } -> std::convertible_to<const SetInfo&>;
  set.fields();
};

template <class State>
concept DeclaredState = requires(State& state) {
  state.sets();
};

// visit(set) for every set of the state, in declaration order.
template <DeclaredState State, class Visit>
void for_each_set(State& state, Visit&& visit) {
  std::apply([&](auto&... sets) { (visit(sets), ...); }, state.sets());
}

// visit(field) for every field of a set, in declaration order.
template <ParticleSet Set, class Visit>
void for_each_field_of(Set& set, Visit&& visit) {
  std::apply([&](auto&... fields) { (visit(fields), ...); }, set.fields());
}

// visit(field) for every field of every set: the one order of snapshots, hashes and diffs.
template <DeclaredState State, class Visit>
void for_each_field(State& state, Visit&& visit) {
  for_each_set(state, [&](auto& set) { for_each_field_of(set, visit); });
}

// Stamps every field with its set's name. Fails to compile if a set has a member that its
// fields() does not list.
template <DeclaredState State>
void declare_state(State& state) {
  for_each_set(state, [](auto& set) {
    using Set = std::remove_cvref_t<decltype(set)>;
    constexpr std::size_t listed = std::tuple_size_v<decltype(std::declval<Set&>().fields())>;
    using Field = std::remove_cvref_t<decltype(std::get<0>(std::declval<Set&>().fields()))>;
    static_assert(sizeof(Set) == listed * sizeof(Field),
                  "a particle set's fields() must list every one of its members");
    for_each_field_of(set, [](auto& field) { field.set_particle_set(std::string(Set::set.name)); });
  });
}

// Resizes every field of a set to `count` particles (values zero).
template <ParticleSet Set>
void resize_set(Set& set, std::size_t count) {
  for_each_field_of(set, [&](auto& field) { field.resize(count); });
}

// The number of particles of a set (that of its first field).
template <ParticleSet Set>
std::size_t set_size(Set& set) {
  return std::get<0>(set.fields()).count();
}

// Throws std::logic_error naming the first field without a set name (declare_state not called)
// or a scale, or a set whose fields disagree on the particle count.
template <DeclaredState State>
void require_complete(State& state) {
  for_each_set(state, [](auto& set) {
    const std::size_t count = set_size(set);
    for_each_field_of(set, [&](const auto& field) {
      const std::string what = std::string(field.info().particle_set) + "." + field.info().name;
      if (field.info().particle_set.empty()) {
        throw std::logic_error("state field " + field.info().name +
                               " belongs to no particle set (declare_state was not called)");
      }
      if (!field.has_scale()) {
        throw std::logic_error("state field " + what + " (stored as " + field.info().quantity() +
                               ") has no fixed-point scale");
      }
      if (field.count() != count) {
        throw std::logic_error("state field " + what + " holds " + std::to_string(field.count()) +
                               " particles, its set " + std::to_string(count));
      }
    });
  });
}

// The fixed-point scale of each quantity a model stores ("position", "velocity", "mass", ...),
// chosen once at setup: set_scales gives every field the scale of its quantity
// (VariableInfo::quantity), so a scale is stated once whatever the number of sets and copies.
struct QuantityScale {
  std::string quantity;
  fixedpoint::Scale scale;
};

// Fields whose quantity `scales` does not list are left for the setup to scale later (shtc's
// masses follow from the kernel sums); require_complete names any left without a scale.
template <class State>
void set_scales(State& state, std::span<const QuantityScale> scales) {
  for_each_field(state, [&](auto& field) {
    if (field.has_scale()) {
      return;
    }
    const std::string& quantity = field.info().quantity();
    for (const QuantityScale& q : scales) {
      if (q.quantity == quantity) {
        field.set_scale(q.scale);
        return;
      }
    }
  });
}
template <class State>
void set_scales(State& state, std::initializer_list<QuantityScale> scales) {
  set_scales(state, std::span<const QuantityScale>(scales.begin(), scales.size()));
}

struct SetSize {
  std::string particle_set;
  std::size_t count = 0;
  bool moving = true;
};

template <DeclaredState State>
std::vector<SetSize> set_sizes(State& state) {
  std::vector<SetSize> sizes;
  for_each_set(state, [&](auto& set) {
    using Set = std::remove_cvref_t<decltype(set)>;
    sizes.push_back({std::string(Set::set.name), set_size(set), Set::set.motion == Motion::moving});
  });
  return sizes;
}

} // namespace revsph
