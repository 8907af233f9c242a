// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_REPAIR_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_REPAIR_H

// The repairs after the contouring: small closed components (bubbles)
// removed, small holes closed.

#include <CGAL/Boolean_isosurfacing_3/Contouring_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Flat_uint64_map.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

namespace internal {

/// Removes, from the triangles appended from `first_triangle` on (whose
/// vertices are the points from `first_vertex` on), every connected component
/// that is closed (each of its edges in exactly 2 of its triangles) and whose
/// bounding box has a diagonal below `min_diagonal`.  Returns how many.
template <typename PointOutRange, typename TriangleRange>
std::size_t remove_small_closed_components(PointOutRange& points, TriangleRange& triangles, std::size_t first_vertex,
                                           std::size_t first_triangle, double min_diagonal)
{
  const std::size_t nv = points.size() - first_vertex;
  std::vector<std::size_t> parent(nv);
  for(std::size_t v = 0; v < nv; ++v)
    parent[v] = v;
  auto find = [&parent](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    for(int i = 1; i < 3; ++i)
    {
      const std::size_t a = find(std::size_t(triangles[t][0]) - first_vertex);
      const std::size_t b = find(std::size_t(triangles[t][i]) - first_vertex);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  std::vector<std::array<double, 6>> box(nv, {{std::numeric_limits<double>::infinity(),
                                              std::numeric_limits<double>::infinity(),
                                              std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity()}});
  for(std::size_t v = 0; v < nv; ++v)
  {
    std::array<double, 6>& b = box[find(v)];
    for(int a = 0; a < 3; ++a)
    {
      const double x = CGAL::to_double(points[first_vertex + v][a]);
      b[a] = (std::min)(b[a], x);
      b[3 + a] = (std::max)(b[3 + a], x);
    }
  }
  std::vector<char> small(nv, 0);
  bool any = false;
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] == v)
    {
      const std::array<double, 6>& b = box[v];
      const double d2 = (b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) + (b[5] - b[2]) * (b[5] - b[2]);
      small[v] = d2 < min_diagonal * min_diagonal;
      any = any || small[v];
    }
  if(!any)
    return 0;
  // Closedness of the small components: their undirected edges, sorted.
  std::vector<std::array<std::size_t, 3>> edges; // root, lower vertex, upper vertex
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
  {
    const std::size_t root = find(std::size_t(triangles[t][0]) - first_vertex);
    if(small[root])
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t a = std::size_t(triangles[t][i]), b = std::size_t(triangles[t][(i + 1) % 3]);
        edges.push_back({{root, (std::min)(a, b), (std::max)(a, b)}});
      }
  }
  std::sort(edges.begin(), edges.end());
  for(std::size_t e = 0; e < edges.size();)
  {
    std::size_t end = e + 1;
    while(end < edges.size() && edges[end] == edges[e])
      ++end;
    if(end - e != 2)
      small[edges[e][0]] = 0; // has a border or non-manifold edge: not a bubble
    e = end;
  }
  std::size_t removed = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] == v && small[v])
      ++removed;
  if(removed == 0)
    return 0;
  // Compact, keeping the order of what stays.
  std::vector<std::size_t> new_index(nv, std::size_t(-1));
  std::vector<typename PointOutRange::value_type> kept_points;
  for(std::size_t v = 0; v < nv; ++v)
    if(!small[find(v)])
    {
      new_index[v] = first_vertex + kept_points.size();
      kept_points.push_back(points[first_vertex + v]);
    }
  std::vector<typename TriangleRange::value_type> kept_triangles;
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    if(!small[find(std::size_t(triangles[t][0]) - first_vertex)])
    {
      const auto& tri = triangles[t];
      kept_triangles.push_back(typename TriangleRange::value_type{new_index[std::size_t(tri[0]) - first_vertex],
                                                                  new_index[std::size_t(tri[1]) - first_vertex],
                                                                  new_index[std::size_t(tri[2]) - first_vertex]});
    }
  points.erase(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  points.insert(points.end(), kept_points.begin(), kept_points.end());
  triangles.erase(triangles.begin() + std::ptrdiff_t(first_triangle), triangles.end());
  triangles.insert(triangles.end(), kept_triangles.begin(), kept_triangles.end());
  return removed;
}

