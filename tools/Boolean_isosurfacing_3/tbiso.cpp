// tbiso: the boundary of a Boolean combination of scalar fields sampled on a
// tetrahedral domain, with its crease polylines and corners (TBISO: Taubin &
// Sibley, "Extracting Boolean isosurfaces from tetrahedral meshes").
//
//   tbiso (--cells N | --spacing h | --mesh FILE) (--fields FILE | --field SPEC ...) [--expr TEXT]
//         [--close] [--smooth [ITER]] [-o out.ply|.off|.obj|.stl] [--creases F] [--corners F]
//   tbiso --demo DIR
//   and the common options of cli.h (--threads, --sequential, --json, --quiet, --version)
//
// The literal fi of the expression is the region f_i < 0.  Prints the domain,
// the fields, the canonical expression, the time of every stage, the output
// sizes and, for a closed surface, the enclosed volume.  An error is one line
// `tbiso: error: ...` on stderr: exit status 2 for a bad command line, 1 for
// a bad file or a failed computation (doc/Boolean_isosurfacing_3/tools.md).
//
// The jobs are in their own headers: the command line (tbiso_options.h), the
// domain and the fields (tbiso_input.h, tbiso_fields.h), the extraction
// (tbiso_extract.h), the smoothing (tbiso_smooth.h), the files
// (tbiso_output.h) and the summary (tbiso_summary.h).

#include "cli.h"
#include "process_start.h"
#include "tbiso_extract.h"
#include "tbiso_input.h"
#include "tbiso_options.h"
#include "tbiso_output.h"
#include "tbiso_smooth.h"
#include "tbiso_summary.h"

#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

