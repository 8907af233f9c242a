// csg's command line: its options on the shared layer (cli.h), their
// conversion and checks, and the expression they ask for.  Shared by csg.cpp
// and csg_distributed.cpp (`csg --distributed`), so the two parse alike.

#ifndef BISO_TOOLS_CSG_OPTIONS_H
#define BISO_TOOLS_CSG_OPTIONS_H

#include "cli.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <string>
#include <vector>

namespace csg_tool {

namespace BI = CGAL::Boolean_isosurfacing;
using biso_tools::Tool;
using biso_tools::Usage_error;


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
  bool quiet = false;
  // Post-processing (issue 17): --simplify [D] (D in cells, default 0.1),
  // --remesh [L] (L in the inputs' units, default the spacing).
  bool simplify = false, remesh = false;
  double simplify_cells = 0.1, remesh_length = 0;
  bool check_inputs = false; // --check-inputs: the self-intersection test too
};

const char* const description =
    "csg: Boolean operations on closed triangle meshes by Marching Cubes\n"
    "usage: csg A B --op union|intersection|difference (--cells N | --spacing h) [options]\n"
    "       csg A B C ... --expr \"A & !B | C\" (--cells N | --spacing h) [options]\n"
    "       csg --demo DIR [--cells N | --spacing h]\n"
    "inputs: closed triangle meshes (OFF, OBJ, PLY, STL); the i-th is variable A, B, C, ... (or f0, f1, ...).\n"
    "  Their orientation does not matter (a lattice point is inside a mesh by the parity of its crossings):\n"
    "  an inward-oriented input is used as the solid it bounds, with a note on stderr.\n";


// The expression the command line asks for, over `number_of_meshes`
// variables.  \throws Usage_error: it is a command-line problem.
inline BI::Boolean_expression expression_from(const Options& options, std::size_t number_of_meshes)
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


// The options' text, checked and converted once parsed.
struct Option_text
{
  std::string cells, spacing, feature_angle, max_memory, unbounded, simplify, remesh;
};

inline void add_options(Tool& tool, Options& o, Option_text& t)
{
  CLI::App& app = tool.app();
  app.add_option("--op", o.op, "union, intersection or difference (A & !B)")->type_name("OP");
  app.add_option("--expr", o.expression,
                 "a Boolean expression of the inputs: ! (not), & (and), | (or), - (difference), parentheses, "
                 "true, false")
      ->type_name("E");
  biso_tools::add_lattice_options(app, t.cells, t.spacing,
                                  "the box where the result can be (A & B: the two boxes' intersection, "
                                  "A & !B: A's box, a union: the union of the boxes)");
  app.add_option("-o,--output", o.output, "write the result to F (.off, .obj, .ply or .stl), checked before computing")
      ->type_name("F");
  app.add_option("--unbounded", t.unbounded,
                 "a result true outside every input (\"!A\", \"A | !A\") is unbounded; box (default): clip it to "
                 "the box one cell larger than the inputs' bounding box and close it (a closed, outward solid); "
                 "surface: keep only the inputs' surfaces (closed, inward-oriented, bounding the complement)")
      ->type_name("box|surface");
  app.add_flag("--no-features", "plain Marching Cubes (default: sharp creases and corners, Extended Marching Cubes "
                                "on the exact crossing normals)");
  app.add_option("--feature-angle", t.feature_angle,
                 "a cube whose crossing normals differ by more than DEG degrees gets a feature vertex (default 30, "
                 "in (0, 180))")
      ->type_name("DEG");
  app.add_option("--creases", o.creases_file, "write the crease edges as polylines (CGAL polylines text format)")
      ->type_name("F");
  app.add_option("--corners", o.corners_file, "write the corners, one 'x y z' line each")->type_name("F");
  app.add_option("--simplify", t.simplify,
                 "simplify the result by edge collapses keeping its creases and corners: moved triangles within "
                 "D cells of the extracted surface at 7 samples each, input vertices within 2 D of the result "
                 "(default 0.1)")
      ->expected(0, 1)
      ->type_name("[D]");
  app.add_option("--remesh", t.remesh,
                 "isotropic remeshing of the result towards edges of length L (default: the lattice spacing), "
                 "the creases and corners kept")
      ->expected(0, 1)
      ->type_name("[L]");
  app.add_flag("--check-inputs", o.check_inputs,
               "also test every input for self-intersections (exact, O(n log n)); overlapping shells of one input "
               "are always looked for");
  app.add_flag("--strict", o.strict,
               "an input component the lattice does not resolve (no lattice point inside, or a lattice volume off "
               "by more than a factor 2), or an empty result from non-empty inputs, is an error (exit 1, nothing "
               "written) instead of a warning");
  app.add_option("--max-memory", t.max_memory,
                 "refuse a lattice estimated to need more than G GiB (default 8, at most 3/4 of the RAM)")
      ->type_name("G");
  app.add_option("--demo", o.demo_dir, "write a sphere, a torus and their union, intersection and difference to DIR")
      ->type_name("DIR");
  app.add_flag("--distributed", "under mpirun, split the lattice over the ranks (needs --no-features)");
}

