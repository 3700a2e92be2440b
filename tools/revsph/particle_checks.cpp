#include "tools/revsph/particle_checks.hpp"

#include "core/distributed/processes.hpp"
#include "core/finite_positions.hpp"
#include "core/smallest_distance.hpp"
#include "core/wall_penetration.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace revsph::cli {

namespace {

template <int D>
Vec<D> position_of(const FieldSnapshot& position, std::size_t particle) {
  Vec<D> p{};
  for (int k = 0; k < D; ++k) {
    p[k] = position.real(k, particle);
  }
  return p;
}

template <int D>
void count_own(const std::vector<WallRegion<D>>& regions, const StateSnapshot& state,
               const std::vector<std::string>& moving_sets, std::vector<std::uint64_t>& counts) {
  const WallPenetration<D> walls(regions, state);
  for (const std::string& set : moving_sets) {
    const FieldSnapshot* position = state.find(set, "position");
    if (position == nullptr) {
      continue;
    }
    for (std::size_t i = 0; i < position->count; ++i) {
      const std::size_t r = walls.region_holding(position_of<D>(*position, i));
      if (r < regions.size()) {
        ++counts[r];
      }
    }
  }
}

// Over this process's particles, those of the moving sets first.
template <int D>
double own_smallest_distance(const StateSnapshot& state, const std::vector<std::string>& moving,
                             const std::vector<std::string>& fixed, double cell_size) {
  CoordinateArrays<D> points;
  append_finite_positions<D>(state, moving, points);
  const std::size_t moving_count = points[0].size();
  append_finite_positions<D>(state, fixed, points);
  return smallest_distance<D>(view_of<D>(points), moving_count, cell_size);
}

} // namespace

ParticleChecks::ParticleChecks(const CaseFile& case_file, const SimulationInfo& info)
    : dimension_(info.dimension) {
  // Every model's spacing key; a model without one has neither check.
  if (!case_file.has("discretisation.dr")) {
    return;
  }
  dr_ = case_file.positive_number("discretisation.dr");
  for (const ParticleCount& set : info.particles) {
    (set.moving ? moving_sets_ : fixed_sets_).push_back(set.particle_set);
  }
  auto read = [&]<int D>() {
    std::vector<WallRegion<D>> regions = read_wall_regions<D>(case_file, dr_, fixed_sets_);
    for (const WallRegion<D>& region : regions) {
      keys_.push_back(region.key());
      kinds_.push_back(region.kind());
    }
    regions_ = std::move(regions);
  };
  switch (dimension_) {
  case 1:
    read.template operator()<1>();
    break;
  case 2:
    read.template operator()<2>();
    break;
  case 3:
    read.template operator()<3>();
    break;
  default:
    throw std::invalid_argument("particle checks: dimension " + std::to_string(dimension_));
  }
}

WallCount ParticleChecks::count_in_walls(const StateSnapshot& state) const {
  WallCount count;
  count.per_region.assign(keys_.size(), 0);
  std::visit(
      [&](const auto& regions) { count_own(regions, state, moving_sets_, count.per_region); },
      regions_);
  for (std::uint64_t& n : count.per_region) {
    // Integers: the same sum in any order, on any number of processes.
    n = static_cast<std::uint64_t>(distributed::sum_over_processes(static_cast<std::int64_t>(n)));
    count.total += n;
  }
  return count;
}

double ParticleChecks::smallest_distance_over_dr(const StateSnapshot& state) const {
  if (dr_ <= 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  const double own = std::visit(
      [&]<int D>(const std::vector<WallRegion<D>>&) {
        return own_smallest_distance<D>(state, moving_sets_, fixed_sets_, dr_);
      },
      regions_);
  return distributed::min_over_processes(own) / dr_;
}

std::string ParticleChecks::wall_warning(std::int64_t step, double time,
                                         const WallCount& count) const {
  char head[96];
  std::snprintf(head, sizeof head, "warning: step %lld, t = %.6g s: %llu ",
                static_cast<long long>(step), time, static_cast<unsigned long long>(count.total));
  std::string line = head;
  line += (moving_sets_.size() == 1 ? moving_sets_.front() : std::string("moving")) +
          (count.total == 1 ? " particle" : " particles") + " inside walls (";
  bool first = true;
  for (std::size_t r = 0; r < keys_.size(); ++r) {
    if (count.per_region[r] == 0) {
      continue;
    }
    line += (first ? "" : ", ") + keys_[r] + " \"" + kinds_[r] + "\" " + (first ? "holds " : "") +
            std::to_string(count.per_region[r]);
    first = false;
  }
  return line + "); check the wall's energy per mass, the sound speed and dt";
}

} // namespace revsph::cli
