// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>

#include <charconv>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {
namespace internal_io {

// Writes `bytes` to `path` in one go; throws std::runtime_error naming the
// reason.  (An output problem is not an input error.)
inline void write_whole_file(const std::string& path, const std::string& bytes)
{
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if(f == nullptr)
    throw std::runtime_error("cannot write " + path + " (" + std::strerror(errno) + ")");
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool closed = std::fclose(f) == 0;
  if(!ok || !closed)
    throw std::runtime_error("cannot write " + path + " (" + std::strerror(errno) + ")");
}

// The shortest decimal that reads back as the same double.
inline void append_double(std::string& out, double v)
{
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), v);
  out.append(buffer, r.ptr);
}

inline void append_unsigned(std::string& out, std::uint32_t v)
{
  char buffer[16];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), v);
  out.append(buffer, r.ptr);
}

} // namespace internal_io

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * the bytes of `soup` as a binary little-endian PLY file: `vertex` with
 * double x, y, z, `face` with `list uchar uint vertex_indices`.  Doubles
 * keep every coordinate exact, so reading the file back gives `soup` again.
 */
inline std::string triangle_soup_to_binary_PLY(const Triangle_soup_3& soup)
{
  const std::string header = "ply\nformat binary_little_endian 1.0\ncomment Boolean_isosurfacing_3\n"
                             "element vertex " + std::to_string(soup.points.size()) +
                             "\nproperty double x\nproperty double y\nproperty double z\n"
                             "element face " + std::to_string(soup.triangles.size()) +
                             "\nproperty list uchar uint vertex_indices\nend_header\n";
  std::string out;
  out.resize(header.size() + 24 * soup.points.size() + 13 * soup.triangles.size());
  char* p = &out[0];
  std::memcpy(p, header.data(), header.size());
  p += header.size();
  const bool little = CGAL::Boolean_isosurfacing::internal::host_is_little_endian();
  if(little)
  {
    std::memcpy(p, soup.points.data(), 24 * soup.points.size());
    p += 24 * soup.points.size();
  }
  else
    for(const auto& q : soup.points)
      for(double c : q)
      {
        std::string b;
        CGAL::Boolean_isosurfacing::internal::put_little_endian(b, c);
        std::memcpy(p, b.data(), 8);
        p += 8;
      }
  for(const auto& t : soup.triangles)
  {
    *p++ = 3;
    std::uint32_t v[3] = {t[0], t[1], t[2]};
    if(!little)
      CGAL::Boolean_isosurfacing::internal::little_endian_to_host(v, 3); // the same byte reversal
    std::memcpy(p, v, 12);
    p += 12;
  }
  return out;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * the text of `soup` as an OFF file, each coordinate in the shortest decimal
 * that reads back as the same double (`std::to_chars`).
 */
inline std::string triangle_soup_to_OFF(const Triangle_soup_3& soup)
{
  std::string out = "OFF\n" + std::to_string(soup.points.size()) + " " + std::to_string(soup.triangles.size()) + " 0\n";
  out.reserve(out.size() + 40 * soup.points.size() + 20 * soup.triangles.size());
  for(const auto& q : soup.points)
  {
    internal_io::append_double(out, q[0]);
    out += ' ';
    internal_io::append_double(out, q[1]);
    out += ' ';
    internal_io::append_double(out, q[2]);
    out += '\n';
  }
  for(const auto& t : soup.triangles)
  {
    out += "3 ";
    internal_io::append_unsigned(out, t[0]);
    out += ' ';
    internal_io::append_unsigned(out, t[1]);
    out += ' ';
    internal_io::append_unsigned(out, t[2]);
    out += '\n';
  }
  return out;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * writes `soup` to `path` as binary PLY (extension `.ply`) or OFF (`.off`),
 * straight from its arrays, in one write.
 *
 * \throws std::invalid_argument for another extension, std::runtime_error if
 * the file cannot be written.
 */
inline void write_triangle_soup(const std::string& path, const Triangle_soup_3& soup)
{
  if(CGAL::Boolean_isosurfacing::internal::ends_with_lowercase(path, ".ply"))
    internal_io::write_whole_file(path, triangle_soup_to_binary_PLY(soup));
  else if(CGAL::Boolean_isosurfacing::internal::ends_with_lowercase(path, ".off"))
    internal_io::write_whole_file(path, triangle_soup_to_OFF(soup));
  else
    throw std::invalid_argument("write_triangle_soup: " + path + ": the extension must be .ply or .off");
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H
