// Tests of TBISO (extract_boolean_isosurface): marching tetrahedra as the
// one-field case, exact singular configurations, welding, orientation,
// regularization and volume convergence on analytic CSG shapes.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Tetrahedral_grid_3<K> Grid;
typedef BI::Boolean_isosurface_soup<Point> Soup;
typedef std::function<double(const Point&)> Field;

namespace {

const double pi = 3.14159265358979323846;

Grid unit_grid(std::size_t n, double lo = -1, double hi = 1)
{
  return Grid::spanning(Point(lo, lo, lo), Point(hi, hi, hi), {n, n, n});
}

Soup extract(const Grid& grid, const std::vector<Field>& f, const std::string& expression, bool close = true)
{
  Soup soup;
  BI::extract_boolean_isosurface(grid, BI::sample_fields(grid, f), BI::Boolean_expression::parse(expression), soup,
                                 BI::parameters::close_at_domain_boundary(close));
  return soup;
}

// Volume by the divergence theorem over fan-triangulated polygons.
double volume(const Soup& s)
{
  double v = 0;
  for(const auto& poly : s.polygons)
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
    {
      const Point& a = s.points[poly[0]];
      const Point& b = s.points[poly[k]];
      const Point& c = s.points[poly[k + 1]];
      v += CGAL::to_double(CGAL::determinant(a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN)) / 6;
    }
  return v;
}

// No polygon has two vertices at the same position, or zero area: its
// vertices are not all collinear (exact predicate on the doubles) and its
// area vector, computed in double, is not zero.
::testing::AssertionResult has_no_degenerate_polygon(const Soup& s)
{
  for(std::size_t p = 0; p < s.polygons.size(); ++p)
  {
    const auto& poly = s.polygons[p];
    std::set<Point> positions;
    for(std::size_t v : poly)
      positions.insert(s.points[v]);
    if(positions.size() != poly.size())
      return ::testing::AssertionFailure() << "polygon " << p << " has two vertices at " << s.points[poly[0]]
                                           << " (or nearby) at the same position";
    bool collinear = true;
    for(std::size_t k = 2; k < poly.size() && collinear; ++k)
      collinear = CGAL::collinear(s.points[poly[0]], s.points[poly[1]], s.points[poly[k]]);
    K::Vector_3 area(0, 0, 0);
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      area = area + CGAL::cross_product(s.points[poly[k]] - s.points[poly[0]], s.points[poly[k + 1]] - s.points[poly[0]]);
    if(collinear || area.squared_length() == 0)
      return ::testing::AssertionFailure() << "polygon " << p << " at " << s.points[poly[0]] << " has zero area";
  }
  return ::testing::AssertionSuccess();
}

// Every directed edge once and its reverse once: closed, consistently
// oriented, no edge with more than two faces.
::testing::AssertionResult is_closed_oriented_manifold(const Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(std::size_t p = 0; p < s.polygons.size(); ++p)
  {
    const auto& poly = s.polygons[p];
    if(poly.size() < 3)
      return ::testing::AssertionFailure() << "polygon " << p << " has " << poly.size() << " vertices";
    std::set<std::size_t> distinct(poly.begin(), poly.end());
    if(distinct.size() != poly.size())
      return ::testing::AssertionFailure() << "polygon " << p << " repeats a vertex";
    for(std::size_t k = 0; k < poly.size(); ++k)
      ++directed[{poly[k], poly[(k + 1) % poly.size()]}];
  }
  for(const auto& e : directed)
  {
    if(e.second != 1)
      return ::testing::AssertionFailure() << "directed edge (" << e.first.first << "," << e.first.second << ") used "
                                           << e.second << " times";
    auto r = directed.find({e.first.second, e.first.first});
    if(r == directed.end())
      return ::testing::AssertionFailure() << "edge (" << e.first.first << "," << e.first.second << ") at "
                                           << s.points[e.first.first] << " is on the border";
  }
  const ::testing::AssertionResult nondegenerate = has_no_degenerate_polygon(s);
  if(!nondegenerate)
    return nondegenerate;
  // Welded: no two points equal.
  std::vector<Point> p = s.points;
  std::sort(p.begin(), p.end());
  if(std::adjacent_find(p.begin(), p.end()) != p.end())
    return ::testing::AssertionFailure() << "two vertices at the same position " << *std::adjacent_find(p.begin(), p.end());
  return ::testing::AssertionSuccess();
}

// Independent marching tetrahedra, written from the textbook: a triangle or
// a quad per tetrahedron, vertices on edges at t = -f_a / (f_b - f_a) from
// the lower-index end, welded by edge, oriented with the normal towards f > 0
// flipped to point out of {f < 0}.
struct Marching_tetrahedra
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_vertex;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;

