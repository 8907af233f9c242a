// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Tests of Regular_lattice_3, Lattice_classifier_3 and marching_cubes_csg().
// The oracles are independent of the code under test:
//  - CGAL::Side_of_triangle_mesh (AABB-tree ray shooting) for the
//    classification of lattice points not on a mesh;
//  - closed-form expectations for meshes built on the lattice on purpose
//    (boxes, octahedra), which exercise the symbolic perturbation;
//  - PMP::corefine_and_compute_* for the volume of the exact polyhedral result;
//  - a literal transcription of the seed's INT_POINT.

// Every marching_cubes_csg() call of this test also checks, on every lattice
// edge, that the crossings agree with the classification of its ends.
#define CGAL_BOOLEAN_ISOSURFACING_3_CHECK_CONSISTENCY

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Lattice_classifier_3.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::array<std::size_t, 3> Triangle;

const std::string data_dir = std::string(BISO_SHARED_DATA_DIR) + "/meshes/";

// ------------------------------------------------------------------ meshes

Mesh load_mesh(const std::string& name)
{
  Mesh mesh;
  const bool ok = CGAL::IO::read_polygon_mesh(data_dir + name, mesh);
  EXPECT_TRUE(ok) << "cannot read " << data_dir + name;
  return mesh;
}

Mesh make_sphere(const Point& center, double radius, unsigned subdivisions)
{
  Mesh mesh;
  BI::make_icosphere(mesh, center, radius, subdivisions);
  return mesh;
}

// Octahedron |x - c| + |y - c| + |z - c| <= r, outward.
Mesh make_octahedron(const Point& c, double r)
{
  const std::vector<Point> points = {{c.x() + r, c.y(), c.z()}, {c.x() - r, c.y(), c.z()},
                                     {c.x(), c.y() + r, c.z()}, {c.x(), c.y() - r, c.z()},
                                     {c.x(), c.y(), c.z() + r}, {c.x(), c.y(), c.z() - r}};
  const std::vector<Triangle> triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

Mesh transformed(const Mesh& mesh, const std::function<Point(const Point&)>& f)
{
  Mesh copy = mesh;
  for(auto v : vertices(copy))
    copy.point(v) = f(copy.point(v));
  return copy;
}

Mesh translated(const Mesh& mesh, double dx, double dy, double dz)
{
  return transformed(mesh, [=](const Point& p) { return Point(p.x() + dx, p.y() + dy, p.z() + dz); });
}

CGAL::Bbox_3 bbox_of(const std::vector<const Mesh*>& meshes)
{
  CGAL::Bbox_3 box;
  for(const Mesh* m : meshes)
    box += PMP::bbox(*m);
  return box;
}

std::vector<std::reference_wrapper<const Mesh>> refs(const std::vector<const Mesh*>& meshes)
{
  std::vector<std::reference_wrapper<const Mesh>> result;
  for(const Mesh* m : meshes)
    result.push_back(std::cref(*m));
  return result;
}

// ------------------------------------------------------------------ oracles

struct Classification_check
{
  std::size_t compared = 0, on_boundary = 0, mismatches = 0;
};

// Compares the classification of every lattice point not on the mesh with
// CGAL::Side_of_triangle_mesh.
Classification_check compare_with_side_of_triangle_mesh(const BI::Lattice_classifier_3& classifier, std::size_t m,
                                                        const Mesh& mesh)
{
  const CGAL::Side_of_triangle_mesh<Mesh, Epick> side(mesh);
  const BI::Regular_lattice_3& lattice = classifier.lattice();
  const auto& n = lattice.number_of_points();
  Classification_check check;
  for(std::size_t k = 0; k < n[2]; ++k)
    for(std::size_t j = 0; j < n[1]; ++j)
      for(std::size_t i = 0; i < n[0]; ++i)
      {
        const Point p(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k));
        const CGAL::Bounded_side s = side(p);
        if(s == CGAL::ON_BOUNDARY)
        {
          ++check.on_boundary;
          continue;
        }
        ++check.compared;
        if((s == CGAL::ON_BOUNDED_SIDE) != classifier.is_inside(m, i, j, k))
          ++check.mismatches;
      }
  return check;
}

struct Soup
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  BI::Marching_cubes_csg_statistics statistics;
};

// `sharp = false`: the plain Marching Cubes output (one vertex per edge with
// a change of state, in the documented order), without feature vertices.
template <typename Tag = CGAL::Sequential_tag>
Soup run_csg(const std::vector<const Mesh*>& meshes, const BI::Boolean_expression& e, const BI::Regular_lattice_3& lattice,
             bool sharp = true)
{
  Soup soup;
  soup.statistics = BI::marching_cubes_csg<Tag>(lattice, refs(meshes), e, soup.points, soup.triangles,
                                                BI::parameters::sharp_features(sharp));
  return soup;
}

// Closed, 2-manifold, no duplicated vertex, outward; returns the volume.
double check_output(const Soup& soup, const std::string& what, bool expect_distinct_points = true)
{
  SCOPED_TRACE(what);
  EXPECT_EQ(soup.statistics.number_of_vertices, soup.points.size());
  EXPECT_EQ(soup.statistics.number_of_faces, soup.triangles.size());
  EXPECT_EQ(soup.statistics.boundary_points_inside, 0u);
  if(soup.triangles.empty())
    return 0;
  EXPECT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(soup.triangles)) << "not a 2-manifold polygon mesh";
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(mesh.number_of_vertices(), soup.points.size()); // every point used, none duplicated
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  if(expect_distinct_points)
  {
    std::vector<Point> sorted = soup.points;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "two vertices at the same position";
  }
  const double volume = BI::surveyor_volume(soup.points, soup.triangles, BI::parameters::signed_volume(true));
  EXPECT_GT(volume, 0) << "not outward";
  return volume;
}

enum class Operation { UNION, INTERSECTION, DIFFERENCE };

BI::Boolean_expression expression_of(Operation op)
{
  switch(op)
  {
  case Operation::UNION: return BI::Boolean_expression::union_of(2);
  case Operation::INTERSECTION: return BI::Boolean_expression::intersection_of(2);
  default: return BI::Boolean_expression::difference();
  }
}

const char* name_of(Operation op)
{
  return op == Operation::UNION ? "union" : (op == Operation::INTERSECTION ? "intersection" : "difference");
}

// The volume of the exact polyhedral result, by corefinement.
double corefinement_volume(const Mesh& a, const Mesh& b, Operation op)
{
  Mesh ca = a, cb = b, out;
  bool ok = false;
  switch(op)
  {
  case Operation::UNION: ok = PMP::corefine_and_compute_union(ca, cb, out); break;
  case Operation::INTERSECTION: ok = PMP::corefine_and_compute_intersection(ca, cb, out); break;
  case Operation::DIFFERENCE: ok = PMP::corefine_and_compute_difference(ca, cb, out); break;
  }
  EXPECT_TRUE(ok) << "corefinement failed";
  return out.is_empty() ? 0.0 : PMP::volume(out);
}

// ------------------------------------------------------------------ Regular_lattice_3

TEST(RegularLattice, CoordinatesIndicesAndEnclosing)
{
  const BI::Regular_lattice_3 lattice({{-1.5, 0.25, 3}}, 0.1, {{4, 5, 6}});
  EXPECT_EQ(lattice.total_number_of_points(), 120u);
  EXPECT_EQ(lattice.linear_index(1, 2, 3), 1u + 4u * (2u + 5u * 3u));
  for(std::size_t i = 0; i < 6; ++i)
  {
    volatile double product = double(i) * 0.1;
    EXPECT_EQ(lattice.coordinate(2, i), 3 + product);
  }
  for(int a = 0; a < 3; ++a)
    for(std::size_t i = 0; i + 1 < lattice.number_of_points(a); ++i)
    {
      const double c = lattice.coordinate(a, i);
      EXPECT_EQ(lattice.first_index_not_below(a, c), i);
      EXPECT_EQ(lattice.first_index_not_below(a, std::nextafter(c, 1e300)), i + 1);
    }
  EXPECT_EQ(lattice.first_index_not_below(0, -1e300), 0u);
  EXPECT_EQ(lattice.first_index_not_below(0, 1e300), 4u);

  const CGAL::Bbox_3 box(0.1, -0.2, 0.3, 1.7, 0.9, 0.31);
  for(std::size_t margin : {0u, 1u, 3u})
  {
    const BI::Regular_lattice_3 e = BI::Regular_lattice_3::enclosing(box, 0.07, margin);
    for(int a = 0; a < 3; ++a)
    {
      const std::size_t n = e.number_of_points(a);
      EXPECT_LE(e.coordinate(a, margin), box.min(a));
      EXPECT_GE(e.coordinate(a, n - 1 - margin), box.max(a));
      // Tight: one point fewer on either side would not do.
      EXPECT_LT(e.coordinate(a, n - 2 - margin), box.max(a));
      if(margin >= 1)
      {
        EXPECT_LT(e.coordinate(a, 0), box.min(a));
        EXPECT_GT(e.coordinate(a, n - 1), box.max(a));
      }
    }
  }
  const BI::Regular_lattice_3 c = BI::Regular_lattice_3::enclosing_with_cells(box, 32, 1);
  EXPECT_DOUBLE_EQ(c.spacing(), 1.6 / 32);
  EXPECT_GE(c.number_of_points(0), 32u + 3u);
  EXPECT_LE(c.number_of_points(0), 32u + 4u);
}

