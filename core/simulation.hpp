#pragma once
// The model-independent face of a running simulation, used by the CLI, the verifier and the
// tests. A model is any type satisfying the `Model` concept; ModelSimulation adapts it, so a new
// model never implements this interface by hand.

#include "core/arithmetic.hpp"
#include "core/distributed/agreed_fault.hpp"
#include "core/distributed/state_distribution.hpp"
#include "core/energy.hpp"
#include "core/fault.hpp"
#include "core/global_totals.hpp"
#include "core/interaction_reach.hpp"
#include "core/particle_sets.hpp"
#include "core/particle_view.hpp"
#include "core/periodic_images.hpp"
#include "core/state_snapshot.hpp"
#include "core/step_composition.hpp"
#include "core/step_splitting.hpp"
#include "core/units.hpp"

#include <concepts>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace revsph {

// A particle set's name, size and motion (core/particle_sets.hpp).
using ParticleCount = SetSize;

struct SimulationInfo {
  std::string case_name;
  std::string model;
  int dimension = 2;
  Arithmetic arithmetic = Arithmetic::fixed;
  double dt = 0.0;
  // The speed of sound the time step resolves (c of dt = courant h / c; the initial one where
  // it varies), for the progress line's max |v| / c; 0 where the model sets none.
  double sound_speed = 0.0;
  // Where the model's irreversible operators go in the step (core/step_splitting.hpp): the
  // case's step.splitting, for a model that has operators.
  Splitting splitting = Splitting::strang;
  // Filled by ModelSimulation from the state's particle sets.
  std::vector<ParticleCount> particles;
  // The sub-steps and hooks that act irreversibly in this case ("name: what"), filled by
  // ModelSimulation from their declarations (core/step_composition.hpp): with any of them the
  // case cannot return bit for bit, and the verifier says so.
  std::vector<std::string> irreversible_terms;
  // What the setup computed that a reader of the output should be able to see and repeat
  // (e.g. the initial state correction's seed, iterations and residual), as name-value pairs.
  std::vector<std::pair<std::string, std::string>> setup_report;

  std::size_t moving_particle_count() const {
    std::size_t n = 0;
    for (const ParticleCount& p : particles) {
      n += p.moving ? p.count : 0;
    }
    return n;
  }
};

// What a model provides (see README "Adding a model").
template <class M>
concept Model = requires(M& model, const M& const_model) {
  // The palindromic sequence of sub-steps of one time step.
  { M::palindrome() } -> std::convertible_to<std::span<const Substep<M>>>;
  // The declared state (core/state_field.hpp), visited by for_each_field.
  { model.state() } -> DeclaredState;
  // Energy terms at the current (synchronised) state.
  { model.energy() } -> std::same_as<EnergyBudget>;
  // Physical per-particle quantities for snapshots (density, pressure, energy per particle, …).
  model.derived_views(std::declval<const ViewSink&>());
  // Forget cached quantities derived from the state (after the state was replaced).
  model.invalidate_derived();
  { const_model.info() } -> std::convertible_to<const SimulationInfo&>;
};

// Optional: a time reversal of the model's own. Without it the reversal negates the state's odd
// variables (apply_time_reversal), which is all a model whose state is its declaration needs.
template <class M>
concept HasOwnTimeReversal = requires(M& model) {
  model.reverse_time();
};

// Optional: quantities reported with the energies every output (an error norm against an
// analytic solution, say), as named values.
template <class M>
concept HasDiagnostics = requires(M& model) {
  { model.diagnostics() } -> std::same_as<std::vector<EnergyTerm>>;
};
// The same for diagnostics that need the simulated time (an error against an analytic solution
// that evolves, say); the time is steps taken * dt.
template <class M>
concept HasTimedDiagnostics = requires(M& model, double time) {
  { model.diagnostics(time) } -> std::same_as<std::vector<EnergyTerm>>;
};

