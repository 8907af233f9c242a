// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_SLIVER_FLIPS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_SLIVER_FLIPS_H

// The slivers an edge collapse cannot remove: "caps" (a vertex next to the
// middle of the opposite side, from an edge point near a lattice point on a
// face) and needles whose short edge ends at a feature vertex.  Lawson's
// edge flips (flip an edge whose two opposite angles add up to more than
// 180 degrees) remove them where the two triangles are nearly coplanar, so
// that the surface barely moves:
//  - the new edge must not exist yet (the flip keeps a closed 2-manifold);
//  - the edge is not a crease edge and the two triangles' normals differ by
//    less than `max_dihedral` (no flip across a feature), unless one of
//    them has an angle below `unreliable_normal_angle`: the normal of such
//    a sliver says little about the surface (a cap next to a crease stands
//    at any angle to its neighbour), and the deviation bound below still
//    holds;
//  - the two diagonals are closer than `max_deviation` (the surface moves by
//    at most that much), and both new triangles keep the orientation of the
//    old ones (the quadrilateral is convex seen along its normal);
//  - the smallest angle of the two triangles increases.
// The flips are done from a work list seeded with the edges of the
// triangles whose smallest angle is below `seed_angle`, in a deterministic
// order, with at most `4 * triangles` flips, on a corner table (the
// opposite corner of each corner: 4 bytes per corner).

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

/// The cosine of the smallest angle of the triangle abc (1 if degenerate).
inline double largest_cosine(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const Vector_3d p[3] = {a, b, c};
  double best = -1;
  for(int i = 0; i < 3; ++i)
  {
    const Vector_3d u = sub3(p[(i + 1) % 3], p[i]), v = sub3(p[(i + 2) % 3], p[i]);
    const double l = dot3(u, u) * dot3(v, v);
    if(!(l > 0))
      return 1;
    best = (std::max)(best, dot3(u, v) / std::sqrt(l));
  }
  return best;
}

/// Whether the smallest angle of the triangle abc is below the angle whose
/// cosine is `cos_angle` (in (0, 1)), or abc is degenerate: the cosine of
/// the angle opposite the shortest side, by the law of cosines on squared
/// lengths (no square root: this tests every triangle of the output).
inline bool has_angle_below(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c, double cos_angle)
{
  const Vector_3d ab = sub3(b, a), bc = sub3(c, b), ca = sub3(a, c);
  double s = dot3(ab, ab), p = dot3(bc, bc), q = dot3(ca, ca);
  if(p < s)
    std::swap(p, s);
  if(q < s)
    std::swap(q, s);
  if(!(s > 0))
    return true;
  // cos = (p + q - s) / (2 sqrt(p q)), and p + q - s >= p > 0.
  const double n = p + q - s;
  return n * n > 4 * cos_angle * cos_angle * p * q;
}

/// Parameters of `flip_slivers()`.
struct Sliver_flip_settings
{
  double max_deviation = 0;                 // length
  double cos_max_dihedral = 0.9396926207859084; // 20 degrees
  double seed_angle = 0.3490658503988659;   // 20 degrees, in radians
  double unreliable_normal_angle = 0.08726646259971647; // 5 degrees, in radians
};

