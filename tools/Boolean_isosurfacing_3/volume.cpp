// volume: the Surveyor's-formula volume of closed triangle meshes.
//
//   volume [--check] [--signed] [--no-self-intersection-check] FILE...
//   volume --demo DIR
//
// Reads OFF/OBJ/PLY/STL with the package's own readers (IO::read_triangle_soup:
// flat arrays, no mesh), prints one line per file.  A mesh is built only for
// the self-intersection check and --check.
// --check also prints PMP::volume (Epick) and the exact volume (Epeck) with
// the relative errors of both double results.  --demo writes meshes made in
// code (some far from the origin) to DIR and runs --check on them.
// A file that cannot be read or does not bound a solid gets one line on
// stderr; the exit status is then 1 (2 for a usage error).

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <stdexcept>
#include <sys/stat.h>
#include <sys/types.h>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

struct Options
{
  bool check = false;
  bool signed_volume = false;
  bool self_intersection_check = true;
  std::string demo_dir;
  std::vector<std::string> files;
};

const char* const usage_text = "usage: volume [--check] [--signed] [--no-self-intersection-check] FILE...\n"
                               "       volume --demo DIR\n";

int usage(const char* message)
{
  std::cerr << "volume: " << message << "\n" << usage_text;
  return 2;
}

int help()
{
  std::cout << "volume: the Surveyor's-formula volume of closed triangle meshes (OFF, OBJ, PLY, STL)\n"
            << usage_text
            << "  --check                       also print PMP::volume (Epick) and the exact (Epeck) volume\n"
               "  --signed                      accept inward and self-intersecting surfaces (signed volume)\n"
               "  --no-self-intersection-check  skip the O(n log n) check (the volume itself is O(n))\n"
               "  --demo DIR                    write meshes made in code to DIR and --check them\n"
               "Exit status: 0 on success, 1 if a file cannot be read or does not bound a solid, 2 for usage.\n";
  return 0;
}

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double exact_volume(const Mesh& mesh)
{
  CGAL::Surface_mesh<Epeck::Point_3> exact_mesh;
  CGAL::copy_face_graph(mesh, exact_mesh);
  return CGAL::to_double(CGAL::exact(PMP::volume(exact_mesh)));
}

double relative_error(double value, double reference)
{
  return reference == 0 ? std::abs(value) : std::abs(value - reference) / std::abs(reference);
}

bool report(const std::string& path, const Options& options)
{
  try
  {
    const auto start = std::chrono::steady_clock::now();
    const BI::Triangle_soup_3 soup = BI::IO::read_triangle_soup(path);
    const double read_ms = milliseconds_since(start);
    const auto volume_start = std::chrono::steady_clock::now();
    // Validates the soup (closed, oriented, finite) as it computes.
    const double volume = BI::surveyor_volume(soup, BI::parameters::signed_volume(options.signed_volume));
    const double ms = milliseconds_since(volume_start);
    Mesh mesh;
    const bool need_mesh = options.check || (options.self_intersection_check && !options.signed_volume);
    if(need_mesh)
      BI::IO::triangle_soup_to_mesh(soup, mesh);
    if(options.self_intersection_check && !options.signed_volume && PMP::does_self_intersect(mesh))
      throw BI::Self_intersecting_mesh_error("the surface intersects itself, so its inside is not well defined "
                                             "(use --signed for the winding-number-weighted volume)");
    std::string note;
    if(soup.triangulated_polygons != 0)
      note = ", " + std::to_string(soup.triangulated_polygons) + " polygons split into triangles";
    if(!options.check)
    {
      std::printf("%s: volume %.17g  (%zu triangles%s, read %.1f ms, volume %.3f ms)\n", path.c_str(), volume,
                  soup.triangles.size(), note.c_str(), read_ms, ms);
      return true;
    }
    const double pmp = PMP::volume(mesh);
    const double exact = exact_volume(mesh);
    std::printf("%s: %zu triangles%s\n", path.c_str(), soup.triangles.size(), note.c_str());
    std::printf("  surveyor_volume      %-24.17g relative error %.2e  (%.3f ms)\n", volume,
                relative_error(volume, exact), ms);
    std::printf("  PMP::volume (Epick)  %-24.17g relative error %.2e\n", pmp, relative_error(pmp, exact));
    std::printf("  exact (Epeck)        %-24.17g\n", exact);
    return true;
  }
  catch(const BI::Invalid_input_error& e)
  {
    std::cerr << "volume: " << path << ": " << e.what() << "\n";
    return false;
  }
}

