// Tests of surveyor_volume(): analytic values, invariances, accuracy against
// the exact (Epeck) volume on generated and real meshes, and every bad input.

#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/internal/check_closed_soup.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace CGAL::Boolean_isosurfacing::test::kernels;
typedef std::array<std::size_t, 3> Triangle;

using CGAL::Boolean_isosurfacing::test::exact_volume; // the oracle

double relative_error(double value, double reference)
{
  return std::abs(value - reference) / std::abs(reference);
}

Mesh make_triangulated_box(const Point& low, const Point& high)
{
  Mesh mesh;
  CGAL::make_hexahedron(Point(low.x(), low.y(), low.z()), Point(high.x(), low.y(), low.z()),
                        Point(high.x(), high.y(), low.z()), Point(low.x(), high.y(), low.z()),
                        Point(low.x(), high.y(), high.z()), Point(low.x(), low.y(), high.z()),
                        Point(high.x(), low.y(), high.z()), Point(high.x(), high.y(), high.z()), mesh);
  PMP::triangulate_faces(mesh);
  return mesh;
}

Mesh make_sphere(const Point& center, double radius, unsigned subdivisions)
{
  Mesh mesh;
  BI::make_icosphere(mesh, center, radius, subdivisions);
  return mesh;
}

Mesh make_torus(const Point& center, double major, double minor, std::size_t nu, std::size_t nv)
{
  Mesh mesh;
  BI::make_torus(mesh, center, major, minor, nu, nv);
  return mesh;
}

Mesh translated(const Mesh& mesh, const Epick::Vector_3& t)
{
  Mesh copy = mesh;
  PMP::transform(Epick::Aff_transformation_3(CGAL::TRANSLATION, t), copy);
  return copy;
}

// The seed's algorithm, literally: unsigned tetrahedron volumes against the
// centroid, added or subtracted by the sign of n . (tc - c).
double seed_literal_volume(const Mesh& mesh)
{
  Epick::Vector_3 sum(0, 0, 0);
  for(auto v : vertices(mesh)) sum = sum + (mesh.point(v) - CGAL::ORIGIN);
  const Point c = CGAL::ORIGIN + sum / double(mesh.number_of_vertices());
  double volume = 0;
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    const Point& t1 = mesh.point(target(h, mesh));
    const Point& t2 = mesh.point(target(next(h, mesh), mesh));
    const Point& t3 = mesh.point(target(next(next(h, mesh), mesh), mesh));
    const Epick::Vector_3 tn = CGAL::cross_product(t2 - t1, t3 - t1);
    const Point tc = CGAL::centroid(t1, t2, t3);
    const double d = tn * (tc - c);
    const double unsigned_volume = std::abs(CGAL::volume(t1, t2, t3, c));
    if(d < 0) volume -= unsigned_volume;
    if(d > 0) volume += unsigned_volume;
  }
  return volume;
}

// ---------------------------------------------------------------- analytic

TEST(SurveyorVolume, AnalyticTetrahedronCubeOctahedron)
{
  Mesh tetrahedron;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tetrahedron);
  EXPECT_NEAR(BI::surveyor_volume(tetrahedron), 1.0 / 6.0, 1e-16);

  const Mesh cube = make_triangulated_box(Point(-1, -1, -1), Point(1, 1, 1));
  EXPECT_NEAR(BI::surveyor_volume(cube), 8.0, 1e-15);

  // Octahedron with vertices at +-1 on the axes: volume 4/3.
  const std::vector<Point> points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::vector<Triangle> triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  EXPECT_NEAR(BI::surveyor_volume(points, triangles), 4.0 / 3.0, 1e-15);
  Mesh octahedron;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, octahedron);
  EXPECT_NEAR(BI::surveyor_volume(octahedron), 4.0 / 3.0, 1e-15);
}

TEST(SurveyorVolume, ExactKernelGivesExactRationalVolume)
{
  Exact_mesh tetrahedron;
  CGAL::make_tetrahedron(Epeck::Point_3(0, 0, 0), Epeck::Point_3(1, 0, 0), Epeck::Point_3(0, 1, 0),
                         Epeck::Point_3(0, 0, 1), tetrahedron);
  EXPECT_TRUE(BI::surveyor_volume(tetrahedron) == Epeck::FT(1) / Epeck::FT(6));
}

