#include "core/particle_blocks.hpp"

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

namespace {

constexpr double relative_tolerance = 1e-9;

// Lattice period along each axis (distance between rows/layers).
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

template <int D>
Vec<D> to_vec(const std::vector<double>& values) {
  Vec<D> v{};
  for (int k = 0; k < D; ++k) {
    v[k] = values[k];
  }
  return v;
}

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

template <int D>
bool strictly_inside(const Box<D>& box, const Vec<D>& p) {
  bool inside = true;
  for (int k = 0; k < D; ++k) {
    inside = inside && p[k] > box.min[k] && p[k] < box.max[k];
  }
  return inside;
}

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
  const double reach = std::hypot(region.max[0] - centre[0], region.max[1] - centre[1]);
  const double margin = 0.25 * spacing * (1.0 - relative_tolerance);
  std::vector<Vec<2>> points;
  for (long k = 0;; ++k) {
    const double radius = spacing * std::sqrt((static_cast<double>(k) + 0.5) / std::numbers::pi);
    if (radius > reach) {
      break;
    }
    const double angle = static_cast<double>(k) * golden_angle;
    const Vec<2> p{centre[0] + radius * std::cos(angle), centre[1] + radius * std::sin(angle)};
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
  Box<D> domain{to_vec<D>(case_file.numbers("domain.min", D)),
                to_vec<D>(case_file.numbers("domain.max", D))};
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

enum class Shape { box, container, annulus, outline, points, stl };

// Concentric rings filling the annulus inner_radius < |x - centre| < outer_radius (2D): as many
// rings as spacings fit across it, each at the middle of its band, with round(2 pi r / spacing)
// equally spaced points, odd rings turned by half a step. Every point then stands for about
// spacing^2, and the walls of a circular domain are smooth circles (a lattice cut by a circle
// leaves steps a fluid would feel as roughness).
struct AnnulusSpec {
  Vec<2> centre{};
  double inner_radius = 0.0;
  double outer_radius = 0.0;
};

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
      points.push_back(Vec<2>{annulus.centre[0] + radius * std::cos(angle),
                              annulus.centre[1] + radius * std::sin(angle)});
    }
  }
  return points;
}

// A block as read from the case, before its particles are generated.
template <int D>
struct BlockSpec {
  std::string key;
  std::string kind;
  Lattice lattice = Lattice::square;
  Shape shape = Shape::box;
  double spacing = 0.0;
  Box<D> region;
  Box<D> outer; // the region grown by a container's layers (the region itself for a box)
  AnnulusSpec annulus;
  // An outline (2D): its region, the lattice origin its points continue, the shell thickness
  // (0: filled).
  std::shared_ptr<const Outline> outline;
  Vec<2> lattice_origin{};
  double shell = 0.0;
  // Blocks whose regions this block's particles leave out (indices into [[particles]]).
  std::vector<std::size_t> exclude;
  // A points block's particles, read from its file (core/point_file.hpp).
  std::vector<Vec<D>> points;
  double particle_volume = 0.0;
  // An stl block (3D): the surface, and where it goes: x = offset + scale * x_file.
  std::shared_ptr<const StlRegion> stl;
  double stl_scale = 1.0;
  Vec<D> stl_offset{};
};

// Whether `p` is strictly inside an stl block's surface, placed by its scale and offset.
template <int D>
bool inside_stl(const BlockSpec<D>& spec, const Vec<D>& p) {
  if constexpr (D == 3) {
    Vec<3> in_file{};
    for (int k = 0; k < 3; ++k) {
      in_file[k] = (p[k] - spec.stl_offset[k]) / spec.stl_scale;
    }
    return spec.stl->contains(in_file);
  } else {
    return false;
  }
}

template <int D>
double volume_of(const Box<D>& box) {
  double volume = 1.0;
  for (int k = 0; k < D; ++k) {
    volume *= box.max[k] - box.min[k];
  }
  return volume;
}

