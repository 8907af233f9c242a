// contour: oriented (or unoriented) point samples -> closed triangle mesh,
// by Hoppe's tangent-plane signed distance and Marching Cubes
// (the contour-tracing assignment, [ContourTracing] in the manual's references).
//
//   contour [FILE|-] [-o out.tris|out.off|out.ply|out.obj|out.stl] [--spacing h | --cells N] [--k K]
//           [--rho R] [--delta D] [--hoppe] [--max-jump J] [--no-features]
//   and the common options of cli.h (--threads, --sequential, --json, --quiet, --version)
//
// FILE: .pts (the seed's format, or Hoppe's A3d points), .xyz, .pwn, .ply;
// "-": a .pts stream on standard input (`contour - < mechpart.pts`; with no
// FILE, standard input too, unless it is a terminal).  Prints the point
// count, the time of every stage and the triangle count on stdout.
// `contour --help` lists the options.  Exit status: 0, 1 for a bad file or a
// failed computation, 2 for a bad command line; every error is one line on
// stderr (doc/Boolean_isosurfacing_3/tools.md).

#include "cli.h"
#include "process_start.h"

#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tris.h>
#include <CGAL/Boolean_isosurfacing_3/IO/write_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

namespace {

using biso_tools::Usage_error;

using biso_tools::Tool;

const char* description =
    "contour: oriented (or unoriented) point samples -> closed triangle mesh (Hoppe et al. 1992)\n"
    "usage: contour [FILE|-] [-o OUT] [--spacing h | --cells N] [--k K] [--rho R] [--delta D] [--hoppe] [--max-jump J]\n"
    "               [--no-features]\n"
    "  FILE: .pts (x y z [nx ny nz] per line), .xyz, .pwn or .ply; '-' reads .pts from standard input; with no\n"
    "  FILE standard input is read too, unless it is a terminal (then this is a usage error: give FILE, or '-'\n"
    "  to type the points, ended by Ctrl-D).\n"
    "  A lattice estimated to cross more than 2^27 surface cubes (about 10 GB of output) is refused.\n";

// Largest --k: the neighbour lists take points x K entries, and beyond a
// few dozen neighbours a neighbourhood is no longer a tangent plane.
constexpr std::size_t max_neighbors = 1024;
// Largest number of surface cubes the tool lets a lattice cross (estimate).
constexpr double max_surface_cubes = double(std::size_t(1) << 27);

struct Options
{
  std::string input = "-";
  bool have_input = false;
  std::string output;
  std::optional<double> cell;
  std::optional<std::size_t> cells;
  std::string lattice_flag; // "--spacing h" or "--cells N", for messages
  std::optional<double> rho, delta;
  std::optional<double> max_jump; // in cells; the library's default without it
  bool hoppe_only = false;        // --hoppe, or --max-jump: Hoppe's f alone
  bool no_features = false;       // --no-features: plain Marching Cubes with input normals too
  std::size_t k = 15;
};

// The options' text, converted and checked once parsed.
struct Option_text
{
  std::string spacing, cells, k, rho, delta, max_jump;
};

void add_options(Tool& tool, Options& o, Option_text& t)
{
  CLI::App& app = tool.app();
  app.add_option("-o", o.output, "write the mesh: .off, .obj, .ply, .stl, or .tris (the seed's format); checked "
                                 "before computing")
      ->type_name("OUT");
  biso_tools::add_lattice_options(app, t.cells, t.spacing, "the samples' bounding box");
  // The old name of --spacing, kept for scripts.
  app.add_option("--cell", t.spacing)->group("");
  app.add_option("--k", t.k, "neighbours per tangent plane (whole, 3 to 1024; default 15)")->type_name("K");
  app.add_option("--rho", t.rho, "sampling density (positive; default estimated)")->type_name("R");
  app.add_option("--delta", t.delta, "noise level (>= 0; default estimated)")->type_name("D");
  app.add_flag("--hoppe", o.hoppe_only,
               "Hoppe's f alone: skip cubes with an undefined corner or a jump of f (holes), instead of one "
               "consistent sign per lattice point (winding number; closed output)");
  app.add_option("--max-jump", t.max_jump,
                 "with Hoppe's f alone (implies --hoppe): skip cubes where f jumps by more than J cells (>= 0; inf = "
                 "Hoppe's plain rule; default 3 cells + 2 delta)")
      ->type_name("J");
  app.add_flag("--no-features", o.no_features,
               "with input normals, no crease and corner vertices (plain Marching Cubes triangles); without "
               "input normals there are none anyway");
}

// \throws Usage_error.
void check_options(Tool& tool, Options& o, const Option_text& t)
{
  using biso_tools::Sign_rule;
  const CLI::App& app = tool.app();
  if(app.count("-o"))
    biso_tools::check_mesh_extension("-o", o.output, {"tris"});
  const std::size_t spacing_flags = app.count("--spacing") + app.count("--cell");
  if(spacing_flags > 1)
    throw Usage_error("--spacing is given more than once");
  const std::string spacing_name = app.count("--cell") ? "--cell" : "--spacing";
  if(spacing_flags)
  {
    o.cell = biso_tools::parse_real(spacing_name, t.spacing, Sign_rule::POSITIVE);
    o.lattice_flag = spacing_name + " " + t.spacing;
  }
  if(app.count("--cells"))
  {
    o.cells = biso_tools::parse_count("--cells", t.cells, 1, std::size_t(1) << 20,
                                      "a lattice has at most 2^20 cells per axis");
    o.lattice_flag = "--cells " + t.cells;
  }
  if(app.count("--k"))
    o.k = biso_tools::parse_count("--k", t.k, 3, max_neighbors, "neighbour lists take points x K entries");
  if(app.count("--rho"))
    o.rho = biso_tools::parse_real("--rho", t.rho, Sign_rule::POSITIVE);
  if(app.count("--delta"))
    o.delta = biso_tools::parse_real("--delta", t.delta, Sign_rule::NON_NEGATIVE);
  if(app.count("--max-jump"))
  {
    o.max_jump = biso_tools::parse_real("--max-jump", t.max_jump, Sign_rule::NON_NEGATIVE, /* allow_infinity = */ true);
    o.hoppe_only = true;
  }
  const std::vector<std::string>& files = tool.positionals();
  if(files.size() > 1)
    throw Usage_error("more than one input file: " + biso_tools::quote_arg(files[0]) + " and " +
                      biso_tools::quote_arg(files[1]));
  if(files.size() == 1)
  {
    if(files[0].empty())
      throw Usage_error("the input file name is empty");
    o.input = files[0];
    o.have_input = true;
  }
  if(o.cell && o.cells)
    throw Usage_error(spacing_name + " and --cells are exclusive");
}

// Refuses a cell so much finer than the samples that the output would not
// fit: a surface of area S crosses about 1.5 S / r^2 cubes (1.5: the mean
// of |nx| + |ny| + |nz| over the unit normals), and the samples' area is
// about N s^2 for their mean spacing s (default_cell_size() is 1.25 s).
// Measured on sphere.pwn at --cells 400: estimate 5.0e5, 7.5e5 crossed.
void check_cell_size(double cell, double default_cell, std::size_t number_of_points, const std::string& flag)
{
  const double spacing = default_cell / 1.25;
  const double estimate = 1.5 * double(number_of_points) * (spacing / cell) * (spacing / cell);
  if(!(estimate <= max_surface_cubes))
  {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%s: the cell %.3g is %.3g times finer than the default %.3g: about %.2g surface cubes, above the "
                  "limit of %.3g (2^27): use a larger cell",
                  flag.c_str(), cell, default_cell / cell, default_cell, estimate, max_surface_cubes);
    throw BI::Invalid_input_error(text);
  }
}

