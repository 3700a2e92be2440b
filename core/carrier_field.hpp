#pragma once
// One state variable across the carrier sets of a SlotLayout (core/slot_layout.hpp): the
// position of fluid and dummy particles, say, read as one array indexed by carrier, so that model
// code never branches on "which set is this index in".

#include "core/state_field.hpp"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <vector>

namespace revsph {

template <class Arith>
class CarrierField {
public:
  using Raw = typename Arith::Raw;

  // The same variable of each carrier set, in the layout's set order.
  CarrierField(std::initializer_list<const StateField<Raw>*> per_set) : fields_(per_set) {
    for (const StateField<Raw>* field : fields_) {
      firsts_.push_back(count_);
      count_ += field->count();
      if (field->components() != fields_.front()->components()) {
        throw std::logic_error("carrier field " + field->info().name +
                               ": the sets disagree on its components");
      }
    }
  }

  std::size_t count() const { return count_; }

  // Component c of one carrier, raw or as a physical value (what SlotLayout::build gathers into
  // slot order without a per-carrier copy).
  Raw raw(int component, std::size_t carrier) const {
    const std::size_t set = set_of(carrier);
    return fields_[set]->at(component, carrier - firsts_[set]);
  }
  double real(int component, std::size_t carrier) const {
    const std::size_t set = set_of(carrier);
    return Arith::real(fields_[set]->at(component, carrier - firsts_[set]),
                       fields_[set]->info().scale);
  }

  // Component c of every carrier, in carrier order, as physical values.
  std::vector<double> reals(int component = 0) const {
    std::vector<double> values;
    values.reserve(count_);
    for (const StateField<Raw>* field : fields_) {
      for (const Raw raw : field->component(component)) {
        values.push_back(Arith::real(raw, field->info().scale));
      }
    }
    return values;
  }
  // The same as raw values.
  std::vector<Raw> raws(int component = 0) const {
    std::vector<Raw> values;
    values.reserve(count_);
    for (const StateField<Raw>* field : fields_) {
      const auto part = field->component(component);
      values.insert(values.end(), part.begin(), part.end());
    }
    return values;
  }

private:
  std::size_t set_of(std::size_t carrier) const {
    std::size_t set = fields_.size() - 1;
    while (carrier < firsts_[set]) {
      --set;
    }
    return set;
  }

  std::vector<const StateField<Raw>*> fields_;
  std::vector<std::size_t> firsts_;
  std::size_t count_ = 0;
};

} // namespace revsph
