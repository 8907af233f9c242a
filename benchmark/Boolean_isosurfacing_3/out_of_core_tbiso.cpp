// Out-of-core TBISO on a grid whose fields do not fit comfortably in memory.
//
//   out_of_core_tbiso [N=1024] [FIELDS=/tmp/tbiso_N.f32] [OUTPUT=/tmp/tbiso_N.ply] [SLAB=4] [--sequential]
//
// Writes (once) the 4 fields of the seed set-up of benchmark_boolean_isosurface
// (4 spheres, "at least two of four") on an N^3 grid as raw float32
// (N = 1024: 17.2 GB), then extracts the surface slab by slab, streaming it
// to a binary PLY file, and prints the time of each stage and the peak
// resident memory of the process (getrusage).

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_by_slabs.h>
#include <CGAL/Boolean_isosurfacing_3/IO/Boolean_isosurface_PLY_stream.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef BI::Tetrahedral_grid_3<K> Grid;

namespace {

double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void write_fields(const Grid& grid, const std::string& filename)
{
  const double a = 0.45 / std::sqrt(3.), r = 0.62;
  const double centres[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  const auto n = grid.vertex_counts();
  std::ofstream out(filename, std::ios::binary | std::ios::trunc);
  std::vector<float> layer(n[0] * n[1] * 4);
  for(std::size_t k = 0; k < n[2]; ++k)
  {
    BI::internal::concurrent_for<CGAL::Parallel_if_available_tag>(n[1], [&](std::size_t j) {
      for(std::size_t i = 0; i < n[0]; ++i)
      {
        const auto p = grid.position(grid.vertex_index(i, j, k));
        for(int f = 0; f < 4; ++f)
        {
          const double x = p[0] - centres[f][0], y = p[1] - centres[f][1], z = p[2] - centres[f][2];
          layer[(i + n[0] * j) * 4 + f] = float(std::sqrt(x * x + y * y + z * z) - r);
        }
      }
    });
    out.write(reinterpret_cast<const char*>(layer.data()), std::streamsize(layer.size() * sizeof(float)));
  }
  if(!out)
    throw std::runtime_error("failed writing " + filename);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  bool sequential = false;
  for(auto it = args.begin(); it != args.end();)
    if(*it == "--sequential")
    {
      sequential = true;
      it = args.erase(it);
    }
    else
      ++it;
  const std::size_t N = args.size() > 0 ? std::stoul(args[0]) : 1024;
  const std::string fields = args.size() > 1 ? args[1] : "/tmp/tbiso_" + std::to_string(N) + ".f32";
  const std::string output = args.size() > 2 ? args[2] : "/tmp/tbiso_" + std::to_string(N) + ".ply";
  const std::size_t slab = args.size() > 3 ? std::stoul(args[3]) : 4;

  const Grid grid = Grid::spanning(K::Point_3(-1, -1, -1), K::Point_3(1, 1, 1), {N, N, N});
  const std::uintmax_t bytes = std::uintmax_t(grid.number_of_vertices()) * 4 * sizeof(float);
  std::cout << "grid " << N << "^3: " << grid.number_of_vertices() << " vertices, " << grid.number_of_tetrahedra()
            << " tetrahedra; 4 fields as float32: " << double(bytes) / 1e9 << " GB in " << fields << "\n";
  std::error_code ec;
  if(!std::filesystem::exists(fields) || std::filesystem::file_size(fields, ec) != bytes)
  {
    const auto t = std::chrono::steady_clock::now();
    write_fields(grid, fields);
    std::cout << "writing the fields: " << seconds_since(t) << " s\n";
  }

  const BI::Boolean_expression e =
      BI::Boolean_expression::parse("f0 & f1 | f0 & f2 | f0 & f3 | f1 & f2 | f1 & f3 | f2 & f3");
  BI::IO::Raw_scalar_field_reader reader(fields, grid.number_of_vertices(), 4, BI::IO::Raw_scalar_type::FLOAT32);
  BI::IO::Boolean_isosurface_PLY_stream ply(output);
  const auto t = std::chrono::steady_clock::now();
  BI::Boolean_isosurface_slab_statistics stats;
  if(sequential)
    stats = BI::extract_boolean_isosurface_by_slabs<CGAL::Sequential_tag>(grid, reader, e, ply,
                                                                         BI::parameters::slab_layers(slab));
  else
    stats = BI::extract_boolean_isosurface_by_slabs<CGAL::Parallel_if_available_tag>(
        grid, reader, e, ply, BI::parameters::slab_layers(slab));
  ply.close();
  const double total = seconds_since(t);
  std::cout << (sequential ? "sequential" : "parallel") << ", " << stats.number_of_slabs << " slabs of " << slab
            << " layers\n"
            << "extraction end to end: " << total << " s (reading " << stats.seconds_reading
            << " s summed over threads, evaluation+reading wall " << stats.seconds_extraction << " s, welding+writing "
            << stats.seconds_welding << " s)\n"
            << "evaluated tetrahedra: " << stats.number_of_evaluated_tetrahedra << "\n"
            << "output: " << stats.number_of_vertices << " vertices, " << stats.number_of_faces << " polygons, "
            << double(std::filesystem::file_size(output)) / 1e6 << " MB in " << output << "\n"
            << "field values held at once: " << stats.peak_field_values << " ("
            << double(stats.peak_field_values) * 8 / 1e6 << " MB as double)\n"
            << "peak resident memory: " << peak_resident_megabytes() << " MB\n";
  return 0;
}