/// Repairs the holes that skipped cubes leave (issue 18), on the triangles
/// appended from `first_triangle` on (vertices from `first_vertex` on):
///  1. vertices pinched between two holes (two skipped cubes diagonal around
///     a lattice edge) are split (PMP::orient_polygon_soup), so the soup is an
///     oriented 2-manifold with border;
///  2. each border loop whose bounding box has a diagonal of at most
///     `max_hole_diagonal` is filled (PMP::triangulate_hole, no new vertex).
/// Larger loops (the border of an open sample, an unsampled region wider
/// than the hole limit) stay.  Returns (vertices split, holes filled).
template <typename PointOutRange, typename TriangleRange>
std::pair<std::size_t, std::size_t> close_small_holes(PointOutRange& points, TriangleRange& triangles,
                                                      std::size_t first_vertex, std::size_t first_triangle,
                                                      double max_hole_diagonal)
{
  typedef typename std::decay<decltype(points[0])>::type Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point_3> soup_points(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  std::vector<std::array<std::size_t, 3>> soup;
  soup.reserve(triangles.size() - first_triangle);
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    soup.push_back({{std::size_t(triangles[t][0]) - first_vertex, std::size_t(triangles[t][1]) - first_vertex,
                     std::size_t(triangles[t][2]) - first_vertex}});
  const std::size_t before = soup_points.size();
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup))
    PMP::orient_polygon_soup(soup_points, soup);
  const std::size_t split = soup_points.size() - before;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, soup, mesh);
  std::vector<typename Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  // A loop is a hole of a surface only if its component is larger than the
  // loop limit: a small open piece (one cube's triangles) bounded by the loop
  // would become a doubled patch.
  auto component = mesh.template add_property_map<typename Mesh::Face_index, std::size_t>("f:biso_cc", 0).first;
  const std::size_t number_of_components = PMP::connected_components(mesh, component);
  std::vector<Bbox_3> component_box(number_of_components);
  for(const auto f : mesh.faces())
    for(const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      component_box[component[f]] += mesh.point(v).bbox();
  std::size_t filled = 0;
  for(const auto h : cycles)
  {
    if(!mesh.is_border(h))
      continue;
    const Bbox_3& piece = component_box[component[mesh.face(mesh.opposite(h))]];
    if(CGAL::square(piece.xmax() - piece.xmin()) + CGAL::square(piece.ymax() - piece.ymin()) +
         CGAL::square(piece.zmax() - piece.zmin()) <= max_hole_diagonal * max_hole_diagonal)
      continue;
    Bbox_3 box;
    for(const auto g : CGAL::halfedges_around_face(h, mesh))
      box += mesh.point(mesh.target(g)).bbox();
    const double d2 = CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                      CGAL::square(box.zmax() - box.zmin());
    if(!(d2 <= max_hole_diagonal * max_hole_diagonal))
      continue;
    PMP::triangulate_hole(mesh, h, CGAL::Emptyset_iterator());
    ++filled;
  }
  // Back to the soup: vertex order is kept (the hole filling adds no vertex).
  std::vector<Point_3> new_points;
  std::vector<std::array<std::size_t, 3>> new_soup;
  mesh.remove_property_map(component);
  PMP::polygon_mesh_to_polygon_soup(mesh, new_points, new_soup);
  points.erase(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  for(const Point_3& p : new_points)
    points.push_back(p);
  triangles.erase(triangles.begin() + std::ptrdiff_t(first_triangle), triangles.end());
  for(const auto& t : new_soup)
    triangles.push_back(typename TriangleRange::value_type{t[0] + first_vertex, t[1] + first_vertex,
                                                           t[2] + first_vertex});
  return {split, filled};
}

/// The faces of a soup around each vertex, in CSR form.
struct Vertex_faces
{
  std::vector<std::size_t> begin, faces;
  template <typename TriangleRange>
  Vertex_faces(const TriangleRange& triangles, std::size_t first_vertex, std::size_t first_triangle, std::size_t nv,
               const std::vector<char>& removed)
    : begin(nv + 1, 0)
  {
    for(std::size_t t = first_triangle; t < triangles.size(); ++t)
      if(!removed[t - first_triangle])
        for(int i = 0; i < 3; ++i)
          ++begin[std::size_t(triangles[t][i]) - first_vertex + 1];
    for(std::size_t v = 0; v < nv; ++v)
      begin[v + 1] += begin[v];
    faces.resize(begin[nv]);
    std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
    for(std::size_t t = first_triangle; t < triangles.size(); ++t)
      if(!removed[t - first_triangle])
        for(int i = 0; i < 3; ++i)
          faces[fill[std::size_t(triangles[t][i]) - first_vertex]++] = t - first_triangle;
  }
};

/// The samples bucketed in a uniform grid of step `h`: whether a point is
/// within h of a sample, by looking at the 27 cells around it (the membrane
/// rule asks this of every output vertex; a kd-tree query each costs more).
/// The cells are found by hashing, the point's own cell first (where a
/// sample within h nearly always is).
class Sample_grid
{
public:
  template <typename PointRange>
  Sample_grid(const PointRange& samples, double h) : m_h(h)
  {
    std::vector<std::pair<std::uint64_t, std::array<double, 3>>> keyed;
    keyed.reserve(samples.size());
    for(const auto& p : samples)
    {
      const std::array<double, 3> x{{CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])}};
      keyed.emplace_back(key(cell(x[0]), cell(x[1]), cell(x[2])), x);
    }
    std::sort(keyed.begin(), keyed.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for(const auto& k : keyed)
    {
      if(m_begin.empty() || m_last_key != k.first)
      {
        m_cells.insert(k.first, m_begin.size());
        m_begin.push_back(m_points.size());
        m_last_key = k.first;
      }
      m_points.push_back(k.second);
    }
    m_begin.push_back(m_points.size());
  }

  /// Whether some sample is within h of `p`.
  template <typename Point>
  bool near(const Point& p) const
  {
    const double x[3] = {CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])};
    const std::int64_t c[3] = {cell(x[0]), cell(x[1]), cell(x[2])};
    const double h2 = m_h * m_h;
    auto near_in_cell = [&](std::int64_t dx, std::int64_t dy, std::int64_t dz) {
      const std::size_t* b = m_cells.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
      if(b == nullptr)
        return false;
      for(std::size_t i = m_begin[*b]; i < m_begin[*b + 1]; ++i)
      {
        const double d0 = m_points[i][0] - x[0], d1 = m_points[i][1] - x[1], d2 = m_points[i][2] - x[2];
        if(d0 * d0 + d1 * d1 + d2 * d2 <= h2)
          return true;
      }
      return false;
    };
    if(near_in_cell(0, 0, 0))
      return true;
    for(std::int64_t dz = -1; dz <= 1; ++dz)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dx = -1; dx <= 1; ++dx)
          if((dx != 0 || dy != 0 || dz != 0) && near_in_cell(dx, dy, dz))
            return true;
    return false;
  }

