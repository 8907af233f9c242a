// Test support: a triangle soup written in every format and variant the
// mesh readers accept, so that the tests (and the reader benchmark) can read
// the same mesh back from each and compare.  Independent of the package's
// own writers on purpose, except for sharing Triangle_soup_3.

#ifndef BISO_TEST_MESH_FORMAT_WRITERS_H
#define BISO_TEST_MESH_FORMAT_WRITERS_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

namespace biso_test {

using CGAL::Boolean_isosurfacing::Triangle_soup_3;

inline std::string decimal(double v)
{
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

inline std::string to_OBJ(const Triangle_soup_3& s, bool slashes = false)
{
  std::string o = "# test mesh\no thing\n";
  for(const auto& p : s.points) o += "v " + decimal(p[0]) + " " + decimal(p[1]) + " " + decimal(p[2]) + "\n";
  o += "vn 0 0 1\ns off\n";
  for(const auto& t : s.triangles)
  {
    o += "f";
    for(std::uint32_t v : t) o += " " + std::to_string(v + 1) + (slashes ? "//1" : "");
    o += "\n";
  }
  return o;
}

inline std::string to_ASCII_PLY(const Triangle_soup_3& s, const std::string& coordinate_type = "double")
{
  std::string o = "ply\nformat ascii 1.0\ncomment test\nelement vertex " + std::to_string(s.points.size()) +
                  "\nproperty " + coordinate_type + " x\nproperty " + coordinate_type + " y\nproperty " +
                  coordinate_type + " z\nelement face " + std::to_string(s.triangles.size()) +
                  "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : s.points) o += decimal(p[0]) + " " + decimal(p[1]) + " " + decimal(p[2]) + "\n";
  for(const auto& t : s.triangles)
    o += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  return o;
}

template <typename T>
void put(std::string& o, T v, bool big_endian)
{
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if(big_endian) std::reverse(b, b + sizeof(T)); // the tests run on little-endian hosts
  o.append(b, sizeof(T));
}

// Binary PLY with coordinates of type Coordinate (named `coordinate_name`),
// a list count of type Count and indices of type Index, and an extra
// per-vertex property and an extra element to skip.
template <typename Coordinate, typename Count, typename Index>
std::string to_binary_PLY(const Triangle_soup_3& s, bool big_endian, const std::string& coordinate_name,
                          const std::string& count_name, const std::string& index_name)
{
  std::string o = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex " + std::to_string(s.points.size()) + "\nproperty " + coordinate_name +
                  " x\nproperty " + coordinate_name + " y\nproperty uchar red\nproperty " + coordinate_name +
                  " z\nelement face " + std::to_string(s.triangles.size()) + "\nproperty list " + count_name + " " +
                  index_name + " vertex_indices\nelement extra 2\nproperty list uchar float stuff\nend_header\n";
  for(const auto& p : s.points)
  {
    put(o, Coordinate(p[0]), big_endian);
    put(o, Coordinate(p[1]), big_endian);
    put(o, std::uint8_t(7), big_endian);
    put(o, Coordinate(p[2]), big_endian);
  }
  for(const auto& t : s.triangles)
  {
    put(o, Count(3), big_endian);
    for(std::uint32_t v : t) put(o, Index(v), big_endian);
  }
  put(o, std::uint8_t(1), big_endian);
  put(o, 1.5f, big_endian);
  put(o, std::uint8_t(0), big_endian);
  return o;
}

inline std::string to_ASCII_STL(const Triangle_soup_3& s)
{
  std::string o = "solid test\n";
  for(const auto& t : s.triangles)
  {
    o += "  facet normal 0 0 0\n    outer loop\n";
    for(std::uint32_t v : t)
      o += "      vertex " + decimal(s.points[v][0]) + " " + decimal(s.points[v][1]) + " " + decimal(s.points[v][2]) +
           "\n";
    o += "    endloop\n  endfacet\n";
  }
  return o + "endsolid test\n";
}

// Binary STL stores floats: exact only for coordinates that are floats.
inline std::string to_binary_STL(const Triangle_soup_3& s)
{
  std::string o(80, ' ');
  std::memcpy(&o[0], "solid binary, not ascii", 23);
  put(o, std::uint32_t(s.triangles.size()), false);
  for(const auto& t : s.triangles)
  {
    for(int k = 0; k < 3; ++k) put(o, 0.0f, false);
    for(std::uint32_t v : t)
      for(int k = 0; k < 3; ++k) put(o, float(s.points[v][std::size_t(k)]), false);
    put(o, std::uint16_t(0), false);
  }
  return o;
}

// x rounded to float.  Through a volatile: g++ 12 -O2 was seen to drop a
// plain double(float(x * std::cos(u))).
inline double rounded_to_float(double x)
{
  volatile float f = float(x);
  return f;
}

// A closed, outward torus of n*m*2 triangles with coordinates that are
// floats (so every format, binary STL included, stores them exactly).
inline Triangle_soup_3 float_torus(std::uint32_t n, std::uint32_t m, double R = 1.0, double r = 0.4)
{
  Triangle_soup_3 s;
  const double pi = 3.14159265358979323846;
  for(std::uint32_t i = 0; i < n; ++i)
    for(std::uint32_t j = 0; j < m; ++j)
    {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      s.points.push_back({rounded_to_float((R + r * std::cos(v)) * std::cos(u)),
                          rounded_to_float((R + r * std::cos(v)) * std::sin(u)), rounded_to_float(r * std::sin(v))});
    }
  for(std::uint32_t i = 0; i < n; ++i)
    for(std::uint32_t j = 0; j < m; ++j)
    {
      const std::uint32_t a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                          d = i * m + (j + 1) % m;
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({a, c, d});
    }
  return s;
}

} // namespace biso_test

#endif // BISO_TEST_MESH_FORMAT_WRITERS_H
