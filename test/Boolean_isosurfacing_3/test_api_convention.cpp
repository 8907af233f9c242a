// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// The rules every entry point obeys (issue 13): the domain first, a
// ConcurrencyTag, outputs cleared first, CGAL's `callback` named parameter
// cancels with Operation_cancelled_error, one statistics naming, and the
// CSG's `vertex_point_maps`.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::array<std::size_t, 3> Triangle;

namespace {

Mesh sphere(const Point& c, double r)
{
  Mesh m;
  BI::make_icosphere(m, c, r, 2);
  return m;
}

struct Csg_case
{
  std::vector<Mesh> meshes{sphere(Point(0, 0, 0), 1.0), sphere(Point(0.6, 0.1, 0), 0.8)};
  BI::Regular_lattice_3 lattice =
      BI::Regular_lattice_3::enclosing(PMP::bbox(meshes[0]) + PMP::bbox(meshes[1]), 0.1, 1);
  BI::Boolean_expression expression = BI::Boolean_expression::parse("A | B");
};

std::vector<Point> sphere_samples(std::size_t n)
{
  std::vector<Point> points;
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (double(i) + 0.5) / double(n), r = std::sqrt(1 - z * z);
    points.push_back(Point(r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z));
  }
  return points;
}

// Cancels at the first report after `calls` calls; counts them.
struct Cancel_after
{
  int calls;
  int* seen;
  bool operator()(double) const { return ++*seen <= calls; }
};

// A ball of radius 0.7 cut by the plane x = 0.1 ("f0 & f1") on an n^3
// tetrahedral grid over [-1, 1]^3: a surface with a crease loop.
struct Tbiso_case
{
  explicit Tbiso_case(std::size_t n)
    : grid(BI::Tetrahedral_grid_3<K>::spanning(Point(-1, -1, -1), Point(1, 1, 1), {{n, n, n}})),
      fields(BI::sample_fields(
          grid, std::vector<std::function<double(const Point&)>>{
                    [](const Point& p) { return std::sqrt(CGAL::squared_distance(p, Point(0, 0, 0))) - 0.7; },
                    [](const Point& p) { return p.x() - 0.1; }})),
      expression(BI::Boolean_expression::parse("f0 & f1"))
  {}
  BI::Tetrahedral_grid_3<K> grid;
  BI::Scalar_fields fields;
  BI::Boolean_expression expression;
};

} // namespace

TEST(ApiConvention, Csg_outputs_are_cleared_first)
{
  const Csg_case c;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  const BI::Marching_cubes_csg_statistics s =
      BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, points, triangles);
  ASSERT_GT(triangles.size(), 100u);
  std::vector<Point> again(5, Point(9, 9, 9));
  std::vector<Triangle> again_triangles(4, Triangle{{0, 1, 2}});
  BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, again, again_triangles);
  EXPECT_EQ(again, points);
  EXPECT_EQ(again_triangles, triangles);
  // A mesh output too: a mesh that already has a face is replaced.
  Mesh out = sphere(Point(5, 5, 5), 1.0);
  BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, out);
  EXPECT_TRUE(BI::test::is_closed_triangle_mesh(out));
  EXPECT_EQ(out.number_of_vertices(), points.size());
  EXPECT_EQ(out.number_of_faces(), triangles.size());
  // One statistics naming.
  EXPECT_EQ(s.number_of_vertices, points.size());
  EXPECT_EQ(s.number_of_faces, triangles.size());
  EXPECT_GT(s.seconds, 0.0);
  EXPECT_GE(s.seconds + 1e-9, s.seconds_classification + s.seconds_edges);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(ApiConvention, Csg_warns_when_the_output_is_open)
{
  const Csg_case c;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  // The lattice cut through the union: its boundary has points inside.
  const BI::Regular_lattice_3 cut = c.lattice.z_range(0, c.lattice.number_of_points(2) / 2);
  const auto s = BI::marching_cubes_csg(cut, c.meshes, c.expression, points, triangles);
  EXPECT_GT(s.boundary_points_inside, 0u);
  EXPECT_FALSE(s.warnings.empty());
}

