// surveyor_volume (on a Surface_mesh, on a soup of kernel points, and on the
// flat arrays of IO::read_triangle_soup) against PMP::volume (Epick) and against a plain loop that
// sums signed tetrahedra over flat arrays (the memory-bandwidth limit), on a
// torus of 1.2 million triangles made in code and on the shared meshes.
//
//   benchmark_surveyor_volume [--data=DIR] [google-benchmark flags]
//
// Each benchmark also reports `rel_error`: its relative error against the
// exact (Epeck) volume of the same double coordinates.

#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "test_util.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace CGAL::Boolean_isosurfacing::test::kernels;

struct Input
{
  std::string name;
  Mesh mesh;
  std::vector<std::array<double, 3>> flat_points;
  std::vector<Point> soup_points;
  std::vector<std::array<std::uint32_t, 3>> flat_triangles;
  BI::Triangle_soup_3 soup;
  double exact = 0;
};

void prepare(Input& input)
{
  const Mesh& mesh = input.mesh;
  input.flat_points.reserve(mesh.number_of_vertices());
  for(auto v : vertices(mesh))
  {
    input.flat_points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    input.soup_points.push_back(mesh.point(v));
  }
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    input.flat_triangles.push_back({std::uint32_t(target(h, mesh)), std::uint32_t(target(next(h, mesh), mesh)),
                                    std::uint32_t(target(prev(h, mesh), mesh))});
  }
  input.soup.points = input.flat_points;
  input.soup.triangles = input.flat_triangles;
  input.exact = BI::test::exact_volume(mesh);
}

double relative_error(double value, double exact) { return std::abs(value - exact) / std::abs(exact); }

// The bandwidth limit: read each triangle's three indices and points once,
// one determinant against the origin, a plain sum.  No validation, no
// accuracy.
double plain_loop_volume(const Input& input)
{
  const auto& p = input.flat_points;
  double sum = 0;
  for(const auto& t : input.flat_triangles)
  {
    const auto& a = p[t[0]];
    const auto& b = p[t[1]];
    const auto& c = p[t[2]];
    sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return sum / 6;
}

template <typename F>
void run(benchmark::State& state, const Input& input, F volume)
{
  double v = 0;
  for(auto _ : state)
  {
    v = volume();
    benchmark::DoNotOptimize(v);
  }
  state.counters["triangles"] = double(input.flat_triangles.size());
  state.counters["rel_error"] = relative_error(v, input.exact);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(input.flat_triangles.size()));
}

void register_input(const std::shared_ptr<Input>& input)
{
  const std::string& n = input->name;
  benchmark::RegisterBenchmark(("surveyor_volume/mesh/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] { return BI::surveyor_volume(input->mesh); });
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("PMP_volume_Epick/mesh/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] { return PMP::volume(input->mesh); });
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("plain_loop/flat/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] { return plain_loop_volume(*input); });
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("surveyor_volume/flat/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] { return BI::surveyor_volume(input->soup); });
  })->Unit(benchmark::kMillisecond);
  // The two parts of surveyor_volume/flat: the closedness check (the soup's
  // own, linear-time edge check; a mesh has it from its connectivity) and
  // the certified sum with its centroid pass.
  benchmark::RegisterBenchmark(("closedness_check_only/flat/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] {
      BI::internal::check_soup_is_closed(input->soup.triangles, input->soup.points.size());
      return input->exact;
    });
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("certified_sum_only/flat/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] {
      const std::array<double, 3> c = BI::internal::finite_centroid(input->soup.points);
      return BI::internal::sum_of_signed_tetrahedra_of_arrays(input->soup.points, input->soup.triangles, c[0], c[1],
                                                             c[2]);
    });
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("surveyor_volume/soup/" + n).c_str(), [input](benchmark::State& s) {
    run(s, *input, [&] {
      return BI::surveyor_volume(input->soup_points, input->flat_triangles);
    });
  })->Unit(benchmark::kMillisecond);
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = BISO_SHARED_DATA_DIR;
  std::vector<char*> rest;
  for(int i = 0; i < argc; ++i)
  {
    if(std::strncmp(argv[i], "--data=", 7) == 0) data = argv[i] + 7;
    else rest.push_back(argv[i]);
  }
  int rest_count = int(rest.size());
  benchmark::Initialize(&rest_count, rest.data());

  {
    auto torus = std::make_shared<Input>();
    torus->name = "torus_1.2M";
    BI::make_torus(torus->mesh, Point(0, 0, 0), 1.0, 0.4, 1000, 600);
    prepare(*torus);
    register_input(torus);
    // The same torus moved far from the origin: where accuracy differs.
    auto far = std::make_shared<Input>();
    far->name = "torus_1.2M_at_1e5";
    far->mesh = torus->mesh;
    PMP::transform(Epick::Aff_transformation_3(CGAL::TRANSLATION, Epick::Vector_3(1e5, -1e5, 1e5)), far->mesh);
    prepare(*far);
    register_input(far);
  }
  for(const char* file : {"meshes/armadillo.obj", "meshes/bunny_hoppe.off", "meshes/fandisk.off",
                          "boolean_pairs/Generic_Twin_7081.1.t0_left.obj"})
  {
    auto input = std::make_shared<Input>();
    const std::string path = data + "/" + file;
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if(!CGAL::IO::read_polygon_soup(path, points, polygons) || !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    {
      std::cerr << "benchmark_surveyor_volume: cannot read " << path << " as a closed mesh\n";
      return 1;
    }
    PMP::polygon_soup_to_polygon_mesh(points, polygons, input->mesh);
    input->name = file;
    prepare(*input);
    register_input(input);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
