// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_SCALAR_FIELDS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_SCALAR_FIELDS_H

// Files of `Scalar_fields`: N scalar fields sampled at the V vertices of a
// tetrahedral domain.  Vertex v is
//   - for a `Tetrahedral_grid_3` with nx * ny * nz vertices, grid vertex
//     (i, j, k) with v = i + nx * (j + ny * k) (`vertex_index(i, j, k)`):
//     i varies fastest, k slowest;
//   - for a `Tetrahedral_mesh_3`, its 0-based index (the Medit index minus
//     1, the TetGen vertex number minus the file's first number).
// Value (v, i) is field i (0 <= i < N) at vertex v.  1 <= N <= 64.
//
// 1. Raw binary (`.raw` or `.f64`: float64; `.f32`: float32).
//    No header, no padding, no trailer: the file is exactly the V * N values
//    in vertex-major order (the N values of vertex 0, then the N values of
//    vertex 1, ...), each an IEEE 754 binary64 (8 bytes) or binary32
//    (4 bytes) number in little-endian byte order.  Value (v, i) is at byte
//    offset (v * N + i) * s, s = 8 or 4, and the file size is exactly
//    V * N * s bytes.  The file does not record V, N or s: the reader is
//    given them, and a file whose size differs is rejected (the message gives
//    the expected and the actual size).  Because the order is vertex-major
//    and the grid index puts k slowest, the values of a slab of grid layers
//    k0 <= k < k1 are one contiguous byte range: `Raw_scalar_field_reader`
//    reads such a range without loading the whole file.
//    float32 values are widened exactly to double when read; writing
//    float32 rounds to the nearest float, which can turn a tiny value into
//    +0 or -0 and so change its sign: prefer float64 when signs matter.
//
// 2. Text (any other extension).  Read line by line; a '#' starts a comment
//    that runs to the end of the line; blank lines are ignored.  The first
//    remaining line holds N alone; then each remaining line is one vertex,
//    in vertex order, holding its N values separated by blanks (spaces or
//    tabs).  Numbers are in C syntax ("1", "-0.5", "2.5e-3"), parsed with
//    std::from_chars (independent of the locale).  The writer prints
//    max_digits10 (17) significant digits, so that reading gives back the
//    same doubles.
//
// In both layouts every value must be finite: NaN and infinities are
// rejected with a Non_finite_value_error naming the vertex and the field.

#include <CGAL/Boolean_isosurfacing_3/Scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Input_excerpt.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <locale>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The number type of a raw scalar field file (always little-endian IEEE 754).
enum class Raw_scalar_type
{
  FLOAT64, ///< 8-byte binary64 (`double`)
  FLOAT32  ///< 4-byte binary32 (`float`)
};

/// The size in bytes of one value of type `type`.
inline std::size_t raw_scalar_size(Raw_scalar_type type) { return type == Raw_scalar_type::FLOAT64 ? 8 : 4; }

namespace internal {
namespace scalar_fields_io {

static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559, "double must be IEEE 754 binary64");
static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559, "float must be IEEE 754 binary32");

using CGAL::Boolean_isosurfacing::internal::host_is_little_endian;
using CGAL::Boolean_isosurfacing::internal::little_endian_to_host;

inline const char* type_name(Raw_scalar_type type)
{
  return type == Raw_scalar_type::FLOAT64 ? "float64" : "float32";
}

inline void check_number_of_fields(std::size_t number_of_fields, const std::string& filename)
{
  if(number_of_fields == 0 || number_of_fields > 64)
    throw Invalid_input_error("'" + filename + "': the number of scalar fields must be between 1 and 64, got " +
                              std::to_string(number_of_fields));
}

// V * N * s, or Invalid_input_error if it overflows.
inline std::uintmax_t expected_size(std::size_t number_of_vertices, std::size_t number_of_fields,
                                    Raw_scalar_type type, const std::string& filename)
{
  const std::uintmax_t s = raw_scalar_size(type);
  const std::uintmax_t limit = (std::numeric_limits<std::uintmax_t>::max)();
  if(number_of_fields != 0 && number_of_vertices > limit / (number_of_fields * s))
    throw Invalid_input_error("'" + filename + "': " + std::to_string(number_of_vertices) + " vertices x " +
                              std::to_string(number_of_fields) + " fields is too large");
  return std::uintmax_t(number_of_vertices) * number_of_fields * s;
}

