// Contouring point samples (issue 18) against the three surface
// reconstructions of CGAL 5.5, on the same points.  One binary; Google
// Benchmark flags apply (--benchmark_filter, --benchmark_format=csv|json).
//
// Methods (each timed as a whole, points in, Surface_mesh or soup out):
//  - contour: the contouring with the defaults (normals when the input has
//    them, else oriented by its spanning tree); contour_hoppe: the same with
//    consistent_signs(false), Hoppe's f alone (holes where it is undefined);
//  - poisson: CGAL::poisson_surface_reconstruction_delaunay with CGAL's
//    defaults (sm_angle 20, sm_radius 30, sm_distance 0.375 spacings); on
//    inputs without normals, CGAL's pca_estimate_normals (18 neighbours) and
//    mst_orient_normals first, timed with it;
//  - afront: CGAL::advancing_front_surface_reconstruction, defaults;
//  - scale_space: CGAL::Scale_space_surface_reconstruction_3, increase_scale(4)
//    (weighted PCA smoother) and the alpha-shape mesher at the smoother's
//    radius (CGAL's default) with separate shells and a forced manifold, the
//    facets on the input points.
//
// Inputs: CGAL's and Hoppe's shared point sets, and samples made here of
// shared meshes: 60K area-uniform samples with exact normals ("clean"),
// 60K samples with Gaussian noise of 0.5 spacing and no normals ("noisy"),
// and 8 merged orthographic range scans with noise 0.5 grid step, drop-out
// bands, no normals ("scans").
//
// Counters: closed (1/0), nm_vertices (non-manifold vertices), components,
// chi (Euler characteristic), borders (border cycles), triangles, and
// hausdorff_pct: the symmetric Hausdorff distance to the source mesh in
// percent of its bounding-box diagonal (sphere.pwn: to a level-6 icosphere
// of radius 1; the other files have no source: the largest distance from a
// sample to the output, a one-sided proxy, in percent of the samples'
// diagonal).  Times: the benchmark's own (CPU, one iteration).

#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Scale_space_surface_reconstruction_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>

#include <benchmark/benchmark.h>

#include "../../test/Boolean_isosurfacing_3/point_samples.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef std::pair<Point_3, Vector_3> Pwn;
typedef std::vector<std::array<std::size_t, 3>> Soup;

namespace {

struct Dataset
{
  std::string name;
  std::vector<Point_3> points;
  std::vector<Vector_3> normals; // empty: unoriented
  double spacing = 0;            // CGAL's average spacing, 6 neighbours
  std::unique_ptr<Mesh> source;  // null: no ground truth
};

std::map<std::string, std::unique_ptr<Dataset>>& datasets()
{
  static std::map<std::string, std::unique_ptr<Dataset>> all;
  return all;
}

const std::string data_dir = BISO_SHARED_DATA_DIR;

Dataset& new_dataset(const std::string& name)
{
  auto& slot = datasets()[name];
  slot = std::make_unique<Dataset>();
  slot->name = name;
  return *slot;
}

void finish(Dataset& d) { d.spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(d.points, 6); }

const Dataset* file_dataset(const std::string& file)
{
  Dataset& d = new_dataset(file);
  BI::IO::read_point_samples(data_dir + "/points/" + file, d.points, d.normals);
  if(file == "sphere.pwn")
  {
    d.source = std::make_unique<Mesh>();
    BI::make_icosphere(*d.source, Point_3(0, 0, 0), 1.0, 6);
  }
  finish(d);
  return &d;
}

// kind: "clean" (60K, normals), "noisy" (60K, sigma 0.5 spacing, no normals),
// "scans" (8 merged scans, 0.5 grid step noise, no normals).
const Dataset* mesh_dataset(const std::string& file, const std::string& kind)
{
  Dataset& d = new_dataset(file + "/" + kind);
  d.source = std::make_unique<Mesh>();
  CGAL::IO::read_polygon_mesh(data_dir + "/meshes/" + file, *d.source);
  biso_samples::Samples s;
  if(kind == "clean")
    s = biso_samples::sample_mesh(*d.source, 60000, 18);
  else if(kind == "noisy")
  {
    s = biso_samples::sample_mesh(*d.source, 60000, 18, 0.5);
    s.normals.clear();
  }
  else
    s = biso_samples::simulate_range_scans(*d.source, 8, 160, 0.5, 7);
  d.points = s.points;
  d.normals = s.normals;
  finish(d);
  return &d;
}

struct Result
{
  Soup triangles;
  std::vector<Point_3> points;
};

void report(benchmark::State& state, const Dataset& d, const Result& r, const std::string& method)
{
  const biso_samples::Measure m = biso_samples::measure(r.points, r.triangles, d.source.get());
  double error = m.hausdorff_percent;
  if(!d.source && !m.mesh.is_empty())
  {
    typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
    CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(faces(m.mesh).first, faces(m.mesh).second, m.mesh);
    tree.accelerate_distance_queries();
    double worst = 0;
    for(const Point_3& p : d.points)
      worst = (std::max)(worst, tree.squared_distance(p));
    const auto box = CGAL::bounding_box(d.points.begin(), d.points.end());
    error = 100 * std::sqrt(worst) / std::sqrt(CGAL::squared_distance(box.min(), box.max()));
  }
  state.counters["points"] = double(d.points.size());
  state.counters["triangles"] = double(m.faces);
  state.counters["closed"] = m.closed ? 1 : 0;
  state.counters["nm_vertices"] = double(m.non_manifold_vertices);
  state.counters["components"] = double(m.components);
  state.counters["chi"] = double(m.euler);
  state.counters["borders"] = double(m.border_cycles);
  state.counters["hausdorff_pct"] = error;
  if(const char* dump = std::getenv("BISO_DUMP_DIR"))
  {
    std::string name = method + "_" + d.name;
    for(char& c : name)
      if(c == '/' || c == ':')
        c = '_';
    CGAL::IO::write_polygon_mesh(std::string(dump) + "/" + name + ".off", m.mesh,
                                 CGAL::parameters::stream_precision(17));
  }
}

void BM_contour(benchmark::State& state, const Dataset* d, bool consistent)
{
  Result r;
  BI::Contouring_statistics statistics;
  for(auto _ : state)
  {
    std::vector<std::size_t> indices(d->points.size());
    for(std::size_t i = 0; i < indices.size(); ++i)
      indices[i] = i;
    auto run = [&](const auto& np) {
      const BI::Tangent_plane_signed_distance_3<K> field(indices, np);
      statistics = BI::contour_signed_distance(BI::contouring_lattice(field), field, r.points, r.triangles,
                                               BI::parameters::consistent_signs(consistent));
    };
    if(d->normals.empty())
      run(CGAL::parameters::point_map(CGAL::make_property_map(d->points)));
    else
      run(CGAL::parameters::point_map(CGAL::make_property_map(d->points))
            .normal_map(CGAL::make_property_map(d->normals)));
  }
  state.counters["membranes"] = double(statistics.removed_membranes);
  report(state, *d, r, consistent ? "contour" : "contour_hoppe");
}

// Normals for CGAL's Poisson on unoriented inputs: PCA (18 neighbours, as in
// CGAL's examples) oriented by CGAL's MST; the points whose normal could not
// be oriented are dropped, as the examples do.
std::vector<Pwn> oriented_points(const Dataset& d)
{
  std::vector<Pwn> pwn;
  for(std::size_t i = 0; i < d.points.size(); ++i)
    pwn.emplace_back(d.points[i], d.normals.empty() ? Vector_3(0, 0, 0) : d.normals[i]);
  if(d.normals.empty())
  {
    const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>())
                      .normal_map(CGAL::Second_of_pair_property_map<Pwn>());
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(pwn, 18, np);
    const auto unoriented = CGAL::mst_orient_normals(pwn, 18, np);
    pwn.erase(unoriented, pwn.end());
  }
  return pwn;
}