  std::size_t vertex(const Grid& g, const BI::Scalar_fields& f, std::size_t a, std::size_t b)
  {
    if(b < a)
      std::swap(a, b);
    auto it = edge_vertex.find({a, b});
    if(it != edge_vertex.end())
      return it->second;
    const double fa = f.value(a, 0), fb = f.value(b, 0), t = -fa / (fb - fa);
    const auto pa = g.position(a), pb = g.position(b);
    points.push_back(Point(pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]), pa[2] + t * (pb[2] - pa[2])));
    edge_vertex[{a, b}] = points.size() - 1;
    return points.size() - 1;
  }

  Marching_tetrahedra(const Grid& g, const BI::Scalar_fields& f)
  {
    const auto n = g.vertex_counts();
    for(std::size_t k = 0; k + 1 < n[2]; ++k)
      for(std::size_t j = 0; j + 1 < n[1]; ++j)
        for(std::size_t i = 0; i + 1 < n[0]; ++i)
          for(int t = 0; t < 6; ++t)
          {
            const auto tet = g.tetrahedron(i, j, k, t);
            std::vector<int> in, out;
            for(int c = 0; c < 4; ++c)
              (f.value(tet[c], 0) < 0 ? in : out).push_back(c);
            if(in.empty() || out.empty())
              continue;
            std::vector<std::size_t> poly;
            if(in.size() == 1 || out.size() == 1)
            {
              const bool single_in = in.size() == 1;
              const int s = single_in ? in[0] : out[0];
              for(int c : (single_in ? out : in))
                poly.push_back(vertex(g, f, tet[s], tet[c]));
            }
            else
            {
              poly = {vertex(g, f, tet[in[0]], tet[out[0]]), vertex(g, f, tet[in[0]], tet[out[1]]),
                      vertex(g, f, tet[in[1]], tet[out[1]]), vertex(g, f, tet[in[1]], tet[out[0]])};
            }
            // Orient: normal must point to the positive side.
            const Point& a = points[poly[0]];
            const Point& b = points[poly[1]];
            const Point& c = points[poly[2]];
            const K::Vector_3 normal = CGAL::cross_product(b - a, c - a);
            double centroid[3] = {0, 0, 0};
            for(std::size_t q : poly)
            {
              centroid[0] += CGAL::to_double(points[q].x()) / poly.size();
              centroid[1] += CGAL::to_double(points[q].y()) / poly.size();
              centroid[2] += CGAL::to_double(points[q].z()) / poly.size();
            }
            // The direction from the polygon to an outside corner.
            const auto po = g.position(tet[out[0]]);
            const K::Vector_3 to_out(po[0] - centroid[0], po[1] - centroid[1], po[2] - centroid[2]);
            if(normal * to_out < 0)
              std::reverse(poly.begin(), poly.end());
            polygons.push_back(poly);
          }
  }
};

// Polygons as cyclic sequences of positions, rotated to start at the smallest.
std::multiset<std::vector<Point>> polygon_positions(const std::vector<Point>& points,
                                                    const std::vector<std::vector<std::size_t>>& polygons)
{
  std::multiset<std::vector<Point>> result;
  for(const auto& poly : polygons)
  {
    std::vector<Point> p;
    for(std::size_t v : poly)
      p.push_back(points[v]);
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    result.insert(p);
  }
  return result;
}

Field sphere(double cx, double cy, double cz, double r)
{
  return [=](const Point& p) {
    const double x = p.x() - cx, y = p.y() - cy, z = p.z() - cz;
    return std::sqrt(x * x + y * y + z * z) - r;
  };
}
Field plane(double a, double b, double c, double d) // a x + b y + c z + d
{
  return [=](const Point& p) { return a * p.x() + b * p.y() + c * p.z() + d; };
}

} // namespace

TEST(BooleanIsosurface, OneFieldIsMarchingTetrahedra)
{
  for(std::size_t n : {5, 12, 21})
  {
    const Grid grid = unit_grid(n);
    const BI::Scalar_fields f = BI::sample_fields(grid, std::vector<Field>{sphere(0.1, -0.05, 0.02, 0.71)});
    Soup soup;
    BI::extract_boolean_isosurface(grid, f, BI::Boolean_expression::parse("f0"), soup);
    const Marching_tetrahedra mt(grid, f);
    ASSERT_EQ(soup.points.size(), mt.points.size()) << n;
    ASSERT_EQ(soup.polygons.size(), mt.polygons.size()) << n;
    std::vector<Point> a = soup.points, b = mt.points;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << "same vertices, bit for bit";
    EXPECT_EQ(polygon_positions(soup.points, soup.polygons), polygon_positions(mt.points, mt.polygons))
        << "same faces, same orientation";
    EXPECT_TRUE(is_closed_oriented_manifold(soup));
    for(int label : soup.face_fields)
      EXPECT_EQ(label, 0);
  }
}

TEST(BooleanIsosurface, ParallelEqualsSequential)
{
  const Grid grid = unit_grid(33);
  const std::vector<Field> f{sphere(0, 0, 0, 0.8), sphere(0.5, 0.1, 0, 0.5), plane(0, 0, 1, -0.3)};
  const BI::Scalar_fields values = BI::sample_fields(grid, f);
  const BI::Boolean_expression e = BI::Boolean_expression::parse("f0 & !f1 | f2 & f1");
  Soup sequential, parallel;
  BI::extract_boolean_isosurface<CGAL::Sequential_tag>(grid, values, e, sequential,
                                                       BI::parameters::close_at_domain_boundary(true));
#ifdef CGAL_LINKED_WITH_TBB
  BI::extract_boolean_isosurface<CGAL::Parallel_tag>(grid, values, e, parallel,
                                                     BI::parameters::close_at_domain_boundary(true));
#else
  GTEST_SKIP() << "TBB not available";
#endif
  EXPECT_EQ(sequential.points, parallel.points);
  EXPECT_EQ(sequential.polygons, parallel.polygons);
  EXPECT_EQ(sequential.face_fields, parallel.face_fields);
  EXPECT_TRUE(is_closed_oriented_manifold(sequential));
}

