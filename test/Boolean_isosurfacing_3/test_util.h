// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TEST_UTIL_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TEST_UTIL_H

// Helpers shared by the tests (and the benchmarks): the kernels and mesh
// types, the exact volume oracle, input meshes, analytic fields, the
// invariants every closed output must satisfy.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace test {

/// The kernels and meshes of the tests and benchmarks
/// (`using namespace CGAL::Boolean_isosurfacing::test::kernels;`).
namespace kernels {
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
} // namespace kernels

/// The oracle of volumes: PMP::volume with Epeck (it calls exact() after
/// every term, so the value is the exact rational volume of the mesh's double
/// coordinates), rounded to the nearest double once at the end.
template <typename TriangleMesh>
double exact_volume(const TriangleMesh& mesh)
{
  kernels::Exact_mesh exact_mesh;
  CGAL::copy_face_graph(mesh, exact_mesh);
  return CGAL::to_double(CGAL::exact(CGAL::Polygon_mesh_processing::volume(exact_mesh)));
}

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

/// A prism on a regular `segments`-gon of circumradius `radius`, axis along
/// z from `base` up `height`, triangulated (4 `segments` triangles, outward).
template <typename Mesh, typename Point>
Mesh make_cylinder(const Point& base, double radius, double height, int segments)
{
  const double pi = 3.14159265358979323846;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for(int s = 0; s < segments; ++s)
  {
    const double a = 2 * pi * s / segments;
    points.emplace_back(base.x() + radius * std::cos(a), base.y() + radius * std::sin(a), base.z());
    points.emplace_back(base.x() + radius * std::cos(a), base.y() + radius * std::sin(a), base.z() + height);
  }
  const std::size_t bottom = points.size(), top = bottom + 1;
  points.push_back(base);
  points.emplace_back(base.x(), base.y(), base.z() + height);
  for(int s = 0; s < segments; ++s)
  {
    const std::size_t b0 = 2 * s, t0 = 2 * s + 1, b1 = 2 * ((s + 1) % segments), t1 = b1 + 1;
    triangles.push_back({{b0, b1, t1}});
    triangles.push_back({{b0, t1, t0}});
    triangles.push_back({{bottom, b1, b0}});
    triangles.push_back({{top, t0, t1}});
  }
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

/// `mesh` rotated by `angle` (radians) about the axis through `c` along
/// `axis` (Rodrigues' formula), then moved by `t`.
template <typename Mesh, typename Point, typename Vector>
Mesh moved(const Mesh& mesh, const Point& c, const Vector& axis, double angle, const Vector& t)
{
  const Vector u = axis / std::sqrt(axis.squared_length());
  const double co = std::cos(angle), s = std::sin(angle);
  Mesh copy = mesh;
  for(auto v : vertices(copy))
  {
    const Vector p = get(CGAL::vertex_point, copy, v) - c;
    put(CGAL::vertex_point, copy, v, c + p * co + CGAL::cross_product(u, p) * s + u * (u * p) * (1 - co) + t);
  }
  return copy;
}

/// Issue 17's moved copy of a mesh: rotated by 10 degrees about the axis
/// (1, 2, 3) through its bounding box centre, then moved by (0.137, 0.091,
/// 0.063) times the box's longest side.
template <typename Mesh>
Mesh moved_copy(const Mesh& mesh)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  const double pi = 3.14159265358979323846;
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double size = (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
  const Point c((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2, (b.zmin() + b.zmax()) / 2);
  return moved(mesh, c, Vector(1, 2, 3), 10 * pi / 180, Vector(0.137 * size, 0.091 * size, 0.063 * size));
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
