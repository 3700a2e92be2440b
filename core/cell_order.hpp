#pragma once
// Sorting the particles a model's pair loops run over (its carriers) into cell order: the cell
// list is built from the carriers' coordinates, which are then gathered by slot
// (core/pair_list.hpp works on slots). Models gather their other per-carrier arrays themselves.

#include "core/cell_list.hpp"
#include "core/fault.hpp"
#include "core/geometry.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace revsph {

// Builds `cells` from coordinate(axis, a) of the carriers a < count and writes their coordinates
// in slot order into `slot_position`. A carrier outside the domain becomes a SimulationFault
// (step unknown) naming it by name_of(a) = {particle set, index in the set}.
template <int D, class Coordinate, class NameOf>
void sort_into_cells(CellList<D>& cells, std::size_t count, const Coordinate& coordinate,
                     const NameOf& name_of, CoordinateArrays<D>& slot_position) {
  try {
    cells.build(count, coordinate);
  } catch (const PointOutsideDomain& outside) {
    const auto [set, index] = name_of(outside.index());
    throw SimulationFault(
        {set, index, "position", "left the domain: " + std::string(outside.what())}, -1);
  }
  const std::span<const std::uint32_t> carrier_of_slot = cells.sorted_points();
  for (int k = 0; k < D; ++k) {
    slot_position[k].resize(count);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < count; ++s) {
    for (int k = 0; k < D; ++k) {
      slot_position[k][s] = coordinate(k, carrier_of_slot[s]);
    }
  }
}

} // namespace revsph