inline std::uintmax_t file_size(const std::string& filename)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(filename, ec))
    throw Invalid_input_error("cannot open '" + filename + "': no such regular file");
  const std::uintmax_t size = std::filesystem::file_size(filename, ec);
  if(ec)
    throw Invalid_input_error("cannot open '" + filename + "': " + ec.message());
  return size;
}

[[noreturn]] inline void throw_non_finite(const std::string& filename, std::size_t vertex, std::size_t field,
                                          double value)
{
  throw Non_finite_value_error("'" + filename + "': vertex " + std::to_string(vertex) + ", field " +
                               std::to_string(field) + ": non-finite value " + std::to_string(value));
}

// Writers refuse what the readers would reject, before creating any file.
inline void check_finite_for_writing(const Scalar_fields& fields, const std::string& filename)
{
  const std::vector<double>& data = fields.data();
  const std::size_t N = fields.number_of_fields();
  for(std::size_t k = 0; k < data.size(); ++k)
    if(!std::isfinite(data[k]))
      throw_non_finite(filename, k / N, k % N, data[k]);
}

inline bool ends_with(const std::string& s, const char* suffix) { return CGAL::Boolean_isosurfacing::internal::ends_with_lowercase(s, suffix); }

} // namespace scalar_fields_io
} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Out-of-core access to a raw scalar field file (layout 1 at the top of this
 * header): opens the file once, checks its size, then reads any range of
 * vertices on demand with `seekg()` / `read()`.
 *
 * \warning Not thread-safe: one reader holds one stream; give each thread its own reader.
 *
 * \cgalModels{ScalarFieldSource}
 */
class Raw_scalar_field_reader
{
public:
  /// \throws Invalid_input_error if `number_of_fields` is not in 1..64, the
  ///         file cannot be opened, or its size is not exactly
  ///         `number_of_vertices * number_of_fields * raw_scalar_size(type)`
  ///         bytes (the message gives both sizes).
  Raw_scalar_field_reader(const std::string& filename, std::size_t number_of_vertices,
                          std::size_t number_of_fields, Raw_scalar_type type = Raw_scalar_type::FLOAT64)
    : m_filename(filename), m_number_of_vertices(number_of_vertices), m_number_of_fields(number_of_fields),
      m_type(type)
  {
    using namespace internal::scalar_fields_io;
    check_number_of_fields(number_of_fields, filename);
    const std::uintmax_t expected = expected_size(number_of_vertices, number_of_fields, type, filename);
    const std::uintmax_t actual = file_size(filename);
    if(actual != expected)
      throw Invalid_input_error("'" + filename + "' has " + std::to_string(actual) + " bytes, expected " +
                                std::to_string(expected) + " (" + std::to_string(number_of_vertices) +
                                " vertices x " + std::to_string(number_of_fields) + " fields x " +
                                std::to_string(raw_scalar_size(type)) + " bytes of " + type_name(type) + ")");
    m_in.open(filename, std::ios::binary);
    if(!m_in)
      throw Invalid_input_error("cannot open '" + filename + "'");
  }

  const std::string& filename() const { return m_filename; }
  std::size_t number_of_vertices() const { return m_number_of_vertices; }
  std::size_t number_of_fields() const { return m_number_of_fields; }
  Raw_scalar_type type() const { return m_type; }

