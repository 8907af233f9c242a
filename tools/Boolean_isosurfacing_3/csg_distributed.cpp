// csg --distributed: Marching Cubes CSG on the ranks of MPI_COMM_WORLD, started by
//
//   mpirun -np K csg --distributed --no-features A B ... (--op OP | --expr TEXT) (--cells N | --spacing h)
//          [--max-memory G] -o OUT.off|OUT.obj|OUT.ply
//
// Every rank reads the meshes and classifies only the lattice lines of its
// z slab range; the ranks weld through lattice-edge ids and write OUT
// collectively, byte for byte the file `csg --no-features ... -o OUT`
// writes in one process (sharp features are not distributed: see
// doc/Boolean_isosurfacing_3/distributed.md for why and what it would take).  The options are csg's
// (csg_options.h), the MPI frame mpi_driver.h's.  Only rank 0 prints; an error is one line on stderr (rank 0) and
// a non-zero exit on every rank.  See doc/Boolean_isosurfacing_3/distributed.md.

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/MPI/distributed_marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/result_bounding_box.h>

#include "csg_options.h"
#include "kernels.h"
#include "mpi_driver.h"
#include "process_start.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>


namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using biso_tools::Mesh;
using biso_tools::Usage_error;
using biso_tools::mpi::Ranks;
using csg_tool::Options;

// csg's options (csg_options.h), and what --distributed does not do.
void check_distributed_options(biso_tools::Tool& tool, Options& o, const csg_tool::Option_text& t)
{
  csg_tool::check_options(tool, o, t);
  const CLI::App& app = tool.app();
  for(const char* flag : {"--demo", "--creases", "--corners", "--strict", "--unbounded", "--feature-angle"})
    if(app.count(flag))
      throw Usage_error(std::string("--distributed: unsupported option ") + flag +
                        " (--op, --expr, --cells, --spacing, --threads, --max-memory, --no-features, -o)");
  if(o.files.empty())
    throw Usage_error("no input file");
  if(o.have_op == o.have_expression)
    throw Usage_error("give exactly one of --op and --expr");
  if((o.cells > 0) == (o.spacing > 0))
    throw Usage_error("give exactly one of --cells N and --spacing h");
  // Sharp features number their vertices after all edge vertices, flip
  // edges between cubes of different ranks and collapse short edges on the
  // whole mesh: not distributed yet.  Refused rather than silently a
  // different output than `csg` without the flag.
  if(o.features)
    throw Usage_error("--distributed computes plain Marching Cubes only: add --no-features (the output is then "
                      "byte for byte the one of csg --no-features)");
  const std::string format = biso_tools::extension(o.output);
  if(format != "off" && format != "obj" && format != "ply")
    throw Usage_error("--distributed writes OFF, OBJ or binary PLY: give -o OUT.off, OUT.obj or OUT.ply");
  // One thread per rank unless --threads.
  o.parallel = app.count("--threads") > 0 && tool.parallel();
}

// The lattice of csg.cpp's run() and run_csg(), which the byte-identity
// tests check: the library's enclosing lattice (its default offset keeps the
// box's faces off the lattice planes) of the box where the result can be
// (`result_bounding_box()`), or of all the inputs' box when it cannot be
// anywhere.  An unbounded result is refused: csg clips it with an extra box
// mesh, which is not distributed.
BI::Regular_lattice_3 csg_lattice(const std::vector<Mesh>& meshes, const BI::Boolean_expression& expression,
                                  const Options& o)
{
  if(expression.evaluate(0))
    throw BI::Invalid_input_error("--distributed: the result is unbounded (the expression holds outside every "
                                  "input); csg clips it to a box, which --distributed does not do");
  std::vector<CGAL::Bbox_3> boxes;
  CGAL::Bbox_3 all;
  for(const Mesh& m : meshes)
  {
    boxes.push_back(PMP::bbox(m));
    all += boxes.back();
  }
  const BI::Result_bounding_box result = BI::result_bounding_box(expression, boxes);
  const CGAL::Bbox_3 box = result.bounded && !result.empty ? result.box : all;
  return o.cells > 0 ? BI::Regular_lattice_3::enclosing_with_cells(box, o.cells)
                     : BI::Regular_lattice_3::enclosing(box, o.spacing);
}