TEST(RegularLattice, BadParametersThrow)
{
  const CGAL::Bbox_3 unit(0, 0, 0, 1, 1, 1);
  EXPECT_THROW(BI::Regular_lattice_3({{0, 0, 0}}, 0.0, {{2, 2, 2}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3({{0, 0, 0}}, -1.0, {{2, 2, 2}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3({{0, 0, 0}}, std::nan(""), {{2, 2, 2}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3({{0, std::numeric_limits<double>::infinity(), 0}}, 1.0, {{2, 2, 2}}),
               BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3({{0, 0, 0}}, 1.0, {{2, 0, 2}}), BI::Invalid_input_error);
  // Spacing lost in the rounding of the coordinates.
  EXPECT_THROW(BI::Regular_lattice_3({{1e20, 0, 0}}, 1.0, {{3, 2, 2}}), BI::Invalid_input_error);
  // Beyond 2^62 points linear_index() would overflow; 2^32 points are fine.
  EXPECT_THROW(BI::Regular_lattice_3({{0, 0, 0}}, 1.0, {{1u << 21, 1u << 21, 1u << 21}}), BI::Lattice_too_large_error);
  EXPECT_NO_THROW(BI::Regular_lattice_3({{0, 0, 0}}, 1.0, {{2048, 2048, 1024}}));
  EXPECT_THROW(BI::Regular_lattice_3::enclosing(CGAL::Bbox_3(), 0.1), BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3::enclosing(unit, 0.0), BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3::enclosing_with_cells(CGAL::Bbox_3(1, 1, 1, 1, 1, 1), 10),
               BI::Invalid_input_error);
  EXPECT_THROW(BI::Regular_lattice_3::enclosing_with_cells(unit, 0), BI::Invalid_input_error);
  try
  {
    BI::Regular_lattice_3::enclosing(unit, 1e-9);
    ADD_FAILURE() << "no exception";
  }
  catch(const BI::Lattice_too_large_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("2^62"), std::string::npos) << e.what();
  }
}

// ------------------------------------------------------------------ 1. classification

TEST(LatticeClassifier, EqualsSideOfTriangleMeshOnGeneratedAndRealMeshes)
{
  struct Case
  {
    std::string name;
    Mesh mesh;
    std::size_t cells;
  };
  std::vector<Case> cases;
  cases.push_back({"icosphere", make_sphere(Point(0.1, -0.2, 0.05), 1.0, 3), 40});
  {
    Mesh torus;
    BI::make_torus(torus, Point(0, 0, 0), 1.0, 0.4, 48, 24);
    cases.push_back({"torus", torus, 40});
  }
  cases.push_back({"bunny.off", load_mesh("bunny.off"), 48});
  cases.push_back({"fandisk.off", load_mesh("fandisk.off"), 48});
  {
    // Nested shells: the region between them is inside (parity).
    Mesh nested;
    BI::make_icosphere(nested, Point(0, 0, 0), 1.0, 3);
    BI::make_icosphere(nested, Point(0.1, 0, 0), 0.5, 3);
    cases.push_back({"nested spheres", nested, 40});
  }
  {
    Mesh two;
    BI::make_icosphere(two, Point(0, 0, 0), 1.0, 2);
    BI::make_icosphere(two, Point(3, 0.5, 0), 0.7, 2);
    cases.push_back({"two components", two, 48});
  }
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    // A generic lattice and one with a round spacing and origin.
    const CGAL::Bbox_3 box = PMP::bbox(c.mesh);
    const BI::Regular_lattice_3 generic = BI::Regular_lattice_3::enclosing_with_cells(box, c.cells);
    const double round_spacing = std::ldexp(1.0, int(std::floor(std::log2(generic.spacing()))));
    const BI::Regular_lattice_3 round = BI::Regular_lattice_3::enclosing(box, round_spacing);
    for(const BI::Regular_lattice_3& lattice : {generic, round})
    {
      const std::vector<const Mesh*> meshes = {&c.mesh};
      const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
      const Classification_check check = compare_with_side_of_triangle_mesh(classifier, 0, c.mesh);
      EXPECT_EQ(check.mismatches, 0u);
      EXPECT_GT(check.compared, lattice.total_number_of_points() / 2);
      EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
      std::size_t inside = 0;
      for(std::size_t idx = 0; idx < lattice.total_number_of_points(); ++idx)
        inside += classifier.mask(idx) & 1;
      EXPECT_GT(inside, 0u);
      EXPECT_GT(classifier.number_of_crossings(), 0u);
    }
  }
}

// A lattice that covers only part of the mesh: crossings before the first
// lattice point of a line still count, crossings after the last do not.
TEST(LatticeClassifier, LatticeCoveringOnlyPartOfTheMesh)
{
  const Mesh bunny = load_mesh("bunny.off");
  const CGAL::Bbox_3 box = PMP::bbox(bunny);
  const CGAL::Bbox_3 middle(box.xmin() + 0.3 * (box.xmax() - box.xmin()), box.ymin() + 0.25 * (box.ymax() - box.ymin()),
                            box.zmin() + 0.2 * (box.zmax() - box.zmin()), box.xmin() + 0.7 * (box.xmax() - box.xmin()),
                            box.ymin() + 0.6 * (box.ymax() - box.ymin()), box.zmin() + 0.9 * (box.zmax() - box.zmin()));
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(middle, 32, 0);
  const std::vector<const Mesh*> meshes = {&bunny};
  const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
  const Classification_check check = compare_with_side_of_triangle_mesh(classifier, 0, bunny);
  EXPECT_EQ(check.mismatches, 0u);
  EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
  // The output is open where the solid meets the lattice boundary, and says so.
  const Soup soup = run_csg(meshes, BI::Boolean_expression::single(0, 1), lattice);
  EXPECT_GT(soup.statistics.boundary_points_inside, 0u);
  EXPECT_FALSE(soup.triangles.empty());
}

// 9 meshes and 33 meshes (more bits than a byte or a word): every bit of
// the mask is the classification of that mesh alone.
TEST(LatticeClassifier, ManyMeshesUseWiderMasks)
{
  for(std::size_t count : {9u, 33u})
  {
    SCOPED_TRACE(count);
    std::vector<Mesh> spheres;
    for(std::size_t m = 0; m < count; ++m)
    {
      const double angle = 2 * 3.14159265358979 * double(m) / double(count);
      spheres.push_back(make_sphere(Point(std::cos(angle), std::sin(angle), 0.1 * double(m % 3)), 0.45, 1));
    }
    std::vector<const Mesh*> pointers;
    for(const Mesh& m : spheres)
      pointers.push_back(&m);
    const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of(pointers), 28);
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(spheres, lattice);
    EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
    for(std::size_t m = 0; m < count; m += 4)
    {
      const BI::Lattice_classifier_3 alone = BI::Lattice_classifier_3::classify(std::vector<Mesh>{spheres[m]}, lattice);
      std::size_t wrong = 0;
      for(std::size_t idx = 0; idx < lattice.total_number_of_points(); ++idx)
        wrong += ((classifier.mask(idx) >> m) & 1) != alone.mask(idx);
      EXPECT_EQ(wrong, 0u) << "mesh " << m;
    }
    const Soup soup = run_csg(pointers, BI::Boolean_expression::union_of(count), lattice);
    check_output(soup, "union of " + std::to_string(count));
  }
}

// ------------------------------------------------------------------ 2. degenerate configurations

// Boxes whose faces lie on lattice planes (and vertices on lattice points):
// a point on the boundary is classified as the point moved by +d, i.e.
// inside iff low <= x < high on every axis.
TEST(McCsgDegenerate, BoxOnLatticePlanesFollowsThePerturbationConvention)
{
  const BI::Regular_lattice_3 lattice({{0, 0, 0}}, 1.0, {{8, 8, 8}});
  const std::vector<std::pair<Point, Point>> boxes = {
      {Point(2, 2, 2), Point(5, 5, 5)}, {Point(2, 1.5, 2), Point(5.5, 4, 3)}, {Point(0.5, 1, 3), Point(7, 6.25, 6)}};
  for(const auto& b : boxes)
  {
    const Mesh box = BI::test::make_box<Mesh>(b.first, b.second);
    const std::vector<const Mesh*> meshes = {&box};
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
    EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
    std::size_t wrong = 0;
    for(std::size_t k = 0; k < 8; ++k)
      for(std::size_t j = 0; j < 8; ++j)
        for(std::size_t i = 0; i < 8; ++i)
        {
          const std::array<double, 3> p{{double(i), double(j), double(k)}};
          bool expected = true;
          for(int a = 0; a < 3; ++a)
            expected = expected && b.first[a] <= p[a] && p[a] < b.second[a];
          wrong += expected != classifier.is_inside(0, i, j, k);
        }
    EXPECT_EQ(wrong, 0u);
    const Soup soup = run_csg(meshes, BI::Boolean_expression::single(0, 1), lattice);
    // The surface passes through lattice points: vertices may coincide there.
    const double volume = check_output(soup, "box", false);
    // Every vertex lies on the box (crossings of axis-aligned faces are
    // exact), so the output is inside the convex box; Marching Cubes cuts
    // its edges and corners, by at most one cell layer.
    for(const Point& p : soup.points)
    {
      bool on_a_face = false;
      for(int a = 0; a < 3; ++a)
      {
        EXPECT_GE(p[a], b.first[a]);
        EXPECT_LE(p[a], b.second[a]);
        on_a_face = on_a_face || p[a] == b.first[a] || p[a] == b.second[a];
      }
      EXPECT_TRUE(on_a_face) << p;
    }
    const double dx = b.second.x() - b.first.x(), dy = b.second.y() - b.first.y(), dz = b.second.z() - b.first.z();
    const double exact = dx * dy * dz, area = 2 * (dx * dy + dy * dz + dz * dx);
    EXPECT_LE(volume, exact + 1e-12);
    EXPECT_GE(volume, exact - 0.5 * area * lattice.spacing());
  }
}

// An octahedron centred on a lattice point with its vertices on lattice
// points: lattice rays run through its vertices, along and across its edges.
// Inside iff |x-c|_1 < r, or on the surface and the +d1 shift along x enters
// it (x < c_x; on the plane x = c_x the shift leaves it).
TEST(McCsgDegenerate, OctahedronThroughLatticePointsVerticesAndEdges)
{
  for(double spacing : {1.0, 0.5, 0.25})
  {
    SCOPED_TRACE(spacing);
    const Point c(4, 4, 4);
    const double r = 2;
    const Mesh octahedron = make_octahedron(c, r);
    const std::size_t n = std::size_t(8 / spacing) + 1;
    const BI::Regular_lattice_3 lattice({{0, 0, 0}}, spacing, {{n, n, n}});
    const std::vector<const Mesh*> meshes = {&octahedron};
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
    EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
    std::size_t wrong = 0, on_surface = 0;
    for(std::size_t k = 0; k < n; ++k)
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i)
        {
          const double x = lattice.coordinate(0, i), y = lattice.coordinate(1, j), z = lattice.coordinate(2, k);
          const double l1 = std::abs(x - 4) + std::abs(y - 4) + std::abs(z - 4); // exact: small dyadics
          const bool expected = l1 < r || (l1 == r && x < 4);
          on_surface += l1 == r;
          wrong += expected != classifier.is_inside(0, i, j, k);
        }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(on_surface, 0u);
    const Soup soup = run_csg(meshes, BI::Boolean_expression::single(0, 1), lattice);
    check_output(soup, "octahedron", false);
  }
}

// The same with a lattice that is not aligned with the octahedron at all,
// against Side_of_triangle_mesh, and with a rotated (non axis-aligned)
// octahedron whose vertices still are lattice points.
TEST(McCsgDegenerate, TiltedOctahedronWithLatticePointVertices)
{
  // Vertices at lattice points, edges along lattice diagonals.
  const std::vector<Point> points = {{5, 4, 4}, {3, 4, 4}, {4, 5, 5}, {4, 3, 3}, {4, 5, 3}, {4, 3, 5}};
  const std::vector<Triangle> triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  if(PMP::volume(mesh) < 0)
    PMP::reverse_face_orientations(mesh);
  const BI::Regular_lattice_3 lattice({{0, 0, 0}}, 0.5, {{17, 17, 17}});
  const std::vector<const Mesh*> meshes = {&mesh};
  const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
  EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
  const Classification_check check = compare_with_side_of_triangle_mesh(classifier, 0, mesh);
  EXPECT_EQ(check.mismatches, 0u);
  EXPECT_GT(check.on_boundary, 6u);
  // On the surface: as Side_of_triangle_mesh at p + (1e-3, 1e-5, 1e-7)
  // (close enough to the infinitesimal order for this small integer mesh).
  const CGAL::Side_of_triangle_mesh<Mesh, Epick> side(mesh);
  std::size_t wrong = 0;
  for(std::size_t k = 0; k < 17; ++k)
    for(std::size_t j = 0; j < 17; ++j)
      for(std::size_t i = 0; i < 17; ++i)
      {
        const Point p(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k));
        if(side(p) != CGAL::ON_BOUNDARY)
          continue;
        const Point q(p.x() + 1e-3, p.y() + 1e-5, p.z() + 1e-7);
        wrong += (side(q) == CGAL::ON_BOUNDED_SIDE) != classifier.is_inside(0, i, j, k);
      }
  EXPECT_EQ(wrong, 0u);
  check_output(run_csg(meshes, BI::Boolean_expression::single(0, 1), lattice), "tilted octahedron", false);
}

bool same_soup(const Soup& a, const Soup& b)
{
  return a.points == b.points && a.triangles == b.triangles;
}

TEST(McCsgDegenerate, IdenticalMeshes)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh b = a;
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(a), 30);
  const Soup alone = run_csg({&a}, BI::Boolean_expression::single(0, 1), lattice);
  // The lattice point (-1, 0, 0) is a vertex of the icosphere: the output
  // vertices of the edges around it all sit there.
  check_output(alone, "A", false);
  EXPECT_TRUE(same_soup(run_csg({&a, &b}, BI::Boolean_expression::union_of(2), lattice), alone));
  EXPECT_TRUE(same_soup(run_csg({&a, &b}, BI::Boolean_expression::intersection_of(2), lattice), alone));
  const Soup difference = run_csg({&a, &b}, BI::Boolean_expression::difference(), lattice);
  EXPECT_TRUE(difference.points.empty());
  EXPECT_TRUE(difference.triangles.empty());
  // Also on a round lattice, with many lattice points on the sphere's
  // vertices (+-1, 0, 0) etc. and on its edges.
  const BI::Regular_lattice_3 round({{-2, -2, -2}}, 0.125, {{33, 33, 33}});
  const Soup alone_round = run_csg({&a}, BI::Boolean_expression::single(0, 1), round);
  EXPECT_TRUE(same_soup(run_csg({&a, &b}, BI::Boolean_expression::union_of(2), round), alone_round));
  EXPECT_TRUE(run_csg({&a, &b}, BI::Boolean_expression::difference(), round).triangles.empty());
}

