#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main()
{
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::make_tetrahedron(K::Point_3(0, 0, 0), K::Point_3(6, 0, 0), K::Point_3(0, 6, 0), K::Point_3(0, 0, 6), mesh);
  const double v = CGAL::Boolean_isosurfacing::surveyor_volume(mesh);
  std::cout << "downstream: volume " << v << "\n";
  return v == 36.0 ? 0 : 1;
}
