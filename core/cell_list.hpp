#pragma once
// A uniform grid of cells over the domain, each holding the indices of the points inside it.
//
// Built by a stable counting sort, so within a cell the points are in ascending index order.
// Query results never depend on the cell size: neighbour_list.hpp filters candidates by exact
// distance and sorts each list by index.

#include "core/geometry.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

namespace revsph {

// A point outside the domain box (or not finite): the cell list cannot place it.
class PointOutsideDomain : public std::runtime_error {
public:
  PointOutsideDomain(std::size_t index, const std::string& where)
      : std::runtime_error(where), index_(index) {}
  std::size_t index() const { return index_; }

private:
  std::size_t index_;
};

// The cell budget of a list over `points` points: a few cells per point, so that a large, sparse
// domain cannot exhaust memory.
inline std::size_t cell_budget(std::size_t points) {
  return 4 * points + 4096;
}

template <int D>
class CellList {
public:
  // cell_size >= the largest query radius. The cell size may be enlarged so that the grid has at
  // most about `max_cells` cells (a huge, sparse domain must not exhaust memory).
  CellList(const Box<D>& domain, double cell_size, std::size_t max_cells);

  // Sorts the points into cells. Throws PointOutsideDomain for the lowest-index point outside.
  void build(const CoordinateView<D>& points);
  // The same for n points given by coordinate(axis, i) -> double, for callers that hold them in
  // another form (a model's fixed-point state) and need no copy in doubles.
  template <class Coordinate>
  void build(std::size_t n, Coordinate&& coordinate);

  double cell_size() const { return cell_size_; }
  std::size_t cell_count() const { return cell_start_.size() - 1; }
  std::size_t point_count() const { return sorted_points_.size(); }
  const std::array<int, D>& cells_per_axis() const { return cells_per_axis_; }

  // The points in cell order: slot s holds point sorted_points()[s]; cell c holds the slots
  // [cell_start()[c], cell_start()[c + 1]). Cells are numbered with axis 0 fastest, so the cells
  // of one row (and their points) are contiguous.
  std::span<const std::uint32_t> sorted_points() const { return sorted_points_; }
  std::span<const std::uint32_t> cell_start() const { return cell_start_; }

  // Calls visit(j) for every point j in the 3^D cells around `query` (a superset of the points
  // within cell_size of it).
  template <class Visit>
  void for_each_candidate(const Vec<D>& query, Visit&& visit) const {
    std::array<int, D> centre{};
    for (int k = 0; k < D; ++k) {
      centre[k] = cell_coordinate(query[k], k);
    }
    std::array<int, D> lo{};
    std::array<int, D> hi{};
    for (int k = 0; k < D; ++k) {
      lo[k] = centre[k] > 0 ? centre[k] - 1 : 0;
      hi[k] = centre[k] + 1 < cells_per_axis_[k] ? centre[k] + 1 : cells_per_axis_[k] - 1;
    }
    if constexpr (D == 1) {
      visit_cells(static_cast<std::size_t>(lo[0]), static_cast<std::size_t>(hi[0]), visit);
    } else if constexpr (D == 2) {
      for (int y = lo[1]; y <= hi[1]; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * cells_per_axis_[0];
        visit_cells(row + lo[0], row + hi[0], visit);
      }
    } else {
      for (int z = lo[2]; z <= hi[2]; ++z) {
        for (int y = lo[1]; y <= hi[1]; ++y) {
          const std::size_t row =
              (static_cast<std::size_t>(z) * cells_per_axis_[1] + y) * cells_per_axis_[0];
          visit_cells(row + lo[0], row + hi[0], visit);
        }
      }
    }
  }

private:
  [[noreturn]] void throw_outside(int axis, std::size_t i, double x) const;
  void sort_into_cells(std::size_t n); // from cell_of_point_: stable counting sort
  int cell_coordinate(double x, int axis) const {
    const int c = static_cast<int>((x - domain_.min[axis]) * inverse_cell_size_);
    return c < 0 ? 0 : (c >= cells_per_axis_[axis] ? cells_per_axis_[axis] - 1 : c);
  }
  // Consecutive cells of one row are contiguous in sorted_points_.
  template <class Visit>
  void visit_cells(std::size_t first_cell, std::size_t last_cell, Visit& visit) const {
    const std::uint32_t begin = cell_start_[first_cell];
    const std::uint32_t end = cell_start_[last_cell + 1];
    for (std::uint32_t s = begin; s < end; ++s) {
      visit(sorted_points_[s]);
    }
  }

  Box<D> domain_;
  double cell_size_;
  double inverse_cell_size_;
  std::array<int, D> cells_per_axis_{};
  std::vector<std::uint32_t> cell_start_;    // cell c holds sorted_points_[start[c], start[c+1])
  std::vector<std::uint32_t> sorted_points_; // point indices, by cell, ascending within a cell
  std::vector<std::uint32_t> cell_of_point_; // scratch for build()
};

template <int D>
template <class Coordinate>
void CellList<D>::build(std::size_t n, Coordinate&& coordinate) {
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("cell list: more than 2^32 - 1 points");
  }
  cell_of_point_.resize(n);
  // Cells in parallel; a point outside the domain is marked and the lowest one reported below,
  // the same for any thread count.
  constexpr std::uint32_t outside = std::numeric_limits<std::uint32_t>::max();
  bool any_outside = false;
#pragma omp parallel for schedule(static) reduction(|| : any_outside)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t cell = 0;
    bool inside = true;
    for (int k = D - 1; k >= 0; --k) {
      const double x = coordinate(k, i);
      inside = inside && x >= domain_.min[k] && x <= domain_.max[k]; // NaN is outside
      cell = cell * static_cast<std::size_t>(cells_per_axis_[k]) +
             static_cast<std::size_t>(cell_coordinate(inside ? x : domain_.min[k], k));
    }
    cell_of_point_[i] = inside ? static_cast<std::uint32_t>(cell) : outside;
    any_outside = any_outside || !inside;
  }
  if (any_outside) {
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = D - 1; k >= 0 && cell_of_point_[i] == outside; --k) {
        const double x = coordinate(k, i);
        if (!(x >= domain_.min[k] && x <= domain_.max[k])) {
          throw_outside(k, i, x);
        }
      }
    }
  }
  sort_into_cells(n);
}

extern template class CellList<1>;
extern template class CellList<2>;
extern template class CellList<3>;

} // namespace revsph
