// tbiso: the boundary of a Boolean combination of scalar fields sampled on a
// tetrahedral domain, with its crease polylines and corners (TBISO: Taubin &
// Sibley, "Extracting Boolean isosurfaces from tetrahedral meshes").
//
//   tbiso (--grid N | --mesh FILE) (--fields FILE | --field SPEC ...) [--expr TEXT]
//         [--close] [--smooth [ITER]] [-o out.ply|out.off] [--creases F] [--corners F]
//   tbiso --demo DIR
//
// The literal fi of the expression is the region f_i < 0.  Prints the domain,
// the fields, the canonical expression, the time of every stage, the output
// sizes and, for a closed surface, the enclosed volume.  Any error is one line
// `tbiso: error: ...` on stderr and exit status 1.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/Boolean_isosurface_PLY_stream.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_by_slabs.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>
#include "tool_support.h"
#include "tbiso_fields.h"
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/blocked_range.h>
#  include <tbb/global_control.h>
#  include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <sys/resource.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Tetrahedral_grid_3<K> Grid;
typedef BI::Tetrahedral_mesh_3<K> Tet_mesh;
typedef BI::Boolean_isosurface_soup<Point> Soup;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef tbiso_fields::Field Field;
using tbiso_fields::Error;
using tbiso_fields::make_field;
using tbiso_fields::parse_double;
using tbiso_fields::parse_numbers;
using tbiso_fields::split;

const char* usage_text =
    "usage: tbiso (--grid N | --grid NX,NY,NZ [--box XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX] | --mesh FILE)\n"
    "             (--fields FILE [--field-count N] | --field SPEC [--field SPEC ...])\n"
    "             [--expr TEXT] [--close] [--smooth [ITER] [--lambda L] [--mu M]]\n"
    "             [-o OUT.ply|OUT.off] [--creases FILE] [--corners FILE] [--sequential] [--threads N]\n"
    "             [--slab-size LAYERS] [--out-of-core]\n"
    "       tbiso --demo DIR\n"
    "\n"
    "The boundary of the regularized Boolean set EXPR(f0, f1, ...) where the literal fi is\n"
    "the region f_i < 0, for scalar fields sampled at the vertices of a tetrahedral domain\n"
    "(TBISO), with its crease polylines and corners.\n"
    "\n"
    "domain:\n"
    "  --grid N | NX,NY,NZ   regular grid of N^3 (NX*NY*NZ) vertices, 6 tetrahedra per cube\n"
    "  --box X0,Y0,Z0,X1,Y1,Z1  extent of the grid (default -1,-1,-1,1,1,1)\n"
    "  --mesh FILE           tetrahedral mesh: Medit .mesh or TetGen .node/.ele\n"
    "fields (one of):\n"
    "  --fields FILE         values at the domain vertices: .f64/.raw (float64) or .f32 raw\n"
    "                        binary, vertex-major (needs --field-count N); any other: text\n"
    "  --field SPEC          an analytic field, repeatable (f0, f1, ... in order):\n"
    "                          sphere:CX,CY,CZ,R          |p - c| - R\n"
    "                          plane:A,B,C,D              A x + B y + C z + D\n"
    "                          box:X0,Y0,Z0,X1,Y1,Z1      signed distance to the box\n"
    "                          cylinder:AXIS,C1,C2,R      infinite cylinder, AXIS x|y|z,\n"
    "                                                     (C1,C2) its centre in the other axes\n"
    "                          torus:R,r                  torus around the z axis at the origin\n"
    "                          distance:MESHFILE          signed distance to a closed triangle\n"
    "                                                     mesh (OFF/OBJ/PLY/STL), negative inside\n"
    "expression:\n"
    "  --expr TEXT           e.g. \"f0 & !f1 | f2\" (default f0 for one field)\n"
    "  --close               close the set on the boundary of the domain\n"
    "smoothing:\n"
    "  --smooth [ITER]       Taubin lambda|mu smoothing keeping creases and corners\n"
    "                        (default 10 iterations); the surface must be manifold\n"
    "  --lambda L, --mu M    smoothing factors (default 0.6307, -0.6732)\n"
    "output:\n"
    "  -o FILE               the surface: .ply (with field labels and colours) or .off\n"
    "  --creases FILE        crease polylines (CGAL polylines text format)\n"
    "  --corners FILE        corners, one 'x y z' line each\n"
    "other:\n"
    "  --sequential          run on one thread (default: parallel when built with TBB)\n"
    "  --threads N           use at most N threads\n"
    "  --slab-size LAYERS    cube layers per slab along z, the unit of parallel work on a grid\n"
    "                        (default: about 1/64 of the grid in core, 8 out of core)\n"
    "  --out-of-core         grid + raw --fields file (or --field SPECs) + -o OUT.ply: read (or\n"
    "                        evaluate) the fields one slab at a time and stream the surface to\n"
    "                        the file; memory is a few slabs\n"
    "                        (no --creases, --corners or --smooth: they need the whole surface)\n"
    "  --demo DIR            four spheres on a 128^3 grid, 'at least two of four';\n"
    "                        writes DIR/tbiso_demo.ply, DIR/tbiso_demo_creases.polylines.txt,\n"
    "                        DIR/tbiso_demo_corners.xyz\n"
    "  -h, --help            this text\n";

