// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_SOUP_BUILDER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_SOUP_BUILDER_H

// What every reader does with what it parsed: polygons become triangles,
// header counts are checked against the bytes that must hold them.

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Huge_pages.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Appends the polygon v[0..k) (k >= 3, indices already checked) as a fan of
// triangles from v[0]: exact for convex polygons, which is what the formats'
// writers produce for quads and n-gons.
inline void add_fan_of_triangles(Triangle_soup_3& soup, const std::uint32_t* v, std::size_t k)
{
  if(k == 3)
  {
    soup.triangles.push_back({v[0], v[1], v[2]});
    return;
  }
  for(std::size_t i = 1; i + 1 < k; ++i)
    soup.triangles.push_back({v[0], v[std::size_t(i)], v[i + 1]});
  ++soup.triangulated_polygons;
}

// A header that claims `count` elements of at least `min_bytes` bytes each
// must fit in the `available` bytes left: checked before anything is
// allocated from the count, so an 18-byte file cannot claim 10^9 vertices.
inline bool count_fits(std::uint64_t count, std::uint64_t min_bytes, std::uint64_t available)
{
  return min_bytes == 0 ? true : count <= available / min_bytes;
}

inline std::string count_error(const std::string& what, std::uint64_t count, std::uint64_t min_bytes,
                               std::uint64_t available)
{
  return "the header declares " + std::to_string(count) + " " + what + ", which need at least " +
         (min_bytes != 0 && count > (~std::uint64_t(0)) / min_bytes ? std::string("more than 2^64")
                                                                    : std::to_string(count * min_bytes)) +
         " bytes, but only " + std::to_string(available) + " bytes follow (truncated file or corrupt header)";
}

// Indices are 32-bit: more points than that cannot be indexed.
inline void check_point_count(std::uint64_t count)
{
  if(count >= (std::uint64_t(1) << 32))
    throw Invalid_input_error("the file has " + std::to_string(count) +
                              " vertices; at most 2^32 - 1 are supported");
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_SOUP_BUILDER_H