  /*!
   * reads the values of the vertices `[first, first + count)` into `values`
   * (resized to `count * number_of_fields()`, vertex-major: the value of
   * field `i` at vertex `first + c` is `values[c * number_of_fields() + i]`),
   * widening float32 to double.
   * \throws std::out_of_range if the range is not within `[0, number_of_vertices())`;
   * \throws Non_finite_value_error naming the first NaN or infinite value (vertex and field);
   * \throws Invalid_input_error if the read fails (the file changed since it was opened).
   */
  void read(std::size_t first, std::size_t count, std::vector<double>& values)
  {
    using namespace internal::scalar_fields_io;
    if(first > m_number_of_vertices || count > m_number_of_vertices - first)
      throw std::out_of_range("'" + m_filename + "': vertices [" + std::to_string(first) + ", " +
                              std::to_string(first) + " + " + std::to_string(count) + ") are not within [0, " +
                              std::to_string(m_number_of_vertices) + ")");
    const std::size_t n = count * m_number_of_fields;
    values.resize(n);
    if(n == 0)
      return;
    const std::size_t s = raw_scalar_size(m_type);
    m_in.clear();
    m_in.seekg(std::streamoff(first * m_number_of_fields * s), std::ios::beg);
    if(m_type == Raw_scalar_type::FLOAT64)
    {
      read_bytes(reinterpret_cast<char*>(values.data()), n * s, first);
      little_endian_to_host(values.data(), n);
    }
    else
    {
      // Through a bounded buffer: no second full-size copy for large ranges.
      const std::size_t chunk = std::size_t(1) << 16;
      m_buffer.resize((std::min)(n, chunk));
      for(std::size_t done = 0; done < n;)
      {
        const std::size_t k = (std::min)(chunk, n - done);
        read_bytes(reinterpret_cast<char*>(m_buffer.data()), k * s, first);
        little_endian_to_host(m_buffer.data(), k);
        std::copy(m_buffer.begin(), m_buffer.begin() + std::ptrdiff_t(k), values.begin() + std::ptrdiff_t(done));
        done += k;
      }
    }
    for(std::size_t k = 0; k < n; ++k)
      if(!std::isfinite(values[k]))
        throw_non_finite(m_filename, first + k / m_number_of_fields, k % m_number_of_fields, values[k]);
  }

private:
  void read_bytes(char* to, std::size_t bytes, std::size_t first)
  {
    m_in.read(to, std::streamsize(bytes));
    if(!m_in || std::size_t(m_in.gcount()) != bytes)
      throw Invalid_input_error("'" + m_filename + "': reading from vertex " + std::to_string(first) +
                                " failed (the file is shorter than when it was opened?)");
  }

