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
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
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

namespace internal {

// Where a rank's surface waits for the prefix sums: two temporary files next
// to the output, `OUT.rank<r>.points` (the PLY vertex records, in local
// order) and `OUT.rank<r>.faces` (per polygon: the vertex count as one byte,
// the local indices as uint32, the label as int32, host byte order), so that
// a rank holds a few slabs of surface instead of its whole share.  Removed
// on destruction.
class Spilled_slab_range
{
public:
  Spilled_slab_range(const std::string& output, int rank)
    : m_points_name(output + ".rank" + std::to_string(rank) + ".points"),
      m_faces_name(output + ".rank" + std::to_string(rank) + ".faces")
  {
    reset();
  }
  Spilled_slab_range(const Spilled_slab_range&) = delete;
  Spilled_slab_range& operator=(const Spilled_slab_range&) = delete;
  ~Spilled_slab_range()
  {
    m_points.close();
    m_faces.close();
    std::remove(m_points_name.c_str());
    std::remove(m_faces_name.c_str());
  }

  /// Empties both files (a range extracted again starts over).
  void reset()
  {
    m_points.close();
    m_faces.close();
    m_points.open(m_points_name, std::ios::binary | std::ios::trunc);
    m_faces.open(m_faces_name, std::ios::binary | std::ios::trunc);
    if(!m_points || !m_faces)
      throw std::runtime_error("cannot write the temporary file '" + m_points_name + "' (next to the output)");
    m_point_buffer.clear();
    m_face_buffer.clear();
    m_corners = 0;
  }

  // BooleanIsosurfaceSink
  void add_point(const std::array<double, 3>& p)
  {
    IO::Boolean_isosurface_PLY_stream::append_point(m_point_buffer, p);
    flush(m_points, m_point_buffer, false);
  }
  void add_polygon(const std::size_t* v, std::size_t n, int label)
  {
    if(n > 255)
      throw Invalid_input_error("a polygon of " + std::to_string(n) + " vertices does not fit a PLY uchar list");
    m_face_buffer.push_back(char(n));
    for(std::size_t k = 0; k < n; ++k)
    {
      if(v[k] > std::size_t((std::numeric_limits<std::int32_t>::max)()))
        throw Invalid_input_error("too many points for PLY int indices");
      append(std::uint32_t(v[k]));
    }
    append(std::int32_t(label));
    m_corners += n;
    flush(m_faces, m_face_buffer, false);
  }

  /// Flushes and closes the files for reading.
  void finish()
  {
    flush(m_points, m_point_buffer, true);
    flush(m_faces, m_face_buffer, true);
    m_points.close();
    m_faces.close();
    if(!m_points || !m_faces)
      throw std::runtime_error("failed writing the temporary file '" + m_points_name + "'");
  }

  /// The vertex indices of all polygons so far.
  std::uint64_t number_of_corners() const { return m_corners; }
  const std::string& points_name() const { return m_points_name; }
  const std::string& faces_name() const { return m_faces_name; }

private:
  template <typename T>
  void append(T value)
  {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    m_face_buffer.append(bytes, sizeof(T));
  }
  static void flush(std::ofstream& out, std::string& buffer, bool always)
  {
    if(always || buffer.size() >= (std::size_t(1) << 20))
    {
      out.write(buffer.data(), std::streamsize(buffer.size()));
      buffer.clear();
    }
  }

  std::string m_points_name, m_faces_name;
  std::ofstream m_points, m_faces;
  std::string m_point_buffer, m_face_buffer;
  std::uint64_t m_corners = 0;
};

// Local vertex index -> global index without a table of all local vertices:
// the matched bottom-layer vertices take the indices of the range below, and
// the others `offset, offset + 1, ...` in local order (global_vertex_indices()).
class Slab_range_renumbering
{
public:
  Slab_range_renumbering(const Boolean_isosurface_slab_range& range,
                         const Boolean_isosurface_slab_range_welding& welding, std::size_t offset)
    : m_offset(offset)
  {
    for(std::size_t b = 0; b < range.bottom_vertices.size(); ++b)
      if(welding.below_match[b] != welding.no_match)
        m_matched.emplace_back(range.bottom_vertices[b], offset - welding.below_vertices + welding.below_match[b]);
    std::sort(m_matched.begin(), m_matched.end());
    m_matched.erase(std::unique(m_matched.begin(), m_matched.end()), m_matched.end());
  }

  bool is_new(std::size_t local) const { return find(local) == m_matched.end(); }

