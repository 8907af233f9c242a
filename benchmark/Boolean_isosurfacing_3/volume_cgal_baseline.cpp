// The alternative to the `volume` tool as a whole process: CGAL's own reader
// into a Surface_mesh (Epick), then PMP::volume.  Used to compare whole
// processes in RESULTS.md ("Input and volume at disk speed"):
//
//   time volume_cgal_baseline FILE
//   time volume --no-self-intersection-check FILE

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: volume_cgal_baseline FILE\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  CGAL::Surface_mesh<K::Point_3> mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "volume_cgal_baseline: " << argv[1] << ": cannot read a closed triangle mesh\n";
    return 1;
  }
  const auto read = std::chrono::steady_clock::now();
  const double volume = CGAL::Polygon_mesh_processing::volume(mesh);
  const auto done = std::chrono::steady_clock::now();
  std::printf("%s: volume %.17g  (%zu triangles, read %.1f ms, volume %.3f ms)\n", argv[1], volume,
              std::size_t(mesh.number_of_faces()), std::chrono::duration<double, std::milli>(read - start).count(),
              std::chrono::duration<double, std::milli>(done - read).count());
  return 0;
}