// Parallel where TBB is: --threads and --sequential bound it (the field is
// the same on any number of threads).
typedef BI::Tangent_plane_signed_distance_3<K, CGAL::Parallel_if_available_tag> Field;

struct Samples
{
  std::vector<Point_3> points;
  std::vector<Vector_3> normals;
  std::vector<std::size_t> indices; // 0, 1, ...: the field's input range
  bool has_normals = false;
};

Samples read_samples(Tool& tool, const Options& options)
{
  const biso_tools::Stopwatch watch;
  Samples s;
  s.has_normals = (options.input == "-") ? BI::IO::read_pts(std::cin, s.points, s.normals)
                                         : BI::IO::read_point_samples(options.input, s.points, s.normals);
  s.indices.resize(s.points.size());
  for(std::size_t i = 0; i < s.indices.size(); ++i)
    s.indices[i] = i;
  tool.input(options.input);
  tool.stage("read", "read " + std::to_string(s.points.size()) + " points", watch.seconds());
  tool.summary().set("points", s.points.size());
  tool.summary().set("normals", s.has_normals);
  tool.human_stream() << "points: " << s.points.size() << (s.has_normals ? " (with normals)" : " (no normals)")
                      << "\n";
  return s;
}

// The field, with only the parameters the command line sets: the class
// treats a negative rho or delta given explicitly as an error.
void build_field(const Options& options, const Samples& s, std::optional<Field>& field)
{
  const auto point_map = CGAL::make_property_map(s.points);
  const auto normal_map = CGAL::make_property_map(s.normals);
  const double rho = options.rho ? *options.rho : -1.0, delta = options.delta ? *options.delta : -1.0;
  const auto base = BI::parameters::number_of_neighbors(options.k).point_map(point_map);
  auto build = [&](const auto& np) {
    if(options.rho && options.delta)
      field.emplace(s.indices, BI::parameters::sampling_density(rho, BI::parameters::noise_level(delta, np)));
    else if(options.rho)
      field.emplace(s.indices, BI::parameters::sampling_density(rho, np));
    else if(options.delta)
      field.emplace(s.indices, BI::parameters::noise_level(delta, np));
    else
      field.emplace(s.indices, np);
  };
  if(s.has_normals)
    build(base.normal_map(normal_map));
  else
    build(base);
}

