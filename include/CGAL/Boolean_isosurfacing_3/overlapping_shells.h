// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_OVERLAPPING_SHELLS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_OVERLAPPING_SHELLS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `find_overlapping_shells()` found in one closed mesh.
struct Overlapping_shells_report
{
  /// Connected components (shells) of the mesh.
  std::size_t components = 0;
  /// Pairs (i, j), i < j, of components with the same orientation (both
  /// outward or both inward) where a sampled vertex of one is strictly
  /// inside the other: the shells overlap or one is nested in the other.
  /// Parity (what `Lattice_classifier_3` uses) counts the doubly covered part
  /// as outside the solid; the union reading (winding number at least 1)
  /// counts it inside.
  std::vector<std::pair<std::size_t, std::size_t>> overlapping_pairs;
  /// Whether the self-intersection test ran (`check_self_intersection`).
  bool checked_self_intersection = false;
  /// Whether two triangles of the mesh intersect
  /// (`Polygon_mesh_processing::does_self_intersect()`): crossing shells,
  /// or one shell crossing itself.
  bool self_intersecting = false;

  /// Whether the mesh's inside differs between parity and the union reading
  /// (as far as the checks tell).
  bool overlaps() const { return !overlapping_pairs.empty() || self_intersecting; }
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Detects the input shells that overlap themselves: in a closed mesh, two
 * connected components of the same orientation one of whose vertices
 * (up to `samples_per_component`, evenly spread) lies strictly inside the
 * other (exact `Side_of_triangle_mesh`), and, if
 * `check_self_intersection`, any two intersecting triangles
 * (`Polygon_mesh_processing::does_self_intersect()`, the expensive part:
 * O(n log n) with exact predicates).  A mesh of one component costs only
 * the connected-component pass unless the self-intersection test is asked
 * for.  A cavity (an inward shell inside an outward one) is not an overlap.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
 *         (`CGAL::Surface_mesh`), closed
 */
template <typename TriangleMesh>
Overlapping_shells_report find_overlapping_shells(const TriangleMesh& mesh, bool check_self_intersection,
                                                  std::size_t samples_per_component = 32)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Surface_mesh<Point> Shell;
  Overlapping_shells_report report;
  if(check_self_intersection)
  {
    report.checked_self_intersection = true;
    report.self_intersecting = PMP::does_self_intersect(mesh);
  }
  std::vector<std::size_t> component_of(num_faces(mesh));
  const auto fim = get(CGAL::face_index, mesh);
  const auto indexed = boost::make_iterator_property_map(component_of.begin(), fim);
  report.components = PMP::connected_components(mesh, indexed);
  if(report.components < 2)
    return report;
  // Each component as its own closed mesh, with its orientation.
  std::vector<Shell> shells(report.components);
  std::vector<int> orientation(report.components);
  for(std::size_t c = 0; c < report.components; ++c)
  {
    const CGAL::Face_filtered_graph<TriangleMesh> part(mesh, c, indexed);
    CGAL::copy_face_graph(part, shells[c]);
    orientation[c] = PMP::volume(shells[c]) >= 0 ? 1 : -1;
  }
  std::vector<std::vector<Point>> samples(report.components);
  for(std::size_t c = 0; c < report.components; ++c)
  {
    const std::size_t n = shells[c].number_of_vertices();
    const std::size_t step = (std::max)(std::size_t(1), n / samples_per_component);
    for(std::size_t i = 0; i < n; i += step)
      samples[c].push_back(shells[c].point(typename Shell::Vertex_index(typename Shell::size_type(i))));
  }
  for(std::size_t j = 0; j < report.components; ++j)
  {
    const CGAL::Side_of_triangle_mesh<Shell, Kernel> inside(shells[j]);
    for(std::size_t i = 0; i < report.components; ++i)
    {
      if(i == j || orientation[i] != orientation[j])
        continue;
      const bool hit = std::any_of(samples[i].begin(), samples[i].end(),
                                   [&](const Point& p) { return inside(p) == CGAL::ON_BOUNDED_SIDE; });
      if(hit)
        report.overlapping_pairs.emplace_back((std::min)(i, j), (std::max)(i, j));
    }
  }
  std::sort(report.overlapping_pairs.begin(), report.overlapping_pairs.end());
  report.overlapping_pairs.erase(std::unique(report.overlapping_pairs.begin(), report.overlapping_pairs.end()),
                                 report.overlapping_pairs.end());
  return report;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_OVERLAPPING_SHELLS_H
