// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TRIANGLE_PAIR_INTERSECTION_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TRIANGLE_PAIR_INTERSECTION_H

// Whether two triangles of a soup (indices into its points) meet, as
// `PMP::self_intersections()` decides it for two faces of a mesh, with exact
// predicates: the pair test of the weak-fan check (Marching_cubes_csg/
// Weak_fan_check.h) and of does_triangle_soup_self_intersect().  Cheaper
// than PMP's on the common pairs: the triangles around a shared vertex are
// told apart by statically filtered orientations before any construction,
// and points on a common lattice-parallel plane (CAD faces of Marching Cubes
// output, whose orientations are exact zeros that no filter decides) are
// decided in 2D.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// The axis along which all `n` points have the same coordinate, or -1.
/// The flat faces of CAD inputs lie on lattice-parallel planes, and their
/// edge points on such a plane are exactly coplanar: there the orientations
/// are exactly zero, which no filter decides (each one a multiprecision
/// evaluation).  Projected along that axis they are decided in 2D instead.
template <typename Point, std::size_t n>
int common_axis_plane(const std::array<const Point*, n>& p)
{
  for(int a = 0; a < 3; ++a)
  {
    bool same = true;
    for(std::size_t i = 1; i < n && same; ++i)
      same = (*p[i])[a] == (*p[0])[a];
    if(same)
      return a;
  }
  return -1;
}

/// The projection of `p` along `axis`: its two other coordinates, in cyclic
/// order.
template <typename Point>
Exact_predicates_inexact_constructions_kernel::Point_2 drop_axis(const Point& p, int axis)
{
  return {p[(axis + 1) % 3], p[(axis + 2) % 3]};
}

/// `CGAL::orientation(p, q, r, s)`; when p, q and r lie on a
/// lattice-parallel plane (and `use_axis_planes`), from the side of `s`
/// along that axis and the projected orientation of p, q, r (a comparison
/// and a 2D orientation, exact without a filter failing on the points of
/// that plane).
template <typename Point>
CGAL::Orientation orientation_3(const Point& p, const Point& q, const Point& r, const Point& s,
                                bool use_axis_planes = true)
{
  for(int a = 0; a < 3 && use_axis_planes; ++a)
    if(p[a] == q[a] && q[a] == r[a])
    {
      if(s[a] == p[a])
        return CGAL::COPLANAR;
      // det(q - p, r - p, s - p) = (s - p)[a] * the 2D determinant of the
      // two other coordinates taken in cyclic order.
      const CGAL::Orientation o = CGAL::orientation(drop_axis(p, a), drop_axis(q, a), drop_axis(r, a));
      return s[a] > p[a] ? o : CGAL::opposite(o);
    }
  return CGAL::orientation(p, q, r, s);
}

/// The orientation of `s` to the plane of triangle `t` (orientation_3()).
template <typename Point>
CGAL::Orientation orientation_to(const std::array<Point, 3>& t, const Point& s, bool use_axis_planes = true)
{
  return orientation_3(t[0], t[1], t[2], s, use_axis_planes);
}

/// Whether segment [c, d] meets the closed, non-degenerate triangle t, in
/// 2D: an endpoint in t, or the segment meets a side.  Orientations only
/// (CGAL 5.5's do_intersect() of a Segment_2 and a Triangle_2 clips with
/// constructed points, inexact on this kernel).
template <typename Point_2>
bool segment_meets_triangle_2(const Point_2& c, const Point_2& d, const std::array<Point_2, 3>& t)
{
  const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2]);
  const auto inside = [&](const Point_2& x) {
    for(int i = 0; i < 3; ++i)
      if(CGAL::orientation(t[i], t[(i + 1) % 3], x) == -o)
        return false;
    return true;
  };
  if(inside(c) || inside(d))
    return true;
  typedef Exact_predicates_inexact_constructions_kernel::Segment_2 Segment_2;
  const Segment_2 cd(c, d);
  for(int i = 0; i < 3; ++i)
    if(CGAL::do_intersect(cd, Segment_2(t[i], t[(i + 1) % 3])))
      return true;
  return false;
}

/// Whether segment [c, d] meets the closed triangle t (c and d strictly on
/// opposite sides of its plane: then it does iff the line cd passes the
/// triangle's three sides on one side; statically filtered orientations).
/// Otherwise CGAL's general test, in 2D when the five points lie on a
/// lattice-parallel plane (`use_axis_planes`).
template <typename Point>
bool segment_meets_triangle(const Point& c, const Point& d, const std::array<Point, 3>& t,
                            bool use_axis_planes = true)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  // Boxes apart (comparisons only): two thirds of the pairs of triangles
  // around a vertex of a Marching Cubes surface, before any orientation.
  if(!CGAL::do_overlap(c.bbox() + d.bbox(), t[0].bbox() + t[1].bbox() + t[2].bbox()))
    return false;
  if(use_axis_planes)
  {
    const int axis = common_axis_plane(std::array<const Point*, 5>{{&c, &d, &t[0], &t[1], &t[2]}});
    if(axis >= 0)
    {
      const std::array<K::Point_2, 3> triangle{{drop_axis(t[0], axis), drop_axis(t[1], axis), drop_axis(t[2], axis)}};
      return !CGAL::collinear(triangle[0], triangle[1], triangle[2]) &&
             segment_meets_triangle_2(drop_axis(c, axis), drop_axis(d, axis), triangle);
    }
  }
  const CGAL::Orientation oc = orientation_to(t, c, use_axis_planes), od = orientation_to(t, d, use_axis_planes);
  if(oc == od && oc != CGAL::COPLANAR)
    return false;
  if(oc == CGAL::COPLANAR || od == CGAL::COPLANAR)
  {
    const K::Triangle_3 triangle(t[0], t[1], t[2]);
    return !triangle.is_degenerate() && CGAL::do_intersect(K::Segment_3(c, d), triangle);
  }
  bool positive = false, negative = false;
  for(int i = 0; i < 3; ++i)
  {
    const CGAL::Orientation o = orientation_3(c, d, t[i], t[(i + 1) % 3], use_axis_planes);
    positive = positive || o == CGAL::POSITIVE;
    negative = negative || o == CGAL::NEGATIVE;
  }
  return !(positive && negative);
}

