#pragma once
// The one pair-sum loop of the engine (design note §3). A model writes its SPH sums as small
// pair terms, the way HOOMD-blue plugs a pair evaluator into one generic neighbour loop; this
// file runs them over the half pair list of a SlotLayout and accumulates the results exactly.
//
// A pair term T provides
//   static constexpr int width;                           // how many quantities it sums
//   void pair(const PairGeometry<D>& p, std::array<double, width>& to_a,
//             std::array<double, width>& to_b) const;     // a pair's contribution to each side
// and optionally
//   bool receives(std::uint32_t slot) const;              // whether a slot's sums are wanted
//                                                         // (default: every slot)
//   template <class Add> void self(std::uint32_t slot, Add& add) const;
//                                                         // the particle's own terms (b = a, an
//                                                         // external field, a constant) through
//                                                         // add(q, value) and add.raw(q, raw)
//   void cross_pair(const PairGeometry<D>& p, std::array<double, width>& to_a) const;
//                                                         // one-sided terms from fixed targets
//                                                         // (a CrossPairs list: walls, say)
//   auto slot_inputs() const;                             // the per-slot arrays pair() reads
//                                                         // that the model fills itself, as a
//                                                         // std::tie of spans or std::arrays of
//                                                         // spans (a volume, a velocity)
// The model names each summed quantity and gives its fixed-point scale (PairSums). Every term is
// rounded once to that scale and added in integers (FixedArithmetic), so a sum is the same for
// any order of its terms: any thread count, any cell size, any future domain decomposition. With
// FloatArithmetic (the paper's FloPA) the terms are added as doubles in the order the pair list
// fixes (the same for any thread count, not for any cell size). A sum that overflows its scale
// or is not finite stops the run with a SimulationFault naming the particle and the quantity.

#include "core/arithmetic.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"
#include "core/neighbour_list.hpp"
#include "core/pair_sums.hpp"
#include "core/slot_layout.hpp"

#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace revsph {

template <int D>
struct PairGeometry {
  std::uint32_t a = 0;          // slot
  std::uint32_t b = 0;          // slot of the partner, or the target's index in a cross pair
  std::array<double, D> x_ab{}; // x_a - x_b
  double r_squared = 0.0;       // |x_ab|^2, summed over the axes in order
  double r = 0.0;               // sqrt(r_squared)
};

// What a term's self() adds to its slot's sums.
template <class Arith, int K>
class SelfTerms {
public:
  SelfTerms(PairSums<Arith, K>& sums, std::size_t slot) : sums_(sums), slot_(slot) {}
  void operator()(int q, double term) { sums_.add(slot_, q, term); }
  // A value already in raw units of the quantity's scale (a stored constant).
  void raw(int q, typename Arith::Raw value) { sums_.add_raw(slot_, q, value); }

private:
  PairSums<Arith, K>& sums_;
  std::size_t slot_;
};

// Fixed targets that act on the slots one-sidedly (the wall particles of paper 1 eq. 7): their
// positions and, per slot, the targets within reach (core/neighbour_list.hpp).
template <int D>
struct CrossPairs {
  CoordinateView<D> targets;
  const NeighbourList* of_slot = nullptr;
};

template <class Term, int D>
concept PairTerm = requires(const Term& term, const PairGeometry<D>& pair,
                            std::array<double, Term::width>& to_a,
                            std::array<double, Term::width>& to_b) {
  { Term::width } -> std::convertible_to<int>;
  term.pair(pair, to_a, to_b);
};

template <class Term>
concept ReceivesSomeSlots = requires(const Term& term, std::uint32_t slot) {
  { term.receives(slot) } -> std::convertible_to<bool>;
};

template <class Term, class Arith>
concept HasSelfTerms = requires(const Term& term, std::uint32_t slot,
                                SelfTerms<Arith, Term::width>& add) {
  term.self(slot, add);
};

template <class Term, int D>
concept HasCrossPairs = requires(const Term& term, const PairGeometry<D>& pair,
                                 std::array<double, Term::width>& to_a) {
  term.cross_pair(pair, to_a);
};

template <class Term>
concept HasSlotInputs = requires(const Term& term) {
  term.slot_inputs();
};