/// The opposite corner of every corner of a closed, oriented triangle soup
/// (corner `3t + i` is vertex `i` of triangle `t`; the corner opposite it
/// is the corner, in the neighbouring triangle, facing the same edge), or
/// false if the soup is not a closed, consistently oriented 2-manifold.
/// A corner table is 3 indices per triangle: the hash table of edges it
/// replaces needed about 48 bytes per edge (4.7 GB at 2048 cells).  The
/// vertices' corner lists it is built from take about `max_star_corners`
/// entries at a time (ranges of a power of two vertices), the ranges in
/// parallel with `Parallel_tag`.  By default (0): up to 2^21 corners (about
/// 700K triangles), one range (each range reads the triangles of its window
/// twice, and the feature vertices' window is all of them: armadillo united
/// with a copy at 128 cells, 0.5 ms less than ranges of 2^16 corners);
/// above, 2^16 entries or 1/128 of the corners, whichever is more, so that
/// the lists of the ranges in work add little to the table at the memory
/// peak of the feature path (1/32 was 60 MB more at 2048 cells on two
/// threads).  With `with_border`, a part of a closed soup is accepted: an
/// edge in one triangle only (the part's border) faces `Index(-1)`.
template <typename ConcurrencyTag = Sequential_tag, typename Index, typename Triangle>
bool opposite_corners(std::size_t number_of_points, const std::vector<Triangle>& triangles, std::vector<Index>& opposite,
                      std::size_t max_star_corners = 0, bool with_border = false)
{
  const std::size_t corners = 3 * triangles.size();
  if(max_star_corners == 0)
    max_star_corners = corners <= (std::size_t(1) << 21) ? 2 * corners // one range: 2^shift > points below
                                                         : (std::max)(std::size_t(1) << 16, corners / 128);
  const Index none = Index(-1);
  const auto next = [](std::size_t c) { return c - c % 3 + (c + 1) % 3; };
  const auto previous = [](std::size_t c) { return c - c % 3 + (c + 2) % 3; };
  opposite.assign(corners, none);
  // The corners of each vertex (compressed rows), built for one range of
  // 2^shift vertices at a time: the rows of all vertices at once would be
  // another 12 bytes a corner at the memory peak of the feature path.  The
  // ranges only change the order of the work, not the table.  Each range
  // reads only the triangles from the first to the last that has a vertex
  // in it: the vertices of Marching Cubes are numbered plane by plane and
  // its triangles layer by layer, so that window is narrow for all but the
  // few feature vertices, appended at the end.
  unsigned shift = 0;
  while(shift < 40 && (std::size_t(2) << shift) * corners <= max_star_corners * number_of_points)
    ++shift;
  const std::size_t ranges = (number_of_points >> shift) + 1;
  std::vector<std::size_t> window_begin(ranges, triangles.size()), window_end(ranges, 0);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(std::size_t v : triangles[t])
    {
      if(v >= number_of_points)
        return false;
      const std::size_t r = v >> shift;
      window_begin[r] = (std::min)(window_begin[r], t);
      window_end[r] = t + 1;
    }
  std::atomic<bool> manifold(true);
  concurrent_for<ConcurrencyTag>(ranges, [&](std::size_t r) {
    const std::size_t low = r << shift, high = (std::min)(number_of_points, (r + 1) << shift);
    if(window_begin[r] >= window_end[r] || !manifold)
      return; // no triangle has a vertex in this range, or no table
    std::vector<Index> first(high - low + 1, 0);
    for(std::size_t t = window_begin[r]; t < window_end[r]; ++t)
      for(std::size_t v : triangles[t])
        if(v >= low && v < high)
          ++first[v - low + 1];
    for(std::size_t v = 0; v < high - low; ++v)
      first[v + 1] += first[v];
    // Each entry of v's star is a corner of v with the vertices after and
    // before v in its triangle, written while the triangles are read in
    // order: the matching below then reads no triangle.
    struct Star_corner
    {
      Index corner, after, before;
    };
    std::vector<Star_corner> star(first.back());
    std::vector<Index> fill(first.begin(), first.end() - 1);
    for(std::size_t t = window_begin[r]; t < window_end[r]; ++t)
    {
      const std::array<std::size_t, 3> tv{{std::size_t(triangles[t][0]), std::size_t(triangles[t][1]),
                                           std::size_t(triangles[t][2])}};
      for(int i = 0; i < 3; ++i)
        if(tv[i] >= low && tv[i] < high)
          star[fill[tv[i] - low]++] = {Index(3 * t + i), Index(tv[(i + 1) % 3]), Index(tv[(i + 2) % 3])};
    }
    // Both halves of an edge v -> w and w -> v pass through v, so the twin
    // of each edge leaving v is found in v's own star: each triangle is
    // read once per corner, not once per corner and neighbour.
    for(std::size_t v = 0; v < high - low; ++v)
    {
      const Star_corner* const begin = star.data() + first[v];
      const Star_corner* const end = star.data() + first[v + 1];
      for(const Star_corner* k = begin; k != end; ++k)
      {
        // The edge v -> w of corner c's triangle faces previous(c); its twin
        // w -> v must be in exactly one other triangle, where w comes before
        // v and the twin faces the corner after v.  (A second v -> w makes
        // the search from w find two.)
        const Index w = k->after;
        const Star_corner* twin = nullptr;
        bool unique = true;
        for(const Star_corner* j = begin; j != end; ++j)
          if(j->before == w)
          {
            unique = twin == nullptr;
            twin = j;
          }
        if(twin == nullptr && with_border)
          continue;
        if(twin == nullptr || !unique)
        {
          manifold = false;
          return;
        }
        // Written by this range only: corner previous(c) belongs to v.
        opposite[previous(std::size_t(k->corner))] = Index(next(std::size_t(twin->corner)));
      }
    }
  });
  return manifold;
}