// Optional: particles whose position diagnostics.csv follows (a probe point's nearest particle,
// chosen at setup), as (set, index in the whole state). The core reports each as
// PREFIX_x, PREFIX_y (, PREFIX_z) before the model's own diagnostics, read from whichever process
// holds the particle, so that a model never looks a particle up by its index on a process.
struct ProbeParticle {
  std::string name; // the columns' prefix ("probe")
  std::string particle_set;
  std::size_t particle = 0;
};
template <class M>
concept HasProbeParticles = requires(const M& model) {
  { model.probe_particles() } -> std::convertible_to<std::vector<ProbeParticle>>;
};

// Optional: energy the model exchanged with the outside since the run began (a heater's input,
// heat through a cooler's walls), kept outside the particles' state in members of its own. The
// model names them once, `static auto energy_accounts() { return std::array{EnergyAccount<Model>{
// "heater_input", &Model::heater_energy_}, ...}; }`; a snapshot carries them so that a run
// continued from it (`revsph run --from`) keeps its energy budget, and a name the model does not
// keep is refused (std::invalid_argument).
template <class M>
struct EnergyAccount {
  const char* name;
  RunTotal M::*value;
};
template <class M>
concept HasEnergyAccounts = requires {
  { *std::begin(M::energy_accounts()) } -> std::convertible_to<EnergyAccount<M>>;
};

// Optional: a model whose terms depend on the time (a decay law, a ramp) is told the time at the
// start of every step, from the step count, so that a run continued from a snapshot sees the
// same times as one that never stopped.
template <class M>
concept HasClock = requires(M& model, double time) {
  model.set_time(time);
};

// Optional: operations after each full step, outside the palindrome (core/step_composition.hpp).
template <class M>
concept HasStepHooks = requires {
  { M::step_hooks() } -> std::convertible_to<std::span<const StepHook<M>>>;
};

// Optional: irreversible operators over dt (a dissipation, a relaxation), which the core places
// around the palindrome by the case's splitting (core/step_splitting.hpp).
template <class M>
concept HasIrreversibleOperators = requires {
  { M::irreversible_operators() } -> std::convertible_to<std::span<const IrreversibleOperator<M>>>;
};

template <class M>
std::span<const StepHook<M>> step_hooks_of() {
  if constexpr (HasStepHooks<M>) {
    return M::step_hooks();
  } else {
    return {};
  }
}

class Simulation {
public:
  virtual ~Simulation() = default;

  virtual const SimulationInfo& info() const = 0;
  // Advances by `steps` full time steps. Throws SimulationFault naming the particle, variable
  // and step if a value overflows, turns non-finite or leaves the domain.
  virtual void advance(std::int64_t steps) = 0;
  virtual void reverse_time() = 0;
  // In a distributed run (more than one process, docs/design/distributed.md) a state snapshot
  // holds this process's rows and says which (StateSnapshot::pieces); a hash, a comparison or a
  // snapshot file of it sees the whole state.
  virtual StateSnapshot capture_state() = 0;
  // The state without a copy of its fixed-point fields (revsph::borrow_state): valid only until
  // the state changes (for a snapshot write or a hash).
  virtual StateSnapshot borrow_state() = 0;
  // A whole state (a snapshot file's), or one captured by this run's processes in pieces (any
  // decomposition: each process gets its region's particles again).
  virtual void restore_state(const StateSnapshot& snapshot) = 0;
  virtual EnergyBudget energy() = 0;
  // Hands the physical views to `sink` one by one (see ViewSink).
  virtual void derived_views(const ViewSink& sink) = 0;
  // Empty unless the model reports diagnostics.
  virtual std::vector<EnergyTerm> diagnostics() = 0;
  // Empty unless the model keeps energy accounts (HasEnergyAccounts).
  virtual std::vector<EnergyTerm> energy_accounts() const = 0;
  virtual void restore_energy_accounts(const std::vector<EnergyTerm>& accounts) = 0;

  // Single sub-steps, to check each one's reversibility on its own.
  virtual std::vector<std::string> substep_names() const = 0;
  virtual void apply_substep(std::size_t index, double dt) = 0;

  // This process's share of a distributed run (zeros but the own particles on one process).
  virtual distributed::DistributionCounts distribution_counts() const = 0;

