// csg: Boolean operations on closed triangle meshes by Marching Cubes.
//
//   csg A B --op union|intersection|difference (--cells N | --spacing r) [-o out.off]
//   csg A B C ... --expr "A & !B | C" (--cells N | --spacing r) [-o out.off]
//   csg --demo DIR
//   [--no-features] [--feature-angle DEG] [--creases F] [--corners F] [--strict]
//
// Reads OFF/OBJ/PLY/STL; the i-th input is the variable A, B, C, ... of the
// expression (also f0, f1, ...).  Prints the lattice size, the time of each
// stage, the output size and the output's Surveyor volume.  `csg --help`
// lists the options.  Sharp creases and corners are on by default
// (doc/Boolean_isosurfacing_3/features.md).  Input components the lattice
// does not resolve (and empty results) get a warning naming them and the
// --cells that would resolve them; --strict makes that an error.  Exit
// status: 0, 1 for a bad file, a failed computation or (--strict) an
// unresolved input, 2 for a bad command line; every error is one line on
// stderr.

#include "tool_support.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using biso_tools::Usage_error;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

// What to do with a result that is true outside every input ("!A").
enum class Unbounded_mode
{
  BOX,    // intersect it with a box around the inputs: a closed, outward solid
  SURFACE // keep the inputs' surfaces only: closed, inward-oriented (it bounds the complement)
};

struct Options
{
  std::vector<std::string> files;
  std::string op, expression, output, demo_dir;
  bool have_op = false, have_expression = false;
  std::size_t cells = 0;
  double spacing = 0;
  std::string lattice_flag; // "--cells N" or "--spacing r", for messages
  double max_memory_gib = 0; // 0: the default
  Unbounded_mode unbounded = Unbounded_mode::BOX;
  bool parallel = true;
  bool features = true;
  double feature_angle = 30;
  std::string creases_file, corners_file;
  bool strict = false;
};

const char* help_text =
    "csg: Boolean operations on closed triangle meshes by Marching Cubes\n"
    "usage: csg A B --op union|intersection|difference (--cells N | --spacing r) [options]\n"
    "       csg A B C ... --expr \"A & !B | C\" (--cells N | --spacing r) [options]\n"
    "       csg --demo DIR [--cells N | --spacing r]\n"
    "inputs: closed triangle meshes (OFF, OBJ, PLY, STL); the i-th is variable A, B, C, ... (or f0, f1, ...).\n"
    "  Their orientation does not matter (a lattice point is inside a mesh by the parity of its crossings):\n"
    "  an inward-oriented input is used as the solid it bounds, with a note on stderr.\n"
    "options:\n"
    "  --op OP          union, intersection or difference (A & !B)\n"
    "  --expr E         a Boolean expression of the inputs: ! (not), & (and), | (or), - (difference),\n"
    "                   parentheses, true, false\n"
    "  --cells N        N lattice cells along the longest side of the inputs' bounding box\n"
    "  --spacing r      the lattice spacing\n"
    "  -o, --output F   write the result to F (.off, .obj, .ply or .stl), checked before computing\n"
    "  --unbounded box|surface\n"
    "                   a result that is true outside every input (\"!A\", \"!(A | B)\", \"A | !A\") is unbounded:\n"
    "                   box (default): clip it to the box one lattice cell larger than the inputs'\n"
    "                     bounding box on every side and close it with the box's faces (a closed,\n"
    "                     outward solid, whose volume is printed; \"A | !A\" gives the box itself);\n"
    "                   surface: keep only the inputs' surfaces (closed and inward-oriented, bounding\n"
    "                     the complement, whose volume is printed)\n"
    "  --no-features    plain Marching Cubes (default: sharp creases and corners, Extended Marching Cubes\n"
    "                   on the exact crossing normals)\n"
    "  --feature-angle DEG\n"
    "                   a cube whose crossing normals differ by more than DEG degrees gets a feature\n"
    "                   vertex (default 30, in (0, 180))\n"
    "  --creases F      write the crease edges as polylines (CGAL polylines text format)\n"
    "  --corners F      write the corners, one 'x y z' line each\n"
    "  --strict         an input component the lattice does not resolve (no lattice point inside, or\n"
    "                   a lattice volume off by more than a factor 2), or an empty result from\n"
    "                   non-empty inputs, is an error (exit 1, nothing written) instead of a warning\n"
    "  --max-memory G   refuse a lattice estimated to need more than G GiB (default 8, at most 3/4 of the RAM)\n"
    "  --sequential     one thread (default: parallel when built with TBB; the same mesh)\n"
    "  --distributed    under mpirun, split the lattice over the ranks (needs --no-features)\n"
    "  -h, --help       this help\n"
    "exit status: 0 success, 1 bad input file or failed computation, 2 bad command line\n";