namespace tbiso_tool {
namespace {

const char* parallelism(const Options& o)
{
#ifdef CGAL_LINKED_WITH_TBB
  return o.parallel ? ", parallel" : ", sequential";
#else
  (void)o;
  return ", sequential";
#endif
}

// The domain and the fields, with their progress lines.
Input read_input(Tool& tool, const Options& o)
{
  Input in;
  if(o.grid)
    check_grid_memory(o, o.field_specs.empty() ? o.field_count : o.field_specs.size());
  biso_tools::Stopwatch watch;
  read_domain(o, in);
  print_domain(tool, in, o, watch.seconds());
  watch.restart();
  read_fields(o, in);
  const double seconds = watch.seconds();
  print_fields(tool, o, in.fields.number_of_fields(), "");
  print_expression(tool, o, in.expression);
  const bool sampled = o.fields_file.empty();
  tool.stage("fields",
             std::string(sampled ? "sampled " : "read ") + std::to_string(in.fields.number_of_fields()) +
                 " fields at " + std::to_string(in.number_of_vertices()) + " vertices",
             seconds);
  std::fprintf(tool.human(), "time fields:     %.3f s (%s)\n", seconds, sampled ? "sampling" : "reading");
  std::fflush(tool.human());
  return in;
}

BI::Boolean_isosurface_statistics extract_surface(Tool& tool, const Input& in, const Options& o, Soup& soup)
{
  const biso_tools::Stopwatch watch;
  const Callback progress = tool.progress("extracting the surface");
  const BI::Boolean_isosurface_statistics s = in.grid ? extract(*in.grid, in.fields, in.expression, soup, o, progress)
                                                      : extract(*in.mesh, in.fields, in.expression, soup, o, progress);
  const double seconds = watch.seconds();
  std::fprintf(tool.human(),
               "time extraction: %.3f s (table %.3f s, extraction %.3f s, welding %.3f s; %zu of %zu tetrahedra "
               "evaluated%s)\n",
               seconds, s.seconds_tables, s.seconds_extraction, s.seconds_welding, s.number_of_evaluated_tetrahedra,
               s.number_of_tetrahedra, parallelism(o));
  tool.stage("extraction",
             "extracted " + std::to_string(soup.polygons.size()) + " polygons from " +
                 std::to_string(s.number_of_evaluated_tetrahedra) + " tetrahedra",
             seconds);
  tool.time("table", s.seconds_tables);
  tool.time("welding", s.seconds_welding);
  tool.summary().set("evaluated_tetrahedra", s.number_of_evaluated_tetrahedra);
  return s;
}

BI::Crease_network find_creases(Tool& tool, const Soup& soup)
{
  const biso_tools::Stopwatch watch;
  BI::Crease_network creases = BI::extract_crease_network(soup);
  std::fprintf(tool.human(), "time creases:    %.3f s\n", watch.seconds());
  tool.stage("creases", "found " + std::to_string(creases.number_of_crease_edges) + " crease edges",
             watch.seconds());
  return creases;
}

void smooth_surface(Tool& tool, const Options& o, Soup& soup, const BI::Crease_network& creases)
{
  const biso_tools::Stopwatch watch;
  smooth(soup, creases, o);
  std::fprintf(tool.human(),
               "time smoothing:  %.3f s (%lld lambda|mu iterations, lambda %g, mu %g, creases and corners kept)\n",
               watch.seconds(), *o.smooth_iterations, o.lambda ? *o.lambda : BI::taubin_default_lambda,
               o.mu ? *o.mu : BI::taubin_default_mu);
  tool.stage("smoothing", "smoothed " + std::to_string(*o.smooth_iterations) + " iterations", watch.seconds());
}

int run(Tool& tool, const Options& o)
{
  const biso_tools::Stopwatch total;
  const Input in = read_input(tool, o);
  Soup soup;
  extract_surface(tool, in, o, soup);
  const BI::Crease_network creases = find_creases(tool, soup);
  if(o.smooth_iterations)
    smooth_surface(tool, o, soup, creases);
  write_outputs(tool, o, soup, creases);
  std::fprintf(tool.human(), "time total:      %.3f s\n", total.seconds());
  tool.time("total", total.seconds());
  print_surface(tool, o, soup, creases);
  for(const std::string* file : {&o.output, &o.creases_file, &o.corners_file})
    if(!file->empty())
      std::fprintf(tool.human(), "wrote %s\n", file->c_str());
  return 0;
}

double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

void print_out_of_core(Tool& tool, const Options& o, const BI::Boolean_isosurface_slab_statistics& s, double seconds,
                       double total)
{
  std::FILE* out = tool.human();
  std::fprintf(out,
               "time extraction: %.3f s (%zu slabs of %zu layers; reading %.3f s, evaluation and reading %.3f s, "
               "welding and writing %.3f s; %zu of %zu tetrahedra evaluated%s)\n",
               seconds, s.number_of_slabs, out_of_core_slab_layers(o), s.seconds_reading, s.seconds_extraction,
               s.seconds_welding, s.number_of_evaluated_tetrahedra, s.number_of_tetrahedra,
               o.parallel ? ", parallel" : ", sequential");
  std::fprintf(out, "time total:      %.3f s\n", total);
  std::fprintf(out, "output:     %zu vertices, %zu polygons\n", s.number_of_vertices, s.number_of_faces);
  std::fprintf(out, "memory:     %.1f MB of field values held at most, peak resident %.1f MB\n",
               double(s.peak_field_values) * 8 / 1e6, peak_resident_megabytes());
  std::fprintf(out, "wrote %s\n", o.output.c_str());
  tool.stage("extraction", "extracted and wrote " + std::to_string(s.number_of_faces) + " polygons", seconds);
  tool.time("total", total);
  tool.output(o.output);
  biso_tools::Json_object& j = tool.summary();
  j.set("vertices", s.number_of_vertices);
  j.set("faces", s.number_of_faces);
  j.set("slabs", s.number_of_slabs);
  j.set("peak_field_megabytes", double(s.peak_field_values) * 8 / 1e6);
}

// Fields read one slab at a time from a raw file (or evaluated slab by
// slab: the same doubles as the in-core sampling), the surface streamed to
// a binary PLY file: memory is a few slabs, whatever the grid size.
int run_out_of_core(Tool& tool, const Options& o)
{
  const biso_tools::Stopwatch total;
  const bool analytic = !o.field_specs.empty();
  const std::size_t field_count = analytic ? o.field_specs.size() : o.field_count;
  const BI::Boolean_expression expression = BI::Boolean_expression::parse(o.expression ? *o.expression : "f0");
  if(expression.number_of_variables() > field_count)
    throw Error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                " but there are only " + std::to_string(field_count) + " fields");
  const Grid grid = make_grid(o);
  Input in;
  in.grid.emplace(grid);
  print_domain(tool, in, o, 0);
  check_grid_memory(o, field_count);
  const biso_tools::Stopwatch watch;
  BI::Boolean_isosurface_slab_statistics s;
  if(analytic)
  {
    tbiso_fields::Analytic_field_source source(grid, make_fields(o.field_specs));
    print_fields(tool, o, field_count, ", evaluated slab by slab");
    print_expression(tool, o, expression);
    s = extract_out_of_core(grid, source, expression, o, tool.progress("extracting and writing the surface"));
  }
  else
  {
    const bool f32 = biso_tools::extension(o.fields_file) == "f32";
    BI::IO::Raw_scalar_field_reader reader(o.fields_file, grid.number_of_vertices(), o.field_count,
                                           f32 ? BI::IO::Raw_scalar_type::FLOAT32 : BI::IO::Raw_scalar_type::FLOAT64);
    print_fields(tool, o, field_count, " slab by slab");
    print_expression(tool, o, expression);
    s = extract_out_of_core(grid, reader, expression, o, tool.progress("extracting and writing the surface"));
  }
  print_out_of_core(tool, o, s, watch.seconds(), total.seconds());
  return 0;
}

int run_demo(Tool& tool, Options o)
{
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
  o.lattice_flag = "--demo";
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
  std::fprintf(tool.human(),
               "TBISO demo: the points inside at least two of four spheres (radius %g, centres at the\n"
               "vertices of a regular tetrahedron), on a 128^3 grid over [-1, 1]^3\n",
               r);
  return run(tool, o);
}

} // namespace
} // namespace tbiso_tool

int main(int argc, char** argv)
{
  // The MPI driver first: it is started with the huge-page heap directly.
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--distributed")
    {
#ifdef BISO_WITH_MPI
      return biso_tools::run_distributed_driver("tbiso", "tbiso_distributed", argv);
#else
      std::cerr << "tbiso: error: --distributed: this tbiso was built without MPI\n";
      return 1;
#endif
    }
  biso_tools::restart_with_huge_page_heap(argv);
  using namespace tbiso_tool;
  Tool tool("tbiso", description);
  Options options;
  Option_text text;
  add_options(tool, options, text);
  const auto check = [&] {
    if(argc == 1)
      throw Usage_error("nothing to do (see tbiso --help, or try tbiso --demo DIR)");
    check_options(tool, options, text);
    // Output paths are checked before any computation, so that an unwritable
    // one costs a second, not the whole extraction.
    for(const std::string* path : {&options.output, &options.creases_file, &options.corners_file})
      if(!path->empty())
        biso_tools::check_output_file(*path);
  };
  return tool.run(argc, argv, check, [&] {
    if(!options.demo_dir.empty())
      return run_demo(tool, options);
    return options.out_of_core ? run_out_of_core(tool, options) : run(tool, options);
  });
}