void write_mesh(const std::string& path, const Mesh& mesh)
{
  if(!CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + path);
}

Mesh triangulated_box(const Point& low, double side)
{
  Mesh mesh;
  const double x = low.x(), y = low.y(), z = low.z(), s = side;
  CGAL::make_hexahedron(Point(x, y, z), Point(x + s, y, z), Point(x + s, y + s, z), Point(x, y + s, z),
                        Point(x, y + s, z + s), Point(x, y, z + s), Point(x + s, y, z + s),
                        Point(x + s, y + s, z + s), mesh);
  PMP::triangulate_faces(mesh);
  return mesh;
}

int run_demo(const Options& options)
{
  const std::string& dir = options.demo_dir;
  if(mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
  {
    std::cerr << "volume: cannot create directory " << dir << "\n";
    return 1;
  }
  struct Shape { std::string file; std::string what; Mesh mesh; };
  std::vector<Shape> shapes;
  {
    Mesh sphere;
    BI::make_icosphere(sphere, Point(0, 0, 0), 1.0, 5);
    shapes.push_back({"sphere.off", "unit icosphere (20480 triangles) at the origin", sphere});
    Mesh far_sphere;
    BI::make_icosphere(far_sphere, Point(1e7, 1e7, 1e7), 1.0, 5);
    shapes.push_back({"sphere_at_1e7.off", "the same sphere moved to (1e7, 1e7, 1e7)", far_sphere});
    shapes.push_back({"cube_at_1e6.off", "unit cube with a corner at (1e6, 1e6, 1e6)", triangulated_box(Point(1e6, 1e6, 1e6), 1.0)});
    Mesh torus;
    BI::make_torus(torus, Point(0, 0, 0), 1.0, 0.5, 256, 128);
    shapes.push_back({"torus.off", "torus R = 1, r = 0.5 (65536 triangles)", torus});
  }
  std::printf("Surveyor's formula volumes of meshes made in code, written to %s/\n"
              "(relative errors against the exact Epeck volume of the same double coordinates)\n\n",
              dir.c_str());
  bool all_ok = true;
  Options check = options;
  check.check = true;
  for(const Shape& shape : shapes)
  {
    const std::string path = dir + "/" + shape.file;
    write_mesh(path, shape.mesh);
    std::printf("%s\n", shape.what.c_str());
    all_ok = report(path, check) && all_ok;
    std::printf("\n");
  }
  return all_ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--check") options.check = true;
    else if(arg == "--signed") options.signed_volume = true;
    else if(arg == "--no-self-intersection-check") options.self_intersection_check = false;
    else if(arg == "--demo")
    {
      if(i + 1 >= argc) return usage("--demo needs a directory");
      options.demo_dir = argv[++i];
    }
    else if(arg == "-h" || arg == "--help") return help();
    else if(!arg.empty() && arg[0] == '-') return usage(("unknown option " + arg).c_str());
    else options.files.push_back(arg);
  }
  try
  {
    if(!options.demo_dir.empty()) return run_demo(options);
    if(options.files.empty()) return usage("no input file");
    bool all_ok = true;
    for(const std::string& file : options.files) all_ok = report(file, options) && all_ok;
    return all_ok ? 0 : 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "volume: " << e.what() << "\n";
    return 1;
  }
}
