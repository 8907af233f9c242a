// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_GENERATORS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_GENERATORS_H

// Closed, outward-oriented triangle meshes made in code, for examples, tests
// and benchmarks that must not depend on data files.  CGAL's
// `<CGAL/boost/graph/generators.h>` already has the tetrahedron, hexahedron,
// octahedron-like pyramids and the icosahedron; these add the two smooth
// shapes the package's demos need, with a size parameter to reach millions of
// triangles.  (Functions in the style of `CGAL::make_icosahedron()`.)

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// Appends to `mesh` a geodesic sphere: an icosahedron whose faces are split
/// into 4 `subdivisions` times, every new vertex pushed onto the sphere.
/// It has 20 * 4^subdivisions triangles and is oriented outward.
template <typename MutableFaceGraph, typename Point_3>
void make_icosphere(MutableFaceGraph& mesh, const Point_3& center, double radius, unsigned subdivisions)
{
  typedef std::array<std::size_t, 3> Triangle;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> unit = {
      {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Triangle> triangles = {
      {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  auto normalize = [](std::array<double, 3>& p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for(double& c : p) c /= n;
  };
  for(auto& p : unit) normalize(p);

  for(unsigned level = 0; level < subdivisions; ++level)
  {
    // One midpoint per edge, shared by its two faces, so the result is welded.
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint_of;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = midpoint_of.find(key);
      if(found != midpoint_of.end()) return found->second;
      std::array<double, 3> m = {(unit[a][0] + unit[b][0]) / 2, (unit[a][1] + unit[b][1]) / 2,
                                 (unit[a][2] + unit[b][2]) / 2};
      normalize(m);
      unit.push_back(m);
      midpoint_of.emplace(key, unit.size() - 1);
      return unit.size() - 1;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * triangles.size());
    for(const Triangle& f : triangles)
    {
      const std::size_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles.swap(finer);
  }

  std::vector<Point_3> points;
  points.reserve(unit.size());
  for(const auto& p : unit)
    points.emplace_back(CGAL::to_double(center.x()) + radius * p[0],
                        CGAL::to_double(center.y()) + radius * p[1],
                        CGAL::to_double(center.z()) + radius * p[2]);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
}

/// Appends to `mesh` a torus around the axis through `center` parallel to z,
/// with major radius `major_radius` (centre of the tube to the axis) and
/// minor radius `minor_radius` (the tube), sampled with `major_segments`
/// steps around the axis and `minor_segments` around the tube:
/// 2 * major_segments * minor_segments triangles, oriented outward.
/// \pre major_radius > minor_radius > 0, major_segments >= 3, minor_segments >= 3
template <typename MutableFaceGraph, typename Point_3>
void make_torus(MutableFaceGraph& mesh, const Point_3& center, double major_radius, double minor_radius,
                std::size_t major_segments, std::size_t minor_segments)
{
  typedef std::array<std::size_t, 3> Triangle;
  const double two_pi = 2.0 * 3.14159265358979323846;
  const double cx = CGAL::to_double(center.x()), cy = CGAL::to_double(center.y()),
               cz = CGAL::to_double(center.z());
  std::vector<Point_3> points;
  points.reserve(major_segments * minor_segments);
  for(std::size_t i = 0; i < major_segments; ++i)
  {
    const double u = two_pi * double(i) / double(major_segments);
    for(std::size_t j = 0; j < minor_segments; ++j)
    {
      const double v = two_pi * double(j) / double(minor_segments);
      const double rho = major_radius + minor_radius * std::cos(v);
      points.emplace_back(cx + rho * std::cos(u), cy + rho * std::sin(u), cz + minor_radius * std::sin(v));
    }
  }
  auto index = [&](std::size_t i, std::size_t j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  std::vector<Triangle> triangles;
  triangles.reserve(2 * major_segments * minor_segments);
  // (d/du) x (d/dv) is the outward normal, so each quad is listed
  // counterclockwise in (u, v).
  for(std::size_t i = 0; i < major_segments; ++i)
    for(std::size_t j = 0; j < minor_segments; ++j)
    {
      triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_GENERATORS_H
