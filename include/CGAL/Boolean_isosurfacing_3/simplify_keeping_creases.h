// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_SIMPLIFY_KEEPING_CREASES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_SIMPLIFY_KEEPING_CREASES_H

#include <CGAL/Boolean_isosurfacing_3/Post_processing_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/angle_raising_flips.h>
#include <CGAL/Boolean_isosurfacing_3/internal/post_process_without_self_intersections.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/optional.hpp>

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The placement of a crease-keeping collapse: corners never move; an edge
// with one end on a crease collapses onto that end; an edge between two
// crease vertices only if it is itself a crease edge and one of its ends is
// the interior vertex of a straight crease polyline (then that end goes);
// otherwise the base placement (Garland-Heckbert).
template <typename BasePlacement, typename EdgeIsConstrainedMap, typename VertexIsConstrainedMap>
class Crease_keeping_placement
{
public:
  Crease_keeping_placement(const BasePlacement& base, EdgeIsConstrainedMap ecm, VertexIsConstrainedMap vcm,
                           double cos_straight)
    : m_base(base), m_ecm(ecm), m_vcm(vcm), m_cos_straight(cos_straight)
  {}

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const
  {
    typedef typename Profile::TM TM;
    const TM& tm = profile.surface_mesh();
    const auto v0 = profile.v0(), v1 = profile.v1();
    if(get(m_vcm, v0) || get(m_vcm, v1))
      return boost::none;
    const int c0 = crease_degree(v0, tm), c1 = crease_degree(v1, tm);
    // The two faces' other edges must not be creases (one of each pair is
    // removed by the collapse).
    for(const auto& h : {profile.v0_v1(), profile.v1_v0()})
      if(!is_border(h, tm) && (get(m_ecm, edge(next(h, tm), tm)) || get(m_ecm, edge(prev(h, tm), tm))))
        return boost::none;
    if(c0 == 0 && c1 == 0)
      return m_base(profile);
    if(c0 > 0 && c1 == 0)
      return get(profile.vertex_point_map(), v0);
    if(c1 > 0 && c0 == 0)
      return get(profile.vertex_point_map(), v1);
    // Both on creases: only along a crease edge, removing a straight interior vertex.
    if(!get(m_ecm, edge(profile.v0_v1(), tm)))
      return boost::none;
    if(c1 == 2 && straight(v1, tm, profile))
      return get(profile.vertex_point_map(), v0);
    if(c0 == 2 && straight(v0, tm, profile))
      return get(profile.vertex_point_map(), v1);
    return boost::none;
  }

private:
  template <typename Vertex, typename TM>
  int crease_degree(Vertex v, const TM& tm) const
  {
    int n = 0;
    for(const auto h : halfedges_around_target(v, tm))
      n += get(m_ecm, edge(h, tm)) ? 1 : 0;
    return n;
  }
  // Whether the two crease edges at v are nearly collinear.
  template <typename Vertex, typename TM, typename Profile>
  bool straight(Vertex v, const TM& tm, const Profile& profile) const
  {
    const auto vpm = profile.vertex_point_map();
    const auto p = get(vpm, v);
    double d[2][3];
    int k = 0;
    for(const auto h : halfedges_around_target(v, tm))
      if(get(m_ecm, edge(h, tm)) && k < 2)
      {
        const auto q = get(vpm, source(h, tm));
        d[k][0] = CGAL::to_double(q.x() - p.x());
        d[k][1] = CGAL::to_double(q.y() - p.y());
        d[k][2] = CGAL::to_double(q.z() - p.z());
        ++k;
      }
    if(k != 2)
      return false;
    const double dot = d[0][0] * d[1][0] + d[0][1] * d[1][1] + d[0][2] * d[1][2];
    const double l0 = std::sqrt(d[0][0] * d[0][0] + d[0][1] * d[0][1] + d[0][2] * d[0][2]);
    const double l1 = std::sqrt(d[1][0] * d[1][0] + d[1][1] * d[1][1] + d[1][2] * d[1][2]);
    return l0 > 0 && l1 > 0 && dot / (l0 * l1) < -m_cos_straight;
  }

  BasePlacement m_base;
  EdgeIsConstrainedMap m_ecm;
  VertexIsConstrainedMap m_vcm;
  double m_cos_straight;
};

