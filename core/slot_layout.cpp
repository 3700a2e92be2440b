#include "core/slot_layout.hpp"

#include <algorithm>

namespace revsph {

namespace {

std::size_t total_count(const std::vector<CarrierSet>& sets) {
  std::size_t total = 0;
  for (const CarrierSet& set : sets) {
    total += set.count;
  }
  return total;
}

} // namespace

template <int D>
SlotLayout<D>::SlotLayout(const Box<D>& domain, double cell_size, std::vector<CarrierSet> sets)
    : sets_(std::move(sets)), carrier_count_(total_count(sets_)),
      cells_(domain, cell_size, cell_budget(carrier_count_)) {
  // Two bits per set in SlotInSet's mask: its own particles and its ghosts.
  if (sets_.size() > 32) {
    throw std::logic_error("a slot layout holds at most 32 particle sets");
  }
  first_carrier_.push_back(0);
  for (const CarrierSet& set : sets_) {
    first_carrier_.push_back(first_carrier_.back() + set.count);
  }
  first_carrier_.insert(first_carrier_.end(), sets_.size(), first_carrier_.back()); // no ghosts
}

template <int D>
std::pair<const char*, std::size_t> SlotLayout<D>::particle_of_carrier(std::size_t carrier) const {
  const SetParticle particle = particle_of(carrier);
  return {sets_[particle.set].name.c_str(), particle.index};
}

template <int D>
void SlotLayout<D>::record_fault(FaultRecorder& faults, std::size_t slot, const char* variable,
                                 const char* reason) const {
  const SetParticle particle = particle_in_slot(slot);
  faults.record(particle.index, sets_[particle.set].name.c_str(), variable, reason);
}

template class SlotLayout<1>;
template class SlotLayout<2>;
template class SlotLayout<3>;

} // namespace revsph
