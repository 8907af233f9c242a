// volume: the Surveyor's-formula volume of closed triangle meshes.
//
//   volume [--check] [--signed] [--no-self-intersection-check] FILE...
//   volume --demo DIR
//
// Reads OFF/OBJ/PLY/STL with the package's own readers (IO::read_triangle_soup:
// flat arrays, no mesh), prints one line per file.  The self-intersection
// check runs on the arrays (internal::does_triangle_soup_self_intersect(),
// PMP's answer without a mesh); a mesh is built only for --check, or for
// PMP's check when the triangles are too unevenly sized for that one.
// --check also prints PMP::volume (Epick) and the exact volume (Epeck) with
// the relative errors of both double results.  --demo writes meshes made in
// code (some far from the origin) to DIR and runs --check on them.
// A file that cannot be read or does not bound a solid gets one line on
// stderr; the exit status is then 1 (2 for a usage error).  The common
// options of cli.h (--threads, --sequential, --json, --quiet, --version)
// apply (doc/Boolean_isosurfacing_3/tools.md).

#include "cli.h"
#include "process_start.h"
#include "kernels.h"
#include "self_intersection.h"

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/check_manifold_vertices.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <cerrno>
#include <cstring>
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
using biso_tools::Mesh;
using biso_tools::Point;
using biso_tools::exact_volume;

using biso_tools::Tool;

struct Options
{
  bool check = false;
  bool signed_volume = false;
  bool self_intersection_check = true;
  bool parallel = true;
  std::string demo_dir;
  std::vector<std::string> files;
};

const char* const description =
    "volume: the Surveyor's-formula volume of closed triangle meshes (OFF, OBJ, PLY, STL)\n"
    "usage: volume [--check] [--signed] [--no-self-intersection-check] FILE...\n"
    "       volume --demo DIR\n";

double relative_error(double value, double reference)
{
  return reference == 0 ? std::abs(value) : std::abs(value - reference) / std::abs(reference);
}

// PMP's answer on the mesh of a closed soup.  A soup with a non-manifold
// vertex has no mesh, and is refused as before.
bool does_self_intersect(const BI::Triangle_soup_3& soup, bool parallel)
{
  BI::internal::check_manifold_vertices(soup.triangles, soup.points.size());
  return biso_tools::soup_self_intersects(soup, parallel);
}

// The JSON record of one file.
biso_tools::Json_object file_record(const std::string& path, const BI::Triangle_soup_3& soup, double volume,
                                    double read_ms, double ms)
{
  biso_tools::Json_object j;
  j.set("input", path);
  j.set("vertices", soup.points.size());
  j.set("faces", soup.triangles.size());
  j.set("volume", volume);
  j.set("read_seconds", read_ms / 1e3);
  j.set("volume_seconds", ms / 1e3);
  return j;
}

bool report(Tool& tool, const std::string& path, const Options& options, std::vector<std::string>& records)
{
  std::FILE* out = tool.human();
  tool.input(path);
  try
  {
    const biso_tools::Stopwatch watch;
    const BI::Triangle_soup_3 soup = BI::IO::read_triangle_soup(path);
    const double read_ms = watch.seconds() * 1e3;
    const biso_tools::Stopwatch volume_watch;
    // Validates the soup (closed, oriented, finite) as it computes.
    const double volume = BI::surveyor_volume(soup, BI::parameters::signed_volume(options.signed_volume));
    const double ms = volume_watch.seconds() * 1e3;
    if(options.self_intersection_check && !options.signed_volume && does_self_intersect(soup, options.parallel))
      throw BI::Self_intersecting_mesh_error("the surface intersects itself, so its inside is not well defined "
                                             "(use --signed for the winding-number-weighted volume)");
    std::string note;
    if(soup.triangulated_polygons != 0)
      note = ", " + std::to_string(soup.triangulated_polygons) + " polygons split into triangles";
    biso_tools::Json_object record = file_record(path, soup, volume, read_ms, ms);
    tool.stage("measure", path + ": read and measured " + std::to_string(soup.triangles.size()) + " triangles",
               watch.seconds());
    if(!options.check)
    {
      std::fprintf(out, "%s: volume %.17g  (%zu triangles%s, read %.1f ms, volume %.3f ms)\n", path.c_str(), volume,
                   soup.triangles.size(), note.c_str(), read_ms, ms);
      records.push_back(record.str());
      return true;
    }
    Mesh mesh;
    BI::IO::triangle_soup_to_mesh(soup, mesh);
    const double pmp = PMP::volume(mesh);
    const double exact = exact_volume(mesh);
    std::fprintf(out, "%s: %zu triangles%s\n", path.c_str(), soup.triangles.size(), note.c_str());
    std::fprintf(out, "  surveyor_volume      %-24.17g relative error %.2e  (%.3f ms)\n", volume,
                 relative_error(volume, exact), ms);
    std::fprintf(out, "  PMP::volume (Epick)  %-24.17g relative error %.2e\n", pmp, relative_error(pmp, exact));
    std::fprintf(out, "  exact (Epeck)        %-24.17g\n", exact);
    record.set("pmp_volume", pmp);
    record.set("exact_volume", exact);
    records.push_back(record.str());
    return true;
  }
  catch(const BI::Invalid_input_error& e)
  {
    biso_tools::print_error("volume", "error: " + path + ": " + e.what());
    biso_tools::Json_object record;
    record.set("input", path);
    record.set("error", std::string(e.what()));
    records.push_back(record.str());
    return false;
  }
}