// The cell size the command line asks for (the field's default without a
// flag), checked against the tool's limit on the output size.
std::optional<double> cell_size(const Options& options, const Samples& s, const Field& field)
{
  std::optional<double> cell;
  if(options.cell)
    cell = *options.cell;
  else if(options.cells)
  {
    std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
    for(const Point_3& p : s.points)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    cell = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / *options.cells;
  }
  if(cell)
    check_cell_size(*cell, field.default_cell_size(), s.points.size(), options.lattice_flag);
  return cell;
}

// The library's contouring lattice of the field, with the spacing asked for
// (a lattice has at most 2^31 points).
BI::Regular_lattice_3 lattice_of(const Options& options, const Field& field, const std::optional<double>& cell)
{
  try
  {
    return cell ? BI::contouring_lattice(field, BI::parameters::cell_size(*cell)) : BI::contouring_lattice(field);
  }
  catch(const BI::Lattice_too_large_error& e)
  {
    throw BI::Lattice_too_large_error((options.lattice_flag.empty() ? "" : options.lattice_flag + ": ") + e.what());
  }
}

// The contouring, on `tool`'s progress line; --max-jump is in cells.
template <typename ConcurrencyTag>
BI::Contouring_statistics contour(Tool& tool, const Options& options, const BI::Regular_lattice_3& lattice,
                                  const Field& field, std::vector<Point_3>& points,
                                  std::vector<std::array<std::size_t, 3>>& triangles)
{
  const std::function<bool(double)> progress = tool.progress("contouring");
  const bool consistent = !options.hoppe_only;
  const bool features = field.uses_input_normals() && field.number_of_sharp_samples() > 0 && !options.no_features;
  if(options.max_jump)
    return BI::contour_signed_distance<ConcurrencyTag>(
        lattice, field, points, triangles,
        BI::parameters::maximum_jump(*options.max_jump * lattice.spacing(),
                                     BI::parameters::consistent_signs(consistent, BI::parameters::sharp_features(features)))
            .callback(progress));
  return BI::contour_signed_distance<ConcurrencyTag>(
      lattice, field, points, triangles,
      BI::parameters::consistent_signs(consistent, BI::parameters::sharp_features(features)).callback(progress));
}

