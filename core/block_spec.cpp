#include "core/block_spec.hpp"

#include "core/outline.hpp"
#include "core/point_file.hpp"
#include "core/stl_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>

namespace revsph {

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
bool in_excluding_region(const BlockSpec<D>& region, const Vec<D>& p) {
  switch (region.shape) {
  case BlockShape::box:
    return strictly_inside<D>(region.region, p);
  case BlockShape::outline:
    if constexpr (D == 2) {
      return region.outline->contains(p);
    }
    return false;
  case BlockShape::stl:
    return inside_stl<D>(region, p);
  default:
    return false;
  }
}

namespace {

template <int D>
void read_annulus(const CaseFile& case_file, BlockSpec<D>& spec) {
  auto field = [&](const char* name) { return spec.key + "." + name; };
  if constexpr (D != 2) {
    case_file.fail(field("shape"), "an \"annulus\" block is two-dimensional");
  } else {
    if (case_file.has(field("lattice"))) {
      case_file.fail(field("lattice"), "an annulus is filled with concentric rings, not a lattice");
    }
    spec.shape = BlockShape::annulus;
    spec.annulus.centre = vec_of<2>(case_file.numbers(field("centre"), 2));
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
  spec.shape = BlockShape::outline;
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
  spec.shape = BlockShape::points;
  try {
    spec.points = read_point_file<D>(block_input_file(case_file, spec.key)).positions;
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
      spec.stl = std::make_shared<const StlRegion>(block_input_file(case_file, spec.key));
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
    spec.shape = BlockShape::stl;
    const Box<3> bounds = spec.stl->bounds();
    for (int k = 0; k < 3; ++k) {
      spec.region.min[k] = spec.stl_offset[k] + spec.stl_scale * bounds.min[k];
      spec.region.max[k] = spec.stl_offset[k] + spec.stl_scale * bounds.max[k];
    }
    spec.outer = spec.region;
  }
}

} // namespace

template <int D>
BlockSpec<D> read_block_spec(const CaseFile& case_file, std::size_t index, double default_spacing) {
  BlockSpec<D> spec;
  spec.key = "particles[" + std::to_string(index) + "]";
  auto field = [&](const char* name) { return spec.key + "." + name; };
  spec.kind = case_file.string(field("kind"));
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
  // Checked before the shape's own keys, so a misspelt shape is named rather than a key that
  // only another shape needs.
  static constexpr std::array<std::string_view, 6> shapes = {"box",     "container", "annulus",
                                                             "outline", "points",    "stl"};
  if (std::find(shapes.begin(), shapes.end(), shape) == shapes.end()) {
    std::string message = "unknown shape \"" + shape + "\"; expected one of";
    for (const std::string_view known : shapes) {
      message += (known == shapes.front() ? " \"" : ", \"") + std::string(known) + "\"";
    }
    case_file.fail(field("shape"), message);
  }
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
  spec.region = Box<D>{vec_of<D>(case_file.numbers(field("min"), D)),
                       vec_of<D>(case_file.numbers(field("max"), D))};
  for (int k = 0; k < D; ++k) {
    if (!(spec.region.min[k] < spec.region.max[k])) {
      case_file.fail(field("max"), "must be greater than min on every axis");
    }
  }
  spec.outer = spec.region;
  if (shape == "container") {
    spec.shape = BlockShape::container;
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
  } else if (case_file.has(field("layers")) || case_file.has(field("open_top"))) {
    case_file.fail(case_file.has(field("layers")) ? field("layers") : field("open_top"),
                   "only a \"container\" block has layers and open_top");
  }
  return spec;
}

template BlockSpec<1> read_block_spec<1>(const CaseFile&, std::size_t, double);
template BlockSpec<2> read_block_spec<2>(const CaseFile&, std::size_t, double);
template BlockSpec<3> read_block_spec<3>(const CaseFile&, std::size_t, double);
template bool inside_stl<1>(const BlockSpec<1>&, const Vec<1>&);
template bool inside_stl<2>(const BlockSpec<2>&, const Vec<2>&);
template bool inside_stl<3>(const BlockSpec<3>&, const Vec<3>&);
template bool in_excluding_region<1>(const BlockSpec<1>&, const Vec<1>&);
template bool in_excluding_region<2>(const BlockSpec<2>&, const Vec<2>&);
template bool in_excluding_region<3>(const BlockSpec<3>&, const Vec<3>&);

} // namespace revsph
