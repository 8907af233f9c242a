// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ANGLE_RAISING_FLIPS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ANGLE_RAISING_FLIPS_H

#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Sliver_flips.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <vector>

// Edge flips that raise the smallest angle of a post-processed mesh
// (`remesh_keeping_creases()`, `simplify_keeping_creases()`), in double: they
// only choose between two triangulations of the same four vertices, and the
// results are checked for self-intersections exactly afterwards.

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

template <typename TriangleMesh>
Marching_cubes_csg::Vector_3d vertex_vector(const TriangleMesh& mesh,
                                            typename boost::graph_traits<TriangleMesh>::vertex_descriptor v)
{
  const auto& p = get(get(CGAL::vertex_point, mesh), v);
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

// Whether replacing the triangles abc and bad (on the edge ab) by adc and dbc
// raises their smallest angle, the largest cosine falling by more than
// `margin`, and keeps both new triangles facing the way the pair did.
inline bool flip_raises_smallest_angle(const Marching_cubes_csg::Vector_3d& a, const Marching_cubes_csg::Vector_3d& b,
                                       const Marching_cubes_csg::Vector_3d& c, const Marching_cubes_csg::Vector_3d& d,
                                       double margin = 0)
{
  namespace MC = Marching_cubes_csg;
  const double before = (std::max)(MC::largest_cosine(a, b, c), MC::largest_cosine(b, a, d));
  const double after = (std::max)(MC::largest_cosine(a, d, c), MC::largest_cosine(d, b, c));
  if(!(after < before - margin))
    return false;
  const MC::Vector_3d p = MC::cross3(MC::sub3(b, a), MC::sub3(c, a)), q = MC::cross3(MC::sub3(a, b), MC::sub3(d, b));
  const MC::Vector_3d old_normal{{p[0] + q[0], p[1] + q[1], p[2] + q[2]}};
  return MC::dot3(MC::cross3(MC::sub3(d, a), MC::sub3(c, a)), old_normal) > 0 &&
         MC::dot3(MC::cross3(MC::sub3(b, d), MC::sub3(c, d)), old_normal) > 0;
}

// Whether the edge of `h` can flip: not constrained, not on a border, and
// the edge joining the two faces' far vertices not already there.
template <typename TriangleMesh, typename EdgeIsConstrainedMap>
bool flippable(const TriangleMesh& mesh, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
               EdgeIsConstrainedMap constrained)
{
  if(is_border_edge(h, mesh) || get(constrained, edge(h, mesh)))
    return false;
  const auto vc = target(next(h, mesh), mesh), vd = target(next(opposite(h, mesh), mesh), mesh);
  return vc != vd && !halfedge(vc, vd, mesh).second;
}

// Flips the side opposite the largest angle of every cap (a triangle with an
// angle above 160 degrees) where that makes the two triangles' smallest angle
// larger without folding them: the remeshing can leave such caps where it
// meets faces it was not given.  Constrained edges never flip.  Returns the
// flips.
template <typename TriangleMesh, typename EdgeIsConstrainedMap>
std::size_t flip_caps(TriangleMesh& mesh, EdgeIsConstrainedMap constrained)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  namespace MC = Marching_cubes_csg;
  typedef MC::Vector_3d V;
  // The cosine of the angle at a of the triangle abc.
  const auto cosine = [](const V& a, const V& b, const V& c) {
    const V u = MC::sub3(b, a), v = MC::sub3(c, a);
    const double l = MC::dot3(u, u) * MC::dot3(v, v);
    return l > 0 ? MC::dot3(u, v) / std::sqrt(l) : 1.0;
  };
  // The side opposite an angle above 160 degrees.
  const double cap_cosine = std::cos(160.0 * 3.14159265358979323846 / 180.0);
  const auto opposite_cap = [&](halfedge_descriptor h) {
    return cosine(vertex_vector(mesh, target(next(h, mesh), mesh)), vertex_vector(mesh, source(h, mesh)),
                  vertex_vector(mesh, target(h, mesh))) < cap_cosine;
  };
  std::vector<halfedge_descriptor> candidates;
  for(const auto f : faces(mesh))
  {
    halfedge_descriptor h = halfedge(f, mesh);
    for(int k = 0; k < 3; ++k, h = next(h, mesh))
      if(opposite_cap(h))
        candidates.push_back(h);
  }
  std::size_t flips = 0;
  for(const halfedge_descriptor h : candidates)
  {
    if(face(h, mesh) == boost::graph_traits<TriangleMesh>::null_face() || !flippable(mesh, h, constrained) ||
       !opposite_cap(h)) // an earlier flip changed it
      continue;
    if(!flip_raises_smallest_angle(vertex_vector(mesh, source(h, mesh)), vertex_vector(mesh, target(h, mesh)),
                                   vertex_vector(mesh, target(next(h, mesh), mesh)),
                                   vertex_vector(mesh, target(next(opposite(h, mesh), mesh), mesh))))
      continue;
    CGAL::Euler::flip_edge(h, mesh);
    ++flips;
  }
  return flips;
}

// Flips the edges between two nearly coplanar triangles where that raises
// their smallest angle (Lawson's flips, restricted to flat pairs): edge
// collapses leave a flat face of a CAD result as needles fanned from its
// corners, which the flips turn into its Delaunay triangulation.  An edge
// flips only if each of the two triangles' far vertices is within
// `max_height` of the other triangle's plane (so the surface moves by at
// most that), the flipped triangles keep the orientation, and the edge is
// not constrained and touches no face with `is_frozen` set.  Returns the
// flips.
template <typename TriangleMesh, typename EdgeIsConstrainedMap, typename FaceIsFrozenMap>
std::size_t flip_flat_slivers(TriangleMesh& mesh, EdgeIsConstrainedMap constrained, FaceIsFrozenMap is_frozen,
                              double max_height)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  namespace MC = Marching_cubes_csg;
  typedef MC::Vector_3d V;
  // Whether d is within max_height of the plane through a with normal n.
  const auto near_plane = [&](const V& a, const V& n, const V& d) {
    const double h = MC::dot3(MC::sub3(d, a), n);
    return h * h <= max_height * max_height * MC::dot3(n, n);
  };
  std::deque<edge_descriptor> queue(edges(mesh).first, edges(mesh).second);
  std::size_t flips = 0;
  const std::size_t max_flips = 10 * num_edges(mesh);
  while(!queue.empty() && flips < max_flips)
  {
    const halfedge_descriptor h = halfedge(queue.front(), mesh), o = opposite(h, mesh);
    queue.pop_front();
    if(!flippable(mesh, h, constrained) || get(is_frozen, face(h, mesh)) || get(is_frozen, face(o, mesh)))
      continue;
    const V a = vertex_vector(mesh, source(h, mesh)), b = vertex_vector(mesh, target(h, mesh)),
            c = vertex_vector(mesh, target(next(h, mesh), mesh)), d = vertex_vector(mesh, target(next(o, mesh), mesh));
    // A strict gain, so that the flips end.
    if(!near_plane(a, MC::cross3(MC::sub3(b, a), MC::sub3(c, a)), d) ||
       !near_plane(b, MC::cross3(MC::sub3(a, b), MC::sub3(d, b)), c) || !flip_raises_smallest_angle(a, b, c, d, 1e-12))
      continue;
    CGAL::Euler::flip_edge(h, mesh);
    ++flips;
    for(const halfedge_descriptor g : {next(h, mesh), prev(h, mesh), next(o, mesh), prev(o, mesh)})
      queue.push_back(edge(g, mesh));
  }
  return flips;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ANGLE_RAISING_FLIPS_H
