// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {
namespace internal_io {

// The writers produce bytes into a sink: a std::string (the `*_to_*`
// functions) or a file written in large blocks as it fills (so that writing
// a soup never holds a second copy of it in memory).
class String_sink
{
public:
  explicit String_sink(std::string& out) : m_out(out) {}
  void put(const char* data, std::size_t size) { m_out.append(data, size); }
  void reserve(std::size_t size) { m_out.reserve(m_out.size() + size); }

private:
  std::string& m_out;
};

class File_sink
{
public:
  explicit File_sink(const std::string& path) : m_path(path), m_file(std::fopen(path.c_str(), "wb"))
  {
    if(m_file == nullptr)
      fail();
    m_buffer.reserve(block);
  }
  File_sink(const File_sink&) = delete;
  File_sink& operator=(const File_sink&) = delete;
  ~File_sink()
  {
    if(m_file != nullptr)
      std::fclose(m_file);
  }

  void put(const char* data, std::size_t size)
  {
    if(m_buffer.size() + size > block)
      flush();
    if(size >= block) // a large block (the points of a binary PLY): straight to the file
      write(data, size);
    else
      m_buffer.insert(m_buffer.end(), data, data + size);
  }
  void reserve(std::size_t) {}

  // Flushes and closes; throws std::runtime_error naming the reason.
  void close()
  {
    flush();
    std::FILE* f = m_file;
    m_file = nullptr;
    if(std::fclose(f) != 0)
      fail();
  }

private:
  static constexpr std::size_t block = std::size_t(1) << 22;

  void flush()
  {
    write(m_buffer.data(), m_buffer.size());
    m_buffer.clear();
  }
  void write(const char* data, std::size_t size)
  {
    if(size != 0 && std::fwrite(data, 1, size, m_file) != size)
      fail();
  }
  [[noreturn]] void fail() const
  {
    throw std::runtime_error("cannot write " + m_path + " (" + std::strerror(errno) + ")");
  }

  std::string m_path;
  std::FILE* m_file;
  std::vector<char> m_buffer;
};

// Text formatting into a small stack buffer, flushed into the sink.
template <typename Sink>
class Text_writer
{
public:
  explicit Text_writer(Sink& sink) : m_sink(sink) {}
  ~Text_writer() { flush(); }

  // The shortest decimal that reads back as the same double.
  void number(double v) { m_end = std::to_chars(m_end, m_buffer + sizeof(m_buffer), v).ptr; }
  void number(std::uint64_t v) { m_end = std::to_chars(m_end, m_buffer + sizeof(m_buffer), v).ptr; }
  void text(const char* s)
  {
    const std::size_t n = std::strlen(s);
    std::memcpy(m_end, s, n);
    m_end += n;
  }
  void character(char c) { *m_end++ = c; }
  // Called after each line: room for the longest line (4 numbers) remains.
  void end_line()
  {
    *m_end++ = '\n';
    if(m_end - m_buffer > std::ptrdiff_t(sizeof(m_buffer) - 256))
      flush();
  }

private:
  void flush()
  {
    m_sink.put(m_buffer, std::size_t(m_end - m_buffer));
    m_end = m_buffer;
  }