void BM_poisson(benchmark::State& state, const Dataset* d)
{
  Result r;
  for(auto _ : state)
  {
    const std::vector<Pwn> pwn = oriented_points(*d);
    Mesh mesh;
    bool ok = false;
    try
    {
      ok = CGAL::poisson_surface_reconstruction_delaunay(pwn.begin(), pwn.end(),
                                                         CGAL::First_of_pair_property_map<Pwn>(),
                                                         CGAL::Second_of_pair_property_map<Pwn>(), mesh, d->spacing);
    }
    catch(const std::exception& e) // cube.pwn's unoriented normals: a CGAL assertion in the surface mesher
    {
      state.SkipWithError((std::string("Poisson threw: ") + e.what()).substr(0, 120).c_str());
      return;
    }
    if(!ok)
    {
      state.SkipWithError("Poisson failed");
      return;
    }
    r.points.clear();
    r.triangles.clear();
    PMP::polygon_mesh_to_polygon_soup(mesh, r.points, r.triangles);
  }
  report(state, *d, r, "poisson");
}

void BM_afront(benchmark::State& state, const Dataset* d)
{
  Result r;
  for(auto _ : state)
  {
    r.triangles.clear();
    CGAL::advancing_front_surface_reconstruction(d->points.begin(), d->points.end(), std::back_inserter(r.triangles));
  }
  r.points = d->points;
  report(state, *d, r, "afront");
}

void BM_scale_space(benchmark::State& state, const Dataset* d)
{
  Result r;
  for(auto _ : state)
  {
    // As CGAL's default (4 iterations of the weighted PCA smoother, the
    // alpha-shape mesher at the smoother's radius), with separate shells and
    // a forced manifold: the default's double-layered soup has every edge in
    // 4 triangles.
    typedef CGAL::Scale_space_surface_reconstruction_3<K> Reconstruction;
    Reconstruction reconstruct(d->points.begin(), d->points.end());
    CGAL::Scale_space_reconstruction_3::Weighted_PCA_smoother<K> smoother;
    reconstruct.increase_scale(4, smoother);
    reconstruct.reconstruct_surface(
      CGAL::Scale_space_reconstruction_3::Alpha_shape_mesher<K>(smoother.squared_radius(), true, true));
    r.triangles.clear();
    for(auto it = reconstruct.facets_begin(); it != reconstruct.facets_end(); ++it)
      r.triangles.push_back({{std::size_t((*it)[0]), std::size_t((*it)[1]), std::size_t((*it)[2])}});
  }
  r.points = d->points;
  report(state, *d, r, "scale_space");
}

void register_all()
{
  std::vector<const Dataset*> inputs;
  for(const char* file : {"sphere.pwn", "elephant.pwn", "cube.pwn", "oni.xyz", "cactus.pts", "distcap.pts"})
    inputs.push_back(file_dataset(file));
  for(const char* mesh : {"bunny_hoppe.off", "fertility.off", "mechpart_hoppe.off", "elephant_cgal.off"})
    for(const char* kind : {"clean", "noisy", "scans"})
      inputs.push_back(mesh_dataset(mesh, kind));
  for(const Dataset* d : inputs)
  {
    benchmark::RegisterBenchmark(("contour/" + d->name).c_str(), BM_contour, d, true)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("contour_hoppe/" + d->name).c_str(), BM_contour, d, false)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("poisson/" + d->name).c_str(), BM_poisson, d)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("afront/" + d->name).c_str(), BM_afront, d)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("scale_space/" + d->name).c_str(), BM_scale_space, d)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
  }
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
