#include "core/stl_region.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <optional>
#include <sstream>

namespace revsph {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

struct StlRegion::Surface {
  Mesh mesh;
  std::optional<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
};

StlRegion::StlRegion(const InputFile& file) : surface_(std::make_unique<Surface>()) {
  try {
    read(file);
  } catch (const CGAL::Failure_exception& failure) {
    // A precondition of CGAL's repair or orientation that this surface breaks.
    throw StlError(file.path + ": CGAL cannot use the surface (" + failure.expression() + ")");
  }
}

void StlRegion::read(const InputFile& file) {
  const std::string& path = file.path;
  // An STL file is a soup of triangles, each with its own copies of its corners: merged into
  // one mesh (repair), its faces turned consistently (orient), before anything asks inside.
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> triangles;
  std::istringstream bytes(file.bytes); // CGAL tells ASCII from binary by the first word
  if (!CGAL::IO::read_STL(bytes, points, triangles) || triangles.empty()) {
    throw StlError(path + ": not an STL file with triangles");
  }
  PMP::repair_polygon_soup(points, triangles);
  if (!PMP::orient_polygon_soup(points, triangles)) {
    throw StlError(path + ": the surface cannot be oriented (not a manifold)");
  }
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface_->mesh);
  if (!CGAL::is_closed(surface_->mesh)) {
    throw StlError(path + ": the surface is not closed (it encloses no volume)");
  }
  if (!PMP::is_outward_oriented(surface_->mesh)) {
    PMP::reverse_face_orientations(surface_->mesh);
  }
  surface_->side.emplace(surface_->mesh);
}

StlRegion::~StlRegion() = default;
StlRegion::StlRegion(StlRegion&&) noexcept = default;
StlRegion& StlRegion::operator=(StlRegion&&) noexcept = default;

Box<3> StlRegion::bounds() const {
  const CGAL::Bbox_3 box = PMP::bbox(surface_->mesh);
  return Box<3>{{box.xmin(), box.ymin(), box.zmin()}, {box.xmax(), box.ymax(), box.zmax()}};
}

double StlRegion::volume() const {
  return CGAL::to_double(PMP::volume(surface_->mesh));
}

std::size_t StlRegion::triangle_count() const {
  return surface_->mesh.number_of_faces();
}

bool StlRegion::contains(const Vec<3>& point) const {
  return (*surface_->side)(Kernel::Point_3(point[0], point[1], point[2])) == CGAL::ON_BOUNDED_SIDE;
}

std::vector<Vec<3>> StlRegion::inside(std::span<const Vec<3>> candidates) const {
  // Serial: the queries share the AABB tree, which CGAL builds lazily on the first one.
  std::vector<Vec<3>> kept;
  for (const Vec<3>& point : candidates) {
    if (contains(point)) {
      kept.push_back(point);
    }
  }
  return kept;
}

} // namespace revsph