// A progress bar on stderr, only for runs that last and only on a terminal.
class Progress_bar
{
public:
  void operator()(double fraction) const
  {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if(seconds < 1.0 || !isatty(2)) return;
    const int width = 40, done = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(done, '#').c_str(), std::string(width - done, ' ').c_str(),
                 int(fraction * 100 + 0.5));
    if(fraction >= 1.0) std::fprintf(stderr, "\r%*s\r", width + 8, "");
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// The expression the command line asks for, over `number_of_meshes`
// variables.  \throws Usage_error: it is a command-line problem.
BI::Boolean_expression expression_from(const Options& options, std::size_t number_of_meshes)
{
  if(options.have_expression)
  {
    BI::Boolean_expression parsed;
    try
    {
      parsed = BI::Boolean_expression::parse(options.expression);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw Usage_error(std::string("--expr: ") + e.what());
    }
    if(parsed.number_of_variables() > number_of_meshes)
      throw Usage_error("--expr names " + std::to_string(parsed.number_of_variables()) + " inputs but " +
                        std::to_string(number_of_meshes) + " files were given");
    return BI::Boolean_expression(number_of_meshes, parsed.terms());
  }
  if(number_of_meshes != 2)
    throw Usage_error("--op needs exactly two input files, got " + std::to_string(number_of_meshes) +
                      " (use --expr for more)");
  if(options.op == "union") return BI::Boolean_expression::union_of(2);
  if(options.op == "intersection") return BI::Boolean_expression::intersection_of(2);
  if(options.op == "difference") return BI::Boolean_expression::difference();
  throw Usage_error("--op: unknown operation " + biso_tools::quote_arg(options.op) +
                    " (union, intersection or difference)");
}

// `expression & X`, X a new last variable: the result clipped to the solid X.
BI::Boolean_expression and_with_new_variable(const BI::Boolean_expression& expression)
{
  const std::size_t n = expression.number_of_variables();
  if(n + 1 > BI::Boolean_expression::max_variables)
    throw BI::Invalid_input_error("the result is unbounded and " + std::to_string(n) +
                                  " inputs leave no variable for the clipping box: use --unbounded surface");
  std::vector<BI::Boolean_term> terms = expression.terms();
  for(BI::Boolean_term& t : terms)
    t.pos |= std::uint64_t(1) << n;
  return BI::Boolean_expression(n + 1, std::move(terms));
}

// The closed, outward triangulated box [lo, hi].
Mesh box_mesh(const std::array<double, 3>& lo, const std::array<double, 3>& hi)
{
  Mesh m;
  std::array<Mesh::Vertex_index, 8> v;
  // Corner k at (k & 1, (k >> 1) & 1, (k >> 2) & 1).
  for(int k = 0; k < 8; ++k)
    v[k] = m.add_vertex(Point((k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]));
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for(const auto& f : faces)
    m.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return m;
}

struct Result
{
  Mesh mesh;
  BI::Marching_cubes_csg_statistics statistics;
  BI::Regular_lattice_3 lattice;
  BI::Crease_network creases; // vertex indices of `mesh`
};

std::size_t max_memory_bytes(const Options& options)
{
  if(options.max_memory_gib > 0)
    return std::size_t(options.max_memory_gib * double(std::size_t(1) << 30));
  // The library's default, unless this machine has less: refusing with an
  // estimate beats being killed half-way.
  std::size_t limit = BI::Lattice_classifier_3::default_max_memory_bytes;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if(pages > 0 && page_size > 0)
    limit = (std::min)(limit, std::size_t(double(pages) * double(page_size) * 0.75));
  return limit;
}

// `e`'s message, with the named parameter the library suggests replaced by
// this tool's flag, prefixed by the lattice flag that caused it.
std::string lattice_message(const Options& options, const BI::Lattice_too_large_error& e)
{
  std::string message = e.what();
  const std::string parameter = "(named parameter max_memory_bytes)";
  const std::size_t at = message.find(parameter);
  if(at != std::string::npos)
    message.replace(at, parameter.size(), "(--max-memory)");
  return options.lattice_flag.empty() ? message : options.lattice_flag + ": " + message;
}

CGAL::Bbox_3 bounding_box(const std::vector<Mesh>& meshes)
{
  CGAL::Bbox_3 box;
  for(const Mesh& m : meshes) box += PMP::bbox(m);
  return box;
}

// The crease edges (vertex pairs) chained into polylines between corners,
// branch points and ends; a closed crease repeats its first vertex.
BI::Crease_network crease_polylines(std::size_t number_of_vertices, const std::vector<std::array<std::size_t, 2>>& edges,
                                    const std::vector<std::size_t>& corners)
{
  BI::Crease_network network;
  network.corners = corners;
  network.number_of_crease_edges = edges.size();
  std::vector<std::vector<std::size_t>> incident(number_of_vertices);
  for(std::size_t e = 0; e < edges.size(); ++e)
    for(std::size_t v : edges[e])
      incident[v].push_back(e);
  std::vector<bool> is_corner(number_of_vertices, false), used(edges.size(), false);
  for(std::size_t v : corners)
    is_corner[v] = true;
  auto is_end = [&](std::size_t v) { return is_corner[v] || incident[v].size() != 2; };
  auto walk = [&](std::size_t v, std::size_t e) {
    std::vector<std::size_t> line{v};
    while(!used[e])
    {
      used[e] = true;
      v = edges[e][0] == v ? edges[e][1] : edges[e][0];
      line.push_back(v);
      if(is_end(v))
        break;
      e = incident[v][0] == e ? incident[v][1] : incident[v][0];
    }
    network.polylines.push_back(std::move(line));
  };
  for(std::size_t v = 0; v < number_of_vertices; ++v)
    if(is_end(v))
      for(std::size_t e : incident[v])
        if(!used[e])
          walk(v, e);
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(!used[e])
      walk(edges[e][0], e); // a closed loop without corner
  return network;
}

// The lattice encloses `box` (the inputs' bounding box) with `margin_cells`;
// the library's default lattice keeps the box's faces off the lattice planes.
Result run_csg(const std::vector<Mesh>& meshes, const BI::Boolean_expression& expression, const Options& options,
               const CGAL::Bbox_3& box, std::size_t margin_cells = 1)
{
  const BI::Regular_lattice_3 lattice =
      options.cells > 0 ? BI::Regular_lattice_3::enclosing_with_cells(box, options.cells, margin_cells)
                        : BI::Regular_lattice_3::enclosing(box, options.spacing, margin_cells);
  Mesh output;
  auto crease = output.add_property_map<Mesh::Edge_index, bool>("e:csg_crease", false).first;
  auto corner = output.add_property_map<Mesh::Vertex_index, bool>("v:csg_corner", false).first;
  const Progress_bar progress;
  BI::Marching_cubes_csg_statistics statistics;
  const auto np =
      BI::parameters::sharp_features(
          options.features,
          BI::parameters::feature_angle(
              options.feature_angle,
              BI::parameters::max_memory_bytes(max_memory_bytes(options), BI::parameters::progress(progress))))
          .edge_is_constrained_map(crease)
          .vertex_is_constrained_map(corner);
#ifdef CGAL_LINKED_WITH_TBB
  if(options.parallel)
    statistics = BI::marching_cubes_csg<CGAL::Parallel_tag>(meshes, expression, lattice, output, np);
  else
#endif
    statistics = BI::marching_cubes_csg<CGAL::Sequential_tag>(meshes, expression, lattice, output, np);
  // A fresh Surface_mesh: vertex i is soup point i.
  std::vector<std::array<std::size_t, 2>> edges;
  std::vector<std::size_t> corners;
  for(const Mesh::Edge_index e : output.edges())
    if(crease[e])
      edges.push_back({{std::size_t(output.vertex(e, 0)), std::size_t(output.vertex(e, 1))}});
  for(const Mesh::Vertex_index v : output.vertices())
    if(corner[v])
      corners.push_back(std::size_t(v));
  BI::Crease_network creases = crease_polylines(output.number_of_vertices(), edges, corners);
  // Not part of the written mesh.
  output.remove_property_map(crease);
  output.remove_property_map(corner);
  return {std::move(output), std::move(statistics), lattice, std::move(creases)};
}

// The part of the result's volume in intervals of lattice lines that hold no
// lattice point (walls or gaps thinner than a cell), in percent.
double thin_result_percent(const BI::Marching_cubes_csg_statistics& s)
{
  return s.result_line_volume > 0 ? 100 * s.thin_result_volume / s.result_line_volume : 0;
}

void print_result(const Result& r)
{
  const auto& n = r.lattice.number_of_points();
  const auto& s = r.statistics;
  std::printf("  lattice %zu x %zu x %zu points (%zu), spacing %.6g\n", n[0], n[1], n[2], s.lattice_points,
              r.lattice.spacing());
  std::printf("  classification %.3f s, edge points %.3f s, triangulation %.3f s (%zu crossings)\n",
              s.seconds_classification, s.seconds_edges, s.seconds_triangulation, s.crossings);
  std::printf("  output %zu vertices, %zu triangles\n", std::size_t(r.mesh.number_of_vertices()),
              std::size_t(r.mesh.number_of_faces()));
  if(s.feature_vertices > 0 || s.plain_feature_polygons > 0)
    std::printf("  sharp features: %zu feature vertices (%zu corners), %zu crease edges in %zu polylines, "
                "%zu feature polygons kept plain, %zu short edges collapsed\n",
                s.feature_vertices, s.corner_vertices, s.crease_edges, r.creases.polylines.size(),
                s.plain_feature_polygons, s.collapsed_edges);
  std::printf("  resolution check: %zu input components, %zu not resolved by the lattice; %zu of %zu result "
              "intervals on lattice lines thinner than a cell (%.3g %% of the volume)\n",
              s.checked_components, s.under_resolved_components.size(), s.thin_result_intervals, s.result_intervals,
              thin_result_percent(s));
}

// The warnings about what the lattice missed: one line each, at most
// `limit` lines.  Returns their number (all of them, not only printed).
std::size_t resolution_warnings(const Result& r, const Options& options, const std::vector<Mesh>& meshes,
                                const CGAL::Bbox_3& box, const BI::Boolean_expression& requested)
{
  const char* level = options.strict ? "error: " : "warning: ";
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  std::size_t count = 0, printed = 0;
  const std::size_t limit = 10;
  for(const BI::Marching_cubes_csg_component_report& c : r.statistics.under_resolved_components)
  {
    if(c.mesh >= options.files.size())
      continue; // the clipping box
    ++count;
    if(printed == limit)
      continue;
    ++printed;
    const double cells = std::ceil(longest / c.suggested_spacing);
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s%s (%s) component %zu (%zu triangles, volume %.6g) is not resolved by the lattice: %s, "
                  "lattice volume %.6g; --cells %.0f (spacing %.6g) would resolve it",
                  level, options.files[c.mesh].c_str(), c.mesh < 26 ? std::string(1, char('A' + c.mesh)).c_str() : "",
                  c.component, c.triangles, c.volume,
                  c.crossings == 0 ? "it crosses no lattice edge"
                                   : (std::to_string(c.inside_points) + " lattice points inside").c_str(),
                  c.lattice_volume, cells, c.suggested_spacing);
    biso_tools::print_error("csg", text);
  }
  if(count > printed)
    biso_tools::print_error("csg", std::string(level) + std::to_string(count - printed) +
                                       " more input components are not resolved by the lattice");
  // An empty result from non-empty inputs is the answer only if the
  // expression is false wherever some inputs overlap; we cannot tell
  // cheaply, so it is never a plain success unless the expression is
  // false everywhere (A & !A).
  bool inputs_empty = true;
  for(std::size_t i = 0; i < options.files.size(); ++i)
    inputs_empty = inputs_empty && meshes[i].number_of_faces() == 0;
  if(r.mesh.number_of_faces() == 0 && !requested.evaluate(0) && !inputs_empty)
  {
    const std::size_t n = requested.number_of_variables();
    bool satisfiable = n > 20; // too many to enumerate: assume it can be true
    for(std::uint64_t m = 1; !satisfiable && m < (std::uint64_t(1) << n); ++m)
      satisfiable = requested.evaluate(m);
    if(satisfiable)
    {
      ++count;
      biso_tools::print_error("csg", std::string(level) +
                                         "the result is empty although the inputs are not: either the exact result "
                                         "is empty or the lattice is too coarse to see it");
    }
  }
  // Thin walls or gaps of the result itself (a difference of nearly
  // coincident solids), which the component check cannot see.  Above 2 %
  // the output is visibly wrong (hull-body - hull-mask: 8 % thin at 128
  // cells, 40 % of the volume lost); lines grazing a smooth surface give
  // about 1 % at 16-32 cells.  Not repeated when input components were
  // named already (their --cells suffices).
  const BI::Marching_cubes_csg_statistics& s = r.statistics;
  if(count == 0 && thin_result_percent(s) > 2 && s.thin_result_suggested_spacing > 0)
  {
    ++count;
    char text[512];
    std::snprintf(text, sizeof text,
                  "%sthe result has walls or gaps thinner than a lattice cell: %zu of %zu intervals of lattice lines "
                  "through it hold no lattice point (at least %.3g %% of its volume is missing or filled in); --cells %.0f "
                  "(spacing %.6g) would see most of them",
                  level, s.thin_result_intervals, s.result_intervals, thin_result_percent(s),
                  std::ceil(longest / s.thin_result_suggested_spacing), s.thin_result_suggested_spacing);
    biso_tools::print_error("csg", text);
  }
  return count;
}