TEST(SurveyorVolume, GeneratedShapesAreClosedOutwardAndNearTheirSmoothVolume)
{
  const double pi = 3.14159265358979323846;
  const Mesh sphere = make_sphere(Point(0, 0, 0), 1.0, 5);
  EXPECT_TRUE(CGAL::is_closed(sphere));
  EXPECT_EQ(sphere.number_of_faces(), 20480u);
  // An inscribed polyhedron: a little smaller than the ball.
  const double ball = 4.0 / 3.0 * pi;
  EXPECT_LT(BI::surveyor_volume(sphere), ball);
  EXPECT_GT(BI::surveyor_volume(sphere), ball * (1 - 2e-3));

  const Mesh torus = make_torus(Point(0, 0, 0), 1.0, 0.5, 256, 128);
  EXPECT_TRUE(CGAL::is_closed(torus));
  const double smooth_torus = 2 * pi * pi * 1.0 * 0.25;
  EXPECT_LT(BI::surveyor_volume(torus), smooth_torus);
  EXPECT_GT(BI::surveyor_volume(torus), smooth_torus * (1 - 1e-3));
}

TEST(SurveyorVolume, SignTestEqualsTheSeedsLiteralAlgorithm)
{
  for(const Mesh& mesh : {make_torus(Point(0.3, -2, 5), 2.0, 0.7, 40, 17), make_sphere(Point(1, 2, 3), 2.0, 3)})
  {
    const double ours = BI::surveyor_volume(mesh);
    EXPECT_LT(relative_error(ours, seed_literal_volume(mesh)), 1e-13);
    EXPECT_LT(relative_error(ours, exact_volume(mesh)), 1e-14);
  }
}

// ------------------------------------------------------------- invariances

TEST(SurveyorVolume, ReversingTheOrientationFlipsTheSign)
{
  const Mesh torus = make_torus(Point(0, 0, 0), 1.0, 0.4, 60, 30);
  Mesh reversed = torus;
  PMP::reverse_face_orientations(reversed);
  const double v = BI::surveyor_volume(torus);
  const double r = BI::surveyor_volume(reversed, BI::parameters::signed_volume(true));
  EXPECT_LT(r, 0);
  EXPECT_LT(relative_error(-r, v), 1e-14);
  // Without the opt-in, an inward surface is an error, not a negative number.
  EXPECT_THROW(BI::surveyor_volume(reversed), BI::Inward_oriented_mesh_error);
}

TEST(SurveyorVolume, InvariantUnderTranslationAndRotation)
{
  const Mesh mesh = make_torus(Point(0, 0, 0), 1.0, 0.3, 80, 40);
  const double v = BI::surveyor_volume(mesh);
  // Translation by integers keeps small integer-free coordinates exact only
  // up to rounding; compare with the exact volume of the moved mesh, and
  // with the unmoved value up to the rounding of the input coordinates.
  for(const Epick::Vector_3 t : {Epick::Vector_3(3, -7, 11), Epick::Vector_3(1e3, 2e3, -4e3)})
  {
    const Mesh moved = translated(mesh, t);
    const double w = BI::surveyor_volume(moved);
    EXPECT_LT(relative_error(w, exact_volume(moved)), 1e-12);
    EXPECT_LT(relative_error(w, v), 1e-10);
  }
  // Rotations about several axes (rounded coordinates: same tolerances).
  for(int k = 1; k <= 5; ++k)
  {
    const double a = 0.37 * k, c = std::cos(a), s = std::sin(a);
    const Epick::Aff_transformation_3 rotation(c, -s, 0, s * c, c * c, -s, s * s, c * s, c);
    Mesh rotated = mesh;
    PMP::transform(rotation, rotated);
    const double w = BI::surveyor_volume(rotated);
    EXPECT_LT(relative_error(w, exact_volume(rotated)), 1e-12);
    EXPECT_LT(relative_error(w, v), 1e-12);
  }
}

