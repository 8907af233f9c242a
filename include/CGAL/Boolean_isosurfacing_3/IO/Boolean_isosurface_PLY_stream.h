// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_PLY_STREAM_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_PLY_STREAM_H

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A `BooleanIsosurfaceSink` that streams the surface to a binary
/// little-endian PLY file in the layout of `write_PLY_with_fields()`, for
/// surfaces too large to hold in memory.  Points go straight to the file;
/// faces go to a temporary file `filename + ".faces"` (PLY stores all
/// vertices first), appended by `close()`, which also writes the final
/// counts into the fixed-width header.  Memory: O(1).
///
/// \cgalModels{BooleanIsosurfaceSink}
class Boolean_isosurface_PLY_stream
{
public:
  /// \throws std::runtime_error if a file cannot be opened.
  explicit Boolean_isosurface_PLY_stream(const std::string& filename)
    : m_filename(filename), m_faces_filename(filename + ".faces")
  {
    m_out.open(filename, std::ios::binary | std::ios::trunc);
    m_faces.open(m_faces_filename, std::ios::binary | std::ios::trunc);
    if(!m_out || !m_faces)
      throw std::runtime_error("cannot open '" + filename + "' for writing");
    write_header();
  }

  ~Boolean_isosurface_PLY_stream()
  {
    if(!m_closed)
    {
      m_faces.close();
      std::remove(m_faces_filename.c_str());
    }
  }

  void add_point(const std::array<double, 3>& p)
  {
    append_point(m_buffer, p);
    ++m_vertices;
    flush(m_out, m_buffer);
  }

  void add_polygon(const std::size_t* v, std::size_t n, int field)
  {
    append_polygon(m_face_buffer, v, n, field);
    ++m_polygons;
    flush(m_faces, m_face_buffer);
  }

  /// The bytes of one vertex record, appended to `out`.  With `header()` and
  /// `append_polygon()`, they let a writer that assembles the file from
  /// pieces (the MPI driver writes each rank's part at its offset) produce
  /// the very bytes of this stream.
  static void append_point(std::string& out, const std::array<double, 3>& p)
  {
    for(double c : p)
      CGAL::Boolean_isosurfacing::internal::put_little_endian(out, c);
  }

  /// The bytes of one face record (`v` are global vertex indices), appended to `out`.
  /// \throws Invalid_input_error if the polygon has more than 255 vertices or an index exceeds 2^31 - 1.
  static void append_polygon(std::string& out, const std::size_t* v, std::size_t n, int field)
  {
    if(n > 255)
      throw Invalid_input_error("a polygon of " + std::to_string(n) + " vertices does not fit a PLY uchar list");
    CGAL::Boolean_isosurfacing::internal::put_little_endian(out, static_cast<std::uint8_t>(n));
    for(std::size_t k = 0; k < n; ++k)
    {
      if(v[k] > std::size_t((std::numeric_limits<std::int32_t>::max)()))
        throw Invalid_input_error("too many points for PLY int indices");
      CGAL::Boolean_isosurfacing::internal::put_little_endian(out, static_cast<std::int32_t>(v[k]));
    }
    CGAL::Boolean_isosurfacing::internal::put_little_endian(out, static_cast<std::int32_t>(field));
    for(unsigned char c : field_color(field))
      CGAL::Boolean_isosurfacing::internal::put_little_endian(out, static_cast<std::uint8_t>(c));
  }

  /// The header of a file with these counts; its length does not depend on them.
  static std::string header(std::size_t vertices, std::size_t polygons)
  {
    char v[32], f[32];
    std::snprintf(v, sizeof v, "%020zu", vertices);
    std::snprintf(f, sizeof f, "%020zu", polygons);
    return std::string("ply\nformat binary_little_endian 1.0\n") +
           "comment Boolean_isosurfacing_3: field = index of the scalar field the face lies on, "
           "-1 = domain boundary\n" +
           "element vertex " + v + "\n" + "property double x\nproperty double y\nproperty double z\n" +
           "element face " + f + "\n" +
           "property list uchar int vertex_indices\nproperty int field\n" +
           "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  }

  std::size_t number_of_points() const { return m_vertices; }
  std::size_t number_of_polygons() const { return m_polygons; }

  /// Appends the faces, writes the counts, removes the temporary file.
  void close()
  {
    flush(m_out, m_buffer, true);
    flush(m_faces, m_face_buffer, true);
    m_faces.close();
    std::ifstream faces(m_faces_filename, std::ios::binary);
    m_out << faces.rdbuf();
    faces.close();
    std::remove(m_faces_filename.c_str());
    m_out.seekp(0);
    write_header();
    m_out.close();
    if(!m_out)
      throw std::runtime_error("failed writing '" + m_filename + "'");
    m_closed = true;
  }

private:
  static void flush(std::ofstream& out, std::string& buffer, bool always = false)
  {
    if(always || buffer.size() > (std::size_t(1) << 20))
    {
      out.write(buffer.data(), std::streamsize(buffer.size()));
      buffer.clear();
    }
  }

  // Fixed-width counts (20 digits, zero padded) so that close() can rewrite them in place.
  void write_header() { m_out << header(m_vertices, m_polygons); }

  std::string m_filename, m_faces_filename;
  std::ofstream m_out, m_faces;
  std::string m_buffer, m_face_buffer;
  std::size_t m_vertices = 0, m_polygons = 0;
  bool m_closed = false;
};

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_PLY_STREAM_H