double exact_volume(const CGAL::Surface_mesh<Epeck::Point_3>& m)
{
  return CGAL::to_double(CGAL::exact(PMP::volume(m)));
}

int run_demo(Options options)
{
  const std::string& dir = options.demo_dir;
  struct stat info;
  if(mkdir(dir.c_str(), 0755) != 0 && (errno != EEXIST || stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)))
    throw biso_tools::File_error(dir + ": cannot create the directory (" +
                                 (errno == EEXIST ? std::string("a file of that name exists") : std::strerror(errno)) + ")");
  biso_tools::check_output_file(dir + "/A_sphere.off");
  // The built-in pair: a sphere and a torus that cuts through it.
  std::vector<Mesh> meshes(2);
  BI::make_icosphere(meshes[0], Point(0, 0, 0), 1.0, 4);
  BI::make_torus(meshes[1], Point(0.9, 0, 0), 0.8, 0.35, 96, 48);
  CGAL::IO::write_polygon_mesh(dir + "/A_sphere.off", meshes[0], CGAL::parameters::stream_precision(17));
  CGAL::IO::write_polygon_mesh(dir + "/B_torus.off", meshes[1], CGAL::parameters::stream_precision(17));
  std::printf("Marching Cubes CSG of a sphere (A, %zu triangles) and a torus through it (B, %zu triangles),\n"
              "written with the results to %s/.  'exact' is the volume of the exact Boolean result\n"
              "of the same polyhedra (PMP corefinement with Epeck).\n\n",
              std::size_t(meshes[0].number_of_faces()), std::size_t(meshes[1].number_of_faces()), dir.c_str());

  typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
  Exact_mesh a, b;
  CGAL::copy_face_graph(meshes[0], a);
  CGAL::copy_face_graph(meshes[1], b);
  const std::pair<const char*, BI::Boolean_expression> operations[] = {
      {"union", BI::Boolean_expression::union_of(2)},
      {"intersection", BI::Boolean_expression::intersection_of(2)},
      {"difference", BI::Boolean_expression::difference()}};
  if(options.cells == 0 && options.spacing == 0) options.cells = 128;
  for(const auto& [name, expression] : operations)
  {
    Exact_mesh a_copy = a, b_copy = b, exact_result;
    const std::string op = name;
    if(op == "union") PMP::corefine_and_compute_union(a_copy, b_copy, exact_result);
    else if(op == "intersection") PMP::corefine_and_compute_intersection(a_copy, b_copy, exact_result);
    else PMP::corefine_and_compute_difference(a_copy, b_copy, exact_result);
    const double exact = exact_volume(exact_result);

    const Result r = run_csg(meshes, expression, options, bounding_box(meshes));
    const double ours = BI::surveyor_volume(r.mesh);
    std::printf("%s (%s)\n", name, expression.to_string().c_str());
    print_result(r);
    std::printf("  volume %.6f   exact %.6f   relative error %.2e\n\n", ours, exact, std::abs(ours - exact) / exact);
    CGAL::IO::write_polygon_mesh(dir + "/" + op + ".off", r.mesh, CGAL::parameters::stream_precision(17));
  }
  return 0;
}

