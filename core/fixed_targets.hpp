#pragma once
// Particles held in place that act on the slots of a SlotLayout one-sidedly, with their own
// radius: the Lennard-Jones-like wall particles of paper 1 eq. (7), say. They take no part in
// the layout's pair list; the pair loops (core/pair_sum.hpp) see them as CrossPairs.

#include "core/carrier_field.hpp"
#include "core/cell_list.hpp"
#include "core/fault.hpp"
#include "core/neighbour_list.hpp"
#include "core/pair_sum.hpp"
#include "core/slot_layout.hpp"

#include <string>

namespace revsph {

template <int D>
class FixedTargets {
public:
  // cell_size >= the radius the targets are found within.
  FixedTargets(const Box<D>& domain, double cell_size, std::size_t count, std::string set_name)
      : cells_(domain, cell_size, cell_budget(count)), set_name_(std::move(set_name)) {}

  // Sorts the targets into cells. Throws SimulationFault (step unknown) for one outside the domain.
  void place(CoordinateArrays<D> positions) {
    positions_ = std::move(positions);
    try {
      cells_.build(view_of<D>(positions_));
    } catch (const PointOutsideDomain& outside) {
      throw SimulationFault({set_name_, outside.index(), "position", outside.what()}, -1);
    }
  }

  // The same from a state field of D components (a wall set's positions, read as reals).
  template <class Arith, class Field>
  void place_field(const Field& position) {
    const CarrierField<Arith> field{&position};
    CoordinateArrays<D> reals;
    for (int k = 0; k < D; ++k) {
      reals[k] = field.reals(k);
    }
    place(std::move(reals));
  }

  // Lists, for every slot of `layout`, the targets closer than `radius`, in ascending order.
  void find_near(const SlotLayout<D>& layout, double radius) {
    find_neighbours<D>(cells_, view_of<D>(positions_), layout.position(), radius,
                       SelfPairs::included, near_slot_);
  }

  CrossPairs<D> cross_pairs() const { return {view_of<D>(positions_), &near_slot_}; }
  const CoordinateArrays<D>& positions() const { return positions_; }

private:
  CellList<D> cells_;
  std::string set_name_;
  CoordinateArrays<D> positions_;
  NeighbourList near_slot_;
};

} // namespace revsph
