// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H

// Marching Cubes CSG on the ranks of an MPI communicator
// (doc/Boolean_isosurfacing_3/distributed.md): rank r classifies and
// triangulates only the cube layers `slab_range_of_part(layers, r, K)`
// (`marching_cubes_csg_slab_range()`); the rank above sends down the edge ids
// of its first plane's vertices (one message per boundary), an MPI_Exscan of
// the owned vertex counts gives the offsets, and the output file is written
// collectively -- byte for byte the file `IO::write_triangle_soup()` writes
// for the single-process `marching_cubes_csg()` output (OFF, OBJ or binary PLY).

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/MPI/internal/Mpi_support.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_slab_range.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg_slab_range.h>

#include <CGAL/Boolean_isosurfacing_3/IO/write_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
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

// The records of `IO::write_triangle_soup()`'s formats, so that each rank
// formats its own vertices and triangles: the file is the concatenation of
// a header (counts), the vertex records and the face records.
class Soup_file_records
{
public:
  enum Format { OFF, OBJ, PLY };

  explicit Soup_file_records(const std::string& filename)
  {
    using CGAL::Boolean_isosurfacing::internal::ends_with_lowercase;
    if(ends_with_lowercase(filename, ".off"))
      m_format = OFF;
    else if(ends_with_lowercase(filename, ".obj"))
      m_format = OBJ;
    else if(ends_with_lowercase(filename, ".ply"))
      m_format = PLY;
    else
      throw Invalid_input_error("marching_cubes_csg_distributed: " + filename +
                                ": the extension must be .off, .obj or .ply");
  }

  std::string header(std::size_t vertices, std::size_t faces) const
  {
    if(m_format == OFF)
      return "OFF\n" + std::to_string(vertices) + " " + std::to_string(faces) + " 0\n";
    if(m_format == PLY)
      return "ply\nformat binary_little_endian 1.0\ncomment Boolean_isosurfacing_3\nelement vertex " +
             std::to_string(vertices) +
             "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(faces) +
             "\nproperty list uchar uint vertex_indices\nend_header\n";
    return std::string();
  }

  // The records of points [first, last) appended to `out`.
  void vertices(std::string& out, const std::array<double, 3>* first, const std::array<double, 3>* last) const
  {
    if(m_format == PLY)
    {
      for(; first != last; ++first)
        for(double c : *first)
          put_little_endian(out, c);
      return;
    }
    IO::internal_io::String_sink sink(out);
    IO::internal_io::Text_writer<IO::internal_io::String_sink> text(sink);
    for(; first != last; ++first)
    {
      if(m_format == OBJ)
        text.text("v ");
      text.number((*first)[0]);
      text.character(' ');
      text.number((*first)[1]);
      text.character(' ');
      text.number((*first)[2]);
      text.end_line();
    }
  }

  // The records of triangles [first, last) appended to `out`, with the
  // vertex indices `global(i)`.
  template <typename Triangle, typename Global>
  void faces(std::string& out, const Triangle* first, const Triangle* last, const Global& global) const
  {
    if(m_format == PLY)
    {
      for(; first != last; ++first)
      {
        put_little_endian(out, std::uint8_t(3));
        for(std::size_t v : *first)
        {
          const std::uint64_t g = global(v);
          if(g > 0xffffffffu)
            throw Invalid_input_error("more than 2^32 vertices for PLY uint indices");
          put_little_endian(out, std::uint32_t(g));
        }
      }
      return;
    }
    IO::internal_io::String_sink sink(out);
    IO::internal_io::Text_writer<IO::internal_io::String_sink> text(sink);
    const std::uint64_t base = m_format == OBJ ? 1 : 0;
    for(; first != last; ++first)
    {
      text.text(m_format == OBJ ? "f " : "3 ");
      text.number(std::uint64_t(global((*first)[0])) + base);
      text.character(' ');
      text.number(std::uint64_t(global((*first)[1])) + base);
      text.character(' ');
      text.number(std::uint64_t(global((*first)[2])) + base);
      text.end_line();
    }
  }

private:
  Format m_format = OFF;
};

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Marching Cubes CSG over all ranks of `comm` (each rank passes the same
/// meshes, expression and lattice), written to `filename` (`.off`, `.obj` or
/// `.ply`) as `IO::write_triangle_soup()` writes the soup that
/// `marching_cubes_csg()` returns, byte for byte.  Each rank keeps its part
/// of the file in a temporary file next to it (`filename.rank<r>.text`)
/// until the offsets are known.  Collective.
///
/// \param comm the communicator
/// \param lattice the whole lattice
/// \param meshes the closed triangle meshes (the same on every rank)
/// \param expression a Boolean expression with `meshes.size()` variables
/// \param filename the output file: `.off`, `.obj` or binary `.ply`
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
  std::unique_ptr<internal::Soup_file_records> records;
  mpi::on_all_ranks(comm, [&] {
    records.reset(new internal::Soup_file_records(filename));
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
  for(const auto& t : range.triangles)
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

  // The file: [header (rank 0)] [vertex records] [face records], each
  // section the ranks' parts in rank order.  The records are formatted once,
  // piece by piece, into a temporary file next to the output, and copied
  // from there once every part's size is known: a rank never holds its
  // whole part of the text (about 50 bytes per vertex and per triangle).
  start = std::chrono::steady_clock::now();
  const std::string header = rank == 0 ? records->header(stats.number_of_vertices, stats.number_of_faces) : "";
  const std::size_t piece_records = std::size_t(1) << 15;
  std::vector<std::uint64_t> part_bytes{header.size(), 0, 0};
  std::unique_ptr<mpi::Temporary_file> text;
  mpi::on_all_ranks(comm, [&] {
    text.reset(new mpi::Temporary_file(filename + ".rank" + std::to_string(rank) + ".text"));
    std::string piece;
    for(std::size_t v = 0; v < range.points.size(); v += piece_records)
    {
      piece.clear();
      const std::size_t end = (std::min)(range.points.size(), v + piece_records);
      records->vertices(piece, range.points.data() + v, range.points.data() + end);
      part_bytes[1] += text->append(piece);
    }
    for(std::size_t f = 0; f < range.triangles.size(); f += piece_records)
    {
      piece.clear();
      const std::size_t end = (std::min)(range.triangles.size(), f + piece_records);
      records->faces(piece, range.triangles.data() + f, range.triangles.data() + end, global);
      part_bytes[2] += text->append(piece);
    }
    text->finish();
  });
  const std::uint64_t piece_bytes = std::uint64_t(1) << 22;
  std::vector<std::uint64_t> left = part_bytes;
  mpi::write_sections(comm, filename, part_bytes, [&](std::size_t section, std::string& piece) {
    if(section == 0)
    {
      piece = header;
      return false;
    }
    const std::uint64_t bytes = (std::min)(left[section], piece_bytes);
    text->read(piece, std::size_t(bytes));
    left[section] -= bytes;
    return left[section] > 0;
  });
  text.reset();
  stats.seconds_writing = internal::seconds_since(start);
  stats.seconds = internal::seconds_since(call_start);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_MARCHING_CUBES_CSG_H
