// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_TRIANGLES_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_TRIANGLES_3_H

// Reads closed triangle meshes (any FaceListGraph) into flat arrays of
// double triangles, validating them on the way.

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/check_closed_soup.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/for_each_closed_mesh_triangle.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Elements of a mesh range may be meshes or std::reference_wrapper<Mesh>.
template <typename T>
const T& unwrap_mesh(const T& t)
{
  return t;
}
template <typename T>
const T& unwrap_mesh(const std::reference_wrapper<T>& t)
{
  return t.get();
}

template <typename TriangleMeshRange>
using Mesh_of_range = std::decay_t<decltype(unwrap_mesh(*std::begin(std::declval<const TriangleMeshRange&>())))>;

template <typename TriangleMesh>
using Mesh_point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;

/// Appends the triangles of `mesh` (input number `mesh_index`) to `out`.
/// \throws Empty_input_error, Non_triangle_face_error, Open_mesh_error,
/// Non_finite_value_error, each naming the mesh and the element.
template <typename TriangleMesh, typename VertexPointMap>
void append_lattice_triangles(const TriangleMesh& mesh, const VertexPointMap& vpm, std::uint32_t mesh_index,
                              std::vector<Lattice_triangle>& out)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  const std::string name = "mesh #" + std::to_string(mesh_index);
  if(faces(mesh).empty())
    throw Empty_input_error(name + " has no face");
  std::size_t vertex_number = 0;
  for(const auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
    {
      std::ostringstream message;
      message << name << ": vertex #" << vertex_number << " has a non-finite coordinate (" << x << ' ' << y << ' '
              << z << ")";
      throw Non_finite_value_error(message.str());
    }
    ++vertex_number;
  }
  auto coordinates = [&](halfedge_descriptor h) {
    const auto& p = get(vpm, target(h, mesh));
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  for_each_closed_mesh_triangle(mesh, name, [&](halfedge_descriptor h0, halfedge_descriptor h1, halfedge_descriptor h2) {
    out.push_back(make_lattice_triangle(coordinates(h0), coordinates(h1), coordinates(h2), mesh_index));
  });
}

/// As above, with the mesh's own `vertex_point` map.
template <typename TriangleMesh>
void append_lattice_triangles(const TriangleMesh& mesh, std::uint32_t mesh_index, std::vector<Lattice_triangle>& out)
{
  append_lattice_triangles(mesh, get_const_property_map(CGAL::vertex_point, mesh), mesh_index, out);
}

/// Appends the triangles of the soup `soup` (input number `mesh_index`),
/// after checking that it bounds a solid: indices in range, no repeated
/// vertex, finite points, every directed edge matched by its opposite
/// (non-manifold vertices are fine: the classification counts crossings).
/// \throws Empty_input_error, Invalid_input_error, Open_mesh_error,
/// Non_finite_value_error, each naming the mesh.
inline void append_lattice_triangles(const Triangle_soup_3& soup, std::uint32_t mesh_index,
                                     std::vector<Lattice_triangle>& out)
{
  const std::string name = "mesh #" + std::to_string(mesh_index);
  if(soup.triangles.empty())
    throw Empty_input_error(name + " has no face");
  try
  {
    if(soup.points.size() >= (std::size_t(1) << 32))
      throw Invalid_input_error("it has 2^32 points or more");
    check_triangle_indices(soup.triangles, soup.points.size());
    check_soup_is_closed(soup.triangles, soup.points.size());
  }
  catch(const Open_mesh_error& e)
  {
    throw Open_mesh_error(name + ": " + e.what());
  }
  catch(const Invalid_input_error& e)
  {
    throw Invalid_input_error(name + ": " + e.what());
  }
  for(std::size_t v = 0; v < soup.points.size(); ++v)
  {
    const std::array<double, 3>& p = soup.points[v];
    if(!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      std::ostringstream message;
      message << name << ": point #" << v << " has a non-finite coordinate (" << p[0] << ' ' << p[1] << ' ' << p[2]
              << ")";
      throw Non_finite_value_error(message.str());
    }
  }
  out.reserve(out.size() + soup.triangles.size());
  for(const Triangle_soup_3::Triangle& t : soup.triangles)
    out.push_back(make_lattice_triangle(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]], mesh_index));
}

/// The number of triangles a mesh or soup gives (for reserving).
template <typename TriangleMesh>
std::size_t number_of_input_faces(const TriangleMesh& mesh)
{
  return std::size_t(num_faces(mesh));
}
inline std::size_t number_of_input_faces(const Triangle_soup_3& soup) { return soup.triangles.size(); }

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_TRIANGLES_3_H