struct Options
{
  std::optional<std::array<std::size_t, 3>> grid;
  std::optional<std::array<double, 6>> box;
  std::string mesh_file, fields_file;
  std::size_t field_count = 0;
  std::vector<std::string> field_specs;
  std::optional<std::string> expression;
  bool close = false;
  bool parallel = true;
  std::size_t threads = 0;
  std::size_t slab_layers = 0;
  bool out_of_core = false;
  std::optional<long long> smooth_iterations;
  std::optional<double> lambda, mu;
  std::string output, creases_file, corners_file, demo_dir;
};

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// ---- argument parsing ------------------------------------------------------

std::size_t parse_count(const std::string& text, const std::string& what)
{
  if(text.empty() || text.size() > 12 || !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit((unsigned char)c); }))
    throw Error(what + ": '" + text + "' is not a whole number");
  return std::size_t(std::stoull(text));
}

bool has_extension(const std::string& file, const std::string& extension)
{
  if(file.size() < extension.size())
    return false;
  for(std::size_t k = 0; k < extension.size(); ++k)
    if(std::tolower((unsigned char)file[file.size() - extension.size() + k]) != extension[k])
      return false;
  return true;
}

// Returns false for --help.
bool parse_arguments(int argc, char** argv, Options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Error(arg + " needs a value (see tbiso --help)");
      return argv[++i];
    };
    if(arg == "-h" || arg == "--help")
      return false;
    else if(arg == "--grid")
    {
      const std::string text = value();
      const std::vector<std::string> parts = split(text, ',');
      if(parts.size() != 1 && parts.size() != 3)
        throw Error("--grid: expected N or NX,NY,NZ, got '" + text + "'");
      std::array<std::size_t, 3> n;
      for(int a = 0; a < 3; ++a)
      {
        n[a] = parse_count(parts[parts.size() == 1 ? 0 : a], "--grid");
        if(n[a] < 2)
          throw Error("--grid: at least 2 vertices per axis are needed, got " + std::to_string(n[a]));
      }
      o.grid = n;
    }
    else if(arg == "--box")
    {
      const std::vector<double> b = parse_numbers(value(), 6, "--box");
      for(int a = 0; a < 3; ++a)
        if(!(b[a] < b[a + 3]))
          throw Error("--box: the minimum must be below the maximum on every axis");
      o.box = std::array<double, 6>{b[0], b[1], b[2], b[3], b[4], b[5]};
    }
    else if(arg == "--mesh")
      o.mesh_file = value();
    else if(arg == "--fields")
      o.fields_file = value();
    else if(arg == "--field-count")
    {
      o.field_count = parse_count(value(), "--field-count");
      if(o.field_count == 0)
        throw Error("--field-count: at least one field is needed");
    }
    else if(arg == "--field")
      o.field_specs.push_back(value());
    else if(arg == "--expr")
      o.expression = value();
    else if(arg == "--close")
      o.close = true;
    else if(arg == "--sequential")
      o.parallel = false;
    else if(arg == "--threads")
    {
      const std::string text = value();
      o.threads = parse_count(text, "--threads");
      if(o.threads < 1)
        throw Error("--threads: at least 1 thread is needed, got " + text);
    }
    else if(arg == "--slab-size")
    {
      const std::string text = value();
      o.slab_layers = parse_count(text, "--slab-size");
      if(o.slab_layers < 1)
        throw Error("--slab-size: at least 1 layer per slab is needed, got " + text);
    }
    else if(arg == "--out-of-core")
      o.out_of_core = true;
    else if(arg == "--smooth")
    {
      // ITER is optional: a following word that is not an option is it.
      o.smooth_iterations = BI::taubin_default_number_of_iterations;
      if(i + 1 < argc && argv[i + 1][0] != '-')
        o.smooth_iterations = (long long)parse_count(argv[++i], "--smooth");
    }
    else if(arg == "--lambda")
      o.lambda = parse_double(value(), "--lambda");
    else if(arg == "--mu")
      o.mu = parse_double(value(), "--mu");
    else if(arg == "-o" || arg == "--output")
    {
      o.output = value();
      if(!has_extension(o.output, ".ply") && !has_extension(o.output, ".off"))
        throw Error("-o: unknown output extension in '" + o.output + "' (use .ply or .off)");
    }
    else if(arg == "--creases")
      o.creases_file = value();
    else if(arg == "--corners")
      o.corners_file = value();
    else if(arg == "--demo")
      o.demo_dir = value();
    else
      throw Error("unknown option '" + arg + "' (see tbiso --help)");
  }
  if((o.lambda || o.mu) && !o.smooth_iterations)
    throw Error("--lambda and --mu need --smooth");
  return true;
}