/// Flips edges of the closed, oriented triangle soup to raise its smallest
/// angles (see above).  `protected_edges` (vertex pairs) are never flipped.
/// Returns the number of flips.  With `part`, `triangles` is a part of a
/// closed soup: an edge on its border is never flipped, nor one whose new
/// edge could not be checked against the star of its first end (a star
/// that leaves the part).
template <typename Index, typename ConcurrencyTag, typename Triangle>
std::size_t flip_slivers_with_corners(const std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                                      const std::vector<std::array<std::size_t, 2>>& protected_edges,
                                      const Sliver_flip_settings& settings,
                                      std::vector<unsigned char>* flipped_vertices, bool part = false)
{
  if(flipped_vertices != nullptr)
    flipped_vertices->assign(points.size(), 0);
  std::vector<Index> opposite;
  if(!opposite_corners<ConcurrencyTag>(points.size(), triangles, opposite, 0, part))
    return 0; // not a closed 2-manifold: leave it alone
  const Index none = Index(-1);
  const auto key = [](std::size_t a, std::size_t b) {
    return a < b ? (std::uint64_t(a) << 32) | std::uint64_t(b) : (std::uint64_t(b) << 32) | std::uint64_t(a);
  };
  // The protected edges, sorted, and a flag on their vertices: most edges
  // tried have an end off every crease, and need no search.
  std::vector<std::uint64_t> fixed;
  std::vector<bool> on_fixed(points.size(), false);
  for(const auto& e : protected_edges)
  {
    fixed.push_back(key(e[0], e[1]));
    for(const std::size_t v : e)
      if(v < on_fixed.size())
        on_fixed[v] = true;
  }
  std::sort(fixed.begin(), fixed.end());
  const auto is_fixed = [&](std::size_t a, std::size_t b) {
    return on_fixed[a] && on_fixed[b] && std::binary_search(fixed.begin(), fixed.end(), key(a, b));
  };
  const auto vertex = [&](std::size_t c) { return triangles[c / 3][c % 3]; };
  const auto next = [](std::size_t c) { return c - c % 3 + (c + 1) % 3; };
  const auto previous = [](std::size_t c) { return c - c % 3 + (c + 2) % 3; };
  // Is `d` a neighbour of the vertex of corner `c`?  (Walks its star.)
  const auto adjacent = [&](std::size_t c, std::size_t d) {
    std::size_t k = c;
    for(std::size_t steps = 0; steps < triangles.size(); ++steps)
    {
      if(vertex(next(k)) == d)
        return true;
      if(opposite[previous(k)] == none)
        return true; // the star leaves the part: unknown, so no flip
      k = previous(std::size_t(opposite[previous(k)]));
      if(k == c)
        return false;
    }
    return true; // a broken star: say yes, so nothing flips there
  };
  const auto cotangent_at = [&](std::size_t apex, std::size_t u, std::size_t v) {
    const Vector_3d a = sub3(points[u], points[apex]), b = sub3(points[v], points[apex]);
    const Vector_3d n = cross3(a, b);
    const double sine = std::sqrt(dot3(n, n));
    return sine > 0 ? dot3(a, b) / sine : 0.0;
  };
  const auto unit = [](Vector_3d v) {
    const double l = std::sqrt(dot3(v, v));
    if(l > 0)
      for(double& x : v)
        x /= l;
    return v;
  };
  const auto link = [&](std::size_t x, Index y) {
    opposite[x] = y;
    if(y != none)
      opposite[std::size_t(y)] = Index(x);
  };
  std::size_t flips = 0;
  const std::size_t max_flips = 4 * triangles.size();
  // Tries the edge facing corner c1 (c1 = c in t1 = (a, b, c); its twin
  // faces d in t2 = (b, a, d)); on success the four outer edges are queued.
  // A first-in first-out queue in blocks: the rounds of before in the same
  // order, without a second vector (and its doubling) beside the corner
  // table at the memory peak of the feature path.
  std::deque<Index> queued;
  const double cos_unreliable_normal = std::cos(settings.unreliable_normal_angle);
  const auto try_flip = [&](std::size_t c1) {
    if(opposite[c1] == none)
      return; // on the part's border
    const std::size_t c2 = std::size_t(opposite[c1]);
    const std::size_t t1 = c1 / 3, t2 = c2 / 3;
    const std::size_t c = vertex(c1), a = vertex(next(c1)), b = vertex(previous(c1)), d = vertex(c2);
    if(t1 == t2 || c == d)
      return;
    // Delaunay criterion: the opposite angles add up to more than pi, i.e.
    // their cotangents to less than 0.
    if(!(cotangent_at(c, a, b) + cotangent_at(d, b, a) < -1e-9))
      return;
    if(is_fixed(a, b) || adjacent(c1, d))
      return;
    const Vector_3d n1 = unit(triangle_normal(points[a], points[b], points[c]));
    const Vector_3d n2 = unit(triangle_normal(points[b], points[a], points[d]));
    if(!(dot3(n1, n2) > settings.cos_max_dihedral) &&
       !has_angle_below(points[a], points[b], points[c], cos_unreliable_normal) &&
       !has_angle_below(points[b], points[a], points[d], cos_unreliable_normal))
      return;
    const Vector_3d m1 = triangle_normal(points[a], points[d], points[c]);
    const Vector_3d m2 = triangle_normal(points[d], points[b], points[c]);
    const Vector_3d n12{{n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]}};
    if(!(dot3(m1, n12) > 0 && dot3(m2, n12) > 0 && dot3(m1, n1) > 0 && dot3(m1, n2) > 0 && dot3(m2, n1) > 0 &&
         dot3(m2, n2) > 0))
      return;
    // Distance between the two diagonals' lines.
    const Vector_3d ab = sub3(points[b], points[a]), cd = sub3(points[d], points[c]);
    const Vector_3d across = cross3(ab, cd);
    const double across_length = std::sqrt(dot3(across, across));
    if(!(across_length > 0))
      return;
    if(!(std::abs(dot3(sub3(points[c], points[a]), across)) / across_length <= settings.max_deviation))
      return;
    // The smallest angle grows iff the largest of the cosines shrinks.
    const double before = (std::max)(largest_cosine(points[a], points[b], points[c]),
                                      largest_cosine(points[b], points[a], points[d]));
    const double after = (std::max)(largest_cosine(points[a], points[d], points[c]),
                                     largest_cosine(points[d], points[b], points[c]));
    if(!(after < before) || !(triangle_quality(points[a], points[d], points[c]) > degenerate_quality &&
                              triangle_quality(points[d], points[b], points[c]) > degenerate_quality))
      return;
    // The outer corners: across b-c (facing a in t1), c-a (facing b in t1),
    // a-d (facing b in t2) and d-b (facing a in t2).
    const Index across_bc = opposite[next(c1)], across_ca = opposite[previous(c1)];
    const Index across_ad = opposite[next(c2)], across_db = opposite[previous(c2)];
    triangles[t1] = make_triangle<Triangle>(a, d, c);
    triangles[t2] = make_triangle<Triangle>(d, b, c);
    const std::size_t f1 = 3 * t1, f2 = 3 * t2; // corners of a, d, c and of d, b, c
    link(f1 + 0, Index(f2 + 1)); // facing the new edge d-c
    link(f1 + 1, across_ca);
    link(f1 + 2, across_ad);
    link(f2 + 0, across_bc);
    link(f2 + 2, across_db);
    ++flips;
    if(flipped_vertices != nullptr)
      for(const std::size_t v : {a, b, c, d})
        (*flipped_vertices)[v] = 1;
    // The outer edges, as the new triangles see them: c-a faces d (f1 + 1),
    // a-d faces c (f1 + 2), b-c faces d (f2 + 0), d-b faces c (f2 + 2).
    for(std::size_t k : {f1 + 1, f1 + 2, f2 + 0, f2 + 2})
      queued.push_back(Index(k));
  };
  // The work list: the edges of the triangles whose smallest angle is below
  // `seed_angle`, in triangle order, then the edges around each flip, in
  // rounds.  A queued corner may face another edge by the time it comes up
  // (its triangle flipped since): that edge is tried instead, and the one it
  // faced was queued again by that flip.
  const double cos_seed = std::cos(settings.seed_angle);
  for(std::size_t t = 0; t < triangles.size() && flips < max_flips; ++t)
  {
    const auto& tr = triangles[t];
    if(has_angle_below(points[tr[0]], points[tr[1]], points[tr[2]], cos_seed))
      for(std::size_t i = 0; i < 3 && flips < max_flips; ++i)
        try_flip(3 * t + i);
  }
  while(!queued.empty() && flips < max_flips)
  {
    const std::size_t c = std::size_t(queued.front());
    queued.pop_front();
    try_flip(c);
  }
  return flips;
}

