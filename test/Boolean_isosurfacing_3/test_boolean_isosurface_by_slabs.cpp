// Out-of-core TBISO by slabs: identical to the in-core extraction (same
// vertices, same polygons, same order) for any slab size and both
// concurrency tags, with fields read from a raw file and the surface
// streamed to a PLY file.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_by_slabs.h>
#include <CGAL/Boolean_isosurfacing_3/IO/Boolean_isosurface_PLY_stream.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Tetrahedral_grid_3<K> Grid;
typedef BI::Boolean_isosurface_soup<Point> Soup;
typedef std::function<double(const Point&)> Field;

namespace {

Field sphere(double cx, double cy, double cz, double r) { return BI::test::sphere_field<Point>(cx, cy, cz, r); }

struct Slab_case
{
  Grid grid = Grid::spanning(Point(-1, -1, -1), Point(1, 1, 1), {23, 19, 29});
  std::vector<Field> f{sphere(0.2, 0, 0, 0.6), sphere(-0.2, 0.1, 0, 0.5), [](const Point& p) { return p.z() - 0.25; }};
  BI::Boolean_expression e = BI::Boolean_expression::parse("f0 & !f1 | f1 & f2");
  BI::Scalar_fields fields = BI::sample_fields(grid, f);
};

} // namespace

TEST(BooleanIsosurfaceBySlabs, SameAsInCoreForEverySlabSize)
{
  const Slab_case s;
  for(bool close : {false, true})
    for(std::size_t slab : {1, 2, 3, 7, 100})
    {
      Soup in_core, by_slabs_sequential, by_slabs_parallel;
      BI::extract_boolean_isosurface(s.grid, s.fields, s.e, in_core,
                                     BI::parameters::slab_layers(slab, BI::parameters::close_at_domain_boundary(close)));
      BI::Scalar_fields_source source(s.fields);
      BI::Boolean_isosurface_soup_sink<Point> sink(by_slabs_sequential);
      const auto stats = BI::extract_boolean_isosurface_by_slabs(
          s.grid, source, s.e, sink, BI::parameters::slab_layers(slab, BI::parameters::close_at_domain_boundary(close)));
      EXPECT_EQ(in_core.points, by_slabs_sequential.points) << slab;
      EXPECT_EQ(in_core.polygons, by_slabs_sequential.polygons) << slab;
      EXPECT_EQ(in_core.face_fields, by_slabs_sequential.face_fields) << slab;
      EXPECT_EQ(stats.number_of_slabs, (28 + slab - 1) / slab);
      // Peak memory: one slab of values (plus two ghost layers) at a time when sequential.
      EXPECT_LE(stats.peak_field_values, (std::min<std::size_t>(slab, 28) + 3) * 23 * 19 * 3);
#ifdef CGAL_LINKED_WITH_TBB
      BI::Boolean_isosurface_soup_sink<Point> parallel_sink(by_slabs_parallel);
      BI::extract_boolean_isosurface_by_slabs<CGAL::Parallel_tag>(
          s.grid, source, s.e, parallel_sink,
          BI::parameters::slab_layers(slab, BI::parameters::close_at_domain_boundary(close)), 3);
      EXPECT_EQ(in_core.points, by_slabs_parallel.points) << slab;
      EXPECT_EQ(in_core.polygons, by_slabs_parallel.polygons) << slab;
#endif
    }
}

