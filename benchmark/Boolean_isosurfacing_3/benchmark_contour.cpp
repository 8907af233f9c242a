// Contouring oriented point samples (Hoppe's tangent-plane signed distance +
// Marching Cubes) against CGAL's Poisson surface reconstruction on the same
// oriented points.  One binary; Google Benchmark flags apply
// (--benchmark_filter, --benchmark_format=csv|json).
//
// Counters per run:
//   triangles; err_max / err_mean: distance error in units of the input's mean
//   spacing s (s = CGAL::compute_average_spacing, 6 neighbours), measured
//     - sphere.pwn: against the analytic unit sphere, | |v| - 1 | over the
//       output vertices (both methods give closed surfaces without missing
//       parts, so this is the Hausdorff distance up to the triangles' sag);
//     - torus_*: the symmetric Hausdorff distance to the generating mesh
//       (PMP::bounded_error_symmetric_Hausdorff_distance, error 1e-2 s);
//     - elephant.pwn (no ground truth): the distance from the input samples to
//       the output (max and mean; a one-sided proxy);
//   t_knn, t_pca, t_orient, t_field, t_contour: seconds per stage (contour only).

#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/poisson_surface_reconstruction.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
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

namespace {

struct Dataset
{
  std::string name;
  std::vector<Point_3> points;
  std::vector<Vector_3> normals;
  double spacing = 0;
  std::unique_ptr<Mesh> truth; // torus: the generating mesh
  bool unit_sphere = false;
};

std::map<std::string, std::unique_ptr<Dataset>>& datasets()
{
  static std::map<std::string, std::unique_ptr<Dataset>> all;
  return all;
}

void finish(Dataset& d)
{
  d.spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(d.points, 6);
}

const Dataset& file_dataset(const std::string& name)
{
  auto& slot = datasets()[name];
  if(!slot)
  {
    slot = std::make_unique<Dataset>();
    slot->name = name;
    BI::IO::read_point_samples(std::string(BISO_SHARED_DATA_DIR) + "/points/" + name, slot->points, slot->normals);
    slot->unit_sphere = (name == "sphere.pwn");
    finish(*slot);
  }
  return *slot;
}

// Area-uniform samples of a fine torus mesh (R = 1, r = 0.4) with face normals.
const Dataset& torus_dataset(std::size_t n)
{
  const std::string name = "torus_" + std::to_string(n);
  auto& slot = datasets()[name];
  if(!slot)
  {
    slot = std::make_unique<Dataset>();
    slot->name = name;
    slot->truth = std::make_unique<Mesh>();
    BI::make_torus(*slot->truth, Point_3(0, 0, 0), 1.0, 0.4, 600, 240);
    std::vector<std::array<Point_3, 3>> faces;
    std::vector<double> cumulative;
    double total = 0;
    const Mesh& m = *slot->truth;
    for(auto f : m.faces())
    {
      auto h = m.halfedge(f);
      std::array<Point_3, 3> t{{m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))}};
      total += std::sqrt(CGAL::squared_area(t[0], t[1], t[2]));
      faces.push_back(t);
      cumulative.push_back(total);
    }
    CGAL::Random random(42);
    for(std::size_t i = 0; i < n; ++i)
    {
      const double u = random.get_double(0, total);
      const std::size_t f = std::min(faces.size() - 1, std::size_t(std::upper_bound(cumulative.begin(),
                                                                                       cumulative.end(), u) -
                                                                      cumulative.begin()));
      double a = random.get_double(), b = random.get_double();
      if(a + b > 1)
      {
        a = 1 - a;
        b = 1 - b;
      }
      const auto& t = faces[f];
      slot->points.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
      Vector_3 normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      slot->normals.push_back(normal / std::sqrt(normal.squared_length()));
    }
    finish(*slot);
  }
  return *slot;
}

// Error of `mesh` for dataset `d`, in units of its spacing: {max, mean}.
std::pair<double, double> error(const Dataset& d, const Mesh& mesh)
{
  if(mesh.number_of_faces() == 0)
    return {std::nan(""), std::nan("")};
  if(d.unit_sphere)
  {
    double worst = 0, sum = 0;
    for(auto v : mesh.vertices())
    {
      const double e = std::abs(std::sqrt(mesh.point(v).x() * mesh.point(v).x() + mesh.point(v).y() * mesh.point(v).y() +
                                          mesh.point(v).z() * mesh.point(v).z()) -
                                1.0);
      worst = std::max(worst, e);
      sum += e;
    }
    return {worst / d.spacing, sum / double(mesh.number_of_vertices()) / d.spacing};
  }
  if(d.truth)
  {
    const double h =
      PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(mesh, *d.truth, 1e-2 * d.spacing);
    return {h / d.spacing, std::nan("")};
  }
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  double worst = 0, sum = 0;
  for(const Point_3& p : d.points)
  {
    const double e = std::sqrt(tree.squared_distance(p));
    worst = std::max(worst, e);
    sum += e;
  }
  return {worst / d.spacing, sum / double(d.points.size()) / d.spacing};
}

