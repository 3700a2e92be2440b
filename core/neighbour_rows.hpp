#pragma once
// Whole neighbour rows of a movable point set, with a fixed set as extra neighbours, and the
// parallel loop over the rows.
//
// The half pair loop of pair_list.hpp hands out each pair once, to be added to both particles;
// some setup-time solvers in doubles need instead every neighbour of one point at a time (a row
// of a Jacobian, say, whose diagonal block sums over the row and whose entries must be placed in
// column order). NeighbourRows keeps the cell lists and neighbour lists for that and walks each
// row in a fixed order: the movable neighbours (the point itself excluded) in ascending index
// order, then the fixed ones in ascending index order. That order and the arithmetic of each
// distance depend on the coordinates alone (neighbour_list.hpp), so floating-point sums over a
// row are the same for any thread count and cell size.

#include "core/cell_list.hpp"
#include "core/neighbour_list.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace revsph {

// One neighbour b of row a, as a row visit hands it out.
template <int D>
struct RowNeighbour {
  std::uint32_t index; // b, in its own set (movable or fixed)
  Vec<D> separation;   // x_a - x_b
  // sqrt of the squared separation summed over the axes in order (geometry.hpp's
  // squared_distance): the same bits wherever a distance is needed.
  double distance;
};

template <int D>
class NeighbourRows;

// The neighbours of one row, valid during NeighbourRows::for_each_row.
template <int D>
class NeighbourRow {
public:
  NeighbourRow(const NeighbourRows<D>& rows, std::size_t a) : rows_(rows), a_(a) {}

  // Calls visit(const RowNeighbour<D>&) for each movable neighbour, ascending, the row excluded.
  template <class Visit>
  void for_each_movable(Visit&& visit) const {
    visit_all(rows_.movable_, rows_.of_movable_, visit);
  }
  // The same for the fixed neighbours.
  template <class Visit>
  void for_each_fixed(Visit&& visit) const {
    visit_all(rows_.fixed_, rows_.of_fixed_, visit);
  }

private:
  template <class Visit>
  void visit_all(const CoordinateView<D>& others, const NeighbourList& list, Visit& visit) const {
    for (const std::uint32_t b : list.of(a_)) {
      RowNeighbour<D> neighbour{b, {}, 0.0};
      neighbour.distance =
          std::sqrt(squared_distance<D>(rows_.movable_, a_, others, b, neighbour.separation));
      visit(std::as_const(neighbour));
    }
  }

  const NeighbourRows<D>& rows_;
  std::size_t a_;
};

template <int D>
class NeighbourRows {
public:
  // radius: neighbours are the points with |x_a - x_b| < radius. `fixed` is viewed, not copied:
  // it must outlive this object unchanged. `row_count` sizes the movable cell list.
  NeighbourRows(const Box<D>& domain, double radius, std::size_t row_count,
                const CoordinateView<D>& fixed);

  // Rebuilds the rows for the movable points at `movable` (viewed, not copied: they must stay
  // unchanged until the last visit before the next update). Throws PointOutsideDomain.
  void update(const CoordinateView<D>& movable);

  std::size_t row_count() const { return of_movable_.query_count(); }
  std::size_t movable_neighbour_count(std::size_t a) const { return of_movable_.of(a).size(); }
  // Movable neighbours summed over all rows (each pair counted from both sides).
  std::size_t movable_pair_count() const { return of_movable_.pair_count(); }

  // Calls visit(a, const NeighbourRow<D>&) for every row a, rows in parallel: visit may write to
  // what belongs to row a only.
  template <class Visit>
  void for_each_row(Visit&& visit) const {
    const std::size_t n = row_count();
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      visit(a, NeighbourRow<D>(*this, a));
    }
  }

private:
  friend class NeighbourRow<D>;

  double radius_;
  CellList<D> movable_cells_;
  CellList<D> fixed_cells_;
  CoordinateView<D> movable_{};
  CoordinateView<D> fixed_;
  NeighbourList of_movable_;
  NeighbourList of_fixed_;
};

extern template class NeighbourRows<1>;
extern template class NeighbourRows<2>;
extern template class NeighbourRows<3>;

} // namespace revsph
