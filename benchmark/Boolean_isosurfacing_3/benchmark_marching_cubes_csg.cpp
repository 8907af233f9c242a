// Marching Cubes CSG against the alternatives, on bunny_hoppe.off (70K
// triangles) and a copy moved by 0.3 of its bounding box along x:
//  - ours, sequential and parallel (CGAL::Parallel_tag, 2 cores);
//  - PMP::corefine_and_compute_union (Epick), exact topology, no lattice;
//  - OpenVDB: meshToLevelSet -> csgUnion -> volumeToMesh at the same voxel size;
//  - Nef_polyhedron_3 (Epeck), once (it is slow);
// and lattice classification against CGAL::Side_of_triangle_mesh queried
// point by point on the same lattice.
//
//   benchmark_marching_cubes_csg [--data=DIR] [--cells=N] [google-benchmark flags]
//
// --cells (default 160) is the lattice resolution along the longest side; the
// setup prints the union's volume error at that resolution against the
// corefinement result.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#ifdef BISO_WITH_OPENVDB
#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>
#endif

#include "test_util.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace CGAL::Boolean_isosurfacing::test::kernels;

struct Setup
{
  std::vector<Mesh> meshes; // A and B
  BI::Regular_lattice_3 lattice{{0, 0, 0}, 1.0, {1, 1, 1}};
  double reference_union_volume = 0;
};
Setup setup;

template <typename Tag>
void BM_ours_union(benchmark::State& state)
{
  std::size_t triangles = 0;
  double volume = 0;
  for(auto _ : state)
  {
    Mesh out;
    BI::marching_cubes_csg<Tag>(setup.lattice, setup.meshes, BI::Boolean_expression::union_of(2), out);
    triangles = out.number_of_faces();
    state.PauseTiming();
    volume = BI::surveyor_volume(out);
    state.ResumeTiming();
  }
  state.counters["out_triangles"] = double(triangles);
  state.counters["vol_rel_error"] = std::abs(volume - setup.reference_union_volume) / setup.reference_union_volume;
}

void BM_corefine_union_epick(benchmark::State& state)
{
  for(auto _ : state)
  {
    Mesh a = setup.meshes[0], b = setup.meshes[1], out;
    PMP::corefine_and_compute_union(a, b, out);
    benchmark::DoNotOptimize(out.number_of_faces());
  }
}

void BM_nef_union_epeck(benchmark::State& state)
{
  for(auto _ : state)
  {
    Exact_mesh a, b;
    CGAL::copy_face_graph(setup.meshes[0], a);
    CGAL::copy_face_graph(setup.meshes[1], b);
    CGAL::Nef_polyhedron_3<Epeck> na(a), nb(b);
    na += nb;
    benchmark::DoNotOptimize(na.number_of_volumes());
  }
}

#ifdef BISO_WITH_OPENVDB
void BM_openvdb_union(benchmark::State& state)
{
  openvdb::initialize();
  const double voxel = setup.lattice.spacing();
  auto transform = openvdb::math::Transform::createLinearTransform(voxel);
  std::vector<std::vector<openvdb::Vec3s>> points(2);
  std::vector<std::vector<openvdb::Vec3I>> triangles(2);
  for(int m = 0; m < 2; ++m)
  {
    const Mesh& mesh = setup.meshes[m];
    for(auto v : vertices(mesh))
      points[m].emplace_back(float(mesh.point(v).x()), float(mesh.point(v).y()), float(mesh.point(v).z()));
    for(auto f : faces(mesh))
    {
      auto h = halfedge(f, mesh);
      triangles[m].emplace_back(std::uint32_t(target(h, mesh)), std::uint32_t(target(next(h, mesh), mesh)),
                                std::uint32_t(target(prev(h, mesh), mesh)));
    }
  }
  std::size_t out_polygons = 0;
  for(auto _ : state)
  {
    auto a = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points[0], triangles[0], 3.0f);
    auto b = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points[1], triangles[1], 3.0f);
    openvdb::tools::csgUnion(*a, *b);
    std::vector<openvdb::Vec3s> out_points;
    std::vector<openvdb::Vec3I> out_triangles;
    std::vector<openvdb::Vec4I> out_quads;
    openvdb::tools::volumeToMesh(*a, out_points, out_triangles, out_quads, 0.0);
    out_polygons = out_triangles.size() + out_quads.size();
  }
  state.counters["out_polygons"] = double(out_polygons);
}
#endif