// Refuses a collapse that takes the mesh farther than `max_distance` from
// the input surface, as far as 7 samples per new triangle (its vertices,
// edge midpoints and centroid) tell: distances to an AABB tree of the input
// triangles, in double.  (CGAL's Polyhedral_envelope_filter gives an exact
// bound but took minutes on a 10^4-triangle CSG result.)
template <typename Kernel, typename BaseFilter>
class Sampled_distance_filter
{
  typedef typename Kernel::Point_3 Point;
  typedef typename Kernel::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Iterator>>> Tree;

public:
  template <typename TriangleMesh>
  Sampled_distance_filter(const TriangleMesh& mesh, double max_distance, const BaseFilter& base = BaseFilter())
    : m_triangles(std::make_shared<std::vector<Triangle>>()), m_squared(max_distance * max_distance), m_base(base)
  {
    const auto vpm = get(CGAL::vertex_point, mesh);
    for(const auto f : faces(mesh))
    {
      const auto h = halfedge(f, mesh);
      m_triangles->emplace_back(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                                get(vpm, target(next(h, mesh), mesh)));
    }
    m_tree = std::make_shared<Tree>(m_triangles->begin(), m_triangles->end());
    m_tree->accelerate_distance_queries();
  }

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile,
                                                      boost::optional<typename Profile::Point> op) const
  {
    op = m_base(profile, op);
    if(!op)
      return op;
    const auto& triangles = profile.triangles();
    auto it = triangles.begin();
    if(profile.left_face_exists())
      ++it;
    if(profile.right_face_exists())
      ++it;
    const Point q = *op;
    if(!close(q))
      return boost::none;
    for(; it != triangles.end(); ++it)
    {
      // The second vertex of each triangle is the one that moves to q.
      const Point p = get(profile.vertex_point_map(), it->v0), r = get(profile.vertex_point_map(), it->v2);
      const Point samples[] = {CGAL::midpoint(p, q), CGAL::midpoint(q, r), CGAL::midpoint(r, p), CGAL::centroid(p, q, r)};
      for(const Point& x : samples)
        if(!close(x))
          return boost::none;
    }
    return op;
  }

