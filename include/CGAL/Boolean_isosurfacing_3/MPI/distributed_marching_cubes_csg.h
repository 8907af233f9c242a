// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H

// Marching Cubes CSG on the ranks of an MPI communicator
// (doc/Boolean_isosurfacing_3/distributed.md): rank r classifies and
// triangulates only the cube layers `slab_range_of_part(layers, r, K)`
// (`marching_cubes_csg_slab_range()`); the rank above sends down the edge ids
// of its first plane's vertices (one message per boundary), an MPI_Exscan of
// the owned vertex counts gives the offsets, and the OFF file is written
// collectively -- byte for byte the file CGAL's `write_polygon_mesh()` writes
// for the single-process `marching_cubes_csg()` output (precision 17).

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/MPI/internal/Mpi_support.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_slab_range.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg_slab_range.h>

#include <CGAL/IO/OFF/File_writer_OFF.h>

#include <mpi.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `marching_cubes_csg_distributed()` did: global counts (the same on
/// every rank) and this rank's share and times.  `number_of_vertices`,
/// `number_of_faces` (triangles, all ranks), `seconds` (this rank's whole
/// call) and `warnings` are those of `Algorithm_statistics`.
struct Marching_cubes_csg_distributed_statistics : Algorithm_statistics
{
  /// The enclosed volume (divergence theorem about the lattice centre), summed over the ranks.
  double volume = 0;
  /// This rank's cube layers `[first_layer, last_layer)`.
  std::size_t first_layer = 0, last_layer = 0;
  /// This rank's share: output vertices it owns, triangles, input triangles
  /// that reach its layers, lattice points of its layers.
  std::size_t rank_vertices = 0, rank_faces = 0, rank_input_triangles = 0, rank_lattice_points = 0;
  /// Words of the boundary message this rank sent down (0 for rank 0).
  std::size_t sent_words = 0;
  /// This rank's wall times: extraction (classification and triangulation
  /// of its layers), welding (exchange, prefix sums, volume), writing.
  double seconds_extraction = 0, seconds_welding = 0, seconds_writing = 0;
  /// The largest `seconds_extraction` over the ranks (the critical path).
  double max_seconds_extraction = 0;
};

