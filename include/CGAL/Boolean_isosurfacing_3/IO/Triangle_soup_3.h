// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIANGLE_SOUP_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIANGLE_SOUP_3_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * A triangle soup in flat arrays: what the package's mesh readers produce
 * (`IO::read_triangle_soup()`) and its writers consume.  Points are doubles,
 * triangles are triples of 0-based indices into `points`, so the whole soup
 * is two contiguous allocations that a loop streams through.
 *
 * The readers fill the two counters so that a tool can say what it did to
 * the file's content: polygons with more than 3 vertices are split into
 * triangles (a fan from their first vertex), and STL's per-facet corners are
 * welded into shared points by exact coordinate equality.
 */
struct Triangle_soup_3
{
  typedef std::array<double, 3> Point;
  typedef std::array<std::uint32_t, 3> Triangle;

  std::vector<Point> points;
  std::vector<Triangle> triangles;
  /// The number of input polygons with more than 3 vertices that were
  /// split into triangles (each adds `size - 2` triangles).
  std::size_t triangulated_polygons = 0;
  /// STL only: the number of facet corners before welding (3 per facet).
  std::size_t unwelded_corners = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIANGLE_SOUP_3_H
