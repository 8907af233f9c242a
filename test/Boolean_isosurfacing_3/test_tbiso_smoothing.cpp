// Crease-preserving lambda|mu smoothing of TBISO output on an analytic CSG
// shape, against plain lambda|mu: a capped cylinder (radius R, |z| < H),
// whose two crease circles have 90-degree dihedral angles.  Prints the
// numbers quoted in RESULTS.md.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::function<double(const Point&)> Field;

namespace {

const double R = 0.6, H = 0.47, pi = 3.14159265358979323846;

// Exact distance from p to the boundary of the capped cylinder.
double distance_to_can(const Point& p)
{
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y()), z = std::abs(p.z());
  const double dr = r - R, dz = z - H;
  if(dr > 0 && dz > 0)
    return std::sqrt(dr * dr + dz * dz);
  if(dr > 0 || dz > 0)
    return std::max(dr, dz);
  return std::min(-dr, -dz);
}

// Distance of a crease vertex to the nearest crease circle (r = R, z = +-H).
double distance_to_crease(const Point& p)
{
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y()), z = std::abs(p.z());
  return std::sqrt((r - R) * (r - R) + (z - H) * (z - H));
}

struct Measures
{
  double mean_vertex = 0, max_vertex = 0, mean_centroid = 0, max_centroid = 0;
  double volume = 0, mean_crease = 0, max_crease = 0, mean_dihedral = 0, min_dihedral = 180;
};

Measures measure(const Mesh& mesh, const BI::Boolean_isosurface_mesh_maps<Point>& maps)
{
  Measures m;
  for(auto v : mesh.vertices())
  {
    const double d = distance_to_can(mesh.point(v));
    m.mean_vertex += d / double(mesh.number_of_vertices());
    m.max_vertex = std::max(m.max_vertex, d);
  }
  for(auto f : mesh.faces())
  {
    double c[3] = {0, 0, 0};
    int n = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      c[0] += mesh.point(v).x();
      c[1] += mesh.point(v).y();
      c[2] += mesh.point(v).z();
      ++n;
    }
    const double d = distance_to_can(Point(c[0] / n, c[1] / n, c[2] / n));
    m.mean_centroid += d / double(mesh.number_of_faces());
    m.max_centroid = std::max(m.max_centroid, d);
  }
  Mesh triangles = mesh;
  PMP::triangulate_faces(triangles);
  m.volume = PMP::volume(triangles);
  std::size_t creases = 0, crease_vertices = 0;
  for(auto e : mesh.edges())
  {
    if(!maps.edge_is_crease[e])
      continue;
    for(int side = 0; side < 2; ++side)
    {
      const Point& p = mesh.point(mesh.vertex(e, side));
      const double d = distance_to_crease(p);
      m.mean_crease += d;
      m.max_crease = std::max(m.max_crease, d);
      ++crease_vertices;
    }
    // Dihedral angle: between the outward normals of the two faces.
    const auto h = mesh.halfedge(e);
    const K::Vector_3 a = PMP::compute_face_normal(mesh.face(h), mesh);
    const K::Vector_3 b = PMP::compute_face_normal(mesh.face(mesh.opposite(h)), mesh);
    const double angle = 180 - std::acos(std::max(-1., std::min(1., a * b))) * 180 / pi;
    m.mean_dihedral += angle;
    m.min_dihedral = std::min(m.min_dihedral, angle);
    ++creases;
  }
  m.mean_crease /= double(crease_vertices);
  m.mean_dihedral /= double(creases);
  return m;
}

void print(const char* name, const Measures& m, double h, double exact_volume)
{
  std::cout << name << ": vertex distance mean " << m.mean_vertex / (h * h) << " h^2, max " << m.max_vertex / (h * h)
            << " h^2; face-centroid distance mean " << m.mean_centroid / (h * h) << " h^2, max "
            << m.max_centroid / (h * h) << " h^2; crease distance mean " << m.mean_crease / (h * h) << " h^2, max "
            << m.max_crease / (h * h) << " h^2; dihedral mean " << m.mean_dihedral << " deg, min " << m.min_dihedral
            << " deg; volume error " << 100 * (m.volume - exact_volume) / exact_volume << " %\n";
}

} // namespace

TEST(TbisoSmoothing, HierarchicalKeepsCreasesPlainRoundsThem)
{
  const std::vector<Field> f{[](const Point& p) { return std::sqrt(p.x() * p.x() + p.y() * p.y()) - R; },
                             [](const Point& p) { return p.z() - H; }, [](const Point& p) { return -p.z() - H; }};
  const double exact_volume = pi * R * R * 2 * H;
  for(std::size_t n : {33, 65})
  {
    const double h = 2.0 / double(n - 1);
    const auto grid = BI::Tetrahedral_grid_3<K>::spanning(Point(-1, -1, -1), Point(1, 1, 1), {n, n, n});
    BI::Boolean_isosurface_soup<Point> soup;
    BI::extract_boolean_isosurface(grid, BI::sample_fields(grid, f), BI::Boolean_expression::parse("f0 & f1 & f2"),
                                   soup);
    const BI::Crease_network network = BI::extract_crease_network(soup);
    ASSERT_EQ(network.corners.size(), 0u);
    ASSERT_EQ(network.polylines.size(), 2u) << "two closed crease circles";

    Mesh raw, hierarchical, plain;
    const auto raw_maps = BI::boolean_isosurface_to_mesh(soup, network, raw);
    const auto h_maps = BI::boolean_isosurface_to_mesh(soup, network, hierarchical);
    const auto p_maps = BI::boolean_isosurface_to_mesh(soup, network, plain);
    BI::smooth_with_creases(hierarchical, CGAL::parameters::edge_is_constrained_map(h_maps.edge_is_crease)
                                              .vertex_is_constrained_map(h_maps.vertex_is_corner));
    BI::plain_lambda_mu_smoothing(plain);

    const Measures r = measure(raw, raw_maps), s = measure(hierarchical, h_maps), p = measure(plain, p_maps);
    std::cout << "capped cylinder, grid " << n << "^3 (h = " << h << "):\n";
    print("  raw         ", r, h, exact_volume);
    print("  hierarchical", s, h, exact_volume);
    print("  plain       ", p, h, exact_volume);

    // The smoothed surface is closer to the exact one (over face centroids,
    // which carry the faceting error), and no more than 0.5 % off in volume.
    EXPECT_LT(s.mean_centroid, r.mean_centroid);
    EXPECT_LT(std::abs(s.volume - r.volume) / r.volume, 0.005);
    // Creases stay within O(h^2) of the analytic circles, and sharp.
    EXPECT_LT(s.max_crease, 1.0 * h * h);
    EXPECT_NEAR(s.mean_dihedral, 90, 5);
    // Plain lambda|mu rounds them: creases move away and flatten.
    EXPECT_GT(p.max_crease, 3 * s.max_crease);
    EXPECT_GT(p.mean_dihedral, s.mean_dihedral + 15);
  }
}