  std::string m_filename;
  std::ifstream m_in;
  std::size_t m_number_of_vertices;
  std::size_t m_number_of_fields;
  Raw_scalar_type m_type;
  std::vector<float> m_buffer;
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a whole raw scalar field file (layout 1 at the top of this header).
 * \throws as the constructor and `read()` of `Raw_scalar_field_reader`.
 */
inline Scalar_fields read_raw_scalar_fields(const std::string& filename, std::size_t number_of_vertices,
                                            std::size_t number_of_fields,
                                            Raw_scalar_type type = Raw_scalar_type::FLOAT64)
{
  Raw_scalar_field_reader reader(filename, number_of_vertices, number_of_fields, type);
  std::vector<double> values;
  reader.read(0, number_of_vertices, values);
  return Scalar_fields(number_of_fields, std::move(values));
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes `fields` as a raw file (layout 1 at the top of this header).
 * \throws Non_finite_value_error on a NaN or infinite value (the file would not be readable);
 * \throws Invalid_input_error for float32 if a value overflows the float range;
 * \throws std::runtime_error if the file cannot be opened or written.
 */
inline void write_raw_scalar_fields(const std::string& filename, const Scalar_fields& fields,
                                    Raw_scalar_type type = Raw_scalar_type::FLOAT64)
{
  using namespace internal::scalar_fields_io;
  const std::vector<double>& data = fields.data();
  const std::size_t N = fields.number_of_fields();
  check_finite_for_writing(fields, filename);
  for(std::size_t k = 0; k < data.size(); ++k)
  {
    if(type == Raw_scalar_type::FLOAT32 && !std::isfinite(static_cast<float>(data[k])))
      throw Invalid_input_error("'" + filename + "': vertex " + std::to_string(k / N) + ", field " +
                                std::to_string(k % N) + ": the value " + std::to_string(data[k]) +
                                " overflows float32");
  }
  std::ofstream out(filename, std::ios::binary | std::ios::trunc);
  if(!out)
    throw std::runtime_error("cannot open '" + filename + "' for writing");
  const std::size_t chunk = std::size_t(1) << 16;
  std::vector<double> buffer64;
  std::vector<float> buffer32;
  for(std::size_t done = 0; done < data.size();)
  {
    const std::size_t k = (std::min)(chunk, data.size() - done);
    if(type == Raw_scalar_type::FLOAT64)
    {
      buffer64.assign(data.begin() + std::ptrdiff_t(done), data.begin() + std::ptrdiff_t(done + k));
      little_endian_to_host(buffer64.data(), k); // the swap is its own inverse
      out.write(reinterpret_cast<const char*>(buffer64.data()), std::streamsize(8 * k));
    }
    else
    {
      buffer32.resize(k);
      for(std::size_t c = 0; c < k; ++c)
        buffer32[c] = static_cast<float>(data[done + c]);
      little_endian_to_host(buffer32.data(), k);
      out.write(reinterpret_cast<const char*>(buffer32.data()), std::streamsize(4 * k));
    }
    done += k;
  }
  out.flush();
  if(!out)
    throw std::runtime_error("cannot write '" + filename + "'");
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a text scalar field stream (layout 2 at the top of this header);
 * `name` is used in error messages.
 * \throws Parse_error (position() = 1-based line number) on a malformed line
 *         (not a number, a wrong number of values, N not in 1..64);
 * \throws Non_finite_value_error naming the line, the vertex and the field;
 * \throws Empty_input_error if there is no N line or no vertex line.
 */
inline Scalar_fields read_text_scalar_fields(std::istream& in, const std::string& name = "<stream>")
{
  std::string line;
  std::size_t line_number = 0;
  std::size_t N = 0;
  std::vector<double> values;
  std::vector<std::string_view> tokens;
  auto fail = [&](const std::string& what) {
    throw Parse_error("'" + name + "' line " + std::to_string(line_number) + ": " + what + ": '" +
                        CGAL::Boolean_isosurfacing::internal::input_excerpt(line, 77) + "'",
                      line_number);
  };
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while(std::getline(in, line))
  {
    ++line_number;
    tokens.clear();
    for(const char *p = line.data(), *end = p + line.size(); p != end;)
    {
      while(p != end && blank(*p))
        ++p;
      if(p == end || *p == '#')
        break;
      const char* start = p;
      while(p != end && !blank(*p) && *p != '#')
        ++p;
      tokens.emplace_back(start, std::size_t(p - start));
    }
    if(tokens.empty())
      continue;
    if(N == 0)
    {
      unsigned long long n = 0;
      const char* last = tokens[0].data() + tokens[0].size();
      const std::from_chars_result r = std::from_chars(tokens[0].data(), last, n);
      if(tokens.size() != 1 || r.ec != std::errc() || r.ptr != last || n == 0 || n > 64)
        fail("expected the number of fields N (one integer, 1 to 64) on the first line");
      N = std::size_t(n);
      continue;
    }
    if(tokens.size() != N)
      fail("expected " + std::to_string(N) + " values (one per field) for vertex " +
           std::to_string(values.size() / N) + ", found " + std::to_string(tokens.size()));
    for(std::size_t i = 0; i < N; ++i)
    {
      const char* first = tokens[i].data();
      const char* last = first + tokens[i].size();
      if(first != last && *first == '+')
        ++first; // from_chars does not accept a leading '+'
      double value = 0;
      const std::from_chars_result r = std::from_chars(first, last, value);
      if(r.ec == std::errc::result_out_of_range && r.ptr == last)
        value = std::numeric_limits<double>::infinity(); // reported as non-finite below
      else if(r.ec != std::errc() || r.ptr != last)
        fail("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(tokens[i]) + "' is not a number");
      if(!std::isfinite(value))
        throw Non_finite_value_error("'" + name + "' line " + std::to_string(line_number) + ": vertex " +
                                     std::to_string(values.size() / N) + ", field " + std::to_string(i) +
                                     ": non-finite value '" + CGAL::Boolean_isosurfacing::internal::input_excerpt(tokens[i]) + "'");
      values.push_back(value);
    }
  }
  if(in.bad())
    throw Invalid_input_error("'" + name + "': read error after line " + std::to_string(line_number));
  if(N == 0)
    throw Empty_input_error("'" + name + "': no line giving the number of fields");
  if(values.empty())
    throw Empty_input_error("'" + name + "': " + std::to_string(N) + " fields but no vertex line");
  return Scalar_fields(N, std::move(values));
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// reads the text scalar field file `filename` (layout 2 at the top of this header).
/// \throws Invalid_input_error if it cannot be opened, else as the stream overload.
inline Scalar_fields read_text_scalar_fields(const std::string& filename)
{
  internal::scalar_fields_io::file_size(filename); // a regular file, or the error naming it
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Invalid_input_error("cannot open '" + filename + "'");
  return read_text_scalar_fields(in, filename);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes `fields` as text (layout 2 at the top of this header), with
 * `max_digits10` significant digits and the classic locale.
 * \throws Non_finite_value_error on a NaN or infinite value (the file would not be readable);
 * \throws std::runtime_error if writing fails.
 */
inline void write_text_scalar_fields(std::ostream& out, const Scalar_fields& fields)
{
  const std::size_t N = fields.number_of_fields();
  internal::scalar_fields_io::check_finite_for_writing(fields, "<output>");
  const std::locale old_locale = out.imbue(std::locale::classic());
  const std::streamsize old_precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << N << '\n';
  for(std::size_t v = 0; v < fields.number_of_vertices(); ++v)
  {
    const double* x = fields.values_at(v);
    for(std::size_t i = 0; i < N; ++i)
      out << (i == 0 ? "" : " ") << x[i];
    out << '\n';
  }
  out.precision(old_precision);
  out.imbue(old_locale);
  out.flush();
  if(!out)
    throw std::runtime_error("writing the scalar fields failed");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes `fields` to the text file `filename` (see the stream overload).
/// \throws Non_finite_value_error (naming the file, vertex and field) before creating the file;
/// \throws std::runtime_error if the file cannot be opened or written.
inline void write_text_scalar_fields(const std::string& filename, const Scalar_fields& fields)
{
  internal::scalar_fields_io::check_finite_for_writing(fields, filename);
  std::ofstream out(filename, std::ios::binary | std::ios::trunc);
  if(!out)
    throw std::runtime_error("cannot open '" + filename + "' for writing");
  try
  {
    write_text_scalar_fields(out, fields);
  }
  catch(const std::runtime_error&)
  {
    throw std::runtime_error("cannot write '" + filename + "'");
  }
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads scalar fields for a domain of `number_of_vertices` vertices, choosing
 * the layout by the extension (case-insensitive): `.raw` and `.f64` are raw
 * float64, `.f32` raw float32, anything else text.
 *
 * - Raw files have no header: `number_of_vertices` must be given (not 0), and
 *   so must `number_of_fields_hint` (N).  With a hint of 0 the call fails,
 *   stating the N the file size would give if it is a whole number.
 * - Text files give N themselves: a non-zero `number_of_fields_hint` must
 *   equal it, and a non-zero `number_of_vertices` must equal the number of
 *   vertex lines (0: not checked).
 *
 * \throws Invalid_input_error (or a derived type) as the layout readers, or on a
 *         count that does not match.
 */
inline Scalar_fields read_scalar_fields(const std::string& filename, std::size_t number_of_vertices,
                                        std::size_t number_of_fields_hint = 0)
{
  using namespace internal::scalar_fields_io;
  const bool f32 = ends_with(filename, ".f32");
  if(f32 || ends_with(filename, ".raw") || ends_with(filename, ".f64"))
  {
    const Raw_scalar_type type = f32 ? Raw_scalar_type::FLOAT32 : Raw_scalar_type::FLOAT64;
    if(number_of_vertices == 0)
      throw Invalid_input_error("'" + filename + "' is a raw " + type_name(type) +
                                " file without header: the number of vertices of the domain is needed to read it");
    if(number_of_fields_hint == 0)
    {
      const std::uintmax_t size = file_size(filename);
      const std::uintmax_t per_field = expected_size(number_of_vertices, 1, type, filename);
      if(size != 0 && size % per_field == 0)
        throw Invalid_input_error("'" + filename + "' is a raw " + type_name(type) +
                                  " file without header: give its number of fields N (its size, " +
                                  std::to_string(size) + " bytes, fits N = " + std::to_string(size / per_field) +
                                  " over " + std::to_string(number_of_vertices) + " vertices)");
      throw Invalid_input_error("'" + filename + "' has " + std::to_string(size) + " bytes, not a positive multiple of " +
                                std::to_string(per_field) + " (" + std::to_string(number_of_vertices) +
                                " vertices x " + std::to_string(raw_scalar_size(type)) + " bytes of " +
                                type_name(type) + "): it does not hold fields over " +
                                std::to_string(number_of_vertices) + " vertices");
    }
    return read_raw_scalar_fields(filename, number_of_vertices, number_of_fields_hint, type);
  }
  Scalar_fields fields = read_text_scalar_fields(filename);
  if(number_of_fields_hint != 0 && fields.number_of_fields() != number_of_fields_hint)
    throw Invalid_input_error("'" + filename + "' has " + std::to_string(fields.number_of_fields()) +
                              " fields, expected " + std::to_string(number_of_fields_hint));
  if(number_of_vertices != 0 && fields.number_of_vertices() != number_of_vertices)
    throw Invalid_input_error("'" + filename + "' has values for " + std::to_string(fields.number_of_vertices()) +
                              " vertices, the domain has " + std::to_string(number_of_vertices));
  return fields;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_SCALAR_FIELDS_H