std::string variable_name(std::size_t i)
{
  return i < 26 ? std::string(1, char('A' + i)) : "f" + std::to_string(i);
}

// Reads every input; an inward-oriented one is accepted with a note.
std::vector<Mesh> read_inputs(const std::vector<std::string>& files)
{
  std::vector<Mesh> meshes(files.size());
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    biso_tools::check_input_file(files[i]);
    try
    {
      BI::IO::read_closed_triangle_mesh(files[i], meshes[i], /* allow_inward = */ true);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw biso_tools::File_error(files[i] + ": " + e.what());
    }
    if(BI::surveyor_volume(meshes[i], BI::parameters::signed_volume(true)) < 0)
      biso_tools::print_error("csg", "note: " + files[i] + " (" + variable_name(i) +
                                         ") is oriented inward; the classification counts crossings, so it "
                                         "is used as the solid it bounds");
  }
  return meshes;
}

int run(const Options& options)
{
  if(options.files.empty()) throw Usage_error("no input file (csg --help for usage)");
  if(options.have_op == options.have_expression) throw Usage_error("give exactly one of --op and --expr");
  if((options.cells > 0) == (options.spacing > 0)) throw Usage_error("give exactly one of --cells N and --spacing r");
  const BI::Boolean_expression requested = expression_from(options, options.files.size());
  BI::Boolean_expression expression = requested;
  if(!options.output.empty()) biso_tools::check_output_file(options.output);
  for(const std::string* f : {&options.creases_file, &options.corners_file})
    if(!f->empty()) biso_tools::check_output_file(*f);

  std::vector<Mesh> meshes = read_inputs(options.files);

  // Outside every input all masks are 0, so the result is unbounded iff
  // the expression is true there.
  const bool unbounded = expression.evaluate(0);
  const bool clip = unbounded && options.unbounded == Unbounded_mode::BOX;
  std::array<double, 3> clip_lo{}, clip_hi{};
  std::size_t margin_cells = 1;
  const CGAL::Bbox_3 box = bounding_box(meshes);
  if(clip)
  {
    const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    const double spacing = options.cells > 0 ? longest / double(options.cells) : options.spacing;
    // The box one cell beyond the inputs, inside a lattice of two cells'
    // margin: its faces lie between lattice planes (the library's lattice is offset
    // by a fraction of a cell), so they come out flat.
    for(int a = 0; a < 3; ++a)
    {
      clip_lo[a] = box.min(a) - spacing;
      clip_hi[a] = box.max(a) + spacing;
    }
    meshes.push_back(box_mesh(clip_lo, clip_hi));
    expression = and_with_new_variable(expression);
    margin_cells = 2;
  }

  const auto start = std::chrono::steady_clock::now();
  std::optional<Result> result;
  try
  {
    result.emplace(run_csg(meshes, expression, options, box, margin_cells));
  }
  catch(const BI::Lattice_too_large_error& e)
  {
    throw BI::Invalid_input_error(lattice_message(options, e));
  }
  const Result& r = *result;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t unresolved = resolution_warnings(r, options, meshes, box, requested);
  const std::size_t inputs = options.files.size();
  std::printf("csg %s over %zu meshes\n", requested.to_string().c_str(), options.files.size());
  if(clip)
    std::printf("  the result is unbounded: clipped to the box [%.9g, %.9g, %.9g] - [%.9g, %.9g, %.9g]\n",
                clip_lo[0], clip_lo[1], clip_lo[2], clip_hi[0], clip_hi[1], clip_hi[2]);
  print_result(r);
  std::printf("  total %.3f s\n", seconds);
  if(r.mesh.number_of_faces() == 0)
    std::printf(unbounded && !clip ? "  the result is all of space (no surface)\n" : "  the result is empty\n");
  else if(unbounded && !clip)
    std::printf("  the result is unbounded: its surface is inward-oriented; the complement has volume %.9g\n",
                -BI::surveyor_volume(r.mesh, BI::parameters::signed_volume(true)));
  else
    std::printf("  volume %.9g\n", BI::surveyor_volume(r.mesh));
  if(unresolved > 0 && options.strict)
    return 1; // nothing written: the result is not trusted
  if(!options.output.empty() &&
     !CGAL::IO::write_polygon_mesh(options.output, r.mesh, CGAL::parameters::stream_precision(17)))
    throw biso_tools::File_error(options.output + ": cannot write");
  if(!options.creases_file.empty() || !options.corners_file.empty())
  {
    std::vector<Point> points(r.mesh.points().begin(), r.mesh.points().end());
    try
    {
      if(!options.creases_file.empty())
        BI::IO::write_polylines(options.creases_file, points, r.creases);
      if(!options.corners_file.empty())
        BI::IO::write_corners(options.corners_file, points, r.creases);
    }
    catch(const std::runtime_error& e)
    {
      throw biso_tools::File_error(e.what());
    }
  }
  return 0;
}

