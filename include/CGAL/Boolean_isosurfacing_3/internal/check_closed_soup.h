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

// Sorts the k <= N entries of one bucket with Batcher's odd-even merge sort
// network (N = 8: 19 compare-exchanges, N = 16: 63), branch-free, and tells
// whether they pair up as a consistently oriented 2-manifold's edges do:
// (high, up) followed by (high, down), once each.  The bucket sizes of a mesh
// vary from vertex to vertex, so an insertion sort mispredicts a branch on
// almost every entry: that was three quarters of the check.
template <int N, typename Entry>
bool sorted_bucket_pairs_up(const Entry* bucket, std::ptrdiff_t k)
{
  Entry e[N];
  for(int i = 0; i < N; ++i)
    e[i] = i < k ? bucket[i] : Entry(-1); // the padding sorts last
  auto cx = [&e](int i, int j) {
    const Entry x = e[i], y = e[j];
    e[i] = x < y ? x : y;
    e[j] = x < y ? y : x;
  };
  if constexpr(N == 8)
  {
    cx(0, 1); cx(2, 3); cx(4, 5); cx(6, 7); cx(0, 2); cx(1, 3); cx(4, 6); cx(5, 7); cx(1, 2); cx(5, 6);
    cx(0, 4); cx(1, 5); cx(2, 6); cx(3, 7); cx(2, 4); cx(3, 5); cx(1, 2); cx(3, 4); cx(5, 6);
  }
  else
  {
    static_assert(N == 16, "networks for 8 and 16 entries only");
    cx(0, 1); cx(2, 3); cx(4, 5); cx(6, 7); cx(8, 9); cx(10, 11); cx(12, 13); cx(14, 15); cx(0, 2); cx(1, 3);
    cx(4, 6); cx(5, 7); cx(8, 10); cx(9, 11); cx(12, 14); cx(13, 15); cx(1, 2); cx(5, 6); cx(9, 10); cx(13, 14);
    cx(0, 4); cx(1, 5); cx(2, 6); cx(3, 7); cx(8, 12); cx(9, 13); cx(10, 14); cx(11, 15); cx(2, 4); cx(3, 5);
    cx(10, 12); cx(11, 13); cx(1, 2); cx(3, 4); cx(5, 6); cx(9, 10); cx(11, 12); cx(13, 14); cx(0, 8); cx(1, 9);
    cx(2, 10); cx(3, 11); cx(4, 12); cx(5, 13); cx(6, 14); cx(7, 15); cx(4, 8); cx(5, 9); cx(6, 10); cx(7, 11);
    cx(2, 4); cx(3, 5); cx(6, 8); cx(7, 9); cx(10, 12); cx(11, 13); cx(1, 2); cx(3, 4); cx(5, 6); cx(7, 8);
    cx(9, 10); cx(11, 12); cx(13, 14);
  }
  Entry unpaired = Entry(k & 1);
  for(int i = 0; i < N; i += 2)
    unpaired |= i < k ? ((e[i] & 1) | (e[i] ^ 1 ^ e[i + 1])) : Entry(0);
  return unpaired == 0;
}

// An entry is (larger endpoint << 1 | direction), in the bucket of the smaller
// endpoint; Offset indexes the 3n entries.
template <typename Entry, typename Offset, typename TriangleIndices>
void check_soup_is_closed_with(const std::vector<TriangleIndices>& triangles, std::size_t number_of_points)
{
  // A counting sort of the 3n directed edges by their smaller endpoint.
  // bound[v] first counts v's bucket, then (prefix sums) marks its end, and
  // the backward fill leaves it at its begin: no second array of offsets.
  std::vector<Offset, Default_init_allocator<Offset>> bound(number_of_points + 1);
  std::fill(bound.begin(), bound.end(), Offset(0));
  for(const TriangleIndices& t : triangles)
  {
    const Entry a = Entry(t[0]), b = Entry(t[1]), c = Entry(t[2]);
    ++bound[std::min(a, b)];
    ++bound[std::min(b, c)];
    ++bound[std::min(c, a)];
  }
  Offset sum = 0;
  for(std::size_t v = 0; v < number_of_points; ++v)
  {
    sum += bound[v];
    bound[v] = sum;
  }
  bound[number_of_points] = sum;
  // Every entry is written below: no zero-filling of 3n words first.
  std::vector<Entry, Default_init_allocator<Entry>> entries;
  reserve_in_huge_pages(entries, std::size_t(sum));
  entries.resize(std::size_t(sum));
  for(const TriangleIndices& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      const Entry a = Entry(t[i]), b = Entry(t[i == 2 ? 0 : i + 1]);
      const bool down = a > b;
      entries[--bound[down ? b : a]] = (Entry(down ? a : b) << 1) | Entry(down);
    }

  // Every directed edge (a, b) must be matched by as many edges (b, a):
  // within a sorted bucket, the entries of each larger endpoint balance.
  const auto check_balance = [&](std::size_t low, Entry* begin, Entry* end) {
    std::sort(begin, end);
    for(Entry* run = begin; run != end;)
    {
      const Entry high = *run >> 1;
      std::ptrdiff_t balance = 0; // (low, high) edges minus (high, low) edges
      Entry* it = run;
      for(; it != end && (*it >> 1) == high; ++it)
        balance += (*it & 1) ? -1 : 1;
      if(balance != 0)
      {
        std::ostringstream out;
        out << "the polygon soup is not closed: edge (" << low << ", " << high << ") is used "
            << std::count(run, it, Entry(high << 1)) << " time(s) but its opposite (" << high << ", " << low
            << ") " << std::count(run, it, Entry((high << 1) | 1))
            << " time(s) (a border edge, or inconsistently oriented faces)";
        throw Open_mesh_error(out.str());
      }
      run = it;
    }
  };
  for(std::size_t low = 0; low < number_of_points; ++low)
  {
    Entry* begin = entries.data() + bound[low];
    Entry* end = entries.data() + bound[low + 1];
    const std::ptrdiff_t k = end - begin;
    // The common case, each edge once in each direction, on a network; the
    // rest (non-manifold edges, high degrees, an open soup) on the general count.
    const bool paired = k <= 8 ? sorted_bucket_pairs_up<8>(begin, k)
                               : k <= 16 && sorted_bucket_pairs_up<16>(begin, k);
    if(!paired)
      check_balance(low, begin, end);
  }
}

// Checks that a polygon soup bounds a solid: every directed edge (a,b) is
// matched by as many edges (b,a).  That is the exact condition under which
// the sum of signed tetrahedra does not depend on the reference point (each
// edge's contribution cancels against its opposite), so it is what the
// result's meaning needs -- no more (non-manifold vertices are fine).
// Linear time: a counting sort of the directed edges by their smaller
// endpoint, then a small sort per vertex.  Indices must be in range
// (check_triangle_indices).
template <typename TriangleIndices>
void check_soup_is_closed(const std::vector<TriangleIndices>& triangles, std::size_t number_of_points)
{
  // 32-bit entries and offsets whenever they fit: half the memory traffic.
  const bool small_entries = number_of_points < (std::size_t(1) << 31);
  const bool small_offsets = 3 * triangles.size() < (std::size_t(1) << 32);
  if(small_entries && small_offsets)
    check_soup_is_closed_with<std::uint32_t, std::uint32_t>(triangles, number_of_points);
  else if(small_entries)
    check_soup_is_closed_with<std::uint32_t, std::uint64_t>(triangles, number_of_points);
  else
    check_soup_is_closed_with<std::uint64_t, std::uint64_t>(triangles, number_of_points);
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CHECK_CLOSED_SOUP_H
