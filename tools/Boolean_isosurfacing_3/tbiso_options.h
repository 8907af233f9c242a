// tbiso's command line: its options on the shared layer (cli.h), their
// conversion, and every check that needs only the command line, so that a
// usage error (exit 2) comes before any file is read.

#ifndef BISO_TOOLS_TBISO_OPTIONS_H
#define BISO_TOOLS_TBISO_OPTIONS_H

#include "cli.h"
#include "tbiso_fields.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tbiso_tool {

namespace BI = CGAL::Boolean_isosurfacing;
using biso_tools::Tool;
using biso_tools::Usage_error;

struct Options
{
  std::optional<std::array<std::size_t, 3>> grid; // vertex counts
  std::string lattice_flag;                       // "--cells", "--spacing" or "--grid", for messages
  std::optional<std::array<double, 6>> box;
  std::string mesh_file, fields_file;
  std::size_t field_count = 0;
  std::vector<std::string> field_specs;
  std::optional<std::string> expression;
  bool close = false;
  bool parallel = true;
  bool quiet = false;
  std::size_t slab_layers = 0;
  bool out_of_core = false;
  std::optional<long long> smooth_iterations;
  std::optional<double> lambda, mu;
  std::string output, creases_file, corners_file, demo_dir;

  std::array<double, 6> domain_box() const { return box ? *box : std::array<double, 6>{-1, -1, -1, 1, 1, 1}; }
};

const char* const description =
    "tbiso: the boundary of the regularized Boolean set EXPR(f0, f1, ...) where the literal fi is the region\n"
    "f_i < 0, for scalar fields sampled at the vertices of a tetrahedral domain (TBISO), with its crease\n"
    "polylines and corners.\n"
    "usage: tbiso ((--cells N | --cells NX,NY,NZ | --spacing h) [--box X0,Y0,Z0,X1,Y1,Z1] | --mesh FILE)\n"
    "             (--fields FILE [--field-count N] | --field SPEC [--field SPEC ...])\n"
    "             [--expr TEXT] [--close] [--smooth [ITER] [--lambda L] [--mu M]]\n"
    "             [-o OUT.ply|.off|.obj|.stl] [--creases FILE] [--corners FILE] [--slab-size LAYERS] [--out-of-core]\n"
    "       tbiso --demo DIR\n"
    "field SPECs (f0, f1, ... in order):\n"
    "  sphere:CX,CY,CZ,R          |p - c| - R\n"
    "  plane:A,B,C,D              A x + B y + C z + D\n"
    "  box:X0,Y0,Z0,X1,Y1,Z1      signed distance to the box\n"
    "  cylinder:AXIS,C1,C2,R      infinite cylinder, AXIS x|y|z, (C1,C2) its centre in the other axes\n"
    "  torus:R,r                  torus around the z axis at the origin\n"
    "  distance:MESHFILE          signed distance to a closed triangle mesh (OFF/OBJ/PLY/STL), negative inside\n";

// The options' text, converted and checked once parsed.
struct Option_text
{
  std::string cells, spacing, grid, box, field_count, slab_layers, smooth, lambda, mu;
};