  std::int64_t steps_taken() const { return steps_taken_; }
  double time() const { return time_at(steps_taken_); }
  // The simulated time after `step` steps: step * dt, or, in a run continued from a snapshot
  // written at another dt (`revsph run --from S --set discretisation.courant_number=...`), the
  // snapshot's time plus the steps since at this dt. Continuing at the same dt keeps step * dt,
  // so a continued run takes the same times, bit for bit, as one that never stopped.
  double time_at(std::int64_t step) const {
    const double dt = info().dt;
    if (clock_origin_step_ < 0) {
      return static_cast<double>(step) * dt;
    }
    return clock_origin_time_ + static_cast<double>(step - clock_origin_step_) * dt;
  }
  // For a restart: the state came from a snapshot taken after `steps` steps, at time `time`.
  void continue_from(std::int64_t steps, double time) {
    steps_taken_ = steps;
    clock_origin_step_ = -1;
    if (time != static_cast<double>(steps) * info().dt) {
      clock_origin_step_ = steps;
      clock_origin_time_ = time;
    }
  }

protected:
  std::int64_t steps_taken_ = 0;

private:
  std::int64_t clock_origin_step_ = -1; // -1: time = steps * dt
  double clock_origin_time_ = 0.0;
};

template <Model M>
class ModelSimulation final : public Simulation {
public:
  // Checks the declarations: a palindromic step, every state field in a set with a scale.
  explicit ModelSimulation(M model) : model_(std::move(model)), info_(model_.info()) {
    require_palindrome<M>(M::palindrome());
    require_complete(model_.state());
    info_.particles = set_sizes(model_.state());
    place_irreversible_operators();
    // A periodic domain's images travel as ghosts (docs/design/periodic.md): one process then
    // distributes its state to itself.
    if (distributed::process_count() > 1 || has_periodic_positions(model_.state())) {
      distribute();
    }
  }

  // The ghost reach this simulation set (distribute) must not limit the next one's set-up.
  ~ModelSimulation() override {
    if (distribution_) {
      forget_interaction_radii();
    }
  }
  ModelSimulation(const ModelSimulation&) = delete;
  ModelSimulation& operator=(const ModelSimulation&) = delete;

  const SimulationInfo& info() const override { return info_; }

  void advance(std::int64_t steps) override {
    const double dt = model_.info().dt;
    for (std::int64_t s = 0; s < steps; ++s) {
      try {
        if constexpr (HasClock<M>) {
          model_.set_time(time_at(steps_taken_));
        }
        for (const Substep<M>& substep : step_) {
          (model_.*substep.apply)(substep.dt_fraction * dt);
          refresh_pieces();
        }
        for (const StepHook<M>& hook : step_hooks_of<M>()) {
          (model_.*hook.apply)(steps_taken_ + 1);
          refresh_pieces();
        }
      } catch (const SimulationFault& fault) {
        throw SimulationFault(reported(fault), steps_taken_ + 1, fault.shared());
      }
      ++steps_taken_;
    }
  }

  void reverse_time() override {
    if constexpr (HasOwnTimeReversal<M>) {
      model_.reverse_time();
    } else {
      apply_time_reversal(model_.state());
    }
    refresh_pieces();
  }
  StateSnapshot capture_state() override {
    return with_pieces(revsph::capture_state(model_.state()));
  }
  StateSnapshot borrow_state() override {
    return with_pieces(revsph::borrow_state(model_.state()));
  }
  void restore_state(const StateSnapshot& snapshot) override {
    if (distribution_) {
      distribution_->restore(model_.state(), snapshot);
    } else if (!snapshot.pieces.empty()) {
      throw std::invalid_argument("a piece of a distributed state cannot be restored by one "
                                  "process holding the whole state");
    } else {
      revsph::restore_state(model_.state(), snapshot);
    }
    model_.invalidate_derived();
  }
  EnergyBudget energy() override {
    EnergyBudget budget = attributing_faults([&] { return model_.energy(); });
    for (EnergyTerm& term : budget.terms) {
      term.unit = energy_unit_of(info_.dimension);
    }
    return budget;
  }
  void derived_views(const ViewSink& sink) override {
    attributing_faults([&] { model_.derived_views(sink); });
  }
  std::vector<EnergyTerm> diagnostics() override {
    std::vector<EnergyTerm> terms = probe_positions();
    std::vector<EnergyTerm> own;
    if constexpr (HasTimedDiagnostics<M>) {
      own = attributing_faults([&] { return model_.diagnostics(time()); });
    } else if constexpr (HasDiagnostics<M>) {
      own = attributing_faults([&] { return model_.diagnostics(); });
    }
    for (const EnergyTerm& term : own) {
      if (term.unit.empty()) {
        throw std::logic_error("diagnostic '" + term.name + "' of model " + info_.model +
                               " has no unit");
      }
    }
    terms.insert(terms.end(), own.begin(), own.end());
    return terms;
  }