template <int D>
void read_annulus(const CaseFile& case_file, BlockSpec<D>& spec) {
  auto field = [&](const char* name) { return spec.key + "." + name; };
  if constexpr (D != 2) {
    case_file.fail(field("shape"), "an \"annulus\" block is two-dimensional");
  } else {
    if (case_file.has(field("lattice"))) {
      case_file.fail(field("lattice"), "an annulus is filled with concentric rings, not a lattice");
    }
    spec.shape = Shape::annulus;
    spec.annulus.centre = to_vec<2>(case_file.numbers(field("centre"), 2));
    spec.annulus.inner_radius = case_file.number(field("inner_radius"));
    spec.annulus.outer_radius = case_file.positive_number(field("outer_radius"));
    if (!(spec.annulus.inner_radius >= 0.0) ||
        !(spec.annulus.inner_radius < spec.annulus.outer_radius)) {
      case_file.fail(field("inner_radius"), "must be at least 0 and less than outer_radius");
    }
    if (!(spec.annulus.outer_radius - spec.annulus.inner_radius >= spec.spacing)) {
      case_file.fail(field("outer_radius"),
                     "the annulus must be at least one spacing wide (outer - inner radius)");
    }
    for (int k = 0; k < 2; ++k) {
      spec.region.min[k] = spec.annulus.centre[k] - spec.annulus.outer_radius;
      spec.region.max[k] = spec.annulus.centre[k] + spec.annulus.outer_radius;
    }
    spec.outer = spec.region;
  }
}

void read_exclusions(const CaseFile& case_file, const std::string& key, std::size_t index,
                     std::vector<std::size_t>& exclude) {
  const std::string exclude_key = key + ".exclude_blocks";
  if (!case_file.has(exclude_key)) {
    return;
  }
  const std::size_t count = case_file.table_count("particles");
  for (const double value : case_file.number_list(exclude_key)) {
    if (!(value >= 0.0 && value < static_cast<double>(count) && value == std::floor(value)) ||
        static_cast<std::size_t>(value) == index) {
      std::ostringstream reason;
      reason << "expected indices of other [[particles]] blocks (0 to " << count - 1 << "), got "
             << value;
      case_file.fail(exclude_key, reason.str());
    }
    exclude.push_back(static_cast<std::size_t>(value));
  }
}

// shape = "outline" (2D): vertices = [x0, y0, x1, y1, ...], corner_radii, mirror_x, offset,
// lattice_origin, layers (core/outline.hpp).
template <int D>
void read_outline(const CaseFile& case_file, BlockSpec<D>& spec) {
  auto field = [&](const char* name) { return spec.key + "." + name; };
  if (spec.lattice != Lattice::square) {
    case_file.fail(field("lattice"), "an outline is filled on a square lattice");
  }
  const std::vector<double> flat = case_file.number_list(field("vertices"));
  if (flat.size() % 2 != 0 || flat.size() < 6) {
    case_file.fail(field("vertices"), "expected x0, y0, x1, y1, ... for three vertices or more");
  }
  std::vector<Vec<2>> vertices;
  for (std::size_t i = 0; i < flat.size(); i += 2) {
    vertices.push_back({flat[i], flat[i + 1]});
  }
  std::vector<double> radii;
  if (case_file.has(field("corner_radii"))) {
    radii = case_file.number_list(field("corner_radii"));
  }
  const bool mirror = case_file.boolean_or(field("mirror_x"), false);
  Vec<2> offset{};
  if (case_file.has(field("offset"))) {
    const std::vector<double> given = case_file.numbers(field("offset"), 2);
    offset = {given[0], given[1]};
  }
  if (case_file.has(field("lattice_origin"))) {
    const std::vector<double> given = case_file.numbers(field("lattice_origin"), 2);
    spec.lattice_origin = {given[0], given[1]};
  }
  if (case_file.has(field("layers"))) {
    const std::int64_t layers = case_file.integer(field("layers"));
    if (layers < 1 || layers > 1000) {
      case_file.fail(field("layers"),
                     "must be between 1 and 1000 (got " + std::to_string(layers) + ")");
    }
    spec.shell = static_cast<double>(layers) * spec.spacing;
  }
  try {
    spec.outline =
        std::make_shared<const Outline>(Outline(vertices, radii).transformed(mirror, offset));
  } catch (const std::invalid_argument& error) {
    case_file.fail(field(radii.empty() ? "vertices" : "corner_radii"), error.what());
  }
  spec.shape = Shape::outline;
  const Box<2> bounds = spec.outline->bounds();
  for (int k = 0; k < D; ++k) {
    spec.region.min[k] = bounds.min[k];
    spec.region.max[k] = bounds.max[k];
  }
  spec.outer = spec.region;
}

