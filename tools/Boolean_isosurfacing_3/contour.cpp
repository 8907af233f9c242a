// contour: oriented (or unoriented) point samples -> closed triangle mesh,
// by Hoppe's tangent-plane signed distance and Marching Cubes
// (the contour-tracing assignment, [ContourTracing] in the manual's references).
//
//   contour [FILE|-] [-o out.tris|out.off|out.ply|out.obj|out.stl] [--cell r | --cells N] [--k K]
//           [--rho R] [--delta D] [--max-jump J]
//
// FILE: .pts (the seed's format, or Hoppe's A3d points), .xyz, .pwn, .ply;
// "-": a .pts stream on standard input (`contour - < mechpart.pts`; with no
// FILE, standard input too, unless it is a terminal).  Prints the point
// count, the time of every stage and the triangle count on stdout.
// `contour --help` lists the options.  Exit status: 0, 1 for a bad file or a
// failed computation, 2 for a bad command line; every error is one line on
// stderr.

#include "tool_support.h"

#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tris.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

namespace {

using biso_tools::Usage_error;

const char* help_text =
    "contour: oriented (or unoriented) point samples -> closed triangle mesh (Hoppe et al. 1992)\n"
    "usage: contour [FILE|-] [-o OUT] [--cell r | --cells N] [--k K] [--rho R] [--delta D] [--max-jump J]\n"
    "  FILE             .pts (x y z [nx ny nz] per line), .xyz, .pwn or .ply; '-' reads .pts from standard\n"
    "                   input; with no FILE standard input is read too, unless it is a terminal (then this\n"
    "                   is a usage error: give FILE, or '-' to type the points, ended by Ctrl-D)\n"
    "  -o OUT           write the mesh: .tris (the seed's format), .off, .ply, .obj or .stl; checked\n"
    "                   before computing\n"
    "  --cell r         lattice cell size (positive; default about 1.25 x the mean sample spacing)\n"
    "  --cells N        N cells along the longest side of the samples' bounding box (whole, >= 1)\n"
    "  --k K            neighbours per tangent plane (whole, 3 to 1024; default 15)\n"
    "  --rho R          sampling density (positive; default estimated)\n"
    "  --delta D        noise level (>= 0; default estimated)\n"
    "  --max-jump J     skip cubes where f jumps by more than J cells (>= 0; inf = Hoppe's plain rule;\n"
    "                   default 3 cells + 2 delta)\n"
    "  -h, --help       this help\n"
    "A lattice estimated to cross more than 2^27 surface cubes (about 10 GB of output) is refused.\n"
    "exit status: 0 success, 1 bad input file or failed computation, 2 bad command line\n";

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
  std::string lattice_flag; // "--cell r" or "--cells N", for messages
  std::optional<double> rho, delta;
  double max_jump = -1; // default of the library
  std::size_t k = 15;
  bool help = false;
};