  std::vector<EnergyTerm> energy_accounts() const override {
    std::vector<EnergyTerm> terms;
    if constexpr (HasEnergyAccounts<M>) {
      for (const EnergyAccount<M>& account : M::energy_accounts()) {
        terms.push_back({account.name, model_.*account.value});
      }
    }
    return terms;
  }
  void restore_energy_accounts(const std::vector<EnergyTerm>& accounts) override {
    for (const EnergyTerm& given : accounts) {
      RunTotal* kept = account_named(given.name);
      if (kept == nullptr) {
        throw std::invalid_argument("unknown energy account '" + given.name + "' (model " +
                                    info_.model + ")");
      }
      *kept = given.value;
    }
  }

  std::vector<std::string> substep_names() const override {
    std::vector<std::string> names;
    for (const Substep<M>& s : step_) {
      names.emplace_back(s.name);
    }
    return names;
  }
  void apply_substep(std::size_t index, double dt) override {
    attributing_faults([&] { (model_.*step_.at(index).apply)(dt); });
    refresh_pieces();
  }

  distributed::DistributionCounts distribution_counts() const override {
    if (distribution_) {
      return distribution_->counts();
    }
    distributed::DistributionCounts counts;
    counts.own_particles = 0;
    for (const ParticleCount& set : info_.particles) {
      counts.own_particles += set.count;
    }
    return counts;
  }

  M& model() { return model_; }

private:
  // The step: the palindrome with the operators that act in this case placed by the case's
  // splitting; their terms first in the irreversible terms, each with its placement.
  // The member keeping the energy account `name`, or nullptr.
  RunTotal* account_named(const std::string& name) {
    if constexpr (HasEnergyAccounts<M>) {
      for (const EnergyAccount<M>& account : M::energy_accounts()) {
        if (name == account.name) {
          return &(model_.*account.value);
        }
      }
    }
    return nullptr;
  }

  void place_irreversible_operators() {
    std::vector<IrreversibleOperator<M>> acting;
    const bool marked = marked_strang_sites<M>(M::palindrome()) != 0;
    std::span<const IrreversibleOperator<M>> operators;
    if constexpr (HasIrreversibleOperators<M>) {
      operators = M::irreversible_operators();
    }
    for (const IrreversibleOperator<M>& op : operators) {
      if (const std::string what = op.acts(model_); !what.empty()) {
        acting.push_back(op);
        info_.irreversible_terms.push_back(std::string(op.name) + ": " + what + ", " +
                                           placement_text(info_.splitting, marked));
      }
    }
    step_ = compose_step<M>(M::palindrome(), acting, info_.splitting);
    for (std::string& term : irreversible_terms<M>(model_, M::palindrome(), step_hooks_of<M>())) {
      info_.irreversible_terms.push_back(std::move(term));
    }
  }

  // A fault found outside advance(), in quantities derived from the current state (say the
  // forces of a restored snapshot), belongs to the next step: the first one to use them.
  template <class Compute>
  auto attributing_faults(Compute&& compute) {
    try {
      return compute();
    } catch (const SimulationFault& fault) {
      if (fault.step() >= 0) {
        throw;
      }
      throw SimulationFault(reported(fault), steps_taken_ + 1, fault.shared());
    }
  }