TEST(BooleanIsosurface, SlabSizeDoesNotChangeTheSurface)
{
  const Grid grid = unit_grid(20);
  const BI::Scalar_fields values =
      BI::sample_fields(grid, std::vector<Field>{sphere(0, 0, 0, 0.7), plane(1, 1.01, 0, 0.013)});
  const BI::Boolean_expression e = BI::Boolean_expression::parse("f0 & !f1");
  Soup one, many;
  BI::extract_boolean_isosurface(grid, values, e, one, BI::parameters::slab_layers(100));
  BI::extract_boolean_isosurface(grid, values, e, many, BI::parameters::slab_layers(1));
  EXPECT_EQ(one.points.size(), many.points.size());
  EXPECT_EQ(polygon_positions(one.points, one.polygons), polygon_positions(many.points, many.polygons));
  EXPECT_TRUE(is_closed_oriented_manifold(many));
}

// Linear fields are reproduced exactly by piecewise-linear interpolation, so
// boxes cut by planes have exact volumes, even when the planes pass through
// grid vertices, edges and faces.
TEST(BooleanIsosurface, PlanesThroughGridVerticesGiveExactVolumes)
{
  const Grid grid = unit_grid(9); // vertices at multiples of 0.25
  // f0 = x - 0.25, zero on a whole layer of grid faces.
  const Soup half = extract(grid, {plane(1, 0, 0, -0.25)}, "f0");
  EXPECT_TRUE(is_closed_oriented_manifold(half));
  EXPECT_NEAR(volume(half), 1.25 * 4, 1e-12);
  // Three planes through the grid vertex (0.25, -0.5, 0): a box corner.
  const Soup box = extract(grid, {plane(1, 0, 0, -0.25), plane(0, 1, 0, 0.5), plane(0, 0, 1, 0)}, "f0 & f1 & f2");
  EXPECT_TRUE(is_closed_oriented_manifold(box));
  EXPECT_NEAR(volume(box), 1.25 * 0.5 * 1, 1e-12);
  // Creases: the 12 box edges, the 3 between two faces on different planes
  // of the domain boundary included.  Corners: the 8 box corners, where 3
  // labels or boundary planes meet.
  const BI::Crease_network creases = BI::extract_crease_network(box);
  EXPECT_EQ(creases.corners.size(), 8u);
  EXPECT_EQ(creases.polylines.size(), 12u);
  bool found_triple_corner = false;
  for(std::size_t c : creases.corners)
    found_triple_corner |= box.points[c] == Point(0.25, -0.5, 0);
  EXPECT_TRUE(found_triple_corner);
  // Tilted planes through a vertex, cutting edges and faces at their zeros.
  const Soup wedge = extract(grid, {plane(1, 1, 0, 0), plane(1, -1, 0, 0)}, "f0 & f1");
  EXPECT_TRUE(is_closed_oriented_manifold(wedge));
  EXPECT_NEAR(volume(wedge), 2 * 1 * 2 / 2.0, 1e-12); // x < -|y| in [-1,1]^3: triangle area 1, height 2
}

TEST(BooleanIsosurface, TwoFieldsCrossingAnEdgeAtTheSamePoint)
{
  const Grid grid = unit_grid(9);
  // Both zero sets contain the line x = 0.125, y = 0.25 (y = 0.25 is a grid
  // layer, so they cross the x-edges of that layer at the same points).
  // Dyadic coefficients: the sampled values are exact.
  const std::vector<Field> f{plane(1, 0, 0, -0.125), plane(1, 0.75, 0, -0.3125)};
  for(const char* e : {"f0 & f1", "f0 | f1", "f0 & !f1", "!f0 & f1"})
  {
    const Soup s = extract(grid, f, e);
    EXPECT_TRUE(is_closed_oriented_manifold(s)) << e;
    // Exact volumes from the planes' geometry: f1 = x + 0.75 (y - 0.25) - 0.125.
    // Region f0 < 0: x < 0.125;  f1 < 0: x < 0.125 - 0.75 (y - 0.25).
    // Integrate over y in [-1, 1], z-extent 2: width of each region in x.
    auto width = [](double xmax) { return std::min(1., std::max(-1., xmax)) + 1; };
    double expected = 0;
    const int steps = 200000;
    for(int s = 0; s < steps; ++s)
    {
      const double y = -1 + (s + 0.5) * 2.0 / steps;
      const double a = 0.125, b = 0.125 - 0.75 * (y - 0.25);
      double w = 0;
      if(std::string(e) == "f0 & f1") w = width(std::min(a, b));
      if(std::string(e) == "f0 | f1") w = width(std::max(a, b));
      if(std::string(e) == "f0 & !f1") w = std::max(0., width(a) - width(b));
      if(std::string(e) == "!f0 & f1") w = std::max(0., width(b) - width(a));
      expected += w * 2 * (2.0 / steps);
    }
    EXPECT_NEAR(volume(s), expected, 1e-6) << e;
    // The common zeros on the layer y = 0.25 are single vertices on which both fields vanish.
    std::size_t on_line = 0;
    for(const Point& p : s.points)
      on_line += (p.x() == 0.125 && p.y() == 0.25);
    // The line meets the 9 x-edges of the layer and the 8 diagonals of the
    // layer's squares between them; each crossing is one welded vertex.
    EXPECT_EQ(on_line, 17u) << e;
  }
}