TEST(McCsgDegenerate, BoxesTouchingAlongAFace)
{
  const Mesh a = BI::test::make_box<Mesh>(Point(1, 1, 1), Point(3, 3, 3));
  const Mesh b = BI::test::make_box<Mesh>(Point(3, 1, 1), Point(5, 3, 3));
  for(double offset : {0.0, 0.1})
  {
    SCOPED_TRACE(offset);
    const BI::Regular_lattice_3 lattice({{offset, offset, offset}}, 0.5, {{13, 13, 13}});
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs({&a, &b}), lattice);
    EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
    const Soup u = run_csg({&a, &b}, BI::Boolean_expression::union_of(2), lattice);
    const double volume = check_output(u, "union", offset != 0);
    EXPECT_NEAR(volume, 16.0, 16 * 0.25);
    // The union is exactly what the merged box gives: same states, and the
    // crossings of axis-aligned faces are exact.
    const Mesh merged = BI::test::make_box<Mesh>(Point(1, 1, 1), Point(5, 3, 3));
    EXPECT_TRUE(same_soup(u, run_csg({&merged}, BI::Boolean_expression::single(0, 1), lattice)));
    // The common face is not in the union.
    for(const Triangle& t : u.triangles)
    {
      bool all_on_face = true;
      for(std::size_t v : t)
        all_on_face = all_on_face && u.points[v].x() == 3 && u.points[v].y() > 1 && u.points[v].y() < 3 &&
                      u.points[v].z() > 1 && u.points[v].z() < 3;
      EXPECT_FALSE(all_on_face);
    }
    EXPECT_TRUE(run_csg({&a, &b}, BI::Boolean_expression::intersection_of(2), lattice).triangles.empty());
    EXPECT_TRUE(same_soup(run_csg({&a, &b}, BI::Boolean_expression::difference(), lattice),
                          run_csg({&a}, BI::Boolean_expression::single(0, 1), lattice)));
  }
}

