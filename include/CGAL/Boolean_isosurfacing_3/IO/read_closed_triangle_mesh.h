// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <fstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads `path` (OFF, OBJ, PLY, STL or any format of `CGAL::IO::read_polygon_soup()`)
 * into `mesh` and checks that it bounds a solid: a non-empty, closed,
 * consistently oriented, outward triangle mesh with finite coordinates and
 * manifold vertices.  Unlike `CGAL::IO::read_polygon_mesh()`, it never repairs
 * or reorients: a file that does not describe a solid is an error.
 *
 * \tparam MutableFaceGraph a model of `MutableFaceGraph` with an internal
 *         vertex point property whose kernel models `SurveyorVolumeTraits_3`
 *
 * \throws Invalid_input_error (or a derived type: `Empty_input_error`,
 *   `Non_triangle_face_error`, `Open_mesh_error`, `Non_finite_value_error`,
 *   `Inward_oriented_mesh_error`) whose message states the problem in one line,
 *   without the file name.  With `allow_inward = true`, inward-oriented meshes
 *   are accepted.
 */
template <typename MutableFaceGraph>
void read_closed_triangle_mesh(const std::string& path, MutableFaceGraph& mesh, bool allow_inward = false)
{
  typedef typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;

  struct stat info;
  if(stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) || !std::ifstream(path))
    throw Invalid_input_error("cannot open the file");
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    throw Invalid_input_error("cannot parse it as OFF, OBJ, PLY or STL (malformed or unsupported)");
  // The soup overload of surveyor_volume validates everything a solid needs
  // (faces, closedness, orientation, finiteness) with messages naming the
  // offending element.
  surveyor_volume(points, polygons, parameters::signed_volume(allow_inward));
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw Invalid_input_error("it is closed but has a non-manifold vertex; split it first "
                              "(PMP::duplicate_non_manifold_vertices)");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_MESH_H
