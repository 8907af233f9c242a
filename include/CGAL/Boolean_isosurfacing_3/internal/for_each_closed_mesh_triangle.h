// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FOR_EACH_CLOSED_MESH_TRIANGLE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FOR_EACH_CLOSED_MESH_TRIANGLE_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/Polyhedron_3_fwd.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Whether the counts alone prove that no halfedge is a border: a halfedge
// belongs to one face or to none, so when there are exactly three halfedges
// a face and every face is a triangle (which the traversal still checks),
// every halfedge is in a face.  Known in constant time for Surface_mesh and
// Polyhedron_3; other graphs answer false and have their faces' edges
// checked one by one.
template <typename TriangleMesh>
bool has_three_halfedges_per_face(const TriangleMesh&)
{
  return false;
}

template <typename Point>
bool has_three_halfedges_per_face(const CGAL::Surface_mesh<Point>& mesh)
{
  return mesh.number_of_halfedges() == 3 * std::size_t(mesh.number_of_faces());
}

template <typename Traits, typename Items, template <class T, class I, class A> class HDS, typename Alloc>
bool has_three_halfedges_per_face(const CGAL::Polyhedron_3<Traits, Items, HDS, Alloc>& mesh)
{
  return mesh.size_of_halfedges() == 3 * std::size_t(mesh.size_of_facets());
}

// Calls f(h0, h1, h2) with the three halfedges of every face of `mesh`,
// checking on the way that the mesh is a closed triangle mesh: a face that
// is not a triangle throws Non_triangle_face_error, a border edge
// Open_mesh_error; `mesh_name` ("the mesh", "mesh #2") starts the messages.
// The border checks are fused into the traversal (the opposite halfedge is
// next to h in memory for the common halfedge data structures), and skipped
// where the counts already prove the mesh has no border.
template <typename TriangleMesh, typename Function>
void for_each_closed_mesh_triangle(const TriangleMesh& mesh, const std::string& mesh_name, const Function& f)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  // Even fused, the border tests were 30-50 % of a traversal that only sums.
  const bool check_borders = !has_three_halfedges_per_face(mesh);
  std::size_t face_number = 0;
  for(const auto face : faces(mesh))
  {
    // h2 from prev(h0), not next(h1): with Surface_mesh's halfedge records
    // (next and prev side by side) h1 and h2 are then two independent loads
    // after h0 instead of a chain of three dependent ones (as PMP::volume
    // does).  next(h1) == prev(h0) holds exactly for a face of 3 halfedges.
    const halfedge_descriptor h0 = halfedge(face, mesh);
    const halfedge_descriptor h1 = next(h0, mesh);
    const halfedge_descriptor h2 = prev(h0, mesh);
    if(next(h1, mesh) != h2)
      throw Non_triangle_face_error(mesh_name + ": face #" + std::to_string(face_number) +
                                    " is not a triangle (triangulate the mesh first, e.g. with "
                                    "PMP::triangulate_faces)");
    if(check_borders && (is_border(opposite(h0, mesh), mesh) || is_border(opposite(h1, mesh), mesh) ||
                         is_border(opposite(h2, mesh), mesh)))
      throw Open_mesh_error(mesh_name + " is not closed: face #" + std::to_string(face_number) +
                            " has a border edge, so it does not bound a solid");
    f(h0, h1, h2);
    ++face_number;
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_FOR_EACH_CLOSED_MESH_TRIANGLE_H
