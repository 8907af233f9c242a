// tbiso --distributed: TBISO on the ranks of MPI_COMM_WORLD, started by
//
//   mpirun -np K tbiso --distributed --grid NX,NY,NZ [--box ...]
//          (--fields FILE.f64|.f32 --field-count N | --field SPEC ...)
//          [--expr TEXT] [--close] [--slab-size LAYERS] [--threads T] -o OUT.ply
//
// Rank r reads only its z slab range plus ghost layers of the raw field file
// (MPI_File_read_at), or evaluates the analytic fields (the specs of
// tbiso_fields.h) at only those vertices, extracts it, welds with its
// neighbours through the exact vertex keys, and writes its part of OUT.ply.
// OUT.ply is byte for byte the file `tbiso --out-of-core` writes in one
// process with the same fields and --slab-size.  Only rank 0
// prints; an error is one line `tbiso: error: ...` on stderr (rank 0) and
// exit status 1 on every rank.  See doc/Boolean_isosurfacing_3/distributed.md.

#include <CGAL/Boolean_isosurfacing_3/MPI/distributed_boolean_isosurface.h>

#include "tbiso_fields.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <mpi.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/global_control.h>
#endif

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

int tbiso_distributed_main(int argc, char** argv);

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef BI::Tetrahedral_grid_3<K> Grid;

struct Options
{
  std::array<std::size_t, 3> grid{{0, 0, 0}};
  std::array<double, 6> box{{-1, -1, -1, 1, 1, 1}};
  std::string fields_file, output, expression = "f0";
  std::vector<std::string> field_specs;
  std::size_t field_count = 0, slab_layers = 8, threads = 0;
  bool close = false;
};

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts(1);
  for(char c : text)
    if(c == separator)
      parts.emplace_back();
    else
      parts.back() += c;
  return parts;
}

std::size_t parse_count(const std::string& text, const std::string& what)
{
  if(text.empty() || text.size() > 12 ||
     !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit((unsigned char)c) != 0; }))
    throw std::invalid_argument(what + ": '" + text + "' is not a whole number");
  return std::size_t(std::stoull(text));
}

double parse_double(const std::string& text, const std::string& what)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    throw std::invalid_argument(what + ": '" + text + "' is not a finite number");
  return v;
}

bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Options parse(int argc, char** argv)
{
  Options o;
  bool have_grid = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--distributed")
      continue;
    if(arg == "--grid")
    {
      const std::vector<std::string> parts = split(value(), ',');
      if(parts.size() != 1 && parts.size() != 3)
        throw std::invalid_argument("--grid: expected N or NX,NY,NZ");
      for(int a = 0; a < 3; ++a)
        o.grid[a] = parse_count(parts[parts.size() == 1 ? 0 : a], "--grid");
      have_grid = true;
    }
    else if(arg == "--box")
    {
      const std::vector<std::string> parts = split(value(), ',');
      if(parts.size() != 6)
        throw std::invalid_argument("--box: expected 6 comma-separated numbers");
      for(int a = 0; a < 6; ++a)
        o.box[a] = parse_double(parts[a], "--box");
      for(int a = 0; a < 3; ++a)
        if(!(o.box[a] < o.box[a + 3]))
          throw std::invalid_argument("--box: the minimum must be below the maximum on every axis");
    }
    else if(arg == "--fields")
      o.fields_file = value();
    else if(arg == "--field")
      o.field_specs.push_back(value());
    else if(arg == "--field-count")
      o.field_count = parse_count(value(), "--field-count");
    else if(arg == "--expr")
      o.expression = value();
    else if(arg == "--close")
      o.close = true;
    else if(arg == "--slab-size")
    {
      o.slab_layers = parse_count(value(), "--slab-size");
      if(o.slab_layers == 0)
        throw std::invalid_argument("--slab-size: at least 1 layer per slab is needed");
    }
    else if(arg == "--threads")
    {
      o.threads = parse_count(value(), "--threads");
      if(o.threads == 0)
        throw std::invalid_argument("--threads: at least 1 thread is needed");
    }
    else if(arg == "--out-of-core" || arg == "--sequential")
      continue; // implied: a distributed run is out of core; one thread per rank unless --threads
    else if(arg == "-o" || arg == "--output")
      o.output = value();
    else
      throw std::invalid_argument("--distributed: unsupported option '" + arg +
                                  "' (--grid, --box, --fields, --field-count, --field, --expr, --close, --slab-size, "
                                  "--threads, -o)");
  }
  if(!have_grid)
    throw std::invalid_argument("--distributed needs --grid");
  if(!o.field_specs.empty())
  {
    if(!o.fields_file.empty())
      throw std::invalid_argument("give either --fields FILE or --field SPEC, not both");
    if(o.field_count != 0)
      throw std::invalid_argument("--field-count is for --fields FILE");
    if(o.field_specs.size() > 64)
      throw std::invalid_argument("at most 64 fields are supported");
    o.field_count = o.field_specs.size();
  }
  else
  {
    const bool f32 = ends_with(o.fields_file, ".f32");
    if(o.fields_file.empty() || !(f32 || ends_with(o.fields_file, ".f64") || ends_with(o.fields_file, ".raw")))
      throw std::invalid_argument("--distributed needs a raw --fields file (.f32, .f64 or .raw) or --field SPEC");
    if(o.field_count == 0)
      throw std::invalid_argument("--distributed: give the number of fields with --field-count N");
  }
  if(!ends_with(o.output, ".ply"))
    throw std::invalid_argument("--distributed writes a binary PLY file: give -o OUT.ply");
  return o;
}

