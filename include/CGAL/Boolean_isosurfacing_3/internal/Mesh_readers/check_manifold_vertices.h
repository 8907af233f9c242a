// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_CHECK_MANIFOLD_VERTICES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_CHECK_MANIFOLD_VERTICES_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// For a closed soup (every directed edge matched by its opposite), checks
// that it is also a 2-manifold, which a halfedge data structure needs: each
// directed edge occurs once, and the triangles around each vertex form one
// fan.  The link of vertex v is the set of arcs b -> c, one per triangle
// (v, b, c); it must be a single cycle.  Linear time: a counting sort of the
// 3n arcs by vertex, then a sort of each (small) link.
template <typename TriangleArray>
void check_manifold_vertices(const TriangleArray& triangles, std::size_t number_of_points)
{
  std::vector<std::uint32_t> first(number_of_points + 1, 0);
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) ++first[std::size_t(t[i]) + 1];
  for(std::size_t v = 0; v < number_of_points; ++v) first[v + 1] += first[v];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs(first.back());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
      arcs[fill[t[i]]++] = {std::uint32_t(t[(i + 1) % 3]), std::uint32_t(t[(i + 2) % 3])};

  for(std::size_t v = 0; v < number_of_points; ++v)
  {
    const auto begin = arcs.begin() + first[v], end = arcs.begin() + first[v + 1];
    if(begin == end)
      continue;
    std::sort(begin, end);
    for(auto it = begin + 1; it != end; ++it)
      if(it->first == (it - 1)->first)
        throw Invalid_input_error("it is closed but has a non-manifold edge (" + std::to_string(v) + ", " +
                                  std::to_string(it->first) + ") shared by more than two triangles");
    // Walk the cycle from the first arc: it must visit every arc.
    std::size_t steps = 0;
    std::uint32_t at = begin->first;
    do
    {
      const auto arc = std::lower_bound(begin, end, std::make_pair(at, std::uint32_t(0)));
      if(arc == end || arc->first != at)
        break; // cannot happen in a closed soup; reported as non-manifold
      at = arc->second;
      ++steps;
    } while(at != begin->first && steps <= std::size_t(end - begin));
    if(steps != std::size_t(end - begin))
      throw Invalid_input_error("it is closed but has a non-manifold vertex (point #" + std::to_string(v) +
                                ": its triangles form several fans); split it first "
                                "(PMP::duplicate_non_manifold_vertices)");
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_CHECK_MANIFOLD_VERTICES_H