TEST(McCsgDegenerate, TorusAndItsCopyShiftedByOneTouchTangentially)
{
  // torus.off: axis z, R = 1, r = 0.5.  The copy rotated by 90 degrees
  // about x (exact: a permutation and a negation) and shifted by 1 along x
  // has its tube's centre circle at distance exactly 1 = r + r from the
  // original one everywhere: the tubes touch along a whole curve.
  const Mesh torus = load_mesh("torus.off");
  const Mesh shifted =
      translated(transformed(torus, [](const Point& p) { return Point(p.x(), -p.z(), p.y()); }), 1, 0, 0);
  const std::vector<const Mesh*> meshes = {&torus, &shifted};
  const CGAL::Bbox_3 box = bbox_of(meshes);
  // Round spacings put lattice points on the touching line x = 0.5 region.
  for(const BI::Regular_lattice_3& lattice :
      {BI::Regular_lattice_3::enclosing(box, 1.0 / 16), BI::Regular_lattice_3::enclosing_with_cells(box, 50)})
  {
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
    EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
    for(std::size_t m = 0; m < 2; ++m)
      EXPECT_EQ(compare_with_side_of_triangle_mesh(classifier, m, *meshes[m]).mismatches, 0u);
    const double v = PMP::volume(torus);
    const double u = check_output(run_csg(meshes, BI::Boolean_expression::union_of(2), lattice), "union");
    EXPECT_GT(u, 1.8 * v);
    EXPECT_LT(u, 2.1 * v);
    const Soup i = run_csg(meshes, BI::Boolean_expression::intersection_of(2), lattice);
    const double vi = check_output(i, "intersection");
    EXPECT_LT(vi, 0.2 * v);
    check_output(run_csg(meshes, BI::Boolean_expression::difference(), lattice), "difference");
  }
}

// ------------------------------------------------------------------ 3. output properties and volumes

struct Pair_case
{
  std::string name;
  Mesh a, b;
};

std::vector<Pair_case> pair_cases()
{
  std::vector<Pair_case> cases;
  cases.push_back({"spheres", make_sphere(Point(0, 0, 0), 1.0, 4), make_sphere(Point(0.8, 0.3, 0.1), 0.9, 4)});
  {
    Mesh torus;
    BI::make_torus(torus, Point(0, 0, 0), 1.0, 0.45, 64, 32);
    const Mesh linked = translated(
        transformed(torus, [](const Point& p) { return Point(p.x(), -p.z(), p.y()); }), 0.8, 0, 0);
    cases.push_back({"interlinked tori", torus, linked});
  }
  {
    const Mesh bunny = load_mesh("bunny.off");
    const CGAL::Bbox_3 box = PMP::bbox(bunny);
    cases.push_back({"bunny pair", bunny, translated(bunny, 0.3 * (box.xmax() - box.xmin()), 0, 0)});
  }
  return cases;
}

TEST(McCsgOutput, ClosedManifoldOutwardAndConvergingVolumes)
{
  for(const Pair_case& c : pair_cases())
  {
    const std::vector<const Mesh*> meshes = {&c.a, &c.b};
    const CGAL::Bbox_3 box = bbox_of(meshes);
    for(Operation op : {Operation::UNION, Operation::INTERSECTION, Operation::DIFFERENCE})
    {
      const std::string what = c.name + " " + name_of(op);
      SCOPED_TRACE(what);
      const double exact = corefinement_volume(c.a, c.b, op);
      ASSERT_GT(exact, 0);
      std::vector<double> errors;
      for(std::size_t cells : {24u, 48u, 96u})
      {
        const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(box, cells);
        const Soup soup = run_csg(meshes, expression_of(op), lattice);
        const double volume = check_output(soup, what + " " + std::to_string(cells));
        errors.push_back(std::abs(volume - exact) / exact);
      }
      std::cout << what << ": exact volume " << exact << ", relative errors " << errors[0] << " " << errors[1]
                << " " << errors[2] << std::endl;
      EXPECT_LT(errors[1], errors[0]);
      EXPECT_LT(errors[2], errors[1]);
      // Relative to the operands (a thin intersection has a large relative error).
      EXPECT_LT(errors[2] * exact, 0.005 * PMP::volume(c.a));
    }
  }
}

// ------------------------------------------------------------------ 4. INT_POINT against the seed

// The seed's INT_POINT, literally: p1 is the inside end; pa, pb the
// crossings with A and B (NaN: none).
double seed_int_point(Operation op, double p1, double pa, double pb)
{
  if(std::isnan(pa) || std::isnan(pb))
    return std::isnan(pa) ? pb : pa;
  const double da = std::abs(pa - p1), db = std::abs(pb - p1);
  if(op == Operation::UNION)
    return da > db ? pa : pb;
  return da < db ? pa : pb;
}

bool seed_csg_state(Operation op, bool a, bool b)
{
  switch(op)
  {
  case Operation::UNION: return a || b;
  case Operation::INTERSECTION: return a && b;
  default: return a && !b;
  }
}

