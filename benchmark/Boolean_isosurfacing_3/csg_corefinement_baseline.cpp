// The alternative to the `csg` tool as a whole process: CGAL's reader into two
// Surface_mesh (Epick), PMP::corefine_and_compute_{union,intersection,
// difference}, CGAL's writer.  Used to compare whole processes in RESULTS.md
// ("Marching Cubes CSG"):
//
//   csg_corefinement_baseline A B union|intersection|difference OUT
//   csg A B -e "A | B" --cells N -o OUT

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

static bool read_closed(const char* file, Mesh& mesh)
{
  if(CGAL::IO::read_polygon_mesh(file, mesh) && CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh))
    return true;
  std::cerr << "csg_corefinement_baseline: " << file << ": cannot read a closed triangle mesh\n";
  return false;
}

int main(int argc, char** argv)
{
  if(argc != 5)
  {
    std::cerr << "usage: csg_corefinement_baseline A B union|intersection|difference OUT\n";
    return 2;
  }
  const std::string operation = argv[3];
  if(operation != "union" && operation != "intersection" && operation != "difference")
  {
    std::cerr << "csg_corefinement_baseline: unknown operation '" << operation << "'\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  Mesh a, b, out;
  if(!read_closed(argv[1], a) || !read_closed(argv[2], b))
    return 1;
  const auto read = std::chrono::steady_clock::now();
  const bool valid = operation == "union"          ? PMP::corefine_and_compute_union(a, b, out)
                     : operation == "intersection" ? PMP::corefine_and_compute_intersection(a, b, out)
                                                   : PMP::corefine_and_compute_difference(a, b, out);
  if(!valid)
  {
    std::cerr << "csg_corefinement_baseline: the result is not a valid volume\n";
    return 1;
  }
  const auto computed = std::chrono::steady_clock::now();
  if(!CGAL::IO::write_polygon_mesh(argv[4], out, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "csg_corefinement_baseline: cannot write " << argv[4] << "\n";
    return 1;
  }
  const auto done = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::printf("%s: %zu triangles (read %.1f ms, corefinement %.1f ms, write %.1f ms)\n", argv[4],
              std::size_t(out.number_of_faces()), ms(start, read), ms(read, computed), ms(computed, done));
  return 0;
}
