// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EMBEDDED_VERTEX_STARS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EMBEDDED_VERTEX_STARS_H

// Which vertices of a triangle soup have an embedded star: the triangles
// around the vertex meet only in the vertex and their shared edges, so no
// pair of them intersects (in the sense of triangles_intersect()).  Most
// pairs of overlapping boxes in a self-intersection test share a vertex
// (7.8M of 12.0M on a 1.6M-triangle Marching Cubes surface, and 2.4M more
// share an edge); one certificate a vertex settles them all.
//
// The certificate is exact and needs no construction: the star is projected
// along a coordinate axis (dropping a coordinate is exact) and is embedded
// in 3D if the projection is one-to-one, that is if
// - every projected triangle (v, a, b) has the same nonzero orientation
//   (each is the image of its triangle one to one), and
// - the sectors a -> b follow each other around v in one cycle through all
//   of them, and that cycle turns once around v, not twice or more (counted
//   exactly, by the sectors that cross the ray from v along the first
//   projected axis).
// Then the projected triangles tile a neighbourhood of v's image, two of
// them overlapping only on a common side v-a; a common point of the two
// triangles in 3D projects onto such an overlap, and its only preimage in
// either triangle is on their common vertex or edge.  A star that fails on
// every axis (a fan folded over itself, a sharp cone, a degenerate or
// non-manifold fan) is simply not certified: its pairs are tested one by one.

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// The triangles around each vertex: `triangles_of(v)` lists (by index) the
/// triangles that have `v` as a corner, in increasing order.  Compressed
/// rows, built by one counting sort.
class Vertex_triangle_incidences
{
public:
  template <typename Triangle>
  Vertex_triangle_incidences(std::size_t number_of_vertices, const std::vector<Triangle>& triangles)
      : m_first(number_of_vertices + 1, 0), m_triangles(3 * triangles.size())
  {
    for(const Triangle& t : triangles)
      for(int i = 0; i < 3; ++i)
        ++m_first[std::size_t(t[i]) + 1];
    for(std::size_t v = 0; v < number_of_vertices; ++v)
      m_first[v + 1] += m_first[v];
    std::vector<std::size_t> next(m_first.begin(), m_first.end() - 1);
    for(std::size_t t = 0; t < triangles.size(); ++t)
      for(int i = 0; i < 3; ++i)
        m_triangles[next[std::size_t(triangles[t][i])]++] = std::uint32_t(t);
  }

  std::size_t number_of_vertices() const { return m_first.size() - 1; }
  const std::uint32_t* begin(std::size_t v) const { return m_triangles.data() + m_first[v]; }
  const std::uint32_t* end(std::size_t v) const { return m_triangles.data() + m_first[v + 1]; }

private:
  std::vector<std::size_t> m_first; // 3 n may exceed 32 bits
  std::vector<std::uint32_t, Default_init_allocator<std::uint32_t>> m_triangles;
};

/// Whether the star of `v` (the triangles `star_begin` to `star_end`, each
/// having `v` as a corner) projects one to one along `axis`, which certifies
/// it embedded (see above).  Stars of more than 32 triangles are not
/// certified.
template <typename Triangle>
bool star_projects_one_to_one(const std::vector<std::array<double, 3>>& points,
                              const std::vector<Triangle>& triangles, std::size_t v, const std::uint32_t* star_begin,
                              const std::uint32_t* star_end, int axis)
{
  typedef Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  constexpr std::size_t max_star = 32;
  const std::size_t n = std::size_t(star_end - star_begin);
  if(n < 3 || n > max_star)
    return false;
  const int x = (axis + 1) % 3, y = (axis + 2) % 3; // cyclic: orientations keep their sign
  const Point_2 centre(points[v][x], points[v][y]);
  // Whether p is on the half-open upper side of the ray from the centre
  // along x: angles in [0, pi).
  const auto upper = [&](const Point_2& p) {
    return p.y() > centre.y() || (p.y() == centre.y() && p.x() > centre.x());
  };
  std::array<std::size_t, max_star> from, to;
  CGAL::Orientation turn = CGAL::COLLINEAR;
  int crossings = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Triangle& t = triangles[star_begin[i]];
    const int c = std::size_t(t[0]) == v ? 0 : (std::size_t(t[1]) == v ? 1 : 2);
    from[i] = std::size_t(t[(c + 1) % 3]);
    to[i] = std::size_t(t[(c + 2) % 3]);
    const std::array<double, 3>&a = points[from[i]], &b = points[to[i]];
    const Point_2 pa(a[x], a[y]), pb(b[x], b[y]);
    const CGAL::Orientation o = CGAL::orientation(centre, pa, pb);
    if(o == CGAL::COLLINEAR || (i > 0 && o != turn))
      return false;
    turn = o;
    // A sector (less than pi) crosses the ray once as it turns past it: from
    // the lower to the upper side counterclockwise, the other way clockwise.
    const bool ua = upper(pa), ub = upper(pb);
    if(ua != ub && ub == (o == CGAL::LEFT_TURN))
      ++crossings;
  }
  if(crossings != 1)
    return false;
  // One cycle through all the sectors, each starting where the last ended
  // (else, not certified: a fan whose sides do not pair up is no star).
  std::size_t length = 1;
  for(std::size_t end = to[0]; end != from[0]; ++length)
  {
    std::size_t next = 1;
    while(next < n && from[next] != end)
      ++next;
    if(next == n || length == n)
      return false;
    end = to[next];
  }
  return length == n;
}

/// For each vertex of the soup, whether its star is certified embedded by a
/// one-to-one projection along some axis (the axis of the largest component
/// of the star's area vector first).  A vertex in no triangle is not.
template <typename ConcurrencyTag, typename Triangle>
std::vector<char> vertices_with_embedded_stars(const std::vector<std::array<double, 3>>& points,
                                               const std::vector<Triangle>& triangles,
                                               const Vertex_triangle_incidences& stars)
{
  std::vector<char> embedded(points.size(), 0);
  concurrent_for_blocks<ConcurrencyTag>(points.size(), 4096, [&](std::size_t first, std::size_t last) {
    for(std::size_t v = first; v < last; ++v)
    {
      const std::uint32_t *begin = stars.begin(v), *end = stars.end(v);
      // The area vector, in double: it only orders the axes to try.
      std::array<double, 3> area{{0, 0, 0}};
      for(const std::uint32_t* t = begin; t != end; ++t)
      {
        const std::array<double, 3>&p = points[std::size_t(triangles[*t][0])],
                                    &q = points[std::size_t(triangles[*t][1])],
                                    &r = points[std::size_t(triangles[*t][2])];
        const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        area[0] += u[1] * w[2] - u[2] * w[1];
        area[1] += u[2] * w[0] - u[0] * w[2];
        area[2] += u[0] * w[1] - u[1] * w[0];
      }
      std::array<int, 3> axes{{0, 1, 2}};
      std::sort(axes.begin(), axes.end(),
                [&](int a, int b) { return std::abs(area[a]) > std::abs(area[b]); });
      for(const int axis : axes)
        if(star_projects_one_to_one(points, triangles, v, begin, end, axis))
        {
          embedded[v] = 1;
          break;
        }
    }
  });
  return embedded;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EMBEDDED_VERTEX_STARS_H