// shape = "points": the particles of a point file (file, particle_volume); its other columns are
// initial values of the set's fields, given to them by fill_set (core/state_fill.hpp).
template <int D>
void read_points(const CaseFile& case_file, BlockSpec<D>& spec) {
  auto field = [&](const char* name) { return spec.key + "." + name; };
  for (const char* lattice_key : {"lattice", "min", "max", "layers", "exclude_blocks"}) {
    if (case_file.has(field(lattice_key))) {
      case_file.fail(field(lattice_key), "a \"points\" block's particles come from its file");
    }
  }
  spec.shape = Shape::points;
  try {
    spec.points = read_point_file<D>(block_file_path(case_file, spec.key)).positions;
  } catch (const PointFileError& error) {
    case_file.fail(field("file"), error.what());
  }
  double volume = 1.0;
  for (int k = 0; k < D; ++k) {
    volume *= spec.spacing;
  }
  spec.particle_volume = volume;
  if (case_file.has(field("particle_volume"))) {
    spec.particle_volume = case_file.positive_number(field("particle_volume"));
  }
  spec.region = Box<D>{spec.points.front(), spec.points.front()};
  for (const Vec<D>& p : spec.points) {
    for (int k = 0; k < D; ++k) {
      spec.region.min[k] = std::min(spec.region.min[k], p[k]);
      spec.region.max[k] = std::max(spec.region.max[k], p[k]);
    }
  }
  spec.outer = spec.region;
}

// shape = "stl" (3D): the inside of a closed STL surface (file, relative to the case file's
// folder; scale, offset) filled with the block's lattice (core/stl_region.hpp).
template <int D>
void read_stl(const CaseFile& case_file, BlockSpec<D>& spec) {
  auto field = [&](const char* name) { return spec.key + "." + name; };
  if constexpr (D != 3) {
    case_file.fail(field("shape"), "an \"stl\" block is three-dimensional");
  } else {
    for (const char* region_key : {"min", "max", "layers", "open_top"}) {
      if (case_file.has(field(region_key))) {
        case_file.fail(field(region_key), "an \"stl\" block's region is its surface's inside");
      }
    }
    if (spec.lattice == Lattice::vogel) {
      case_file.fail(field("lattice"), "an stl block is filled on a square, hexagonal or bcc "
                                       "lattice");
    }
    try {
      spec.stl = std::make_shared<const StlRegion>(block_file_path(case_file, spec.key).string());
    } catch (const StlError& error) {
      case_file.fail(field("file"), error.what());
    }
    if (case_file.has(field("scale"))) {
      spec.stl_scale = case_file.positive_number(field("scale"));
    }
    if (case_file.has(field("offset"))) {
      const std::vector<double> given = case_file.numbers(field("offset"), 3);
      spec.stl_offset = {given[0], given[1], given[2]};
    }
    spec.shape = Shape::stl;
    const Box<3> bounds = spec.stl->bounds();
    for (int k = 0; k < 3; ++k) {
      spec.region.min[k] = spec.stl_offset[k] + spec.stl_scale * bounds.min[k];
      spec.region.max[k] = spec.stl_offset[k] + spec.stl_scale * bounds.max[k];
    }
    spec.outer = spec.region;
  }
}