TEST(BooleanIsosurface, IdenticalProportionalAndOppositeFields)
{
  const Grid grid = unit_grid(11);
  const Field s = sphere(0.05, 0, 0, 0.6);
  const Field twice = [&](const Point& p) { return 2 * s(p); }; // exactly proportional
  const Field opposite = [&](const Point& p) { return -s(p); };
  const Soup reference = extract(grid, {s}, "f0");
  ASSERT_GT(reference.polygons.size(), 0u);
  // f0 & !f1 with f1 = f0: empty.  f0 | f1: f0.
  EXPECT_EQ(extract(grid, {s, s}, "f0 & !f1").polygons.size(), 0u);
  EXPECT_EQ(extract(grid, {s, s}, "!f0 & f1").polygons.size(), 0u);
  for(const char* e : {"f0 | f1", "f0 & f1"})
  {
    const Soup same = extract(grid, {s, s}, e);
    EXPECT_EQ(polygon_positions(same.points, same.polygons),
              polygon_positions(reference.points, reference.polygons)) << e;
    const Soup scaled = extract(grid, {s, twice}, e);
    EXPECT_EQ(scaled.polygons.size(), reference.polygons.size()) << e;
    EXPECT_NEAR(volume(scaled), volume(reference), 1e-12) << e;
    for(int label : same.face_fields)
      EXPECT_EQ(label, 0) << "the lowest field labels a shared face";
  }
  // f1 = -f0: f0 & f1 is empty, f0 | f1 is everything but a zero-volume set:
  // the whole box when closed, with no sheet inside.
  EXPECT_EQ(extract(grid, {s, opposite}, "f0 & f1").polygons.size(), 0u);
  const Soup all = extract(grid, {s, opposite}, "f0 | f1");
  EXPECT_TRUE(is_closed_oriented_manifold(all));
  EXPECT_NEAR(volume(all), 8, 1e-12);
  for(int label : all.face_fields)
    EXPECT_EQ(label, Soup::domain_boundary);
  // f0 & !f1 with f1 = -f0 is f0 (f0 < 0 implies -f0 > 0).
  EXPECT_NEAR(volume(extract(grid, {s, opposite}, "f0 & !f1")), volume(reference), 1e-12);
}

TEST(BooleanIsosurface, FieldIdenticallyZeroOnTetrahedra)
{
  const Grid grid = unit_grid(9);
  // f0 = max(0, x - 0.25): zero on every tetrahedron with x <= 0.25.
  const Field ramp = [](const Point& p) { return std::max(0., p.x() - 0.25); };
  // !f0 (f0 > 0) is x > 0.25; f0 (f0 < 0) is empty.
  const Soup right = extract(grid, {ramp}, "!f0");
  EXPECT_TRUE(is_closed_oriented_manifold(right));
  EXPECT_NEAR(volume(right), 0.75 * 4, 1e-12);
  EXPECT_EQ(extract(grid, {ramp}, "f0").polygons.size(), 0u);
  // With a second field: the zero region is neither inside nor outside f0.
  const Soup cut = extract(grid, {ramp, plane(0, 1, 0, 0)}, "!f0 & f1");
  EXPECT_TRUE(is_closed_oriented_manifold(cut));
  EXPECT_NEAR(volume(cut), 0.75 * 1 * 2, 1e-12);
  // A face of the output lies on grid faces (x = 0.25) where f0 vanishes
  // identically; it is labelled by f0.
  bool has_f0_face = false;
  for(std::size_t p = 0; p < cut.polygons.size(); ++p)
    has_f0_face |= cut.face_fields[p] == 0;
  EXPECT_TRUE(has_f0_face);
}

TEST(BooleanIsosurface, OpenWithoutClosingClosedWithClosing)
{
  const Grid grid = unit_grid(10);
  const Soup open = extract(grid, {plane(0.3, 1, 0.2, 0.1234)}, "f0", false);
  EXPECT_FALSE(is_closed_oriented_manifold(open)); // a plane across the box has a border
  const Soup closed = extract(grid, {plane(0.3, 1, 0.2, 0.1234)}, "f0", true);
  EXPECT_TRUE(is_closed_oriented_manifold(closed));
  // Exact: the plane y = -(0.3 x + 0.2 z + 0.1) inside [-1,1]^3 (it stays inside).
  EXPECT_NEAR(volume(closed), 4 * (1 - 0.1234), 1e-12);
}

