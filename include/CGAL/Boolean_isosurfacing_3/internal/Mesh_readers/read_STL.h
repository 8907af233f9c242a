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
#include <cstdlib>
#include <memory>
#include <new>
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

// The welder of binary STL, whose corners are floats.  Open addressing on
// 8-byte slots (32 bits of the key's hash, point index + 1; 0 = empty),
// linear probing, at most 7/10 full.  A matching hash is confirmed against
// the point itself: the points a lookup finds are almost always recent ones
// (a mesh's facets come in an order where shared corners are near each
// other), so that read hits the cache.  Float to double is injective, so
// welding the floats welds exactly the doubles that Point_welder would.
//
// At 1M+ facets the table is larger than the caches and each new point is a
// miss; corners are therefore looked up in batches: hash the batch and
// prefetch every slot, then probe, so that the misses overlap instead of
// waiting for each other.  Small slots matter as much: the fresh table is
// zeroed page by page by the kernel, which cost more than the lookups with
// 16-byte slots holding the key (measured on a 1.2M-facet file).
class Float_triple_welder
{
public:
  static constexpr std::size_t batch = 96; // corners per lookup batch

  // `facets` is proven by the file size (84 + 50 facets bytes), so the
  // table, at most about two slots per facet, is proportional to the file.
  Float_triple_welder(std::vector<Triangle_soup_3::Point>& points, std::uint64_t facets) : m_points(points)
  {
    // A closed mesh has about facets / 2 points: start at a load of 0.35 to
    // 0.7 for it, and grow (rarely) for soups with more points.
    std::size_t capacity = 1024;
    while(10 * (facets / 2 + batch) > 7 * capacity) capacity *= 2;
    allocate(capacity);
  }

  // `keys[k]` (k < n <= batch) are finite float triples with -0 made +0;
  // writes their point indices to `out`, adding unseen ones to the points
  // in order of first use.
  void index_batch(const std::uint32_t (*keys)[3], std::size_t n, std::uint32_t* out)
  {
    if(10 * (m_points.size() + n) > 7 * m_capacity) // no growth inside a batch: the slots stay valid
      grow();
    // Pass 1: a corner equal to one of the 5 corners before it (which
    // cover the previous facet) takes that corner's index, without a
    // lookup: in the facet order of meshes written from a mesh data
    // structure, about half of the corners repeat a corner of the previous
    // facet.  The others are hashed and their slots prefetched.
    std::uint64_t h[batch];
    std::uint8_t back[batch];
    for(std::size_t k = 0; k < n; ++k)
    {
      back[k] = 0;
      for(std::size_t d = 1; d <= 5 && d <= k; ++d)
        if(same_key(keys[k], keys[k - d]))
        {
          back[k] = std::uint8_t(d);
          break;
        }
      if(back[k] != 0)
        continue;
      h[k] = hash(keys[k]);
      __builtin_prefetch(m_slots + (h[k] >> m_shift));
    }
    // Pass 2, in order: the points are numbered in order of first use.
    const std::size_t mask = m_capacity - 1;
    for(std::size_t k = 0; k < n; ++k)
    {
      if(back[k] != 0)
      {
        out[k] = out[k - back[k]];
        continue;
      }
      float f[3];
      std::memcpy(f, keys[k], 12);
      const double x = f[0], y = f[1], z = f[2];
      const std::uint64_t tag = tag_of(h[k]);
      for(std::size_t s = std::size_t(h[k] >> m_shift);; s = (s + 1) & mask)
      {
        const std::uint64_t e = m_slots[s];
        if(e == 0)
        {
          check_point_count(m_points.size() + 1);
          m_points.push_back({x, y, z});
          m_slots[s] = tag | std::uint64_t(m_points.size());
          out[k] = std::uint32_t(m_points.size() - 1);
          break;
        }
        if((e & ~std::uint64_t(0xffffffffu)) == tag)
        {
          const auto& p = m_points[std::size_t(std::uint32_t(e)) - 1];
          if(p[0] == x && p[1] == y && p[2] == z)
          {
            out[k] = std::uint32_t(e) - 1;
            break;
          }
        }
      }
    }
  }

private:
  static bool same_key(const std::uint32_t* a, const std::uint32_t* b)
  {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
  }

  static std::uint64_t hash(const std::uint32_t* key)
  {
    // Multiplicative (Fibonacci) hashing: the high bits of the product,
    // which depend on every bit of the key, pick the slot.
    const std::uint64_t xy = std::uint64_t(key[0]) | (std::uint64_t(key[1]) << 32);
    return (xy ^ (std::uint64_t(key[2]) * 0xC2B2AE3D27D4EB4Full)) * 0x9E3779B97F4A7C15ull;
  }
  // 32 bits of the hash stored in the slot, mixed from both halves of it.
  static std::uint64_t tag_of(std::uint64_t h) { return (h ^ (h >> 32)) << 32; }