TEST(McCsgIntPoint, EqualsTheSeedsRuleOnRandomEdges)
{
  std::mt19937_64 random(20260611);
  std::uniform_real_distribution<double> position(0.0, 1.0);
  std::size_t compared = 0;
  for(Operation op : {Operation::UNION, Operation::INTERSECTION, Operation::DIFFERENCE})
  {
    const BI::Boolean_expression e = expression_of(op);
    const BI::internal::Expression_evaluator inside(e);
    for(int trial = 0; trial < 20000; ++trial)
    {
      const std::uint64_t low_mask = random() & 3;
      const bool cross_a = random() & 1, cross_b = random() & 1;
      std::vector<BI::Lattice_crossing> crossings;
      const double none = std::numeric_limits<double>::quiet_NaN();
      const double pa = cross_a ? position(random) : none, pb = cross_b ? position(random) : none;
      if(cross_a)
        crossings.push_back({pa, 1, 0});
      if(cross_b)
        crossings.push_back({pb, 1, 1});
      std::sort(crossings.begin(), crossings.end(),
                [](const BI::Lattice_crossing& x, const BI::Lattice_crossing& y) { return x.position < y.position; });
      const std::uint64_t high_mask = low_mask ^ (cross_a ? 1 : 0) ^ (cross_b ? 2 : 0);
      const bool low_in = seed_csg_state(op, low_mask & 1, low_mask & 2);
      const bool high_in = seed_csg_state(op, high_mask & 1, high_mask & 2);
      ASSERT_EQ(low_in, inside(low_mask));
      ASSERT_EQ(high_in, inside(high_mask));
      if(low_in == high_in)
        continue;
      const double p1 = low_in ? 0.0 : 1.0;
      const std::size_t c = BI::internal::csg_edge_crossing(crossings.data(), crossings.size(), low_in,
                                                            low_in ? low_mask : high_mask, inside);
      ASSERT_LT(c, crossings.size());
      EXPECT_EQ(crossings[c].position, seed_int_point(op, p1, pa, pb)) << name_of(op) << " trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 20000u);
}

// End to end: every output vertex of a two-sphere CSG whose edge has at most
// one crossing per mesh is where the seed's INT_POINT puts it.  This also
// checks the documented vertex order (z plane, then edge id).
TEST(McCsgIntPoint, OutputVerticesFollowTheSeedsRule)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh b = make_sphere(Point(0.7, 0.2, -0.1), 0.8, 3);
  const std::vector<const Mesh*> meshes = {&a, &b};
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of(meshes), 40);
  const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
  const auto& n = lattice.number_of_points();
  for(Operation op : {Operation::UNION, Operation::INTERSECTION, Operation::DIFFERENCE})
  {
    SCOPED_TRACE(name_of(op));
    const Soup soup = run_csg(meshes, expression_of(op), lattice, false);
    auto state = [&](std::size_t i, std::size_t j, std::size_t k) {
      const std::uint64_t m = classifier.mask(i, j, k);
      return seed_csg_state(op, m & 1, m & 2);
    };
    std::size_t vertex = 0, compared = 0, wrong = 0;
    for(std::size_t k = 0; k < n[2]; ++k)
      for(std::size_t j = 0; j < n[1]; ++j)
        for(std::size_t i = 0; i < n[0]; ++i)
          for(int axis = 0; axis < 3; ++axis)
          {
            std::array<std::size_t, 3> q{{i, j, k}};
            if(++q[axis] >= n[axis])
              continue;
            const bool s1 = state(i, j, k), s2 = state(q[0], q[1], q[2]);
            if(s1 == s2)
              continue;
            ASSERT_LT(vertex, soup.points.size());
            const BI::Lattice_classifier_3::Crossing_range crossings = classifier.crossings_on_edge(axis, i, j, k);
            double pa = std::numeric_limits<double>::quiet_NaN(), pb = pa;
            int count_a = 0, count_b = 0;
            for(const BI::Lattice_crossing& c : crossings)
            {
              if(c.mesh == 0)
              {
                ++count_a;
                pa = c.position;
              }
              else
              {
                ++count_b;
                pb = c.position;
              }
            }
            const Point& p = soup.points[vertex++];
            // Off-axis coordinates are the lattice's.
            const std::array<double, 3> lp{{lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k)}};
            for(int b2 = 0; b2 < 3; ++b2)
            {
              if(b2 != axis)
                EXPECT_EQ(p[b2], lp[b2]);
            }
            if(count_a > 1 || count_b > 1)
              continue;
            const double p1 = s1 ? lp[axis] : lattice.coordinate(axis, q[axis]);
            wrong += p[axis] != seed_int_point(op, p1, pa, pb);
            ++compared;
          }
    EXPECT_EQ(vertex, soup.points.size());
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(compared, 1000u);
  }
}

// ------------------------------------------------------------------ 5. N-ary expressions

TEST(McCsgNary, ThreeSpheresAAndNotBOrC)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh b = make_sphere(Point(0.9, 0.1, 0), 0.8, 3);
  const Mesh c = make_sphere(Point(-0.2, 1.0, 0.3), 0.6, 3);
  const std::vector<const Mesh*> meshes = {&a, &b, &c};
  const BI::Boolean_expression e = BI::Boolean_expression::parse("A & !B | C");
  ASSERT_EQ(e.number_of_variables(), 3u);
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of(meshes), 48);
  const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
  EXPECT_EQ(classifier.number_of_inconsistent_edges(), 0u);
  const CGAL::Side_of_triangle_mesh<Mesh, Epick> side_a(a), side_b(b), side_c(c);
  const auto& n = lattice.number_of_points();
  std::vector<std::uint8_t> state(lattice.total_number_of_points());
  std::size_t wrong = 0, compared = 0;
  for(std::size_t k = 0; k < n[2]; ++k)
    for(std::size_t j = 0; j < n[1]; ++j)
      for(std::size_t i = 0; i < n[0]; ++i)
      {
        const std::size_t idx = lattice.linear_index(i, j, k);
        state[idx] = e.evaluate(classifier.mask(idx));
        const Point p(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k));
        const CGAL::Bounded_side sa = side_a(p), sb = side_b(p), sc = side_c(p);
        if(sa == CGAL::ON_BOUNDARY || sb == CGAL::ON_BOUNDARY || sc == CGAL::ON_BOUNDARY)
          continue;
        const std::uint64_t oracle = std::uint64_t(sa == CGAL::ON_BOUNDED_SIDE) |
                                     (std::uint64_t(sb == CGAL::ON_BOUNDED_SIDE) << 1) |
                                     (std::uint64_t(sc == CGAL::ON_BOUNDED_SIDE) << 2);
        wrong += e.evaluate(oracle) != bool(state[idx]);
        ++compared;
      }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(compared, lattice.total_number_of_points() / 2);

  const Soup soup = run_csg(meshes, e, lattice, false);
  // One vertex per edge with a change of output state.
  std::size_t changing = 0;
  for(std::size_t k = 0; k < n[2]; ++k)
    for(std::size_t j = 0; j < n[1]; ++j)
      for(std::size_t i = 0; i < n[0]; ++i)
      {
        const std::size_t idx = lattice.linear_index(i, j, k);
        changing += (i + 1 < n[0] && state[idx] != state[idx + 1]) + (j + 1 < n[1] && state[idx] != state[idx + n[0]]) +
                    (k + 1 < n[2] && state[idx] != state[idx + n[0] * n[1]]);
      }
  EXPECT_EQ(soup.points.size(), changing);
  const double volume = check_output(soup, "A & !B | C");
  // (A - B) | C by corefinement.
  Mesh ca = a, cb = b, cc = c, difference, result;
  ASSERT_TRUE(PMP::corefine_and_compute_difference(ca, cb, difference));
  ASSERT_TRUE(PMP::corefine_and_compute_union(difference, cc, result));
  const double exact = PMP::volume(result);
  EXPECT_LT(std::abs(volume - exact) / exact, 0.02) << volume << " vs " << exact;
}

// ------------------------------------------------------------------ 6. parallel = sequential

TEST(McCsgParallel, IdenticalToSequential)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "built without TBB";
#else
  const Mesh bunny = load_mesh("bunny.off");
  const CGAL::Bbox_3 box = PMP::bbox(bunny);
  const Mesh moved = translated(bunny, 0.3 * (box.xmax() - box.xmin()), 0, 0);
  const std::vector<const Mesh*> meshes = {&bunny, &moved};
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of(meshes), 64);
  for(Operation op : {Operation::UNION, Operation::DIFFERENCE})
  {
    const Soup sequential = run_csg<CGAL::Sequential_tag>(meshes, expression_of(op), lattice);
    const Soup parallel = run_csg<CGAL::Parallel_tag>(meshes, expression_of(op), lattice);
    EXPECT_FALSE(sequential.triangles.empty());
    EXPECT_TRUE(same_soup(sequential, parallel)) << name_of(op);
    EXPECT_EQ(sequential.statistics.crossings, parallel.statistics.crossings);
  }
  const BI::Lattice_classifier_3 s = BI::Lattice_classifier_3::classify<CGAL::Sequential_tag>(refs(meshes), lattice);
  const BI::Lattice_classifier_3 p = BI::Lattice_classifier_3::classify<CGAL::Parallel_tag>(refs(meshes), lattice);
  for(std::size_t idx = 0; idx < lattice.total_number_of_points(); ++idx)
    ASSERT_EQ(s.mask(idx), p.mask(idx));
  EXPECT_EQ(p.number_of_inconsistent_edges(), 0u);
#endif
}

// ------------------------------------------------------------------ sparse lattice

