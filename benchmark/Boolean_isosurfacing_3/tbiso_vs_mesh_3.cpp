// TBISO against CGAL's alternative for a Boolean combination of implicit
// functions: Mesh_3 on a labelled domain whose labelling function is the
// Boolean expression (1 where it holds, 0 elsewhere), surface facets only.
// Same input as benchmark_boolean_isosurface's "seed 128^3" set-up: 4
// spheres, "at least two of four".  Mesh_3's facet size and distance are set
// to the grid spacing h = 2/127 and h/8; the comparison prints both outputs'
// size, time and vertex distance to the nearest sphere (a lower bound of the
// distance to the exact surface, the same for both).
//
//   tbiso_vs_mesh_3 [facet_size_factor=1]

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Criteria;

namespace {

const double a = 0.45 / std::sqrt(3.), r = 0.62;
const double centres[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};

double sphere(int i, const Point& p)
{
  const double x = p.x() - centres[i][0], y = p.y() - centres[i][1], z = p.z() - centres[i][2];
  return std::sqrt(x * x + y * y + z * z) - r;
}

// "At least two of four" spheres contain p.
int label(const Point& p)
{
  int inside = 0;
  for(int i = 0; i < 4; ++i)
    inside += sphere(i, p) < 0;
  return inside >= 2 ? 1 : 0;
}

double nearest_sphere_distance(const Point& p)
{
  double d = 1e9;
  for(int i = 0; i < 4; ++i)
    d = std::min(d, std::abs(sphere(i, p)));
  return d;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  const double factor = argc > 1 ? std::stod(argv[1]) : 1.0;
  const double h = 2.0 / 127;

  // TBISO, sequential, sampling included.
  auto start = std::chrono::steady_clock::now();
  const auto grid = BI::Tetrahedral_grid_3<K>::spanning(Point(-1, -1, -1), Point(1, 1, 1), {128, 128, 128});
  std::vector<std::function<double(const Point&)>> f;
  for(int i = 0; i < 4; ++i)
    f.push_back([i](const Point& p) { return sphere(i, p); });
  BI::Boolean_isosurface_soup<Point> soup;
  BI::extract_boolean_isosurface(grid, BI::sample_fields(grid, f),
                                 BI::Boolean_expression::parse("f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3"), soup);
  const double tbiso_seconds = seconds_since(start);
  std::size_t triangles = 0;
  double mean = 0, worst = 0;
  for(const auto& poly : soup.polygons)
    triangles += poly.size() - 2;
  for(const Point& p : soup.points)
  {
    const double d = nearest_sphere_distance(p);
    mean += d / double(soup.points.size());
    worst = std::max(worst, d);
  }
  std::printf("TBISO (128^3, sequential, sampling included): %.3f s, %zu vertices, %zu triangles, "
              "vertex distance mean %.2e max %.2e, crease polylines kept\n",
              tbiso_seconds, soup.points.size(), triangles, mean, worst);

  // Mesh_3 on the labelled domain.
  start = std::chrono::steady_clock::now();
  const Domain domain(std::function<int(const Point&)>(label), K::Sphere_3(CGAL::ORIGIN, 3.), 1e-6);
  const Criteria criteria(CGAL::parameters::facet_angle = 25, CGAL::parameters::facet_size = factor * h,
                          CGAL::parameters::facet_distance = factor * h / 8);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, CGAL::parameters::no_perturb(),
                                            CGAL::parameters::no_exude());
  CGAL::Surface_mesh<Point> surface;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, surface);
  const double mesh_3_seconds = seconds_since(start);
  mean = 0;
  worst = 0;
  for(auto v : surface.vertices())
  {
    const double d = nearest_sphere_distance(surface.point(v));
    mean += d / double(surface.number_of_vertices());
    worst = std::max(worst, d);
  }
  std::printf("Mesh_3 (facet size %.4f, distance %.5f, no crease protection): %.3f s, %zu vertices, %zu triangles, "
              "vertex distance mean %.2e max %.2e\n",
              factor * h, factor * h / 8, mesh_3_seconds, std::size_t(surface.number_of_vertices()),
              std::size_t(surface.number_of_faces()), mean, worst);
  std::printf("ratio Mesh_3 / TBISO time: %.1f\n", mesh_3_seconds / tbiso_seconds);
  return 0;
}