// ---- the run ---------------------------------------------------------------

// A progress bar on stderr, only for runs that last and only on a terminal.
class Progress_bar
{
public:
  void operator()(double fraction) const
  {
    const double seconds = seconds_since(m_start);
    if(seconds < 1.0 || !isatty(2))
      return;
    const int width = 40, done = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(done, '#').c_str(), std::string(width - done, ' ').c_str(),
                 int(fraction * 100 + 0.5));
    if(fraction >= 1.0)
      std::fprintf(stderr, "\r%*s\r", width + 8, "");
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// Field i at vertex v is fields[i](point_at(v)); every vertex writes its own
// values, so the parallel loop gives the sequential result.
template <typename PointAt>
BI::Scalar_fields sample(std::size_t number_of_vertices, const std::vector<Field>& functions,
                         const PointAt& point_at, bool parallel)
{
  BI::Scalar_fields fields(number_of_vertices, functions.size());
  const std::size_t n = functions.size();
  double* values = fields.data().data();
  const auto body = [&](std::size_t begin, std::size_t end) {
    for(std::size_t v = begin; v < end; ++v)
    {
      const Point p = point_at(v);
      for(std::size_t i = 0; i < n; ++i)
        values[v * n + i] = functions[i](p);
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, number_of_vertices, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  else
#endif
    body(0, number_of_vertices);
  (void)parallel;
  return fields;
}

template <typename Domain>
BI::Boolean_isosurface_statistics extract(const Domain& domain, const BI::Scalar_fields& fields,
                                          const BI::Boolean_expression& expression, Soup& soup, const Options& o)
{
  // slab_layers 0: the library's default.
  const auto np = BI::parameters::close_at_domain_boundary(
      o.close, BI::parameters::progress(Progress_bar(), BI::parameters::slab_layers(o.slab_layers)));
  if(o.parallel)
    return BI::extract_boolean_isosurface<CGAL::Parallel_if_available_tag>(domain, fields, expression, soup, np);
  return BI::extract_boolean_isosurface<CGAL::Sequential_tag>(domain, fields, expression, soup, np);
}

// Closed: every directed edge is matched by exactly one reverse edge (so
// each undirected edge is in exactly two consistently oriented polygons).
struct Edge_report
{
  std::size_t border = 0, non_manifold = 0, inconsistent = 0;
  bool closed() const { return border == 0 && non_manifold == 0 && inconsistent == 0; }
};

Edge_report check_edges(const Soup& soup)
{
  struct Use
  {
    std::size_t a, b;
    bool forward;
    bool operator<(const Use& u) const { return a != u.a ? a < u.a : (b != u.b ? b < u.b : forward < u.forward); }
  };
  std::vector<Use> uses;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
      uses.push_back(a < b ? Use{a, b, true} : Use{b, a, false});
    }
  std::sort(uses.begin(), uses.end());
  Edge_report report;
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while(j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b)
      ++j;
    if(j - i == 1)
      ++report.border;
    else if(j - i > 2)
      ++report.non_manifold;
    else if(uses[i].forward == uses[i + 1].forward)
      ++report.inconsistent;
    i = j;
  }
  return report;
}

// Divergence theorem over the fan triangles of the polygons, relative to the
// centre of the bounding box (fewer lost digits than the origin far away).
double enclosed_volume(const Soup& soup)
{
  if(soup.points.empty())
    return 0;
  CGAL::Bbox_3 box;
  for(const Point& p : soup.points)
    box += p.bbox();
  const K::Vector_3 centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  double volume = 0;
  for(const std::vector<std::size_t>& poly : soup.polygons)
  {
    const K::Vector_3 a = soup.points[poly[0]] - CGAL::ORIGIN - centre;
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      volume += CGAL::determinant(a, soup.points[poly[k]] - CGAL::ORIGIN - centre,
                                  soup.points[poly[k + 1]] - CGAL::ORIGIN - centre);
  }
  return volume / 6;
}

// Hierarchical lambda|mu smoothing of the soup's points through a
// Surface_mesh: vertex i of the mesh is point i of the soup, so the polygons
// and their labels are kept as they are.
void smooth(Soup& soup, const BI::Crease_network& creases, const Options& o)
{
  Surface_mesh mesh;
  BI::Boolean_isosurface_mesh_maps<Point> maps;
  try
  {
    maps = BI::boolean_isosurface_to_mesh(soup, creases, mesh);
  }
  catch(const BI::Invalid_input_error& e)
  {
    throw Error(std::string("--smooth: ") + e.what());
  }
  BI::smooth_with_creases(mesh, o.lambda ? *o.lambda : BI::taubin_default_lambda,
                          o.mu ? *o.mu : BI::taubin_default_mu,
                          CGAL::parameters::number_of_iterations(*o.smooth_iterations)
                              .edge_is_constrained_map(maps.edge_is_crease)
                              .vertex_is_constrained_map(maps.vertex_is_corner));
  for(const Surface_mesh::Vertex_index v : mesh.vertices())
    soup.points[std::size_t(v)] = mesh.point(v);
}

// The memory the process may still use: MemAvailable, or less under a
// limit on the address space; 0 when unknown.
double available_bytes()
{
  double available = 0;
  if(std::FILE* f = std::fopen("/proc/meminfo", "r"))
  {
    char line[256];
    while(std::fgets(line, sizeof line, f))
    {
      unsigned long long kb = 0;
      if(std::sscanf(line, "MemAvailable: %llu kB", &kb) == 1)
        available = double(kb) * 1024;
    }
    std::fclose(f);
  }
  rlimit limit;
  if(getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
     (available == 0 || double(limit.rlim_cur) < available))
    available = double(limit.rlim_cur);
  return available;
}

std::string gigabytes(double bytes)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

// Refuses, before allocating anything, a grid whose field values alone do not
// fit in memory: 8 bytes per vertex and field (in core), or per vertex of the
// slabs in flight (out of core).  The surface and the sign masks come on top,
// so this is a lower bound.
void check_grid_memory(const Options& o, std::size_t number_of_fields)
{
  const std::array<std::size_t, 3>& n = *o.grid;
  const double vertices = double(n[0]) * double(n[1]) * double(n[2]);
  const double fields = double(std::max<std::size_t>(1, number_of_fields));
  double values = vertices * fields;
  std::string what = std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) + " vertices";
  if(o.out_of_core)
  {
    const double slab = double(o.slab_layers ? o.slab_layers : 8) + 3;
    const double in_flight = 2 * std::max(1u, std::thread::hardware_concurrency());
    values = std::min(values, double(n[0]) * double(n[1]) * slab * fields * in_flight);
    what += " (out of core: the slabs in flight)";
  }
  const double needed = 8 * values;
  const double available = available_bytes();
  if(vertices > 1e18 || (available > 0 && needed > available))
    throw Error("--grid: " + what + " x " + std::to_string(std::size_t(fields)) + " field" + (fields == 1 ? "" : "s") +
                " need at least " + gigabytes(needed) + " for the field values, but only " + gigabytes(available) +
                " of memory are available (use a coarser grid" + (o.out_of_core ? ", or a smaller --slab-size)" : ", or --out-of-core with a raw --fields file)"));
}

