// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_WEAK_FAN_CHECK_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_WEAK_FAN_CHECK_H

// The check that makes the weaker fold test (`Fold_test::SUM`) safe: the
// triangles around the feature vertices whose fans only that test accepted
// ("weak" fans) are intersected with every triangle near them, on the
// finished output (after the flips and the collapses, which may have
// changed those triangles).  The cubes of the weak fans in an intersecting
// pair are returned; `marching_cubes_csg()` runs again with the strict test
// there.  The other triangles are not checked: they come out of the strict
// test as before (features.md, "Why the guarantees stay").
//
// Cost: two passes over the triangles (the weak ones, then every triangle
// against the weak ones listed in the lattice cells its box meets), and
// statically filtered orientations on the pairs whose boxes meet (in 2D
// where the points share a lattice plane): about 10 pairs a weak triangle,
// 9-16 ms on one thread for the moved copies at 128 cells (2,500-3,500
// weak triangles).

#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

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
/// in one meets the other triangle.  Exact predicates; a degenerate triangle
/// sharing no vertex meets nothing (the output has none: `test_csg_features`).
/// Points on a common lattice-parallel plane are decided in 2D
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

/// The cubes (sorted, distinct) of the weak fans whose triangles intersect
/// another triangle of the output.  `weak_fans` lists (f, cube id): the fan
/// of feature vertex `first_feature_vertex + f` is weak.  The output's
/// points lie in the lattice's box (cells outside it are clamped to the
/// border ones).
template <typename ConcurrencyTag, typename Triangle>
std::vector<std::uint64_t> cubes_of_intersecting_weak_fans(const std::vector<std::array<double, 3>>& points,
                                                           const std::vector<Triangle>& triangles,
                                                           std::size_t first_feature_vertex,
                                                           const std::vector<std::array<std::uint64_t, 2>>& weak_fans,
                                                           const Regular_lattice_3& lattice)
{
  std::vector<std::uint64_t> cubes;
  if(weak_fans.empty() || first_feature_vertex > points.size())
    return cubes;
  // The cube id plus one of each feature vertex, 0 if its fan is not weak.
  std::vector<std::uint64_t> weak_cube(points.size() - first_feature_vertex, 0);
  for(const std::array<std::uint64_t, 2>& w : weak_fans)
    if(w[0] < weak_cube.size())
      weak_cube[std::size_t(w[0])] = w[1] + 1;
  const auto weak = [&](std::size_t v) -> std::uint64_t {
    return v >= first_feature_vertex && v - first_feature_vertex < weak_cube.size()
               ? weak_cube[v - first_feature_vertex]
               : 0;
  };
  const auto is_weak = [&](const Triangle& t) {
    return weak(std::size_t(t[0])) != 0 || weak(std::size_t(t[1])) != 0 || weak(std::size_t(t[2])) != 0;
  };

  // A grid of cells of b^3 lattice cubes (b = 1, or the power of two that
  // keeps its bitmap within 2^26 bits).  The weak triangles are listed in
  // the cells their boxes meet; every triangle is compared with the weak
  // triangles listed in the cells its box meets, in the one cell that holds
  // the lowest corner of the two boxes' intersection (each pair once).
  // (CGAL's box_intersection_d() took 5-20 ms here at 128 cells, as long as
  // the whole feature triangulation: the triangles are all about a cell.)
  std::array<double, 3> origin;
  std::array<std::size_t, 3> cells;
  std::size_t b = 1;
  for(;;)
  {
    for(int a = 0; a < 3; ++a)
      cells[a] = (lattice.number_of_points(a) + b - 1) / b + 1;
    if(double(cells[0]) * double(cells[1]) * double(cells[2]) <= double(std::size_t(1) << 26))
      break;
    b *= 2;
  }
  for(int a = 0; a < 3; ++a)
    origin[a] = lattice.coordinate(a, 0);
  // Any nondecreasing map of a coordinate to its cell finds each pair once
  // (the cell of the larger of two lower bounds is the larger of their
  // cells): a product, not a division.
  const double inverse_cell_size = 1 / (lattice.spacing() * double(b));
  const auto cell_of = [&](int a, double x) {
    const double c = std::floor((x - origin[a]) * inverse_cell_size);
    return c >= 0 ? std::uint32_t((std::min)(c, double(cells[a] - 1))) : std::uint32_t(0);
  };
  struct Cell_box
  {
    CGAL::Bbox_3 box;
    std::array<std::uint32_t, 3> lo, hi; // its cells
  };
  const auto cell_box_of = [&](const Triangle& t) {
    const std::array<double, 3>&p = points[std::size_t(t[0])], &q = points[std::size_t(t[1])],
                                &r = points[std::size_t(t[2])];
    Cell_box c;
    c.box = CGAL::Bbox_3((std::min)({p[0], q[0], r[0]}), (std::min)({p[1], q[1], r[1]}), (std::min)({p[2], q[2], r[2]}),
                         (std::max)({p[0], q[0], r[0]}), (std::max)({p[1], q[1], r[1]}), (std::max)({p[2], q[2], r[2]}));
    for(int a = 0; a < 3; ++a)
    {
      c.lo[a] = cell_of(a, c.box.min(a));
      c.hi[a] = cell_of(a, c.box.max(a));
    }
    return c;
  };
  const auto cell_index = [&](std::size_t i, std::size_t j, std::size_t k) {
    return i + cells[0] * (j + cells[1] * k);
  };

  // The weak triangles, and for each cell their list (sorted cell ids,
  // offsets, members: one binary search a marked cell).
  std::vector<std::size_t> weak_triangles;
  std::vector<Cell_box> weak_boxes;
  std::vector<std::pair<std::size_t, std::uint32_t>> listed; // (cell, index into weak_triangles)
  std::vector<bool> marked(cells[0] * cells[1] * cells[2], false);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    if(is_weak(triangles[t]))
    {
      const std::uint32_t w = std::uint32_t(weak_triangles.size());
      weak_triangles.push_back(t);
      weak_boxes.push_back(cell_box_of(triangles[t]));
      const Cell_box& c = weak_boxes.back();
      for(std::size_t k = c.lo[2]; k <= c.hi[2]; ++k)
        for(std::size_t j = c.lo[1]; j <= c.hi[1]; ++j)
          for(std::size_t i = c.lo[0]; i <= c.hi[0]; ++i)
          {
            listed.emplace_back(cell_index(i, j, k), w);
            marked[listed.back().first] = true;
          }
    }
  if(weak_triangles.empty())
    return cubes;
  std::sort(listed.begin(), listed.end());
  std::vector<std::size_t> listed_cells;
  std::vector<std::uint32_t> first_listed, members(listed.size());
  for(std::size_t l = 0; l < listed.size(); ++l)
  {
    if(l == 0 || listed[l].first != listed[l - 1].first)
    {
      listed_cells.push_back(listed[l].first);
      first_listed.push_back(std::uint32_t(l));
    }
    members[l] = listed[l].second;
  }
  first_listed.push_back(std::uint32_t(listed.size()));
  std::vector<std::pair<std::size_t, std::uint32_t>>().swap(listed);

  // Ranges of triangles in parallel; the cubes found do not depend on the
  // concurrency (they are sorted at the end).
  const std::size_t ranges = 64;
  std::vector<std::vector<std::uint64_t>> found(ranges);
  concurrent_for<ConcurrencyTag>(ranges, [&](std::size_t range) {
    for(std::size_t t = triangles.size() * range / ranges; t < triangles.size() * (range + 1) / ranges; ++t)
    {
      const Cell_box c = cell_box_of(triangles[t]);
      const bool t_is_weak = is_weak(triangles[t]);
      for(std::size_t k = c.lo[2]; k <= c.hi[2]; ++k)
        for(std::size_t j = c.lo[1]; j <= c.hi[1]; ++j)
          for(std::size_t i = c.lo[0]; i <= c.hi[0]; ++i)
          {
            const std::size_t cell = cell_index(i, j, k);
            if(!marked[cell])
              continue;
            const std::size_t slot =
                std::size_t(std::lower_bound(listed_cells.begin(), listed_cells.end(), cell) - listed_cells.begin());
            for(std::uint32_t l = first_listed[slot]; l < first_listed[slot + 1]; ++l)
            {
              const std::size_t u = weak_triangles[members[l]];
              // A pair of weak triangles once, from the higher one.
              if(u == t || (t_is_weak && u > t))
                continue;
              const Cell_box& other = weak_boxes[members[l]];
              if(!CGAL::do_overlap(c.box, other.box) || (std::max)(c.lo[0], other.lo[0]) != i ||
                 (std::max)(c.lo[1], other.lo[1]) != j || (std::max)(c.lo[2], other.lo[2]) != k ||
                 !triangles_intersect(points, triangles[t], triangles[u]))
                continue;
              for(const std::size_t x : {t, u})
                for(int v = 0; v < 3; ++v)
                  if(const std::uint64_t cube = weak(std::size_t(triangles[x][v])))
                    found[range].push_back(cube - 1);
            }
          }
    }
  });
  for(const std::vector<std::uint64_t>& f : found)
    cubes.insert(cubes.end(), f.begin(), f.end());
  std::sort(cubes.begin(), cubes.end());
  cubes.erase(std::unique(cubes.begin(), cubes.end()), cubes.end());
  return cubes;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_WEAK_FAN_CHECK_H