template <int D>
BlockSpec<D> read_block(const CaseFile& case_file, std::size_t index, double default_spacing,
                        std::span<const std::string_view> kinds) {
  BlockSpec<D> spec;
  spec.key = "particles[" + std::to_string(index) + "]";
  auto field = [&](const char* name) { return spec.key + "." + name; };
  spec.kind = case_file.string(field("kind"));
  bool known_kind = false;
  std::string allowed;
  for (std::string_view k : kinds) {
    known_kind = known_kind || k == spec.kind;
    allowed += (allowed.empty() ? "\"" : ", \"") + std::string(k) + "\"";
  }
  if (!known_kind) {
    case_file.fail(field("kind"),
                   "unknown particle kind \"" + spec.kind + "\" (this model has " + allowed + ")");
  }
  const std::string lattice_name = case_file.string_or(field("lattice"), "square");
  if (lattice_name == "hexagonal") {
    spec.lattice = Lattice::hexagonal;
    if (D == 1) {
      case_file.fail(field("lattice"), "a 1D block is a row of particles: use \"square\"");
    }
  } else if (lattice_name == "vogel") {
    spec.lattice = Lattice::vogel;
    if (D != 2) {
      case_file.fail(field("lattice"), "the \"vogel\" spiral lattice is two-dimensional");
    }
  } else if (lattice_name == "bcc") {
    spec.lattice = Lattice::body_centred_cubic;
    if (D != 3) {
      case_file.fail(field("lattice"), "the \"bcc\" lattice is three-dimensional");
    }
  } else if (lattice_name != "square") {
    case_file.fail(field("lattice"),
                   "expected \"square\", \"hexagonal\", \"bcc\" or \"vogel\", got \"" +
                       lattice_name + "\"");
  }
  spec.spacing = default_spacing;
  if (case_file.has(field("spacing"))) {
    spec.spacing = case_file.positive_number(field("spacing"));
  }
  const std::string shape = case_file.string_or(field("shape"), "box");
  read_exclusions(case_file, spec.key, index, spec.exclude);
  if (shape == "annulus") {
    read_annulus<D>(case_file, spec);
    return spec;
  }
  if (shape == "points") {
    read_points<D>(case_file, spec);
    return spec;
  }
  if (shape == "stl") {
    read_stl<D>(case_file, spec);
    return spec;
  }
  if (shape == "outline") {
    if constexpr (D != 2) {
      case_file.fail(field("shape"), "an outline is two-dimensional");
    } else {
      read_outline(case_file, spec);
    }
    return spec;
  }
  spec.region = Box<D>{to_vec<D>(case_file.numbers(field("min"), D)),
                       to_vec<D>(case_file.numbers(field("max"), D))};
  for (int k = 0; k < D; ++k) {
    if (!(spec.region.min[k] < spec.region.max[k])) {
      case_file.fail(field("max"), "must be greater than min on every axis");
    }
  }
  spec.outer = spec.region;
  if (shape == "container") {
    spec.shape = Shape::container;
    if (spec.lattice == Lattice::vogel || spec.lattice == Lattice::body_centred_cubic) {
      case_file.fail(field("lattice"), "a container's walls are on a square or hexagonal lattice");
    }
    const std::int64_t layers = case_file.integer_or(field("layers"), 1);
    if (layers < 1 || layers > 1000) {
      case_file.fail(field("layers"),
                     "must be between 1 and 1000 (got " + std::to_string(layers) + ")");
    }
    const bool open_top = case_file.boolean_or(field("open_top"), false);
    const Vec<D> period = lattice_periods<D>(spec.lattice, spec.spacing);
    for (int k = 0; k < D; ++k) {
      spec.outer.min[k] -= static_cast<double>(layers) * period[k];
      if (!(open_top && k == D - 1)) {
        spec.outer.max[k] += static_cast<double>(layers) * period[k];
      }
    }
  } else if (shape != "box") {
    case_file.fail(field("shape"),
                   "expected \"box\", \"container\", \"annulus\", \"outline\", \"points\" or "
                   "\"stl\", got \"" +
                       shape + "\"");
  } else if (case_file.has(field("layers")) || case_file.has(field("open_top"))) {
    case_file.fail(case_file.has(field("layers")) ? field("layers") : field("open_top"),
                   "only a \"container\" block has layers and open_top");
  }
  return spec;
}