TEST(BooleanIsosurfaceBySlabs, RawFileInPlyFileOut)
{
  const Slab_case s;
  const std::string fields_file = ::testing::TempDir() + "slabs_fields.f32";
  const std::string ply_file = ::testing::TempDir() + "slabs_out.ply";
  BI::IO::write_raw_scalar_fields(fields_file, s.fields, BI::IO::Raw_scalar_type::FLOAT32);
  BI::IO::Raw_scalar_field_reader reader(fields_file, s.grid.number_of_vertices(), 3,
                                         BI::IO::Raw_scalar_type::FLOAT32);
  {
    BI::IO::Boolean_isosurface_PLY_stream ply(ply_file);
    BI::extract_boolean_isosurface_by_slabs<CGAL::Parallel_if_available_tag>(
        s.grid, reader, s.e, ply, BI::parameters::slab_layers(4, BI::parameters::close_at_domain_boundary(true)));
    ply.close();
  }
  // The reference: in-core on the same (float-rounded) values.
  const BI::Scalar_fields rounded = BI::IO::read_raw_scalar_fields(fields_file, s.grid.number_of_vertices(), 3,
                                                                   BI::IO::Raw_scalar_type::FLOAT32);
  Soup in_core, from_file;
  BI::extract_boolean_isosurface(s.grid, rounded, s.e, in_core,
                                 BI::parameters::slab_layers(4, BI::parameters::close_at_domain_boundary(true)));
  BI::IO::read_PLY_with_fields(ply_file, from_file);
  EXPECT_EQ(in_core.points, from_file.points);
  EXPECT_EQ(in_core.polygons, from_file.polygons);
  EXPECT_EQ(in_core.face_fields, from_file.face_fields);
  EXPECT_GT(from_file.polygons.size(), 100u);
  std::remove(fields_file.c_str());
  std::remove(ply_file.c_str());
}

TEST(BooleanIsosurfaceBySlabs, NonFiniteValueIsReportedWithItsVertex)
{
  Slab_case s;
  s.fields.value(5000, 1) = std::nan("");
  BI::Scalar_fields_source source(s.fields);
  Soup out;
  BI::Boolean_isosurface_soup_sink<Point> sink(out);
  try
  {
    BI::extract_boolean_isosurface_by_slabs(s.grid, source, s.e, sink, BI::parameters::slab_layers(2));
    FAIL() << "no exception";
  }
  catch(const BI::Non_finite_value_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("vertex 5000"), std::string::npos) << e.what();
  }
}

// Four spheres mirrored onto each other by coordinate swaps (the tbiso demo
// on a 24^3 grid): the sampled values of two spheres differ by a few ulps
// where they should be equal, so the exact arrangement has cells of size
// 1e-16 whose polygons degenerate when rounded.  Removing those (see
// weld_chunk()) keeps the slab stream identical to the in-core extraction.
TEST(BooleanIsosurfaceBySlabs, SameAsInCoreWithRoundingDegeneracies)
{
  const double a = 0.45 / std::sqrt(3.0), r = 0.62;
  const Grid grid = Grid::spanning(Point(-1, -1, -1), Point(1, 1, 1), {24, 24, 24});
  const BI::Scalar_fields fields = BI::sample_fields(
      grid, std::vector<Field>{sphere(a, a, a, r), sphere(a, -a, -a, r), sphere(-a, a, -a, r), sphere(-a, -a, a, r)});
  const BI::Boolean_expression e = BI::Boolean_expression::parse("f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3");
  for(std::size_t slab : {1, 2, 5, 100})
  {
    Soup in_core, by_slabs;
    BI::extract_boolean_isosurface(grid, fields, e, in_core, BI::parameters::slab_layers(slab));
    BI::Scalar_fields_source source(fields);
    BI::Boolean_isosurface_soup_sink<Point> sink(by_slabs);
    BI::extract_boolean_isosurface_by_slabs(grid, source, e, sink, BI::parameters::slab_layers(slab));
    EXPECT_EQ(in_core.points, by_slabs.points) << slab;
    EXPECT_EQ(in_core.polygons, by_slabs.polygons) << slab;
    EXPECT_EQ(in_core.face_fields, by_slabs.face_fields) << slab;
    std::size_t degenerate = 0;
    for(const auto& poly : by_slabs.polygons)
    {
      std::vector<Point> p;
      for(std::size_t v : poly)
        p.push_back(by_slabs.points[v]);
      std::sort(p.begin(), p.end());
      degenerate += std::adjacent_find(p.begin(), p.end()) != p.end();
    }
    EXPECT_EQ(degenerate, 0u) << slab;
  }
}