// Converts and checks the options' text.  \throws Usage_error.
inline void check_options(Tool& tool, Options& o, const Option_text& t)
{
  using biso_tools::quote_arg;
  const CLI::App& app = tool.app();
  o.files = tool.positionals();
  o.have_op = app.count("--op") > 0;
  o.have_expression = app.count("--expr") > 0;
  o.features = app.count("--no-features") == 0;
  o.parallel = tool.parallel();
  o.quiet = tool.quiet();
  if(app.count("--op") && o.op.empty())
    throw Usage_error("--op needs an operation (union, intersection or difference), got an empty argument");
  if(app.count("--output")) biso_tools::check_mesh_extension("-o", o.output);
  if(app.count("--demo") && o.demo_dir.empty()) throw Usage_error("--demo needs a directory, got an empty argument");
  if(app.count("--feature-angle"))
  {
    o.feature_angle = biso_tools::parse_real("--feature-angle", t.feature_angle, biso_tools::Sign_rule::POSITIVE);
    if(!(o.feature_angle < 180)) throw Usage_error("--feature-angle: the angle must be in (0, 180) degrees");
  }
  if(app.count("--cells"))
  {
    // Each axis of a lattice has fewer than 2^26 points; whether the whole
    // lattice fits is decided once the inputs' box is known.
    o.cells = biso_tools::parse_count("--cells", t.cells, 1, (std::size_t(1) << 26) - 8,
                                      "a lattice has fewer than 2^26 points along an axis");
    o.lattice_flag = "--cells " + t.cells;
  }
  if(app.count("--spacing"))
  {
    o.spacing = biso_tools::parse_real("--spacing", t.spacing, biso_tools::Sign_rule::POSITIVE);
    o.lattice_flag = "--spacing " + t.spacing;
  }
  if(app.count("--max-memory"))
    o.max_memory_gib = biso_tools::parse_real("--max-memory", t.max_memory, biso_tools::Sign_rule::POSITIVE);
  if(app.count("--unbounded"))
  {
    if(t.unbounded == "box") o.unbounded = Unbounded_mode::BOX;
    else if(t.unbounded == "surface") o.unbounded = Unbounded_mode::SURFACE;
    else throw Usage_error("--unbounded: " + quote_arg(t.unbounded) + " is neither box nor surface");
  }
  if(!o.demo_dir.empty() && (!o.files.empty() || o.have_op || o.have_expression || !o.output.empty() ||
                             !o.creases_file.empty() || !o.corners_file.empty()))
    throw Usage_error("--demo takes a directory and at most --cells or --spacing, no input file, --op, --expr or -o");
  if(o.cells > 0 && o.spacing > 0) throw Usage_error("give only one of --cells N and --spacing h");
  o.simplify = app.count("--simplify") > 0;
  o.remesh = app.count("--remesh") > 0;
  if(o.simplify && !t.simplify.empty())
    o.simplify_cells = biso_tools::parse_real("--simplify", t.simplify, biso_tools::Sign_rule::POSITIVE);
  if(o.remesh && !t.remesh.empty())
    o.remesh_length = biso_tools::parse_real("--remesh", t.remesh, biso_tools::Sign_rule::POSITIVE);
  if(o.simplify && o.remesh) throw Usage_error("give at most one of --simplify and --remesh");
  if(!o.features && (!o.creases_file.empty() || !o.corners_file.empty()))
    throw Usage_error("--creases and --corners need sharp features: drop --no-features");
}


} // namespace csg_tool

#endif // BISO_TOOLS_CSG_OPTIONS_H
