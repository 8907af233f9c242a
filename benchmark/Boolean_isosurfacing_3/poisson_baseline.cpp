// The `contour` tool's alternative as a whole process: CGAL 5.5's Poisson
// reconstruction as CGAL's example runs it, files in and out.  Used to
// compare whole processes in RESULTS.md ("Contouring point samples"):
//
//   poisson_baseline FILE OUT.off
//   contour FILE -o OUT.off
//
// The points are read with the project's reader (.pts, .xyz, .pwn, .ply,
// .off: CGAL's readers know no .pts); samples without normals get CGAL's
// pca_estimate_normals (18 neighbours) and mst_orient_normals first, as in
// `benchmark_contour`; the spacing is CGAL's compute_average_spacing (6
// neighbours), as in CGAL's example.  Sequential, as CGAL's Poisson is.

#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Pwn;

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::cerr << "usage: poisson_baseline POINTS OUT.off\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<K::Point_3> points;
  std::vector<K::Vector_3> normals;
  try
  {
    CGAL::Boolean_isosurfacing::IO::read_point_samples(argv[1], points, normals); // throws on bad input
  }
  catch(const std::exception& e)
  {
    std::cerr << "poisson_baseline: " << e.what() << "\n";
    return 1;
  }
  std::vector<Pwn> pwn;
  pwn.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    pwn.emplace_back(points[i], normals.empty() ? K::Vector_3(0, 0, 0) : normals[i]);
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>())
                    .normal_map(CGAL::Second_of_pair_property_map<Pwn>());
  if(normals.empty())
  {
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(pwn, 18, np);
    pwn.erase(CGAL::mst_orient_normals(pwn, 18, np), pwn.end());
  }
  const double spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(
      pwn, 6, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pwn>()));
  CGAL::Surface_mesh<K::Point_3> mesh;
  bool ok = false;
  try
  {
    ok = CGAL::poisson_surface_reconstruction_delaunay(pwn.begin(), pwn.end(), CGAL::First_of_pair_property_map<Pwn>(),
                                                       CGAL::Second_of_pair_property_map<Pwn>(), mesh, spacing);
  }
  catch(const std::exception& e) // cube.pwn's unoriented normals: a CGAL assertion in the surface mesher
  {
    std::cerr << "poisson_baseline: Poisson threw: " << e.what() << "\n";
    return 1;
  }
  if(!ok || !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "poisson_baseline: " << argv[1] << ": Poisson failed\n";
    return 1;
  }
  std::printf("%s: %zu points, %zu triangles in %.3f s\n", argv[1], pwn.size(), std::size_t(mesh.number_of_faces()),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}
