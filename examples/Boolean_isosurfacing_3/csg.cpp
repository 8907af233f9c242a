// csg: Boolean operations on closed triangle meshes by Marching Cubes.
//
//   csg A B --op union|intersection|difference (--cells N | --spacing r) [-o out.off] [--threads T]
//   csg A B C ... --expr "A & !B | C" (--cells N | --spacing r) [-o out.off]
//   csg --demo DIR
//
// Reads OFF/OBJ/PLY/STL; the i-th input is the variable A, B, C, ... of the
// expression (also f0, f1, ...).  Prints the lattice size, the time of each
// stage, the output size and the output's Surveyor volume.  Bad input gets one
// line on stderr and a non-zero exit.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

struct Options
{
  std::vector<std::string> files;
  std::string op, expression, output, demo_dir;
  std::size_t cells = 0;
  double spacing = 0;
  bool parallel = true;
};

int usage(const std::string& message)
{
  std::cerr << "csg: " << message << "\n"
            << "usage: csg A B --op union|intersection|difference (--cells N | --spacing r) [-o out.off]\n"
            << "       csg A B C ... --expr \"A & !B | C\" (--cells N | --spacing r) [-o out.off]\n"
            << "       csg --demo DIR\n"
            << "options: --sequential (default: parallel when built with TBB)\n";
  return 2;
}

