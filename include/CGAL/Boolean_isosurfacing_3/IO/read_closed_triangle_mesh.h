// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/check_manifold_vertices.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * builds `mesh` from a soup that bounds a solid (as `read_closed_triangle_soup()`
 * returns), after checking that it is a 2-manifold (each edge in exactly two
 * triangles, one fan of triangles around each vertex), which a halfedge
 * data structure needs.
 *
 * \throws Invalid_input_error naming a non-manifold edge or vertex.
 */
template <typename MutableFaceGraph>
void triangle_soup_to_mesh(const Triangle_soup_3& soup, MutableFaceGraph& mesh)
{
  typedef typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  CGAL::Boolean_isosurfacing::internal::check_manifold_vertices(soup.triangles, soup.points.size());
  std::vector<Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.triangles, mesh);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * reads `path` (OFF, OBJ, PLY or STL, see `read_triangle_soup()`) into `mesh`
 * and checks that it bounds a solid: a non-empty, closed, consistently
 * oriented, outward triangle mesh with finite coordinates and manifold
 * vertices.  Polygons with more than 3 vertices are split into triangles;
 * otherwise it never repairs or reorients: a file that does not describe a
 * solid is an error.  The file is parsed by the package's own readers, which
 * check header counts against the file size first (CGAL 5.5's readers
 * allocate from them, and crash on some legal PLY files).
 *
 * \tparam MutableFaceGraph a model of `MutableFaceGraph` with an internal
 *         vertex point property constructible from three doubles
 *
 * \returns the number of polygons that were split into triangles.
 *
 * \throws Invalid_input_error (or a derived type: `Parse_error` with the line
 *   number for text formats, `Empty_input_error`, `Open_mesh_error`,
 *   `Non_finite_value_error`, `Inward_oriented_mesh_error`) whose message
 *   states the problem in one line, without the file name.  With
 *   `allow_inward = true`, inward-oriented meshes are accepted.
 */
template <typename MutableFaceGraph>
std::size_t read_closed_triangle_mesh(const std::string& path, MutableFaceGraph& mesh, bool allow_inward = false)
{
  const Triangle_soup_3 soup = read_closed_triangle_soup(path, allow_inward);
  triangle_soup_to_mesh(soup, mesh);
  return soup.triangulated_polygons;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H