// The headline accuracy claim: far from the origin, the centroid reference
// point keeps every digit while PMP::volume (tetrahedra against the origin)
// loses them.  The exact value is the Epeck volume of the same doubles.
TEST(SurveyorVolume, FarFromTheOriginKeepsItsDigitsWherePmpVolumeLosesThem)
{
  struct Case { const char* name; Mesh mesh; };
  const Case cases[] = {
      {"unit cube moved to 1e6", make_triangulated_box(Point(1e6, 1e6, 1e6), Point(1e6 + 1, 1e6 + 1, 1e6 + 1))},
      {"unit sphere moved to 1e7", make_sphere(Point(1e7, 1e7, 1e7), 1.0, 4)},
      {"torus moved to (-3e5, 2e5, 7e5)", make_torus(Point(-3e5, 2e5, 7e5), 1.0, 0.5, 64, 32)},
      {"unit sphere at the origin", make_sphere(Point(0, 0, 0), 1.0, 4)}};
  std::printf("%-34s %-24s %-10s %-10s\n", "mesh", "exact volume", "ours", "PMP::volume");
  for(const Case& c : cases)
  {
    const double exact = exact_volume(c.mesh);
    const double ours = relative_error(BI::surveyor_volume(c.mesh), exact);
    const double pmp = relative_error(PMP::volume(c.mesh), exact);
    std::printf("%-34s %-24.17g %-10.2e %-10.2e\n", c.name, exact, ours, pmp);
    EXPECT_LT(ours, 1e-12) << c.name;
    EXPECT_LE(ours, pmp + 1e-15) << c.name;
  }
}

// A sum that cancels completely: a sphere far from the origin and its
// reversed copy in one mesh enclose exactly zero.  The double sum cannot
// certify any relative accuracy there, so the exact fallback must run and
// return exactly 0 -- not a rounding residue.
TEST(SurveyorVolume, CancellingSumFallsBackToExactArithmetic)
{
  Mesh both = make_sphere(Point(1e5 + 0.1, -2e5, 3.3e5), 1.0, 3);
  Mesh reversed = both;
  PMP::reverse_face_orientations(reversed);
  CGAL::copy_face_graph(reversed, both);
  EXPECT_EQ(BI::surveyor_volume(both, BI::parameters::signed_volume(true)), 0.0);
  EXPECT_EQ(exact_volume(both), 0.0);

  // Nearly cancelling: a big sphere minus a slightly smaller reversed one
  // (a thin shell).  Compare with the exact value.
  Mesh shell = make_sphere(Point(7e3, 0, 0), 1.0, 4);
  Mesh inner = make_sphere(Point(7e3, 0, 0), 1.0 - 1e-9, 4);
  PMP::reverse_face_orientations(inner);
  CGAL::copy_face_graph(inner, shell);
  const double exact = exact_volume(shell);
  EXPECT_GT(exact, 0);
  EXPECT_LT(relative_error(BI::surveyor_volume(shell), exact), 1e-14);
}

// The AVX kernel (chosen at run time where the processor has it) runs the
// SSE2 kernel's lanes on wider registers: its sums must be the same bits, for
// every count of triangles (the last n mod 4 go to the SSE2 code) and for
// terms of mixed signs and magnitudes.  Where AVX is absent both runs take
// the SSE2 path and the test checks nothing more than determinism.
TEST(SurveyorVolume, AvxAndSse2KernelsGiveTheSameBits)
{
  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for(std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(7),
                       std::size_t(1000), std::size_t(4099)})
  {
    std::vector<std::array<double, 3>> corners(3 * n);
    for(auto& c : corners)
    {
      const double scale = std::ldexp(1.0, exponent(random));
      c = {1e3 + scale * coordinate(random), scale * coordinate(random), -7 + scale * coordinate(random)};
    }
    const auto corner = [&](std::size_t i, int k) { return corners[3 * i + std::size_t(k)].data(); };
    double sum[2], permanents[2];
    std::size_t count[2];
    for(int avx = 0; avx < 2; ++avx)
    {
      BI::internal::Tetrahedra_pair_sum pair_sum(1e3 + 0.25, -0.5, -7.125, avx == 1);
      // In two calls, as the mesh overload feeds batches.
      pair_sum.add(n / 2, corner);
      pair_sum.add(n - n / 2, [&](std::size_t i, int k) { return corner(n / 2 + i, k); });
      pair_sum.finish(sum[avx], permanents[avx], count[avx]);
    }
    EXPECT_EQ(std::memcmp(&sum[0], &sum[1], sizeof(double)), 0) << n << " triangles: " << sum[0] << " " << sum[1];
    EXPECT_EQ(std::memcmp(&permanents[0], &permanents[1], sizeof(double)), 0) << n << " triangles";
    EXPECT_EQ(count[0], count[1]);
    if(n > 0)
      EXPECT_GT(permanents[0], 0);
  }
}