// CSG of analytic shapes: volume converges to the exact value.
TEST(BooleanIsosurface, VolumeConvergesOnAnalyticCsg)
{
  // Two spheres of radius r with centres d apart: lens volume.
  const double r = 0.6, d = 0.5;
  const double sphere_volume = 4 * pi * r * r * r / 3;
  const double lens = pi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12;
  struct Case
  {
    const char* expression;
    double exact;
  };
  const Case cases[] = {{"f0 & f1", lens}, {"f0 | f1", 2 * sphere_volume - lens}, {"f0 & !f1", sphere_volume - lens}};
  const std::vector<Field> f{sphere(-d / 2, 0.013, 0.007, r), sphere(d / 2, 0.013, 0.007, r)};
  for(const Case& c : cases)
  {
    double previous = 1e9;
    for(std::size_t n : {17, 33, 65})
    {
      const Soup s = extract(unit_grid(n), f, c.expression);
      ASSERT_TRUE(is_closed_oriented_manifold(s)) << c.expression << " n=" << n;
      const double error = std::abs(volume(s) - c.exact) / c.exact;
      EXPECT_LT(error, previous * 0.6) << c.expression << " n=" << n;
      previous = error;
    }
    EXPECT_LT(previous, 5e-3) << c.expression;
  }
}

TEST(BooleanIsosurface, BadInput)
{
  const Grid grid = unit_grid(5);
  BI::Scalar_fields f = BI::sample_fields(grid, std::vector<Field>{plane(1, 0, 0, 0)});
  Soup s;
  EXPECT_THROW(BI::extract_boolean_isosurface(grid, f, BI::Boolean_expression::parse("f0 & f1"), s),
               BI::Invalid_input_error);
  f.value(3, 0) = std::nan("");
  EXPECT_THROW(BI::extract_boolean_isosurface(grid, f, BI::Boolean_expression::parse("f0"), s),
               BI::Non_finite_value_error);
  const BI::Scalar_fields small(7, 1);
  EXPECT_THROW(BI::extract_boolean_isosurface(grid, small, BI::Boolean_expression::parse("f0"), s),
               BI::Invalid_input_error);
}

TEST(BooleanIsosurface, SphereThroughGridVertices)
{
  // Radius 0.5 on a grid of spacing 0.25: the field is exactly zero at the
  // six grid vertices (+-0.5, 0, 0), (0, +-0.5, 0), (0, 0, +-0.5).
  const Grid grid = unit_grid(9);
  const Soup s = extract(grid, {sphere(0, 0, 0, 0.5)}, "f0", false);
  EXPECT_TRUE(is_closed_oriented_manifold(s));
  std::size_t on_vertex = 0;
  for(const Point& p : s.points)
    on_vertex += (p == Point(0.5, 0, 0) || p == Point(-0.5, 0, 0) || p == Point(0, 0.5, 0) || p == Point(0, -0.5, 0) ||
                  p == Point(0, 0, 0.5) || p == Point(0, 0, -0.5));
  EXPECT_EQ(on_vertex, 6u) << "each grid vertex on the sphere is one output vertex";
  EXPECT_NEAR(volume(s), 4 * pi * 0.125 / 3, 0.25 * 4 * pi * 0.125 / 3);
}

TEST(BooleanIsosurface, ThreePlanesThroughAPointInsideATetrahedron)
{
  // (a, b, c) is at fractions (1/4, 1/2, 3/4) of a grid cube: strictly inside
  // one tetrahedron, so the corner comes from a 4x4 determinant.
  const double a = 0.3125, b = -0.125, c = 0.1875;
  const Grid grid = unit_grid(9);
  const Soup box = extract(grid, {plane(1, 0, 0, -a), plane(0, 1, 0, -b), plane(0, 0, 1, -c)}, "f0 & f1 & f2");
  EXPECT_TRUE(is_closed_oriented_manifold(box));
  EXPECT_NEAR(volume(box), (a + 1) * (b + 1) * (c + 1), 1e-12);
  // The 8 box corners: 1 where the three planes meet, 3 where two planes meet
  // the domain boundary, 3 where one does, and the domain box's own corner.
  const BI::Crease_network creases = BI::extract_crease_network(box);
  EXPECT_EQ(creases.corners.size(), 8u);
  EXPECT_EQ(creases.polylines.size(), 12u);
  double nearest = 1e9;
  for(std::size_t v : creases.corners)
    nearest = std::min(nearest, std::sqrt(CGAL::to_double(CGAL::squared_distance(box.points[v], Point(a, b, c)))));
  EXPECT_LT(nearest, 1e-15);
  // Tilted planes through the same point: the complement of their union.
  const Soup tilted = extract(grid, {plane(1, 0.5, 0.25, -(a + 0.5 * b + 0.25 * c)),
                                     plane(-0.25, 1, 0.5, -(-0.25 * a + b + 0.5 * c)),
                                     plane(0.5, -0.25, 1, -(0.5 * a - 0.25 * b + c))},
                              "!f0 & !f1 | !f2", false);
  EXPECT_GT(tilted.polygons.size(), 0u);
  const BI::Crease_network t = BI::extract_crease_network(tilted);
  bool corner_at_point = false;
  for(std::size_t v : t.corners)
    corner_at_point |= std::sqrt(CGAL::to_double(CGAL::squared_distance(tilted.points[v], Point(a, b, c)))) < 1e-14;
  EXPECT_TRUE(corner_at_point);
}

