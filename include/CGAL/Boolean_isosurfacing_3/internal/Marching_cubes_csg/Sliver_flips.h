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
//    less than `max_dihedral` (no flip across a feature);
//  - the two diagonals are closer than `max_deviation` (the surface moves by
//    at most that much), and both new triangles keep the orientation of the
//    old ones (the quadrilateral is convex seen along its normal);
//  - the smallest angle of the two triangles increases.
// The flips are done from a work list seeded with the edges of the
// triangles whose smallest angle is below `seed_angle`, in a deterministic
// order, with at most `4 * triangles` flips.

#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

/// Undirected edge (a 64-bit key) -> its two triangles: open addressing
/// with linear probing (std::unordered_map's node per edge cost more than
/// the flips).
class Edge_triangle_table
{
public:
  static constexpr std::uint64_t empty = ~std::uint64_t(0), erased = ~std::uint64_t(0) - 1;
  static constexpr std::size_t none = std::size_t(-1);

  explicit Edge_triangle_table(std::size_t edges)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * edges + 16)
      capacity *= 2;
    m_keys.assign(capacity, empty);
    m_values.resize(capacity);
    m_mask = capacity - 1;
  }

  // The entry of `key`, or null.
  std::array<std::size_t, 2>* find(std::uint64_t key)
  {
    for(std::size_t i = slot(key);; i = (i + 1) & m_mask)
    {
      if(m_keys[i] == key)
        return &m_values[i];
      if(m_keys[i] == empty)
        return nullptr;
    }
  }
  // The entry of `key`, created as {none, none} if absent.
  std::array<std::size_t, 2>& insert(std::uint64_t key)
  {
    std::size_t free = std::size_t(-1);
    for(std::size_t i = slot(key);; i = (i + 1) & m_mask)
    {
      if(m_keys[i] == key)
        return m_values[i];
      if(m_keys[i] == erased && free == std::size_t(-1))
        free = i;
      if(m_keys[i] == empty)
      {
        if(free == std::size_t(-1))
          free = i;
        m_keys[free] = key;
        m_values[free] = {{none, none}};
        return m_values[free];
      }
    }
  }
  void erase(std::uint64_t key)
  {
    for(std::size_t i = slot(key);; i = (i + 1) & m_mask)
    {
      if(m_keys[i] == key)
      {
        m_keys[i] = erased;
        return;
      }
      if(m_keys[i] == empty)
        return;
    }
  }

private:
  std::size_t slot(std::uint64_t key) const
  {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return std::size_t(key) & m_mask;
  }
  std::vector<std::uint64_t> m_keys;
  std::vector<std::array<std::size_t, 2>> m_values;
  std::size_t m_mask = 0;
};

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

/// Parameters of `flip_slivers()`.
struct Sliver_flip_settings
{
  double max_deviation = 0;                 // length
  double cos_max_dihedral = 0.9396926207859084; // 20 degrees
  double seed_angle = 0.3490658503988659;   // 20 degrees, in radians
};

