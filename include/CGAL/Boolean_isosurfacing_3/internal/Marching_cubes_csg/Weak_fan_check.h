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
// statically filtered orientations on the pairs whose boxes meet: about 10
// pairs a weak triangle, 0.4 us a pair, 10-20 ms on one thread for the
// moved copies at 128 cells (3,000-4,500 weak triangles).

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

/// Whether segment [c, d] meets the closed triangle t (c and d strictly on
/// opposite sides of its plane: then it does iff the line cd passes the
/// triangle's three sides on one side; statically filtered orientations).
/// Otherwise CGAL's general test.
template <typename Point>
bool segment_meets_triangle(const Point& c, const Point& d, const std::array<Point, 3>& t)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  const CGAL::Orientation oc = CGAL::orientation(t[0], t[1], t[2], c), od = CGAL::orientation(t[0], t[1], t[2], d);
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
    const CGAL::Orientation o = CGAL::orientation(c, d, t[i], t[(i + 1) % 3]);
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
template <typename Triangle>
bool triangles_intersect(const std::vector<std::array<double, 3>>& points, const Triangle& a, const Triangle& b)
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
    return segment_meets_triangle(pa[(i + 1) % 3], pa[(i + 2) % 3], pb) ||
           segment_meets_triangle(pb[(j + 1) % 3], pb[(j + 2) % 3], pa);
  }
  if(shared == 2)
  {
    const int i = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2); // a's corner off the shared edge
    int j = 0;
    while(b[j] == a[(i + 1) % 3] || b[j] == a[(i + 2) % 3])
      ++j;
    const Point &p = pa[(i + 1) % 3], &q = pa[(i + 2) % 3], &r = pa[i], &s = pb[j];
    return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
  }
  // No shared vertex: apart if one lies strictly on one side of the
  // other's plane (most pairs), else CGAL's general test.
  const auto apart = [](const std::array<Point, 3>& t, const std::array<Point, 3>& u) {
    const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2], u[0]);
    return o != CGAL::COPLANAR && CGAL::orientation(t[0], t[1], t[2], u[1]) == o &&
           CGAL::orientation(t[0], t[1], t[2], u[2]) == o;
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
  const double cell_size = lattice.spacing() * double(b);
  const auto cell_of = [&](int a, double x) {
    const double c = std::floor((x - origin[a]) / cell_size);
    return c >= 0 ? std::size_t((std::min)(c, double(cells[a] - 1))) : std::size_t(0);
  };
  const auto box_of = [&](const Triangle& t) {
    const std::array<double, 3>&p = points[std::size_t(t[0])], &q = points[std::size_t(t[1])],
                                &r = points[std::size_t(t[2])];
    return CGAL::Bbox_3((std::min)({p[0], q[0], r[0]}), (std::min)({p[1], q[1], r[1]}), (std::min)({p[2], q[2], r[2]}),
                        (std::max)({p[0], q[0], r[0]}), (std::max)({p[1], q[1], r[1]}), (std::max)({p[2], q[2], r[2]}));
  };
  const auto for_each_cell = [&](const CGAL::Bbox_3& box, const auto& f) {
    const std::array<std::size_t, 3> lo{{cell_of(0, box.xmin()), cell_of(1, box.ymin()), cell_of(2, box.zmin())}};
    const std::array<std::size_t, 3> hi{{cell_of(0, box.xmax()), cell_of(1, box.ymax()), cell_of(2, box.zmax())}};
    for(std::size_t k = lo[2]; k <= hi[2]; ++k)
      for(std::size_t j = lo[1]; j <= hi[1]; ++j)
        for(std::size_t i = lo[0]; i <= hi[0]; ++i)
          f(i + cells[0] * (j + cells[1] * k), std::array<std::size_t, 3>{{i, j, k}});
  };

  std::vector<std::size_t> weak_triangles;
  std::vector<CGAL::Bbox_3> weak_boxes;
  std::vector<std::pair<std::size_t, std::uint32_t>> listed; // (cell, index into weak_triangles)
  std::vector<bool> marked(cells[0] * cells[1] * cells[2], false);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    if(is_weak(triangles[t]))
    {
      const std::uint32_t w = std::uint32_t(weak_triangles.size());
      weak_triangles.push_back(t);
      weak_boxes.push_back(box_of(triangles[t]));
      for_each_cell(weak_boxes.back(), [&](std::size_t cell, const std::array<std::size_t, 3>&) {
        listed.emplace_back(cell, w);
        marked[cell] = true;
      });
    }
  if(weak_triangles.empty())
    return cubes;
  std::sort(listed.begin(), listed.end());

  // Ranges of triangles in parallel; the cubes found do not depend on the
  // concurrency (they are sorted at the end).
  const std::size_t ranges = 64;
  std::vector<std::vector<std::uint64_t>> found(ranges);
  concurrent_for<ConcurrencyTag>(ranges, [&](std::size_t range) {
    for(std::size_t t = triangles.size() * range / ranges; t < triangles.size() * (range + 1) / ranges; ++t)
    {
      const CGAL::Bbox_3 box = box_of(triangles[t]);
      const bool t_is_weak = is_weak(triangles[t]);
      for_each_cell(box, [&](std::size_t cell, const std::array<std::size_t, 3>& ijk) {
        if(!marked[cell])
          return;
        auto it = std::lower_bound(listed.begin(), listed.end(), std::make_pair(cell, std::uint32_t(0)));
        for(; it != listed.end() && it->first == cell; ++it)
        {
          const std::size_t u = weak_triangles[it->second];
          // A pair of weak triangles once, from the higher one.
          if(u == t || (t_is_weak && u > t))
            continue;
          const CGAL::Bbox_3& other = weak_boxes[it->second];
          if(!CGAL::do_overlap(box, other))
            continue;
          bool lowest = true;
          for(int a = 0; a < 3; ++a)
            lowest = lowest && cell_of(a, (std::max)(box.min(a), other.min(a))) == ijk[a];
          if(!lowest || !triangles_intersect(points, triangles[t], triangles[u]))
            continue;
          for(const std::size_t x : {t, u})
            for(int c = 0; c < 3; ++c)
              if(const std::uint64_t cube = weak(std::size_t(triangles[x][c])))
                found[range].push_back(cube - 1);
        }
      });
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