void report_field(Tool& tool, const Field& field)
{
  const auto& t = field.timings();
  tool.stage("neighbors", "found the k nearest neighbours", t.neighbors);
  tool.stage("planes", "fitted the tangent planes", t.planes);
  tool.stage("orientation", "oriented the tangent planes", t.orientation);
  if(field.input_normals_rejected())
  {
    const auto votes = field.input_normal_votes();
    tool.warning("the input normals do not point outward (the extreme samples of " + std::to_string(votes.second) +
                 " of " + std::to_string(votes.first) +
                 " directions face inward); their signs are ignored and the planes are oriented as without normals");
  }
}

void print_report(Tool& tool, const Field& field, const BI::Contouring_statistics& report, double read_seconds,
                  std::size_t vertices, std::size_t triangles)
{
  const auto& t = field.timings();
  std::ostream& out = tool.human_stream();
  out << "k: " << field.number_of_neighbors() << ", rho: " << field.sampling_density()
      << ", delta: " << field.noise_level() << ", cell: " << report.cell_size << " (lattice "
      << report.number_of_cells[0] << " x " << report.number_of_cells[1] << " x " << report.number_of_cells[2]
      << " cells)\n";
  out << "time read:          " << read_seconds << " s\n"
      << "time k-NN:          " << t.neighbors << " s\n"
      << "time PCA:           " << t.planes << " s (" << field.number_of_trimmed_neighbourhoods()
      << " neighbourhoods trimmed to one sheet)\n"
      << "time orientation:   " << t.orientation << " s"
      << (field.has_input_normals() && !field.input_normals_rejected()
              ? std::string(" (from input normals)")
              : " (minimum spanning forest, " + std::to_string(field.number_of_orientation_trees()) + " tree(s))")
      << "\n"
      << "time distance field: " << report.seconds_field << " s (" << report.field_evaluations
      << " lattice points, " << report.undefined_points << " undefined)\n"
      << "time contouring:    " << report.seconds_contouring << " s (" << report.visited_cubes
      << " cubes visited, " << report.surface_cubes << " crossed, " << report.skipped_cubes
      << " skipped for an undefined corner, " << report.border_exits << " lattice-border exits, "
      << report.discontinuous_cubes << " skipped for a jump of f, " << report.removed_closed_components
      << " closed pieces smaller than rho removed)\n"
      << "signs: " << (report.consistent_signs ? "consistent (winding number)" : "Hoppe's f alone") << ", "
      << report.removed_membranes << " membranes across wide openings removed\n"
      << "planes: "
      << (field.uses_input_normals()
              ? "the input normals' (" + std::to_string(field.number_of_sharp_samples()) + " samples by a sharp edge)"
              : std::string("Hoppe's PCA planes"))
      << ", " << report.feature_creases << " crease and " << report.feature_corners << " corner vertices, "
      << report.feature_flips << " edges flipped to join them\n";
  out << "triangles: " << triangles << ", vertices: " << vertices << "\n";
  biso_tools::Json_object& j = tool.summary();
  j.set("k", field.number_of_neighbors());
  j.set("rho", field.sampling_density());
  j.set("delta", field.noise_level());
  j.set("spacing", report.cell_size);
  j.set_raw("cells", biso_tools::json_number_array({double(report.number_of_cells[0]),
                                                    double(report.number_of_cells[1]),
                                                    double(report.number_of_cells[2])}));
  j.set("consistent_signs", report.consistent_signs);
  j.set("removed_membranes", report.removed_membranes);
  j.set("input_normal_planes", field.uses_input_normals());
  j.set("feature_creases", report.feature_creases);
  j.set("feature_corners", report.feature_corners);
  j.set("vertices", vertices);
  j.set("faces", triangles);
}

