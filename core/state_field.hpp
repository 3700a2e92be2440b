#pragma once
// The one declaration of a state variable (name, unit, parity, scale) and its storage.
//
// A model's state is a struct of particle sets, each a struct of StateField members
// (core/particle_sets.hpp). That single declaration drives the time reversal (odd fields are
// negated), the state hash, the bitwise comparison of the verifier and the snapshots: no code is
// written per model for those.

#include "core/periodic_box.hpp"
#include "fixedpoint/scale.hpp"

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace revsph {

namespace distributed {
class GhostPlan;
}

// Behaviour under time reversal R: odd variables (velocities, fluxes) change sign.
enum class Parity { even, odd };

// Declared with designated initialisers: {.name = "velocity", .unit = "m/s", .parity =
// Parity::odd, .components = D}. The set's name is stamped by declare_state; the scale is the
// setup's scale of the field's quantity (set_scales, core/particle_sets.hpp): the quantity is the
// field's name unless it names another (.scaled_as = "velocity" for a copy of a velocity). A field
// without a scale is an error before the first step (require_complete).
struct VariableInfo {
  std::string particle_set; // "fluid", "wall", … (a model may have several species)
  std::string name;         // "velocity"
  std::string unit;         // "m/s"
  Parity parity = Parity::even;
  int components = 1; // 1 scalar, D vector, D*D matrix
  fixedpoint::Scale scale;
  bool evolved = true;   // false: fixed at setup (masses, wall positions, integration constants)
  std::string scaled_as; // the quantity whose scale it is stored in; empty: its own name
  // A position field's periodic axes ([domain] periodic; core/periodic_box.hpp): the drift wraps
  // it, the distribution gives its particles images across the periodic faces. Set by fill_set.
  PeriodicBox period;
  // Positive by its nature (a mass, an absolute temperature): a point file's value must be > 0.
  bool positive = false;

  const std::string& quantity() const { return scaled_as.empty() ? name : scaled_as; }
};

// Values of one variable for all particles of its set, component-major: component c of particle i
// is values[c * count + i]. Raw is std::int64_t (fixed point) or double (the FloPA variant).
//
// In a distributed run (docs/design/distributed.md) the particles are this process's own, and a
// ghost segment holds copies of other processes' particles near its region, laid out the same
// way. Only the distributed layer fills it and only CarrierField reads it (the pair passes):
// count(), all(), component() and at() are the owned particles, so a model's pointwise loops
// never see a ghost. Without ghosts (every one-process run) the segment is empty.
template <class Raw>
class StateField {
public:
  using value_type = Raw;

  explicit StateField(VariableInfo info) : info_(std::move(info)) {}

  const VariableInfo& info() const { return info_; }
  void set_scale(const fixedpoint::Scale& scale) {
    info_.scale = scale;
    has_scale_ = true;
  }
  bool has_scale() const { return has_scale_; }
  void set_period(const PeriodicBox& period) { info_.period = period; }
  void set_particle_set(std::string name) { info_.particle_set = std::move(name); }
  std::size_t count() const { return count_; }
  int components() const { return info_.components; }

  void resize(std::size_t count) {
    count_ = count;
    values_.assign(count * static_cast<std::size_t>(info_.components), Raw{});
  }

  std::span<Raw> component(int c) {
    assert(c >= 0 && c < info_.components);
    return {values_.data() + static_cast<std::size_t>(c) * count_, count_};
  }
  std::span<const Raw> component(int c) const {
    assert(c >= 0 && c < info_.components);
    return {values_.data() + static_cast<std::size_t>(c) * count_, count_};
  }
  // Particle i's component c; i >= count() is ghost i - count() (what a loop over a layout's
  // slots reaches through SlotLayout::particle_in_slot: it reads a ghost like an own particle,
  // and what it writes there is replaced at the next refresh).
  Raw& at(int c, std::size_t i) {
    return i < count_ ? values_[static_cast<std::size_t>(c) * count_ + i]
                      : ghost_values_[static_cast<std::size_t>(c) * ghost_count_ + i - count_];
  }
  const Raw& at(int c, std::size_t i) const {
    return i < count_ ? values_[static_cast<std::size_t>(c) * count_ + i]
                      : ghost_values_[static_cast<std::size_t>(c) * ghost_count_ + i - count_];
  }
  std::span<Raw> all() { return values_; }
  std::span<const Raw> all() const { return values_; }

  std::size_t ghost_count() const { return ghost_count_; }
  // `values`: component-major over `count` ghosts. `plan`: the exchange that brought them
  // (core/distributed/ghost_plan.hpp), along which a pair pass sends its ghosts' sums; null in
  // a test that places ghosts by hand.
  void set_ghosts(std::size_t count, std::vector<Raw> values,
                  const distributed::GhostPlan* plan = nullptr) {
    assert(values.size() == count * static_cast<std::size_t>(info_.components));
    ghost_count_ = count;
    ghost_values_ = std::move(values);
    ghost_plan_ = plan;
  }
  const distributed::GhostPlan* ghost_plan() const { return ghost_plan_; }
  const Raw& ghost_at(int c, std::size_t g) const {
    return ghost_values_[static_cast<std::size_t>(c) * ghost_count_ + g];
  }

private:
  VariableInfo info_;
  bool has_scale_ = false;
  std::size_t count_ = 0;
  std::vector<Raw> values_;
  std::size_t ghost_count_ = 0;
  std::vector<Raw> ghost_values_;
  const distributed::GhostPlan* ghost_plan_ = nullptr;
};

} // namespace revsph