// An upper estimate of a block's particles from volumes, without generating any: the lattice
// cells of its outer box padded by one period (partial rows, half-period offsets), minus the
// hollow of a container.
template <int D>
double estimated_particles(const BlockSpec<D>& spec) {
  if (spec.shape == Shape::points) {
    return static_cast<double>(spec.points.size());
  }
  Box<D> padded = spec.outer;
  const Vec<D> period = lattice_periods<D>(spec.lattice, spec.spacing);
  for (int k = 0; k < D; ++k) {
    padded.max[k] += period[k];
  }
  if constexpr (D == 2) {
    if (spec.shape == Shape::annulus) {
      const AnnulusSpec& a = spec.annulus;
      const double width = a.outer_radius - a.inner_radius;
      return std::numbers::pi * (a.outer_radius + a.inner_radius + 2.0 * spec.spacing) *
                 (width + spec.spacing) / (spec.spacing * spec.spacing) +
             1.0;
    }
  }
  const double hollow = spec.shape == Shape::container ? volume_of<D>(spec.region) : 0.0;
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
  if (spec.shape == Shape::box) {
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
  } else if (spec.shape == Shape::outline) {
    if constexpr (D == 2) {
      block.positions =
          square_lattice_points(*spec.outline, spec.lattice_origin, spec.spacing, spec.shell);
    }
  } else if (spec.shape == Shape::points) {
    block.positions = spec.points;
    block.volume_per_particle = spec.particle_volume;
  } else if (spec.shape == Shape::stl) {
    block.positions = lattice_points<D>(spec.lattice, spec.region, spec.spacing);
    std::erase_if(block.positions, [&](const Vec<D>& p) { return !inside_stl<D>(spec, p); });
  } else if (spec.shape == Shape::annulus) {
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
    const double denser = std::max(1.0, std::pow(default_spacing / specs.back().spacing, D));
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
      if (region.shape != Shape::outline && region.shape != Shape::box &&
          region.shape != Shape::stl) {
        case_file.fail(specs[b].key + ".exclude_blocks",
                       region.key + " is not a box, an outline or an stl block: only their "
                                    "regions exclude");
      }
      auto inside = [&](const Vec<D>& p) {
        if constexpr (D == 2) {
          if (region.shape == Shape::outline) {
            return region.outline->contains(p);
          }
        }
        if (region.shape == Shape::stl) {
          return inside_stl<D>(region, p);
        }
        return strictly_inside<D>(region.region, p);
      };
      std::erase_if(blocks[b].positions, inside);
    }
    if (blocks[b].positions.empty()) {
      case_file.fail(specs[b].key, "the block holds no particles once exclude_blocks are left out");
    }
  }
  refuse_coincident_particles<D>(case_file, blocks);
  return blocks;
}

std::filesystem::path block_file_path(const CaseFile& case_file, const std::string& block_key) {
  const std::filesystem::path file = case_file.string(block_key + ".file");
  if (file.empty()) {
    case_file.fail(block_key + ".file", "an empty path");
  }
  return file.is_absolute() ? file
                            : std::filesystem::path(case_file.source_name()).parent_path() / file;
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
      PointFile<D> file = read_point_file<D>(block_file_path(case_file, key));
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
