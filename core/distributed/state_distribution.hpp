#pragma once
// A model's declared state held in pieces by the processes of a distributed run
// (docs/design/distributed.md, pieces 4 to 6): each process owns the particles of its region of
// space, in global-index order, and holds copies (ghosts) of the other processes' particles
// within the interaction reach, in every field's ghost segment (core/state_field.hpp), where the
// pair passes find them through the carrier fields. The model never sees any of this.
//
// Ghosts are listed with a skin (the reach plus a quarter of it): particles migrate to the owner
// of their position and the lists are remade only when some particle has moved more than half
// the skin since the last time, so that in between the ghosts still cover every pair within the
// reach; each refresh then only sends the values. Sums are exact, so who owns a particle changes
// no bit of any result, only the speed.

#include "core/arithmetic.hpp"
#include "core/distributed/distribution_counts.hpp"
#include "core/distributed/ghost_plan.hpp"
#include "core/distributed/measured_cost.hpp"
#include "core/distributed/migration.hpp"
#include "core/distributed/processes.hpp"
#include "core/distributed/set_rows.hpp"
#include "core/distributed/spatial_partition.hpp"
#include "core/distributed/work_estimate.hpp"
#include "core/particle_sets.hpp"
#include "core/periodic_images.hpp"
#include "core/state_snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace revsph::distributed {

namespace detail {

// A field's own rows particle after particle (values[i * components + c]).
template <class Raw>
std::vector<Raw> rows_of(const StateField<Raw>& field) {
  const auto n = field.count();
  const auto width = static_cast<std::size_t>(field.components());
  std::vector<Raw> rows(n * width);
  for (std::size_t c = 0; c < width; ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      rows[i * width + c] = field.at(static_cast<int>(c), i);
    }
  }
  return rows;
}

// Component-major values of `count` particles from rows.
template <class Raw>
std::vector<Raw> components_of_rows(const std::vector<Raw>& rows, std::size_t width) {
  const std::size_t count = width == 0 ? 0 : rows.size() / width;
  std::vector<Raw> values(rows.size());
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < width; ++c) {
      values[c * count + i] = rows[i * width + c];
    }
  }
  return values;
}

template <class Raw>
void replace_own_rows(StateField<Raw>& field, const std::vector<Raw>& rows) {
  const auto width = static_cast<std::size_t>(field.components());
  const std::vector<Raw> values = components_of_rows(rows, width);
  field.resize(width == 0 ? 0 : rows.size() / width);
  std::copy(values.begin(), values.end(), field.all().begin());
}

template <class Raw>
double real_value(Raw raw, const fixedpoint::Scale& scale) {
  if constexpr (std::is_same_v<Raw, double>) {
    return raw;
  } else {
    return FixedArithmetic::real(raw, scale);
  }
}

// The set's "position" field, or null for a set that has none (it stays whole on process 0).
template <ParticleSet Set>
const auto* position_field(Set& set) {
  using Field = std::remove_cvref_t<decltype(std::get<0>(set.fields()))>;
  const Field* position = nullptr;
  for_each_field_of(set, [&](const Field& field) {
    if (field.info().name == "position") {
      position = &field;
    }
  });
  return position;
}

// The positions of a set's own particles, point after point (metres).
template <class Raw>
std::vector<double> points_of(const StateField<Raw>& position) {
  std::vector<double> points(position.count() * static_cast<std::size_t>(position.components()));
  const auto d = static_cast<std::size_t>(position.components());
  for (std::size_t i = 0; i < position.count(); ++i) {
    for (std::size_t k = 0; k < d; ++k) {
      points[i * d + k] = real_value(position.at(static_cast<int>(k), i), position.info().scale);
    }
  }
  return points;
}

} // namespace detail

