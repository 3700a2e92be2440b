#pragma once
// The particles that take part in a model's pair sums (its carriers) sorted into cell order, with
// the half pair list over them: the one place where particles become slots.
//
// Carriers are the particles of one or more particle sets, numbered set after set: carrier c of a
// layout over sets {fluid: 100, dummy: 20} is fluid particle c for c < 100, dummy particle c - 100
// otherwise. build() sorts them into the cells of a CellList; slot s then holds carrier
// carrier_of_slot()[s], and the pair loops (core/pair_sum.hpp) run over slots, which keeps the
// partners of a particle close in memory and visits every pair once. Everything a model reports
// stays in the canonical particle order: gather() and scatter() cross between the two, and
// record_fault() names a slot's particle by its set and index in the set.

#include "core/carrier_field.hpp"
#include "core/cell_list.hpp"
#include "core/distributed/ghost_plan.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"
#include "core/pair_list.hpp"
#include "core/particle_sets.hpp"

#include <concepts>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace revsph {

struct CarrierSet {
  std::string name; // the particle set, as the state declares it
  std::size_t count = 0;
};

// The carrier sets of a layout from the state's own sets (core/particle_sets.hpp), in the order
// given: their declared names and sizes, so that a model never restates them.
template <ParticleSet... Sets>
std::vector<CarrierSet> carrier_sets(Sets&... sets) {
  return {CarrierSet{std::string(Sets::set.name), set_size(sets)}...};
}

// Whether a slot holds a particle of some sets (SlotLayout::in): what a pair term asks instead of
// reading a per-slot flag array of its own. `sets` has bit k for set k.
struct SlotInSet {
  std::span<const std::uint8_t> set_of_slot;
  std::uint64_t sets = 0;
  bool operator()(std::uint32_t slot) const { return ((sets >> set_of_slot[slot]) & 1u) != 0; }
};

// A particle named by its set (an index into SlotLayout::sets()) and its index in the set.
struct SetParticle {
  std::uint32_t set;
  std::uint32_t index;
};

// Per-carrier values and where to put them in slot order (SlotLayout::build): an array
// (by_carrier[c]) or a function of the carrier (by_carrier(c): a carrier field's raw values, say,
// or whether the carrier is in a set), which saves a per-carrier copy of what the state holds.
template <class T, class Source = std::span<const T>>
struct Gathered {
  Source by_carrier;
  std::vector<T>* by_slot;

  T operator()(std::size_t carrier) const {
    if constexpr (std::invocable<const Source&, std::size_t>) {
      return by_carrier(carrier);
    } else {
      return by_carrier[carrier];
    }
  }
};
template <class T, class Source>
Gathered(Source, std::vector<T>*) -> Gathered<T, Source>;

template <int D>
class SlotLayout {
public:
  // cell_size >= every radius the pairs are listed for (the support radius times the case's
  // cell_size_factor). The grid is coarsened if it would need more than a few cells per carrier,
  // so that a large, sparse domain cannot exhaust memory.
  SlotLayout(const Box<D>& domain, double cell_size, std::vector<CarrierSet> sets);

  // Sorts the carriers into cells by coordinate(axis, carrier) (metres) and lists the pairs
  // closer than `radius`. A carrier outside the domain becomes a SimulationFault (step unknown)
  // naming its set and index. Each `gathered` per-carrier array is copied into slot order in the
  // same pass (the masses and constants a model's pair terms read: no separate region each).
  template <class Coordinate, class... T, class... Source>
  void build(const Coordinate& coordinate, double radius, Gathered<T, Source>... gathered);
  // The same from the carriers' position field (one per carrier set, core/carrier_field.hpp).
  template <class Arith, class... T, class... Source>
  void build(const CarrierField<Arith>& position, double radius, Gathered<T, Source>... gathered) {
    resize_sets(position);
    build([&position](int axis, std::size_t carrier) { return position.real(axis, carrier); },
          radius, gathered...);
  }
  // The sets' own and ghost particle counts from a carrier field over them (they change in a
  // distributed run when particles migrate and ghosts are refreshed; never in one process).
  template <class Arith>
  void resize_sets(const CarrierField<Arith>& field);

