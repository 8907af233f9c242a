// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_TRIANGLE_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_TRIANGLE_SOUP_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Input_buffer.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/read_OBJ.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/read_OFF.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/read_PLY.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/read_STL.h>

#include <cstddef>
#include <cstring>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/// \ingroup PkgBooleanIsosurfacing3IO
/// The mesh file formats of `read_triangle_soup()`.
enum class Mesh_file_format { OFF, OBJ, PLY, STL, from_content };

/// \ingroup PkgBooleanIsosurfacing3IO
/// The format named by the extension of `path` (case-insensitive), or
/// `from_content` for any other extension.
inline Mesh_file_format mesh_file_format_of(const std::string& path)
{
  using CGAL::Boolean_isosurfacing::internal::ends_with_lowercase;
  if(ends_with_lowercase(path, ".off")) return Mesh_file_format::OFF;
  if(ends_with_lowercase(path, ".obj")) return Mesh_file_format::OBJ;
  if(ends_with_lowercase(path, ".ply")) return Mesh_file_format::PLY;
  if(ends_with_lowercase(path, ".stl")) return Mesh_file_format::STL;
  return Mesh_file_format::from_content;
}

namespace internal_io {

inline Mesh_file_format sniff_format(const char* begin, const char* end)
{
  const std::size_t n = std::size_t(end - begin);
  if(n >= 4 && std::memcmp(begin, "ply", 3) == 0 && (begin[3] == '\n' || begin[3] == '\r'))
    return Mesh_file_format::PLY;
  CGAL::Boolean_isosurfacing::internal::Text_cursor in(begin, end);
  in.skip_spaces_and_comments('#');
  if(CGAL::Boolean_isosurfacing::internal::read_OFF_keyword(in))
    return Mesh_file_format::OFF;
  if(std::size_t(end - in.p) >= 6 && std::memcmp(in.p, "solid", 5) == 0 && CGAL::Boolean_isosurfacing::internal::is_text_space(in.p[5]))
    return Mesh_file_format::STL;
  // OBJ: the first statement (after comments) is one of the usual ones.
  const char* word = in.p;
  while(in.p < end && !CGAL::Boolean_isosurfacing::internal::is_text_space(*in.p)) ++in.p;
  const std::string first(word, in.p);
  for(const char* statement : {"v", "vn", "vt", "f", "o", "g", "s", "mtllib", "usemtl"})
    if(first == statement)
      return Mesh_file_format::OBJ;
  throw Invalid_input_error("cannot parse it as OFF, OBJ, PLY or STL: the extension names none of them and "
                            "the content starts like none of them");
}

inline void read_triangle_soup(const CGAL::Boolean_isosurfacing::internal::Input_buffer& buffer, Mesh_file_format format,
                               Triangle_soup_3& soup)
{
  soup = Triangle_soup_3();
  if(format == Mesh_file_format::from_content)
    format = sniff_format(buffer.begin(), buffer.end());
  switch(format)
  {
  case Mesh_file_format::OFF: CGAL::Boolean_isosurfacing::internal::read_OFF(buffer.begin(), buffer.end(), soup); break;
  case Mesh_file_format::OBJ: CGAL::Boolean_isosurfacing::internal::read_OBJ(buffer.begin(), buffer.end(), soup); break;
  case Mesh_file_format::PLY: CGAL::Boolean_isosurfacing::internal::read_PLY(buffer.begin(), buffer.end(), soup); break;
  default: CGAL::Boolean_isosurfacing::internal::read_STL(buffer.begin(), buffer.end(), soup); break;
  }
}

} // namespace internal_io

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * reads the mesh in `size` bytes at `data` (an OFF, OBJ, PLY or STL file's
 * content) into `soup`.  See the path overload.
 */
inline void read_triangle_soup(const char* data, std::size_t size, Mesh_file_format format, Triangle_soup_3& soup)
{
  internal_io::read_triangle_soup(CGAL::Boolean_isosurfacing::internal::Input_buffer(data, size), format, soup);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * reads the mesh file `path` into flat arrays: ASCII OFF; OBJ; PLY in ASCII
 * and binary (both byte orders, any numeric coordinate type, any integer
 * list types, other elements and properties skipped); STL in ASCII and
 * binary, its corners welded by exact coordinate equality.  The format comes
 * from the extension, or from the content for other extensions.
 *
 * The file is read with one `read()` and parsed from memory; numbers are
 * parsed with fast_float.  Polygons with more than 3 vertices are split into
 * a fan of triangles and counted in `Triangle_soup_3::triangulated_polygons`.
 * Nothing is validated beyond the file itself (the indices are in range, the
 * coordinates finite): see `read_closed_triangle_soup()` for a soup that
 * bounds a solid.
 *
 * Header counts are checked against the size of the file before anything is
 * allocated from them, so memory stays proportional to the file.
 *
 * \throws Invalid_input_error with a one-line message, without the file name:
 *   the file cannot be opened or is a directory; `Parse_error` (text formats,
 *   the message starts with "line N:"), `Non_finite_value_error` for a NaN or
 *   infinite coordinate (named as such); binary-format messages give the
 *   byte offset.
 */
inline Triangle_soup_3 read_triangle_soup(const std::string& path)
{
  Triangle_soup_3 soup;
  internal_io::read_triangle_soup(CGAL::Boolean_isosurfacing::internal::read_whole_file(path), mesh_file_format_of(path), soup);
  return soup;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_TRIANGLE_SOUP_H