struct Input
{
  std::optional<Grid> grid;
  std::optional<Tet_mesh> mesh;
  BI::Scalar_fields fields;
  BI::Boolean_expression expression;
};

std::size_t number_of_vertices(const Input& in)
{
  return in.grid ? in.grid->number_of_vertices() : in.mesh->number_of_vertices();
}

void print_domain(const Input& in, const Options& o, double seconds)
{
  if(in.grid)
  {
    const auto& n = in.grid->vertex_counts();
    const std::array<double, 6> b = o.box ? *o.box : std::array<double, 6>{-1, -1, -1, 1, 1, 1};
    std::printf("domain:     grid %zu x %zu x %zu vertices (%zu), %zu tetrahedra, box [%g, %g] x [%g, %g] x [%g, %g]\n",
                n[0], n[1], n[2], in.grid->number_of_vertices(), in.grid->number_of_tetrahedra(), b[0], b[3], b[1],
                b[4], b[2], b[5]);
  }
  else
    std::printf("domain:     tetrahedral mesh %s: %zu vertices, %zu tetrahedra (%zu boundary faces), read in %.3f s\n",
                o.mesh_file.c_str(), in.mesh->number_of_vertices(), in.mesh->number_of_tetrahedra(),
                in.mesh->number_of_boundary_faces(), seconds);
}