// A thin-walled part turned off the axes (a hollow box, walls 2 % of its
// size): its permanents are many times its volume, so the double bound
// fails; the long double tier (where long double is wider) certifies it
// without the exact sum, which would visit the terms a second time.
TEST(SurveyorVolume, ThinRotatedWallsAreCertifiedInLongDoubleWithoutTheExactSum)
{
  Mesh shell = BI::test::make_box<Mesh>(Point(0, 0, 0), Point(1, 1, 1));
  Mesh inner = BI::test::make_box<Mesh>(Point(0.02, 0.02, 0.02), Point(0.98, 0.98, 0.98));
  PMP::reverse_face_orientations(inner);
  CGAL::copy_face_graph(inner, shell);
  typedef CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  shell = BI::test::moved(shell, Point(0.5, 0.5, 0.5), Vector(1, 2, 3), 0.4, Vector(3.1, -2.7, 0.9));

  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for(auto v : vertices(shell))
    points.push_back({shell.point(v).x(), shell.point(v).y(), shell.point(v).z()});
  for(auto f : faces(shell))
  {
    auto h = halfedge(f, shell);
    triangles.push_back({std::uint32_t(target(h, shell)), std::uint32_t(target(next(h, shell), shell)),
                         std::uint32_t(target(prev(h, shell), shell))});
  }
  const std::array<double, 3> c = BI::internal::finite_centroid(points);
  BI::internal::Tetrahedra_pair_sum pair_sum(c[0], c[1], c[2]);
  pair_sum.add(triangles.size(), [&](std::size_t i, int k) { return points[triangles[i][std::size_t(k)]].data(); });
  double s, permanents;
  std::size_t n;
  pair_sum.finish(s, permanents, n);
  EXPECT_GT(permanents, 4 * std::abs(s)) << "the double bound would pass: the test no longer tests the tier";

  int visits = 0;
  const double volume = BI::internal::certified_or_exact_sum(s, permanents, n, c[0], c[1], c[2], [&](const auto& f) {
    ++visits;
    for(const auto& t : triangles)
    {
      const auto &a = points[t[0]], &b = points[t[1]], &d = points[t[2]];
      f(a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2]);
    }
  });
  if(std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits)
    EXPECT_EQ(visits, 1) << "the exact sum ran";
  const double exact = exact_volume(shell);
  EXPECT_LT(relative_error(volume, exact), 4e-15) << volume << " against " << exact;
  EXPECT_NEAR(exact, 1 - 0.96 * 0.96 * 0.96, 1e-12);
  EXPECT_LT(relative_error(BI::surveyor_volume(shell), exact), 4e-15);
}

// ----------------------------------------------------------- other models

TEST(SurveyorVolume, WorksOnPolyhedron3AndWithAVertexPointMap)
{
  CGAL::Polyhedron_3<Epick> polyhedron;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(2, 0, 0), Point(0, 2, 0), Point(0, 0, 2), polyhedron);
  EXPECT_NEAR(BI::surveyor_volume(polyhedron), 8.0 / 6.0, 1e-15);

  // Scaled positions in a separate property map.
  Mesh mesh;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), mesh);
  auto scaled = mesh.add_property_map<Mesh::Vertex_index, Point>("v:scaled").first;
  for(auto v : vertices(mesh)) scaled[v] = Point(3 * mesh.point(v).x(), 3 * mesh.point(v).y(), 3 * mesh.point(v).z());
  EXPECT_NEAR(BI::surveyor_volume(mesh, CGAL::parameters::vertex_point_map(scaled)), 27.0 / 6.0, 1e-14);
  EXPECT_NEAR(BI::surveyor_volume(mesh, BI::parameters::signed_volume(false).vertex_point_map(scaled)),
              27.0 / 6.0, 1e-14);
}