// The lattice is never stored point by point: a lattice of 2.7e10 points
// (a dense byte per point would be 25 GB) around a box a few cells wide
// costs its lines and crossings only.  The output is the one of a small
// lattice of the same spacing around the box: same counts, same volume.
TEST(McCsgSparse, HugeLatticeAroundASmallBoxEqualsASmallLattice)
{
  const double r = 1.0 / 1024;
  const Mesh box = BI::test::make_box<Mesh>(Point(1.5 + 0.31 * r, 1.5 + 0.27 * r, 1.5 + 0.45 * r),
                            Point(1.5 + 4.63 * r, 1.5 + 3.72 * r, 1.5 + 5.18 * r));
  const std::vector<const Mesh*> meshes = {&box};
  const BI::Boolean_expression a = BI::Boolean_expression::single(0, 1);
  const BI::Regular_lattice_3 huge({{0, 0, 0}}, r, {{3000, 3000, 3000}});
  // The small lattice's points 0..9 are the huge one's points 1536..1545.
  const BI::Regular_lattice_3 small({{1.5, 1.5, 1.5}}, r, {{10, 10, 10}});
  ASSERT_EQ(huge.coordinate(0, 1536), 1.5);
  const Soup far = run_csg(meshes, a, huge);
  const Soup near = run_csg(meshes, a, small);
  EXPECT_EQ(far.statistics.lattice_points, std::size_t(3000) * 3000 * 3000);
  EXPECT_EQ(far.points.size(), near.points.size());
  EXPECT_EQ(far.triangles.size(), near.triangles.size());
  const double exact = 4.32 * 3.45 * 4.73 * r * r * r;
  const double volume = check_output(far, "huge lattice");
  EXPECT_NEAR(volume, exact, 1e-9 * exact);
  EXPECT_NEAR(check_output(near, "small lattice"), volume, 1e-12 * exact);
}

// The sparse builder against a dense reference written here: every point's
// state from mask(), every cube through the same table, vertices numbered
// plane by plane by edge id 3 (i + nx j) + axis (the documented order).  The
// triangles must be the same, index for index, for an expression whose
// result is unbounded (!A | B: rows inside everywhere but near the surface)
// and one that is not, on a lattice that cuts the inputs.
TEST(McCsgSparse, EqualsADenseReferenceMarchingCubes)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh b = BI::test::make_box<Mesh>(Point(0.2, -0.4, -0.3), Point(1.4, 0.5, 0.6));
  const std::vector<const Mesh*> meshes = {&a, &b};
  // Cuts the sphere at x = -0.8 (a lattice narrower than the inputs).
  const BI::Regular_lattice_3 lattice({{-0.8, -1.3, -1.25}}, 0.0731, {{33, 37, 36}});
  const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(refs(meshes), lattice);
  const BI::Marching_cubes_table& table = BI::Marching_cubes_table::instance();
  for(const char* text : {"A & !B", "!A | B"})
  {
    SCOPED_TRACE(text);
    const BI::Boolean_expression e = BI::Boolean_expression::parse(text);
    const Soup soup = run_csg(meshes, e, lattice, false);
    const auto& n = lattice.number_of_points();
    auto state = [&](std::size_t i, std::size_t j, std::size_t k) { return e.evaluate(classifier.mask(i, j, k)); };
    // Vertex number of every vertex edge, in the documented order.
    std::map<std::array<std::size_t, 4>, std::size_t> vertex;
    for(std::size_t k = 0; k < n[2]; ++k)
      for(std::size_t j = 0; j < n[1]; ++j)
        for(std::size_t i = 0; i < n[0]; ++i)
        {
          const bool s = state(i, j, k);
          if(i + 1 < n[0] && s != state(i + 1, j, k)) vertex.emplace(std::array<std::size_t, 4>{{i, j, k, 0}}, vertex.size());
          if(j + 1 < n[1] && s != state(i, j + 1, k)) vertex.emplace(std::array<std::size_t, 4>{{i, j, k, 1}}, vertex.size());
          if(k + 1 < n[2] && s != state(i, j, k + 1)) vertex.emplace(std::array<std::size_t, 4>{{i, j, k, 2}}, vertex.size());
        }
    std::vector<Triangle> expected;
    for(std::size_t k = 0; k + 1 < n[2]; ++k)
      for(std::size_t j = 0; j + 1 < n[1]; ++j)
        for(std::size_t i = 0; i + 1 < n[0]; ++i)
        {
          unsigned code = 0;
          for(int c = 0; c < 8; ++c)
            code |= unsigned(state(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))) << c;
          for(const BI::Marching_cubes_table::Triangle& t : table.triangles(code))
          {
            Triangle out;
            for(int v = 0; v < 3; ++v)
            {
              const std::array<int, 3> o = BI::cube_edge_origin_offset(t[v]);
              out[v] = vertex.at({{i + std::size_t(o[0]), j + std::size_t(o[1]), k + std::size_t(o[2]),
                                   std::size_t(BI::cube_edge_axis(t[v]))}});
            }
            expected.push_back(out);
          }
        }
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(soup.points.size(), vertex.size());
    EXPECT_TRUE(soup.triangles == expected);
  }
}

// A lattice with 2^26 points or more along an axis is refused (the width
// of a crossing's index), with the axis and the limit.
TEST(McCsgSparse, AxisOfTwoToThe26PointsIsRefused)
{
  const Mesh box = BI::test::make_box<Mesh>(Point(0.1, 0.1, 0.1), Point(0.2, 0.2, 0.2));
  const BI::Regular_lattice_3 lattice({{0, 0, 0}}, 1.0 / (1u << 26), {{std::size_t(1) << 26, 4, 4}});
  try
  {
    BI::Lattice_classifier_3::classify(std::vector<Mesh>{box}, lattice);
    ADD_FAILURE() << "no exception";
  }
  catch(const BI::Lattice_too_large_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("along x"), std::string::npos) << e.what();
  }
}

// ------------------------------------------------------------------ API variants

TEST(McCsgApi, SurfaceMeshOutputVectorTrianglesProgressAndAppending)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 2);
  const Mesh b = make_sphere(Point(0.5, 0, 0), 1.0, 2);
  const std::vector<Mesh> meshes = {a, b};
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of({&a, &b}), 24);
  const BI::Boolean_expression e = BI::Boolean_expression::parse("A | B");

  std::vector<Point> points;
  std::vector<Triangle> triangles;
  BI::marching_cubes_csg(lattice, meshes, e, points, triangles);

  Mesh output;
  std::vector<double> fractions;
  const BI::Marching_cubes_csg_statistics s = BI::marching_cubes_csg(
      lattice, meshes, e, output, CGAL::parameters::callback(std::function<bool(double)>([&](double f) {
        fractions.push_back(f);
        return true;
      })));
  EXPECT_EQ(output.number_of_vertices(), points.size());
  EXPECT_EQ(output.number_of_faces(), triangles.size());
  EXPECT_EQ(s.number_of_faces, triangles.size());
  EXPECT_EQ(s.number_of_vertices, points.size());
  EXPECT_TRUE(CGAL::is_closed(output));
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GE(fractions.front(), 0.0);

  // Polygon soup of vectors; the outputs are cleared first (the package's rule).
  std::vector<Point> more_points(3, Point(0, 0, 0));
  std::vector<std::vector<std::size_t>> polygons(2, std::vector<std::size_t>{7, 8, 9});
  BI::marching_cubes_csg(lattice, meshes, e, more_points, polygons);
  ASSERT_EQ(more_points.size(), points.size());
  ASSERT_EQ(polygons.size(), triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int v = 0; v < 3; ++v)
      EXPECT_EQ(polygons[t][v], triangles[t][v]);
  EXPECT_GT(s.lattice_points, 0u);
  EXPECT_GT(s.crossings, 0u);
  EXPECT_GE(s.seconds_classification, 0.0);
  EXPECT_GE(s.seconds_edges, 0.0);
  EXPECT_GE(s.seconds_triangulation, 0.0);
}

