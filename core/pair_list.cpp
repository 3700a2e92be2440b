#include "core/pair_list.hpp"
#include "core/interaction_reach.hpp"

#include <algorithm>
#include <stdexcept>

namespace revsph {

namespace {

struct SlotRange {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

// The slots of cells x_first..x_last (clamped to the grid) of the row starting at cell `row`.
SlotRange row_range(std::span<const std::uint32_t> cell_start, std::size_t row, int x_first,
                    int x_last, int cells_in_row) {
  const int lo = std::max(x_first, 0);
  const int hi = std::min(x_last, cells_in_row - 1);
  return {cell_start[row + static_cast<std::size_t>(lo)],
          cell_start[row + static_cast<std::size_t>(hi) + 1]};
}

// The rows of the 3^D block around `cell` that come after the cell's own row in cell (= slot)
// order, as slot ranges of three cells each (clamped): none in 1D (the own row is the whole
// axis), one row in 2D, up to four in 3D. The rest
// of the own row depends on the slot and is handled by the caller.
template <int D>
int forward_rows(std::span<const std::uint32_t> cell_start, const std::array<int, D>& per_axis,
                 const std::array<int, D>& cell, std::array<SlotRange, 4>& ranges) {
  const int nx = per_axis[0];
  int count = 0;
  auto add_row = [&](std::size_t row) {
    ranges[count++] = row_range(cell_start, row, cell[0] - 1, cell[0] + 1, nx);
  };
  if constexpr (D == 1) {
    (void)add_row;
  } else if constexpr (D == 2) {
    if (cell[1] + 1 < per_axis[1]) {
      add_row(static_cast<std::size_t>(cell[1] + 1) * nx);
    }
  } else {
    const int ny = per_axis[1];
    auto row_of = [&](int y, int z) {
      return (static_cast<std::size_t>(z) * ny + static_cast<std::size_t>(y)) * nx;
    };
    if (cell[1] + 1 < ny) {
      add_row(row_of(cell[1] + 1, cell[2]));
    }
    if (cell[2] + 1 < per_axis[2]) {
      for (int y = std::max(cell[1] - 1, 0); y <= std::min(cell[1] + 1, ny - 1); ++y) {
        add_row(row_of(y, cell[2] + 1));
      }
    }
  }
  return count;
}

} // namespace

std::size_t HalfPairList::pair_count() const {
  std::size_t total = 0;
  for (const Stripe& stripe : stripes_) {
    total += stripe.offsets.back();
  }
  return total;
}

template <int D>
void HalfPairList::build(const CellList<D>& cells, const CoordinateView<D>& x, double radius) {
  if (radius > cells.cell_size()) {
    throw std::invalid_argument("half pair list: the radius exceeds the cell size");
  }
  note_interaction_radius(radius);
  const std::array<int, D>& per_axis = cells.cells_per_axis();
  const std::span<const std::uint32_t> cell_start = cells.cell_start();
  std::size_t cells_per_layer = 1;
  for (int k = 0; k + 1 < D; ++k) {
    cells_per_layer *= static_cast<std::size_t>(per_axis[k]);
  }
  const int layers = per_axis[D - 1];
  const double radius_squared = radius * radius;
  stripes_.resize(static_cast<std::size_t>(layers));

#pragma omp parallel for schedule(dynamic, 1)
  for (int layer = 0; layer < layers; ++layer) {
    Stripe& stripe = stripes_[static_cast<std::size_t>(layer)];
    const std::size_t first_cell = static_cast<std::size_t>(layer) * cells_per_layer;
    const std::size_t end_cell = first_cell + cells_per_layer;
    stripe.first_slot = cell_start[first_cell];
    stripe.slot_count = cell_start[end_cell] - stripe.first_slot;
    stripe.offsets.resize(stripe.slot_count + 1);
    stripe.offsets[0] = 0;
    // Counted in a local, not in the stripe: neighbouring stripes share cache lines, and two
    // threads updating them per slot would serialise on them.
    std::size_t used = 0;

    for (std::size_t c = first_cell; c < end_cell; ++c) {
      if (cell_start[c] == cell_start[c + 1]) {
        continue;
      }
      std::array<int, D> cell{};
      std::size_t rest = c;
      for (int k = 0; k < D; ++k) {
        cell[k] = static_cast<int>(rest % static_cast<std::size_t>(per_axis[k]));
        rest /= static_cast<std::size_t>(per_axis[k]);
      }
      std::array<SlotRange, 4> rows{};
      const int row_count = forward_rows<D>(cell_start, per_axis, cell, rows);
      // Own row: from the next slot to the end of the cell at x + 1.
      const std::uint32_t own_row_end = row_range(cell_start, c - static_cast<std::size_t>(cell[0]),
                                                  cell[0], cell[0] + 1, per_axis[0])
                                            .end;
      std::size_t candidates_after_own_row = 0;
      for (int r = 0; r < row_count; ++r) {
        candidates_after_own_row += rows[r].end - rows[r].begin;
      }

      for (std::uint32_t a = cell_start[c]; a < cell_start[c + 1]; ++a) {
        const std::size_t candidates = own_row_end - (a + 1) + candidates_after_own_row;
        if (used + candidates > stripe.partners.size()) {
          // A quarter of headroom, not the vector's doubling: the lists are the largest array of
          // a run, and they only grow slowly from step to step.
          stripe.partners.reserve(used + candidates + (used + candidates) / 4);
          stripe.partners.resize(used + candidates);
        }
        std::uint32_t* out = stripe.partners.data() + used;
        std::size_t accepted = 0;
        std::array<double, D> xa{};
        for (int k = 0; k < D; ++k) {
          xa[k] = x[k][a];
        }
        // Every candidate is written at the next free place, which advances only when it is
        // accepted: no branch on the distance test (unpredictable once the fluid is disordered).
        auto scan = [&](std::uint32_t begin, std::uint32_t end) {
          for (std::uint32_t b = begin; b < end; ++b) {
            double r_squared = 0.0;
            for (int k = 0; k < D; ++k) {
              const double d = xa[k] - x[k][b];
              r_squared += d * d;
            }
            out[accepted] = b;
            accepted += r_squared < radius_squared;
          }
        };
        scan(a + 1, own_row_end);
        for (int r = 0; r < row_count; ++r) {
          scan(rows[r].begin, rows[r].end);
        }
        used += accepted;
        stripe.offsets[a - stripe.first_slot + 1] = static_cast<std::uint32_t>(used);
      }
    }
  }
}

template void HalfPairList::build<1>(const CellList<1>&, const CoordinateView<1>&, double);
template void HalfPairList::build<2>(const CellList<2>&, const CoordinateView<2>&, double);
template void HalfPairList::build<3>(const CellList<3>&, const CoordinateView<3>&, double);

} // namespace revsph
