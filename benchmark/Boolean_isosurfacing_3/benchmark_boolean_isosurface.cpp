// TBISO timings on the seed's two set-ups (Taubin & Sibley report, on a
// 2 GHz Xeon: 128^3 grid = 12,290,298 tets, 4 fields, 6 terms -> 139K faces:
// tables 8 s, extraction 15 min; 108,045 tets, 6 fields, 15 terms: tables
// 29 ms, extraction 53 s).  Our fields (the seed does not give its own):
//  - "seed 128^3": 4 spheres of radius 0.62 centred on the vertices of a
//    regular tetrahedron inscribed in the sphere of radius 0.45, expression
//    "at least two of four" (the 6 pairwise intersections, 6 terms);
//  - "seed 108K": a 27^3 grid (105,456 tets), 6 spheres of radius 0.55 on
//    the +-axes at distance 0.4, "at least two of six" (15 terms).
// Field sampling is timed separately from extraction.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Tetrahedral_grid_3<K> Grid;
typedef std::function<double(const Point&)> Field;

namespace {

Field sphere(double cx, double cy, double cz, double r)
{
  return [=](const Point& p) {
    const double x = p.x() - cx, y = p.y() - cy, z = p.z() - cz;
    return std::sqrt(x * x + y * y + z * z) - r;
  };
}

std::string at_least_two_of(int n)
{
  std::string e;
  for(int i = 0; i < n; ++i)
    for(int j = i + 1; j < n; ++j)
      e += (e.empty() ? "" : " | ") + std::string("f") + std::to_string(i) + " & f" + std::to_string(j);
  return e;
}

struct Setup
{
  Grid grid;
  std::vector<Field> functions;
  BI::Boolean_expression expression;
};

Setup seed_128()
{
  const double a = 0.45 / std::sqrt(3.);
  return Setup{Grid::spanning(Point(-1, -1, -1), Point(1, 1, 1), {128, 128, 128}),
               {sphere(a, a, a, 0.62), sphere(a, -a, -a, 0.62), sphere(-a, a, -a, 0.62), sphere(-a, -a, a, 0.62)},
               BI::Boolean_expression::parse(at_least_two_of(4))};
}

Setup seed_108k()
{
  return Setup{Grid::spanning(Point(-1, -1, -1), Point(1, 1, 1), {27, 27, 27}),
               {sphere(0.4, 0, 0, 0.55), sphere(-0.4, 0, 0, 0.55), sphere(0, 0.4, 0, 0.55), sphere(0, -0.4, 0, 0.55),
                sphere(0, 0, 0.4, 0.55), sphere(0, 0, -0.4, 0.55)},
               BI::Boolean_expression::parse(at_least_two_of(6))};
}

template <typename Tag>
void extraction(benchmark::State& state, Setup (*make)())
{
  const Setup s = make();
  const BI::Scalar_fields fields = BI::sample_fields(s.grid, s.functions);
  BI::Boolean_isosurface_statistics stats;
  BI::Boolean_isosurface_soup<Point> soup;
  for(auto _ : state)
  {
    stats = BI::extract_boolean_isosurface<Tag>(s.grid, fields, s.expression, soup);
    benchmark::DoNotOptimize(soup.polygons.data());
  }
  std::size_t triangles = 0;
  for(const auto& p : soup.polygons)
    triangles += p.size() - 2;
  state.counters["tets"] = double(stats.number_of_tetrahedra);
  state.counters["evaluated_tets"] = double(stats.number_of_evaluated_tetrahedra);
  state.counters["polygons"] = double(soup.polygons.size());
  state.counters["triangles"] = double(triangles);
  state.counters["vertices"] = double(soup.points.size());
  state.counters["terms"] = double(s.expression.number_of_terms());
}

void extraction_sequential(benchmark::State& state, Setup (*make)()) { extraction<CGAL::Sequential_tag>(state, make); }
void extraction_parallel(benchmark::State& state, Setup (*make)()) { extraction<CGAL::Parallel_if_available_tag>(state, make); }

void sampling(benchmark::State& state, Setup (*make)())
{
  const Setup s = make();
  for(auto _ : state)
  {
    BI::Scalar_fields fields = BI::sample_fields(s.grid, s.functions);
    benchmark::DoNotOptimize(fields.data().data());
  }
}

void end_to_end(benchmark::State& state, Setup (*make)())
{
  const Setup s = make();
  BI::Boolean_isosurface_soup<Point> soup;
  for(auto _ : state)
  {
    const BI::Scalar_fields fields = BI::sample_fields(s.grid, s.functions);
    BI::extract_boolean_isosurface<CGAL::Parallel_if_available_tag>(s.grid, fields, s.expression, soup);
    const BI::Crease_network creases = BI::extract_crease_network(soup);
    benchmark::DoNotOptimize(creases.polylines.data());
  }
}

// The seed's "table construction": here, parsing the expression into its
// canonical form and preparing the per-term sign masks.
void tables(benchmark::State& state, int n)
{
  const std::string text = at_least_two_of(n);
  for(auto _ : state)
  {
    const BI::Boolean_expression e = BI::Boolean_expression::parse(text);
    const BI::internal::Tbiso_tetrahedron_evaluator evaluator(e, false);
    benchmark::DoNotOptimize(&evaluator);
  }
}

} // namespace

BENCHMARK_CAPTURE(tables, seed_4_fields_6_terms, 4)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tables, seed_6_fields_15_terms, 6)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(sampling, seed_128, seed_128)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(extraction_sequential, seed_128_sequential, seed_128)->Unit(benchmark::kMillisecond);
#ifdef CGAL_LINKED_WITH_TBB
BENCHMARK_CAPTURE(extraction_parallel, seed_128_parallel, seed_128)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK_CAPTURE(end_to_end, seed_128, seed_128)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(extraction_sequential, seed_108k_sequential, seed_108k)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(end_to_end, seed_108k, seed_108k)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