Options parse(int argc, char** argv)
{
  using biso_tools::Sign_rule;
  Options o;
  std::set<std::string> seen;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool is_flag = a.size() > 1 && a[0] == '-';
    if(is_flag && !seen.insert(a).second)
      throw Usage_error(biso_tools::printable(a) + " is given more than once");
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error(a + " needs a value");
      return argv[++i];
    };
    if(a == "-o")
    {
      o.output = value();
      if(o.output.empty())
        throw Usage_error("-o needs a file name, got an empty argument");
      const std::string e = biso_tools::extension(o.output);
      if(e != "tris" && e != "off" && e != "obj" && e != "ply" && e != "stl")
        throw Usage_error("-o: " + biso_tools::quote_arg(o.output) +
                          " has no supported extension (.tris, .off, .obj, .ply, .stl)");
    }
    else if(a == "--cell")
    {
      const std::string text = value();
      o.cell = biso_tools::parse_real(a, text, Sign_rule::POSITIVE);
      o.lattice_flag = a + " " + text;
    }
    else if(a == "--cells")
    {
      const std::string text = value();
      o.cells = biso_tools::parse_count(a, text, 1, std::size_t(1) << 20, "a lattice has at most 2^20 cells per axis");
      o.lattice_flag = a + " " + text;
    }
    else if(a == "--k")
      o.k = biso_tools::parse_count(a, value(), 3, max_neighbors, "neighbour lists take points x K entries");
    else if(a == "--rho")
      o.rho = biso_tools::parse_real(a, value(), Sign_rule::POSITIVE);
    else if(a == "--delta")
      o.delta = biso_tools::parse_real(a, value(), Sign_rule::NON_NEGATIVE);
    else if(a == "--max-jump")
      o.max_jump = biso_tools::parse_real(a, value(), Sign_rule::NON_NEGATIVE, /* allow_infinity = */ true);
    else if(a == "-h" || a == "--help")
      o.help = true;
    else if(is_flag)
      throw Usage_error("unknown option " + biso_tools::quote_arg(a) + " (contour --help for usage)");
    else if(o.have_input)
      throw Usage_error("more than one input file: " + biso_tools::quote_arg(o.input) + " and " +
                        biso_tools::quote_arg(a));
    else
    {
      if(a.empty())
        throw Usage_error("the input file name is empty");
      o.input = a;
      o.have_input = true;
    }
  }
  if(o.cell && o.cells)
    throw Usage_error("--cell and --cells are exclusive");
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
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