// The mesh overload reads the points in place when its map returns
// references, and copies them when it returns values (temporaries that the
// sum must not keep pointers to): both give the same bits.  A map that
// returns values is also what the sanitizer build checks for dangling reads.
TEST(SurveyorVolume, PointsReadInPlaceOrCopiedGiveTheSameBits)
{
  Mesh torus = make_torus(Point(0, 0, 0), 1.0, 0.4, 97, 61); // 11834 triangles: not a multiple of the batch
  CGAL::Polygon_mesh_processing::transform(
      CGAL::Aff_transformation_3<Epick>(CGAL::TRANSLATION, Epick::Vector_3(1e3, -2e2, 0.5)), torus);
  const auto by_value = boost::make_function_property_map<Mesh::Vertex_index, Point>(
      [&torus](Mesh::Vertex_index v) { return torus.point(v); });
  const double in_place = BI::surveyor_volume(torus);
  EXPECT_EQ(in_place, BI::surveyor_volume(torus, CGAL::parameters::vertex_point_map(by_value)));
  EXPECT_LT(relative_error(in_place, exact_volume(torus)), 4e-15);
}

// An archetype of SurveyorVolumeTraits_3: exactly the documented members, so
// the function may not use anything else from the kernel.
struct Surveyor_volume_traits_archetype
{
  typedef double FT;
  typedef Epick::Point_3 Point_3;
  struct Compute_x_3 { FT operator()(const Point_3& p) const { return p.x(); } };
  struct Compute_y_3 { FT operator()(const Point_3& p) const { return p.y(); } };
  struct Compute_z_3 { FT operator()(const Point_3& p) const { return p.z(); } };
  struct Construct_point_3
  {
    Point_3 operator()(const FT& x, const FT& y, const FT& z) const { return Point_3(x, y, z); }
  };
  struct Compute_volume_3
  {
    FT operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) const
    {
      return CGAL::volume(p, q, r, s);
    }
  };
  Compute_x_3 compute_x_3_object() const { return {}; }
  Compute_y_3 compute_y_3_object() const { return {}; }
  Compute_z_3 compute_z_3_object() const { return {}; }
  Construct_point_3 construct_point_3_object() const { return {}; }
  Compute_volume_3 compute_volume_3_object() const { return {}; }
};

TEST(SurveyorVolume, ConceptArchetypeIsEnough)
{
  const Mesh torus = make_torus(Point(0, 0, 0), 1.0, 0.5, 30, 20);
  const double with_archetype =
      BI::surveyor_volume(torus, CGAL::parameters::geom_traits(Surveyor_volume_traits_archetype()));
  EXPECT_EQ(with_archetype, BI::surveyor_volume(torus));
}

// --------------------------------------------------------------- bad input

template <typename Error, typename F>
void expect_error(F f, const std::string& message_part)
{
  try
  {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning '" << message_part << "'";
  }
  catch(const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find(message_part), std::string::npos) << e.what();
  }
}

TEST(SurveyorVolumeErrors, EmptyMesh)
{
  Mesh empty;
  expect_error<BI::Empty_input_error>([&] { BI::surveyor_volume(empty); }, "no face");
  const std::vector<Point> points;
  const std::vector<Triangle> triangles;
  expect_error<BI::Empty_input_error>([&] { BI::surveyor_volume(points, triangles); }, "no face");
}

TEST(SurveyorVolumeErrors, NonTriangleFace)
{
  Mesh cube;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1),
                        Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), cube);
  expect_error<BI::Non_triangle_face_error>([&] { BI::surveyor_volume(cube); }, "not a triangle");
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<std::vector<int>> quad = {{0, 1, 2, 3}};
  expect_error<BI::Non_triangle_face_error>([&] { BI::surveyor_volume(points, quad); }, "has 4 vertices");
}