inline void add_options(Tool& tool, Options& o, Option_text& t)
{
  CLI::App& app = tool.app();
  biso_tools::add_lattice_options(app, t.cells, t.spacing, "--box",
                                  "a regular grid of N cells along the longest side of --box (the other axes in "
                                  "proportion), or NX,NY,NZ cells; 6 tetrahedra per cube");
  // The old flag: vertex counts (N = cells + 1), kept for scripts.
  app.add_option("--grid", t.grid)->group("");
  app.add_option("--box", t.box, "extent of the grid (default -1,-1,-1,1,1,1)")->type_name("X0,Y0,Z0,X1,Y1,Z1");
  app.add_option("--mesh", o.mesh_file, "tetrahedral mesh: Medit .mesh or TetGen .node/.ele")->type_name("FILE");
  app.add_option("--fields", o.fields_file,
                 "values at the domain vertices: .f64/.raw (float64) or .f32 raw binary, vertex-major (needs "
                 "--field-count N); any other: text")
      ->type_name("FILE");
  app.add_option("--field-count", t.field_count, "the number of fields of a raw --fields file")->type_name("N");
  app.add_option("--field", o.field_specs, "an analytic field (see the SPECs above), repeatable")
      ->type_name("SPEC")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  tool.allow_repeated("--field");
  app.add_option("--expr", o.expression, "e.g. \"f0 & !f1 | f2\" (default f0 for one field)")->type_name("TEXT");
  app.add_flag("--close", o.close, "close the set on the boundary of the domain");
  app.add_option("--smooth", t.smooth,
                 "Taubin lambda|mu smoothing keeping creases and corners (default 10 iterations); the surface "
                 "must be manifold")
      ->type_name("[ITER]")
      ->expected(0, 1);
  app.add_option("--lambda", t.lambda, "smoothing factor (default 0.6307)")->type_name("L");
  app.add_option("--mu", t.mu, "smoothing factor (default -0.6732)")->type_name("M");
  app.add_option("-o,--output", o.output, "the surface: .ply (with field labels and colours), .off, .obj or .stl")
      ->type_name("FILE");
  app.add_option("--creases", o.creases_file, "crease polylines (CGAL polylines text format)")->type_name("FILE");
  app.add_option("--corners", o.corners_file, "corners, one 'x y z' line each")->type_name("FILE");
  app.add_option("--slab-size", t.slab_layers,
                 "cube layers per slab along z, the unit of parallel work on a grid (default: about 1/64 of the "
                 "grid in core, 8 out of core)")
      ->type_name("LAYERS");
  app.add_flag("--out-of-core", o.out_of_core,
               "grid + raw --fields file (or --field SPECs) + -o OUT.ply: read (or evaluate) the fields one slab "
               "at a time and stream the surface to the file (no --creases, --corners or --smooth)");
  app.add_option("--demo", o.demo_dir,
                 "four spheres on a 128^3 grid, 'at least two of four'; writes DIR/tbiso_demo.ply, "
                 "DIR/tbiso_demo_creases.polylines.txt, DIR/tbiso_demo_corners.xyz")
      ->type_name("DIR");
  app.add_flag("--distributed", "under mpirun, split the grid over the ranks (doc: distributed.md)");
}

// The vertex counts of the grid that --cells TEXT asks for over `box`.
inline std::array<std::size_t, 3> grid_for_cells(const std::string& text, const std::array<double, 6>& box)
{
  const std::vector<std::string> parts = tbiso_fields::split(text, ',');
  if(parts.size() != 1 && parts.size() != 3)
    throw Usage_error("--cells: expected N or NX,NY,NZ, got " + biso_tools::quote_arg(text));
  const std::size_t limit = std::size_t(1) << 40;
  std::array<std::size_t, 3> n;
  if(parts.size() == 3)
  {
    for(int a = 0; a < 3; ++a)
      n[a] = biso_tools::parse_count("--cells", parts[a], 1, limit, "far beyond any memory") + 1;
    return n;
  }
  const std::size_t cells = biso_tools::parse_count("--cells", parts[0], 1, limit, "far beyond any memory");
  const double longest = std::max({box[3] - box[0], box[4] - box[1], box[5] - box[2]});
  for(int a = 0; a < 3; ++a)
    n[a] = std::max<std::size_t>(1, std::size_t(std::llround(double(cells) * (box[a + 3] - box[a]) / longest))) + 1;
  return n;
}

