#pragma once
// One state variable across the carrier sets of a SlotLayout (core/slot_layout.hpp): the
// position of fluid and dummy particles, say, read as one array indexed by carrier, so that model
// code never branches on "which set is this index in". The carriers are the sets' own particles,
// set after set, then their ghosts (core/state_field.hpp), set after set: in a one-process run
// there are none, and in a distributed one the pair passes reach the ghosts through the same
// indices without the model knowing.

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
    owned_count_ = count_;
    for (const StateField<Raw>* field : fields_) {
      firsts_.push_back(count_);
      count_ += field->ghost_count();
    }
  }

  std::size_t count() const { return count_; }
  std::size_t set_count() const { return fields_.size(); }
  std::size_t owned_count(std::size_t set) const { return fields_[set]->count(); }
  std::size_t ghost_count(std::size_t set) const { return fields_[set]->ghost_count(); }
  const distributed::GhostPlan* ghost_plan(std::size_t set) const {
    return fields_[set]->ghost_plan();
  }

  // Component c of one carrier, raw or as a physical value (what SlotLayout::build gathers into
  // slot order without a per-carrier copy).
  Raw raw(int component, std::size_t carrier) const {
    return raw_in(part_of(carrier), component, carrier);
  }
  double real(int component, std::size_t carrier) const {
    const std::size_t part = part_of(carrier);
    return Arith::real(raw_in(part, component, carrier), field_of(part).info().scale);
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
    for (const StateField<Raw>* field : fields_) {
      for (std::size_t g = 0; g < field->ghost_count(); ++g) {
        values.push_back(Arith::real(field->ghost_at(component, g), field->info().scale));
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
    for (const StateField<Raw>* field : fields_) {
      for (std::size_t g = 0; g < field->ghost_count(); ++g) {
        values.push_back(field->ghost_at(component, g));
      }
    }
    return values;
  }

private:
  // Parts 0 .. n-1 are the sets' own particles, n .. 2n-1 their ghosts.
  std::size_t part_of(std::size_t carrier) const {
    std::size_t part = carrier < owned_count_ ? fields_.size() - 1 : firsts_.size() - 1;
    while (carrier < firsts_[part]) {
      --part;
    }
    return part;
  }
  const StateField<Raw>& field_of(std::size_t part) const {
    return *fields_[part < fields_.size() ? part : part - fields_.size()];
  }
  Raw raw_in(std::size_t part, int component, std::size_t carrier) const {
    const std::size_t index = carrier - firsts_[part];
    return part < fields_.size() ? field_of(part).at(component, index)
                                 : field_of(part).ghost_at(component, index);
  }

  std::vector<const StateField<Raw>*> fields_;
  std::vector<std::size_t> firsts_; // the first carrier of each part
  std::size_t owned_count_ = 0;
  std::size_t count_ = 0;
};

} // namespace revsph