  std::size_t carrier_count() const { return carrier_count_; }
  std::size_t slot_count() const { return carrier_count_; }
  const std::vector<CarrierSet>& sets() const { return sets_; }
  // The first carrier of set k: set k's particle i is carrier first_carrier(k) + i.
  std::size_t first_carrier(std::size_t set) const { return first_carrier_[set]; }
  // The set of a carrier (an index into sets()): the last set starting at or before it (sets are
  // few: a linear scan). For a ghost carrier (a distributed run's copy of another process's
  // particle, after every set's own ones: core/carrier_field.hpp) the set's index plus the
  // number of sets.
  std::size_t set_of_carrier(std::size_t carrier) const {
    std::size_t part = 0;
    while (part + 2 < first_carrier_.size() && carrier >= first_carrier_[part + 1]) {
      ++part;
    }
    return part;
  }
  // The part of a per-carrier array that belongs to one set, in the set's order.
  template <class T>
  std::span<T> part_of_set(std::span<T> by_carrier, std::size_t set) const {
    return by_carrier.subspan(first_carrier_[set], first_carrier_[set + 1] - first_carrier_[set]);
  }

  std::span<const std::uint32_t> carrier_of_slot() const { return cells_.sorted_points(); }
  // A carrier set by the state's set it was declared from (carrier_sets): its index into
  // sets(). Throws std::logic_error for a set that is not a carrier set of this layout.
  template <ParticleSet Set>
  std::size_t index_of(const Set&) const {
    for (std::size_t k = 0; k < sets_.size(); ++k) {
      if (sets_[k].name == Set::set.name) {
        return k;
      }
    }
    throw std::logic_error("particle set " + std::string(Set::set.name) +
                           " is not a carrier set of this layout");
  }
  template <ParticleSet Set>
  std::span<const std::uint32_t> slots_of(const Set& set) const {
    return slots_of_set(index_of(set));
  }
  template <class T, ParticleSet Set>
  std::span<T> part_of(std::span<T> by_carrier, const Set& set) const {
    return part_of_set(by_carrier, index_of(set));
  }
  // The set of each slot's particle (an index into sets()), filled by build().
  std::span<const std::uint8_t> set_of_slot() const { return set_of_slot_; }
  template <ParticleSet... Sets>
  SlotInSet in(const Sets&... sets) const {
    // A set's ghosts are in it too: a ghost fluid particle is fluid to a pair term.
    const auto own_and_ghosts = [this](std::size_t set) {
      return (std::uint64_t{1} << set) | (std::uint64_t{1} << (set + sets_.size()));
    };
    return {set_of_slot_, (own_and_ghosts(index_of(sets)) | ...)};
  }
  // The particle in slot s. With it a loop over slots reaches each particle's own set without
  // asking which set an index falls in. A ghost slot's index is its set's own count plus its
  // index among the ghosts: StateField::at reads it there (core/state_field.hpp).
  SetParticle particle_in_slot(std::size_t slot) const {
    return particle_in_part(set_of_slot_[slot], cells_.sorted_points()[slot]);
  }
  // The same for a carrier.
  SetParticle particle_of(std::size_t carrier) const {
    return particle_in_part(set_of_carrier(carrier), carrier);
  }
  // A per-slot array read in one set's particle order: values[i] is the value of the set's
  // particle i (a density or a mass for an output, without a copy in canonical order).
  template <class T>
  struct InSetOrder {
    std::span<const T> by_slot;
    std::span<const std::uint32_t> slots;
    T operator[](std::size_t i) const { return by_slot[slots[i]]; }
    std::size_t size() const { return slots.size(); }
  };
  template <class T>
  InSetOrder<T> in_set_order(std::span<const T> by_slot, std::size_t set) const {
    return {by_slot, slots_of_set(set)};
  }
  template <class T, ParticleSet Set>
  InSetOrder<T> in_set_order(std::span<const T> by_slot, const Set& set) const {
    return {by_slot, slots_of(set)};
  }
  // The slot of each particle of a set, in the set's order: loops over one set's particles (the
  // moving ones that take an acceleration, the walls that do work) read their slots from here.
  std::span<const std::uint32_t> slots_of_set(std::size_t set) const {
    return std::span<const std::uint32_t>(slot_of_carrier_)
        .subspan(first_carrier_[set], first_carrier_[set + 1] - first_carrier_[set]);
  }
  CoordinateView<D> position() const { return view_of<D>(slot_position_); }
  const HalfPairList& pairs() const { return pairs_; }
  const CellList<D>& cells() const { return cells_; }