// The vertex counts of the grid of cells of side at most h over `box`.
inline std::array<std::size_t, 3> grid_for_spacing(const std::string& text, const std::array<double, 6>& box)
{
  const double h = biso_tools::parse_real("--spacing", text, biso_tools::Sign_rule::POSITIVE);
  std::array<std::size_t, 3> n;
  for(int a = 0; a < 3; ++a)
  {
    const double cells = std::ceil((box[a + 3] - box[a]) / h);
    if(!(cells < double(std::size_t(1) << 40)))
      throw Usage_error("--spacing " + text + " gives more than 2^40 cells per axis");
    n[a] = std::max<std::size_t>(1, std::size_t(cells)) + 1;
  }
  return n;
}

// The old --grid N | NX,NY,NZ: vertex counts.
inline std::array<std::size_t, 3> grid_for_vertices(const std::string& text)
{
  const std::vector<std::string> parts = tbiso_fields::split(text, ',');
  if(parts.size() != 1 && parts.size() != 3)
    throw Usage_error("--grid: expected N or NX,NY,NZ, got " + biso_tools::quote_arg(text));
  std::array<std::size_t, 3> n;
  for(int a = 0; a < 3; ++a)
    n[a] = biso_tools::parse_count("--grid", parts[parts.size() == 1 ? 0 : a], 2, std::size_t(1) << 40,
                                   "far beyond any memory");
  return n;
}

inline void check_domain(const CLI::App& app, Options& o, const Option_text& t)
{
  if(app.count("--box"))
  {
    const std::vector<double> b = tbiso_fields::parse_numbers(t.box, 6, "--box");
    for(int a = 0; a < 3; ++a)
      if(!(b[a] < b[a + 3]))
        throw Usage_error("--box: the minimum must be below the maximum on every axis");
    o.box = std::array<double, 6>{b[0], b[1], b[2], b[3], b[4], b[5]};
  }
  const std::size_t lattice_flags = app.count("--cells") + app.count("--spacing") + app.count("--grid");
  if(lattice_flags > 1)
    throw Usage_error("give only one of --cells and --spacing");
  if(app.count("--cells"))
    o.grid = grid_for_cells(t.cells, o.domain_box()), o.lattice_flag = "--cells";
  else if(app.count("--spacing"))
    o.grid = grid_for_spacing(t.spacing, o.domain_box()), o.lattice_flag = "--spacing";
  else if(app.count("--grid"))
    o.grid = grid_for_vertices(t.grid), o.lattice_flag = "--grid";
  if(o.grid && !o.mesh_file.empty())
    throw Usage_error("give either --cells (a grid) or --mesh, not both");
  if(o.box && !o.grid)
    throw Usage_error("--box needs a grid (--cells or --spacing)");
  if(!o.grid && o.mesh_file.empty() && o.demo_dir.empty())
    throw Usage_error("no domain: give --cells N or --mesh FILE (see tbiso --help)");
}

// The analytic specs are parsed here (a typo is a usage error); a
// distance:MESHFILE spec reads its file later, as a run-time step.
inline void check_fields(const CLI::App& app, Options& o, const Option_text& t)
{
  if(!o.fields_file.empty() && !o.field_specs.empty())
    throw Usage_error("give either --fields FILE or --field SPEC, not both");
  if(o.fields_file.empty() && o.field_specs.empty() && o.demo_dir.empty())
    throw Usage_error("no fields given: use --fields FILE or --field SPEC");
  if(app.count("--field-count"))
  {
    o.field_count = biso_tools::parse_count("--field-count", t.field_count, 1, 64, "at most 64 fields are supported");
    if(o.fields_file.empty())
      throw Usage_error("--field-count is for --fields FILE");
  }
  if(o.field_specs.size() > 64)
    throw Usage_error("at most 64 fields are supported");
  for(const std::string& spec : o.field_specs)
    if(spec.rfind("distance:", 0) != 0)
      tbiso_fields::make_field(spec);
}