namespace detail {

// The spans of one entry of slot_inputs(): a span, or an array of them (a vector's components).
template <class T, std::size_t E>
std::array<std::span<T, E>, 1> spans_of(std::span<T, E> span) {
  return {span};
}
template <class T, std::size_t E, std::size_t N>
const std::array<std::span<T, E>, N>& spans_of(const std::array<std::span<T, E>, N>& spans) {
  return spans;
}
template <class T, std::size_t N>
std::array<std::span<const T>, N> spans_of(const std::array<std::vector<T>, N>& arrays) {
  std::array<std::span<const T>, N> spans;
  for (std::size_t k = 0; k < N; ++k) {
    spans[k] = arrays[k];
  }
  return spans;
}
template <class T>
std::array<std::span<const T>, 1> spans_of(const std::vector<T>& array) {
  return {std::span<const T>(array)};
}

// In a distributed run, every ghost slot's entries of the term's slot inputs from the process
// that owns its particle (a model fills them from its own particles' state only), before the
// pass reads them at a partner b. Collective; the row width comes from the types alone, so that a
// process without slots (empty arrays) still sends and receives rows of the same width.
template <int D, class Term>
void copy_slot_inputs_to_ghosts(const SlotLayout<D>& layout, const Term& term) {
  if constexpr (HasSlotInputs<Term>) {
    if (!layout.exchanges_ghost_sums()) {
      return;
    }
    const auto inputs = term.slot_inputs();
    std::size_t row_bytes = 0;
    const auto for_each_span = [&inputs](const auto& visit) {
      std::apply(
          [&](const auto&... entry) {
            (..., [&] {
              for (const auto& span : spans_of(entry)) {
                visit(span);
              }
            }());
          },
          inputs);
    };
    for_each_span([&](const auto& span) { row_bytes += sizeof(span[0]); });
    layout.template copy_to_ghost_slots<std::byte>(
        row_bytes,
        [&](std::size_t slot, std::byte* row) {
          for_each_span([&](const auto& span) {
            const std::size_t size = sizeof(span[0]);
            if (slot < span.size()) {
              std::memcpy(row, &span[slot], size);
            } else {
              std::memset(row, 0, size);
            }
            row += size;
          });
        },
        [&](std::size_t slot, const std::byte* row) {
          for_each_span([&](const auto& span) {
            const std::size_t size = sizeof(span[0]);
            if (slot < span.size()) {
              // The arrays are the model's own (non-const) vectors, lent to the term as const.
              std::memcpy(
                  const_cast<std::remove_const_t<std::remove_reference_t<decltype(span[0])>>*>(
                      &span[slot]),
                  row, size);
            }
            row += size;
          });
        });
  }
}

template <class Term>
bool receives(const Term& term, std::uint32_t slot) {
  if constexpr (ReceivesSomeSlots<Term>) {
    return term.receives(slot);
  } else {
    return true;
  }
}

template <int D>
void fill_geometry(const CoordinateView<D>& x_a, std::uint32_t a, const CoordinateView<D>& x_b,
                   std::uint32_t b, PairGeometry<D>& pair) {
  pair.a = a;
  pair.b = b;
  pair.r_squared = 0.0;
  for (int k = 0; k < D; ++k) {
    pair.x_ab[k] = x_a[k][a] - x_b[k][b];
    pair.r_squared += pair.x_ab[k] * pair.x_ab[k];
  }
  pair.r = std::sqrt(pair.r_squared);
}

// Self terms, then every wanted slot's value; a sum that does not fit becomes a fault; then
// then(slot). Called by every thread of the pair loop's parallel region, as its last work.
template <class Arith, int D, class Term, int K, class Then>
void finish_in_team(const SlotLayout<D>& layout, const Term& term, PairSums<Arith, K>& sums,
                    FaultRecorder& faults, const Then& then) {
  const std::size_t n = layout.slot_count();
  const bool ghosts_from_owners = layout.exchanges_ghost_sums();
  // nowait: the end of the parallel region that calls this is the barrier.
#pragma omp for schedule(static) nowait
  for (std::size_t s = 0; s < n; ++s) {
    const auto slot = static_cast<std::uint32_t>(s);
    if (ghosts_from_owners && layout.is_ghost_slot(s)) {
      continue; // its sums are partial here: its owner's arrive in copy_ghost_sums
    }
    if (!receives(term, slot)) {
      sums.clear_values(s);
    } else {
      if constexpr (HasSelfTerms<Term, Arith>) {
        SelfTerms<Arith, K> add(sums, s);
        term.self(slot, add);
      }
      int failed = 0;
      if (!sums.convert(s, failed)) {
        layout.record_fault(faults, s, sums.quantities()[failed].name,
                            "overflow or non-finite value in a pair sum");
      }
    }
    then(slot);
  }
}

// In a distributed run, every ghost slot's sums from the process that owns its particle (its own
// sums here lack the pairs beyond this process's ghosts), then then(slot) on it: a later pass
// reads a ghost's per-slot values (a pressure) as it reads an own particle's. Collective.
template <class Arith, int D, int K, class Then>
void copy_ghost_sums(const SlotLayout<D>& layout, PairSums<Arith, K>& sums, const Then& then) {
  if (!layout.exchanges_ghost_sums()) {
    return;
  }
  using Row = typename PairSums<Arith, K>::SlotRow;
  layout.template copy_to_ghost_slots<Row>(
      1, [&](std::size_t slot, Row* row) { sums.row(slot, *row); },
      [&](std::size_t slot, const Row* row) {
        sums.set_row(slot, *row);
        then(static_cast<std::uint32_t>(slot));
      });
}

} // namespace detail