Mesh run_contour(const Dataset& d, double cells, BI::Contouring_statistics* report,
                 BI::Tangent_plane_signed_distance_3<K>::Timings* timings)
{
  std::vector<std::size_t> indices(d.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  const BI::Tangent_plane_signed_distance_3<K> field(
    indices, CGAL::parameters::point_map(CGAL::make_property_map(d.points)).normal_map(CGAL::make_property_map(d.normals)));
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const BI::Regular_lattice_3 lattice = cells > 0
      ? BI::contouring_lattice(field, BI::parameters::cells_along_longest_side(cells))
      : BI::contouring_lattice(field);
  *report = BI::contour_signed_distance(lattice, field, points, triangles);
  *timings = field.timings();
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

void BM_contour(benchmark::State& state, const Dataset* d, double cells)
{
  Mesh mesh;
  BI::Contouring_statistics report;
  BI::Tangent_plane_signed_distance_3<K>::Timings timings;
  for(auto _ : state)
    mesh = run_contour(*d, cells, &report, &timings);
  const auto e = error(*d, mesh);
  state.counters["points"] = double(d->points.size());
  state.counters["triangles"] = double(mesh.number_of_faces());
  state.counters["cell_over_s"] = report.cell_size / d->spacing;
  state.counters["err_max"] = e.first;
  state.counters["err_mean"] = e.second;
  state.counters["t_knn"] = timings.neighbors;
  state.counters["t_pca"] = timings.planes;
  state.counters["t_orient"] = timings.orientation;
  state.counters["t_field"] = report.seconds_field;
  state.counters["t_contour"] = report.seconds_contouring;
  state.counters["closed"] = CGAL::is_closed(mesh) ? 1 : 0;
}

// sm_radius and sm_distance in units of the spacing: CGAL's defaults (30,
// 0.375) give a coarse mesh; (2, 0.1) gives about as many triangles as the
// contour at its default resolution.
void BM_poisson(benchmark::State& state, const Dataset* d, double sm_radius, double sm_distance)
{
  std::vector<Pwn> pwn;
  for(std::size_t i = 0; i < d->points.size(); ++i)
    pwn.emplace_back(d->points[i], d->normals[i]);
  Mesh mesh;
  for(auto _ : state)
  {
    mesh.clear();
    const bool ok = CGAL::poisson_surface_reconstruction_delaunay(
      pwn.begin(), pwn.end(), CGAL::First_of_pair_property_map<Pwn>(), CGAL::Second_of_pair_property_map<Pwn>(),
      mesh, d->spacing, 20.0, sm_radius, sm_distance);
    if(!ok)
      state.SkipWithError("Poisson failed");
  }
  const auto e = error(*d, mesh);
  state.counters["points"] = double(d->points.size());
  state.counters["triangles"] = double(mesh.number_of_faces());
  state.counters["err_max"] = e.first;
  state.counters["err_mean"] = e.second;
  state.counters["closed"] = CGAL::is_closed(mesh) ? 1 : 0;
}

void register_all()
{
  const Dataset* files[] = {&file_dataset("sphere.pwn"), &file_dataset("elephant.pwn")};
  for(const Dataset* d : files)
  {
    benchmark::RegisterBenchmark(("contour/" + d->name).c_str(), BM_contour, d, 0.0)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("poisson/" + d->name).c_str(), BM_poisson, d, 30.0, 0.375)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("poisson_fine/" + d->name).c_str(), BM_poisson, d, 2.0, 0.1)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  // Growth with the number of points (default resolution: cell = rho / 2).
  for(std::size_t n : {25000, 50000, 100000, 200000})
  {
    const Dataset* d = &torus_dataset(n);
    benchmark::RegisterBenchmark(("contour/" + d->name).c_str(), BM_contour, d, 0.0)->Unit(benchmark::kMillisecond);
    if(n == 100000 || n == 25000)
      benchmark::RegisterBenchmark(("poisson/" + d->name).c_str(), BM_poisson, d, 30.0, 0.375)
        ->Unit(benchmark::kMillisecond)->Iterations(1);
    if(n == 25000)
      benchmark::RegisterBenchmark(("poisson_fine/" + d->name).c_str(), BM_poisson, d, 2.0, 0.1)
        ->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  // Growth with the resolution at 100K points.
  for(double cells : {64.0, 128.0, 256.0, 512.0})
  {
    const Dataset* d = &torus_dataset(100000);
    benchmark::RegisterBenchmark(("contour/" + d->name + "/cells:" + std::to_string(int(cells))).c_str(), BM_contour,
                                 d, cells)
      ->Unit(benchmark::kMillisecond);
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