// The expression parses, and names no more fields than the specs give.
inline void check_expression(const Options& o)
{
  if(!o.expression)
  {
    if(o.field_specs.size() > 1)
      throw Usage_error("--expr is required with " + std::to_string(o.field_specs.size()) + " fields");
    return;
  }
  BI::Boolean_expression e;
  try
  {
    e = BI::Boolean_expression::parse(*o.expression);
  }
  catch(const BI::Invalid_input_error& error)
  {
    throw Usage_error(std::string("--expr: ") + error.what());
  }
  const std::size_t n = o.field_specs.size();
  if(n > 0 && e.number_of_variables() > n)
    throw Usage_error("the expression names field f" + std::to_string(e.number_of_variables() - 1) + " but there " +
                      (n == 1 ? "is only 1 field" : "are only " + std::to_string(n) + " fields") + " (f0 ... f" +
                      std::to_string(n - 1) + ")");
}

inline void check_smoothing(const CLI::App& app, Options& o, const Option_text& t)
{
  if(app.count("--smooth"))
    o.smooth_iterations = t.smooth.empty() ? BI::taubin_default_number_of_iterations
                                           : (long long)biso_tools::parse_count("--smooth", t.smooth, 0, 1000000,
                                                                                "a million iterations");
  if(app.count("--lambda"))
    o.lambda = tbiso_fields::parse_double(t.lambda, "--lambda");
  if(app.count("--mu"))
    o.mu = tbiso_fields::parse_double(t.mu, "--mu");
  if((o.lambda || o.mu) && !o.smooth_iterations)
    throw Usage_error("--lambda and --mu need --smooth");
}

inline void check_out_of_core(const Options& o)
{
  if(!o.out_of_core)
    return;
  if(!o.grid)
    throw Usage_error("--out-of-core needs a grid (--cells or --spacing)");
  const std::string e = biso_tools::extension(o.fields_file);
  if(o.field_specs.empty() && !(e == "f32" || e == "f64" || e == "raw"))
    throw Usage_error("--out-of-core needs a raw --fields file (.f32, .f64 or .raw) or --field SPEC");
  if(o.field_specs.empty() && o.field_count == 0)
    throw Usage_error("--out-of-core: give the number of fields with --field-count N");
  if(biso_tools::extension(o.output) != "ply")
    throw Usage_error("--out-of-core writes the surface as it goes: give -o OUT.ply");
  if(!o.creases_file.empty() || !o.corners_file.empty() || o.smooth_iterations)
    throw Usage_error("--out-of-core: --creases, --corners and --smooth need the whole surface in memory");
}

inline void check_options_text(Tool& tool, Options& o, const Option_text& t)
{
  const CLI::App& app = tool.app();
  o.parallel = tool.parallel();
  o.quiet = tool.quiet();
  if(!tool.positionals().empty())
    throw Usage_error("unexpected argument " + biso_tools::quote_arg(tool.positionals()[0]) +
                      " (tbiso --help for usage)");
  if(app.count("--demo"))
  {
    if(o.demo_dir.empty())
      throw Usage_error("--demo needs a directory, got an empty argument");
    for(const char* flag : {"--cells", "--spacing", "--grid", "--box", "--mesh", "--fields", "--field", "--expr",
                            "--output", "--creases", "--corners"})
      if(app.count(flag))
        throw Usage_error("--demo sets its own domain, fields, expression and outputs");
    return;
  }
  if(app.count("--output"))
    biso_tools::check_mesh_extension("-o", o.output);
  if(app.count("--slab-size"))
    o.slab_layers = biso_tools::parse_count("--slab-size", t.slab_layers, 1, std::size_t(1) << 40, "too large");
  check_domain(app, o, t);
  check_fields(app, o, t);
  check_expression(o);
  check_smoothing(app, o, t);
  check_out_of_core(o);
}

/// Converts and checks the command line.  \throws Usage_error.
inline void check_options(Tool& tool, Options& o, const Option_text& t)
{
  try
  {
    check_options_text(tool, o, t);
  }
  catch(const tbiso_fields::Error& e) // the number and spec parsers of tbiso_fields.h
  {
    throw Usage_error(e.what());
  }
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_OPTIONS_H