// face_patch_map labels each face with the input mesh it lies on: two boxes
// overlapping along x, united; faces well away from the other box carry
// their own box's number, with and without sharp features.
TEST(McCsgApi, FacePatchMapNamesTheInputOfEachFace)
{
  const Mesh a = BI::test::make_box<Mesh>(Point(0, 0, 0), Point(1, 1, 1));
  const Mesh b = BI::test::make_box<Mesh>(Point(0.6, 0.2, 0.3), Point(1.7, 0.8, 0.9));
  const BI::Regular_lattice_3 lattice =
      BI::Regular_lattice_3::enclosing_with_cells(CGAL::Bbox_3(0, 0, 0, 1.7, 1, 1), 34);
  for(bool sharp : {false, true})
  {
    SCOPED_TRACE(sharp);
    Mesh out;
    auto patch = out.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 99).first;
    BI::marching_cubes_csg(lattice, std::vector<Mesh>{a, b}, BI::Boolean_expression::union_of(2), out,
                           BI::parameters::sharp_features(sharp).face_patch_map(patch));
    ASSERT_GT(out.number_of_faces(), 100u);
    std::size_t checked[2] = {0, 0};
    for(const Mesh::Face_index f : out.faces())
    {
      ASSERT_LT(patch[f], 2u);
      Point c = CGAL::centroid(out.point(out.target(out.halfedge(f))),
                               out.point(out.target(out.next(out.halfedge(f)))),
                               out.point(out.source(out.halfedge(f))));
      if(c.x() < 0.5)
      {
        EXPECT_EQ(patch[f], 0u) << c;
        ++checked[0];
      }
      else if(c.x() > 1.1)
      {
        EXPECT_EQ(patch[f], 1u) << c;
        ++checked[1];
      }
    }
    EXPECT_GT(checked[0], 50u);
    EXPECT_GT(checked[1], 50u);
  }
}

TEST(McCsgApi, PolyhedronInputGivesTheSameOutput)
{
  typedef CGAL::Polyhedron_3<Epick> Polyhedron;
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 2);
  const Mesh b = make_sphere(Point(0.6, 0.1, 0), 0.8, 2);
  Polyhedron pa, pb;
  CGAL::copy_face_graph(a, pa);
  CGAL::copy_face_graph(b, pb);
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(bbox_of({&a, &b}), 24);
  const BI::Boolean_expression e = BI::Boolean_expression::difference();
  Soup from_polyhedra;
  BI::marching_cubes_csg(lattice, std::vector<std::reference_wrapper<const Polyhedron>>{std::cref(pa), std::cref(pb)}, e, from_polyhedra.points, from_polyhedra.triangles);
  EXPECT_FALSE(from_polyhedra.triangles.empty());
  // Same combinatorics; the positions may differ in the last bits (the
  // copy may start the faces at another vertex, which changes the order of
  // the floating-point sums).
  const Soup from_surface_meshes = run_csg({&a, &b}, e, lattice);
  EXPECT_EQ(from_polyhedra.triangles, from_surface_meshes.triangles);
  ASSERT_EQ(from_polyhedra.points.size(), from_surface_meshes.points.size());
  for(std::size_t v = 0; v < from_polyhedra.points.size(); ++v)
    EXPECT_LT(CGAL::squared_distance(from_polyhedra.points[v], from_surface_meshes.points[v]), 1e-24);
}

TEST(McCsgApi, ComplementIsReportedAsOpenAtTheLatticeBoundary)
{
  const Mesh a = make_sphere(Point(0, 0, 0), 1.0, 2);
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(a), 16);
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  const auto s = BI::marching_cubes_csg(lattice, std::vector<Mesh>{a}, BI::Boolean_expression::parse("!A"), points,
                                        triangles);
  const auto& n = lattice.number_of_points();
  EXPECT_EQ(s.boundary_points_inside, n[0] * n[1] * n[2] - (n[0] - 2) * (n[1] - 2) * (n[2] - 2));
  // Its surface is the sphere's, reversed.
  EXPECT_LT(BI::surveyor_volume(points, triangles, BI::parameters::signed_volume(true)), 0);
}

// ------------------------------------------------------------------ 7. bad input

// The resolution check of the result itself: a box minus a box 0.02 smaller
// on every side is a shell 0.02 thick.  At spacing 1/16 most x-line
// intervals through its two x-walls hold no lattice point; at 1/128 every
// interval of the result is at least 0.02 > 2 spacings long.
// The resolution check's components: a soup's by its vertex indices, a
// mesh's by positions.  On a welded soup the two agree triangle for triangle;
// two boxes in one soup that touch at a corner point without sharing its
// index are two closed shells, and are judged as two.
TEST(McCsgResolution, SoupComponentsFollowTheIndicesAndAgreeWithPositionsWhenWelded)
{
  auto soup_of = [](const std::vector<const Mesh*>& parts) {
    BI::Triangle_soup_3 soup;
    for(const Mesh* m : parts)
    {
      const std::uint32_t offset = std::uint32_t(soup.points.size());
      for(const auto v : vertices(*m))
        soup.points.push_back({m->point(v).x(), m->point(v).y(), m->point(v).z()});
      for(const auto f : faces(*m))
      {
        const auto h = halfedge(f, *m);
        soup.triangles.push_back({offset + std::uint32_t(source(h, *m)), offset + std::uint32_t(target(h, *m)),
                                  offset + std::uint32_t(target(next(h, *m), *m))});
      }
    }
    return soup;
  };
  Mesh sphere, torus;
  BI::make_icosphere(sphere, Point(0, 0, 0), 1.0, 3);
  BI::make_torus(torus, Point(3, 0, 0), 1.0, 0.3, 40, 20);
  const Mesh box = BI::test::make_box<Mesh>(Point(-3, -1, -1), Point(-2, 0, 0));
  const std::vector<BI::Triangle_soup_3> welded{soup_of({&sphere, &torus}), soup_of({&box})};
  std::size_t read = 0;
  const std::vector<BI::internal::Lattice_triangle> triangles =
      BI::Lattice_classifier_3::read_meshes(welded, read);
  namespace MC = BI::internal::Marching_cubes_csg;
  const MC::Component_labels by_index = MC::label_input_components(welded, triangles);
  const MC::Component_labels by_position = MC::label_components(triangles);
  ASSERT_EQ(by_index.components.size(), 3u);
  ASSERT_EQ(by_position.components.size(), 3u);
  EXPECT_EQ(by_index.of_triangle, by_position.of_triangle);
  for(std::size_t c = 0; c < 3; ++c)
  {
    EXPECT_EQ(by_index.components[c].mesh, by_position.components[c].mesh);
    EXPECT_EQ(by_index.components[c].number, by_position.components[c].number);
    EXPECT_EQ(by_index.components[c].triangles, by_position.components[c].triangles);
    EXPECT_EQ(by_index.components[c].volume, by_position.components[c].volume);
    EXPECT_EQ(by_index.components[c].area, by_position.components[c].area);
  }
  EXPECT_NEAR(by_index.components[2].volume, 1.0, 1e-12);

  // Corner (0, 0, 0) of both boxes, twice in the soup.
  const Mesh low = BI::test::make_box<Mesh>(Point(-1, -1, -1), Point(0, 0, 0));
  const Mesh high = BI::test::make_box<Mesh>(Point(0, 0, 0), Point(1, 1, 1));
  const std::vector<BI::Triangle_soup_3> touching{soup_of({&low, &high})};
  const std::vector<BI::internal::Lattice_triangle> touching_triangles =
      BI::Lattice_classifier_3::read_meshes(touching, read);
  EXPECT_EQ(MC::label_input_components(touching, touching_triangles).components.size(), 2u);
  EXPECT_EQ(MC::label_components(touching_triangles).components.size(), 1u);
}

