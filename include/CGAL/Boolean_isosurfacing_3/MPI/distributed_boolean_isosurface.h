// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_BOOLEAN_ISOSURFACE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_BOOLEAN_ISOSURFACE_H

// TBISO on the ranks of an MPI communicator (doc/Boolean_isosurfacing_3/distributed.md):
// - rank r gets the contiguous cube layers `slab_range_of_part(layers, r, K, slab_layers)`;
// - it reads only its vertex layers plus one ghost layer on each side of a
//   raw field file, with MPI_File_read_at (`Mpi_raw_scalar_field_reader`);
// - it extracts them (`extract_boolean_isosurface_slab_range()`);
// - one message per boundary (the top-layer keys, to the rank above) and an
//   MPI_Exscan of the new-vertex counts give the global numbering;
// - the binary PLY file is written collectively, each rank at its offsets,
//   byte for byte the file `IO::Boolean_isosurface_PLY_stream` writes in one
//   process (`tbiso --out-of-core`).
// This header needs <mpi.h>; the core headers never do.

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/IO/Boolean_isosurface_PLY_stream.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/MPI/internal/Mpi_support.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_slab_range.h>

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A `ScalarFieldSource` reading a raw field file (the layout of
/// `IO::Raw_scalar_field_reader`: vertex-major, little-endian float64 or
/// float32, no header) with `MPI_File_read_at`: each rank reads only the
/// vertices it asks for.  Opening is collective over `comm`.
///
/// \cgalModels{ScalarFieldSource}
class Mpi_raw_scalar_field_reader
{
public:
  /// \throws Invalid_input_error (on every rank) if the file cannot be opened
  /// or its size is not `number_of_vertices * number_of_fields * scalar size`.
  Mpi_raw_scalar_field_reader(MPI_Comm comm, const std::string& filename, std::size_t number_of_vertices,
                              std::size_t number_of_fields, IO::Raw_scalar_type type = IO::Raw_scalar_type::FLOAT64)
    : m_filename(filename), m_number_of_vertices(number_of_vertices), m_number_of_fields(number_of_fields),
      m_type(type)
  {
    using namespace IO::internal::scalar_fields_io;
    check_number_of_fields(number_of_fields, filename);
    try
    {
      m_file.reset(new internal::mpi::Shared_file(comm, filename, MPI_MODE_RDONLY));
    }
    catch(const std::runtime_error& e)
    {
      throw Invalid_input_error(e.what());
    }
    const std::uint64_t expected = number_of_vertices * number_of_fields * raw_scalar_size(type);
    const std::uint64_t actual = m_file->size();
    if(actual != expected)
      throw Invalid_input_error("'" + filename + "' has " + std::to_string(actual) + " bytes, expected " +
                                std::to_string(expected) + " (" + std::to_string(number_of_vertices) +
                                " vertices x " + std::to_string(number_of_fields) + " fields x " +
                                std::to_string(raw_scalar_size(type)) + " bytes of " + type_name(type) + ")");
  }

  std::size_t number_of_fields() const { return m_number_of_fields; }

  /// As `IO::Raw_scalar_field_reader::read()`.
  void read(std::size_t first, std::size_t count, std::vector<double>& values)
  {
    using namespace IO::internal::scalar_fields_io;
    if(first > m_number_of_vertices || count > m_number_of_vertices - first)
      throw std::out_of_range("'" + m_filename + "': vertices [" + std::to_string(first) + ", " +
                              std::to_string(first + count) + ") are not within [0, " +
                              std::to_string(m_number_of_vertices) + ")");
    const std::size_t n = count * m_number_of_fields, s = raw_scalar_size(m_type);
    values.resize(n);
    const auto start = std::chrono::steady_clock::now();
    if(m_type == IO::Raw_scalar_type::FLOAT64)
    {
      internal::mpi::read_at(m_file->get(), std::uint64_t(first) * m_number_of_fields * s, values.data(), n * s,
                             m_filename);
      internal::little_endian_to_host(values.data(), n);
    }
    else
    {
      std::vector<float> buffer(n);
      internal::mpi::read_at(m_file->get(), std::uint64_t(first) * m_number_of_fields * s, buffer.data(), n * s,
                             m_filename);
      internal::little_endian_to_host(buffer.data(), n);
      std::copy(buffer.begin(), buffer.end(), values.begin());
    }
    m_bytes_read += n * s;
    m_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for(std::size_t k = 0; k < n; ++k)
      if(!std::isfinite(values[k]))
        throw_non_finite(m_filename, first + k / m_number_of_fields, k % m_number_of_fields, values[k]);
  }

  /// Bytes read and seconds spent reading by this rank so far.
  std::uint64_t bytes_read() const { return m_bytes_read; }
  double seconds() const { return m_seconds; }

private:
  std::string m_filename;
  std::size_t m_number_of_vertices, m_number_of_fields;
  IO::Raw_scalar_type m_type;
  std::unique_ptr<internal::mpi::Shared_file> m_file;
  std::uint64_t m_bytes_read = 0;
  double m_seconds = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `extract_boolean_isosurface_distributed()` did: global counts (the
/// same on every rank) and this rank's share and times.
/// `number_of_vertices`, `number_of_faces` (polygons, all ranks), `seconds`
/// (this rank's whole call) and `warnings` are those of `Algorithm_statistics`.
struct Boolean_isosurface_distributed_statistics : Algorithm_statistics
{
  /// Tetrahedra that needed more than the sign test, all ranks.
  std::size_t number_of_evaluated_tetrahedra = 0;
  /// This rank's cube layers `[first_layer, last_layer)`.
  std::size_t first_layer = 0, last_layer = 0;
  /// The vertices this rank owns (writes) and its polygons.
  std::size_t rank_vertices = 0, rank_faces = 0;
  /// Words of the boundary messages this rank sent up (0 for the top rank).
  std::size_t sent_words = 0;
  /// Whether this rank extracted its range a second time, with the message
  /// from below (`Boolean_isosurface_slab_range::depends_on_below`).
  bool extracted_again = false;
  /// Largest number of field values this rank held at once.
  std::size_t peak_field_values = 0;
  /// This rank's wall times: extraction (reading included), welding
  /// (exchange and prefix sums), writing.
  double seconds_extraction = 0, seconds_welding = 0, seconds_writing = 0;
  /// The largest `seconds_extraction` over the ranks (the critical path).
  double max_seconds_extraction = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO over all ranks of `comm`, each extracting its own cube layers from
/// `source` (a `ScalarFieldSource` that every rank can read any range of:
/// `Mpi_raw_scalar_field_reader`, or the caller's own), written to the binary
/// PLY file `filename` in the layout of `IO::Boolean_isosurface_PLY_stream`.
/// The file is the one a single process writes, byte for byte: same vertex
/// numbering, same polygon order.  Collective.
///
/// \param comm the communicator
/// \param grid the whole regular grid (the same on every rank)
/// \param source the fields, a model of `ScalarFieldSource`
/// \param expression the Boolean expression of the fields
/// \param filename the output PLY file
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{close_at_domain_boundary}
///     \cgalParamDescription{close the set on the boundary of the grid}
///     \cgalParamType{`bool`} \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{slab_layers}
///     \cgalParamDescription{cube layers per slab (the unit of reading and of parallel work); 0 means the default}
///     \cgalParamType{`std::size_t`} \cgalParamDefault{8}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Distributed_error on every rank if any rank failed (the message
/// names the lowest failing rank and its error).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename FieldSource,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boolean_isosurface_distributed_statistics
extract_boolean_isosurface_distributed(MPI_Comm comm, const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                                       const Boolean_expression& expression, const std::string& filename,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace mpi = internal::mpi;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t layers = grid.vertex_counts()[2] - 1;
  // Whole slabs per rank: each rank welds the single process's chunks.
  const std::size_t slab = std::max<std::size_t>(
      1, parameters::choose_parameter(parameters::get_parameter(np, internal_np::slab_layers), std::size_t(8)));
  auto range_of = [&](int r) { return slab_range_of_part(layers, std::size_t(r), std::size_t(size), slab); };
  const std::pair<std::size_t, std::size_t> mine = range_of(rank);
  Boolean_isosurface_distributed_statistics stats;
  stats.first_layer = mine.first;
  stats.last_layer = mine.second;

  const auto call_start = std::chrono::steady_clock::now();
  auto start = call_start;
  Boolean_isosurface_slab_range range;
  mpi::on_all_ranks(comm, [&] {
    extract_boolean_isosurface_slab_range<ConcurrencyTag>(grid, source, expression, mine.first, mine.second, range, np);
  });
  stats.seconds_extraction = internal::seconds_since(start);

  // The one neighbour exchange: top-layer keys go to the rank above, when
  // both ranges are non-empty (empty ranges are the last ranks).
  start = std::chrono::steady_clock::now();
  const bool active = mine.first < mine.second;
  const bool above_active = rank + 1 < size && range_of(rank + 1).first < range_of(rank + 1).second;
  std::vector<std::uint64_t> from_below;
  auto exchange_up = [&] {
    std::vector<std::uint64_t> up = active && above_active ? top_layer_message(range) : std::vector<std::uint64_t>();
    stats.sent_words += up.size();
    mpi::on_all_ranks(comm, [&] {
      from_below = mpi::exchange(comm, up, active && above_active ? rank + 1 : MPI_PROC_NULL,
                                 active && rank > 0 ? rank - 1 : MPI_PROC_NULL);
    });
  };
  // A range whose first slab has two bottom-layer vertices at one position
  // (rare: degenerate inputs) must be extracted again with the final message
  // of the range below.  Its depth is its number of such ranges in a row
  // ending with it; ranges of depth t are redone in round t.
  std::vector<int> depends(std::size_t(size), 0);
  const int mine_depends = range.depends_on_below ? 1 : 0;
  MPI_Allgather(&mine_depends, 1, MPI_INT, depends.data(), 1, MPI_INT, comm);
  std::vector<int> depth(std::size_t(size), 0);
  for(int r = 0; r < size; ++r)
    depth[std::size_t(r)] = depends[std::size_t(r)] ? (r > 0 ? depth[std::size_t(r - 1)] : 0) + 1 : 0;
  const int rounds = *std::max_element(depth.begin(), depth.end());
  for(int t = 1; t <= rounds; ++t)
  {
    exchange_up();
    const auto again = std::chrono::steady_clock::now();
    mpi::on_all_ranks(comm, [&] {
      if(depth[std::size_t(rank)] == t)
        extract_boolean_isosurface_slab_range<ConcurrencyTag>(grid, source, expression, mine.first, mine.second,
                                                              from_below, range, np);
    });
    stats.seconds_extraction += internal::seconds_since(again);
  }
  stats.extracted_again = depth[std::size_t(rank)] > 0;
  stats.max_seconds_extraction = mpi::maximum(comm, stats.seconds_extraction);
  exchange_up();
  Boolean_isosurface_slab_range_welding welding;
  mpi::on_all_ranks(comm, [&] { welding = match_boolean_isosurface_slab_range(range, from_below); });
  std::vector<std::uint64_t>().swap(from_below);
  const std::uint64_t offset = mpi::exclusive_sum(comm, welding.number_of_new_vertices);
  std::vector<std::size_t> global = global_vertex_indices(range, welding, std::size_t(offset));
  stats.number_of_vertices = std::size_t(mpi::total_sum(comm, welding.number_of_new_vertices));
  stats.number_of_faces = std::size_t(mpi::total_sum(comm, range.number_of_polygons()));
  stats.number_of_evaluated_tetrahedra = std::size_t(mpi::total_sum(comm, range.number_of_evaluated_tetrahedra));
  stats.rank_vertices = welding.number_of_new_vertices;
  stats.rank_faces = range.number_of_polygons();
  stats.peak_field_values = range.peak_field_values;
  stats.seconds_welding = internal::seconds_since(start);

  // The file: header (rank 0), vertex records, face records, each section
  // the ranks' parts in rank order.
  start = std::chrono::steady_clock::now();
  typedef IO::Boolean_isosurface_PLY_stream Ply;
  const std::string header = Ply::header(stats.number_of_vertices, stats.number_of_faces);
  std::uint64_t face_bytes = 0;
  for(std::size_t p = 0; p < range.number_of_polygons(); ++p)
    face_bytes += 1 + 4 * (range.polygon_begin[p + 1] - range.polygon_begin[p]) + 4 + 3;
  const std::vector<std::uint64_t> part_bytes{rank == 0 ? header.size() : 0,
                                              24 * std::uint64_t(welding.number_of_new_vertices), face_bytes};
  const std::size_t piece_records = std::size_t(1) << 20;
  std::size_t next_vertex = 0, next_polygon = 0;
  std::vector<std::size_t> polygon;
  mpi::write_sections(comm, filename, part_bytes, [&](std::size_t section, std::string& out) {
    if(section == 0)
    {
      if(rank == 0)
        out = header;
      return false;
    }
    if(section == 1)
    {
      // The new vertices are the local ones with global index >= offset, in order.
      for(std::size_t done = 0; next_vertex < range.points.size() && done < piece_records; ++next_vertex)
        if(global[next_vertex] >= offset)
        {
          Ply::append_point(out, range.points[next_vertex]);
          ++done;
        }
      return next_vertex < range.points.size();
    }
    for(std::size_t done = 0; next_polygon < range.number_of_polygons() && done < piece_records; ++next_polygon, ++done)
    {
      polygon.clear();
      for(std::size_t k = range.polygon_begin[next_polygon]; k < range.polygon_begin[next_polygon + 1]; ++k)
        polygon.push_back(global[range.polygon_vertices[k]]);
      Ply::append_polygon(out, polygon.data(), polygon.size(), range.labels[next_polygon]);
    }
    return next_polygon < range.number_of_polygons();
  });
  stats.seconds_writing = internal::seconds_since(start);
  stats.seconds = internal::seconds_since(call_start);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_BOOLEAN_ISOSURFACE_H
