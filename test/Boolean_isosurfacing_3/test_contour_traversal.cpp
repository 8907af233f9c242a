// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// contour_point_set: where the traversal starts (cells finer than the offset
// of the zero set from the samples), empty outputs, and the topology of the
// output on samples of the shared meshes (issue 18).

#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef std::array<std::size_t, 3> Triangle;

namespace {

const std::string data_dir = BISO_SHARED_DATA_DIR;

struct Samples
{
  std::vector<Point_3> points;
  std::vector<Vector_3> normals;
};

// Area-uniform random samples of a triangle mesh, with the exact face normals.
Samples sample_mesh(const Mesh& mesh, std::size_t n, unsigned seed)
{
  std::vector<std::array<Point_3, 3>> faces;
  std::vector<double> cumulative;
  double total = 0;
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    std::array<Point_3, 3> t{{mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                              mesh.point(mesh.target(mesh.next(h)))}};
    total += std::sqrt(CGAL::to_double(CGAL::squared_area(t[0], t[1], t[2])));
    faces.push_back(t);
    cumulative.push_back(total);
  }
  CGAL::Random random(seed);
  Samples s;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double u = random.get_double(0, total);
    const std::size_t f = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    const auto& t = faces[std::min(f, faces.size() - 1)];
    double a = random.get_double(), b = random.get_double();
    if(a + b > 1)
    {
      a = 1 - a;
      b = 1 - b;
    }
    s.points.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
    const Vector_3 normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    s.normals.push_back(normal / std::sqrt(CGAL::to_double(normal.squared_length())));
  }
  return s;
}

struct Outcome
{
  BI::Contouring_statistics report;
  std::size_t split_vertices = 0; // non-manifold vertices of the soup (duplicated by orient_polygon_soup)
  std::size_t remaining_split = 0; // ... left in the output (split here, not by the repair)
  bool closed = false;
  std::size_t components = 0, border_cycles = 0;
  long euler = 0;
  double hausdorff_percent = -1; // of the original's bounding-box diagonal
  Mesh mesh;
};

template <typename NP>
Outcome contour(const Samples& s, const Mesh* original, const NP& np)
{
  Outcome o;
  std::vector<std::size_t> indices(s.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  const BI::Tangent_plane_signed_distance_3<K> field(
    indices, CGAL::parameters::point_map(CGAL::make_property_map(s.points)).normal_map(CGAL::make_property_map(s.normals)));
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  o.report = BI::contour_signed_distance(BI::contouring_lattice(field, np), field, points, triangles, np);
  const std::size_t before = points.size();
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    PMP::orient_polygon_soup(points, triangles);
  o.remaining_split = points.size() - before;
  o.split_vertices = o.report.split_vertices + o.remaining_split;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, o.mesh);
  o.closed = CGAL::is_closed(o.mesh);
  Mesh copy = o.mesh;
  auto fcc = copy.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  o.components = PMP::connected_components(copy, fcc);
  o.euler = long(o.mesh.number_of_vertices()) - long(o.mesh.number_of_edges()) + long(o.mesh.number_of_faces());
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(o.mesh, std::back_inserter(cycles));
  o.border_cycles = cycles.size();
  if(original != nullptr && !o.mesh.is_empty())
  {
    const auto box = CGAL::bounding_box(original->points().begin(), original->points().end());
    const double diagonal = std::sqrt(CGAL::to_double(CGAL::squared_distance(box.min(), box.max())));
    o.hausdorff_percent = 100 / diagonal *
      PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(o.mesh, *original, 1e-4 * diagonal);
  }
  return o;
}

void print(const std::string& what, const Outcome& o)
{
  std::cout << "[ measured ] " << what << ": closed " << o.closed << ", non-manifold vertices " << o.split_vertices
            << ", components " << o.components << ", chi " << o.euler << ", border cycles " << o.border_cycles
            << ", Hausdorff " << o.hausdorff_percent << " % of the diagonal, cell " << o.report.cell_size
            << ", triangles " << o.report.number_of_faces << ", skipped (undefined) " << o.report.skipped_cubes
            << ", skipped (jump) " << o.report.discontinuous_cubes << ", walk seeds " << o.report.walk_seeds
            << std::endl;
}

Mesh load_mesh(const std::string& name)
{
  Mesh m;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(data_dir + "/meshes/" + name, m)) << name;
  return m;
}

struct Analytic_field
{
  typedef K::Point_3 Point_3;
  std::vector<Point_3> seeds;
  double rho = 1, delta = 0;
  std::function<std::optional<double>(const Point_3&)> f;
  const std::vector<Point_3>& points() const { return seeds; }
  double sampling_density() const { return rho; }
  double noise_level() const { return delta; }
  std::optional<double> operator()(const Point_3& p) const { return f(p); }
};

} // namespace