/// Flips edges of the closed, oriented triangle soup to raise its smallest
/// angles (see above).  `protected_edges` (vertex pairs) are never flipped.
/// Returns the number of flips.
inline std::size_t flip_slivers(const std::vector<Vector_3d>& points, std::vector<std::array<std::size_t, 3>>& triangles,
                                const std::vector<std::array<std::size_t, 2>>& protected_edges,
                                const Sliver_flip_settings& settings)
{
  const auto key = [](std::size_t a, std::size_t b) {
    return a < b ? (std::uint64_t(a) << 32) | std::uint64_t(b) : (std::uint64_t(b) << 32) | std::uint64_t(a);
  };
  // Undirected edge -> its two triangles.  Flips keep the number of edges,
  // so the table never fills up.
  const std::size_t none = Edge_triangle_table::none;
  Edge_triangle_table edge_triangles(3 * triangles.size() / 2);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int i = 0; i < 3; ++i)
    {
      std::array<std::size_t, 2>& entry = edge_triangles.insert(key(triangles[t][i], triangles[t][(i + 1) % 3]));
      if(entry[0] == none)
        entry[0] = t;
      else if(entry[1] == none)
        entry[1] = t;
      else
        return 0; // not a 2-manifold: leave it alone
    }
  std::unordered_set<std::uint64_t> fixed;
  for(const auto& e : protected_edges)
    fixed.insert(key(e[0], e[1]));

  std::vector<std::uint64_t> seeds;
  const double cos_seed = std::cos(settings.seed_angle);
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const auto& tr = triangles[t];
    if(largest_cosine(points[tr[0]], points[tr[1]], points[tr[2]]) > cos_seed)
      for(int i = 0; i < 3; ++i)
        seeds.push_back(key(tr[i], tr[(i + 1) % 3]));
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::deque<std::uint64_t> work(seeds.begin(), seeds.end());

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
  std::size_t flips = 0;
  const std::size_t max_flips = 4 * triangles.size();
  while(!work.empty() && flips < max_flips)
  {
    const std::uint64_t e = work.front();
    work.pop_front();
    if(fixed.count(e))
      continue;
    const std::array<std::size_t, 2>* found = edge_triangles.find(e);
    if(found == nullptr || (*found)[1] == none)
      continue;
    const std::size_t t1 = (*found)[0], t2 = (*found)[1];
    // t1 = (a, b, c) with the edge as (a, b); t2 = (b, a, d).
    std::array<std::size_t, 3> r1 = triangles[t1], r2 = triangles[t2];
    const std::size_t ea = std::size_t(e >> 32), eb = std::size_t(e & 0xffffffffu);
    int i1 = 0;
    while(!((r1[i1] == ea && r1[(i1 + 1) % 3] == eb) || (r1[i1] == eb && r1[(i1 + 1) % 3] == ea)))
      ++i1;
    const std::size_t a = r1[i1], b = r1[(i1 + 1) % 3], c = r1[(i1 + 2) % 3];
    int i2 = 0;
    while(!(r2[i2] == b && r2[(i2 + 1) % 3] == a))
      if(++i2 == 3)
        break;
    if(i2 == 3)
      continue; // not oppositely oriented
    const std::size_t d = r2[(i2 + 2) % 3];
    if(c == d || edge_triangles.find(key(c, d)) != nullptr)
      continue;
    // Delaunay criterion: the opposite angles add up to more than pi, i.e.
    // their cotangents to less than 0.
    if(!(cotangent_at(c, a, b) + cotangent_at(d, b, a) < -1e-9))
      continue;
    const Vector_3d n1 = unit(triangle_normal(points[a], points[b], points[c]));
    const Vector_3d n2 = unit(triangle_normal(points[b], points[a], points[d]));
    if(!(dot3(n1, n2) > settings.cos_max_dihedral))
      continue;
    const Vector_3d m1 = triangle_normal(points[a], points[d], points[c]);
    const Vector_3d m2 = triangle_normal(points[d], points[b], points[c]);
    const Vector_3d n12{{n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]}};
    if(!(dot3(m1, n12) > 0 && dot3(m2, n12) > 0 && dot3(m1, n1) > 0 && dot3(m1, n2) > 0 && dot3(m2, n1) > 0 &&
         dot3(m2, n2) > 0))
      continue;
    // Distance between the two diagonals' lines.
    const Vector_3d ab = sub3(points[b], points[a]), cd = sub3(points[d], points[c]);
    const Vector_3d across = cross3(ab, cd);
    const double across_length = std::sqrt(dot3(across, across));
    if(!(across_length > 0))
      continue;
    if(!(std::abs(dot3(sub3(points[c], points[a]), across)) / across_length <= settings.max_deviation))
      continue;
    // The smallest angle grows iff the largest of the cosines shrinks.
    const double before = (std::max)(largest_cosine(points[a], points[b], points[c]),
                                      largest_cosine(points[b], points[a], points[d]));
    const double after = (std::max)(largest_cosine(points[a], points[d], points[c]),
                                     largest_cosine(points[d], points[b], points[c]));
    if(!(after < before) || !(triangle_quality(points[a], points[d], points[c]) > degenerate_quality &&
                              triangle_quality(points[d], points[b], points[c]) > degenerate_quality))
      continue;
    triangles[t1] = {{a, d, c}};
    triangles[t2] = {{d, b, c}};
    edge_triangles.erase(e);
    edge_triangles.insert(key(c, d)) = {{t1, t2}};
    // (a, d) moves from t2 to t1, (b, c) from t1 to t2.
    for(auto& x : *edge_triangles.find(key(a, d)))
      if(x == t2)
        x = t1;
    for(auto& x : *edge_triangles.find(key(b, c)))
      if(x == t1)
        x = t2;
    ++flips;
    for(const std::uint64_t k : {key(a, c), key(c, b), key(b, d), key(d, a)})
      work.push_back(k);
  }
  return flips;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_SLIVER_FLIPS_H
