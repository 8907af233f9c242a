// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DOES_TRIANGLE_SOUP_SELF_INTERSECT_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DOES_TRIANGLE_SOUP_SELF_INTERSECT_H

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Embedded_vertex_stars.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Overlapping_triangle_pairs.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Triangle_pair_intersection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// Whether a triangle soup intersects itself, as `PMP::does_self_intersect()`
/// decides it on the mesh made of the soup: a degenerate triangle intersects
/// itself; two triangles intersect if they have a common point other than
/// their shared vertices and edge (triangles_intersect()).  The soup must be
/// one in which two triangles share a vertex or an edge by index exactly
/// when their faces do in that mesh: a 2-manifold soup
/// (check_manifold_vertices()), whose triangles around a vertex form one fan.
///
/// The pairs of overlapping boxes are found on a grid of cells three times
/// the mean triangle's box (for_each_overlapping_triangle_pair()); no mesh is
/// built.  A pair that shares a vertex whose star is certified embedded
/// (vertices_with_embedded_stars(): 85 % of the pairs on Marching Cubes
/// output) is not tested.  `std::nullopt` when the triangles are too unevenly sized for that
/// grid (the caller asks PMP on a mesh).  Stops at the first intersection.
template <typename ConcurrencyTag, typename Triangle>
std::optional<bool> does_triangle_soup_self_intersect(const std::vector<std::array<double, 3>>& points,
                                                      const std::vector<Triangle>& triangles)
{
  typedef Exact_predicates_inexact_constructions_kernel::Point_3 Point;
  if(triangles.empty())
    return false;
  if(triangles.size() > (std::size_t(1) << 32))
    return std::nullopt;
  const auto point = [&](std::size_t v) { return Point(points[v][0], points[v][1], points[v][2]); };

  std::atomic<bool> degenerate(false);
  const std::size_t parts = overlapping_pair_parts;
  concurrent_for<ConcurrencyTag>(parts, [&](std::size_t part) {
    for(std::size_t t = triangles.size() * part / parts;
        t < triangles.size() * (part + 1) / parts && !degenerate.load(std::memory_order_relaxed); ++t)
      if(CGAL::collinear(point(triangles[t][0]), point(triangles[t][1]), point(triangles[t][2])))
        degenerate = true;
  });
  if(degenerate)
    return true;

  // The grid: the soup's box in cells three times the mean of the
  // triangles' longest box sides (a triangle meets about 2.4 cells; cells of
  // twice the mean were 8 % slower on 1.6M triangles, four times no faster),
  // coarser if that is more cells than the grid allows.
  CGAL::Bbox_3 box;
  double extents = 0;
  for(const Triangle& t : triangles)
  {
    CGAL::Bbox_3 b;
    for(int v = 0; v < 3; ++v)
    {
      const std::array<double, 3>& p = points[std::size_t(t[v])];
      b += CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
    }
    extents += (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
    box += b;
  }
  double cell_size = 3 * extents / double(triangles.size());
  // Coordinates near the largest double overflow the extents or the box's
  // sides to infinity: no grid, PMP (whose exact predicates do not overflow).
  for(int a = 0; a < 3; ++a)
    if(!std::isfinite(box.max(a) - box.min(a)))
      return std::nullopt;
  if(!std::isfinite(cell_size))
    return std::nullopt;
  while(Triangle_grid_3::number_of_cells_covering(box, cell_size) > double(Triangle_grid_3::max_cells))
    cell_size *= 1.25;
  const Triangle_grid_3 grid = Triangle_grid_3::covering(box, cell_size);

  // Each vertex whose star is embedded settles every pair around it.
  std::vector<char> embedded;
  {
    const Vertex_triangle_incidences stars(points.size(), triangles);
    embedded = vertices_with_embedded_stars<ConcurrencyTag>(points, triangles, stars);
  }
  const auto share_an_embedded_star = [&](const Triangle& a, const Triangle& b) {
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        if(a[i] == b[j] && embedded[std::size_t(a[i])])
          return true;
    return false;
  };

  // Budgets well above what triangles of about a cell need (3-4 listings
  // and a few tens of pairs of boxes a triangle).
  const std::size_t n = triangles.size();
  std::atomic<bool> found(false);
  const bool decided = for_each_overlapping_triangle_pair<ConcurrencyTag>(
      points, triangles, grid, true, [](std::size_t) { return true; }, 16 * n + 4096, 128 * n + (std::size_t(1) << 20),
      [&](std::size_t, std::size_t t, std::size_t u) {
        if(share_an_embedded_star(triangles[t], triangles[u]) || !triangles_intersect(points, triangles[t], triangles[u]))
          return false;
        found = true;
        return true;
      });
  if(!decided)
    return std::nullopt;
  return found.load();
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_DOES_TRIANGLE_SOUP_SELF_INTERSECT_H