  std::size_t operator()(std::size_t local) const
  {
    const auto it = find(local);
    if(it != m_matched.end())
      return it->second;
    return m_offset + local -
           std::size_t(std::lower_bound(m_matched.begin(), m_matched.end(), std::make_pair(local, std::size_t(0))) -
                       m_matched.begin());
  }

private:
  typedef std::vector<std::pair<std::size_t, std::size_t>> Pairs;
  Pairs::const_iterator find(std::size_t local) const
  {
    if(m_matched.empty() || local > m_matched.back().first)
      return m_matched.end();
    const auto it = std::lower_bound(m_matched.begin(), m_matched.end(), std::make_pair(local, std::size_t(0)));
    return it != m_matched.end() && it->first == local ? it : m_matched.end();
  }

  std::size_t m_offset;
  Pairs m_matched; // (local, global), by local
};

} // namespace internal

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
  // The rank's surface goes to temporary files as it is welded: memory is
  // a few slabs, not the rank's share of the surface.
  std::unique_ptr<internal::Spilled_slab_range> spill;
  mpi::on_all_ranks(comm, [&] {
    spill.reset(new internal::Spilled_slab_range(filename, rank));
    stream_boolean_isosurface_slab_range<ConcurrencyTag>(grid, source, expression, mine.first, mine.second, nullptr,
                                                         *spill, range, np);
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
      {
        spill->reset();
        stream_boolean_isosurface_slab_range<ConcurrencyTag>(grid, source, expression, mine.first, mine.second,
                                                             &from_below, *spill, range, np);
      }
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
  const internal::Slab_range_renumbering global(range, welding, std::size_t(offset));
  mpi::on_all_ranks(comm, [&] { spill->finish(); });
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
  // A face record: count, indices, label, colour.
  const std::uint64_t face_bytes = 8 * std::uint64_t(range.number_of_polygons()) + 4 * spill->number_of_corners();
  const std::vector<std::uint64_t> part_bytes{rank == 0 ? header.size() : 0,
                                              24 * std::uint64_t(welding.number_of_new_vertices), face_bytes};
  // Pieces of 64 Ki records (1.5 MB of vertices): the write buffers stay
  // small next to the slab buffers.
  const std::size_t piece_records = std::size_t(1) << 16;
  std::ifstream spilled;
  std::size_t next_vertex = 0, next_polygon = 0;
  std::vector<char> records;
  std::vector<std::size_t> polygon;
  auto open = [&](const std::string& name) {
    spilled.close();
    spilled.clear();
    spilled.open(name, std::ios::binary);
    if(!spilled)
      throw std::runtime_error("cannot read the temporary file '" + name + "'");
  };
  auto read = [&](char* data, std::size_t bytes) {
    if(!spilled.read(data, std::streamsize(bytes)))
      throw std::runtime_error("short read in a temporary file next to '" + filename + "'");
  };
  mpi::write_sections(comm, filename, part_bytes, [&](std::size_t section, std::string& out) {
    if(section == 0)
    {
      if(rank == 0)
        out = header;
      return false;
    }
    if(section == 1)
    {
      // The new vertices are the local ones not matched below, in order.
      if(next_vertex == 0)
        open(spill->points_name());
      const std::size_t count = (std::min)(piece_records, range.number_of_vertices() - next_vertex);
      records.resize(24 * count);
      read(records.data(), records.size());
      for(std::size_t k = 0; k < count; ++k, ++next_vertex)
        if(global.is_new(next_vertex))
          out.append(records.data() + 24 * k, 24);
      return next_vertex < range.number_of_vertices();
    }
    if(next_polygon == 0)
      open(spill->faces_name());
    for(std::size_t done = 0; next_polygon < range.number_of_polygons() && done < piece_records; ++next_polygon, ++done)
    {
      unsigned char n = 0;
      read(reinterpret_cast<char*>(&n), 1);
      records.resize(4 * std::size_t(n) + 4);
      read(records.data(), records.size());
      polygon.resize(n);
      for(std::size_t k = 0; k < n; ++k)
      {
        std::uint32_t local = 0;
        std::memcpy(&local, records.data() + 4 * k, 4);
        polygon[k] = global(local);
      }
      std::int32_t label = 0;
      std::memcpy(&label, records.data() + 4 * std::size_t(n), 4);
      Ply::append_polygon(out, polygon.data(), polygon.size(), label);
    }
    return next_polygon < range.number_of_polygons();
  });
  spilled.close();
  spill.reset();
  stats.seconds_writing = internal::seconds_since(start);
  stats.seconds = internal::seconds_since(call_start);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MPI_DISTRIBUTED_BOOLEAN_ISOSURFACE_H
