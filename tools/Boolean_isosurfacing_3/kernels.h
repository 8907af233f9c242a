// The kernels and the mesh type of the tools, and the exact volume their
// checks compare with (the tests' and benchmarks' are in test_util.h).

#ifndef BISO_TOOLS_KERNELS_H
#define BISO_TOOLS_KERNELS_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

namespace biso_tools {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;

/// PMP::volume with Epeck (it calls exact() after every term, so the value is
/// the exact rational volume of the mesh's double coordinates), rounded to
/// the nearest double once at the end.
template <typename TriangleMesh>
double exact_volume(const TriangleMesh& mesh)
{
  Exact_mesh exact_mesh;
  CGAL::copy_face_graph(mesh, exact_mesh);
  return CGAL::to_double(CGAL::exact(CGAL::Polygon_mesh_processing::volume(exact_mesh)));
}

} // namespace biso_tools

#endif // BISO_TOOLS_KERNELS_H
