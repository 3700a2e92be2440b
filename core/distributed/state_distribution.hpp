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
#include "core/distributed/ghost_plan.hpp"
#include "core/distributed/migration.hpp"
#include "core/distributed/processes.hpp"
#include "core/distributed/set_rows.hpp"
#include "core/distributed/spatial_partition.hpp"
#include "core/particle_sets.hpp"
#include "core/state_snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  StateDistribution(State& state, int dimension, double reach)
      : partition_(dimension, PartitionMethod::coordinate_bisection), dimension_(dimension),
        reach_(reach), skin_(0.25 * reach) {
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_.emplace_back();
      pieces.name = std::string(std::remove_cvref_t<decltype(set)>::set.name);
      pieces.total = set_size(set);
      pieces.has_position = detail::position_field(set) != nullptr;
    });
    cut_regions(state);
    keep_own_particles(state);
    remake_ghost_lists(state);
    refresh_ghosts(state);
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
    if (remade) {
      migrate(state);
      remake_ghost_lists(state);
    }
    refresh_ghosts(state);
    return remade;
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
    refresh_ghosts(state);
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
    std::vector<std::uint64_t> global;       // own particles' global indices, ascending
    std::vector<std::uint64_t> ghost_global; // the ghosts' (for fault reports)
    std::vector<double> points_at_lists;     // own positions when the ghost lists were made
    std::unique_ptr<GhostPlan> plan;         // null for a set without positions
  };

  // Zoltan's regions from a share of every positioned particle (each process passes a slice of
  // the whole state it holds, so that the work is spread).
  void cut_regions(State& state) {
    std::vector<double> points;
    std::vector<std::uint64_t> ids;
    std::uint64_t offset = 0;
    const auto d = static_cast<std::size_t>(dimension_);
    const auto rank = static_cast<std::uint64_t>(process_rank());
    const auto count = static_cast<std::uint64_t>(process_count());
    for_each_set(state, [&](auto& set) {
      const auto* position = detail::position_field(set);
      if (position == nullptr) {
        return;
      }
      const std::vector<double> all = detail::points_of(*position);
      const std::uint64_t n = position->count();
      for (std::uint64_t i = n * rank / count; i < n * (rank + 1) / count; ++i) {
        points.insert(points.end(), all.begin() + static_cast<std::ptrdiff_t>(i * d),
                      all.begin() + static_cast<std::ptrdiff_t>((i + 1) * d));
        ids.push_back(offset + i);
      }
      offset += n;
    });
    partition_.balance(points, ids);
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
      // Read in place: this runs after every sub-step.
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
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      Pieces& pieces = pieces_[k++];
      if (!pieces.has_position) {
        return;
      }
      pieces.points_at_lists = detail::points_of(*detail::position_field(set));
      pieces.plan = std::make_unique<GhostPlan>(partition_, pieces.points_at_lists, reach_ + skin_);
      pieces.ghost_global = pieces.plan->template exchange_from<std::uint64_t>(
          1, [&pieces](std::size_t i, std::uint64_t* row) { row[0] = pieces.global[i]; });
    });
  }

  // Every field's ghosts from their owners' rows (collective).
  void refresh_ghosts(State& state) {
    std::size_t k = 0;
    for_each_set(state, [&](auto& set) {
      const Pieces& pieces = pieces_[k++];
      if (!pieces.plan) {
        return;
      }
      for_each_field_of(set, [&](auto& field) {
        using Raw = typename std::remove_cvref_t<decltype(field)>::value_type;
        const auto width = static_cast<std::size_t>(field.components());
        const std::vector<Raw> rows =
            pieces.plan->template exchange_from<Raw>(width, [&](std::size_t i, Raw* row) {
              for (std::size_t c = 0; c < width; ++c) {
                row[c] = field.at(static_cast<int>(c), i);
              }
            });
        field.set_ghosts(pieces.plan->ghost_count(), detail::components_of_rows(rows, width),
                         pieces.plan.get());
      });
    });
  }

  SpatialPartition partition_;
  int dimension_;
  double reach_;
  double skin_;
  std::vector<Pieces> pieces_; // one per set, in the state's order
};

} // namespace revsph::distributed