// One line per rank, gathered on rank 0.
void report_ranks(biso_tools::Tool& tool, const BI::Marching_cubes_csg_distributed_statistics& s, const Ranks& ranks)
{
  const biso_tools::mpi::Rank_table table = biso_tools::mpi::gather_on_root(
      {"first_layer", "last_layer", "lattice_points", "input_triangles", "vertices", "triangles",
       "extraction_seconds", "welding_seconds", "writing_seconds", "sent_kilobytes", "peak_resident_megabytes"},
      {double(s.first_layer), double(s.last_layer), double(s.rank_lattice_points), double(s.rank_input_triangles),
       double(s.rank_vertices), double(s.rank_faces), s.seconds_extraction, s.seconds_welding,
       s.seconds_writing, 8.0 * double(s.sent_words) / 1e3, biso_tools::mpi::peak_resident_megabytes()},
      ranks);
  if(ranks.rank != 0)
    return;
  std::FILE* out = tool.human();
  std::fprintf(out, "rank  layers         lattice pts  input tris   vertices  triangles  extract(s)  weld(s)  write(s)"
                    "  sent kB  peak RSS MB\n");
  for(int r = 0; r < ranks.size; ++r)
  {
    const double* v = table.row(r);
    char layers[48];
    std::snprintf(layers, sizeof layers, "[%.0f, %.0f)", v[0], v[1]);
    std::fprintf(out, "%4d  %-14s %11.0f  %10.0f  %9.0f  %9.0f  %10.3f  %7.3f  %8.3f  %7.1f  %11.1f\n", r, layers,
                 v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10]);
  }
  biso_tools::mpi::set_json_ranks(tool, table, ranks.size);
}

int run(biso_tools::Tool& tool, const Options& o, const Ranks& ranks)
{
  const int size = ranks.size;
  std::FILE* out = tool.human(); // nowhere on ranks other than 0
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
  const BI::Boolean_expression expression = csg_tool::expression_from(o, meshes.size());
  const BI::Regular_lattice_3 lattice = csg_lattice(meshes, expression, o);
  const auto& n = lattice.number_of_points();
  std::fprintf(out, "csg %s over %zu meshes on %d rank%s\n", expression.to_string().c_str(), meshes.size(), size,
               size == 1 ? "" : "s");
  std::fprintf(out, "  lattice %zu x %zu x %zu points (%zu), spacing %.6g, %zu cube layers\n", n[0], n[1], n[2],
               lattice.total_number_of_points(), lattice.spacing(), n[2] - 1);
  std::fflush(out);
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  // --max-memory bounds each rank's estimate (its slab range), not the whole lattice's.
  const std::size_t max_memory = o.max_memory_gib > 0 ? std::size_t(o.max_memory_gib * double(std::size_t(1) << 30))
                                                      : BI::Lattice_classifier_3::default_max_memory_bytes;
  const auto np = BI::parameters::max_memory_bytes(max_memory);
  const BI::Marching_cubes_csg_distributed_statistics s =
      o.parallel
          ? BI::marching_cubes_csg_distributed<CGAL::Parallel_if_available_tag>(MPI_COMM_WORLD, lattice, meshes,
                                                                                 expression, o.output, np)
          : BI::marching_cubes_csg_distributed<CGAL::Sequential_tag>(MPI_COMM_WORLD, lattice, meshes, expression,
                                                                      o.output, np);
  const double total = MPI_Wtime() - start;
  tool.stage("extraction", "extracted, welded and wrote " + std::to_string(s.number_of_faces) + " triangles",
             total);
  report_ranks(tool, s, ranks);
  std::fprintf(out, "  total %.3f s (slowest extraction %.3f s)\n", total, s.max_seconds_extraction);
  std::fprintf(out, "  output %zu vertices, %zu triangles\n", s.number_of_vertices, s.number_of_faces);
  if(s.number_of_faces == 0)
    std::fprintf(out, "  the result is empty\n");
  else
    std::fprintf(out, "  volume %.9g\n", s.volume);
  std::fprintf(out, "wrote %s\n", o.output.c_str());
  tool.output(o.output);
  tool.time("total", total);
  biso_tools::Json_object& j = tool.summary();
  j.set("expression", expression.to_string());
  j.set("vertices", s.number_of_vertices);
  j.set("faces", s.number_of_faces);
  j.set("volume", s.volume);
  j.set("ranks_count", size);
  return 0;
}

} // namespace

// Run by `csg --distributed` (process_start.h), or directly.
int main(int argc, char** argv)
{
  biso_tools::restart_with_huge_page_heap(argv);
  return biso_tools::mpi::distributed_main<Options, csg_tool::Option_text>(
      "csg", csg_tool::description, argc, argv, csg_tool::add_options, check_distributed_options, run);
}