template <DeclaredState State>
class StateDistribution {
public:
  // Every process holds the whole state (each ran the setup): the regions are cut, and each
  // process keeps the particles its region holds and receives its ghosts (collective).
  // `rebalance_above`: the regions are cut again when the largest process's estimated work
  // exceeds the mean by this factor at a migration (and by more than right after the last cut);
  // 1 or less: at every migration. `time_balance`: also when the processes' measured computing
  // times differ by that factor plus 0.05, the particles then weighed by their process's measured
  // cost per unit of estimated work (measured_cost.hpp).
  StateDistribution(State& state, int dimension, double reach, double rebalance_above = 1.05,
                    TimeBalance time_balance = TimeBalance::on)
      : partition_(dimension, PartitionMethod::coordinate_bisection), dimension_(dimension),
        reach_(reach), skin_(0.25 * reach), rebalance_above_(rebalance_above),
        time_balance_(rebalance_above > 1.0 ? time_balance : TimeBalance::off),
        cost_(time_balance_ == TimeBalance::every_reading ? 0.0 : 0.5) {
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_.emplace_back();
      pieces.name = std::string(std::remove_cvref_t<decltype(set)>::set.name);
      pieces.total = set_size(set);
      pieces.has_position = detail::position_field(set) != nullptr;
      if (pieces.has_position) {
        require_room_for_images(detail::position_field(set)->info().period);
      }
    });
    cut_regions(state, /*whole_state_held=*/true);
    keep_own_particles(state);
    remake_ghost_lists(state);
    refresh_ghosts(state, /*every_field=*/true);
    imbalance_after_cut_ = measure_work(state);
    cost_.restart(work_);
  }
  StateDistribution(const StateDistribution&) = delete;
  StateDistribution& operator=(const StateDistribution&) = delete;

  // After a sub-step or a step hook changed the state (collective): particles that moved far
  // enough migrate and the ghost lists are remade; every ghost gets its owner's values. Every
  // set and field, whatever its declared motion: a set declared fixed may still turn rigidly or
  // carry a clock (two_fluid's turning walls, shtc's driven lid). Returns whether particles may
  // have changed owner (the model's layouts must then be rebuilt).
  bool refresh(State& state) {
    const bool remade = moved_beyond_skin(state);
    // A solid that barely moves never remakes its lists: its regions are cut again on measured
    // times alone.
    const bool cut_on_time = measured_times_uneven();
    if (!remade && !cut_on_time) {
      refresh_ghosts(state, /*every_field=*/false);
      return false;
    }
    // One process (a periodic domain's images, nothing else) owns everything: no cut, no
    // migration, only new image lists.
    const bool alone = process_count() == 1;
    const bool rebalance = !alone && (work_drifted_apart(state) || cut_on_time);
    if (rebalance) {
      cut_regions(state, /*whole_state_held=*/false, static_cast<float>(cost_factor_));
      ++rebalances_;
    }
    if (!alone) {
      migrate(state);
    }
    remake_ghost_lists(state);
    refresh_ghosts(state, /*every_field=*/true);
    if (rebalance) {
      imbalance_after_cut_ = measure_work(state);
      cost_.restart(work_);
      cost_factor_ = 1.0;
    }
    return true;
  }

  // A snapshot restored (collective): either the whole state on every process (a snapshot
  // file's) or pieces captured by this run's processes in any decomposition
  // (StateSnapshot::pieces). Each process then keeps its region's particles, with fresh ghosts.
  // Throws std::invalid_argument for a snapshot whose sets' sizes are not this state's.
  void restore(State& state, const StateSnapshot& snapshot) {
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k++];
      std::size_t rows = pieces.total;
      if (!snapshot.pieces.empty()) {
        const SetRows* given = snapshot.rows_of(pieces.name);
        if (given == nullptr || given->total != pieces.total) {
          throw std::invalid_argument("the snapshot's pieces do not hold particle set " +
                                      pieces.name + " of this state");
        }
        pieces.global = given->indices;
        rows = given->indices.size();
      }
      resize_set(set, rows);
    });
    revsph::restore_state(state, snapshot);
    if (snapshot.pieces.empty()) {
      keep_own_particles(state);
    } else {
      migrate(state);
    }
    remake_ghost_lists(state);
    refresh_ghosts(state, /*every_field=*/true);
  }

  // This process's rows of every set, for the whole state's hash and snapshots.
  std::vector<SetRows> own_rows() const {
    std::vector<SetRows> rows;
    for (const Pieces& pieces : pieces_) {
      rows.push_back({pieces.name, pieces.global, pieces.total});
    }
    return rows;
  }
  double reach() const { return reach_; }

  // This process's share of the run (summary.json's "distribution").
  DistributionCounts counts() const {
    DistributionCounts counts{.ghost_lists_made = ghost_lists_made_,
                              .rebalances = rebalances_,
                              .rebalances_by_measured_time = time_rebalances_,
                              .work = work_};
    for (const Pieces& pieces : pieces_) {
      counts.own_particles += pieces.global.size();
      if (pieces.plan) {
        counts.ghosts += pieces.plan->ghost_count();
        counts.copies_sent += pieces.plan->sent_count();
      }
    }
    return counts;
  }

  // The own row of a set's particle given by its global index, if this process holds it.
  std::optional<std::size_t> local_index(const std::string& set, std::uint64_t global) const {
    for (const Pieces& pieces : pieces_) {
      if (pieces.name == set) {
        const auto found = std::lower_bound(pieces.global.begin(), pieces.global.end(), global);
        if (found != pieces.global.end() && *found == global) {
          return static_cast<std::size_t>(found - pieces.global.begin());
        }
      }
    }
    return std::nullopt;
  }

  // A particle's global index from its index on this process (i >= the own count: ghost
  // i - count, as StateField::at numbers them), for fault reports; `local` itself for a set this
  // class does not know.
  std::uint64_t global_index(const std::string& set, std::uint64_t local) const {
    for (const Pieces& pieces : pieces_) {
      if (pieces.name != set) {
        continue;
      }
      if (local < pieces.global.size()) {
        return pieces.global[local];
      }
      const std::uint64_t ghost = local - pieces.global.size();
      return ghost < pieces.ghost_global.size() ? pieces.ghost_global[ghost] : local;
    }
    return local;
  }