Input read_input(const Options& o, double& fields_seconds)
{
  Input in;
  // The expression first: a typo fails before any file is read.
  if(o.expression)
  {
    try
    {
      in.expression = BI::Boolean_expression::parse(*o.expression);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw Error(std::string("--expr: ") + e.what());
    }
  }
  if(o.grid && !o.mesh_file.empty())
    throw Error("give either --grid or --mesh, not both");
  if(o.box && !o.grid)
    throw Error("--box needs --grid");
  if(!o.grid && o.mesh_file.empty())
    throw Error("no domain: give --grid N or --mesh FILE (see tbiso --help)");
  if(!o.fields_file.empty() && !o.field_specs.empty())
    throw Error("give either --fields FILE or --field SPEC, not both");
  if(o.fields_file.empty() && o.field_specs.empty())
    throw Error("no fields given: use --fields FILE or --field SPEC");
  if(o.field_count != 0 && o.fields_file.empty())
    throw Error("--field-count is for --fields FILE");
  if(o.field_specs.size() > 64)
    throw Error("at most 64 fields are supported");
  if(o.grid)
    check_grid_memory(o, o.field_specs.empty() ? o.field_count : o.field_specs.size());
  auto start = std::chrono::steady_clock::now();
  if(o.grid)
  {
    const std::array<double, 6> b = o.box ? *o.box : std::array<double, 6>{-1, -1, -1, 1, 1, 1};
    in.grid.emplace(Grid::spanning(Point(b[0], b[1], b[2]), Point(b[3], b[4], b[5]), *o.grid));
  }
  else
  {
    try
    {
      in.mesh.emplace(BI::IO::read_tetrahedral_mesh<K>(o.mesh_file));
    }
    catch(const BI::Invalid_input_error& e)
    {
      // The mesh checks (conformity, orientation) do not know the file.
      const std::string message = e.what();
      throw Error(message.find(o.mesh_file) == std::string::npos ? "'" + o.mesh_file + "': " + message : message);
    }
  }
  print_domain(in, o, seconds_since(start));


  auto check_expression = [&](std::size_t number_of_fields) {
    if(!o.expression)
    {
      if(number_of_fields != 1)
        throw Error("--expr is required with " + std::to_string(number_of_fields) + " fields");
      in.expression = BI::Boolean_expression::parse("f0");
    }
    if(in.expression.number_of_variables() > number_of_fields)
      throw Error("the expression names field f" + std::to_string(in.expression.number_of_variables() - 1) +
                  " but there " + (number_of_fields == 1 ? "is only 1 field" : "are only " + std::to_string(number_of_fields) + " fields") +
                  " (f0 ... f" + std::to_string(number_of_fields - 1) + ")");
  };
  if(!o.field_specs.empty())
    check_expression(o.field_specs.size());

  start = std::chrono::steady_clock::now();
  if(!o.fields_file.empty())
  {
    in.fields = BI::IO::read_scalar_fields(o.fields_file, number_of_vertices(in), o.field_count);
    in.fields.check_finite();
    check_expression(in.fields.number_of_fields());
  }
  else
  {
    std::vector<Field> functions;
    for(const std::string& spec : o.field_specs)
      functions.push_back(make_field(spec));
    if(in.grid)
      in.fields = sample(number_of_vertices(in), functions, [&](std::size_t v) { return in.grid->point(v); }, o.parallel);
    else
      in.fields = sample(number_of_vertices(in), functions, [&](std::size_t v) { return in.mesh->point(v); }, o.parallel);
  }
  fields_seconds = seconds_since(start);
  return in;
}