void write_mesh(Tool& tool, const std::string& out, const std::vector<Point_3>& points,
                const std::vector<std::array<std::size_t, 3>>& triangles)
{
  const biso_tools::Stopwatch watch;
  if(biso_tools::extension(out) == "tris")
  {
    if(!BI::IO::write_tris(out, points, triangles))
      throw biso_tools::File_error(out + ": cannot write");
  }
  else
  {
    // The package's writer (as csg's): straight from flat arrays, shortest
    // round-trip decimals; CGAL's stream writer took a fifth of the process.
    BI::Triangle_soup_3 soup;
    soup.points.reserve(points.size());
    for(const Point_3& p : points)
      soup.points.push_back({{p.x(), p.y(), p.z()}});
    if(points.size() > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
      throw biso_tools::File_error(out + ": more than 2^32 vertices, too many for the mesh formats' 32-bit indices");
    soup.triangles.reserve(triangles.size());
    for(const std::array<std::size_t, 3>& t : triangles)
      soup.triangles.push_back({{std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])}});
    try
    {
      BI::IO::write_triangle_soup(out, soup);
    }
    catch(const std::runtime_error& e)
    {
      throw biso_tools::File_error(out + ": cannot write (" + e.what() + ")");
    }
  }
  tool.output(out);
  tool.stage("write", "wrote " + out, watch.seconds());
  tool.human_stream() << "wrote " << out << "\n";
}

int run(Tool& tool, const Options& options)
{
  if(!options.have_input && isatty(0))
    throw Usage_error("no input file, and standard input is a terminal: give FILE, or '-' to type .pts lines "
                      "(end with Ctrl-D); contour --help for usage");
  if(options.input != "-")
    biso_tools::check_input_file(options.input);
  if(!options.output.empty())
    biso_tools::check_output_file(options.output);
  if(options.input == "-" && isatty(0))
    std::cerr << "contour: reading .pts lines (x y z [nx ny nz]) from the terminal; end with Ctrl-D\n";
  const std::future<void> table = biso_tools::build_meanwhile<BI::Marching_cubes_table>(tool.parallel());
  const biso_tools::Stopwatch watch;
  const Samples samples = read_samples(tool, options);
  const double read_seconds = watch.seconds();
  std::optional<Field> field;
  build_field(options, samples, field);
  report_field(tool, *field);

  // The lattice (its spacing scales the jump bound), then contour.
  const BI::Regular_lattice_3 lattice = lattice_of(options, *field, cell_size(options, samples, *field));
  std::vector<Point_3> out_points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const BI::Contouring_statistics report =
      tool.parallel() ? contour<CGAL::Parallel_if_available_tag>(tool, options, lattice, *field, out_points, triangles)
                      : contour<CGAL::Sequential_tag>(tool, options, lattice, *field, out_points, triangles);
  tool.stage("field", "evaluated the distance at " + std::to_string(report.field_evaluations) + " lattice points",
             report.seconds_field);
  tool.stage("contouring", "contoured " + std::to_string(triangles.size()) + " triangles", report.seconds_contouring);
  print_report(tool, *field, report, read_seconds, out_points.size(), triangles.size());
  if(report.empty_output) // an empty mesh is an error, not a result
    throw BI::Empty_contour_error(report);
  if(!options.output.empty())
    write_mesh(tool, options.output, out_points, triangles);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  biso_tools::restart_with_huge_page_heap(argv);
  Tool tool("contour", description);
  Options options;
  Option_text text;
  add_options(tool, options, text);
  return tool.run(
      argc, argv, [&] { check_options(tool, options, text); }, [&] { return run(tool, options); });
}
