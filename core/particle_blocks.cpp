#include "core/particle_blocks.hpp"
#include "fixedpoint/deterministic_math.hpp"

#include "core/block_spec.hpp"
#include "core/coincident_particles.hpp"
#include "core/outline.hpp"
#include "core/point_file.hpp"
#include "core/stl_region.hpp"

#include "core/memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <sstream>

namespace revsph {

template <int D>
Vec<D> lattice_periods(Lattice lattice, double spacing) {
  Vec<D> period{};
  period.fill(spacing);
  if constexpr (D >= 2) {
    if (lattice == Lattice::hexagonal) {
      period[1] = spacing * std::sqrt(3.0) / 2.0;
      if constexpr (D == 3) {
        period[2] = spacing * std::sqrt(2.0 / 3.0);
      }
    }
  }
  if (lattice == Lattice::body_centred_cubic) {
    period[D - 1] = 0.5 * spacing; // corner layers and centre layers alternate
  }
  return period;
}

namespace {

constexpr double relative_tolerance = 1e-9;

template <int D>
std::string format_point(const Vec<D>& p) {
  std::ostringstream out;
  out << "(";
  for (int k = 0; k < D; ++k) {
    out << (k ? ", " : "") << p[k];
  }
  out << ")";
  return out.str();
}

} // namespace

template <int D>
double lattice_cell_volume(Lattice lattice, double spacing) {
  const Vec<D> period = lattice_periods<D>(lattice, spacing);
  double volume = 1.0;
  for (int k = 0; k < D; ++k) {
    volume *= period[k];
  }
  return volume;
}

namespace {

// lattice_points, leaving out the points strictly inside `hollow` (if not null). A container's
// hollow is skipped a run at a time rather than point by point, so that generating a container
// costs its walls, not its whole box (which, for a large empty container, would not fit in
// memory or time).
template <int D>
std::vector<Vec<D>> lattice_points_outside(Lattice lattice, const Box<D>& region, double spacing,
                                           const Box<D>* hollow) {
  const Vec<D> period = lattice_periods<D>(lattice, spacing);
  std::array<long, D> counts{};
  for (int k = 0; k < D; ++k) {
    counts[k] = static_cast<long>(std::floor((region.max[k] - region.min[k]) / period[k])) + 2;
  }
  // Keep points at least half a period inside the region (with a tolerance for round-off).
  Vec<D> lo{};
  Vec<D> hi{};
  for (int k = 0; k < D; ++k) {
    lo[k] = region.min[k] + 0.5 * period[k] - relative_tolerance * spacing;
    hi[k] = region.max[k] - 0.5 * period[k] + relative_tolerance * spacing;
  }
  auto point = [&](long column, long row, long layer) {
    Vec<D> p{};
    p[0] = region.min[0] + (0.5 + static_cast<double>(column)) * period[0];
    if constexpr (D == 1) {
      return p; // a 1D lattice is a row of equally spaced points
    } else {
      p[1] = region.min[1] + (0.5 + static_cast<double>(row)) * period[1];
    }
    if constexpr (D == 3) {
      p[2] = region.min[2] + (0.5 + static_cast<double>(layer)) * period[2];
    }
    if constexpr (D >= 2) {
      if (lattice == Lattice::hexagonal) {
        // Odd rows shift by half a spacing; in 3D odd layers (B of ABAB stacking) shift by
        // (spacing / 2, row period / 3).
        p[0] += (row % 2 == 1 ? 0.5 * spacing : 0.0);
        if (D == 3 && layer % 2 == 1) {
          p[0] += 0.5 * spacing;
          p[1] += period[1] / 3.0;
        }
      }
      if (lattice == Lattice::body_centred_cubic && layer % 2 == 1) {
        // Cube centres: half a spacing along x and y from the corner layers.
        p[0] += 0.5 * spacing;
        p[1] += 0.5 * spacing;
      }
    }
    return p;
  };
  std::vector<Vec<D>> points;
  const long layers = D == 3 ? counts[D - 1] : 1;
  const long rows = D >= 2 ? counts[D >= 2 ? 1 : 0] : 1;
  for (long layer = 0; layer < layers; ++layer) {
    for (long row = 0; row < rows; ++row) {
      for (long column = 0; column < counts[0]; ++column) {
        const Vec<D> p = point(column, row, layer);
        if (hollow != nullptr && strictly_inside<D>(*hollow, p)) {
          // Along a row only p[0] changes, never decreasing with `column` (each rounding is
          // monotonic), and the hollow is an interval of it: if the point at `last` is in the
          // hollow too, so is every point in between. Jump to it.
          const double last = std::floor((hollow->max[0] - region.min[0]) / period[0]) - 2.0;
          if (last > static_cast<double>(column) && last < static_cast<double>(counts[0]) &&
              strictly_inside<D>(*hollow, point(static_cast<long>(last), row, layer))) {
            column = static_cast<long>(last);
          }
          continue;
        }
        bool inside = true;
        for (int k = 0; k < D; ++k) {
          inside = inside && p[k] >= lo[k] && p[k] <= hi[k];
        }
        if (inside) {
          points.push_back(p);
        }
      }
    }
  }
  return points;
}

} // namespace

// A Vogel (sunflower) spiral about the region's centre: point k at radius spacing sqrt((k + 1/2)
// / pi) and angle k times the golden angle, so that every point stands for an area spacing^2
// and the arrangement has no lattice directions. Points at least a quarter spacing inside the
// region are kept: unlike a lattice row, the spiral's points are spread evenly up to the cut, so
// a half-spacing margin (the lattice's) would leave a strip of half a spacing without particles
// along the edge, i.e. about 7% too little kernel density there next to walls (measured on the
// Gresho case); a quarter halves the strip and keeps every point 0.75 spacing from a wall
// particle half a spacing outside.
std::vector<Vec<2>> vogel_points(const Box<2>& region, double spacing) {
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const Vec<2> centre{0.5 * (region.min[0] + region.max[0]), 0.5 * (region.min[1] + region.max[1])};
  const double reach = dmath::hypot(region.max[0] - centre[0], region.max[1] - centre[1]);
  const double margin = 0.25 * spacing * (1.0 - relative_tolerance);
  std::vector<Vec<2>> points;
  for (long k = 0;; ++k) {
    const double radius = spacing * std::sqrt((static_cast<double>(k) + 0.5) / std::numbers::pi);
    if (radius > reach) {
      break;
    }
    const double angle = static_cast<double>(k) * golden_angle;
    const Vec<2> p{centre[0] + radius * dmath::cos(angle), centre[1] + radius * dmath::sin(angle)};
    if (p[0] >= region.min[0] + margin && p[0] <= region.max[0] - margin &&
        p[1] >= region.min[1] + margin && p[1] <= region.max[1] - margin) {
      points.push_back(p);
    }
  }
  return points;
}

template <int D>
std::vector<Vec<D>> lattice_points(Lattice lattice, const Box<D>& region, double spacing) {
  if (lattice == Lattice::vogel) {
    if constexpr (D == 2) {
      return vogel_points(region, spacing);
    } else {
      throw std::invalid_argument("the Vogel spiral lattice is two-dimensional");
    }
  }
  return lattice_points_outside<D>(lattice, region, spacing, nullptr);
}

template <int D>
Box<D> read_domain(const CaseFile& case_file) {
  Box<D> domain{vec_of<D>(case_file.numbers("domain.min", D)),
                vec_of<D>(case_file.numbers("domain.max", D))};
  for (int k = 0; k < D; ++k) {
    if (!(domain.min[k] < domain.max[k])) {
      case_file.fail("domain.max", "must be greater than domain.min on every axis");
    }
    if (!std::isfinite(domain.max[k] - domain.min[k])) {
      case_file.fail("domain.max", "domain.max - domain.min overflows on an axis: the domain "
                                   "must have a finite size");
    }
  }
  // Along a periodic axis the pair passes also hold images of the particles near the faces, up
  // to half a period beyond them (the distribution requires the reach below half a period).
  const PeriodicBox period = read_periodic_box<D>(case_file);
  for (int k = 0; k < D; ++k) {
    if (period.periodic[k]) {
      const double half = 0.5 * (domain.max[k] - domain.min[k]);
      domain.min[k] -= half;
      domain.max[k] += half;
    }
  }
  return domain;
}

template <int D>
PeriodicBox read_periodic_box(const CaseFile& case_file) {
  PeriodicBox period;
  const std::string axes = case_file.string_or("domain.periodic", "");
  if (axes.empty()) {
    return period;
  }
  for (const char axis : axes) {
    const int k = axis - 'x';
    if (k < 0 || k >= D) {
      case_file.fail("domain.periodic", "names the axes that are periodic, from \"" +
                                            std::string("xyz").substr(0, D) + "\" (got '" +
                                            std::string(1, axis) + "')");
    }
    if (period.periodic[k]) {
      case_file.fail("domain.periodic", "names axis " + axis_name(k) + " twice");
    }
    period.periodic[k] = true;
  }
  const std::vector<double> min = case_file.numbers("domain.min", D);
  const std::vector<double> max = case_file.numbers("domain.max", D);
  for (int k = 0; k < D; ++k) {
    period.min[k] = min[k];
    period.max[k] = max[k];
  }
  return period;
}

namespace {

// Concentric rings filling the annulus inner_radius < |x - centre| < outer_radius (2D): as many
// rings as spacings fit across it, each at the middle of its band, with round(2 pi r / spacing)
// equally spaced points, odd rings turned by half a step. Every point then stands for about
// spacing^2, and the walls of a circular domain are smooth circles (a lattice cut by a circle
// leaves steps a fluid would feel as roughness).
std::vector<Vec<2>> ring_points(const AnnulusSpec& annulus, double spacing) {
  const double width = annulus.outer_radius - annulus.inner_radius;
  const long rings = std::max(1L, std::lround(width / spacing));
  std::vector<Vec<2>> points;
  for (long ring = 0; ring < rings; ++ring) {
    const double radius = annulus.inner_radius +
                          (static_cast<double>(ring) + 0.5) * width / static_cast<double>(rings);
    const long count = std::max(1L, std::lround(2.0 * std::numbers::pi * radius / spacing));
    const double step = 2.0 * std::numbers::pi / static_cast<double>(count);
    const double offset = ring % 2 == 1 ? 0.5 * step : 0.0;
    for (long k = 0; k < count; ++k) {
      const double angle = offset + static_cast<double>(k) * step;
      points.push_back(Vec<2>{annulus.centre[0] + radius * dmath::cos(angle),
                              annulus.centre[1] + radius * dmath::sin(angle)});
    }
  }
  return points;
}

template <int D>
double volume_of(const Box<D>& box) {
  double volume = 1.0;
  for (int k = 0; k < D; ++k) {
    volume *= box.max[k] - box.min[k];
  }
  return volume;
}

// A block's spec, its kind first checked against the model's.
template <int D>
BlockSpec<D> read_block(const CaseFile& case_file, std::size_t index, double default_spacing,
                        std::span<const std::string_view> kinds) {
  const std::string key = "particles[" + std::to_string(index) + "].kind";
  const std::string kind = case_file.string(key);
  bool known_kind = false;
  std::string allowed;
  for (std::string_view k : kinds) {
    known_kind = known_kind || k == kind;
    allowed += (allowed.empty() ? "\"" : ", \"") + std::string(k) + "\"";
  }
  if (!known_kind) {
    case_file.fail(key, "unknown particle kind \"" + kind + "\" (this model has " + allowed + ")");
  }
  return read_block_spec<D>(case_file, index, default_spacing);
}

// An upper estimate of a block's particles from volumes, without generating any: the lattice
// cells of its outer box padded by one period (partial rows, half-period offsets), minus the
// hollow of a container.
template <int D>
double estimated_particles(const BlockSpec<D>& spec) {
  if (spec.shape == BlockShape::points) {
    return static_cast<double>(spec.points.size());
  }
  Box<D> padded = spec.outer;
  const Vec<D> period = lattice_periods<D>(spec.lattice, spec.spacing);
  for (int k = 0; k < D; ++k) {
    padded.max[k] += period[k];
  }
  if constexpr (D == 2) {
    if (spec.shape == BlockShape::annulus) {
      const AnnulusSpec& a = spec.annulus;
      const double width = a.outer_radius - a.inner_radius;
      return std::numbers::pi * (a.outer_radius + a.inner_radius + 2.0 * spec.spacing) *
                 (width + spec.spacing) / (spec.spacing * spec.spacing) +
             1.0;
    }
  }
  const double hollow = spec.shape == BlockShape::container ? volume_of<D>(spec.region) : 0.0;
  return (volume_of<D>(padded) - hollow) / lattice_cell_volume<D>(spec.lattice, spec.spacing);
}

} // namespace

double neighbours_within(int dimension, double radius_over_spacing) {
  const double r = radius_over_spacing;
  return dimension == 1   ? 2.0 * r
         : dimension == 2 ? std::numbers::pi * r * r
                          : 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

namespace {

void require_memory(const CaseFile& case_file, double particles, double needed,
                    const ParticleBudget& budget) {
  constexpr double index_limit = 4294967295.0; // particle indices are 32-bit
  const std::size_t available =
      budget.memory_bytes > 0 ? budget.memory_bytes : available_memory_bytes();
  char estimate[64];
  std::snprintf(estimate, sizeof estimate, "%.3g", particles);
  if (!(particles <= index_limit)) {
    case_file.fail("particles", std::string("about ") + estimate +
                                    " particles: more than the 2^32 - 1 one run can index");
  }
  if (needed > static_cast<double>(available)) {
    case_file.fail("particles", std::string("about ") + estimate + " particles would need about " +
                                    format_bytes(needed) + " of memory; " +
                                    format_bytes(static_cast<double>(available)) +
                                    " is available (refused before allocating)");
  }
}

template <int D>
ParticleBlock<D> generate_block(const CaseFile& case_file, const BlockSpec<D>& spec,
                                const Box<D>& domain) {
  ParticleBlock<D> block;
  block.key = spec.key;
  block.kind = spec.kind;
  block.spacing = spec.spacing;
  block.volume_per_particle = lattice_cell_volume<D>(spec.lattice, spec.spacing);
  if (spec.shape == BlockShape::box) {
    // A box reaching more than half a spacing past the domain has particles outside it (or
    // none); refused before generating, since a Vogel spiral's work grows with the box's
    // diagonal squared, not its area (a fuzzed box 100 m by 4e-12 m took minutes).
    for (int k = 0; k < D; ++k) {
      const bool below = spec.region.min[k] < domain.min[k] - 0.5 * spec.spacing;
      if (below || spec.region.max[k] > domain.max[k] + 0.5 * spec.spacing) {
        case_file.fail(spec.key, std::string("the block reaches outside the domain: its ") +
                                     (below ? "min" : "max") + " on axis " + std::to_string(k) +
                                     " lies more than half a spacing past [domain]");
      }
    }
    block.positions = lattice_points<D>(spec.lattice, spec.region, spec.spacing);
  } else if (spec.shape == BlockShape::outline) {
    if constexpr (D == 2) {
      block.positions =
          square_lattice_points(*spec.outline, spec.lattice_origin, spec.spacing, spec.shell);
    }
  } else if (spec.shape == BlockShape::points) {
    block.positions = spec.points;
    block.volume_per_particle = spec.particle_volume;
  } else if (spec.shape == BlockShape::stl) {
    block.positions = lattice_points<D>(spec.lattice, spec.region, spec.spacing);
    std::erase_if(block.positions, [&](const Vec<D>& p) { return !inside_stl<D>(spec, p); });
  } else if (spec.shape == BlockShape::annulus) {
    if constexpr (D == 2) {
      block.positions = ring_points(spec.annulus, spec.spacing);
      block.volume_per_particle = std::numbers::pi *
                                  (spec.annulus.outer_radius * spec.annulus.outer_radius -
                                   spec.annulus.inner_radius * spec.annulus.inner_radius) /
                                  static_cast<double>(block.positions.size());
    }
  } else {
    block.positions =
        lattice_points_outside<D>(spec.lattice, spec.outer, spec.spacing, &spec.region);
  }
  if (block.positions.empty()) {
    case_file.fail(spec.key, "the block holds no particles (is it thinner than the spacing?)");
  }
  for (const Vec<D>& p : block.positions) {
    if (!domain.contains(p)) {
      case_file.fail(spec.key, "the block reaches outside the domain: a particle at " +
                                   format_point<D>(p) + " is not inside [domain]");
    }
  }
  return block;
}

} // namespace

template <int D>
std::vector<ParticleBlock<D>>
read_particle_blocks(const CaseFile& case_file, double default_spacing, const Box<D>& domain,
                     std::span<const std::string_view> kinds, const ParticleBudget& budget) {
  const std::size_t count = case_file.table_count("particles");
  if (count == 0) {
    case_file.fail("particles", "no [[particles]] blocks: the case has no particles");
  }
  std::vector<BlockSpec<D>> specs;
  double particles = 0.0;
  double needed = 0.0;
  for (std::size_t b = 0; b < count; ++b) {
    specs.push_back(read_block<D>(case_file, b, default_spacing, kinds));
    const double block = estimated_particles<D>(specs.back());
    // A block denser than dr: its particles' neighbour lists grow as (dr / spacing)^D.
    const double denser =
        std::max(1.0, dmath::integer_power(default_spacing / specs.back().spacing, D));
    particles += block;
    needed +=
        block * (budget.bytes_per_particle + budget.neighbour_bytes_per_particle * (denser - 1.0));
  }
  require_memory(case_file, particles, needed, budget);
  std::vector<ParticleBlock<D>> blocks;
  for (const BlockSpec<D>& spec : specs) {
    blocks.push_back(generate_block<D>(case_file, spec, domain));
  }
  // exclude_blocks: leave out the particles inside other blocks' regions (an outline's, or a
  // box's [min, max]).
  for (std::size_t b = 0; b < specs.size(); ++b) {
    for (const std::size_t other : specs[b].exclude) {
      const BlockSpec<D>& region = specs[other];
      if (region.shape != BlockShape::outline && region.shape != BlockShape::box &&
          region.shape != BlockShape::stl) {
        case_file.fail(specs[b].key + ".exclude_blocks",
                       region.key + " is not a box, an outline or an stl block: only their "
                                    "regions exclude");
      }
      std::erase_if(blocks[b].positions,
                    [&](const Vec<D>& p) { return in_excluding_region<D>(region, p); });
    }
    if (blocks[b].positions.empty()) {
      case_file.fail(specs[b].key, "the block holds no particles once exclude_blocks are left out");
    }
  }
  refuse_coincident_particles<D>(case_file, blocks);
  return blocks;
}

const InputFile& block_input_file(const CaseFile& case_file, const std::string& block_key) {
  const std::string name = case_file.string(block_key + ".file");
  if (name.empty()) {
    case_file.fail(block_key + ".file", "an empty path");
  }
  const std::filesystem::path file = name;
  try {
    return case_file.inputs().get(
        name, file.is_absolute()
                  ? file
                  : std::filesystem::path(case_file.source_name()).parent_path() / file);
  } catch (const InputFileError& error) {
    case_file.fail(block_key + ".file", error.what());
  }
}

template <int D>
std::vector<PointBlockValues<D>> point_blocks_with_values(const CaseFile& case_file,
                                                          std::string_view kind) {
  std::vector<PointBlockValues<D>> blocks;
  for (std::size_t b = 0; b < case_file.table_count("particles"); ++b) {
    const std::string key = "particles[" + std::to_string(b) + "]";
    if (case_file.string_or(key + ".shape", "box") != "points" ||
        case_file.string(key + ".kind") != kind) {
      continue;
    }
    try {
      PointFile<D> file = read_point_file<D>(block_input_file(case_file, key));
      if (!file.columns.empty()) {
        blocks.push_back({key, std::move(file)});
      }
    } catch (const PointFileError& error) {
      case_file.fail(key + ".file", error.what());
    }
  }
  return blocks;
}

template std::vector<PointBlockValues<1>> point_blocks_with_values<1>(const CaseFile&,
                                                                      std::string_view);
template std::vector<PointBlockValues<2>> point_blocks_with_values<2>(const CaseFile&,
                                                                      std::string_view);
template std::vector<PointBlockValues<3>> point_blocks_with_values<3>(const CaseFile&,
                                                                      std::string_view);
template std::vector<Vec<1>> lattice_points<1>(Lattice, const Box<1>&, double);
template std::vector<Vec<2>> lattice_points<2>(Lattice, const Box<2>&, double);
template std::vector<Vec<3>> lattice_points<3>(Lattice, const Box<3>&, double);
template Vec<1> lattice_periods<1>(Lattice, double);
template Vec<2> lattice_periods<2>(Lattice, double);
template Vec<3> lattice_periods<3>(Lattice, double);
template double lattice_cell_volume<1>(Lattice, double);
template double lattice_cell_volume<2>(Lattice, double);
template double lattice_cell_volume<3>(Lattice, double);
template PeriodicBox read_periodic_box<1>(const CaseFile&);
template PeriodicBox read_periodic_box<2>(const CaseFile&);
template PeriodicBox read_periodic_box<3>(const CaseFile&);
template Box<1> read_domain<1>(const CaseFile&);
template Box<2> read_domain<2>(const CaseFile&);
template Box<3> read_domain<3>(const CaseFile&);
template std::vector<ParticleBlock<1>> read_particle_blocks<1>(const CaseFile&, double,
                                                               const Box<1>&,
                                                               std::span<const std::string_view>,
                                                               const ParticleBudget&);
template std::vector<ParticleBlock<2>> read_particle_blocks<2>(const CaseFile&, double,
                                                               const Box<2>&,
                                                               std::span<const std::string_view>,
                                                               const ParticleBudget&);
template std::vector<ParticleBlock<3>> read_particle_blocks<3>(const CaseFile&, double,
                                                               const Box<3>&,
                                                               std::span<const std::string_view>,
                                                               const ParticleBudget&);

} // namespace revsph