TEST(ApiConvention, Csg_callback_reports_progress_and_cancels)
{
  const Csg_case c;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<double> fractions;
  BI::marching_cubes_csg<CGAL::Sequential_tag>(c.lattice, c.meshes, c.expression, points, triangles,
                                               CGAL::parameters::callback(std::function<bool(double)>([&](double f) {
                                                 fractions.push_back(f);
                                                 return true;
                                               })));
  ASSERT_GT(fractions.size(), 2u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  int seen = 0;
  EXPECT_THROW(BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, points, triangles,
                                      CGAL::parameters::callback(std::function<bool(double)>(Cancel_after{2, &seen}))),
               BI::Operation_cancelled_error);
  EXPECT_EQ(seen, 3); // the third report cancelled, and nothing was reported after it
  // Our own parameters first, CGAL's callback chained after them.
  seen = 0;
  EXPECT_THROW(BI::marching_cubes_csg(
                   c.lattice, c.meshes, c.expression, points, triangles,
                   BI::parameters::sharp_features(false).callback(std::function<bool(double)>(Cancel_after{0, &seen}))),
               BI::Operation_cancelled_error);
  EXPECT_EQ(seen, 1);
}

TEST(ApiConvention, Csg_honours_each_mesh_vertex_point_map)
{
  // Mesh 1's points are stored twice: its vertex_point map holds a decoy far
  // away, the "moved" property holds the real sphere.
  Csg_case c;
  std::vector<Point> points, reference_points;
  std::vector<Triangle> triangles, reference_triangles;
  BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, reference_points, reference_triangles);
  Mesh& decoy = c.meshes[1];
  auto moved = decoy.add_property_map<Mesh::Vertex_index, Point>("v:moved").first;
  for(const auto v : decoy.vertices())
  {
    moved[v] = decoy.point(v);
    decoy.point(v) = decoy.point(v) + K::Vector_3(100, 0, 0);
  }
  typedef Mesh::Property_map<Mesh::Vertex_index, Point> Map;
  const std::vector<Map> maps{c.meshes[0].points(), moved};
  BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, points, triangles, BI::parameters::vertex_point_maps(maps));
  EXPECT_EQ(points, reference_points);
  EXPECT_EQ(triangles, reference_triangles);
  // Without the maps, mesh 1 is the decoy: another result.
  BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, points, triangles);
  EXPECT_NE(triangles.size(), reference_triangles.size());
  // One map per mesh, or a one-line error.
  const std::vector<Map> one{moved};
  EXPECT_THROW(BI::marching_cubes_csg(c.lattice, c.meshes, c.expression, points, triangles,
                                      BI::parameters::vertex_point_maps(one)),
               BI::Invalid_input_error);
}

TEST(ApiConvention, Contouring_outputs_cleared_tag_callback_and_statistics)
{
  const std::vector<Point> samples = sphere_samples(2000);
  const BI::Tangent_plane_signed_distance_3<K> field(samples);
  const BI::Regular_lattice_3 lattice = BI::contouring_lattice(field);
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  const BI::Contouring_statistics s =
      BI::contour_signed_distance<CGAL::Sequential_tag>(lattice, field, points, triangles);
  ASSERT_GT(triangles.size(), 100u);
  EXPECT_EQ(s.number_of_vertices, points.size());
  EXPECT_EQ(s.number_of_faces, triangles.size());
  EXPECT_GE(s.seconds, s.seconds_field);
  EXPECT_DOUBLE_EQ(s.cell_size, lattice.spacing());
  std::vector<Point> again(3, Point(7, 7, 7));
  std::vector<Triangle> again_triangles(2, Triangle{{0, 1, 2}});
  BI::contour_signed_distance(lattice, field, again, again_triangles);
  EXPECT_EQ(again, points);
  EXPECT_EQ(again_triangles, triangles);
  // Mesh output: cleared first.
  Mesh mesh = sphere(Point(5, 5, 5), 1.0);
  BI::contour_point_set(lattice, samples, mesh, CGAL::parameters::default_values());
  EXPECT_EQ(mesh.number_of_faces(), triangles.size());
  int seen = 0;
  EXPECT_THROW(BI::contour_signed_distance(lattice, field, points, triangles,
                                           CGAL::parameters::callback(std::function<bool(double)>(Cancel_after{0, &seen}))),
               BI::Operation_cancelled_error);
  EXPECT_EQ(seen, 1);
}