  Sink& m_sink;
  char m_buffer[1 << 16];
  char* m_end = m_buffer;
};

template <typename Sink>
void put_binary_PLY(const Triangle_soup_3& soup, Sink& sink)
{
  const std::string header = "ply\nformat binary_little_endian 1.0\ncomment Boolean_isosurfacing_3\n"
                             "element vertex " + std::to_string(soup.points.size()) +
                             "\nproperty double x\nproperty double y\nproperty double z\n"
                             "element face " + std::to_string(soup.triangles.size()) +
                             "\nproperty list uchar uint vertex_indices\nend_header\n";
  sink.reserve(header.size() + 24 * soup.points.size() + 13 * soup.triangles.size());
  sink.put(header.data(), header.size());
  const bool little = CGAL::Boolean_isosurfacing::internal::host_is_little_endian();
  if(little)
    sink.put(reinterpret_cast<const char*>(soup.points.data()), 24 * soup.points.size());
  else
    for(const auto& q : soup.points)
    {
      std::string b;
      for(double c : q)
        CGAL::Boolean_isosurfacing::internal::put_little_endian(b, c);
      sink.put(b.data(), b.size());
    }
  // 13 bytes per face, packed a block at a time.
  char block[13 * 4096];
  std::size_t used = 0;
  for(const auto& t : soup.triangles)
  {
    block[used] = 3;
    std::uint32_t v[3] = {t[0], t[1], t[2]};
    if(!little)
      CGAL::Boolean_isosurfacing::internal::little_endian_to_host(v, 3); // the same byte reversal
    std::memcpy(block + used + 1, v, 12);
    used += 13;
    if(used == sizeof(block))
    {
      sink.put(block, used);
      used = 0;
    }
  }
  sink.put(block, used);
}

template <typename Sink>
void put_OFF(const Triangle_soup_3& soup, Sink& sink)
{
  Text_writer<Sink> out(sink);
  out.text("OFF\n");
  out.number(std::uint64_t(soup.points.size()));
  out.character(' ');
  out.number(std::uint64_t(soup.triangles.size()));
  out.text(" 0");
  out.end_line();
  for(const auto& q : soup.points)
  {
    out.number(q[0]);
    out.character(' ');
    out.number(q[1]);
    out.character(' ');
    out.number(q[2]);
    out.end_line();
  }
  for(const auto& t : soup.triangles)
  {
    out.text("3 ");
    out.number(std::uint64_t(t[0]));
    out.character(' ');
    out.number(std::uint64_t(t[1]));
    out.character(' ');
    out.number(std::uint64_t(t[2]));
    out.end_line();
  }
}

template <typename Sink>
void put_OBJ(const Triangle_soup_3& soup, Sink& sink)
{
  Text_writer<Sink> out(sink);
  for(const auto& q : soup.points)
  {
    out.text("v ");
    out.number(q[0]);
    out.character(' ');
    out.number(q[1]);
    out.character(' ');
    out.number(q[2]);
    out.end_line();
  }
  for(const auto& t : soup.triangles)
  {
    out.text("f ");
    out.number(std::uint64_t(t[0]) + 1);
    out.character(' ');
    out.number(std::uint64_t(t[1]) + 1);
    out.character(' ');
    out.number(std::uint64_t(t[2]) + 1);
    out.end_line();
  }
}

// Binary STL: 80-byte header, facet count, per facet the unit normal and the
// three corners as little-endian floats and a zero attribute word.
template <typename Sink>
void put_binary_STL(const Triangle_soup_3& soup, Sink& sink)
{
  if(soup.triangles.size() > 0xffffffffu)
    throw std::invalid_argument("binary STL holds at most 2^32 - 1 facets");
  char header[84] = "binary STL written by Boolean_isosurfacing_3";
  std::memset(header + 45, ' ', 80 - 45);
  const std::uint32_t count = std::uint32_t(soup.triangles.size());
  std::string count_bytes;
  CGAL::Boolean_isosurfacing::internal::put_little_endian(count_bytes, count);
  std::memcpy(header + 80, count_bytes.data(), 4);
  sink.reserve(84 + 50 * soup.triangles.size());
  sink.put(header, 84);
  const bool little = CGAL::Boolean_isosurfacing::internal::host_is_little_endian();
  char block[50 * 1024];
  std::size_t used = 0;
  for(const auto& t : soup.triangles)
  {
    std::array<std::array<float, 3>, 3> p;
    for(int v = 0; v < 3; ++v)
      for(int a = 0; a < 3; ++a)
        p[v][a] = float(soup.points[t[v]][a]);
    const double e1[3] = {double(p[1][0]) - p[0][0], double(p[1][1]) - p[0][1], double(p[1][2]) - p[0][2]};
    const double e2[3] = {double(p[2][0]) - p[0][0], double(p[2][1]) - p[0][1], double(p[2][2]) - p[0][2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    float facet[12];
    for(int a = 0; a < 3; ++a)
      facet[a] = length > 0 ? float(n[a] / length) : 0.f;
    for(int v = 0; v < 3; ++v)
      for(int a = 0; a < 3; ++a)
        facet[3 + 3 * v + a] = p[v][a];
    std::memcpy(block + used, facet, 48);
    if(!little)
      for(int f = 0; f < 12; ++f)
        std::reverse(block + used + 4 * f, block + used + 4 * f + 4);
    block[used + 48] = block[used + 49] = 0;
    used += 50;
    if(used == sizeof(block))
    {
      sink.put(block, used);
      used = 0;
    }
  }
  sink.put(block, used);
}

template <typename Sink>
void put_triangle_soup(const std::string& path, const Triangle_soup_3& soup, Sink& sink)
{
  using CGAL::Boolean_isosurfacing::internal::ends_with_lowercase;
  if(ends_with_lowercase(path, ".ply"))
    put_binary_PLY(soup, sink);
  else if(ends_with_lowercase(path, ".off"))
    put_OFF(soup, sink);
  else if(ends_with_lowercase(path, ".obj"))
    put_OBJ(soup, sink);
  else if(ends_with_lowercase(path, ".stl"))
    put_binary_STL(soup, sink);
  else
    throw std::invalid_argument("write_triangle_soup: " + path + ": the extension must be .ply, .off, .obj or .stl");
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
  std::string out;
  internal_io::String_sink sink(out);
  internal_io::put_binary_PLY(soup, sink);
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
  std::string out;
  internal_io::String_sink sink(out);
  internal_io::put_OFF(soup, sink);
  return out;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * writes `soup` to `path`, straight from its arrays and in large blocks (no
 * second copy of the soup in memory), in the format of the extension
 * (case-insensitive): `.ply` binary little-endian PLY with double
 * coordinates, `.off` OFF and `.obj` OBJ with the shortest decimals that
 * read back as the same doubles (all three lossless), `.stl` binary STL
 * (floats, as the format has them).
 *
 * \throws std::invalid_argument for another extension, std::runtime_error if
 * the file cannot be written.
 */
inline void write_triangle_soup(const std::string& path, const Triangle_soup_3& soup)
{
  using CGAL::Boolean_isosurfacing::internal::ends_with_lowercase;
  if(!(ends_with_lowercase(path, ".ply") || ends_with_lowercase(path, ".off") || ends_with_lowercase(path, ".obj") ||
       ends_with_lowercase(path, ".stl")))
    throw std::invalid_argument("write_triangle_soup: " + path + ": the extension must be .ply, .off, .obj or .stl");
  internal_io::File_sink sink(path);
  internal_io::put_triangle_soup(path, soup, sink);
  sink.close();
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_WRITE_TRIANGLE_SOUP_H
