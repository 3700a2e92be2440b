#include "core/neighbour_rows.hpp"

namespace revsph {

template <int D>
NeighbourRows<D>::NeighbourRows(const Box<D>& domain, double radius, std::size_t row_count,
                                const CoordinateView<D>& fixed)
    : radius_(radius), movable_cells_(domain, radius, cell_budget(row_count)),
      fixed_cells_(domain, radius, cell_budget(fixed[0].size())), fixed_(fixed) {
  fixed_cells_.build(fixed_);
}

template <int D>
void NeighbourRows<D>::update(const CoordinateView<D>& movable) {
  movable_ = movable;
  movable_cells_.build(movable_);
  find_neighbours<D>(movable_cells_, movable_, movable_, radius_, SelfPairs::excluded, of_movable_);
  find_neighbours<D>(fixed_cells_, fixed_, movable_, radius_, SelfPairs::included, of_fixed_);
}

template class NeighbourRows<1>;
template class NeighbourRows<2>;
template class NeighbourRows<3>;

} // namespace revsph