// The zero set of Hoppe's f lies inside a convex sample (the planes pass
// through neighbourhood centroids): with a cell finer than that offset no
// sample's cube is crossed, and the traversal used to output nothing
// (`contour sphere.pwn --cells 5000`).  The walk down |f| from the samples
// must find the surface whatever the cell.
TEST(Traversal, Cells_finer_than_the_offset_of_the_zero_set_still_give_the_surface)
{
  Mesh sphere;
  BI::make_icosphere(sphere, Point_3(0.1, -0.2, 0.3), 1.0, 4);
  const Samples s = sample_mesh(sphere, 150, 11);
  std::vector<std::size_t> indices(s.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  const BI::Tangent_plane_signed_distance_3<K> field(
    indices, CGAL::parameters::point_map(CGAL::make_property_map(s.points)).normal_map(CGAL::make_property_map(s.normals)));
  // |f| at the samples: the offset of each sample from the zero set.
  double min_offset = std::numeric_limits<double>::infinity(), max_offset = 0;
  for(const Point_3& p : s.points)
  {
    const std::optional<double> f = field(p);
    ASSERT_TRUE(f.has_value());
    min_offset = std::min(min_offset, std::abs(*f));
    max_offset = std::max(max_offset, std::abs(*f));
  }
  // Cubes of diagonal below the smallest offset: f (1-Lipschitz where the
  // corners share a plane) cannot change sign in a sample's cube.
  const double cell = std::min(min_offset / 2, field.default_cell_size() / 4);
  ASSERT_GT(cell, 0);
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  const BI::Contouring_statistics report =
    BI::contour_signed_distance(BI::contouring_lattice(field, BI::parameters::cell_size(cell)), field, points, triangles, BI::parameters::cell_size(cell));
  std::cout << "[ measured ] offsets " << min_offset << " .. " << max_offset << ", cell " << cell << ", "
            << report.number_of_faces << " triangles, " << report.walk_seeds << " walk seeds" << std::endl;
  EXPECT_GE(report.walk_seeds, 1u);
  EXPECT_FALSE(report.empty_output);
  ASSERT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(triangles));
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  Mesh copy = mesh;
  auto fcc = copy.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  EXPECT_EQ(PMP::connected_components(copy, fcc), 1u);
  EXPECT_EQ(long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces()), 2);
  // Every output vertex is within the offset (plus a cube diagonal) of the sphere.
  double worst = 0;
  for(const Point_3& p : points)
    worst = std::max(worst, std::abs(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point_3(0.1, -0.2, 0.3)))) - 1));
  EXPECT_LE(worst, 2 * max_offset + std::sqrt(3.0) * cell);
}

// An empty output is an error: a flag in the report of contour_signed_distance,
// an exception from contour_point_set.
TEST(Traversal, Empty_output_is_reported)
{
  Analytic_field none; // f > 0 everywhere: no surface
  none.seeds = {Point_3(0, 0, 0), Point_3(1, 1, 1)};
  none.f = [](const Point_3&) -> std::optional<double> { return 1.0; };
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  EXPECT_TRUE(BI::contour_signed_distance(BI::contouring_lattice(none, BI::parameters::cell_size(0.5)), none, points, triangles, BI::parameters::cell_size(0.5)).empty_output);
  Analytic_field plane = none;
  plane.f = [](const Point_3& p) -> std::optional<double> { return p.z() - 0.3; };
  EXPECT_FALSE(BI::contour_signed_distance(BI::contouring_lattice(plane, BI::parameters::cell_size(0.5)), plane, points, triangles, BI::parameters::cell_size(0.5)).empty_output);

  Mesh sphere;
  BI::make_icosphere(sphere, Point_3(0, 0, 0), 1.0, 3);
  const Samples s = sample_mesh(sphere, 1000, 12);
  std::vector<Point_3> out;
  triangles.clear();
  const BI::Regular_lattice_3 lattice = BI::contouring_lattice(BI::Tangent_plane_signed_distance_3<K>(s.points));
  EXPECT_NO_THROW(BI::contour_point_set(lattice, s.points, out, triangles));
  EXPECT_FALSE(triangles.empty());
  // maximum_jump(0): every crossed cube counts as a jump of f, nothing is left.
  try
  {
    out.clear();
    triangles.clear();
    BI::contour_point_set(lattice, s.points, out, triangles, BI::parameters::maximum_jump(0.0));
    ADD_FAILURE() << "an empty contour must throw";
  }
  catch(const BI::Empty_contour_error& e)
  {
    EXPECT_GT(e.report().discontinuous_cubes, 0u);
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos);
  }
  Mesh mesh;
  EXPECT_THROW(BI::contour_point_set(lattice, s.points, mesh, BI::parameters::maximum_jump(0.0)),
               BI::Empty_contour_error);
}

// Issue 18: 60K samples with exact normals of the shared meshes, defaults.
TEST(Topology, Shared_meshes_60k_samples_with_normals)
{
  for(const std::string name :
      {"bunny_hoppe.off", "fertility.off", "3holes.off", "mechpart_hoppe.off", "elephant_cgal.off"})
  {
    const Mesh m = load_mesh(name);
    const Samples s = sample_mesh(m, 60000, 18);
    // Before the hole repair: nothing filled (pinched vertices are still
    // split, and counted).
    const Outcome raw = contour(s, &m, BI::parameters::maximum_hole_size(0.0));
    print(name + " (holes kept)", raw);
    const Outcome o = contour(s, &m, CGAL::parameters::default_values());
    print(name, o);
    // The repair never leaves a non-manifold vertex, and never adds a border.
    EXPECT_EQ(o.remaining_split, 0u) << name;
    EXPECT_LE(o.border_cycles, raw.border_cycles) << name;
    EXPECT_EQ(o.report.filled_holes > 0, o.border_cycles < raw.border_cycles) << name;
    if(const char* dump = std::getenv("BISO_DUMP_DIR"))
      CGAL::IO::write_polygon_mesh(std::string(dump) + "/" + name + ".contour.off", o.mesh,
                                   CGAL::parameters::stream_precision(17));
  }
}