private:
  std::int64_t cell(double x) const { return std::int64_t(std::floor(x / m_h)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k)
  {
    // 21 bits per axis, wrapping: distinct cells may share a key, which only
    // adds samples to look at (the distance test is exact).  Never the map's
    // empty key (bit 63 is clear).
    const std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return (std::uint64_t(i) & mask) | ((std::uint64_t(j) & mask) << 21) | ((std::uint64_t(k) & mask) << 42);
  }

  double m_h;
  std::uint64_t m_last_key = 0;
  Flat_uint64_map<std::size_t> m_cells; // cell key -> its index in m_begin
  std::vector<std::size_t> m_begin;
  std::vector<std::array<double, 3>> m_points;
};

/// Removes membranes: on the triangles appended from `first_triangle` on
/// (vertices from `first_vertex` on), a face is *unwitnessed* when one of its
/// vertices is farther than `witness_distance` from every sample
/// (`distance_to_samples(point)`).  Each edge-connected set of unwitnessed
/// faces that reaches farther than `max_gap` from the samples spans an
/// opening of the sample wider than 2 `max_gap` (the rim of an open scan)
/// and is removed; smaller ones close gaps and stay.  So is one that
/// reaches a border of the soup (the lattice border).  Then, at every vertex
/// whose remaining faces form several fans (two cut regions touching at a
/// vertex), all fans but the largest are removed, until each vertex has one
/// fan: the cut leaves an oriented 2-manifold whose border loops are simple.
/// Returns the number of removed membranes.  The vertices' distances are
/// measured in parallel under Parallel_tag (`distance_to_samples` must then
/// be safe to call concurrently); the rest, and the result, are sequential.
template <typename ConcurrencyTag, typename PointOutRange, typename TriangleRange, typename SampleRange,
          typename Distance>
