// csg --distributed: Marching Cubes CSG on the ranks of MPI_COMM_WORLD, started by
//
//   mpirun -np K csg --distributed --no-features A B ... (--op OP | --expr TEXT) (--cells N | --spacing r) -o OUT.off
//
// Every rank reads the meshes and classifies only the lattice lines of its
// z slab range; the ranks weld through lattice-edge ids and write OUT.off
// collectively, byte for byte the file `csg --no-features ... -o OUT.off`
// writes in one process (sharp features are not distributed yet).  Only rank 0 prints; an error is one line on stderr (rank 0) and
// a non-zero exit on every rank.  See doc/Boolean_isosurfacing_3/distributed.md.

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/MPI/distributed_marching_cubes_csg.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <mpi.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/global_control.h>
#endif

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

int csg_distributed_main(int argc, char** argv);

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// A bad command line: exit status 2, as csg's usage errors.
class Usage_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::vector<std::string> files;
  std::string op, expression, output;
  std::size_t cells = 0, threads = 0;
  double spacing = 0;
  bool no_features = false;
};

bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error(arg + " needs a value");
      return argv[++i];
    };
    auto number = [&]() {
      const std::string text = value();
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if(end == text.c_str() || *end != '\0' || !std::isfinite(v) || v <= 0)
        throw Usage_error(arg + ": '" + text + "' is not a positive number");
      return v;
    };
    if(arg == "--distributed" || arg == "--sequential")
      continue;
    else if(arg == "--no-features")
      o.no_features = true;
    else if(arg == "--op")
      o.op = value();
    else if(arg == "--expr")
      o.expression = value();
    else if(arg == "-o" || arg == "--output")
      o.output = value();
    else if(arg == "--cells")
    {
      const double v = number();
      if(v != std::floor(v) || v > 1e6)
        throw Usage_error("--cells: not a whole number of cells");
      o.cells = std::size_t(v);
    }
    else if(arg == "--spacing")
      o.spacing = number();
    else if(arg == "--threads")
    {
      const double v = number();
      if(v != std::floor(v))
        throw Usage_error("--threads: not a whole number");
      o.threads = std::size_t(v);
    }
    else if(!arg.empty() && arg[0] == '-')
      throw Usage_error("--distributed: unsupported option " + arg +
                                  " (--op, --expr, --cells, --spacing, --threads, --no-features, -o)");
    else
      o.files.push_back(arg);
  }
  if(o.files.empty())
    throw Usage_error("no input file");
  if(o.op.empty() == o.expression.empty())
    throw Usage_error("give exactly one of --op and --expr");
  if((o.cells > 0) == (o.spacing > 0))
    throw Usage_error("give exactly one of --cells N and --spacing r");
  // Sharp features number their vertices after all edge vertices, flip
  // edges between cubes of different ranks and collapse short edges on the
  // whole mesh: not distributed yet.  Refused rather than silently a
  // different output than `csg` without the flag.
  if(!o.no_features)
    throw Usage_error("--distributed computes plain Marching Cubes only: add --no-features (the output is then "
                      "byte for byte the one of csg --no-features)");
  if(!ends_with(o.output, ".off"))
    throw Usage_error("--distributed writes an OFF file: give -o OUT.off");
  return o;
}

// As csg.cpp (expression_from): variable m is input m.
BI::Boolean_expression expression_from(const Options& o, std::size_t number_of_meshes)
{
  if(!o.expression.empty())
  {
    const BI::Boolean_expression parsed = BI::Boolean_expression::parse(o.expression);
    if(parsed.number_of_variables() > number_of_meshes)
      throw BI::Invalid_input_error("the expression names " + std::to_string(parsed.number_of_variables()) +
                                    " inputs but " + std::to_string(number_of_meshes) + " files were given");
    return BI::Boolean_expression(number_of_meshes, parsed.terms());
  }
  if(number_of_meshes != 2)
    throw BI::Invalid_input_error("--op needs exactly two input files (use --expr for more)");
  if(o.op == "union") return BI::Boolean_expression::union_of(2);
  if(o.op == "intersection") return BI::Boolean_expression::intersection_of(2);
  if(o.op == "difference") return BI::Boolean_expression::difference();
  throw BI::Invalid_input_error("unknown operation '" + o.op + "' (union, intersection or difference)");
}