namespace internal {

// The OFF text of CGAL's writer, piece by piece: the same calls
// `write_polygon_mesh()` makes, on a stream with its precision.
inline std::ostringstream off_stream()
{
  std::ostringstream out;
  out.precision(17);
  return out;
}

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Marching Cubes CSG over all ranks of `comm` (each rank passes the same
/// meshes, expression and lattice), written to the OFF file `filename` as
/// `CGAL::IO::write_polygon_mesh(filename, mesh, stream_precision(17))`
/// writes the `Surface_mesh` that `marching_cubes_csg()` returns.
/// Collective.
///
/// \param comm the communicator
/// \param lattice the whole lattice
/// \param meshes the closed triangle meshes (the same on every rank)
/// \param expression a Boolean expression with `meshes.size()` variables
/// \param filename the output OFF file
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{max_memory_bytes}
///     \cgalParamDescription{refuse to start when the estimated memory exceeds it}
///     \cgalParamType{`std::size_t`} \cgalParamDefault{8 GiB}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Distributed_error on every rank if any rank failed.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Marching_cubes_csg_distributed_statistics
marching_cubes_csg_distributed(MPI_Comm comm, const Regular_lattice_3& lattice, const TriangleMeshRange& meshes,
                               const Boolean_expression& expression, const std::string& filename,
                               const NamedParameters& np = parameters::default_values())
{
  namespace mpi = internal::mpi;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t layers = lattice.number_of_points(2) > 0 ? lattice.number_of_points(2) - 1 : 0;
  auto range_of = [&](int r) { return slab_range_of_part(layers, std::size_t(r), std::size_t(size)); };
  const std::pair<std::size_t, std::size_t> mine = range_of(rank);
  Marching_cubes_csg_distributed_statistics stats;
  stats.first_layer = mine.first;
  stats.last_layer = mine.second;

  const auto call_start = std::chrono::steady_clock::now();
  auto start = call_start;
  Marching_cubes_csg_slab_range range;
  mpi::on_all_ranks(comm, [&] {
    marching_cubes_csg_slab_range<ConcurrencyTag>(lattice, meshes, expression, mine.first, mine.second, range, np);
  });
  stats.seconds_extraction = internal::seconds_since(start);
  stats.max_seconds_extraction = mpi::maximum(comm, stats.seconds_extraction);

  // The one neighbour exchange: plane k0's vertex edges go down.
  start = std::chrono::steady_clock::now();
  const bool active = mine.first < mine.second;
  const bool above_active = rank + 1 < size && range_of(rank + 1).first < range_of(rank + 1).second;
  const bool send_down = active && rank > 0;
  stats.sent_words = send_down ? range.bottom_edges.size() : 0;
  std::vector<std::uint64_t> from_above;
  mpi::on_all_ranks(comm, [&] {
    from_above = mpi::exchange(comm, send_down ? range.bottom_edges : std::vector<std::uint64_t>(),
                               send_down ? rank - 1 : MPI_PROC_NULL, active && above_active ? rank + 1 : MPI_PROC_NULL);
  });
  const std::uint64_t offset = mpi::exclusive_sum(comm, range.points.size());
  std::vector<std::size_t> top;
  mpi::on_all_ranks(comm, [&] {
    top = top_vertex_indices(range, from_above, std::size_t(offset) + range.points.size());
  });
  std::vector<std::uint64_t>().swap(from_above);
  auto global = [&](std::size_t t) { return t < range.points.size() ? offset + t : top[t - range.points.size()]; };
  stats.number_of_vertices = std::size_t(mpi::total_sum(comm, range.points.size()));
  stats.number_of_faces = std::size_t(mpi::total_sum(comm, range.triangles.size()));
  stats.rank_vertices = range.points.size();
  stats.rank_faces = range.triangles.size();
  stats.rank_input_triangles = range.number_of_input_triangles;
  stats.rank_lattice_points = range.statistics.lattice_points;

  // Volume: sum over the ranks of the signed tetrahedra of their triangles
  // about one common point (the lattice centre).
  const CGAL::Bbox_3 box = lattice.bbox();
  const std::array<double, 3> c{{(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                                 (box.zmin() + box.zmax()) / 2}};
  internal::Accurate_sum<double> volume;
  for(const std::array<std::size_t, 3>& t : range.triangles)
  {
    std::array<std::array<double, 3>, 3> p;
    for(int v = 0; v < 3; ++v)
    {
      const std::array<double, 3>& q =
          t[v] < range.points.size() ? range.points[t[v]] : range.top_points[t[v] - range.points.size()];
      for(int a = 0; a < 3; ++a)
        p[v][a] = q[a] - c[a];
    }
    volume.add((p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
               6);
  }
  const double mine_volume = volume.result();
  MPI_Allreduce(&mine_volume, &stats.volume, 1, MPI_DOUBLE, MPI_SUM, comm);
  stats.seconds_welding = internal::seconds_since(start);

  // The file: [header (rank 0)] [vertex lines] [facet header + ...] [face lines] [footer]
  // with the facet header and the footer on the last rank.
  start = std::chrono::steady_clock::now();
  std::vector<std::string> parts(3);
  {
    std::ostringstream out = internal::off_stream();
    CGAL::File_writer_OFF writer;
    // Every rank binds the writer to its stream; only rank 0 keeps the header.
    writer.write_header(out, stats.number_of_vertices, 0, stats.number_of_faces);
    if(rank == 0)
      parts[0] = out.str();
    out.str("");
    for(const std::array<double, 3>& p : range.points)
      writer.write_vertex(p[0], p[1], p[2]);
    if(rank == size - 1)
      writer.write_facet_header();
    parts[1] = out.str();
    out.str("");
    for(std::size_t f = 0; f < range.triangles.size(); ++f)
    {
      writer.write_facet_begin(3);
      for(int v = 0; v < 3; ++v)
        writer.write_facet_vertex_index(std::size_t(global(range.triangles[f][v])));
      writer.write_facet_end();
    }
    if(rank == size - 1)
      writer.write_footer();
    parts[2] = out.str();
  }
  const std::vector<std::uint64_t> part_bytes{parts[0].size(), parts[1].size(), parts[2].size()};
  mpi::write_sections(comm, filename, part_bytes, [&](std::size_t section, std::string& out) {
    out.swap(parts[section]);
    return false;
  });
  stats.seconds_writing = internal::seconds_since(start);
  stats.seconds = internal::seconds_since(call_start);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H