// A progress bar on stderr, only for runs that last and only on a terminal.
class Progress_bar
{
public:
  void operator()(double fraction) const
  {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if(seconds < 1.0 || !isatty(2)) return;
    const int width = 40, done = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(done, '#').c_str(), std::string(width - done, ' ').c_str(),
                 int(fraction * 100 + 0.5));
    if(fraction >= 1.0) std::fprintf(stderr, "\r%*s\r", width + 8, "");
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

BI::Boolean_expression expression_from(const Options& options, std::size_t number_of_meshes)
{
  if(!options.expression.empty())
  {
    const BI::Boolean_expression parsed = BI::Boolean_expression::parse(options.expression);
    if(parsed.number_of_variables() > number_of_meshes)
      throw BI::Invalid_input_error("the expression names " + std::to_string(parsed.number_of_variables()) +
                                    " inputs but " + std::to_string(number_of_meshes) + " files were given");
    return BI::Boolean_expression(number_of_meshes, parsed.terms());
  }
  if(number_of_meshes != 2)
    throw BI::Invalid_input_error("--op needs exactly two input files (use --expr for more)");
  if(options.op == "union") return BI::Boolean_expression::union_of(2);
  if(options.op == "intersection") return BI::Boolean_expression::intersection_of(2);
  if(options.op == "difference") return BI::Boolean_expression::difference();
  throw BI::Invalid_input_error("unknown operation '" + options.op + "' (union, intersection or difference)");
}

struct Result
{
  Mesh mesh;
  BI::Marching_cubes_csg_statistics statistics;
  BI::Regular_lattice_3 lattice;
};

Result run_csg(const std::vector<Mesh>& meshes, const BI::Boolean_expression& expression, const Options& options)
{
  CGAL::Bbox_3 box;
  for(const Mesh& m : meshes) box += PMP::bbox(m);
  const BI::Regular_lattice_3 enclosing = options.cells > 0
                                              ? BI::Regular_lattice_3::enclosing_with_cells(box, options.cells)
                                              : BI::Regular_lattice_3::enclosing(box, options.spacing);
  // `enclosing` puts a lattice plane on each side of the bounding box, so
  // inputs with axis-aligned faces there (CAD parts) would have whole faces
  // on lattice planes: still a correct, closed, 2-manifold result (one
  // symbolic convention decides), but several lattice edges then put their
  // vertex on the same lattice point, giving zero-area triangles.  Shifting
  // the lattice by an irrational-looking fraction of a cell, with one more
  // point per axis, moves those planes off the box.
  const double shift = 0.381966011250105 * enclosing.spacing(); // (3 - sqrt 5) / 2
  std::array<double, 3> origin = enclosing.origin();
  std::array<std::size_t, 3> counts = enclosing.number_of_points();
  for(int a = 0; a < 3; ++a)
  {
    origin[a] -= shift;
    ++counts[a];
  }
  const BI::Regular_lattice_3 lattice(origin, enclosing.spacing(), counts);
  Mesh output;
  const Progress_bar progress;
  BI::Marching_cubes_csg_statistics statistics;
#ifdef CGAL_LINKED_WITH_TBB
  if(options.parallel)
    statistics = BI::marching_cubes_csg<CGAL::Parallel_tag>(meshes, expression, lattice, output,
                                                             BI::parameters::progress(progress));
  else
#endif
    statistics = BI::marching_cubes_csg<CGAL::Sequential_tag>(meshes, expression, lattice, output,
                                                               BI::parameters::progress(progress));
  return {std::move(output), statistics, lattice};
}

void print_result(const Result& r)
{
  const auto& n = r.lattice.number_of_points();
  const auto& s = r.statistics;
  std::printf("  lattice %zu x %zu x %zu points (%zu), spacing %.6g\n", n[0], n[1], n[2], s.lattice_points,
              r.lattice.spacing());
  std::printf("  classification %.3f s, edge points %.3f s, triangulation %.3f s (%zu crossings)\n",
              s.seconds_classification, s.seconds_edges, s.seconds_triangulation, s.crossings);
  std::printf("  output %zu vertices, %zu triangles\n", std::size_t(r.mesh.number_of_vertices()),
              std::size_t(r.mesh.number_of_faces()));
}

double exact_volume(const CGAL::Surface_mesh<Epeck::Point_3>& m)
{
  return CGAL::to_double(CGAL::exact(PMP::volume(m)));
}

int run_demo(Options options)
{
  const std::string& dir = options.demo_dir;
  if(mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
  {
    std::cerr << "csg: cannot create directory " << dir << "\n";
    return 1;
  }
  // The built-in pair: a sphere and a torus that cuts through it.
  std::vector<Mesh> meshes(2);
  BI::make_icosphere(meshes[0], Point(0, 0, 0), 1.0, 4);
  BI::make_torus(meshes[1], Point(0.9, 0, 0), 0.8, 0.35, 96, 48);
  CGAL::IO::write_polygon_mesh(dir + "/A_sphere.off", meshes[0], CGAL::parameters::stream_precision(17));
  CGAL::IO::write_polygon_mesh(dir + "/B_torus.off", meshes[1], CGAL::parameters::stream_precision(17));
  std::printf("Marching Cubes CSG of a sphere (A, %zu triangles) and a torus through it (B, %zu triangles),\n"
              "written with the results to %s/.  'exact' is the volume of the exact Boolean result\n"
              "of the same polyhedra (PMP corefinement with Epeck).\n\n",
              std::size_t(meshes[0].number_of_faces()), std::size_t(meshes[1].number_of_faces()), dir.c_str());

  typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
  Exact_mesh a, b;
  CGAL::copy_face_graph(meshes[0], a);
  CGAL::copy_face_graph(meshes[1], b);
  const std::pair<const char*, BI::Boolean_expression> operations[] = {
      {"union", BI::Boolean_expression::union_of(2)},
      {"intersection", BI::Boolean_expression::intersection_of(2)},
      {"difference", BI::Boolean_expression::difference()}};
  if(options.cells == 0 && options.spacing == 0) options.cells = 128;
  for(const auto& [name, expression] : operations)
  {
    Exact_mesh a_copy = a, b_copy = b, exact_result;
    const std::string op = name;
    if(op == "union") PMP::corefine_and_compute_union(a_copy, b_copy, exact_result);
    else if(op == "intersection") PMP::corefine_and_compute_intersection(a_copy, b_copy, exact_result);
    else PMP::corefine_and_compute_difference(a_copy, b_copy, exact_result);
    const double exact = exact_volume(exact_result);

    const Result r = run_csg(meshes, expression, options);
    const double ours = BI::surveyor_volume(r.mesh);
    std::printf("%s (%s)\n", name, expression.to_string().c_str());
    print_result(r);
    std::printf("  volume %.6f   exact %.6f   relative error %.2e\n\n", ours, exact, std::abs(ours - exact) / exact);
    CGAL::IO::write_polygon_mesh(dir + "/" + op + ".off", r.mesh, CGAL::parameters::stream_precision(17));
  }
  return 0;
}

int run(const Options& options)
{
  if(options.files.empty()) return usage("no input file");
  if(options.op.empty() == options.expression.empty()) return usage("give exactly one of --op and --expr");
  if((options.cells > 0) == (options.spacing > 0)) return usage("give exactly one of --cells N and --spacing r");
  std::vector<Mesh> meshes(options.files.size());
  for(std::size_t i = 0; i < options.files.size(); ++i)
  {
    try
    {
      BI::IO::read_closed_triangle_mesh(options.files[i], meshes[i]);
    }
    catch(const BI::Invalid_input_error& e)
    {
      std::cerr << "csg: " << options.files[i] << ": " << e.what() << "\n";
      return 1;
    }
  }
  const BI::Boolean_expression expression = expression_from(options, meshes.size());
  const auto start = std::chrono::steady_clock::now();
  const Result r = run_csg(meshes, expression, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("csg %s over %zu meshes\n", expression.to_string().c_str(), meshes.size());
  print_result(r);
  std::printf("  total %.3f s\n", seconds);
  if(r.mesh.number_of_faces() == 0)
    std::printf("  the result is empty\n");
  else
    std::printf("  volume %.9g\n", BI::surveyor_volume(r.mesh));
  if(!options.output.empty() &&
     !CGAL::IO::write_polygon_mesh(options.output, r.mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "csg: cannot write " << options.output << "\n";
    return 1;
  }
  return 0;
}

bool parse_number(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && std::isfinite(value);
}

} // namespace

#ifdef BISO_WITH_MPI
int csg_distributed_main(int argc, char** argv); // csg_distributed.cpp
#endif

int main(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--distributed")
    {
#ifdef BISO_WITH_MPI
      return csg_distributed_main(argc, argv);
#else
      std::cerr << "csg: --distributed: this csg was built without MPI\n";
      return 1;
#endif
    }
  Options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* what) -> std::string {
      if(i + 1 >= argc) throw std::invalid_argument(arg + " needs " + what);
      return argv[++i];
    };
    try
    {
      if(arg == "--op") options.op = value("an operation");
      else if(arg == "--expr") options.expression = value("an expression");
      else if(arg == "-o" || arg == "--output") options.output = value("a file name");
      else if(arg == "--demo") options.demo_dir = value("a directory");
      else if(arg == "--sequential") options.parallel = false;
      else if(arg == "--cells" || arg == "--spacing")
      {
        double v = 0;
        const std::string text = value("a number");
        if(!parse_number(text, v) || v <= 0) return usage(arg + ": '" + text + "' is not a positive number");
        if(arg == "--cells")
        {
          if(v != std::floor(v) || v > 1e6) return usage("--cells: '" + text + "' is not a whole number of cells");
          options.cells = std::size_t(v);
        }
        else
          options.spacing = v;
      }
      else if(arg == "-h" || arg == "--help") { usage("Boolean operations on closed meshes by Marching Cubes"); return 0; }
      else if(!arg.empty() && arg[0] == '-') return usage("unknown option " + arg);
      else options.files.push_back(arg);
    }
    catch(const std::invalid_argument& e)
    {
      return usage(e.what());
    }
  }
  try
  {
    if(!options.demo_dir.empty()) return run_demo(options);
    return run(options);
  }
  catch(const BI::Invalid_input_error& e)
  {
    std::cerr << "csg: " << e.what() << "\n";
    return 1;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "csg: out of memory (use a coarser lattice)\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "csg: " << e.what() << "\n";
    return 1;
  }
}