// Nothing to do once a slot's sums are final (the default of sum_pairs).
struct NothingAfter {
  void operator()(std::uint32_t) const {}
};

// Sums `term` over every pair of the layout (and, if the term has cross pairs, over `cross`), then
// adds the self terms and converts: sums.value(q, slot) afterwards. Throws SimulationFault (step
// unknown) for the lowest-index particle whose sum does not fit. `then(slot)` runs for every slot
// as soon as its sums are final, in the same parallel loop: per-slot work on the sums (a pressure
// from a density) costs no barrier of its own. It must touch nothing but its slot's data.
// sum_pairs_over runs over `pairs` instead of the layout's own list: a filtered copy of it
// (HalfPairList::assign_filtered) without the pairs the term gives nothing to a wanted slot.
template <class Arith, int D, PairTerm<D> Term, class Then = NothingAfter>
void sum_pairs_over(const SlotLayout<D>& layout, const HalfPairList& pairs, const Term& term,
                    PairSums<Arith, Term::width>& sums, const CrossPairs<D>& cross = {},
                    const Then& then = {}) {
  constexpr int K = Term::width;
  detail::copy_slot_inputs_to_ghosts(layout, term);
  sums.resize(layout.slot_count());
  const CoordinateView<D> x = layout.position();
  FaultRecorder faults;
  // One parallel region for the whole sum (zeroing, the two phases of pairs, the self terms and
  // conversions): its barriers are the only points where the threads wait for each other.
#pragma omp parallel
  {
    sums.zero_in_team();
    pairs.for_each_slot_in_team([&](std::uint32_t a, std::span<const std::uint32_t> partners) {
      typename PairSums<Arith, K>::Local own(sums);
      PairGeometry<D> pair;
      std::array<double, K> to_a{};
      std::array<double, K> to_b{};
      for (const std::uint32_t b : partners) {
        detail::fill_geometry<D>(x, a, x, b, pair);
        term.pair(pair, to_a, to_b);
        for (int q = 0; q < K; ++q) {
          own.add(q, to_a[q]);
          sums.add(b, q, to_b[q]);
        }
      }
      if constexpr (HasCrossPairs<Term, D>) {
        if (detail::receives(term, a)) {
          for (const std::uint32_t w : cross.of_slot->of(a)) {
            detail::fill_geometry<D>(x, a, cross.targets, w, pair);
            term.cross_pair(pair, to_a);
            for (int q = 0; q < K; ++q) {
              own.add(q, to_a[q]);
            }
          }
        }
      }
      sums.add_local(a, own);
    });
    detail::finish_in_team<Arith>(layout, term, sums, faults, then);
  }
  detail::copy_ghost_sums(layout, sums, then);
  faults.throw_if_any();
}