TEST(SurveyorVolumeErrors, OpenMesh)
{
  Mesh mesh = make_sphere(Point(0, 0, 0), 1.0, 2);
  CGAL::Euler::remove_face(halfedge(*faces(mesh).begin(), mesh), mesh);
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(mesh); }, "not closed");
  // Any error of the family is an Invalid_input_error.
  EXPECT_THROW(BI::surveyor_volume(mesh), BI::Invalid_input_error);

  // Soups: a missing face, and a face with the wrong orientation.
  std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<Triangle> open = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}};
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(points, open); }, "not closed");
  std::vector<Triangle> flipped = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}};
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(points, flipped); }, "inconsistently oriented");
}

// Closedness on a Surface_mesh is settled by the counts (three halfedges a
// face) when they allow it, else edge by edge: both ways must agree, with
// removed elements (garbage) or without.
TEST(SurveyorVolumeErrors, ClosednessByCountsHoldsWithAndWithoutGarbage)
{
  Mesh sphere = make_sphere(Point(0, 0, 0), 1.0, 2);
  // Collapsing an edge keeps the mesh closed and leaves removed elements.
  CGAL::Euler::collapse_edge(edge(halfedge(*faces(sphere).begin(), sphere), sphere), sphere);
  ASSERT_TRUE(sphere.has_garbage());
  const double with_garbage = BI::surveyor_volume(sphere);
  EXPECT_LT(relative_error(with_garbage, exact_volume(sphere)), 4e-15);
  Mesh collected = sphere;
  collected.collect_garbage();
  EXPECT_EQ(with_garbage, BI::surveyor_volume(collected));

  // Open, with and without garbage.
  CGAL::Euler::remove_face(halfedge(*faces(collected).begin(), collected), collected);
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(collected); }, "not closed");
  collected.collect_garbage();
  ASSERT_FALSE(collected.has_garbage());
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(collected); }, "not closed");

  // Polyhedron_3 is settled by its counts too.
  CGAL::Polyhedron_3<Epick> polyhedron;
  CGAL::copy_face_graph(make_sphere(Point(0, 0, 0), 1.0, 2), polyhedron);
  EXPECT_LT(relative_error(BI::surveyor_volume(polyhedron), with_garbage), 0.1);
  polyhedron.erase_facet(polyhedron.facets_begin()->halfedge());
  expect_error<BI::Open_mesh_error>([&] { BI::surveyor_volume(polyhedron); }, "not closed");
}