std::size_t remove_unwitnessed_membranes(PointOutRange& points, TriangleRange& triangles, std::size_t first_vertex,
                                         std::size_t first_triangle, const SampleRange& samples,
                                         const Distance& distance_to_samples, double witness_distance, double max_gap)
{
  const std::size_t nv = points.size() - first_vertex;
  const std::size_t nt = triangles.size() - first_triangle;
  if(!(witness_distance > 0))
    return 0;
  const Sample_grid grid(samples, witness_distance);
  std::vector<double> distance(nv, 0);
  std::vector<char> far(nv, 0);
  concurrent_for_blocks<ConcurrencyTag>(nv, 1024, [&](std::size_t begin, std::size_t end) {
    for(std::size_t v = begin; v < end; ++v)
    {
      far[v] = !grid.near(points[first_vertex + v]);
      if(far[v])
        distance[v] = distance_to_samples(points[first_vertex + v]);
    }
  });
  if(std::find(far.begin(), far.end(), char(1)) == far.end())
    return 0;
  std::vector<char> removed(nt, 0);
  std::vector<char> unwitnessed(nt, 0);
  for(std::size_t t = 0; t < nt; ++t)
    for(int i = 0; i < 3; ++i)
      unwitnessed[t] = unwitnessed[t] || far[std::size_t(triangles[first_triangle + t][i]) - first_vertex];
  const Vertex_faces around(triangles, first_vertex, first_triangle, nv, removed);
  auto vertex = [&](std::size_t t, int i) { return std::size_t(triangles[first_triangle + t][i]) - first_vertex; };
  auto shares_edge = [&](std::size_t a, std::size_t b) {
    int common = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        common += vertex(a, i) == vertex(b, j);
    return common >= 2;
  };
  // Faces with an edge in no other face (the lattice border cut the surface).
  auto is_border_face = [&](std::size_t t) {
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = vertex(t, i), b = vertex(t, (i + 1) % 3);
      std::size_t count = 0;
      for(std::size_t k = around.begin[a]; k < around.begin[a + 1]; ++k)
        for(int j = 0; j < 3; ++j)
          count += vertex(around.faces[k], j) == b;
      if(count < 2)
        return true;
    }
    return false;
  };
  // Edge-connected components of the unwitnessed faces (faces sharing an
  // edge share a vertex: look among the faces around each vertex).
  std::vector<std::size_t> component(nt, std::size_t(-1));
  std::vector<std::size_t> stack, members;
  std::size_t membranes = 0;
  for(std::size_t seed = 0; seed < nt; ++seed)
  {
    if(!unwitnessed[seed] || component[seed] != std::size_t(-1))
      continue;
    members.clear();
    double reach = 0;
    bool open = false;
    component[seed] = seed;
    stack.push_back(seed);
    while(!stack.empty())
    {
      const std::size_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      open = open || is_border_face(t);
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t v = vertex(t, i);
        reach = (std::max)(reach, distance[v]);
        for(std::size_t a = around.begin[v]; a < around.begin[v + 1]; ++a)
        {
          const std::size_t u = around.faces[a];
          if(unwitnessed[u] && component[u] == std::size_t(-1) && shares_edge(t, u))
          {
            component[u] = seed;
            stack.push_back(u);
          }
        }
      }
    }
    if(reach > max_gap || open)
    {
      ++membranes;
      for(const std::size_t t : members)
        removed[t] = 1;
    }
  }
  if(membranes == 0)
    return 0;
  // One fan per vertex.  Fans: the faces around v connected through edges at v.
  std::vector<std::size_t> queue;
  for(std::size_t v = 0; v < nv; ++v)
    queue.push_back(v);
  std::vector<std::size_t> local, fan;
  while(!queue.empty())
  {
    const std::size_t v = queue.back();
    queue.pop_back();
    local.clear();
    for(std::size_t a = around.begin[v]; a < around.begin[v + 1]; ++a)
      if(!removed[around.faces[a]])
        local.push_back(around.faces[a]);
    if(local.size() < 2)
      continue;
    fan.assign(local.size(), std::size_t(-1));
    std::size_t fans = 0;
    std::vector<std::size_t> size;
    for(std::size_t s = 0; s < local.size(); ++s)
    {
      if(fan[s] != std::size_t(-1))
        continue;
      fan[s] = fans;
      size.push_back(0);
      stack.assign(1, s);
      while(!stack.empty())
      {
        const std::size_t x = stack.back();
        stack.pop_back();
        ++size[fans];
        for(std::size_t y = 0; y < local.size(); ++y)
          if(fan[y] == std::size_t(-1) && shares_edge(local[x], local[y]))
          {
            fan[y] = fans;
            stack.push_back(y);
          }
      }
      ++fans;
    }
    if(fans < 2)
      continue;
    const std::size_t keep = std::size_t(std::max_element(size.begin(), size.end()) - size.begin());
    for(std::size_t s = 0; s < local.size(); ++s)
      if(fan[s] != keep)
      {
        removed[local[s]] = 1;
        for(int i = 0; i < 3; ++i)
          if(vertex(local[s], i) != v)
            queue.push_back(vertex(local[s], i));
      }
  }
  // Compact, keeping the order of what stays.
  std::vector<std::size_t> new_index(nv, std::size_t(-1));
  std::vector<typename PointOutRange::value_type> kept_points;
  std::vector<typename TriangleRange::value_type> kept_triangles;
  for(std::size_t t = 0; t < nt; ++t)
    if(!removed[t])
    {
      std::array<std::size_t, 3> tri;
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t v = vertex(t, i);
        if(new_index[v] == std::size_t(-1))
        {
          new_index[v] = first_vertex + kept_points.size();
          kept_points.push_back(points[first_vertex + v]);
        }
        tri[std::size_t(i)] = new_index[v];
      }
      kept_triangles.push_back(typename TriangleRange::value_type{tri[0], tri[1], tri[2]});
    }
  points.erase(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  points.insert(points.end(), kept_points.begin(), kept_points.end());
  triangles.erase(triangles.begin() + std::ptrdiff_t(first_triangle), triangles.end());
  triangles.insert(triangles.end(), kept_triangles.begin(), kept_triangles.end());
  return membranes;
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_REPAIR_H
