// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CHECK_CLOSED_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CHECK_CLOSED_SOUP_H

// The linear-time checks that a triangle soup in flat arrays bounds a
// solid: indices in range, no repeated vertex, every directed edge matched
// by its opposite.  Shared by the volume (surveyor_volume.h) and the
// classification of soups (Marching Cubes CSG).

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Huge_pages.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Indices in range and three distinct vertices per triangle: what
// check_soup_is_closed and the volume loop assume.
template <typename TriangleArray>
void check_triangle_indices(const TriangleArray& triangles, std::size_t number_of_points)
{
  std::size_t face_number = 0;
  for(const auto& t : triangles)
  {
    const bool in_range = std::size_t(t[0]) < number_of_points && std::size_t(t[1]) < number_of_points &&
                          std::size_t(t[2]) < number_of_points;
    if(!in_range || t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
      for(int i = 0; i < 3; ++i)
        if(std::size_t(t[i]) >= number_of_points)
          throw Invalid_input_error("triangle #" + std::to_string(face_number) + " refers to point " +
                                    std::to_string(t[i]) + ", but there are " + std::to_string(number_of_points) +
                                    " points");
      throw Invalid_input_error("triangle #" + std::to_string(face_number) + " repeats a vertex (it is degenerate)");
    }
    ++face_number;
  }
}

// Checks that a polygon soup bounds a solid: every directed edge (a,b) is
// matched by as many edges (b,a).  That is the exact condition under which
// the sum of signed tetrahedra does not depend on the reference point (each
// edge's contribution cancels against its opposite), so it is what the
// result's meaning needs -- no more (non-manifold vertices are fine).
template <typename TriangleIndices>
void check_soup_is_closed(const std::vector<TriangleIndices>& triangles, std::size_t number_of_points)
{
  // Bucket the 3n directed edges by their smaller endpoint (a counting
  // sort, linear), store (larger endpoint, direction) and sort each small
  // bucket: then (a, b) and (b, a) are neighbours.  O(n) for bounded vertex
  // degrees, instead of a global sort.
  std::vector<std::uint32_t> first(number_of_points + 1, 0);
  for(const TriangleIndices& t : triangles)
    for(int i = 0; i < 3; ++i)
      ++first[std::min(t[i], t[(i + 1) % 3]) + 1];
  for(std::size_t v = 0; v < number_of_points; ++v)
    first[v + 1] += first[v];
  // Every entry is written below: no zero-filling of 3n words first.
  std::vector<std::uint64_t, Default_init_allocator<std::uint64_t>> entries;
  reserve_in_huge_pages(entries, first.back());
  entries.resize(first.back());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for(const TriangleIndices& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      const std::uint32_t low = std::min(a, b), high = std::max(a, b);
      entries[fill[low]++] = (std::uint64_t(high) << 1) | std::uint64_t(a > b);
    }

  for(std::size_t low = 0; low < number_of_points; ++low)
  {
    const auto begin = entries.begin() + first[low], end = entries.begin() + first[low + 1];
    if(end - begin <= 16)
      for(auto i = begin + 1; i < end; ++i) // insertion sort: buckets hold ~6 entries
      {
        const std::uint64_t v = *i;
        auto j = i;
        for(; j != begin && *(j - 1) > v; --j) *j = *(j - 1);
        *j = v;
      }
    else
      std::sort(begin, end);
    for(auto run = begin; run != end;)
    {
      const std::uint64_t high = *run >> 1;
      std::ptrdiff_t balance = 0; // (low, high) edges minus (high, low) edges
      auto it = run;
      for(; it != end && (*it >> 1) == high; ++it)
        balance += (*it & 1) ? -1 : 1;
      if(balance != 0)
      {
        std::ostringstream out;
        out << "the polygon soup is not closed: edge (" << low << ", " << high << ") is used "
            << std::count(run, it, (high << 1)) << " time(s) but its opposite (" << high << ", " << low << ") "
            << std::count(run, it, (high << 1) | 1)
            << " time(s) (a border edge, or inconsistently oriented faces)";
        throw Open_mesh_error(out.str());
      }
      run = it;
    }
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CHECK_CLOSED_SOUP_H
