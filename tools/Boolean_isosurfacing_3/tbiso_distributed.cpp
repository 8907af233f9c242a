// tbiso --distributed: TBISO on the ranks of MPI_COMM_WORLD, started by
//
//   mpirun -np K tbiso --distributed (--cells N | --cells NX,NY,NZ | --spacing h) [--box ...]
//          (--fields FILE.f64|.f32 --field-count N | --field SPEC ...)
//          [--expr TEXT] [--close] [--slab-size LAYERS] [--threads T] -o OUT.ply
//
// Rank r reads only its z slab range plus ghost layers of the raw field file
// (MPI_File_read_at), or evaluates the analytic fields (the specs of
// tbiso_fields.h) at only those vertices, extracts it, welds with its
// neighbours through the exact vertex keys, and writes its part of OUT.ply.
// OUT.ply is byte for byte the file `tbiso --out-of-core` writes in one
// process with the same fields and --slab-size.  The options are tbiso's
// (tbiso_options.h), the MPI frame mpi_driver.h's.  Only rank 0 prints; an
// error is one line `tbiso: error: ...` on stderr (rank 0) and exit status 1
// (2 for a bad command line) on every rank.  See doc/Boolean_isosurfacing_3/distributed.md.

#include <CGAL/Boolean_isosurfacing_3/MPI/distributed_boolean_isosurface.h>

#include "mpi_driver.h"
#include "process_start.h"
#include "tbiso_fields.h"
#include "tbiso_options.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <mpi.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>


namespace {

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef BI::Tetrahedral_grid_3<K> Grid;
using biso_tools::Usage_error;
using biso_tools::mpi::Ranks;
using tbiso_tool::Options;

// tbiso's options (tbiso_options.h), with the checks of --out-of-core (a
// distributed run is out of core) and what --distributed does not do.
void check_distributed_options(biso_tools::Tool& tool, Options& o, const tbiso_tool::Option_text& t)
{
  const CLI::App& app = tool.app();
  if(biso_tools::extension(o.output) != "ply")
    throw Usage_error("--distributed writes a binary PLY file: give -o OUT.ply");
  if(app.count("--cells") + app.count("--spacing") + app.count("--grid") == 0)
    throw Usage_error("--distributed needs a grid: --cells N, --cells NX,NY,NZ or --spacing h");
  o.out_of_core = true;
  tbiso_tool::check_options(tool, o, t);
  if(!o.demo_dir.empty() || !o.mesh_file.empty())
    throw Usage_error("--distributed needs a grid (--cells or --spacing), not --demo or --mesh");
  if(!o.field_specs.empty())
    o.field_count = o.field_specs.size();
  if(!o.slab_layers)
    o.slab_layers = 8;
  // One thread per rank unless --threads.
  o.parallel = app.count("--threads") > 0 && tool.parallel();
}

// One line per rank, gathered on rank 0.
void report_ranks(biso_tools::Tool& tool, const BI::Boolean_isosurface_distributed_statistics& s,
                  double field_seconds, double field_megabytes, const Ranks& ranks)
{
  const biso_tools::mpi::Rank_table table = biso_tools::mpi::gather_on_root(
      {"first_layer", "last_layer", "vertices", "polygons", "extraction_seconds", "reading_seconds",
       "welding_seconds", "writing_seconds", "read_megabytes", "sent_kilobytes", "field_megabytes",
       "peak_resident_megabytes", "extracted_again"},
      {double(s.first_layer), double(s.last_layer), double(s.rank_vertices), double(s.rank_faces),
       s.seconds_extraction, field_seconds, s.seconds_welding, s.seconds_writing, field_megabytes,
       8.0 * double(s.sent_words) / 1e3, double(s.peak_field_values) * 8 / 1e6,
       biso_tools::mpi::peak_resident_megabytes(), s.extracted_again ? 1.0 : 0.0},
      ranks);
  if(ranks.rank != 0)
    return;
  std::FILE* out = tool.human();
  // "read MB": bytes read from the file, or the field values evaluated (8 bytes each).
  std::fprintf(out, "rank  layers          vertices   polygons  extract(s)  read(s)  weld(s)  write(s)  read MB  sent kB"
                    "  fields MB  peak RSS MB\n");
  for(int r = 0; r < ranks.size; ++r)
  {
    const double* v = table.row(r);
    char layers[48];
    std::snprintf(layers, sizeof layers, "[%.0f, %.0f)", v[0], v[1]);
    std::fprintf(out, "%4d  %-14s %9.0f  %9.0f  %10.3f  %7.3f  %7.3f  %8.3f  %7.1f  %7.1f  %9.1f  %11.1f\n", r, layers,
                 v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]);
    if(v[12] != 0)
      std::fprintf(out, "      (extracted again with the message from below: two bottom-layer vertices at one position)\n");
  }
  biso_tools::mpi::set_json_ranks(tool, table, ranks.size);
}

