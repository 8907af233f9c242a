// contour: oriented (or unoriented) point samples -> closed triangle mesh,
// by Hoppe's tangent-plane signed distance and Marching Cubes
// (seeds/contour_tracing_signed_distance.txt).
//
//   contour [FILE] [-o out.tris|out.off|out.ply|out.obj] [--cell r | --cells N] [--k K]
//           [--rho R] [--delta D] [--max-jump J]
//
// FILE: .pts (the seed's format, or Hoppe's A3d points), .xyz, .pwn, .ply;
// absent or "-": a .pts stream on standard input (`contour < mechpart.pts`).
// Prints the point count, the time of every stage and the triangle count on
// stdout; any error is one line on stderr and exit status 1 (2 for usage).

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
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

namespace {

struct Options
{
  std::string input = "-";
  std::string output;
  std::optional<double> cell;
  std::optional<double> cells;
  std::optional<double> rho, delta;
  double max_jump = -1; // default of the library
  std::size_t k = 15;
};

[[noreturn]] void usage(const std::string& problem)
{
  std::cerr << "contour: " << problem << "\n"
            << "usage: contour [FILE|-] [-o out.tris|out.off|out.ply|out.obj] [--cell r | --cells N] [--k K]"
               " [--rho R] [--delta D] [--max-jump J (cells; inf = Hoppe's plain rule)]\n";
  std::exit(2);
}

double number(const std::string& flag, const char* text)
{
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if(end == text || *end != '\0')
    usage(flag + " expects a number, got '" + text + "'");
  return v;
}

Options parse(int argc, char** argv)
{
  Options o;
  bool have_input = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if(i + 1 >= argc)
        usage(a + " needs a value");
      return argv[++i];
    };
    if(a == "-o")
      o.output = value();
    else if(a == "--cell")
      o.cell = number(a, value());
    else if(a == "--cells")
      o.cells = number(a, value());
    else if(a == "--k")
      o.k = std::size_t(number(a, value()));
    else if(a == "--rho")
      o.rho = number(a, value());
    else if(a == "--delta")
      o.delta = number(a, value());
    else if(a == "--max-jump")
      o.max_jump = number(a, value());
    else if(a == "-h" || a == "--help")
      usage("help");
    else if(a.size() > 1 && a[0] == '-' && a != "-")
      usage("unknown option '" + a + "'");
    else if(have_input)
      usage("more than one input file");
    else
    {
      o.input = a;
      have_input = true;
    }
  }
  if(o.cell && o.cells)
    usage("--cell and --cells are exclusive");
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  const Options options = parse(argc, argv);
  try
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

    if(!options.output.empty())
    {
      const std::string& out = options.output;
      const std::string extension = out.substr(std::min(out.size(), out.find_last_of('.') + 1));
      bool ok;
      if(extension == "tris")
        ok = BI::IO::write_tris(out, out_points, triangles);
      else
        ok = CGAL::IO::write_polygon_soup(out, out_points, triangles, CGAL::parameters::stream_precision(17));
      if(!ok)
      {
        std::cerr << "contour: cannot write '" << out << "'\n";
        return 1;
      }
      std::cout << "wrote " << out << "\n";
    }
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "contour: " << e.what() << "\n";
    return 1;
  }
}