  // by_slot[s] = by_carrier[carrier_of_slot[s]].
  template <class T>
  void gather(std::span<const T> by_carrier, std::vector<T>& by_slot) const;
  // by_carrier[carrier_of_slot[s]] = by_slot[s].
  template <class T>
  void scatter(std::span<const T> by_slot, std::vector<T>& by_carrier) const;

  // Whether this layout's ghosts came from other processes (a distributed run): a pair pass then
  // leaves their sums to their owners and copies them over (copy_to_ghost_slots).
  bool exchanges_ghost_sums() const { return exchanges_ghost_sums_; }
  bool is_ghost_slot(std::size_t slot) const { return set_of_slot_[slot] >= sets_.size(); }
  // Every ghost slot's row of `width` values from its owner's slot (collective):
  // row_of(slot, T* row) writes an own slot's row, put(slot, const T* row) takes a ghost's.
  template <class T, class RowOf, class Put>
  void copy_to_ghost_slots(std::size_t width, const RowOf& row_of, const Put& put) const;

  // Records a fault of the particle in slot s (thread-safe, like FaultRecorder::record).
  void record_fault(FaultRecorder& faults, std::size_t slot, const char* variable,
                    const char* reason) const;
  // The set name and index in the set of a carrier.
  std::pair<const char*, std::size_t> particle_of_carrier(std::size_t carrier) const;
  // A carrier's set (an index into sets()) and its index in the whole set, the same for any
  // decomposition: in a distributed run from its set's ghost plan, in one process its own.
  // Particle i of `set` held here, by its index in the whole set: its identity in the run.
  template <class Set>
  std::uint64_t run_index(const Set& set, std::size_t i) const {
    return global_particle_of_carrier(first_carrier(index_of(set)) + i).index;
  }
  SetParticle global_particle_of_carrier(std::size_t carrier) const {
    const SetParticle local = particle_in_part(set_of_carrier(carrier), carrier);
    const distributed::GhostPlan* plan =
        local.set < ghost_plans_.size() ? ghost_plans_[local.set] : nullptr;
    return {local.set, plan == nullptr
                           ? local.index
                           : static_cast<std::uint32_t>(plan->global_index(local.index))};
  }

private:
  // `carrier` of part `part` (a set, or a set's ghosts) as its set and index in the set.
  SetParticle particle_in_part(std::size_t part, std::size_t carrier) const {
    const std::size_t set = part % sets_.size();
    const std::size_t before = part == set ? 0 : sets_[set].count;
    return {static_cast<std::uint32_t>(set),
            static_cast<std::uint32_t>(before + carrier - first_carrier_[part])};
  }

  std::vector<CarrierSet> sets_;
  // One per set, then one per set's ghosts, then the total.
  std::vector<std::size_t> first_carrier_;
  std::size_t carrier_count_ = 0;
  CellList<D> cells_;
  CoordinateArrays<D> slot_position_;
  std::vector<std::uint32_t> slot_of_carrier_;
  std::vector<std::uint8_t> set_of_slot_;
  HalfPairList pairs_;
  std::vector<const distributed::GhostPlan*> ghost_plans_; // per set; null without ghosts
  bool exchanges_ghost_sums_ = false;
};