// The closedness check sorts most vertices' edges on a sorting network and
// only the rest on the general count: it must agree with a plain map of edge
// balances on every soup, closed or not, manifold or not, whatever the
// numbering, and name the same first unbalanced edge.
TEST(SurveyorVolumeErrors, ClosednessCheckAgreesWithAnEdgeCountOnMutatedSoups)
{
  typedef std::array<std::uint32_t, 3> Flat_triangle;
  auto soup_of = [](const Mesh& mesh, std::uint32_t offset, std::vector<Flat_triangle>& soup) {
    for(auto f : faces(mesh))
    {
      const auto h = halfedge(f, mesh);
      soup.push_back({std::uint32_t(source(h, mesh)) + offset, std::uint32_t(target(h, mesh)) + offset,
                      std::uint32_t(target(next(h, mesh), mesh)) + offset});
    }
  };
  // Bases: a sphere (buckets of up to ~12 entries); a cone whose apex and
  // base centre have 40 neighbours (general path); two boxes glued along an
  // edge by sharing its vertices (a balanced non-manifold edge).
  std::vector<std::pair<std::vector<Flat_triangle>, std::size_t>> bases(3);
  soup_of(make_sphere(Point(0, 0, 0), 1.0, 2), 0, bases[0].first);
  bases[0].second = num_vertices(make_sphere(Point(0, 0, 0), 1.0, 2));
  {
    auto& cone = bases[1].first;
    const std::uint32_t sides = 40, apex = sides, centre = sides + 1;
    for(std::uint32_t i = 0; i < sides; ++i)
    {
      cone.push_back({i, (i + 1) % sides, apex});
      cone.push_back({(i + 1) % sides, i, centre});
    }
    bases[1].second = sides + 2;
  }
  {
    const Mesh box = make_triangulated_box(Point(0, 0, 0), Point(1, 1, 1));
    soup_of(box, 0, bases[2].first);
    soup_of(box, 8, bases[2].first);
    // The second box's vertex 8 + v becomes v for two vertices of an edge of
    // the first (its reflection's orientation is irrelevant to the balance).
    const auto h = halfedge(*faces(box).begin(), box);
    const std::uint32_t a = std::uint32_t(source(h, box)), b = std::uint32_t(target(h, box));
    for(auto& t : bases[2].first)
      for(auto& v : t)
        if(v == a + 8 || v == b + 8)
          v -= 8;
    bases[2].second = 16;
  }
  std::mt19937 random(20261204);
  int closed = 0, open = 0;
  for(int trial = 0; trial < 600; ++trial)
  {
    const auto& base = bases[std::size_t(trial) % bases.size()];
    std::vector<Flat_triangle> soup = base.first;
    const std::size_t n = base.second;
    // Renumber the vertices (the buckets change), then mutate.
    std::vector<std::uint32_t> order(n);
    for(std::uint32_t v = 0; v < n; ++v)
      order[v] = v;
    std::shuffle(order.begin(), order.end(), random);
    for(auto& t : soup)
      for(auto& v : t)
        v = order[v];
    std::shuffle(soup.begin(), soup.end(), random);
    const std::size_t pick = std::size_t(random() % soup.size());
    switch(trial / int(bases.size()) % 5)
    {
    case 0: break;                                                          // unchanged
    case 1: soup.erase(soup.begin() + std::ptrdiff_t(pick)); break;         // a hole
    case 2: std::swap(soup[pick][0], soup[pick][1]); break;                 // one face flipped
    case 3: soup.push_back(soup[pick]); break;                              // a face twice
    case 4: soup.push_back({soup[pick][1], soup[pick][0], soup[pick][2]});  // a face and its
            soup.push_back(soup[pick]);                                     // reverse: balanced
            break;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> balance;
    for(const auto& t : soup)
      for(int i = 0; i < 3; ++i)
      {
        const std::uint32_t a = t[i], b = t[(i + 1) % 3];
        balance[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
      }
    std::string first_unbalanced;
    for(const auto& edge : balance)
      if(edge.second != 0)
      {
        first_unbalanced =
            "edge (" + std::to_string(edge.first.first) + ", " + std::to_string(edge.first.second) + ")";
        break;
      }
    try
    {
      BI::internal::check_soup_is_closed(soup, n);
      EXPECT_TRUE(first_unbalanced.empty()) << "trial " << trial << ": " << first_unbalanced << " not found";
      ++closed;
    }
    catch(const BI::Open_mesh_error& error)
    {
      EXPECT_NE(std::string(error.what()).find(first_unbalanced + " is used"), std::string::npos)
          << "trial " << trial << ": " << error.what() << " instead of " << first_unbalanced;
      ++open;
    }
  }
  EXPECT_EQ(closed, 240); // unchanged, and a face with its reverse: 2 of the 5 mutations
  EXPECT_EQ(open, 360);
}

TEST(SurveyorVolumeErrors, NanAndInfiniteCoordinates)
{
  for(const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mesh mesh = make_sphere(Point(0, 0, 0), 1.0, 1);
    mesh.point(*std::next(vertices(mesh).begin(), 5)) = Point(0.5, bad, 0.5);
    expect_error<BI::Non_finite_value_error>([&] { BI::surveyor_volume(mesh); }, "point #5");
  }
}

TEST(SurveyorVolumeErrors, BadSoupIndices)
{
  const std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::array<int, 3>> out_of_range = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 4}};
  expect_error<BI::Invalid_input_error>([&] { BI::surveyor_volume(points, out_of_range); }, "refers to point 4");
  const std::vector<std::array<int, 3>> negative = {{0, 2, -1}};
  expect_error<BI::Invalid_input_error>([&] { BI::surveyor_volume(points, negative); }, "refers to point -1");
  const std::vector<std::array<int, 3>> degenerate = {{0, 2, 2}};
  expect_error<BI::Invalid_input_error>([&] { BI::surveyor_volume(points, degenerate); }, "repeats a vertex");
}

