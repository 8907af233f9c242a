// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TEST_UTIL_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TEST_UTIL_H

// Helpers shared by the tests (and the benchmarks): input meshes, analytic
// fields, the invariants every closed output must satisfy.

#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace test {

/// The axis-aligned box [low, high], triangulated (12 triangles, outward).
template <typename Mesh, typename Point>
Mesh make_box(const Point& low, const Point& high)
{
  Mesh mesh;
  CGAL::make_hexahedron(Point(low.x(), low.y(), low.z()), Point(high.x(), low.y(), low.z()),
                        Point(high.x(), high.y(), low.z()), Point(low.x(), high.y(), low.z()),
                        Point(low.x(), high.y(), high.z()), Point(low.x(), low.y(), high.z()),
                        Point(high.x(), low.y(), high.z()), Point(high.x(), high.y(), high.z()), mesh);
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  return mesh;
}

/// The signed distance to the sphere of centre (cx, cy, cz) and radius r (negative inside).
template <typename Point>
std::function<double(const Point&)> sphere_field(double cx, double cy, double cz, double r)
{
  return [=](const Point& p) {
    const double x = p.x() - cx, y = p.y() - cy, z = p.z() - cz;
    return std::sqrt(x * x + y * y + z * z) - r;
  };
}

/// Success iff `mesh` is a valid, closed triangle mesh (every edge in two
/// faces, every face a triangle): the guarantee of a closed output.
template <typename Mesh>
::testing::AssertionResult is_closed_triangle_mesh(const Mesh& mesh)
{
  if(!CGAL::is_valid_polygon_mesh(mesh))
    return ::testing::AssertionFailure() << "not a valid polygon mesh";
  if(!CGAL::is_closed(mesh))
    return ::testing::AssertionFailure() << "not closed";
  if(!CGAL::is_triangle_mesh(mesh))
    return ::testing::AssertionFailure() << "a face is not a triangle";
  return ::testing::AssertionSuccess();
}

} // namespace test
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_TEST_UTIL_H