/// Flips edges of the closed, oriented triangle soup to raise its smallest
/// angles (see above), on a corner table of 32-bit indices where they
/// suffice.  `protected_edges` (vertex pairs) are never flipped.  Returns
/// the number of flips (0 if the soup is not a closed 2-manifold).  If
/// `flipped_vertices` is not null, it receives a flag per point: 1 for the
/// vertices of the flipped triangles.  The flips are sequential;
/// `ConcurrencyTag` is for the corner table.
template <typename ConcurrencyTag = Sequential_tag, typename Triangle>
std::size_t flip_slivers(const std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                         const std::vector<std::array<std::size_t, 2>>& protected_edges,
                         const Sliver_flip_settings& settings,
                         std::vector<unsigned char>* flipped_vertices = nullptr)
{
  if(3 * triangles.size() < std::size_t(std::numeric_limits<std::uint32_t>::max()) &&
     points.size() < std::size_t(std::numeric_limits<std::uint32_t>::max()))
    return flip_slivers_with_corners<std::uint32_t, ConcurrencyTag>(points, triangles, protected_edges, settings,
                                                                    flipped_vertices);
  return flip_slivers_with_corners<std::size_t, ConcurrencyTag>(points, triangles, protected_edges, settings,
                                                                flipped_vertices);
}

