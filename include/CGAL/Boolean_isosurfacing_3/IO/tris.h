// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIS_H

// The `.tris` triangle file of the contour-tracing assignment ([ContourTracing]):
//
//   tri[0].n
//   tri[0].p0
//   tri[0].p1
//   tri[0].p2
//   ...
//
// i.e. for each triangle four lines, each `x y z`: the unit normal
// n = cross(p1 - p0, p2 - p0) / |...| (0 0 0 for a degenerate triangle),
// then its three vertices.  No header, no blank lines.  Numbers are written
// with 17 significant digits so that reading gives back the same doubles.

#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/double.h> // CGAL::to_double(double)
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/// A triangle as stored in a `.tris` file.
struct Tris_triangle
{
  std::array<double, 3> n, p0, p1, p2;
};

/// Unit normal of (p0, p1, p2) by the seed's rule, (0,0,0) if degenerate.
inline std::array<double, 3> tris_normal(const std::array<double, 3>& p0, const std::array<double, 3>& p1,
                                         const std::array<double, 3>& p2)
{
  const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
  const double v[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
  std::array<double, 3> n{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if(length > 0 && std::isfinite(length))
    for(double& c : n)
      c /= length;
  else
    n = {{0, 0, 0}};
  return n;
}

/*!
 * Writes an indexed triangle soup as `.tris`.  `points[i]` has `x()`, `y()`,
 * `z()`; each triangle is indexable by 0, 1, 2.
 * \returns whether the stream is still good.
 */
template <typename PointRange, typename TriangleRange>
bool write_tris(std::ostream& out, const PointRange& points, const TriangleRange& triangles)
{
  const auto old_precision = out.precision(17);
  auto coordinates = [&](std::size_t i) {
    const auto& p = points[i];
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto line = [&](const std::array<double, 3>& v) { out << v[0] << ' ' << v[1] << ' ' << v[2] << '\n'; };
  for(const auto& t : triangles)
  {
    const std::array<double, 3> p0 = coordinates(std::size_t(t[0])), p1 = coordinates(std::size_t(t[1])),
                                p2 = coordinates(std::size_t(t[2]));
    line(tris_normal(p0, p1, p2));
    line(p0);
    line(p1);
    line(p2);
  }
  out.precision(old_precision);
  return bool(out);
}

/// As above, into the file `path`.
template <typename PointRange, typename TriangleRange>
bool write_tris(const std::string& path, const PointRange& points, const TriangleRange& triangles)
{
  std::ofstream out(path);
  return out && write_tris(out, points, triangles);
}

/*!
 * Reads a `.tris` stream.  Blank lines are not allowed (the format has none);
 * every line is `x y z`; the number of lines must be a multiple of 4.
 * \throws Parse_error (position() = 1-based line), Non_finite_value_error.
 */
inline std::vector<Tris_triangle> read_tris(std::istream& in)
{
  std::vector<Tris_triangle> triangles;
  std::string line;
  std::size_t line_number = 0;
  std::array<std::pair<const char*, const char*>, 8> tokens;
  Tris_triangle current;
  while(std::getline(in, line))
  {
    ++line_number;
    const std::size_t n = internal::split_tokens(line, tokens);
    if(n != 3)
      throw Parse_error("line " + std::to_string(line_number) + ": expected 'x y z', found " + std::to_string(n) +
                          " fields",
                        line_number);
    std::array<double, 3> v;
    for(int i = 0; i < 3; ++i)
      v[i] = internal::parse_number(tokens[i], line_number);
    switch((line_number - 1) % 4)
    {
    case 0: current.n = v; break;
    case 1: current.p0 = v; break;
    case 2: current.p1 = v; break;
    default: current.p2 = v; triangles.push_back(current);
    }
  }
  if(line_number % 4 != 0)
    throw Parse_error("line " + std::to_string(line_number) + ": the file ends inside a triangle (" +
                        std::to_string(line_number) + " lines is not a multiple of 4)",
                      line_number);
  return triangles;
}

inline std::vector<Tris_triangle> read_tris(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw Invalid_input_error("cannot open '" + path + "'");
  return read_tris(in);
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_TRIS_H