TEST(ApiConvention, Tbiso_outputs_cleared_callback_and_statistics)
{
  const Tbiso_case c(24);
  const auto& grid = c.grid;
  const auto& fields = c.fields;
  const auto& e = c.expression;
  BI::Boolean_isosurface_soup<Point> soup;
  const BI::Boolean_isosurface_statistics s = BI::extract_boolean_isosurface(grid, fields, e, soup);
  ASSERT_GT(soup.polygons.size(), 100u);
  EXPECT_EQ(s.number_of_vertices, soup.points.size());
  EXPECT_EQ(s.number_of_faces, soup.polygons.size());
  EXPECT_GE(s.seconds, s.seconds_extraction);
  BI::Boolean_isosurface_soup<Point> again = soup;
  BI::extract_boolean_isosurface(grid, fields, e, again);
  EXPECT_EQ(again.points, soup.points);
  EXPECT_EQ(again.polygons, soup.polygons);
  int seen = 0;
  EXPECT_THROW(BI::extract_boolean_isosurface(grid, fields, e, again,
                                              CGAL::parameters::callback(std::function<bool(double)>(Cancel_after{1, &seen}))),
               BI::Operation_cancelled_error);
  EXPECT_EQ(seen, 2);
}

TEST(ApiConvention, Tbiso_mesh_output_side_maps)
{
  const Tbiso_case c(20);
  const auto& grid = c.grid;
  const auto& fields = c.fields;
  const auto& e = c.expression;
  BI::Boolean_isosurface_soup<Point> soup;
  BI::extract_boolean_isosurface(grid, fields, e, soup);
  const BI::Crease_network creases = BI::extract_crease_network(soup);
  Mesh mesh = sphere(Point(5, 5, 5), 1.0); // replaced: outputs are cleared first
  auto label = mesh.add_property_map<Mesh::Face_index, int>("f:label", 99).first;
  auto crease = mesh.add_property_map<Mesh::Edge_index, bool>("e:c", false).first;
  auto corner = mesh.add_property_map<Mesh::Vertex_index, bool>("v:c", false).first;
  BI::extract_boolean_isosurface(
      grid, fields, e, mesh,
      CGAL::parameters::face_patch_map(label).edge_is_constrained_map(crease).vertex_is_constrained_map(corner));
  ASSERT_EQ(mesh.number_of_faces(), soup.polygons.size());
  ASSERT_EQ(mesh.number_of_vertices(), soup.points.size());
  std::size_t on_plane = 0, marked = 0, corners = 0, expected = 0;
  for(const auto fd : mesh.faces())
  {
    EXPECT_EQ(label[fd], soup.face_fields[std::size_t(fd)]);
    on_plane += label[fd] == 1 ? 1 : 0;
  }
  for(const auto ed : mesh.edges())
    marked += crease[ed] ? 1 : 0;
  for(const auto vd : mesh.vertices())
    corners += corner[vd] ? 1 : 0;
  for(const auto& line : creases.polylines)
    expected += line.size() - 1;
  EXPECT_GT(on_plane, 0u);
  EXPECT_GT(marked, 10u); // the circle where the plane cuts the sphere
  EXPECT_EQ(marked, expected);
  EXPECT_EQ(corners, creases.corners.size());
}

TEST(ApiConvention, Surveyor_volume_takes_a_concurrency_tag)
{
  const Mesh m = sphere(Point(0, 0, 0), 1.0);
  EXPECT_EQ(BI::surveyor_volume<CGAL::Sequential_tag>(m), BI::surveyor_volume(m));
#ifdef CGAL_LINKED_WITH_TBB
  EXPECT_EQ(BI::surveyor_volume<CGAL::Parallel_tag>(m), BI::surveyor_volume(m));
#endif
}