TEST(McCsgResolution, ThinShellOfADifferenceIsMeasuredOnTheResult)
{
  const Mesh outer = BI::test::make_box<Mesh>(Point(0, 0, 0), Point(1, 1, 1));
  const Mesh inner = BI::test::make_box<Mesh>(Point(0.02, 0.02, 0.02), Point(0.98, 0.98, 0.98));
  const CGAL::Bbox_3 box(0, 0, 0, 1, 1, 1);
  const Soup coarse = run_csg({&outer, &inner}, BI::Boolean_expression::difference(),
                              BI::Regular_lattice_3::enclosing(box, 1.0 / 16));
  EXPECT_EQ(coarse.statistics.under_resolved_components.size(), 0u) << "each input alone is resolved";
  EXPECT_GT(coarse.statistics.thin_result_intervals, 0u);
  EXPECT_LT(coarse.statistics.thin_result_intervals, coarse.statistics.result_intervals);
  const double coarse_part = coarse.statistics.thin_result_volume / coarse.statistics.result_line_volume;
  std::cout << "shell at 1/16: " << coarse.statistics.thin_result_intervals << " of "
            << coarse.statistics.result_intervals << " intervals thin, " << 100 * coarse_part
            << " % of the line volume, suggested spacing " << coarse.statistics.thin_result_suggested_spacing << "\n";
  // Measured on the lattice's x-lines: none runs inside the y- and z-walls
  // (0.02 thick, lines 1/16 apart), so all of the line volume is the thin
  // x-wall intervals (measured: 100 %).
  EXPECT_GT(coarse_part, 0.5);
  EXPECT_LE(coarse_part, 1 + 1e-12);
  EXPECT_GT(coarse.statistics.thin_result_suggested_spacing, 0);
  EXPECT_LE(coarse.statistics.thin_result_suggested_spacing, 0.01 + 1e-12);
  // Well above the 2 % the library warns at: one warning says so.
  EXPECT_TRUE(coarse.statistics.has_thin_result());
  EXPECT_EQ(std::count_if(coarse.statistics.warnings.begin(), coarse.statistics.warnings.end(),
                          [](const std::string& w) { return w.find("thinner than a cell") != std::string::npos; }),
            1);

  const Soup fine = run_csg({&outer, &inner}, BI::Boolean_expression::difference(),
                            BI::Regular_lattice_3::enclosing(box, 1.0 / 128));
  EXPECT_GT(fine.statistics.result_intervals, coarse.statistics.result_intervals);
  EXPECT_EQ(fine.statistics.thin_result_intervals, 0u);
  EXPECT_EQ(fine.statistics.thin_result_volume, 0);
  EXPECT_EQ(fine.statistics.thin_result_suggested_spacing, 0);
  EXPECT_FALSE(fine.statistics.has_thin_result());
  EXPECT_TRUE(fine.statistics.warnings.empty());

  // Two overlapping boxes: nothing thin, and the line volume is exact along
  // x-lines (box faces between lattice planes).
  const Mesh moved = BI::test::make_box<Mesh>(Point(0.5, 0.25, 0.25), Point(1.5, 0.75, 0.75));
  const Soup both = run_csg({&outer, &moved}, BI::Boolean_expression::union_of(2),
                            BI::Regular_lattice_3::enclosing(CGAL::Bbox_3(0, 0, 0, 1.5, 1, 1), 1.0 / 16));
  EXPECT_EQ(both.statistics.thin_result_intervals, 0u);
  EXPECT_GT(both.statistics.result_line_volume, 0.5);
  // Without the check nothing is measured.
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  const BI::Marching_cubes_csg_statistics off = BI::marching_cubes_csg(
      BI::Regular_lattice_3::enclosing(box, 1.0 / 16), refs({&outer, &inner}), BI::Boolean_expression::difference(),
      points, triangles, BI::parameters::resolution_check(false));
  EXPECT_EQ(off.result_intervals, 0u);
}

// Walls one lattice point thick: a ball minus a ball 0.04 smaller in radius
// at spacing 0.04 / 1.1.  Nearly every interval through the shell holds one
// or two lattice points (none is empty), yet the table joins the points of
// an oblique wall only through some cube faces, so the shell comes out in
// pieces; the sparse measure sees it along every axis.  At spacing 0.01 the
// shell holds at least 4 points across.
TEST(McCsgResolution, ShellOnePointThickIsReportedAsSparse)
{
  const Mesh outer = make_sphere(Point(0.013, -0.021, 0.007), 1.0, 4);
  const Mesh inner = make_sphere(Point(0.013, -0.021, 0.007), 0.96, 4);
  const double exact = BI::test::exact_volume(outer) - BI::test::exact_volume(inner);
  const CGAL::Bbox_3 box = PMP::bbox(outer);
  const Soup coarse = run_csg({&outer, &inner}, BI::Boolean_expression::difference(),
                              BI::Regular_lattice_3::enclosing(box, 0.04 / 1.1));
  const double coarse_volume = check_output(coarse, "coarse shell", false);
  std::cout << "shell at 0.04/1.1: sparse " << 100 * coarse.statistics.sparse_result_fraction << " %, thin "
            << 100 * coarse.statistics.thin_result_fraction() << " %, volume error "
            << 100 * (coarse_volume - exact) / exact << " %, suggested spacing "
            << coarse.statistics.sparse_result_suggested_spacing << "\n";
  EXPECT_FALSE(coarse.statistics.has_thin_result());
  EXPECT_TRUE(coarse.statistics.has_sparse_result());
  EXPECT_LT(coarse_volume, 0.97 * exact) << "pieces of the shell are missing";
  EXPECT_GT(coarse.statistics.sparse_result_suggested_spacing, 0);
  EXPECT_LT(coarse.statistics.sparse_result_suggested_spacing, 0.04 / 1.1);
  EXPECT_EQ(std::count_if(coarse.statistics.warnings.begin(), coarse.statistics.warnings.end(),
                          [](const std::string& w) { return w.find("at most one lattice point") != std::string::npos; }),
            1);

  const Soup fine = run_csg({&outer, &inner}, BI::Boolean_expression::difference(),
                            BI::Regular_lattice_3::enclosing(box, 0.01));
  const double fine_volume = check_output(fine, "fine shell", false);
  EXPECT_LT(fine.statistics.sparse_result_fraction, 0.01);
  EXPECT_FALSE(fine.statistics.has_sparse_result());
  EXPECT_TRUE(fine.statistics.warnings.empty());
  EXPECT_NEAR(fine_volume, exact, 0.005 * exact);
}


template <typename Exception>
void expect_error(const std::function<void()>& f, const std::string& fragment)
{
  try
  {
    f();
    ADD_FAILURE() << "no exception, expected one mentioning \"" << fragment << "\"";
  }
  catch(const Exception& e)
  {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
  catch(const std::exception& e)
  {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

TEST(McCsgBadInput, SpecificExceptionsWithClearMessages)
{
  const Mesh sphere = make_sphere(Point(0, 0, 0), 1.0, 1);
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(sphere), 8);
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  const BI::Boolean_expression two = BI::Boolean_expression::union_of(2);

  Mesh open = sphere;
  CGAL::Euler::remove_face(halfedge(*faces(open).begin(), open), open);
  expect_error<BI::Open_mesh_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{sphere, open}, two, points, triangles); },
      "mesh #1 is not closed");

  expect_error<BI::Empty_input_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{sphere, Mesh()}, two, points, triangles); },
      "mesh #1 has no face");
  expect_error<BI::Empty_input_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{}, BI::Boolean_expression(), points, triangles); },
      "no input mesh");

  Mesh nan_mesh = sphere;
  nan_mesh.point(*vertices(nan_mesh).begin()) = Point(std::nan(""), 0, 0);
  expect_error<BI::Non_finite_value_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{nan_mesh, sphere}, two, points, triangles); },
      "mesh #0: vertex #0 has a non-finite coordinate");

  Mesh quad;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1),
                        Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), quad);
  expect_error<BI::Non_triangle_face_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{quad}, BI::Boolean_expression::single(0, 1), points, triangles); },
      "is not a triangle");

  expect_error<BI::Invalid_input_error>(
      [&] { BI::marching_cubes_csg(lattice, std::vector<Mesh>{sphere}, two, points, triangles); },
      "has 2 variable(s) but 1 mesh(es)");
  expect_error<BI::Invalid_input_error>(
      [&] {
        BI::marching_cubes_csg(lattice, std::vector<Mesh>{sphere, sphere, sphere}, two, points, triangles);
      },
      "has 2 variable(s) but 3 mesh(es)");

  expect_error<BI::Lattice_too_large_error>(
      [&] { BI::Regular_lattice_3::enclosing(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 1e-9); }, "2^62");
  // The memory limit.
  expect_error<BI::Lattice_too_large_error>(
      [&] {
        BI::marching_cubes_csg(lattice, std::vector<Mesh>{sphere}, BI::Boolean_expression::single(0, 1), points,
                               triangles, BI::parameters::max_memory_bytes(std::size_t(1000)));
      },
      "max_memory_bytes");
  EXPECT_TRUE(points.empty());
  EXPECT_TRUE(triangles.empty());
}

} // namespace