int run(biso_tools::Tool& tool, const Options& o, const Ranks& ranks)
{
  const int size = ranks.size;
  const BI::Boolean_expression expression = BI::Boolean_expression::parse(o.expression ? *o.expression : "f0");
  if(expression.number_of_variables() > o.field_count)
    throw BI::Invalid_input_error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                                " but there are only " + std::to_string(o.field_count) + " fields");
  const std::array<double, 6> box = o.domain_box();
  const Grid grid = Grid::spanning(K::Point_3(box[0], box[1], box[2]), K::Point_3(box[3], box[4], box[5]), *o.grid);
  const auto np = BI::parameters::close_at_domain_boundary(o.close, BI::parameters::slab_layers(o.slab_layers));
  auto extract = [&](auto& source) {
    return o.parallel
               ? BI::extract_boolean_isosurface_distributed<CGAL::Parallel_if_available_tag>(MPI_COMM_WORLD, grid, source,
                                                                                              expression, o.output, np)
               : BI::extract_boolean_isosurface_distributed<CGAL::Sequential_tag>(MPI_COMM_WORLD, grid, source, expression,
                                                                                   o.output, np);
  };
  std::FILE* out = tool.human(); // nowhere on ranks other than 0
  auto print_header = [&](const std::string& fields) {
    const auto& n = grid.vertex_counts();
    std::fprintf(out, "domain:     grid %zu x %zu x %zu vertices, %zu cube layers on %d rank%s\n", n[0], n[1], n[2], n[2] - 1,
                size, size == 1 ? "" : "s");
    std::fprintf(out, "fields:     %zu, %s\n", o.field_count, fields.c_str());
    for(std::size_t i = 0; i < o.field_specs.size(); ++i)
      std::fprintf(out, "  f%zu = %s\n", i, o.field_specs[i].c_str());
    std::fprintf(out, "expression: %s%s\n", expression.to_string().c_str(),
                 o.close ? ", closed at the domain boundary" : "");
    std::fflush(out);
  };
  BI::Boolean_isosurface_distributed_statistics s;
  double field_seconds = 0, field_megabytes = 0; // reading, or evaluating
  double start = 0;
  if(!o.field_specs.empty())
  {
    // Every rank makes the functions (a distance:MESH field reads the mesh
    // on every rank) and evaluates them only at its vertices.
    std::vector<tbiso_fields::Field> functions;
    BI::internal::mpi::on_all_ranks(MPI_COMM_WORLD, [&] {
      for(const std::string& spec : o.field_specs)
        functions.push_back(tbiso_fields::make_field(spec));
    });
    tbiso_fields::Analytic_field_source source(grid, std::move(functions));
    print_header("evaluated by slab range");
    MPI_Barrier(MPI_COMM_WORLD);
    start = MPI_Wtime();
    s = extract(source);
    field_megabytes = double(source.evaluated_vertices()) * double(o.field_count) * 8 / 1e6;
  }
  else
  {
    const auto type =
        biso_tools::extension(o.fields_file) == "f32" ? BI::IO::Raw_scalar_type::FLOAT32 : BI::IO::Raw_scalar_type::FLOAT64;
    std::optional<BI::Mpi_raw_scalar_field_reader> reader;
    BI::internal::mpi::on_all_ranks(MPI_COMM_WORLD, [&] {
      reader.emplace(MPI_COMM_WORLD, o.fields_file, grid.number_of_vertices(), o.field_count, type);
    });
    print_header("read by slab range from " + o.fields_file);
    MPI_Barrier(MPI_COMM_WORLD);
    start = MPI_Wtime();
    s = extract(*reader);
    field_seconds = reader->seconds();
    field_megabytes = double(reader->bytes_read()) / 1e6;
  }
  const double total = MPI_Wtime() - start;

  tool.stage("extraction", "extracted, welded and wrote " + std::to_string(s.number_of_faces) + " polygons",
             total);
  report_ranks(tool, s, field_seconds, field_megabytes, ranks);
  std::fprintf(out, "time total:      %.3f s (slowest extraction %.3f s)\n", total, s.max_seconds_extraction);
  std::fprintf(out, "output:     %zu vertices, %zu polygons (%zu tetrahedra evaluated)\n", s.number_of_vertices,
               s.number_of_faces, s.number_of_evaluated_tetrahedra);
  std::fprintf(out, "wrote %s\n", o.output.c_str());
  tool.output(o.output);
  tool.time("total", total);
  tool.summary().set("vertices", s.number_of_vertices);
  tool.summary().set("faces", s.number_of_faces);
  tool.summary().set("ranks_count", size);
  return 0;
}

} // namespace

// Run by `tbiso --distributed` (process_start.h), or directly.
int main(int argc, char** argv)
{
  biso_tools::restart_with_huge_page_heap(argv);
  return biso_tools::mpi::distributed_main<Options, tbiso_tool::Option_text>(
      "tbiso", tbiso_tool::description, argc, argv, tbiso_tool::add_options, check_distributed_options, run);
}