// Classification alone: ours against Side_of_triangle_mesh point by point,
// per lattice point of the same lattice.  Ours is Lattice_classifier_3 on the
// one mesh: "x pass" is the classification proper (every point's
// inside/outside, queryable by mask()); "all axes" adds the crossings of the
// y and z lines that Marching Cubes needs for its vertices.
void BM_ours_classification_per_point(benchmark::State& state)
{
  const std::vector<Mesh> one = {setup.meshes[0]};
  const BI::Regular_lattice_3 lattice =
      BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(setup.meshes[0]), std::size_t(state.range(0)));
  double x_pass = 0, all_axes = 0;
  for(auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    const BI::Lattice_classifier_3 classifier = BI::Lattice_classifier_3::classify(one, lattice);
    all_axes += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    x_pass += classifier.seconds(0);
    benchmark::DoNotOptimize(classifier.number_of_crossings());
  }
  const double points = double(state.iterations()) * double(lattice.total_number_of_points());
  state.counters["ns_per_point_x_pass"] = 1e9 * x_pass / points;
  state.counters["ns_per_point_all_axes"] = 1e9 * all_axes / points;
  state.counters["points"] = double(lattice.total_number_of_points());
}

void BM_side_of_triangle_mesh_per_point(benchmark::State& state)
{
  const Mesh& mesh = setup.meshes[0];
  const BI::Regular_lattice_3 lattice =
      BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(mesh), std::size_t(state.range(0)));
  const CGAL::Side_of_triangle_mesh<Mesh, Epick> inside(mesh);
  const auto& n = lattice.number_of_points();
  std::size_t count = 0;
  for(auto _ : state)
  {
    for(std::size_t k = 0; k < n[2]; ++k)
      for(std::size_t j = 0; j < n[1]; ++j)
        for(std::size_t i = 0; i < n[0]; ++i)
          count += inside(Point(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k))) ==
                   CGAL::ON_BOUNDED_SIDE;
  }
  benchmark::DoNotOptimize(count);
  // items_per_second = lattice points per second: ns per point = 1e9 / it.
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(lattice.total_number_of_points()));
  state.counters["points"] = double(lattice.total_number_of_points());
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = BISO_SHARED_DATA_DIR;
  std::size_t cells = 160;
  std::vector<char*> rest;
  for(int i = 0; i < argc; ++i)
  {
    if(std::strncmp(argv[i], "--data=", 7) == 0) data = argv[i] + 7;
    else if(std::strncmp(argv[i], "--cells=", 8) == 0) cells = std::size_t(std::atol(argv[i] + 8));
    else rest.push_back(argv[i]);
  }
  int rest_count = int(rest.size());
  benchmark::Initialize(&rest_count, rest.data());

  setup.meshes.resize(2);
  try
  {
    BI::IO::read_closed_triangle_mesh(data + "/meshes/bunny_hoppe.off", setup.meshes[0]);
  }
  catch(const std::exception& e)
  {
    std::cerr << "benchmark_marching_cubes_csg: " << data << "/meshes/bunny_hoppe.off: " << e.what() << "\n";
    return 1;
  }
  const CGAL::Bbox_3 box = PMP::bbox(setup.meshes[0]);
  setup.meshes[1] = setup.meshes[0];
  PMP::transform(Epick::Aff_transformation_3(CGAL::TRANSLATION, Epick::Vector_3(0.3 * (box.xmax() - box.xmin()), 0, 0)),
                 setup.meshes[1]);
  setup.lattice = BI::Regular_lattice_3::enclosing_with_cells(box + PMP::bbox(setup.meshes[1]), cells);
  {
    Mesh a = setup.meshes[0], b = setup.meshes[1], out;
    PMP::corefine_and_compute_union(a, b, out);
    setup.reference_union_volume = PMP::volume(out);
  }
  const auto& n = setup.lattice.number_of_points();
  std::cout << "bunny_hoppe union with a copy moved by 0.3 bbox along x; lattice " << n[0] << " x " << n[1] << " x "
            << n[2] << ", spacing " << setup.lattice.spacing() << "; reference volume (corefinement) "
            << setup.reference_union_volume << "\n";

  benchmark::RegisterBenchmark("ours_union/sequential", BM_ours_union<CGAL::Sequential_tag>)->Unit(benchmark::kMillisecond);
#ifdef CGAL_LINKED_WITH_TBB
  benchmark::RegisterBenchmark("ours_union/parallel", BM_ours_union<CGAL::Parallel_tag>)->Unit(benchmark::kMillisecond);
#endif
  benchmark::RegisterBenchmark("PMP_corefine_union_Epick", BM_corefine_union_epick)->Unit(benchmark::kMillisecond);
#ifdef BISO_WITH_OPENVDB
  benchmark::RegisterBenchmark("OpenVDB_union_same_voxel", BM_openvdb_union)->Unit(benchmark::kMillisecond);
#endif
  benchmark::RegisterBenchmark("Nef_polyhedron_3_union_Epeck", BM_nef_union_epeck)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
  benchmark::RegisterBenchmark("classification/ours", BM_ours_classification_per_point)
      ->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("classification/Side_of_triangle_mesh", BM_side_of_triangle_mesh_per_point)
      ->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(1);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