  void allocate(std::size_t capacity)
  {
    m_table = Zeroed_array(capacity);
    m_slots = m_table.data();
    m_capacity = capacity;
    m_shift = 64;
    for(std::size_t c = capacity; c > 1; c /= 2) --m_shift;
  }

  void grow()
  {
    Zeroed_array old = std::move(m_table);
    const std::size_t old_capacity = m_capacity;
    allocate(2 * old_capacity);
    const std::size_t mask = m_capacity - 1;
    for(std::size_t i = 0; i < old_capacity; ++i)
    {
      const std::uint64_t e = old.data()[i];
      if(e == 0)
        continue;
      const auto& p = m_points[std::size_t(std::uint32_t(e)) - 1];
      const float f[3] = {float(p[0]), float(p[1]), float(p[2])};
      std::uint32_t key[3];
      std::memcpy(key, f, 12);
      std::size_t s = std::size_t(hash(key) >> m_shift);
      while(m_slots[s] != 0) s = (s + 1) & mask;
      m_slots[s] = e;
    }
  }

  // calloc: fresh pages from the kernel are already zero, so a large table
  // is not written twice.
  class Zeroed_array
  {
  public:
    Zeroed_array() = default;
    explicit Zeroed_array(std::size_t n) : m_data(static_cast<std::uint64_t*>(std::calloc(n, 8)))
    {
      if(m_data == nullptr)
        throw std::bad_alloc();
      advise_huge_pages(m_data.get(), 8 * n);
    }
    std::uint64_t* data() const { return m_data.get(); }

  private:
    struct Free
    {
      void operator()(std::uint64_t* p) const { std::free(p); }
    };
    std::unique_ptr<std::uint64_t[], Free> m_data;
  };

  std::vector<Triangle_soup_3::Point>& m_points;
  Zeroed_array m_table;
  std::uint64_t* m_slots = nullptr;
  std::size_t m_capacity = 0;
  unsigned m_shift = 64;
};

[[noreturn]] inline void fail_non_finite_STL_corner(const char* begin, std::uint64_t facet, int corner)
{
  const char* p = begin + 84 + 50 * facet;
  float c[3];
  std::memcpy(c, p + 12 + 12 * corner, 12);
  little_endian_to_host(c, 3);
  throw Non_finite_value_error("facet " + std::to_string(facet) + " (byte " + std::to_string(84 + 50 * facet) +
                               "): corner " + std::to_string(corner) + " has a non-finite coordinate (" +
                               describe_non_finite(c[0], c[1], c[2]) + ")");
}

inline void read_binary_STL(const char* begin, const char* end, Triangle_soup_3& soup, std::uint64_t facets)
{
  soup.points.clear();
  soup.triangles.clear();
  reserve_in_huge_pages(soup.triangles, std::size_t(facets));
  // A closed triangle mesh has about half as many points as facets.
  reserve_in_huge_pages(soup.points, std::size_t(facets / 2 + 4));
  Float_triple_welder welder(soup.points, facets);
  constexpr std::size_t facets_per_batch = Float_triple_welder::batch / 3;
  std::uint32_t keys[3 * facets_per_batch][3];
  std::uint32_t index[3 * facets_per_batch];
  const char* p = begin + 84;
  for(std::uint64_t f0 = 0; f0 < facets; f0 += facets_per_batch)
  {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(facets_per_batch, facets - f0));
    std::uint32_t non_finite = 0;
    for(std::size_t i = 0; i < n; ++i, p += 50)
    {
      std::memcpy(keys[3 * i], p + 12, 36); // the three corners, after the normal
      little_endian_to_host(&keys[3 * i][0], 9);
      for(int k = 0; k < 9; ++k)
      {
        std::uint32_t& b = keys[3 * i + std::size_t(k / 3)][k % 3];
        non_finite |= std::uint32_t((b & 0x7f800000u) == 0x7f800000u); // exponent all ones: inf or NaN
        b = (b & 0x7fffffffu) == 0 ? 0 : b;                              // -0 -> +0: equal values, one key
      }
    }
    if(non_finite != 0)
      for(std::size_t i = 0; i < 3 * n; ++i)
        for(int k = 0; k < 3; ++k)
          if((keys[i][k] & 0x7f800000u) == 0x7f800000u)
            fail_non_finite_STL_corner(begin, f0 + i / 3, int(i % 3));
    welder.index_batch(keys, 3 * n, index);
    for(std::size_t i = 0; i < n; ++i)
      soup.triangles.push_back({index[3 * i], index[3 * i + 1], index[3 * i + 2]});
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