double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

int run(const Options& o, int rank, int size)
{
  const BI::Boolean_expression expression = BI::Boolean_expression::parse(o.expression);
  if(expression.number_of_variables() > o.field_count)
    throw std::invalid_argument("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                                " but there are only " + std::to_string(o.field_count) + " fields");
  const Grid grid = Grid::spanning(K::Point_3(o.box[0], o.box[1], o.box[2]), K::Point_3(o.box[3], o.box[4], o.box[5]),
                                   o.grid);
  const auto np = BI::parameters::close_at_domain_boundary(o.close, BI::parameters::slab_layers(o.slab_layers));
  auto extract = [&](auto& source) {
    return o.threads > 0
               ? BI::extract_boolean_isosurface_distributed<CGAL::Parallel_if_available_tag>(MPI_COMM_WORLD, grid, source,
                                                                                              expression, o.output, np)
               : BI::extract_boolean_isosurface_distributed<CGAL::Sequential_tag>(MPI_COMM_WORLD, grid, source, expression,
                                                                                   o.output, np);
  };
  auto print_header = [&](const std::string& fields) {
    if(rank != 0)
      return;
    const auto& n = grid.vertex_counts();
    std::printf("domain:     grid %zu x %zu x %zu vertices, %zu cube layers on %d rank%s\n", n[0], n[1], n[2], n[2] - 1,
                size, size == 1 ? "" : "s");
    std::printf("fields:     %zu, %s\n", o.field_count, fields.c_str());
    for(std::size_t i = 0; i < o.field_specs.size(); ++i)
      std::printf("  f%zu = %s\n", i, o.field_specs[i].c_str());
    std::printf("expression: %s%s\n", expression.to_string().c_str(), o.close ? ", closed at the domain boundary" : "");
    std::fflush(stdout);
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
        ends_with(o.fields_file, ".f32") ? BI::IO::Raw_scalar_type::FLOAT32 : BI::IO::Raw_scalar_type::FLOAT64;
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

  // One line per rank, gathered on rank 0.
  const std::vector<double> mine{double(s.first_layer),
                                 double(s.last_layer),
                                 double(s.rank_vertices),
                                 double(s.rank_polygons),
                                 s.extraction_seconds,
                                 field_seconds,
                                 s.welding_seconds,
                                 s.writing_seconds,
                                 field_megabytes,
                                 8.0 * double(s.sent_words) / 1e3,
                                 double(s.peak_field_values) * 8 / 1e6,
                                 peak_resident_megabytes(),
                                 s.extracted_again ? 1.0 : 0.0};
  std::vector<double> all(mine.size() * std::size_t(size));
  MPI_Gather(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), int(mine.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if(rank == 0)
  {
    // "read MB": bytes read from the file, or the field values evaluated (8 bytes each).
    std::printf("rank  layers          vertices   polygons  extract(s)  read(s)  weld(s)  write(s)  read MB  sent kB"
                "  fields MB  peak RSS MB\n");
    for(int r = 0; r < size; ++r)
    {
      const double* v = all.data() + mine.size() * std::size_t(r);
      char layers[48];
      std::snprintf(layers, sizeof layers, "[%.0f, %.0f)", v[0], v[1]);
      std::printf("%4d  %-14s %9.0f  %9.0f  %10.3f  %7.3f  %7.3f  %8.3f  %7.1f  %7.1f  %9.1f  %11.1f\n", r, layers, v[2],
                  v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]);
      if(v[12] != 0)
        std::printf("      (extracted again with the message from below: two bottom-layer vertices at one position)\n");
    }
    std::printf("time total:      %.3f s (slowest extraction %.3f s)\n", total, s.max_extraction_seconds);
    std::printf("output:     %zu vertices, %zu polygons (%zu tetrahedra evaluated)\n", s.number_of_vertices,
                s.number_of_polygons, s.number_of_evaluated_tetrahedra);
    std::printf("wrote %s\n", o.output.c_str());
  }
  return 0;
}

} // namespace

// Called by tbiso's main() when --distributed is on the command line.
int tbiso_distributed_main(int argc, char** argv)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int status = 1;
  try
  {
    const Options o = parse(argc, argv); // the same on every rank: all fail or none
#ifdef CGAL_LINKED_WITH_TBB
    std::optional<tbb::global_control> limit;
    if(o.threads > 0)
      limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
#endif
    status = run(o, rank, size);
  }
  catch(const BI::Distributed_error& e)
  {
    if(rank == 0)
      std::cerr << "tbiso: error: " << e.what() << "\n";
  }
  catch(const std::exception& e)
  {
    // Thrown identically on every rank (arguments, the expression, the grid).
    if(rank == 0)
      std::cerr << "tbiso: error: " << e.what() << "\n";
  }
  MPI_Finalize();
  return status;
}