int run(const Options& o)
{
  const auto total_start = std::chrono::steady_clock::now();
  double fields_seconds = 0;
  Input in = read_input(o, fields_seconds);
  if(o.fields_file.empty())
  {
    std::printf("fields:     %zu\n", in.fields.number_of_fields());
    for(std::size_t i = 0; i < o.field_specs.size(); ++i)
      std::printf("  f%zu = %s\n", i, o.field_specs[i].c_str());
  }
  else
    std::printf("fields:     %zu, read from %s\n", in.fields.number_of_fields(), o.fields_file.c_str());
  std::printf("expression: %s (%zu term%s)%s\n", in.expression.to_string().c_str(), in.expression.number_of_terms(),
              in.expression.number_of_terms() == 1 ? "" : "s", o.close ? ", closed at the domain boundary" : "");
  std::printf("time fields:     %.3f s (%s)\n", fields_seconds,
              o.fields_file.empty() ? "sampling" : "reading");
  std::fflush(stdout);

  Soup soup;
  auto start = std::chrono::steady_clock::now();
  const BI::Boolean_isosurface_statistics s =
      in.grid ? extract(*in.grid, in.fields, in.expression, soup, o) : extract(*in.mesh, in.fields, in.expression, soup, o);
  std::printf("time extraction: %.3f s (table %.3f s, extraction %.3f s, welding %.3f s; %zu of %zu tetrahedra evaluated%s)\n",
              seconds_since(start), s.table_seconds, s.extraction_seconds, s.welding_seconds,
              s.number_of_evaluated_tetrahedra, s.number_of_tetrahedra,
#ifdef CGAL_LINKED_WITH_TBB
              o.parallel ? ", parallel" : ", sequential"
#else
              ", sequential"
#endif
  );

  start = std::chrono::steady_clock::now();
  const BI::Crease_network creases = BI::extract_crease_network(soup);
  std::printf("time creases:    %.3f s\n", seconds_since(start));

  if(o.smooth_iterations)
  {
    start = std::chrono::steady_clock::now();
    smooth(soup, creases, o);
    std::printf("time smoothing:  %.3f s (%lld lambda|mu iterations, lambda %g, mu %g, creases and corners kept)\n",
                seconds_since(start), *o.smooth_iterations, o.lambda ? *o.lambda : BI::taubin_default_lambda,
                o.mu ? *o.mu : BI::taubin_default_mu);
  }

  start = std::chrono::steady_clock::now();
  std::vector<std::string> written;
  if(!o.output.empty())
  {
    if(has_extension(o.output, ".ply"))
      BI::IO::write_PLY_with_fields(o.output, soup);
    else
      BI::IO::write_OFF_polygons(o.output, soup);
    written.push_back(o.output);
  }
  if(!o.creases_file.empty())
  {
    BI::IO::write_polylines(o.creases_file, soup.points, creases);
    written.push_back(o.creases_file);
  }
  if(!o.corners_file.empty())
  {
    BI::IO::write_corners(o.corners_file, soup.points, creases);
    written.push_back(o.corners_file);
  }
  if(!written.empty())
    std::printf("time writing:    %.3f s\n", seconds_since(start));
  std::printf("time total:      %.3f s\n", seconds_since(total_start));

  std::size_t triangles = 0;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    triangles += poly.size() - 2;
  std::printf("output:     %zu vertices, %zu polygons (%zu triangles when fanned)\n", soup.points.size(),
              soup.polygons.size(), triangles);
  std::printf("creases:    %zu edges, %zu polylines, %zu corners\n", creases.number_of_crease_edges,
              creases.polylines.size(), creases.corners.size());
  const Edge_report edges = check_edges(soup);
  if(soup.polygons.empty())
    std::printf("surface:    empty\n");
  else if(edges.closed())
    std::printf("surface:    closed, volume %.15g%s\n", enclosed_volume(soup),
                o.smooth_iterations ? " (after smoothing)" : "");
  else
    std::printf("surface:    not closed (%zu border edges, %zu non-manifold edges, %zu inconsistent edges)%s\n",
                edges.border, edges.non_manifold, edges.inconsistent,
                o.close ? "" : "; --close closes it on the domain boundary");
  for(const std::string& file : written)
    std::printf("wrote %s\n", file.c_str());
  return 0;
}