template <class Arith, int D, PairTerm<D> Term, class Then = NothingAfter>
void sum_pairs(const SlotLayout<D>& layout, const Term& term, PairSums<Arith, Term::width>& sums,
               const CrossPairs<D>& cross = {}, const Then& then = {}) {
  sum_pairs_over<Arith>(layout, layout.pairs(), term, sums, cross, then);
}

// Every listed pair once, one after the other in slot order: visit(pair), pair.a and pair.b its
// slots. For what is built pair by pair rather than summed (a sparse matrix's entries): each
// pair's geometry is the same whichever way round it is listed (x_ab negated exactly, r alike),
// so what the visitor makes of it depends on the positions alone, not on the cell size.
template <int D, class Visit>
void for_each_pair(const SlotLayout<D>& layout, Visit&& visit) {
  const CoordinateView<D> x = layout.position();
  PairGeometry<D> pair;
  for (const HalfPairList::Stripe& stripe : layout.pairs().stripes()) {
    for (std::uint32_t local = 0; local < stripe.slot_count; ++local) {
      const std::uint32_t a = stripe.first_slot + local;
      for (std::uint32_t k = stripe.offsets[local]; k < stripe.offsets[local + 1]; ++k) {
        detail::fill_geometry<D>(x, a, x, stripe.partners[k], pair);
        visit(std::as_const(pair));
      }
    }
  }
}

// Only the one-sided terms of fixed targets: for every wanted slot a, the sum over the targets
// listed for it of term.cross_pair, in ascending target order, plus its self terms.
template <class Arith, int D, class Term>
requires HasCrossPairs<Term, D>
void sum_cross_pairs(const SlotLayout<D>& layout, const Term& term,
                     PairSums<Arith, Term::width>& sums, const CrossPairs<D>& cross) {
  constexpr int K = Term::width;
  const std::size_t n = layout.slot_count();
  sums.resize(n);
  const CoordinateView<D> x = layout.position();
  FaultRecorder faults;
#pragma omp parallel
  {
    sums.zero_in_team();
#pragma omp for schedule(static)
    for (std::size_t s = 0; s < n; ++s) {
      const auto a = static_cast<std::uint32_t>(s);
      if (!detail::receives(term, a)) {
        continue;
      }
      PairGeometry<D> pair;
      std::array<double, K> to_a{};
      for (const std::uint32_t w : cross.of_slot->of(a)) {
        detail::fill_geometry<D>(x, a, cross.targets, w, pair);
        term.cross_pair(pair, to_a);
        for (int q = 0; q < K; ++q) {
          sums.add(s, q, to_a[q]);
        }
      }
    }
    detail::finish_in_team<Arith>(layout, term, sums, faults, NothingAfter{});
  }
  detail::copy_ghost_sums(layout, sums, NothingAfter{});
  faults.throw_if_any();
}

// The cross-pair sums of one set's particles in that set's order, in floating point, for an
// output (the wall energy of each fluid particle, say): each particle's terms are added in
// ascending target order, as sum_cross_pairs<FloatArithmetic> adds them, but into the result
// directly, with no per-slot accumulators (a snapshot is a run's memory peak).
template <int D, class Term>
requires HasCrossPairs<Term, D> &&(Term::width == 1) std::vector<double> cross_sums_of_set(
    const SlotLayout<D>& layout, const Term& term, const CrossPairs<D>& cross, std::size_t set) {
  const std::span<const std::uint32_t> slots = layout.slots_of_set(set);
  std::vector<double> sums(slots.size(), 0.0);
  const CoordinateView<D> x = layout.position();
  FaultRecorder faults;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const std::uint32_t a = slots[i];
    if (!detail::receives(term, a)) {
      continue;
    }
    PairGeometry<D> pair;
    std::array<double, 1> to_a{};
    for (const std::uint32_t w : cross.of_slot->of(a)) {
      detail::fill_geometry<D>(x, a, cross.targets, w, pair);
      term.cross_pair(pair, to_a);
      sums[i] += to_a[0];
    }
    if (!std::isfinite(sums[i])) {
      layout.record_fault(faults, a, "cross-pair sum", "not finite");
    }
  }
  faults.throw_if_any();
  return sums;
}

} // namespace revsph