/// `flip_slivers()` where the triangles changed since a previous run, i.e.
/// near the vertices flagged in `changed` (one flag per point) whose stars
/// changed: every edge whose flip test reads a changed triangle has its ends
/// and its two opposite vertices within two edges of a flagged vertex.  The
/// flips run on the triangles with a vertex within those two rings (whose
/// stars they hold whole), with a corner table of that part only; elsewhere
/// nothing a flip test reads has changed since the previous run, which left
/// nothing to flip there (up to its work list's order).  The full run's
/// corner table and seed scan cost as much as the first run.
template <typename Triangle>
std::size_t flip_slivers_near(const std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                              const std::vector<std::array<std::size_t, 2>>& protected_edges,
                              const Sliver_flip_settings& settings, const std::vector<unsigned char>& changed)
{
  // ring: 1 for a flagged vertex, 2 and 3 for the first and second rings.
  std::vector<unsigned char> ring(changed);
  for(unsigned char level = 1; level <= 2; ++level)
    for(const Triangle& tr : triangles)
      if((ring[tr[0]] != 0 && ring[tr[0]] <= level) || (ring[tr[1]] != 0 && ring[tr[1]] <= level) ||
         (ring[tr[2]] != 0 && ring[tr[2]] <= level))
        for(const std::size_t v : tr)
          if(ring[v] == 0)
            ring[v] = level + 1;
  std::vector<Triangle> part;
  std::vector<std::size_t> whole_index;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tr = triangles[t];
    if(ring[tr[0]] != 0 || ring[tr[1]] != 0 || ring[tr[2]] != 0)
    {
      part.push_back(tr);
      whole_index.push_back(t);
    }
  }
  if(part.empty() || 3 * part.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
    return 0;
  const std::size_t flips = flip_slivers_with_corners<std::uint32_t, Sequential_tag>(
      points, part, protected_edges, settings, nullptr, true);
  // A flip rewrites its two triangles in place: they go back where they were.
  for(std::size_t t = 0; t < part.size(); ++t)
    triangles[whole_index[t]] = part[t];
  return flips;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_SLIVER_FLIPS_H