double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

// Fields read one slab at a time from a raw file, the surface streamed to a
// binary PLY file: memory is a few slabs, whatever the grid size.
int run_out_of_core(const Options& o)
{
  const auto total_start = std::chrono::steady_clock::now();
  if(!o.grid || !o.mesh_file.empty())
    throw Error("--out-of-core needs --grid");
  const bool analytic = !o.field_specs.empty();
  const bool f32 = has_extension(o.fields_file, ".f32");
  if(analytic && !o.fields_file.empty())
    throw Error("give either --fields FILE or --field SPEC, not both");
  if(!analytic &&
     (o.fields_file.empty() || !(f32 || has_extension(o.fields_file, ".f64") || has_extension(o.fields_file, ".raw"))))
    throw Error("--out-of-core needs a raw --fields file (.f32, .f64 or .raw) or --field SPEC");
  if(!analytic && o.field_count == 0)
    throw Error("--out-of-core: give the number of fields with --field-count N");
  if(analytic && o.field_count != 0)
    throw Error("--field-count is for --fields FILE");
  if(o.field_specs.size() > 64)
    throw Error("at most 64 fields are supported");
  if(!has_extension(o.output, ".ply"))
    throw Error("--out-of-core writes the surface as it goes: give -o OUT.ply");
  if(!o.creases_file.empty() || !o.corners_file.empty() || o.smooth_iterations)
    throw Error("--out-of-core: --creases, --corners and --smooth need the whole surface in memory");
  const std::size_t field_count = analytic ? o.field_specs.size() : o.field_count;
  BI::Boolean_expression expression = BI::Boolean_expression::parse(o.expression ? *o.expression : "f0");
  if(expression.number_of_variables() > field_count)
    throw Error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                " but there are only " + std::to_string(field_count) + " fields");
  const std::array<double, 6> b = o.box ? *o.box : std::array<double, 6>{-1, -1, -1, 1, 1, 1};
  const Grid grid = Grid::spanning(Point(b[0], b[1], b[2]), Point(b[3], b[4], b[5]), *o.grid);
  Input in;
  in.grid.emplace(grid);
  print_domain(in, o, 0);
  // The fields: a raw file read slab by slab, or the functions evaluated slab
  // by slab (the same doubles as the in-core sampling).
  auto extract_to = [&](auto& source) {
    BI::IO::Boolean_isosurface_PLY_stream ply(o.output);
    const auto np = BI::parameters::close_at_domain_boundary(
        o.close,
        BI::parameters::progress(Progress_bar(), BI::parameters::slab_layers(o.slab_layers ? o.slab_layers : 8)));
    const BI::Boolean_isosurface_slab_statistics s =
        o.parallel
            ? BI::extract_boolean_isosurface_by_slabs<CGAL::Parallel_if_available_tag>(grid, source, expression, ply, np)
            : BI::extract_boolean_isosurface_by_slabs<CGAL::Sequential_tag>(grid, source, expression, ply, np);
    ply.close();
    return s;
  };
  auto print_expression = [&] {
    std::printf("expression: %s (%zu term%s)%s\n", expression.to_string().c_str(), expression.number_of_terms(),
                expression.number_of_terms() == 1 ? "" : "s", o.close ? ", closed at the domain boundary" : "");
    std::fflush(stdout);
  };
  check_grid_memory(o, field_count);
  const auto start = std::chrono::steady_clock::now();
  BI::Boolean_isosurface_slab_statistics s;
  if(analytic)
  {
    std::vector<Field> functions;
    for(const std::string& spec : o.field_specs)
      functions.push_back(make_field(spec));
    tbiso_fields::Analytic_field_source source(grid, std::move(functions));
    std::printf("fields:     %zu, evaluated slab by slab\n", field_count);
    for(std::size_t i = 0; i < o.field_specs.size(); ++i)
      std::printf("  f%zu = %s\n", i, o.field_specs[i].c_str());
    print_expression();
    s = extract_to(source);
  }
  else
  {
    BI::IO::Raw_scalar_field_reader reader(o.fields_file, grid.number_of_vertices(), o.field_count,
                                           f32 ? BI::IO::Raw_scalar_type::FLOAT32 : BI::IO::Raw_scalar_type::FLOAT64);
    std::printf("fields:     %zu, read slab by slab from %s\n", o.field_count, o.fields_file.c_str());
    print_expression();
    s = extract_to(reader);
  }
  std::printf("time extraction: %.3f s (%zu slabs of %zu layers; reading %.3f s, evaluation and reading %.3f s, "
              "welding and writing %.3f s; %zu of %zu tetrahedra evaluated%s)\n",
              seconds_since(start), s.number_of_slabs, o.slab_layers ? o.slab_layers : std::size_t(8), s.reading_seconds,
              s.extraction_seconds, s.welding_seconds, s.number_of_evaluated_tetrahedra, s.number_of_tetrahedra,
              o.parallel ? ", parallel" : ", sequential");
  std::printf("time total:      %.3f s\n", seconds_since(total_start));
  std::printf("output:     %zu vertices, %zu polygons\n", s.number_of_vertices, s.number_of_polygons);
  std::printf("memory:     %.1f MB of field values held at most, peak resident %.1f MB\n",
              double(s.peak_field_values) * 8 / 1e6, peak_resident_megabytes());
  std::printf("wrote %s\n", o.output.c_str());
  return 0;
}