  // More than one process: each keeps its region's particles and ghosts of its neighbours'. The
  // reach is the largest radius the setup's lists use, found by computing the energies once over
  // the whole state (which builds every pair list); a later list over a larger radius is
  // refused (core/interaction_reach.hpp).
  void distribute() {
    forget_interaction_radii();
    (void)model_.energy();
    const double reach = distributed::max_over_processes(largest_interaction_radius());
    // REVSPH_REBALANCE_ABOVE (docs/running.md): when the regions are cut again; 1: at every
    // migration, which the tests use to check that a rebalance changes no bit.
    // REVSPH_BALANCE_BY_TIME=0: on the estimated work alone (to measure what the measured
    // computing times add); `every_reading`: cut at every reading of them (the tests).
    const char* rebalance_above = std::getenv("REVSPH_REBALANCE_ABOVE");
    const char* by_time = std::getenv("REVSPH_BALANCE_BY_TIME");
    distribution_ = std::make_unique<distributed::StateDistribution<StateOf>>(
        model_.state(), info_.dimension, reach,
        rebalance_above != nullptr ? std::strtod(rebalance_above, nullptr) : 1.05,
        by_time == nullptr                        ? distributed::TimeBalance::on
        : std::string(by_time) == "0"             ? distributed::TimeBalance::off
        : std::string(by_time) == "every_reading" ? distributed::TimeBalance::every_reading
                                                  : distributed::TimeBalance::on);
    limit_interaction_radius(reach);
    model_.invalidate_derived();
  }
  // After every change of the state: migration and ghosts (nothing in a one-process run).
  void refresh_pieces() {
    if (distribution_ && distribution_->refresh(model_.state())) {
      model_.invalidate_derived();
    }
  }
  // The probe particles' positions (HasProbeParticles): the holder's value, summed exactly with
  // the others' zeros (collective).
  std::vector<EnergyTerm> probe_positions() {
    std::vector<EnergyTerm> terms;
    if constexpr (HasProbeParticles<M>) {
      static constexpr const char* axes[] = {"_x", "_y", "_z"};
      for (const ProbeParticle& probe : model_.probe_particles()) {
        std::vector<double> position(static_cast<std::size_t>(info_.dimension), 0.0);
        for_each_set(model_.state(), [&](auto& set) {
          if (std::string(std::remove_cvref_t<decltype(set)>::set.name) != probe.particle_set) {
            return;
          }
          const std::optional<std::size_t> local =
              distribution_ ? distribution_->local_index(probe.particle_set, probe.particle)
                            : std::optional<std::size_t>(probe.particle);
          for_each_field_of(set, [&](const auto& field) {
            if (field.info().name != "position" || !local) {
              return;
            }
            for (int k = 0; k < field.components() && k < info_.dimension; ++k) {
              position[static_cast<std::size_t>(k)] =
                  distributed::detail::real_value(field.at(k, *local), field.info().scale);
            }
          });
        });
        for (std::size_t k = 0; k < position.size(); ++k) {
          ExactDoubleSum held;
          held.add(position[k]);
          terms.push_back({probe.name + axes[k], global_total(held), "m"});
        }
      }
    }
    return terms;
  }
  // In a distributed run, a snapshot of this process's rows says which they are.
  StateSnapshot with_pieces(StateSnapshot snapshot) const {
    if (distribution_) {
      snapshot.pieces = distribution_->own_rows();
    }
    return snapshot;
  }
  // What a fault reports: its particle by its index in the whole state; a fault every process
  // threw together (a shared one) the one all agree on (collective).
  FaultDescription reported(const SimulationFault& fault) const {
    if (!fault.shared()) {
      return with_global_index(fault.fault());
    }
    return distributed::agreed_fault(
        fault.found_elsewhere() ? std::nullopt : std::optional(with_global_index(fault.fault())));
  }
  // A fault names its particle by its index on this process: in a distributed run, by its index
  // in the whole state instead.
  FaultDescription with_global_index(FaultDescription fault) const {
    if (distribution_) {
      fault.particle = distribution_->global_index(fault.particle_set, fault.particle);
    }
    return fault;
  }

  using StateOf = std::remove_cvref_t<decltype(std::declval<M&>().state())>;
  M model_;
  SimulationInfo info_;
  std::vector<Substep<M>> step_;
  std::unique_ptr<distributed::StateDistribution<StateOf>> distribution_;
};

} // namespace revsph
