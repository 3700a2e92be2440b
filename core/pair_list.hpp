#pragma once
// Half neighbour lists over points stored in cell order, and the lock-free parallel loop over
// their pairs.
//
// The points are the slots of a CellList (cell order), so the candidates of a point lie in a few
// contiguous slot ranges that are read sequentially. Each pair {a, b} with |x_a - x_b| < radius
// is listed once, under its smaller slot a: a pair loop evaluates the pair term once and adds it
// to both particles.
//
// The slots are cut into stripes, one layer of cells along the last axis each. A pair listed
// under a stripe has its partner in the same stripe or the next one, so all even stripes can run
// at once and then all odd ones, without two threads ever writing to the same particle. Each
// stripe is walked by one thread in slot order, so every particle receives its terms in an order
// fixed by the geometry alone: the same for any thread count, which keeps even floating-point
// sums reproducible (exact fixed-point sums do not depend on the order at all).

#include "core/cell_list.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph {

class HalfPairList {
public:
  struct Stripe {
    std::uint32_t first_slot = 0;
    std::uint32_t slot_count = 0;
    // Partners of slot first_slot + i: partners[offsets[i], offsets[i + 1]), ascending.
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> partners; // capacity kept between builds; offsets.back() valid
  };

  std::size_t pair_count() const;
  const std::vector<Stripe>& stripes() const { return stripes_; }

  // Calls visit(a, partners) for every slot a, where partners are the slots b > a paired with
  // it, in two parallel phases (even stripes, then odd stripes). visit may write to a and to
  // its partners; see the header comment.
  template <class Visit>
  void for_each_slot(Visit&& visit) const;
  // The same, called by every thread of an enclosing parallel region (orphaned worksharing), so
  // that a pair loop and the work around it share one region.
  template <class Visit>
  void for_each_slot_in_team(Visit&& visit) const;

  // Fills the list for the slots of `cells` at `slot_coordinates` (coordinates in slot order).
  // Requires radius <= cells.cell_size().
  template <int D>
  void build(const CellList<D>& cells, const CoordinateView<D>& slot_coordinates, double radius);

  // Copies the pairs {a, b} of `from` for which keep(a, b) holds, in the same stripes and the
  // same order: the pairs a term can act on, when many cannot (two fixed wall particles, say).
  // A pair loop over it gives the same sums as over `from` if the dropped pairs add nothing to
  // the slots whose sums are used.
  template <class Keep>
  void assign_filtered(const HalfPairList& from, const Keep& keep);

private:
  std::vector<Stripe> stripes_;
};

template <class Keep>
void HalfPairList::assign_filtered(const HalfPairList& from, const Keep& keep) {
  stripes_.resize(from.stripes_.size());
  const std::size_t stripe_count = stripes_.size();
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < stripe_count; ++i) {
    const Stripe& source = from.stripes_[i];
    Stripe& stripe = stripes_[i];
    stripe.first_slot = source.first_slot;
    stripe.slot_count = source.slot_count;
    stripe.offsets.resize(source.slot_count + 1);
    stripe.partners.resize(source.partners.size());
    std::uint32_t used = 0;
    stripe.offsets[0] = 0;
    for (std::uint32_t local = 0; local < source.slot_count; ++local) {
      const std::uint32_t a = source.first_slot + local;
      for (std::uint32_t j = source.offsets[local]; j < source.offsets[local + 1]; ++j) {
        const std::uint32_t b = source.partners[j];
        if (keep(a, b)) {
          stripe.partners[used++] = b;
        }
      }
      stripe.offsets[local + 1] = used;
    }
  }
}

template <class Visit>
void HalfPairList::for_each_slot(Visit&& visit) const {
#pragma omp parallel
  for_each_slot_in_team(visit);
}

template <class Visit>
void HalfPairList::for_each_slot_in_team(Visit&& visit) const {
  const std::size_t stripe_count = stripes_.size();
  for (std::size_t parity = 0; parity < 2; ++parity) {
    const std::size_t in_phase = (stripe_count + 1 - parity) / 2;
    // Dynamic scheduling balances stripes of unequal size; the results do not depend on it. The
    // loop's closing barrier separates the even phase from the odd one.
#pragma omp for schedule(dynamic, 1)
    for (std::size_t i = 0; i < in_phase; ++i) {
      const Stripe& stripe = stripes_[2 * i + parity];
      for (std::uint32_t local = 0; local < stripe.slot_count; ++local) {
        const std::uint32_t* first = stripe.partners.data() + stripe.offsets[local];
        visit(stripe.first_slot + local,
              std::span<const std::uint32_t>(first,
                                             stripe.offsets[local + 1] - stripe.offsets[local]));
      }
    }
  }
}

extern template void HalfPairList::build<1>(const CellList<1>&, const CoordinateView<1>&, double);
extern template void HalfPairList::build<2>(const CellList<2>&, const CoordinateView<2>&, double);
extern template void HalfPairList::build<3>(const CellList<3>&, const CoordinateView<3>&, double);

} // namespace revsph
