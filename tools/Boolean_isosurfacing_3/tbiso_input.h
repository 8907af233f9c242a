// tbiso's inputs: the domain (a grid or a tetrahedral mesh file), the memory
// check of a grid, and the fields at its vertices (read from a file, or the
// analytic functions evaluated there).

#ifndef BISO_TOOLS_TBISO_INPUT_H
#define BISO_TOOLS_TBISO_INPUT_H

#include "tbiso_fields.h"
#include "tbiso_options.h"

#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/blocked_range.h>
#  include <tbb/parallel_for.h>
#endif

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace tbiso_tool {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Tetrahedral_grid_3<K> Grid;
typedef BI::Tetrahedral_mesh_3<K> Tet_mesh;
using tbiso_fields::Error;

// The memory the process may still use: MemAvailable, or less under a
// limit on the address space; 0 when unknown.
inline double available_bytes()
{
  double available = 0;
  if(std::FILE* f = std::fopen("/proc/meminfo", "r"))
  {
    char line[256];
    while(std::fgets(line, sizeof line, f))
    {
      unsigned long long kb = 0;
      if(std::sscanf(line, "MemAvailable: %llu kB", &kb) == 1)
        available = double(kb) * 1024;
    }
    std::fclose(f);
  }
  rlimit limit;
  if(getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
     (available == 0 || double(limit.rlim_cur) < available))
    available = double(limit.rlim_cur);
  return available;
}

inline std::string gigabytes(double bytes)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

// Refuses, before allocating anything, a grid whose field values alone do not
// fit in memory: 8 bytes per vertex and field (in core), or per vertex of the
// slabs in flight (out of core).  The surface and the sign masks come on top,
// so this is a lower bound.
inline void check_grid_memory(const Options& o, std::size_t number_of_fields)
{
  const std::array<std::size_t, 3>& n = *o.grid;
  const double vertices = double(n[0]) * double(n[1]) * double(n[2]);
  const double fields = double(std::max<std::size_t>(1, number_of_fields));
  double values = vertices * fields;
  std::string what = std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) + " vertices";
  if(o.out_of_core)
  {
    const double slab = double(o.slab_layers ? o.slab_layers : 8) + 3;
    const double in_flight = 2 * std::max(1u, std::thread::hardware_concurrency());
    values = std::min(values, double(n[0]) * double(n[1]) * slab * fields * in_flight);
    what += " (out of core: the slabs in flight)";
  }
  const double needed = 8 * values;
  const double available = available_bytes();
  if(vertices > 1e18 || (available > 0 && needed > available))
    throw Error(o.lattice_flag + ": " + what + " x " + std::to_string(std::size_t(fields)) + " field" +
                (fields == 1 ? "" : "s") + " need at least " + gigabytes(needed) + " for the field values, but only " +
                gigabytes(available) + " of memory are available (use a coarser grid" +
                (o.out_of_core ? ", or a smaller --slab-size)" : ", or --out-of-core with a raw --fields file)"));
}

struct Input
{
  std::optional<Grid> grid;
  std::optional<Tet_mesh> mesh;
  BI::Scalar_fields fields;
  BI::Boolean_expression expression;

  std::size_t number_of_vertices() const { return grid ? grid->number_of_vertices() : mesh->number_of_vertices(); }
};

inline Grid make_grid(const Options& o)
{
  const std::array<double, 6> b = o.domain_box();
  return Grid::spanning(Point(b[0], b[1], b[2]), Point(b[3], b[4], b[5]), *o.grid);
}

inline void read_domain(const Options& o, Input& in)
{
  if(o.grid)
  {
    in.grid.emplace(make_grid(o));
    return;
  }
  try
  {
    in.mesh.emplace(BI::IO::read_tetrahedral_mesh<K>(o.mesh_file));
  }
  catch(const BI::Invalid_input_error& e)
  {
    // The mesh checks (conformity, orientation) do not know the file.
    const std::string message = e.what();
    throw Error(message.find(o.mesh_file) == std::string::npos ? "'" + o.mesh_file + "': " + message : message);
  }
}

// Field i at vertex v is functions[i](point_at(v)); every vertex writes its
// own values, so the parallel loop gives the sequential result.
template <typename PointAt>
BI::Scalar_fields sample(std::size_t number_of_vertices, const std::vector<tbiso_fields::Field>& functions,
                         const PointAt& point_at, bool parallel)
{
  BI::Scalar_fields fields(number_of_vertices, functions.size());
  const std::size_t n = functions.size();
  double* values = fields.data().data();
  const auto body = [&](std::size_t begin, std::size_t end) {
    for(std::size_t v = begin; v < end; ++v)
    {
      const Point p = point_at(v);
      for(std::size_t i = 0; i < n; ++i)
        values[v * n + i] = functions[i](p);
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, number_of_vertices, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  else
#endif
    body(0, number_of_vertices);
  (void)parallel;
  return fields;
}

inline std::vector<tbiso_fields::Field> make_fields(const std::vector<std::string>& specs)
{
  std::vector<tbiso_fields::Field> functions;
  for(const std::string& spec : specs)
    functions.push_back(tbiso_fields::make_field(spec));
  return functions;
}

// The fields, read from --fields FILE or sampled from the --field specs;
// the expression, checked against a file's number of fields.
inline void read_fields(const Options& o, Input& in)
{
  in.expression = BI::Boolean_expression::parse(o.expression ? *o.expression : "f0");
  if(!o.fields_file.empty())
  {
    in.fields = BI::IO::read_scalar_fields(o.fields_file, in.number_of_vertices(), o.field_count);
    in.fields.check_finite();
    const std::size_t n = in.fields.number_of_fields();
    if(!o.expression && n != 1)
      throw Error("--expr is required with " + std::to_string(n) + " fields");
    if(in.expression.number_of_variables() > n)
      throw Error("the expression names field f" + std::to_string(in.expression.number_of_variables() - 1) +
                  " but " + o.fields_file + " has " + std::to_string(n) + " field" + (n == 1 ? "" : "s"));
    return;
  }
  const std::vector<tbiso_fields::Field> functions = make_fields(o.field_specs);
  if(in.grid)
    in.fields = sample(in.number_of_vertices(), functions, [&](std::size_t v) { return in.grid->point(v); }, o.parallel);
  else
    in.fields = sample(in.number_of_vertices(), functions, [&](std::size_t v) { return in.mesh->point(v); }, o.parallel);
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_INPUT_H