private:
  struct Pieces {
    std::string name;
    bool has_position = false;
    std::uint64_t total = 0;
    std::vector<std::uint64_t> global;             // own particles' global indices, ascending
    std::vector<std::uint64_t> ghost_global;       // the ghosts' (for fault reports)
    std::vector<double> points_at_lists;           // own positions when the ghost lists were made
    std::unique_ptr<GhostPlan> plan;               // null for a set without positions
    std::vector<std::vector<std::byte>> last_sent; // each field's rows at its last exchange
  };

  // Every positioned particle this process holds, own ones first, then the ghosts; whether its
  // set moves, and its index in the run (the sets' indices one after the other).
  struct HeldPoints {
    std::vector<double> points;
    std::vector<unsigned char> moving;
    std::vector<std::uint64_t> ids; // own particles only
  };
  HeldPoints held_points(State& state, bool with_ghosts) {
    HeldPoints held;
    std::vector<double> ghost_points;
    std::vector<unsigned char> ghost_moving;
    std::uint64_t offset = 0;
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      const Pieces& pieces = pieces_[k++];
      const auto* position = detail::position_field(set);
      const bool moves = std::remove_cvref_t<decltype(set)>::set.motion == Motion::moving;
      if (position != nullptr) {
        const std::vector<double> own = detail::points_of(*position);
        held.points.insert(held.points.end(), own.begin(), own.end());
        held.moving.insert(held.moving.end(), position->count(), moves ? 1 : 0);
        for (std::size_t i = 0; i < position->count(); ++i) {
          held.ids.push_back(offset + (pieces.global.empty() ? i : pieces.global[i]));
        }
        const std::size_t ghosts = with_ghosts && pieces.plan ? pieces.plan->ghost_count() : 0;
        for (std::size_t g = 0; g < ghosts; ++g) {
          for (int a = 0; a < dimension_; ++a) {
            ghost_points.push_back(
                detail::real_value(position->at(a, position->count() + g), position->info().scale));
          }
        }
        ghost_moving.insert(ghost_moving.end(), ghosts, moves ? 1 : 0);
      }
      offset += pieces.total;
    });
    held.points.insert(held.points.end(), ghost_points.begin(), ghost_points.end());
    held.moving.insert(held.moving.end(), ghost_moving.begin(), ghost_moving.end());
    return held;
  }

  // Zoltan's regions, each with about the same estimated work (collective). At setup every
  // process holds the whole state and passes a slice of it, so that the work is spread; at a
  // rebalance each passes its own particles, with its ghosts as their neighbours.
  void cut_regions(State& state, bool whole_state_held, float cost_factor = 1.0F) {
    const HeldPoints held = held_points(state, !whole_state_held);
    std::vector<float> work =
        estimated_work(held.points, held.moving, held.ids.size(), dimension_, reach_);
    for (float& w : work) {
      w *= cost_factor;
    }
    const auto d = static_cast<std::size_t>(dimension_);
    // The own particles only (the ghosts were their neighbours in the estimate).
    std::span<const double> points =
        std::span<const double>(held.points).first(held.ids.size() * d);
    std::span<const std::uint64_t> ids(held.ids);
    std::span<const float> weights(work);
    if (whole_state_held) {
      const auto rank = static_cast<std::uint64_t>(process_rank());
      const auto count = static_cast<std::uint64_t>(process_count());
      const std::uint64_t n = held.ids.size();
      const std::uint64_t first = n * rank / count;
      const std::uint64_t end = n * (rank + 1) / count;
      points = points.subspan(first * d, (end - first) * d);
      ids = ids.subspan(first, end - first);
      weights = weights.subspan(first, end - first);
    }
    partition_.balance(points, ids, weights);
  }

  // This process's estimated work (with its ghosts as neighbours), kept for the summary; returns
  // the largest process's over the mean (collective).
  double measure_work(State& state) {
    const HeldPoints held = held_points(state, /*with_ghosts=*/true);
    double mine = 0.0;
    for (const float w :
         estimated_work(held.points, held.moving, held.ids.size(), dimension_, reach_)) {
      mine += w;
    }
    work_ = mine;
    const double largest = max_over_processes(mine);
    // The mean from an exact integer total (work rounded to whole pairs).
    const double mean =
        static_cast<double>(sum_over_processes(static_cast<std::int64_t>(std::llround(mine)))) /
        process_count();
    return mean > 0.0 ? largest / mean : 1.0;
  }

  // Whether the largest process's estimated work now exceeds the mean by the factor given, and
  // by more than right after the last cut (which RCB may not have evened further). Collective.
  bool work_drifted_apart(State& state) {
    const double imbalance = measure_work(state);
    if (rebalance_above_ <= 1.0) {
      return true; // at every migration (tests)
    }
    return imbalance > std::max(rebalance_above_, imbalance_after_cut_ + 0.03);
  }

  // Every `refreshes_between_readings` refreshes (the same ones on every process), the
  // processes' computing times since the last cut (collective): whether they are uneven enough
  // to cut the regions again. Keeps this process's cost factor for the weights of the next cut.
  bool measured_times_uneven() {
    constexpr std::uint64_t refreshes_between_readings = 64;
    if (time_balance_ == TimeBalance::off || process_count() == 1 ||
        ++refreshes_since_reading_ < refreshes_between_readings) {
      return false;
    }
    refreshes_since_reading_ = 0;
    const CostReading reading = cost_.read();
    if (!reading.long_enough) {
      return false;
    }
    cost_factor_ = reading.factor;
    if (imbalance_at_time_cut_ > 0.0) {
      cost_.judge_last_cut(imbalance_at_time_cut_, reading.imbalance);
      imbalance_at_time_cut_ = 0.0;
    }
    // Measured times are noisier than the estimate: uneven by 5 % more than it before acting.
    if (time_balance_ != TimeBalance::every_reading &&
        reading.imbalance <= rebalance_above_ + 0.05) {
      return false;
    }
    imbalance_at_time_cut_ = reading.imbalance;
    ++time_rebalances_;
    return true;
  }

  // One image per axis at most (image_shifts): a period longer than twice the ghosts' reach.
  void require_room_for_images(const PeriodicBox& period) const {
    revsph::require_room_for_images(period, dimension_, reach_ + skin_,
                                    "the interaction reach with its skin (1.25 times the largest "
                                    "interaction radius)");
  }

  void keep_own_particles(State& state) {
    const int me = process_rank();
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k++];
      std::vector<std::uint32_t> kept;
      if (const auto* position = detail::position_field(set)) {
        const std::vector<double> points = detail::points_of(*position);
        const auto d = static_cast<std::size_t>(dimension_);
        for (std::size_t i = 0; i < position->count(); ++i) {
          if (partition_.owner_of(std::span<const double>(points).subspan(i * d, d)) == me) {
            kept.push_back(static_cast<std::uint32_t>(i));
          }
        }
      } else if (me == 0) {
        for (std::size_t i = 0; i < set_size(set); ++i) {
          kept.push_back(static_cast<std::uint32_t>(i));
        }
      }
      pieces.global.assign(kept.begin(), kept.end());
      for_each_field_of(set, [&](auto& field) {
        const auto width = static_cast<std::size_t>(field.components());
        const auto all = detail::rows_of(field);
        std::remove_cvref_t<decltype(all)> own(kept.size() * width);
        for (std::size_t n = 0; n < kept.size(); ++n) {
          std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(kept[n] * width), width,
                      own.begin() + static_cast<std::ptrdiff_t>(n * width));
        }
        detail::replace_own_rows(field, own);
      });
    });
  }

  // Whether any particle has gone more than half the skin since the lists were made.
  bool moved_beyond_skin(State& state) {
    double largest = 0.0;
    std::size_t k = 0;
    const auto d = static_cast<std::size_t>(dimension_);
    for_each_set(state, [&](auto& set) {
      const Pieces& pieces = pieces_[k++];
      const auto* position = detail::position_field(set);
      if (position == nullptr) {
        return;
      }
      // Read in place: this runs after every sub-step. A particle that crossed a periodic face
      // (its wrap moved it by a period) needs its images on the other side now: the lists are
      // remade (a shear flow remakes them often: docs/periodic.md, "Cost").
      for (std::size_t i = 0; i < position->count(); ++i) {
        double squared = 0.0;
        for (std::size_t a = 0; a < d; ++a) {
          const double now =
              detail::real_value(position->at(static_cast<int>(a), i), position->info().scale);
          const double step = now - pieces.points_at_lists[i * d + a];
          squared += step * step;
        }
        largest = std::max(largest, squared);
      }
    });
    return max_over_processes(std::sqrt(largest)) > 0.5 * skin_;
  }

  // Particles to the owners of their positions (collective; every process ends in
  // global-index order).
  void migrate(State& state) {
    std::size_t k = 0;
    const auto d = static_cast<std::size_t>(dimension_);
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k++];
      if (!pieces.has_position) {
        return;
      }
      const std::vector<double> points = detail::points_of(*detail::position_field(set));
      std::vector<int> owners(pieces.global.size());
      for (std::size_t i = 0; i < owners.size(); ++i) {
        owners[i] = partition_.owner_of(std::span<const double>(points).subspan(i * d, d));
      }
      const Migration migration(owners, pieces.global);
      for_each_field_of(set, [&](auto& field) {
        const auto rows = detail::rows_of(field);
        detail::replace_own_rows(
            field, migration.move(std::span(rows), static_cast<std::size_t>(field.components())));
      });
      pieces.global = migration.global_indices_after();
    });
  }

  // Which own particles each other process needs within the reach and the skin (collective).
  void remake_ghost_lists(State& state) {
    ++ghost_lists_made_;
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k++];
      if (!pieces.has_position) {
        return;
      }
      pieces.points_at_lists = detail::points_of(*detail::position_field(set));
      pieces.plan = std::make_unique<GhostPlan>(partition_, pieces.points_at_lists, reach_ + skin_,
                                                detail::position_field(set)->info().period);
      pieces.ghost_global = pieces.plan->template exchange_from<std::uint64_t>(
          1, [&pieces](std::size_t i, std::uint64_t* row) { row[0] = pieces.global[i]; });
      pieces.plan->set_global_indices(pieces.global, pieces.ghost_global);
    });
  }

  // Every field's ghosts from their owners' rows (collective). After the ghost lists were made
  // every field goes; otherwise only the fields whose rows to send changed, on some process,
  // since they were last sent (a kick changes the velocities, a drift the positions, a fixed
  // set nothing), all of a set's in one exchange.
  void refresh_ghosts(State& state, bool every_field) {
    // Each field's rows to send, as bytes in the plan's order, and a bit for each that changed
    // (fields beyond the 64th always go).
    std::vector<std::vector<std::vector<std::byte>>> rows(pieces_.size());
    std::vector<std::vector<std::size_t>> row_bytes(pieces_.size());
    std::uint64_t changed = 0;
    unsigned bit = 0;
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k];
      auto& set_rows = rows[k];
      auto& set_row_bytes = row_bytes[k++];
      if (!pieces.plan) {
        return;
      }
      const std::span<const std::uint32_t> sent = pieces.plan->sent_particles();
      std::size_t f = 0;
      for_each_field_of(set, [&](auto& field) {
        using Raw = typename std::remove_cvref_t<decltype(field)>::value_type;
        const auto width = static_cast<std::size_t>(field.components());
        std::vector<Raw> values(sent.size() * width);
        for (std::size_t n = 0; n < sent.size(); ++n) {
          for (std::size_t c = 0; c < width; ++c) {
            values[n * width + c] = field.at(static_cast<int>(c), sent[n]);
          }
        }
        // Images across a periodic face go with their positions shifted by the period.
        const std::span<const ImageShift> shifts = pieces.plan->sent_shifts();
        if (!shifts.empty() && field.info().name == "position") {
          const RawPeriod<Raw> period = raw_period<Raw>(field.info());
          for (std::size_t n = 0; n < sent.size(); ++n) {
            for (std::size_t c = 0; c < width; ++c) {
              values[n * width + c] =
                  shifted(values[n * width + c], period, shifts[n], static_cast<int>(c));
            }
          }
        }
        std::vector<std::byte> bytes(values.size() * sizeof(Raw));
        std::memcpy(bytes.data(), values.data(), bytes.size());
        if (pieces.last_sent.size() <= f || pieces.last_sent[f] != bytes) {
          changed |= bit < 64 ? std::uint64_t{1} << bit : 0;
        }
        set_rows.push_back(std::move(bytes));
        set_row_bytes.push_back(width * sizeof(Raw));
        ++f;
        ++bit;
      });
      pieces.last_sent.resize(f);
    });
    if (!every_field) {
      changed = or_over_processes(changed);
    }
    bit = 0;
    k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k];
      auto& set_rows = rows[k];
      const auto& set_row_bytes = row_bytes[k++];
      if (!pieces.plan) {
        return;
      }
      // The chosen fields side by side in each particle's row.
      std::vector<std::size_t> offsets;
      std::size_t row = 0;
      for (const std::size_t bytes : set_row_bytes) {
        const bool goes = every_field || bit >= 64 || ((changed >> bit) & 1U) != 0;
        offsets.push_back(goes ? row : SIZE_MAX);
        row += goes ? bytes : 0;
        ++bit;
      }
      if (row == 0) {
        return;
      }
      const std::size_t sent = pieces.plan->sent_count();
      std::vector<std::byte> packed(sent * row);
      for (std::size_t f = 0; f < offsets.size(); ++f) {
        if (offsets[f] != SIZE_MAX) {
          for (std::size_t n = 0; n < sent; ++n) {
            std::memcpy(packed.data() + n * row + offsets[f],
                        set_rows[f].data() + n * set_row_bytes[f], set_row_bytes[f]);
          }
        }
      }
      const std::vector<std::byte> received =
          pieces.plan->exchange_packed(std::span<const std::byte>(packed), row);
      const std::size_t ghosts = pieces.plan->ghost_count();
      std::size_t f = 0;
      for_each_field_of(set, [&](auto& field) {
        using Raw = typename std::remove_cvref_t<decltype(field)>::value_type;
        const std::size_t offset = offsets[f];
        if (offset != SIZE_MAX) {
          const auto width = static_cast<std::size_t>(field.components());
          std::vector<Raw> values(ghosts * width);
          for (std::size_t g = 0; g < ghosts; ++g) {
            for (std::size_t c = 0; c < width; ++c) {
              std::memcpy(&values[c * ghosts + g],
                          received.data() + g * row + offset + c * sizeof(Raw), sizeof(Raw));
            }
          }
          field.set_ghosts(ghosts, std::move(values), pieces.plan.get());
          pieces.last_sent[f] = std::move(set_rows[f]);
        }
        ++f;
      });
    });
  }

  SpatialPartition partition_;
  int dimension_;
  double reach_;
  double skin_;
  double rebalance_above_;
  TimeBalance time_balance_;
  MeasuredCost cost_;
  double imbalance_at_time_cut_ = 0.0; // the reading that decided the last cut on time, if any
  double cost_factor_ = 1.0;           // this process's, from the last reading since the cut
  std::uint64_t refreshes_since_reading_ = 0;
  std::uint64_t time_rebalances_ = 0;
  double imbalance_after_cut_ = 1.0; // largest / mean estimated work after the last cut
  double work_ = 0.0;                // this process's estimated work at the last migration
  std::uint64_t ghost_lists_made_ = 0;
  std::uint64_t rebalances_ = 0;
  std::vector<Pieces> pieces_; // one per set, in the state's order
};

} // namespace revsph::distributed