int run_demo(Options o)
{
  if(o.grid || o.box || !o.mesh_file.empty() || !o.fields_file.empty() || !o.field_specs.empty() || o.expression ||
     !o.output.empty() || !o.creases_file.empty() || !o.corners_file.empty())
    throw Error("--demo sets its own domain, fields, expression and outputs");
  std::error_code ec;
  std::filesystem::create_directories(o.demo_dir, ec);
  if(ec || !std::filesystem::is_directory(o.demo_dir))
    throw Error("cannot create directory '" + o.demo_dir + "'");
  // Four spheres centred on the vertices of a regular tetrahedron; the set
  // of points inside at least two of them is the union of the six pairwise
  // lenses: creases where two spheres meet, corners where three do.
  const double a = 0.45 / std::sqrt(3.0), r = 0.62;
  const double centres[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  o.grid = std::array<std::size_t, 3>{128, 128, 128};
  for(const auto& c : centres)
  {
    char spec[128];
    std::snprintf(spec, sizeof spec, "sphere:%.17g,%.17g,%.17g,%.17g", c[0], c[1], c[2], r);
    o.field_specs.push_back(spec);
  }
  o.expression = "f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3";
  o.output = o.demo_dir + "/tbiso_demo.ply";
  o.creases_file = o.demo_dir + "/tbiso_demo_creases.polylines.txt";
  o.corners_file = o.demo_dir + "/tbiso_demo_corners.xyz";
  std::printf("TBISO demo: the points inside at least two of four spheres (radius %g, centres at the\n"
              "vertices of a regular tetrahedron), on a 128^3 grid over [-1, 1]^3\n",
              r);
  return run(o);
}

} // namespace

#ifdef BISO_WITH_MPI
int tbiso_distributed_main(int argc, char** argv); // tbiso_distributed.cpp
#endif

int main(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--distributed")
    {
#ifdef BISO_WITH_MPI
      return tbiso_distributed_main(argc, argv);
#else
      std::cerr << "tbiso: error: --distributed: this tbiso was built without MPI\n";
      return 1;
#endif
    }
  try
  {
    Options options;
    if(!parse_arguments(argc, argv, options))
    {
      std::cout << usage_text;
      return 0;
    }
    if(argc == 1)
      throw Error("nothing to do (see tbiso --help, or try tbiso --demo DIR)");
#ifdef CGAL_LINKED_WITH_TBB
    std::optional<tbb::global_control> limit;
    if(options.threads > 0)
      limit.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
#endif
    // Output paths are checked before any computation, so that an unwritable
    // one costs a second, not the whole extraction.
    for(const std::string* path : {&options.output, &options.creases_file, &options.corners_file})
      if(!path->empty())
        biso_tools::check_output_file(*path);
    if(!options.demo_dir.empty())
      return run_demo(options);
    if(options.out_of_core)
      return run_out_of_core(options);
    return run(options);
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "tbiso: error: out of memory (use a coarser grid)\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "tbiso: error: " << e.what() << "\n";
  }
  return 1;
}