TEST(SurveyorVolumeErrors, SelfIntersectingSurfaceOnlyWhenAskedToCheck)
{
  // Two overlapping cubes in one mesh: closed and outward, but the surface
  // crosses itself.  Its winding number is 2 in the overlap, so the signed
  // volume counts the overlap twice: 8 + 8.
  Mesh two = make_triangulated_box(Point(0, 0, 0), Point(2, 2, 2));
  const Mesh other = make_triangulated_box(Point(1, 1, 1), Point(3, 3, 3));
  CGAL::copy_face_graph(other, two);
  EXPECT_NEAR(BI::surveyor_volume(two), 16.0, 1e-14);
  EXPECT_NEAR(BI::surveyor_volume(two, BI::parameters::check_self_intersections(true, BI::parameters::signed_volume(true))), 16.0,
              1e-14);
  expect_error<BI::Self_intersecting_mesh_error>(
      [&] { BI::surveyor_volume(two, BI::parameters::check_self_intersections(true)); }, "intersects itself");
  // A simple mesh passes the check.
  EXPECT_NEAR(BI::surveyor_volume(make_triangulated_box(Point(0, 0, 0), Point(2, 2, 2)),
                                  BI::parameters::check_self_intersections(true)),
              8.0, 1e-14);
}

// ------------------------------------------------------- shared real meshes

std::string shared_data(const std::string& relative) { return std::string(BISO_SHARED_DATA_DIR) + "/" + relative; }

class SharedMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMesh, AgreesWithExactVolumeAndPmpVolume)
{
  const std::string path = shared_data(GetParam());
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, points, polygons)) << "cannot read " << path;
  ASSERT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(polygons)) << path;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

  const double exact = exact_volume(mesh);
  const double ours = BI::surveyor_volume(mesh, BI::parameters::signed_volume(true));
  const double ours_soup = BI::surveyor_volume(points, polygons, BI::parameters::signed_volume(true));
  const double pmp = PMP::volume(mesh);
  std::printf("%-45s faces %7zu  exact %.17g  rel.err ours %.2e  PMP::volume(Epick) %.2e\n", GetParam(),
              std::size_t(mesh.number_of_faces()), exact, relative_error(ours, exact), relative_error(pmp, exact));
  EXPECT_LT(relative_error(ours, exact), 1e-12);
  EXPECT_LT(relative_error(ours_soup, exact), 1e-12);
  // PMP::volume(Epick) agrees to the accuracy its origin-based sum allows.
  EXPECT_LT(relative_error(pmp, exact), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, SharedMesh,
    ::testing::Values("meshes/3holes.off", "meshes/armadillo.obj", "meshes/bumpy-cube.obj", "meshes/bunny.off",
                      "meshes/bunny_hoppe.off", "meshes/cube.obj", "meshes/elephant.obj", "meshes/elephant_cgal.off",
                      "meshes/fandisk.off", "meshes/fertility.off", "meshes/ico4_sphere.obj",
                      "meshes/mechpart_hoppe.off", "meshes/quadknot_tri.off", "meshes/rocker-arm.obj",
                      "meshes/torus.off", "meshes/tray_bottom.off", "meshes/xyz-cube-20mm.off",
                      "boolean_pairs/ballA.off", "boolean_pairs/ballB.off", "boolean_pairs/hull-body.obj",
                      "boolean_pairs/hull-mask.obj", "boolean_pairs/Generic_Twin_7081.1.t0_left.obj",
                      "boolean_pairs/Generic_Twin_7081.1.t0_right.obj"),
    [](const ::testing::TestParamInfo<const char*>& info) {
      std::string name = info.param;
      for(char& ch : name)
        if(!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

} // namespace