template <int D>
template <class Coordinate, class... T, class... Source>
void SlotLayout<D>::build(const Coordinate& coordinate, double radius,
                          Gathered<T, Source>... gathered) {
  // Every process of a distributed run builds its layout at the same point: the fault goes
  // through a recorder, so that they all throw it together (FaultRecorder::throw_if_any).
  FaultRecorder faults;
  try {
    cells_.build(carrier_count_, coordinate);
  } catch (const PointOutsideDomain& outside) {
    const auto [set, index] = particle_of_carrier(outside.index());
    const std::string reason = "left the domain: " + std::string(outside.what());
    faults.record(index, std::string(set).c_str(), "position", reason.c_str());
  }
  faults.throw_if_any();
  const std::span<const std::uint32_t> carrier = cells_.sorted_points();
  for (int k = 0; k < D; ++k) {
    slot_position_[k].resize(carrier_count_);
  }
  slot_of_carrier_.resize(carrier_count_);
  set_of_slot_.resize(carrier_count_);
  (gathered.by_slot->resize(carrier_count_), ...);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carrier_count_; ++s) {
    for (int k = 0; k < D; ++k) {
      slot_position_[k][s] = coordinate(k, carrier[s]);
    }
    slot_of_carrier_[carrier[s]] = static_cast<std::uint32_t>(s);
    set_of_slot_[s] = static_cast<std::uint8_t>(set_of_carrier(carrier[s]));
    (((*gathered.by_slot)[s] = gathered(carrier[s])), ...);
  }
  pairs_.build<D>(cells_, position(), radius);
}

template <int D>
template <class Arith>
void SlotLayout<D>::resize_sets(const CarrierField<Arith>& field) {
  if (field.set_count() != sets_.size()) {
    throw std::logic_error("carrier field over another number of sets than the layout");
  }
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    sets_[k].count = field.owned_count(k);
    first_carrier_[k + 1] = first_carrier_[k] + field.owned_count(k);
  }
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    first_carrier_[sets_.size() + k + 1] = first_carrier_[sets_.size() + k] + field.ghost_count(k);
  }
  carrier_count_ = first_carrier_.back();
  ghost_plans_.resize(sets_.size());
  exchanges_ghost_sums_ = false;
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    ghost_plans_[k] = field.ghost_plan(k);
    exchanges_ghost_sums_ = exchanges_ghost_sums_ || ghost_plans_[k] != nullptr;
  }
}

template <int D>
template <class T, class RowOf, class Put>
void SlotLayout<D>::copy_to_ghost_slots(std::size_t width, const RowOf& row_of,
                                        const Put& put) const {
  const std::size_t n = sets_.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (ghost_plans_[k] == nullptr) {
      continue;
    }
    const std::span<const std::uint32_t> own = slots_of_set(k);
    const std::vector<T> rows = ghost_plans_[k]->template exchange_from<T>(
        width, [&](std::size_t particle, T* row) { row_of(own[particle], row); });
    const std::size_t first = first_carrier_[n + k];
    const std::size_t ghosts = first_carrier_[n + k + 1] - first;
    if (rows.size() != ghosts * width) {
      throw std::logic_error("ghost sums: " + std::to_string(rows.size() / width) +
                             " rows arrived for " + std::to_string(ghosts) + " ghosts");
    }
#pragma omp parallel for schedule(static)
    for (std::size_t g = 0; g < ghosts; ++g) {
      put(std::size_t{slot_of_carrier_[first + g]}, rows.data() + g * width);
    }
  }
}

template <int D>
template <class T>
void SlotLayout<D>::gather(std::span<const T> by_carrier, std::vector<T>& by_slot) const {
  const std::span<const std::uint32_t> carrier = cells_.sorted_points();
  by_slot.resize(carrier.size());
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carrier.size(); ++s) {
    by_slot[s] = by_carrier[carrier[s]];
  }
}

template <int D>
template <class T>
void SlotLayout<D>::scatter(std::span<const T> by_slot, std::vector<T>& by_carrier) const {
  const std::span<const std::uint32_t> carrier = cells_.sorted_points();
  by_carrier.resize(carrier.size());
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < carrier.size(); ++s) {
    by_carrier[carrier[s]] = by_slot[s];
  }
}

extern template class SlotLayout<1>;
extern template class SlotLayout<2>;
extern template class SlotLayout<3>;

} // namespace revsph