int run(const Options& options)
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
  {
    auto start = std::chrono::steady_clock::now();
    std::vector<Point_3> points;
    std::vector<Vector_3> normals;
    const bool has_normals = (options.input == "-") ? BI::IO::read_pts(std::cin, points, normals)
                                                    : BI::IO::read_point_samples(options.input, points, normals);
    const double read_seconds = seconds_since(start);
    std::cout << "points: " << points.size() << (has_normals ? " (with normals)" : " (no normals)") << "\n";

    // Points and normals side by side for the named parameters.
    std::vector<std::size_t> indices(points.size());
    for(std::size_t i = 0; i < indices.size(); ++i)
      indices[i] = i;
    const auto point_map = CGAL::make_property_map(points);
    const auto normal_map = CGAL::make_property_map(normals);
    const double rho = options.rho ? *options.rho : -1.0, delta = options.delta ? *options.delta : -1.0;

    std::optional<BI::Tangent_plane_signed_distance_3<K>> field_storage;
    auto build = [&](auto&& np) -> const BI::Tangent_plane_signed_distance_3<K>& {
      field_storage.emplace(indices, np);
      return *field_storage;
    };
    // A negative rho / delta means "estimate": the class treats a negative
    // value given explicitly as an error, so pass them only when set.
    const auto base = BI::parameters::number_of_neighbors(options.k).point_map(point_map);
    const BI::Tangent_plane_signed_distance_3<K>* field = nullptr;
    if(has_normals)
    {
      if(options.rho && options.delta)
        field = &build(BI::parameters::sampling_density(rho, BI::parameters::noise_level(delta, base.normal_map(normal_map))));
      else if(options.rho)
        field = &build(BI::parameters::sampling_density(rho, base.normal_map(normal_map)));
      else if(options.delta)
        field = &build(BI::parameters::noise_level(delta, base.normal_map(normal_map)));
      else
        field = &build(base.normal_map(normal_map));
    }
    else
    {
      if(options.rho && options.delta)
        field = &build(BI::parameters::sampling_density(rho, BI::parameters::noise_level(delta, base)));
      else if(options.rho)
        field = &build(BI::parameters::sampling_density(rho, base));
      else if(options.delta)
        field = &build(BI::parameters::noise_level(delta, base));
      else
        field = &build(base);
    }

    if(field->input_normals_rejected())
    {
      const auto votes = field->input_normal_votes();
      std::cerr << "warning: the input normals do not point outward (the extreme samples of " << votes.second
                << " of " << votes.first
                << " directions face inward); their signs are ignored and the planes are oriented as without normals\n";
    }

    std::vector<Point_3> out_points;
    std::vector<std::array<std::size_t, 3>> triangles;
    BI::Contouring_report report;
    // The cell size first (it scales the jump bound), then contour.
    double cell = field->default_cell_size();
    if(options.cell)
      cell = *options.cell;
    else if(options.cells)
    {
      std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
      for(const Point_3& p : points)
        for(int a = 0; a < 3; ++a)
        {
          lo[a] = std::min(lo[a], p[a]);
          hi[a] = std::max(hi[a], p[a]);
        }
      cell = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / *options.cells;
    }
    if(options.cell || options.cells)
      check_cell_size(cell, field->default_cell_size(), points.size(), options.lattice_flag);
    const double max_jump = options.max_jump >= 0 ? options.max_jump * cell : 3 * cell + 2 * field->noise_level();
    report = BI::contour_signed_distance(*field, out_points, triangles,
                                         BI::parameters::cell_size(cell, BI::parameters::maximum_jump(max_jump)));

    const auto& t = field->timings();
    std::cout << "k: " << field->number_of_neighbors() << ", rho: " << field->sampling_density()
              << ", delta: " << field->noise_level() << ", cell: " << report.cell_size << " (lattice "
              << report.number_of_cells[0] << " x " << report.number_of_cells[1] << " x " << report.number_of_cells[2]
              << " cells)\n";
    std::cout << "time read:          " << read_seconds << " s\n"
              << "time k-NN:          " << t.neighbors << " s\n"
              << "time PCA:           " << t.planes << " s (" << field->number_of_trimmed_neighbourhoods()
              << " neighbourhoods trimmed to one sheet)\n"
              << "time orientation:   " << t.orientation << " s"
              << (field->has_input_normals() && !field->input_normals_rejected()
                    ? std::string(" (from input normals)")
                    : " (minimum spanning forest, " + std::to_string(field->number_of_orientation_trees()) + " tree(s))")
              << "\n"
              << "time distance field: " << report.field_seconds << " s (" << report.field_evaluations
              << " lattice points, " << report.undefined_points << " undefined)\n"
              << "time contouring:    " << report.contouring_seconds << " s (" << report.visited_cubes
              << " cubes visited, " << report.surface_cubes << " crossed, " << report.skipped_cubes
              << " skipped for an undefined corner, " << report.border_exits << " lattice-border exits, " << report.discontinuous_cubes << " skipped for a jump of f, "
              << report.removed_closed_components << " closed pieces smaller than rho removed)\n";
    std::cout << "triangles: " << triangles.size() << ", vertices: " << out_points.size() << "\n";
    if(report.empty_output) // an empty mesh is an error, not a result
      throw BI::Empty_contour_error(report);

    if(!options.output.empty())
    {
      const std::string& out = options.output;
      bool ok;
      if(biso_tools::extension(out) == "tris")
        ok = BI::IO::write_tris(out, out_points, triangles);
      else
        ok = CGAL::IO::write_polygon_soup(out, out_points, triangles, CGAL::parameters::stream_precision(17));
      if(!ok)
        throw biso_tools::File_error(out + ": cannot write");
      std::cout << "wrote " << out << "\n";
    }
    return 0;
  }
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse(argc, argv);
    if(options.help)
    {
      std::cout << help_text;
      return 0;
    }
    return run(options);
  }
  catch(const Usage_error& e)
  {
    biso_tools::print_error("contour", e.what());
    return 2;
  }
  catch(const std::bad_alloc&)
  {
    biso_tools::print_error("contour", "out of memory (use a larger cell)");
    return 1;
  }
  catch(const std::exception& e)
  {
    biso_tools::print_error("contour", e.what());
    return 1;
  }
}