// Crease polylines and corners converge to the analytic curves as O(h^2).
TEST(BooleanIsosurface, CreasesAndCornersConvergeQuadratically)
{
  const double r = 0.6, d = 0.35, e = 0.5;
  // Spheres at (+-d, 0, 0) and (0, e, 0): pairwise circles, two triple points.
  const double y = (e * e - d * d) / (2 * e), z = std::sqrt(r * r - d * d - y * y);
  const std::vector<Field> f{sphere(d, 0, 0, r), sphere(-d, 0, 0, r), sphere(0, e, 0, r)};
  double previous_curve = 1e9, previous_corner = 1e9;
  for(std::size_t n : {17, 33, 65})
  {
    const Soup s = extract(unit_grid(n), f, "f0 & f1 & f2", false);
    ASSERT_TRUE(is_closed_oriented_manifold(s));
    const BI::Crease_network net = BI::extract_crease_network(s);
    ASSERT_EQ(net.corners.size(), 2u) << n;
    EXPECT_EQ(net.polylines.size(), 3u) << n << ": one arc per pair of spheres, between the two corners";
    // Distance of crease vertices to the analytic circle f_i = f_j = 0 of
    // the two fields labelling the faces around them.
    double worst = 0;
    for(const auto& line : net.polylines)
      for(std::size_t v : line)
      {
        const Point& p = s.points[v];
        // The crease lies on two of the spheres: distance to the nearest pair's circle.
        double best = 1e9;
        for(int i = 0; i < 3; ++i)
          for(int j = i + 1; j < 3; ++j)
            best = std::min(best, std::max(std::abs(f[i](p)), std::abs(f[j](p))));
        worst = std::max(worst, best);
      }
    double corner_error = 0;
    for(std::size_t c : net.corners)
    {
      const Point& p = s.points[c];
      corner_error = std::max(corner_error, std::min(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point(0, y, z)))),
                                                     std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point(0, y, -z))))));
    }
    const double h = 2.0 / double(n - 1);
    std::cout << "n = " << n << ": crease distance " << worst << " (" << worst / (h * h) << " h^2), corner error "
              << corner_error << " (" << corner_error / (h * h) << " h^2)\n";
    EXPECT_LT(worst, 1.0 * h * h);
    EXPECT_LT(corner_error, 2.0 * h * h);
    EXPECT_LT(worst, previous_curve / 2.5) << "quadratic convergence: about 4x per halving";
    previous_curve = worst;
    previous_corner = corner_error;
  }
  (void)previous_corner;
}

TEST(BooleanIsosurface, UnstructuredMeshDriverMatchesGrid)
{
  // The grid's tetrahedra as an unstructured mesh, listed in reverse order
  // and with some tetrahedra reversed: the surface is the same.
  const Grid grid = unit_grid(11);
  std::vector<Point> points;
  for(std::size_t v = 0; v < grid.number_of_vertices(); ++v)
    points.push_back(grid.point(v));
  std::vector<std::array<std::size_t, 4>> tets;
  const auto n = grid.vertex_counts();
  for(std::size_t k = 0; k + 1 < n[2]; ++k)
    for(std::size_t j = 0; j + 1 < n[1]; ++j)
      for(std::size_t i = 0; i + 1 < n[0]; ++i)
        for(int t = 0; t < 6; ++t)
        {
          auto tet = grid.tetrahedron(i, j, k, t);
          if(tets.size() % 3 == 0)
            std::swap(tet[0], tet[1]);
          tets.push_back(tet);
        }
  std::reverse(tets.begin(), tets.end());
  const BI::Tetrahedral_mesh_3<K> mesh(points, tets);
  EXPECT_EQ(mesh.number_of_boundary_faces(), 6u * 2 * 10 * 10);
  EXPECT_GT(mesh.number_of_reoriented_tetrahedra(), 0u);
  const std::vector<Field> f{sphere(0.1, 0, 0, 0.7), plane(0, 0, 1, -0.125), sphere(-0.3, 0.2, 0.1, 0.4)};
  const BI::Boolean_expression e = BI::Boolean_expression::parse("(f0 | !f2) & f1");
  for(bool close : {false, true})
  {
    Soup from_grid, from_mesh;
    BI::extract_boolean_isosurface(grid, BI::sample_fields(grid, f), e, from_grid,
                                   BI::parameters::close_at_domain_boundary(close));
    BI::extract_boolean_isosurface(mesh, BI::sample_fields(mesh, f), e, from_mesh,
                                   BI::parameters::close_at_domain_boundary(close));
    EXPECT_EQ(from_grid.points.size(), from_mesh.points.size());
    // Coordinates come from the canonical key, so even the doubles agree.
    EXPECT_EQ(polygon_positions(from_grid.points, from_grid.polygons),
              polygon_positions(from_mesh.points, from_mesh.polygons));
    if(close)
      EXPECT_TRUE(is_closed_oriented_manifold(from_mesh));
  }
}