void write_mesh(Tool& tool, const std::string& path, const Mesh& mesh)
{
  tool.output(path);
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

int run_demo(Tool& tool, const Options& options, std::vector<std::string>& records)
{
  const std::string& dir = options.demo_dir;
  if(mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    throw biso_tools::File_error(dir + ": cannot create the directory (" + std::strerror(errno) + ")");
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
  std::FILE* out = tool.human();
  std::fprintf(out, "Surveyor's formula volumes of meshes made in code, written to %s/\n"
                    "(relative errors against the exact Epeck volume of the same double coordinates)\n\n",
               dir.c_str());
  bool all_ok = true;
  Options check = options;
  check.check = true;
  for(const Shape& shape : shapes)
  {
    const std::string path = dir + "/" + shape.file;
    write_mesh(tool, path, shape.mesh);
    std::fprintf(out, "%s\n", shape.what.c_str());
    all_ok = report(tool, path, check, records) && all_ok;
    std::fprintf(out, "\n");
  }
  return all_ok ? 0 : 1;
}

} // namespace

int run(Tool& tool, const Options& options)
{
  std::vector<std::string> records;
  bool all_ok = true;
  if(!options.demo_dir.empty())
    all_ok = run_demo(tool, options, records) == 0;
  else
    for(const std::string& file : options.files)
      all_ok = report(tool, file, options, records) && all_ok;
  std::string results = "[";
  for(std::size_t i = 0; i < records.size(); ++i)
    results += (i ? ", " : "") + records[i];
  tool.summary().set_raw("results", results + "]");
  return all_ok ? 0 : 1;
}

int main(int argc, char** argv)
{
  biso_tools::restart_with_huge_page_heap(argv);
  Tool tool("volume", description);
  Options options;
  CLI::App& app = tool.app();
  app.add_flag("--check", options.check, "also print PMP::volume (Epick) and the exact (Epeck) volume");
  app.add_flag("--signed", options.signed_volume, "accept inward and self-intersecting surfaces (signed volume)");
  app.add_flag("--no-self-intersection-check", "skip the O(n log n) check (the volume itself is O(n))");
  app.add_option("--demo", options.demo_dir, "write meshes made in code to DIR and --check them")->type_name("DIR");
  return tool.run(
      argc, argv,
      [&] {
        options.files = tool.positionals();
        options.self_intersection_check = app.count("--no-self-intersection-check") == 0;
        options.parallel = tool.parallel();
        if(app.count("--demo") && options.demo_dir.empty())
          throw biso_tools::Usage_error("--demo needs a directory, got an empty argument");
        if(options.demo_dir.empty() && options.files.empty())
          throw biso_tools::Usage_error("no input file (volume --help for usage)");
        if(!options.demo_dir.empty() && !options.files.empty())
          throw biso_tools::Usage_error("--demo takes a directory, no input file");
      },
      [&] { return run(tool, options); });
}
