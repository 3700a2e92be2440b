#include "core/cell_list.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace revsph {

template <int D>
CellList<D>::CellList(const Box<D>& domain, double cell_size, std::size_t max_cells)
    : domain_(domain), cell_size_(cell_size) {
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("cell list: the cell size must be positive and finite");
  }
  for (int k = 0; k < D; ++k) {
    if (!std::isfinite(domain.max[k] - domain.min[k])) {
      throw std::invalid_argument("cell list: the domain's extent must be finite");
    }
  }
  for (;;) {
    // Counted in double and converted only once they fit: a cell count beyond int (a huge
    // domain) must enlarge the cells, not overflow the conversion (undefined behaviour).
    double cells = 1.0;
    bool fits_int = true;
    std::array<double, D> per_axis{};
    for (int k = 0; k < D; ++k) {
      const double extent = domain.max[k] - domain.min[k];
      per_axis[k] = std::max(1.0, std::ceil(extent / cell_size_));
      fits_int = fits_int && per_axis[k] <= static_cast<double>(std::numeric_limits<int>::max());
      cells *= per_axis[k];
    }
    if (fits_int && cells <= static_cast<double>(std::max<std::size_t>(max_cells, 1))) {
      for (int k = 0; k < D; ++k) {
        cells_per_axis_[k] = static_cast<int>(per_axis[k]);
      }
      break;
    }
    // Enlarging cells only adds candidates that the distance filter rejects.
    cell_size_ *= 1.25;
  }
  inverse_cell_size_ = 1.0 / cell_size_;
  std::size_t total = 1;
  for (int k = 0; k < D; ++k) {
    total *= static_cast<std::size_t>(cells_per_axis_[k]);
  }
  cell_start_.assign(total + 1, 0);
}

template <int D>
void CellList<D>::build(const CoordinateView<D>& points) {
  build(points[0].size(), [&](int axis, std::size_t i) { return points[axis][i]; });
}

template <int D>
void CellList<D>::throw_outside(int axis, std::size_t i, double x) const {
  std::ostringstream where;
  // The point's index is the exception's, not the message's: the message must read the same
  // for any decomposition of a distributed run (core/slot_layout.hpp).
  where << "outside the domain on axis " << axis << " (coordinate " << x << ", domain ["
        << domain_.min[axis] << ", " << domain_.max[axis] << "])";
  throw PointOutsideDomain(i, where.str());
}

template <int D>
void CellList<D>::sort_into_cells(std::size_t n) {
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) {
    ++cell_start_[cell_of_point_[i] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) {
    cell_start_[c] += cell_start_[c - 1];
  }
  sorted_points_.resize(n);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    sorted_points_[fill[cell_of_point_[i]]++] = static_cast<std::uint32_t>(i);
  }
}

template class CellList<1>;
template class CellList<2>;
template class CellList<3>;

} // namespace revsph