TEST(BooleanIsosurface, NonConformingTetrahedralMeshIsRejected)
{
  const std::vector<Point> p{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0, 0, -1),
                             Point(1, 1, 1)};
  // Three tetrahedra on the face (0, 1, 2).
  EXPECT_THROW(BI::Tetrahedral_mesh_3<K>(p, {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Tetrahedral_mesh_3<K>(p, {{0, 1, 2, 2}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Tetrahedral_mesh_3<K>(p, {{0, 1, 2, 9}}), BI::Invalid_input_error);
  EXPECT_THROW(BI::Tetrahedral_mesh_3<K>(p, {}), BI::Empty_input_error);
}

// Seven fields: a cube as six half-spaces, minus a ball inside it.  The cube
// is exact (linear fields), the ball converges; the crease network is the
// cube's 12 edges between its 8 corners, whatever the resolution.
TEST(BooleanIsosurface, SevenFieldsCubeMinusBall)
{
  const double a = 0.45, r = 0.3;
  const std::vector<Field> f{plane(-1, 0, 0, -a), plane(1, 0, 0, -a), plane(0, -1, 0, -a), plane(0, 1, 0, -a),
                             plane(0, 0, -1, -a), plane(0, 0, 1, -a), sphere(0.02, -0.01, 0.015, r)};
  const double exact = 8 * a * a * a - 4 * pi * r * r * r / 3;
  double previous = 1e9;
  for(std::size_t n : {17, 33, 65})
  {
    const Soup s = extract(unit_grid(n), f, "f0 & f1 & f2 & f3 & f4 & f5 & !f6", false);
    ASSERT_TRUE(is_closed_oriented_manifold(s)) << n;
    const double error = std::abs(volume(s) - exact) / exact;
    EXPECT_LT(error, previous / 3) << n;
    previous = error;
    const BI::Crease_network net = BI::extract_crease_network(s);
    EXPECT_EQ(net.corners.size(), 8u) << n;
    EXPECT_EQ(net.polylines.size(), 12u) << n;
    for(std::size_t c : net.corners)
    {
      const Point& p = s.points[c];
      EXPECT_NEAR(std::abs(p.x()), a, 1e-15);
      EXPECT_NEAR(std::abs(p.y()), a, 1e-15);
      EXPECT_NEAR(std::abs(p.z()), a, 1e-15);
    }
    for(std::size_t p = 0; p < s.polygons.size(); ++p)
      EXPECT_TRUE(s.face_fields[p] >= 0 && s.face_fields[p] <= 6);
  }
  EXPECT_LT(previous, 2e-3);
}

// The tbiso demo: four spheres centred on the vertices of a regular
// tetrahedron, "inside at least two".  The spheres are mirrored onto each
// other by coordinate swaps, and |p - c|^2 summed in another order makes
// their sampled values differ by a few ulps where they should be equal; the
// exact arrangement then has cells of size 1e-16, whose polygons are
// degenerate once rounded to double (48 with two vertices at one position, 6
// more collinear ones on this set-up before the cleanup of weld_chunk()).
TEST(BooleanIsosurface, DemoHasNoDegeneratePolygons)
{
  const double a = 0.45 / std::sqrt(3.0), r = 0.62;
  const Grid grid = unit_grid(128);
  const BI::Scalar_fields fields = BI::sample_fields(
      grid, std::vector<Field>{sphere(a, a, a, r), sphere(a, -a, -a, r), sphere(-a, a, -a, r), sphere(-a, -a, a, r)});
  const BI::Boolean_expression e = BI::Boolean_expression::parse("f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3");
  for(bool close : {false, true})
  {
    // The polygons as the exact evaluation emits them, before welding.
    BI::internal::Tbiso_chunk raw;
    BI::internal::extract_grid_slab(grid, fields.data().data(), 0, 4, BI::internal::Tbiso_tetrahedron_evaluator(e, close),
                                    0, 127, raw);
    std::size_t raw_degenerate = 0;
    double raw_volume = 0;
    for(std::size_t p = 0; p + 1 < raw.polygon_begin.size(); ++p)
    {
      std::set<std::array<double, 3>> positions;
      const std::array<double, 3>& o = raw.points[raw.polygon_vertices[raw.polygon_begin[p]]];
      for(std::size_t k = raw.polygon_begin[p]; k < raw.polygon_begin[p + 1]; ++k)
      {
        positions.insert(raw.points[raw.polygon_vertices[k]]);
        if(k + 2 < raw.polygon_begin[p + 1])
        {
          const std::array<double, 3>& b = raw.points[raw.polygon_vertices[k + 1]];
          const std::array<double, 3>& c = raw.points[raw.polygon_vertices[k + 2]];
          raw_volume += CGAL::to_double(CGAL::determinant(K::Vector_3(o[0], o[1], o[2]), K::Vector_3(b[0], b[1], b[2]),
                                                          K::Vector_3(c[0], c[1], c[2]))) / 6;
        }
      }
      raw_degenerate += positions.size() < raw.polygon_begin[p + 1] - raw.polygon_begin[p];
    }
    EXPECT_GT(raw_degenerate, 10u) << "the set-up no longer has rounding degeneracies: the test tests nothing";

    Soup s;
    BI::extract_boolean_isosurface(grid, fields, e, s, BI::parameters::close_at_domain_boundary(close));
    EXPECT_TRUE(is_closed_oriented_manifold(s)) << close; // includes has_no_degenerate_polygon()
    EXPECT_GT(s.polygons.size(), 149000u);
    EXPECT_LT(s.polygons.size(), raw.labels.size());
    // No point moved: the volume is that of the raw polygons.
    EXPECT_NEAR(volume(s), raw_volume, 1e-13);
    EXPECT_NEAR(volume(s), 0.7512277, 1e-6);
  }
}

// With closing, the domain boundary's own edges and corners are creases and
// corners: the whole grid box (a sphere containing it) has 8 corners and 12
// crease polylines, on the grid and on the same tetrahedra as a mesh.
TEST(BooleanIsosurface, ClosingFacesOfDifferentBoundaryPlanesMeetAtCreases)
{
  const Grid grid = Grid::spanning(Point(-1, -0.5, 0), Point(1, 0.5, 0.75), {9, 6, 5});
  const Soup box = extract(grid, {sphere(0, 0, 0, 10)}, "f0");
  ASSERT_TRUE(is_closed_oriented_manifold(box));
  EXPECT_NEAR(volume(box), 2 * 1 * 0.75, 1e-12);
  ASSERT_EQ(box.face_boundary_planes.size(), box.polygons.size());
  std::set<int> planes(box.face_boundary_planes.begin(), box.face_boundary_planes.end());
  EXPECT_EQ(planes, (std::set<int>{0, 1, 2, 3, 4, 5}));
  for(std::size_t p = 0; p < box.polygons.size(); ++p)
  {
    // Every vertex of a closing face is on its box face.
    const int axis = box.face_boundary_planes[p] / 2;
    const double at = box.face_boundary_planes[p] % 2 ? grid.point(grid.number_of_vertices() - 1)[axis]
                                                       : grid.point(0)[axis];
    for(std::size_t v : box.polygons[p])
      EXPECT_EQ(box.points[v][axis], at);
  }
  const BI::Crease_network creases = BI::extract_crease_network(box);
  EXPECT_EQ(creases.corners.size(), 8u);
  EXPECT_EQ(creases.polylines.size(), 12u);
  EXPECT_EQ(creases.number_of_crease_edges, 4u * (8 + 5 + 4));
  for(std::size_t c : creases.corners)
  {
    const Point& p = box.points[c];
    EXPECT_TRUE((p.x() == -1 || p.x() == 1) && (p.y() == -0.5 || p.y() == 0.5) && (p.z() == 0 || p.z() == 0.75)) << p;
  }
  // Without the planes (a soup read from a file) the box is one label.
  Soup plain = box;
  plain.face_boundary_planes.clear();
  EXPECT_EQ(BI::extract_crease_network(plain).number_of_crease_edges, 0u);

  // The same tetrahedra as an unstructured mesh: its boundary faces grouped
  // into coplanar sets give the same six planes.
  std::vector<Point> points;
  for(std::size_t v = 0; v < grid.number_of_vertices(); ++v)
    points.push_back(grid.point(v));
  std::vector<std::array<std::size_t, 4>> tets;
  const auto n = grid.vertex_counts();
  for(std::size_t k = 0; k + 1 < n[2]; ++k)
    for(std::size_t j = 0; j + 1 < n[1]; ++j)
      for(std::size_t i = 0; i + 1 < n[0]; ++i)
        for(int t = 0; t < 6; ++t)
          tets.push_back(grid.tetrahedron(i, j, k, t));
  const BI::Tetrahedral_mesh_3<K> mesh(points, tets);
  Soup from_mesh;
  BI::extract_boolean_isosurface(mesh, BI::sample_fields(mesh, std::vector<Field>{sphere(0, 0, 0, 10)}),
                                 BI::Boolean_expression::parse("f0"), from_mesh,
                                 BI::parameters::close_at_domain_boundary(true));
  ASSERT_TRUE(is_closed_oriented_manifold(from_mesh));
  std::set<int> mesh_planes(from_mesh.face_boundary_planes.begin(), from_mesh.face_boundary_planes.end());
  EXPECT_EQ(mesh_planes.size(), 6u);
  const BI::Crease_network mesh_creases = BI::extract_crease_network(from_mesh);
  EXPECT_EQ(mesh_creases.corners.size(), 8u);
  EXPECT_EQ(mesh_creases.polylines.size(), 12u);
}

// A face on the domain boundary on which a field vanishes identically is that
// field's face when the field bounds the set there, and a closing face
// otherwise.
TEST(BooleanIsosurface, BoundaryFacesOnAZeroSetTakeTheFieldsLabel)
{
  const Grid grid = unit_grid(5);
  const Field left = plane(1, 0, 0, 1); // x + 1: zero on the box face x = -1, positive inside
  const Field everything = sphere(0, 0, 0, 10);
  // !f0 is x > -1: bounded by f0 on x = -1, closed by the domain elsewhere.
  const Soup bounded = extract(grid, {left}, "!f0");
  ASSERT_TRUE(is_closed_oriented_manifold(bounded));
  EXPECT_NEAR(volume(bounded), 8, 1e-12);
  std::size_t on_left = 0;
  for(std::size_t p = 0; p < bounded.polygons.size(); ++p)
  {
    bool at_left = true;
    for(std::size_t v : bounded.polygons[p])
      at_left &= bounded.points[v].x() == -1;
    EXPECT_EQ(bounded.face_fields[p], at_left ? 0 : Soup::domain_boundary);
    on_left += at_left;
  }
  EXPECT_EQ(on_left, 2u * 4 * 4);
  // !f0 | f1 with f1 < 0 everywhere does not depend on f0: all closing faces.
  const Soup unbounded = extract(grid, {left, everything}, "!f0 | f1");
  ASSERT_TRUE(is_closed_oriented_manifold(unbounded));
  for(int label : unbounded.face_fields)
    EXPECT_EQ(label, Soup::domain_boundary);
  // Either way the box keeps its 8 corners and 12 edges.
  EXPECT_EQ(BI::extract_crease_network(bounded).corners.size(), 8u);
  EXPECT_EQ(BI::extract_crease_network(unbounded).corners.size(), 8u);
}
