// The volume of a closed triangle mesh read from a file (default: a sphere
// made in code), with the Surveyor's formula.

#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace BI = CGAL::Boolean_isosurfacing;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc > 1)
  {
    if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
    {
      std::cerr << "cannot read " << argv[1] << " as a polygon mesh\n";
      return 1;
    }
  }
  else
    BI::make_icosphere(mesh, K::Point_3(1e7, 0, 0), 1.0, 4); // far from the origin on purpose

  try
  {
    std::cout.precision(17);
    std::cout << "volume: " << BI::surveyor_volume(mesh) << "\n";
    // Accept an inward-oriented or self-intersecting surface and get the
    // winding-number-weighted (signed) volume instead of an exception:
    std::cout << "signed volume: " << BI::surveyor_volume(mesh, BI::parameters::signed_volume(true)) << "\n";
  }
  catch(const BI::Invalid_input_error& e)
  {
    std::cerr << "not a closed triangle mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