/// Whether triangles `a` and `b` (indices into `points`) have a common point
/// other than their shared vertices and edge, as `PMP::self_intersections()`
/// decides it: two triangles sharing an edge intersect iff they are coplanar
/// and on the same side of it; two sharing a vertex iff the side opposite it
/// in one meets the other triangle.  Exact predicates.  Like PMP's test, it
/// expects non-degenerate triangles (PMP reports a degenerate face apart, as
/// intersecting itself); here a degenerate triangle sharing no vertex meets
/// nothing.  Points on a common lattice-parallel plane are decided in 2D
/// (`use_axis_planes`; the same answers, `test_csg_features` compares them).
template <typename Triangle>
bool triangles_intersect(const std::vector<std::array<double, 3>>& points, const Triangle& a, const Triangle& b,
                         bool use_axis_planes = true)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  typedef K::Point_3 Point;
  const auto point = [&](std::size_t v) { return Point(points[v][0], points[v][1], points[v][2]); };
  const std::array<Point, 3> pa{{point(a[0]), point(a[1]), point(a[2])}};
  const std::array<Point, 3> pb{{point(b[0]), point(b[1]), point(b[2])}};
  int shared = 0;
  std::array<int, 3> in_b{{-1, -1, -1}}; // the corner of b at corner i of a
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      if(a[i] == b[j])
      {
        in_b[i] = j;
        ++shared;
      }
  if(shared == 3)
    return true; // the same triangle twice
  if(shared == 1)
  {
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    return segment_meets_triangle(pa[(i + 1) % 3], pa[(i + 2) % 3], pb, use_axis_planes) ||
           segment_meets_triangle(pb[(j + 1) % 3], pb[(j + 2) % 3], pa, use_axis_planes);
  }
  if(shared == 2)
  {
    const int i = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2); // a's corner off the shared edge
    int j = 0;
    while(b[j] == a[(i + 1) % 3] || b[j] == a[(i + 2) % 3])
      ++j;
    const Point &p = pa[(i + 1) % 3], &q = pa[(i + 2) % 3], &r = pa[i], &s = pb[j];
    const int axis = use_axis_planes ? common_axis_plane(std::array<const Point*, 4>{{&p, &q, &r, &s}}) : -1;
    if(axis >= 0)
    {
      // Coplanar; r and s on the same side of pq in the plane.
      const K::Point_2 p2 = drop_axis(p, axis), q2 = drop_axis(q, axis);
      const CGAL::Orientation o = CGAL::orientation(p2, q2, drop_axis(r, axis));
      return o != CGAL::COLLINEAR && CGAL::orientation(p2, q2, drop_axis(s, axis)) == o;
    }
    return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
  }
  // No shared vertex.
  if(use_axis_planes)
  {
    const int axis = common_axis_plane(
        std::array<const Point*, 6>{{&pa[0], &pa[1], &pa[2], &pb[0], &pb[1], &pb[2]}});
    if(axis >= 0)
    {
      const K::Triangle_2 ta(drop_axis(pa[0], axis), drop_axis(pa[1], axis), drop_axis(pa[2], axis));
      const K::Triangle_2 tb(drop_axis(pb[0], axis), drop_axis(pb[1], axis), drop_axis(pb[2], axis));
      return !ta.is_degenerate() && !tb.is_degenerate() && CGAL::do_intersect(ta, tb);
    }
  }
  // Apart if one lies strictly on one side of the other's plane (most
  // pairs), else CGAL's general test.
  const auto apart = [&](const std::array<Point, 3>& t, const std::array<Point, 3>& u) {
    const CGAL::Orientation o = orientation_to(t, u[0], use_axis_planes);
    return o != CGAL::COPLANAR && orientation_to(t, u[1], use_axis_planes) == o &&
           orientation_to(t, u[2], use_axis_planes) == o;
  };
  if(apart(pa, pb) || apart(pb, pa))
    return false;
  const K::Triangle_3 ta(pa[0], pa[1], pa[2]), tb(pb[0], pb[1], pb[2]);
  return !ta.is_degenerate() && !tb.is_degenerate() && CGAL::do_intersect(ta, tb);
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TRIANGLE_PAIR_INTERSECTION_H
