// TBISO on an unstructured tetrahedral mesh made by CGAL's Mesh_3: mesh a
// ball of radius 1 with tetrahedra, sample two fields at its vertices (a
// sphere and a plane), and extract the boundary of "inside the sphere and
// below the plane", closed on the boundary of the tetrahedral mesh.
//
// The Mesh_3 complex becomes a Tetrahedral_mesh_3: its finite vertices are
// the points, its cells in the complex the tetrahedra.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Criteria;

int main()
{
  // A ball of radius 1, meshed with tetrahedra of size about 0.1.
  const Domain domain = Domain::create_implicit_mesh_domain(
      [](const Point& p) { return (p - CGAL::ORIGIN).squared_length() - 1; },
      K::Sphere_3(CGAL::ORIGIN, 2.));
  const Criteria criteria(CGAL::parameters::facet_angle = 25, CGAL::parameters::facet_size = 0.1,
                          CGAL::parameters::facet_distance = 0.01, CGAL::parameters::cell_size = 0.1);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria);

  // Complex -> Tetrahedral_mesh_3.
  std::map<Tr::Vertex_handle, std::size_t> index;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 4>> tetrahedra;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    std::array<std::size_t, 4> tet;
    for(int i = 0; i < 4; ++i)
    {
      auto inserted = index.emplace(c->vertex(i), points.size());
      if(inserted.second)
        points.push_back(c3t3.triangulation().point(c->vertex(i)).point());
      tet[i] = inserted.first->second;
    }
    tetrahedra.push_back(tet);
  }
  const BI::Tetrahedral_mesh_3<K> mesh(points, tetrahedra);
  std::cout << "Mesh_3: " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_tetrahedra()
            << " tetrahedra, " << mesh.number_of_boundary_faces() << " boundary faces\n";

  // f0: inside the sphere of radius 0.8 centred at (0.1, 0, 0), which stays
  // inside the ball; f1: below z = 0.2.
  const std::vector<std::function<double(const Point&)>> functions{
      [](const Point& p) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point(0.1, 0, 0)))) - 0.8; },
      [](const Point& p) { return p.z() - 0.2; }};
  BI::Boolean_isosurface_soup<Point> surface;
  const BI::Boolean_isosurface_statistics stats = BI::extract_boolean_isosurface(
      mesh, BI::sample_fields(mesh, functions), BI::Boolean_expression::parse("f0 & f1"), surface,
      BI::parameters::close_at_domain_boundary(true));
  const BI::Crease_network creases = BI::extract_crease_network(surface);

  // The solid lies inside the ball, so the domain boundary closes nothing:
  // its volume converges to that of the spherical cap.
  double volume = 0;
  for(const auto& polygon : surface.polygons)
    for(std::size_t k = 1; k + 1 < polygon.size(); ++k)
      volume += CGAL::determinant(surface.points[polygon[0]] - CGAL::ORIGIN, surface.points[polygon[k]] - CGAL::ORIGIN,
                                  surface.points[polygon[k + 1]] - CGAL::ORIGIN) /
                6;
  const double r = 0.8, h = r + 0.2, pi = 3.14159265358979323846;
  const double exact = pi * h * h * (3 * r - h) / 3;
  std::cout << "TBISO: " << surface.points.size() << " vertices, " << surface.polygons.size() << " polygons, "
            << creases.polylines.size() << " crease polyline(s), " << creases.corners.size() << " corner(s), "
            << stats.number_of_evaluated_tetrahedra << " tetrahedra evaluated\n"
            << "volume " << volume << " (exact spherical cap " << exact << ", relative error "
            << std::abs(volume - exact) / exact << ")\n";
  return std::abs(volume - exact) / exact < 0.03 ? 0 : 1;
}
