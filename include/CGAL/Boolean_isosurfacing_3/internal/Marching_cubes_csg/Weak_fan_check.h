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
// Cost: two passes over the triangles (marking the lattice cells the weak
// ones meet, then listing every triangle in the marked cells its box meets:
// Overlapping_triangle_pairs.h), and the exact pair test of
// Triangle_pair_intersection.h on the pairs whose boxes meet, one of them
// weak: about 10 pairs a weak triangle, 9-16 ms on one thread for the
// moved copies at 128 cells (2,500-3,500 weak triangles).

#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Overlapping_triangle_pairs.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Triangle_pair_intersection.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

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
  // keeps the grid within its cell limit); only the cells a weak triangle
  // meets are stored and listed.  (With a dense grid's 2^26 cells, b was 64
  // on a thin shell at 65536 cells, and the cells of 64^2 surface squares
  // made the check 80 % of a 260 s run.)
  Triangle_grid_3 grid;
  std::size_t b = 1;
  for(;;)
  {
    for(int a = 0; a < 3; ++a)
      grid.cells[a] = std::uint32_t((lattice.number_of_points(a) + b - 1) / b + 1);
    if(double(grid.cells[0]) * double(grid.cells[1]) * double(grid.cells[2]) <=
       double(Triangle_grid_3::max_sparse_cells))
      break;
    b *= 2;
  }
  for(int a = 0; a < 3; ++a)
    grid.origin[a] = lattice.coordinate(a, 0);
  grid.inverse_cell_size = 1 / (lattice.spacing() * double(b));

  // The found cubes do not depend on the concurrency (sorted at the end).
  std::vector<std::vector<std::uint64_t>> found(overlapping_pair_parts);
  const std::size_t unlimited = std::size_t(-1);
  const bool decided = for_each_overlapping_triangle_pair<ConcurrencyTag>(
      points, triangles, grid, false, [&](std::size_t t) { return is_weak(triangles[t]); }, unlimited, unlimited,
      [&](std::size_t part, std::size_t t, std::size_t u) {
        if(triangles_intersect(points, triangles[t], triangles[u]))
          for(const std::size_t x : {t, u})
            for(int v = 0; v < 3; ++v)
              if(const std::uint64_t cube = weak(std::size_t(triangles[x][v])))
                found[part].push_back(cube - 1);
        return false;
      });
  if(!decided) // 2^32 marked cells or more: unchecked, so none of the weak fans is kept
    for(const std::array<std::uint64_t, 2>& w : weak_fans)
      cubes.push_back(w[1]);
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