// Fills `options` from the command line.  \throws Usage_error.
void parse(int argc, char** argv, Options& options, bool& help)
{
  using biso_tools::quote_arg;
  std::set<std::string> seen;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool is_flag = arg.size() > 1 && arg[0] == '-';
    if(is_flag && arg != "--sequential" && !seen.insert(arg == "--output" ? "-o" : arg).second)
      throw Usage_error(biso_tools::printable(arg) + " is given more than once");
    auto value = [&](const char* what) -> std::string {
      if(i + 1 >= argc) throw Usage_error(arg + " needs " + what);
      const std::string v = argv[++i];
      if(v.empty()) throw Usage_error(arg + " needs " + what + ", got an empty argument");
      return v;
    };
    if(arg == "--op") { options.op = value("an operation (union, intersection or difference)"); options.have_op = true; }
    else if(arg == "--expr") { options.expression = value("an expression"); options.have_expression = true; }
    else if(arg == "-o" || arg == "--output")
    {
      options.output = value("a file name");
      const std::string e = biso_tools::extension(options.output);
      if(e != "off" && e != "obj" && e != "ply" && e != "stl")
        throw Usage_error(arg + ": " + quote_arg(options.output) + " has no supported extension (.off, .obj, .ply, .stl)");
    }
    else if(arg == "--demo") options.demo_dir = value("a directory");
    else if(arg == "--sequential") options.parallel = false;
    else if(arg == "--no-features") options.features = false;
    else if(arg == "--strict") options.strict = true;
    else if(arg == "--feature-angle")
    {
      options.feature_angle = biso_tools::parse_real(arg, value("an angle in degrees"), biso_tools::Sign_rule::POSITIVE);
      if(!(options.feature_angle < 180)) throw Usage_error("--feature-angle: the angle must be in (0, 180) degrees");
    }
    else if(arg == "--creases") options.creases_file = value("a file name");
    else if(arg == "--corners") options.corners_file = value("a file name");
    else if(arg == "--cells")
    {
      const std::string text = value("a number of cells");
      // Each axis of a lattice has fewer than 2^31 points; whether the whole
      // lattice fits is decided once the inputs' box is known.
      options.cells = biso_tools::parse_count(arg, text, 1, (std::size_t(1) << 31) - 8,
                                              "a lattice has at most 2^31 points");
      options.lattice_flag = "--cells " + text;
    }
    else if(arg == "--spacing")
    {
      const std::string text = value("a spacing");
      options.spacing = biso_tools::parse_real(arg, text, biso_tools::Sign_rule::POSITIVE);
      options.lattice_flag = "--spacing " + text;
    }
    else if(arg == "--max-memory")
      options.max_memory_gib = biso_tools::parse_real(arg, value("a size in GiB"), biso_tools::Sign_rule::POSITIVE);
    else if(arg == "--unbounded")
    {
      const std::string mode = value("box or surface");
      if(mode == "box") options.unbounded = Unbounded_mode::BOX;
      else if(mode == "surface") options.unbounded = Unbounded_mode::SURFACE;
      else throw Usage_error("--unbounded: " + quote_arg(mode) + " is neither box nor surface");
    }
    else if(arg == "-h" || arg == "--help") help = true;
    else if(is_flag) throw Usage_error("unknown option " + quote_arg(arg) + " (csg --help for usage)");
    else options.files.push_back(arg);
  }
  if(!options.demo_dir.empty() && (!options.files.empty() || options.have_op || options.have_expression ||
                                   !options.output.empty() || !options.creases_file.empty() ||
                                   !options.corners_file.empty()))
    throw Usage_error("--demo takes a directory and at most --cells or --spacing, no input file, --op, --expr or -o");
  if(options.cells > 0 && options.spacing > 0) throw Usage_error("give only one of --cells N and --spacing r");
  if(!options.features && (!options.creases_file.empty() || !options.corners_file.empty()))
    throw Usage_error("--creases and --corners need sharp features: drop --no-features");
}

} // namespace

#ifdef BISO_WITH_MPI
int csg_distributed_main(int argc, char** argv); // csg_distributed.cpp
#endif

int main(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--distributed")
    {
#ifdef BISO_WITH_MPI
      return csg_distributed_main(argc, argv);
#else
      std::cerr << "csg: --distributed: this csg was built without MPI\n";
      return 1;
#endif
    }
  Options options;
  try
  {
    bool help = false;
    parse(argc, argv, options, help);
    if(help)
    {
      std::cout << help_text;
      return 0;
    }
    if(!options.demo_dir.empty()) return run_demo(options);
    return run(options);
  }
  catch(const Usage_error& e)
  {
    biso_tools::print_error("csg", e.what());
    return 2;
  }
  catch(const std::bad_alloc&)
  {
    biso_tools::print_error("csg", "out of memory (use a coarser lattice)");
    return 1;
  }
  catch(const std::exception& e)
  {
    biso_tools::print_error("csg", e.what());
    return 1;
  }
}
