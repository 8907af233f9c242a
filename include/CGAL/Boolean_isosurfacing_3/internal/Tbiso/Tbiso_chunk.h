// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_CHUNK_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_CHUNK_H

// The output of a chunk of tetrahedra, and how chunks are welded into one
// soup (in-core drivers and the slab stream alike).

#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Exact_determinant_sign.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_tetrahedron.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The polygons of one chunk of tetrahedra, with chunk-local vertex indices.
struct Tbiso_chunk
{
  std::vector<Tbiso_vertex_key> keys;
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> polygon_begin{0};
  std::vector<std::size_t> polygon_vertices;
  std::vector<int> labels;
  // For a face closing the set on the domain boundary, the boundary plane it
  // lies on (see Boolean_isosurface_soup::face_boundary_planes); else -1.
  std::vector<int> planes;
  std::size_t evaluated = 0;
  std::unordered_map<Tbiso_vertex_key, std::size_t, Tbiso_vertex_key_hash> index;

  // Called from inside the evaluator's `emit`: coordinates are computed only
  // for a key seen for the first time (a vertex is met by about 6 polygons).
  void add(int label, const Tbiso_tetrahedron_evaluator::Vertex* v, std::size_t n,
           const Tbiso_tetrahedron_evaluator& evaluator, int plane = -1)
  {
    for(std::size_t k = 0; k < n; ++k)
    {
      auto inserted = index.emplace(v[k].key, keys.size());
      if(inserted.second)
      {
        keys.push_back(v[k].key);
        points.push_back(evaluator.point(v[k]));
      }
      polygon_vertices.push_back(inserted.first->second);
    }
    polygon_begin.push_back(polygon_vertices.size());
    labels.push_back(label);
    planes.push_back(plane);
  }
};

inline std::size_t tbiso_no_index() { return (std::numeric_limits<std::size_t>::max)(); }