// The lattice of csg.cpp's run_csg(), which the byte-identity tests check:
// the library's enclosing lattice (its default offset keeps the box's faces
// off the lattice planes).
BI::Regular_lattice_3 csg_lattice(const std::vector<Mesh>& meshes, const Options& o)
{
  CGAL::Bbox_3 box;
  for(const Mesh& m : meshes)
    box += PMP::bbox(m);
  return o.cells > 0 ? BI::Regular_lattice_3::enclosing_with_cells(box, o.cells)
                     : BI::Regular_lattice_3::enclosing(box, o.spacing);
}

double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

int run(const Options& o, int rank, int size)
{
  std::vector<Mesh> meshes(o.files.size());
  // Every rank reads the meshes: the same outcome everywhere.
  for(std::size_t i = 0; i < o.files.size(); ++i)
    try
    {
      BI::IO::read_closed_triangle_mesh(o.files[i], meshes[i]);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw BI::Invalid_input_error(o.files[i] + ": " + e.what());
    }
  const BI::Boolean_expression expression = expression_from(o, meshes.size());
  const BI::Regular_lattice_3 lattice = csg_lattice(meshes, o);
  if(rank == 0)
  {
    const auto& n = lattice.number_of_points();
    std::printf("csg %s over %zu meshes on %d rank%s\n", expression.to_string().c_str(), meshes.size(), size,
                size == 1 ? "" : "s");
    std::printf("  lattice %zu x %zu x %zu points (%zu), spacing %.6g, %zu cube layers\n", n[0], n[1], n[2],
                lattice.total_number_of_points(), lattice.spacing(), n[2] - 1);
    std::fflush(stdout);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  const BI::Marching_cubes_csg_distributed_statistics s =
      o.threads > 0
          ? BI::marching_cubes_csg_distributed<CGAL::Parallel_if_available_tag>(MPI_COMM_WORLD, meshes, expression,
                                                                                 lattice, o.output)
          : BI::marching_cubes_csg_distributed<CGAL::Sequential_tag>(MPI_COMM_WORLD, meshes, expression, lattice,
                                                                      o.output);
  const double total = MPI_Wtime() - start;
  const std::vector<double> mine{double(s.first_layer),       double(s.last_layer),      double(s.rank_lattice_points),
                                 double(s.rank_input_triangles), double(s.rank_vertices), double(s.rank_triangles),
                                 s.extraction_seconds,        s.welding_seconds,         s.writing_seconds,
                                 8.0 * double(s.sent_words) / 1e3, peak_resident_megabytes()};
  std::vector<double> all(mine.size() * std::size_t(size));
  MPI_Gather(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), int(mine.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if(rank == 0)
  {
    std::printf("rank  layers         lattice pts  input tris   vertices  triangles  extract(s)  weld(s)  write(s)"
                "  sent kB  peak RSS MB\n");
    for(int r = 0; r < size; ++r)
    {
      const double* v = all.data() + mine.size() * std::size_t(r);
      char layers[48];
      std::snprintf(layers, sizeof layers, "[%.0f, %.0f)", v[0], v[1]);
      std::printf("%4d  %-14s %11.0f  %10.0f  %9.0f  %9.0f  %10.3f  %7.3f  %8.3f  %7.1f  %11.1f\n", r, layers, v[2], v[3],
                  v[4], v[5], v[6], v[7], v[8], v[9], v[10]);
    }
    std::printf("  total %.3f s (slowest extraction %.3f s)\n", total, s.max_extraction_seconds);
    std::printf("  output %zu vertices, %zu triangles\n", s.number_of_vertices, s.number_of_triangles);
    if(s.number_of_triangles == 0)
      std::printf("  the result is empty\n");
    else
      std::printf("  volume %.9g\n", s.volume);
    std::printf("wrote %s\n", o.output.c_str());
  }
  return 0;
}

} // namespace

// Called by csg's main() when --distributed is on the command line.
int csg_distributed_main(int argc, char** argv)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int status = 1;
  try
  {
    const Options o = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
    std::optional<tbb::global_control> limit;
    if(o.threads > 0)
      limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
#endif
    status = run(o, rank, size);
  }
  catch(const Usage_error& e)
  {
    if(rank == 0)
      std::cerr << "csg: " << e.what() << "\n";
    status = 2;
  }
  catch(const std::exception& e)
  {
    if(rank == 0)
      std::cerr << "csg: " << e.what() << "\n";
  }
  MPI_Finalize();
  return status;
}
