// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_STL_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_STL_H

// STL, binary and ASCII.  STL has no shared vertices: each facet lists its
// own corners, so the corners are welded into points by *exact* coordinate
// equality (the bits of the three doubles, -0 taken as +0), which is what
// restores the connectivity of a mesh that was written without rounding.
// Nothing is merged by distance: near-coincident corners stay distinct.

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Input_buffer.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Soup_builder.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Open addressing on 32-bit slots (point index + 1, 0 = empty), linear
// probing, kept at most half full: the points themselves are the keys.
class Point_welder
{
public:
  Point_welder(std::vector<Triangle_soup_3::Point>& points, std::size_t expected_points) : m_points(points)
  {
    std::size_t capacity = 1024;
    while(capacity < 2 * expected_points) capacity *= 2;
    m_slots.assign(capacity, 0);
  }

  std::uint32_t index_of(double x, double y, double z)
  {
    x += 0.0; // -0 -> +0: equal values, one key
    y += 0.0;
    z += 0.0;
    const std::uint64_t h = hash(x, y, z);
    for(std::size_t slot = h & (m_slots.size() - 1);; slot = (slot + 1) & (m_slots.size() - 1))
    {
      const std::uint32_t s = m_slots[slot];
      if(s == 0)
      {
        check_point_count(m_points.size() + 1);
        m_points.push_back({x, y, z});
        m_slots[slot] = std::uint32_t(m_points.size());
        if(2 * m_points.size() > m_slots.size())
          grow();
        return std::uint32_t(m_points.size() - 1);
      }
      const auto& p = m_points[s - 1];
      if(p[0] == x && p[1] == y && p[2] == z)
        return s - 1;
    }
  }

private:
  static std::uint64_t bits(double v)
  {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    return b;
  }
  static std::uint64_t hash(double x, double y, double z)
  {
    std::uint64_t h = bits(x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(y) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
    h ^= bits(z) * 0x165667B19E3779F9ull + (h >> 31);
    return h ^ (h >> 32);
  }
  void grow()
  {
    std::vector<std::uint32_t> old(2 * m_slots.size(), 0);
    old.swap(m_slots);
    const std::size_t mask = m_slots.size() - 1;
    for(std::uint32_t s : old)
      if(s != 0)
      {
        const auto& p = m_points[s - 1];
        std::size_t slot = hash(p[0], p[1], p[2]) & mask;
        while(m_slots[slot] != 0) slot = (slot + 1) & mask;
        m_slots[slot] = s;
      }
  }

  std::vector<Triangle_soup_3::Point>& m_points;
  std::vector<std::uint32_t> m_slots;
};

inline void read_binary_STL(const char* begin, const char* end, Triangle_soup_3& soup, std::uint64_t facets)
{
  soup.points.clear();
  soup.triangles.clear();
  reserve_in_huge_pages(soup.triangles, std::size_t(facets));
  // A closed triangle mesh has about half as many points as facets.
  Point_welder welder(soup.points, std::size_t(facets / 2 + 4));
  const char* p = begin + 84;
  for(std::uint64_t f = 0; f < facets; ++f, p += 50)
  {
    float c[12];
    std::memcpy(c, p, 48);
    little_endian_to_host(c, 12);
    std::uint32_t t[3];
    for(int k = 0; k < 3; ++k)
    {
      const double x = c[3 + 3 * k], y = c[4 + 3 * k], z = c[5 + 3 * k];
      if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
        throw Non_finite_value_error("facet " + std::to_string(f) + " (byte " +
                                     std::to_string(std::size_t(p - begin)) + "): corner " + std::to_string(k) +
                                     " has a non-finite coordinate (" + describe_non_finite(x, y, z) + ")");
      t[k] = welder.index_of(x, y, z);
    }
    soup.triangles.push_back({t[0], t[1], t[2]});
  }
  (void)end;
  soup.unwelded_corners = std::size_t(3 * facets);
}

inline void read_ASCII_STL(const char* begin, const char* end, Triangle_soup_3& soup)
{
  Text_cursor in(begin, end);
  soup.points.clear();
  soup.triangles.clear();
  // A facet takes about 250 bytes of text.
  Point_welder welder(soup.points, std::size_t(end - begin) / 500 + 4);
  std::vector<std::uint32_t> polygon;
  std::size_t facet = 0, corners = 0;
  if(!in.accept("solid"))
    in.fail("cannot parse it as ASCII STL: expected 'solid', found " + in.found());
  in.skip_line();
  const auto expect = [&](const char* word) {
    if(!in.accept(word))
      in.fail(std::string("facet ") + std::to_string(facet) + ": expected '" + word + "', found " + in.found());
  };
  for(;;)
  {
    in.skip_spaces();
    if(in.at_end())
      break;
    if(in.accept("endsolid"))
    {
      in.skip_line();
      in.skip_spaces();
      if(in.at_end())
        break;
      expect("solid"); // several solids in one file
      in.skip_line();
      continue;
    }
    expect("facet");
    expect("normal");
    for(int k = 0; k < 3; ++k)
    {
      double ignored;
      if(!in.parse_double(ignored))
        in.fail("facet " + std::to_string(facet) + ": cannot parse its normal: expected a number, found " +
                in.found());
    }
    expect("outer");
    expect("loop");
    polygon.clear();
    while(in.accept("vertex"))
    {
      const char* at = in.p;
      double c[3];
      for(int k = 0; k < 3; ++k)
        if(!in.parse_double(c[k]))
          in.fail("facet " + std::to_string(facet) + ": cannot parse coordinate " + std::to_string(k + 1) +
                  " of a vertex: expected a number, found " + in.found());
      if(!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        in.fail_at(at, "facet " + std::to_string(facet) + " has a vertex with a non-finite coordinate (" +
                           describe_non_finite(c[0], c[1], c[2]) + ")");
      polygon.push_back(welder.index_of(c[0], c[1], c[2]));
    }
    if(polygon.size() < 3)
      in.fail("facet " + std::to_string(facet) + " has " + std::to_string(polygon.size()) +
              " vertices; a facet needs at least 3");
    expect("endloop");
    expect("endfacet");
    corners += polygon.size();
    add_fan_of_triangles(soup, polygon.data(), polygon.size());
    ++facet;
  }
  soup.unwelded_corners = corners;
}

inline void read_STL(const char* begin, const char* end, Triangle_soup_3& soup)
{
  const std::uint64_t size = std::uint64_t(end - begin);
  std::uint32_t facets = 0;
  if(size >= 84)
  {
    std::memcpy(&facets, begin + 80, 4);
    little_endian_to_host(&facets, 1);
    // The size decides, not the first word: binary files often start with
    // "solid" too.
    if(size == 84 + 50 * std::uint64_t(facets))
      return read_binary_STL(begin, end, soup, facets);
  }
  // A NUL byte cannot be in ASCII STL: a binary file whose size does not
  // match its facet count (truncated) even if it starts with "solid".
  const bool binary = size >= 84 && std::memchr(begin, '\0', std::size_t(std::min<std::uint64_t>(size, 4096))) != nullptr;
  Text_cursor probe(begin, end);
  probe.skip_spaces();
  if(!binary &&std::size_t(end - probe.p) >= 5 && std::memcmp(probe.p, "solid", 5) == 0 && is_text_space(probe.p[5]))
    return read_ASCII_STL(begin, end, soup);
  if(size < 84)
    throw Invalid_input_error("cannot parse it as STL: " + std::to_string(size) +
                              " bytes, too short for binary STL, and it does not start with 'solid'");
  throw Invalid_input_error("cannot parse it as STL: the binary header declares " + std::to_string(facets) +
                            " facets, which need " + std::to_string(84 + 50 * std::uint64_t(facets)) +
                            " bytes, but the file has " + std::to_string(size) + " (truncated or corrupt)");
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_STL_H