// Are the points p[v[0..n)] (doubles) all on one line?  Exact.
inline bool all_collinear(const std::vector<std::array<double, 3>>& p, const std::size_t* v, std::size_t n)
{
  // A cheap rejection first: a cross product well above its rounding error.
  const std::array<double, 3>& a = p[v[0]];
  double scale = 0, area[3] = {0, 0, 0};
  for(std::size_t k = 1; k + 1 < n; ++k)
  {
    const std::array<double, 3>& b = p[v[k]];
    const std::array<double, 3>& c = p[v[k + 1]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    area[0] += u[1] * w[2] - u[2] * w[1];
    area[1] += u[2] * w[0] - u[0] * w[2];
    area[2] += u[0] * w[1] - u[1] * w[0];
    for(int x = 0; x < 3; ++x)
      scale = (std::max)(scale, (std::max)(std::abs(u[x]), std::abs(w[x])));
  }
  const double bound = 1e-12 * scale * scale;
  if(std::abs(area[0]) > bound || std::abs(area[1]) > bound || std::abs(area[2]) > bound)
    return false;
  // Exact: every vertex on the line through v[0] and the first vertex at another position.
  std::size_t far = n;
  for(std::size_t k = 1; k < n && far == n; ++k)
    if(p[v[k]] != a)
      far = k;
  if(far == n)
    return true;
  const std::array<double, 3>& b = p[v[far]];
  for(std::size_t k = 1; k < n; ++k)
  {
    const std::array<double, 3>& c = p[v[k]];
    for(int x = 0; x < 3; ++x)
    {
      const int y = (x + 1) % 3;
      const double m[9] = {1, a[x], a[y], 1, b[x], b[y], 1, c[x], c[y]};
      if(exact_sign_of_determinant(m, 3) != 0)
        return false;
    }
  }
  return true;
}

// Welds one chunk into the output, removing what rounding to double leaves
// degenerate.
//
// The exact evaluation never emits a polygon of zero area, and equal keys
// are equal points.  But distinct exact points can round to the same
// doubles.  When the sampled values of two fields differ by a few units in
// the last place where the exact functions are equal (say two spheres
// mirrored by a coordinate swap, whose squares are summed in another order),
// the arrangement has cells of size 1e-16, and their polygons have two
// vertices at one position, or three collinear vertices.  So, after rounding:
//  1. the vertices of a polygon that have bit-identical coordinates are
//     merged (no point moves, so volumes are unchanged), and each polygon is
//     split at its repeated vertices into simple loops, dropping the loops of
//     fewer than 3 vertices (a loop of two is a pair of opposite edges, so the
//     surface stays closed);
//  2. a polygon whose vertices are all collinear (an exact test on the
//     doubles) is removed, and its vertices are inserted into the edges of its
//     neighbours across it, so that they still match edge for edge.
// Both steps see only the chunk's polygons.  A merge that would join two
// vertices that earlier chunks numbered differently, or a collinear polygon
// with a neighbour in another chunk, is left as is: it would renumber what is
// already written.  All drivers weld with this function, chunk by chunk in
// the same order, so they still agree.
//
// `lookup(key)` returns the output index that an earlier chunk gave the key,
// or tbiso_no_index(); `publish(key, index)` records a key for later chunks;
// `add_point(p)` and `add_polygon(vertices, n, label, plane)` receive the output.
template <typename Lookup, typename Publish, typename AddPoint, typename AddPolygon>
void weld_chunk(Tbiso_chunk& chunk, const Lookup& lookup, const Publish& publish, std::size_t& next_index,
                const AddPoint& add_point, const AddPolygon& add_polygon)
{
  const std::size_t nv = chunk.keys.size(), np = chunk.labels.size();
  const std::vector<std::array<double, 3>>& P = chunk.points;

  // 1. Union-find of the vertices of a polygon at the same position; the
  // root of a class is its lowest index.
  std::vector<std::size_t> leader(nv);
  for(std::size_t v = 0; v < nv; ++v)
    leader[v] = v;
  auto find = [&](std::size_t v) {
    while(leader[v] != v)
      v = leader[v] = leader[leader[v]];
    return v;
  };
  bool merged = false;
  for(std::size_t p = 0; p < np; ++p)
    for(std::size_t i = chunk.polygon_begin[p]; i < chunk.polygon_begin[p + 1]; ++i)
      for(std::size_t j = i + 1; j < chunk.polygon_begin[p + 1]; ++j)
      {
        const std::size_t a = chunk.polygon_vertices[i], b = chunk.polygon_vertices[j];
        if(a != b && P[a] == P[b])
        {
          const std::size_t ra = find(a), rb = find(b);
          if(ra != rb)
          {
            leader[(std::max)(ra, rb)] = (std::min)(ra, rb);
            merged = true;
          }
        }
      }
  // The members of each class, and the dissolution of the classes that would
  // join two indices given by earlier chunks.
  std::unordered_map<std::size_t, std::vector<std::size_t>> members;
  if(merged)
  {
    for(std::size_t v = 0; v < nv; ++v)
    {
      const std::size_t root = find(v);
      if(root != v)
        members[root].push_back(v);
    }
    for(auto& m : members)
      for(std::size_t v : m.second)
        leader[v] = m.first; // flat: every member points at its root
    for(auto& m : members)
    {
      std::size_t known = lookup(chunk.keys[m.first]);
      bool conflict = false;
      for(std::size_t v : m.second)
      {
        const std::size_t k = lookup(chunk.keys[v]);
        if(k != tbiso_no_index() && known != tbiso_no_index() && k != known)
          conflict = true;
        if(k != tbiso_no_index())
          known = k;
      }
      if(conflict)
      {
        for(std::size_t v : m.second)
          leader[v] = v;
        m.second.clear();
      }
    }
  }

  // The polygons on class roots, split at repeated vertices.
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<int> labels, planes;
  polygons.reserve(np);
  labels.reserve(np);
  planes.reserve(np);
  std::vector<std::size_t> loop;
  for(std::size_t p = 0; p < np; ++p)
  {
    loop.clear();
    for(std::size_t i = chunk.polygon_begin[p]; i < chunk.polygon_begin[p + 1]; ++i)
    {
      const std::size_t v = merged ? find(chunk.polygon_vertices[i]) : chunk.polygon_vertices[i];
      const auto repeated = std::find(loop.begin(), loop.end(), v);
      if(repeated == loop.end())
      {
        loop.push_back(v);
        continue;
      }
      // Close the loop from the earlier occurrence of v to here.
      if(loop.end() - repeated >= 3)
      {
        polygons.emplace_back(repeated, loop.end());
        labels.push_back(chunk.labels[p]);
        planes.push_back(chunk.planes[p]);
      }
      loop.erase(repeated + 1, loop.end());
    }
    if(loop.size() >= 3)
    {
      polygons.push_back(loop);
      labels.push_back(chunk.labels[p]);
      planes.push_back(chunk.planes[p]);
    }
  }

  // 2. Collinear polygons.
  std::vector<std::size_t> collinear;
  for(std::size_t p = 0; p < polygons.size(); ++p)
    if(all_collinear(P, polygons[p].data(), polygons[p].size()))
      collinear.push_back(p);
  std::vector<bool> removed(polygons.size(), false);
  if(!collinear.empty())
  {
    struct Pair_hash
    {
      std::size_t operator()(const std::pair<std::size_t, std::size_t>& e) const
      {
        return std::hash<std::size_t>()(e.first * 0x9E3779B97F4A7C15ull ^ e.second);
      }
    };
    std::unordered_map<std::pair<std::size_t, std::size_t>, std::size_t, Pair_hash> edge;
    for(std::size_t p = 0; p < polygons.size(); ++p)
      for(std::size_t k = 0; k < polygons[p].size(); ++k)
        edge[{polygons[p][k], polygons[p][(k + 1) % polygons[p].size()]}] = p;
    // Lexicographic order of points on a line is their order along it.
    auto before = [&](std::size_t a, std::size_t b) { return P[a] < P[b]; };
    for(std::size_t p : collinear)
    {
      const std::vector<std::size_t> poly = polygons[p];
      const std::size_t n = poly.size();
      // Two monotone chains (a convex polygon, flattened): the order along
      // the line changes direction exactly twice around the polygon.
      int turns = 0;
      for(std::size_t k = 0; k < n; ++k)
      {
        const bool up = before(poly[k], poly[(k + 1) % n]);
        const bool next_up = before(poly[(k + 1) % n], poly[(k + 2) % n]);
        turns += up != next_up;
      }
      std::vector<std::size_t> across(n);
      bool ok = turns == 2;
      for(std::size_t k = 0; k < n && ok; ++k)
      {
        const auto e = edge.find({poly[(k + 1) % n], poly[k]});
        ok = e != edge.end() && e->second != p && !removed[e->second];
        if(ok)
          across[k] = e->second;
      }
      if(!ok)
        continue;
      std::vector<std::size_t> sorted = poly;
      std::sort(sorted.begin(), sorted.end(), before);
      for(std::size_t k = 0; k < n; ++k)
      {
        const std::size_t u = poly[k], v = poly[(k + 1) % n];
        // The vertices strictly between u and v, in order from v to u: the
        // neighbour has the edge v -> u.
        std::vector<std::size_t> between;
        for(std::size_t w : sorted)
          if(w != u && w != v && ((before(u, w) && before(w, v)) || (before(v, w) && before(w, u))))
            between.push_back(w);
        if(between.empty())
          continue;
        std::sort(between.begin(), between.end(), [&](std::size_t a, std::size_t b) {
          return before(u, v) ? before(b, a) : before(a, b);
        });
        std::vector<std::size_t>& q = polygons[across[k]];
        const std::size_t qn = q.size();
        std::size_t at = 0;
        while(!(q[at] == v && q[(at + 1) % qn] == u))
          ++at;
        edge.erase({v, u});
        q.insert(q.begin() + std::ptrdiff_t(at + 1), between.begin(), between.end());
        std::size_t from = v;
        for(std::size_t w : between)
        {
          edge[{from, w}] = across[k];
          from = w;
        }
        edge[{from, u}] = across[k];
      }
      for(std::size_t k = 0; k < n; ++k)
        edge.erase({poly[k], poly[(k + 1) % n]});
      removed[p] = true;
    }
  }

  // Output indices, in order of the class roots: a class takes the index an
  // earlier chunk gave one of its keys, or a new one.
  std::vector<bool> used(nv, false);
  for(std::size_t p = 0; p < polygons.size(); ++p)
    if(!removed[p])
      for(std::size_t v : polygons[p])
        used[v] = true;
  std::vector<std::size_t> to_global(nv, tbiso_no_index());
  static const std::vector<std::size_t> none;
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!used[v] || leader[v] != v)
      continue;
    const auto m = merged ? members.find(v) : members.end();
    const std::vector<std::size_t>& others = m != members.end() ? m->second : none;
    std::size_t index = lookup(chunk.keys[v]);
    for(std::size_t w : others)
      if(index == tbiso_no_index())
        index = lookup(chunk.keys[w]);
    if(index == tbiso_no_index())
    {
      index = next_index++;
      add_point(P[v]);
    }
    to_global[v] = index;
    publish(chunk.keys[v], index);
    for(std::size_t w : others)
      publish(chunk.keys[w], index);
  }
  std::vector<std::size_t> polygon;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    if(removed[p])
      continue;
    polygon.clear();
    for(std::size_t v : polygons[p])
      polygon.push_back(to_global[v]);
    add_polygon(polygon.data(), polygon.size(), labels[p], planes[p]);
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_CHUNK_H