private:
  // Whether some input triangle is within the bound of the query point: the
  // tree's traversal stops at the first one, where squared_distance() would
  // go on to find the closest (measured: most of the simplification's time).
  class Within_bound
  {
  public:
    explicit Within_bound(double squared) : m_squared(squared) {}
    bool go_further() const { return !m_found; }
    template <typename Primitive>
    void intersection(const Point& x, const Primitive& primitive)
    {
      if(!m_found && CGAL::to_double(CGAL::squared_distance(x, primitive.datum())) <= m_squared)
        m_found = true;
    }
    template <typename Node>
    bool do_intersect(const Point& x, const Node& node) const
    {
      const CGAL::Bbox_3& b = node.bbox();
      const double c[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
      double d = 0;
      for(int i = 0; i < 3; ++i)
      {
        const double below = b.min(i) - c[i], above = c[i] - b.max(i);
        if(below > 0)
          d += below * below;
        else if(above > 0)
          d += above * above;
      }
      return d <= m_squared;
    }
    bool found() const { return m_found; }

  private:
    double m_squared;
    bool m_found = false;
  };

  bool close(const Point& x) const
  {
    Within_bound within(m_squared);
    m_tree->traversal(x, within);
    return within.found();
  }

  std::shared_ptr<std::vector<Triangle>> m_triangles;
  std::shared_ptr<Tree> m_tree;
  double m_squared;
  BaseFilter m_base;
};

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Simplifies a closed triangle mesh, typically a `marching_cubes_csg()`
 * result with its creases and corners, by edge collapses (CGAL's
 * `Surface_mesh_simplification::edge_collapse()` with Garland-Heckbert plane
 * quadrics), keeping:
 *  - the distance bound: a collapse is refused if one of the moved
 *    triangles' vertices, edge midpoints or centroid is farther than
 *    0.8 `max_distance` from the input surface (AABB tree distance).  This is
 *    a sampled bound: between samples a triangle can stray farther, hence
 *    the margin, but not enough of one (measured with CGAL's
 *    `bounded_error_Hausdorff_distance()` on CSG results at 64 and 128
 *    cells: up to 3.2 `max_distance`);
 *  - the input: a collapse can also take the mesh away from a thin part of
 *    the input (a wedge collapsed onto one of its sides) while its own
 *    triangles stay close to the input.  So the result is checked for input
 *    vertices farther than 2 `max_distance` from it, and where there are
 *    some, the simplification runs again as below with the input's faces
 *    near them kept as they are (on the same 8 results, the largest distance
 *    from the input to the result went from 2.9-11.7 to 1.8-4.9
 *    `max_distance`);
 *  - the creases: a vertex on a crease edge is never moved off it, a crease
 *    polyline only loses interior vertices where it is straight (its two
 *    crease edges within 1 degree of a line), and crease edges are never
 *    removed otherwise;
 *  - the corners (`vertex_is_constrained_map`): never moved or removed;
 *  - no face normal turns by more than 90 degrees (`Bounded_normal_change_filter`);
 *  - no self-intersection: the result is checked exactly
 *    (`Polygon_mesh_processing::self_intersections()`); where it
 *    self-intersects (typically at a wall or a gap thinner than a cell), the
 *    simplification runs again from the input with the input's faces near
 *    there kept as they are, and after 4 such runs the mesh is left as it was
 *    (`Post_processing_statistics::reverted`, with a warning); a last run
 *    that only left input vertices far is kept, with a warning that counts
 *    them.
 * A flat face of the result thus comes back as a few triangles spanning its
 * crease polylines.  Collapses stop when none is allowed; then the edges
 * between nearly coplanar triangles (the fourth vertex within a tenth of
 * `max_distance` of the plane) flip where that raises the smallest angle,
 * so that a flat face is triangulated as Delaunay would.
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` with `Surface_mesh`-like
 *         indexed vertices and faces (`CGAL::Surface_mesh`), triangle faces
 *
 * \param mesh the closed triangle mesh, simplified in place
 * \param max_distance the distance bound, in the mesh's units (for a CSG
 *        result, a fraction of the lattice spacing)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{the crease edges (`true`); kept up to date on the simplified mesh}
 *     \cgalParamType{a `ReadWritePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{no crease}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{the corners (`true`), never moved; kept up to date on the simplified mesh}
 *     \cgalParamType{a `ReadWritePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{no corner}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns what was done (`edges_collapsed`, the runs, the frozen faces,
 *          whether the mesh was left as it was).
 * \throws Invalid_input_error if `max_distance` is not positive and finite or
 *         the mesh is not a closed triangle mesh.
 */
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Post_processing_statistics simplify_keeping_creases(TriangleMesh& mesh, double max_distance,
                                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  if(!(max_distance > 0 && std::isfinite(max_distance)))
    throw Invalid_input_error("simplify_keeping_creases: the distance bound must be positive and finite, got " +
                              std::to_string(max_distance));
  if(!CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    throw Invalid_input_error("simplify_keeping_creases: the mesh must be a closed triangle mesh");
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    CGAL::Static_boolean_property_map<edge_descriptor, false>());
  const auto vcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                    CGAL::Static_boolean_property_map<vertex_descriptor, false>());
  const double cos_straight = std::cos(1.0 * 3.14159265358979323846 / 180.0); // 1 degree

  const auto process = [&](TriangleMesh& work, auto crease, auto corner, auto is_frozen) -> std::size_t {
    // The corners and the vertices of the frozen faces never move.
    auto fixed = get(CGAL::dynamic_vertex_property_t<bool>(), work);
    for(const vertex_descriptor v : vertices(work))
      put(fixed, v, bool(get(corner, v)));
    for(const face_descriptor f : faces(work))
      if(get(is_frozen, f))
        for(const vertex_descriptor v : vertices_around_face(halfedge(f, work), work))
          put(fixed, v, true);
    typedef SMS::GarlandHeckbert_plane_policies<TriangleMesh, Kernel> Policies;
    Policies policies(work);
    typedef internal::Crease_keeping_placement<typename Policies::Get_placement, decltype(crease), decltype(fixed)>
        Placement;
    const Placement placement(policies.get_placement(), crease, fixed, cos_straight);
    // The samples are held to 0.8 of the bound so that the triangles between
    // them stay within it (measured: two spheres' union at 64 cells came 13 %
    // over the bound with the samples held to the bound itself).
    const internal::Sampled_distance_filter<Kernel, SMS::Bounded_normal_change_filter<>> filter(work,
                                                                                               0.8 * max_distance);
    const SMS::Count_ratio_stop_predicate<TriangleMesh> stop(0.0);
    const std::size_t collapsed = std::size_t(SMS::edge_collapse(
        work, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement).filter(filter)));
    internal::flip_flat_slivers(work, crease, is_frozen, 0.1 * max_distance);
    return collapsed;
  };
  // A result that self-intersects, or that lost a part of the input (an
  // input vertex farther than two bounds from it), is redone with the input
  // frozen within about a cell (ten bounds) of where it did.  (One bound:
  // 3-4 runs on 7 of 8 results and 1.2-1.7 times the triangles.)
  return internal::post_process_without_self_intersections(mesh, ecm, vcm, 10 * max_distance, 2 * max_distance,
                                                           "simplify_keeping_creases", process);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_SIMPLIFY_KEEPING_CREASES_H
