// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_FILES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_FILES_H

// Files of the output of the Boolean isosurface extraction
// (`Boolean_isosurface_soup`, `Crease_network`).
//
// PLY with fields (`write_PLY_with_fields()`), ASCII or binary little-endian:
//
//   ply
//   format ascii 1.0                      (or: format binary_little_endian 1.0)
//   comment Boolean_isosurfacing_3: field = index of the scalar field ...
//   element vertex V
//   property double x
//   property double y
//   property double z
//   element face F
//   property list uchar int vertex_indices
//   property int field                    (-1: a face closing the set on the domain boundary)
//   property uchar red
//   property uchar green
//   property uchar blue
//   end_header
//
// then V vertex records and F face records (ASCII: one per line, doubles with
// max_digits10 significant digits).  The colour is `field_color(field)`: a
// fixed palette of 12 colours cycled by field index, grey for -1.
// `read_PLY_with_fields()` reads this layout back, and more generally any
// ASCII or binary (either byte order) PLY file with a vertex element having
// x, y, z and a face element having a list `vertex_indices` (or
// `vertex_index`) and a scalar `field`; other properties and elements are
// skipped.
//
// Polylines (`write_polylines()`), CGAL's polylines text format: one line
// per polyline, `n x1 y1 z1 ... xn yn zn`.  Corners (`write_corners()`): one
// line per corner, `x y z`.  OFF (`write_OFF_polygons()`): `OFF`, `V F 0`,
// V lines `x y z`, F lines `k i1 ... ik`.  All coordinates are written with
// max_digits10 (17) significant digits in the classic locale, so that reading
// gives back the same doubles.
//
// Errors: writers throw std::runtime_error when the file cannot be opened or
// written, and Invalid_input_error when the data cannot be written faithfully
// (an index out of range, a polygon of more than 255 vertices for PLY, a
// field label below -1, face_fields not matching the polygons).  The reader
// throws Invalid_input_error (Parse_error with the line number for ASCII
// bodies and headers) naming the file.

#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Input_excerpt.h>

#include <CGAL/double.h> // CGAL::to_double(double)
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
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
#include <sstream>
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
/// The colour of the faces labelled `field` in `write_PLY_with_fields()`:
/// grey (160, 160, 160) for `domain_boundary` (-1), else entry `field % 12`
/// of a fixed qualitative palette (ColorBrewer Set1 and Dark2 colours, no grey).
inline std::array<unsigned char, 3> field_color(int field)
{
  static const unsigned char palette[12][3] = {{228, 26, 28},  {55, 126, 184},  {77, 175, 74},  {152, 78, 163},
                                               {255, 127, 0},  {255, 255, 51},  {166, 86, 40},  {247, 129, 191},
                                               {27, 158, 119}, {117, 112, 179}, {230, 171, 2},  {102, 194, 165}};
  if(field < 0)
    return {160, 160, 160};
  const unsigned char* c = palette[field % 12];
  return {c[0], c[1], c[2]};
}

namespace internal {
namespace soup_files_io {

using CGAL::Boolean_isosurfacing::internal::host_is_little_endian;
using CGAL::Boolean_isosurfacing::internal::put_little_endian;

// Restores, on destruction, the locale and precision of a stream set up for
// exact, locale-independent numbers.
class Exact_number_format
{
public:
  explicit Exact_number_format(std::ostream& out)
    : m_out(out), m_locale(out.imbue(std::locale::classic())),
      m_precision(out.precision(std::numeric_limits<double>::max_digits10))
  {}
  ~Exact_number_format()
  {
    m_out.precision(m_precision);
    m_out.imbue(m_locale);
  }

private:
  std::ostream& m_out;
  std::locale m_locale;
  std::streamsize m_precision;
};

template <typename Point_3>
std::array<double, 3> coordinates(const Point_3& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}
inline std::array<double, 3> coordinates(const std::array<double, 3>& p) { return p; }

inline void check_point_index(std::size_t index, std::size_t number_of_points, const char* what, std::size_t which)
{
  if(index >= number_of_points)
    throw Invalid_input_error(std::string(what) + " " + std::to_string(which) + " refers to point " +
                              std::to_string(index) + " but there are " + std::to_string(number_of_points) +
                              " points");
}

template <typename Point_3>
void check_soup(const Boolean_isosurface_soup<Point_3>& soup, std::size_t max_polygon_size)
{
  if(soup.face_fields.size() != soup.polygons.size())
    throw Invalid_input_error("the soup has " + std::to_string(soup.face_fields.size()) + " face fields for " +
                              std::to_string(soup.polygons.size()) + " polygons");
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    const std::vector<std::size_t>& polygon = soup.polygons[f];
    if(polygon.size() < 3 || polygon.size() > max_polygon_size)
      throw Invalid_input_error("polygon " + std::to_string(f) + " has " + std::to_string(polygon.size()) +
                                " vertices (3 to " + std::to_string(max_polygon_size) + " can be written)");
    for(std::size_t v : polygon)
      check_point_index(v, soup.points.size(), "polygon", f);
    if(soup.face_fields[f] < Boolean_isosurface_soup<Point_3>::domain_boundary)
      throw Invalid_input_error("polygon " + std::to_string(f) + " has the field label " +
                                std::to_string(soup.face_fields[f]) + " (labels are -1 or a field index)");
  }
}

template <typename F>
void write_to_file(const std::string& filename, bool binary, F write)
{
  std::ofstream out(filename, binary ? (std::ios::binary | std::ios::trunc) : std::ios::trunc);
  if(!out)
    throw std::runtime_error("cannot open '" + filename + "' for writing");
  write(out);
  out.flush();
  if(!out)
    throw std::runtime_error("cannot write '" + filename + "'");
}

inline void check_written(std::ostream& out, const char* what)
{
  out.flush();
  if(!out)
    throw std::runtime_error(std::string("writing the ") + what + " failed");
}

// ---- PLY reading

enum class Ply_type
{
  INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64
};

inline bool ply_type_from_name(const std::string& name, Ply_type& type)
{
  static const std::pair<const char*, Ply_type> names[] = {
      {"char", Ply_type::INT8},     {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
      {"uint8", Ply_type::UINT8},   {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
      {"ushort", Ply_type::UINT16}, {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
      {"int32", Ply_type::INT32},   {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
      {"float", Ply_type::FLOAT32}, {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
      {"float64", Ply_type::FLOAT64}};
  for(const auto& n : names)
    if(name == n.first)
    {
      type = n.second;
      return true;
    }
  return false;
}

inline std::size_t ply_type_size(Ply_type t)
{
  switch(t)
  {
  case Ply_type::INT8: case Ply_type::UINT8: return 1;
  case Ply_type::INT16: case Ply_type::UINT16: return 2;
  case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
  default: return 8;
  }
}

struct Ply_property
{
  std::string name;
  bool is_list = false;
  Ply_type count_type = Ply_type::UINT8;
  Ply_type type = Ply_type::FLOAT64;
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

enum class Ply_format
{
  ASCII, BINARY_LITTLE_ENDIAN, BINARY_BIG_ENDIAN
};

// The values of a PLY body, one at a time, as doubles.
class Ply_value_reader
{
public:
  Ply_value_reader(std::istream& in, Ply_format format, const std::string& name, std::size_t header_lines)
    : m_in(in), m_format(format), m_name(name), m_line_number(header_lines)
  {}

  // ASCII: the next record is the next non-blank line.
  void begin_record(const char* element, std::size_t index)
  {
    if(m_format != Ply_format::ASCII)
      return;
    m_tokens.clear();
    m_next = 0;
    while(m_tokens.empty())
    {
      if(!std::getline(m_in, m_line))
        throw Parse_error("'" + m_name + "' line " + std::to_string(m_line_number) + ": the file ends before " +
                            element + " " + std::to_string(index),
                          m_line_number);
      ++m_line_number;
      std::istringstream split(m_line);
      std::string token;
      while(split >> token)
        m_tokens.push_back(token);
    }
  }

  // ASCII: every value of the record was used.
  void end_record()
  {
    if(m_format == Ply_format::ASCII && m_next != m_tokens.size())
      fail("expected " + std::to_string(m_next) + " values, found " + std::to_string(m_tokens.size()));
  }

  double value(Ply_type type)
  {
    if(m_format == Ply_format::ASCII)
    {
      if(m_next == m_tokens.size())
        fail("too few values");
      const std::string& t = m_tokens[m_next++];
      const char* first = t.data();
      const char* last = first + t.size();
      if(first != last && *first == '+')
        ++first;
      double v = 0;
      const std::from_chars_result r = std::from_chars(first, last, v);
      if(r.ec != std::errc() || r.ptr != last)
        fail("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(t) + "' is not a number");
      return v;
    }
    char b[8];
    const std::size_t s = ply_type_size(type);
    if(!m_in.read(b, std::streamsize(s)))
      throw Invalid_input_error("'" + m_name + "': the binary PLY body ends early");
    if((m_format == Ply_format::BINARY_LITTLE_ENDIAN) != host_is_little_endian())
      std::reverse(b, b + s);
    switch(type)
    {
    case Ply_type::INT8: { std::int8_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::UINT8: { std::uint8_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::INT16: { std::int16_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::UINT16: { std::uint16_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::INT32: { std::int32_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::UINT32: { std::uint32_t x; std::memcpy(&x, b, s); return x; }
    case Ply_type::FLOAT32: { float x; std::memcpy(&x, b, s); return x; }
    default: { double x; std::memcpy(&x, b, s); return x; }
    }
  }

  // An integer value in [lo, hi].
  long long integer(Ply_type type, long long lo, long long hi, const std::string& what)
  {
    const double v = value(type);
    if(!(v >= double(lo) && v <= double(hi)) || v != std::floor(v))
      fail(what + " " + std::to_string(v) + " is not an integer in [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]");
    return static_cast<long long>(v);
  }

  std::size_t line_number() const { return m_line_number; }

  [[noreturn]] void fail(const std::string& what) const
  {
    if(m_format == Ply_format::ASCII)
      throw Parse_error("'" + m_name + "' line " + std::to_string(m_line_number) + ": " + what, m_line_number);
    throw Invalid_input_error("'" + m_name + "' (binary PLY): " + what);
  }

private:
  std::istream& m_in;
  Ply_format m_format;
  std::string m_name;
  std::size_t m_line_number;
  std::string m_line;
  std::vector<std::string> m_tokens;
  std::size_t m_next = 0;
};

// The PLY header of `in`: its format and elements; `line_number` is the
// number of lines read.
inline std::vector<Ply_element> read_fields_PLY_header(std::istream& in, const std::string& name,
                                                       std::size_t& line_number, Ply_format& format)
{
  std::string line;
  line_number = 0;
  auto header_error = [&](const std::string& what) {
    return Parse_error("'" + name + "' line " + std::to_string(line_number) + ": " + what, line_number);
  };
  auto next_header_line = [&](std::vector<std::string>& words) {
    if(!std::getline(in, line))
      throw header_error("the file ends inside the PLY header");
    ++line_number;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    words.clear();
    std::istringstream split(line);
    std::string w;
    while(split >> w)
      words.push_back(w);
  };
  auto excerpt = [](const std::string& text) { return CGAL::Boolean_isosurfacing::internal::input_excerpt(text); };
  std::vector<std::string> words;
  next_header_line(words);
  if(words.size() != 1 || words[0] != "ply")
    throw header_error("not a PLY file (the first line is not 'ply')");
  format = Ply_format::ASCII;
  bool have_format = false;
  std::vector<Ply_element> elements;
  for(;;)
  {
    next_header_line(words);
    if(words.empty() || words[0] == "comment" || words[0] == "obj_info")
      continue;
    if(words[0] == "end_header")
      break;
    if(words[0] == "format")
    {
      if(have_format)
        throw header_error("a second 'format' line");
      if(words.size() != 3)
        throw header_error("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if(words[2] != "1.0")
        throw header_error("unsupported PLY version '" + excerpt(words[2]) + "' (only 1.0 is read)");
      if(words[1] == "ascii")
        format = Ply_format::ASCII;
      else if(words[1] == "binary_little_endian")
        format = Ply_format::BINARY_LITTLE_ENDIAN;
      else if(words[1] == "binary_big_endian")
        format = Ply_format::BINARY_BIG_ENDIAN;
      else
        throw header_error("unknown PLY format '" + excerpt(words[1]) + "'");
      have_format = true;
    }
    else if(words[0] == "element")
    {
      Ply_element e;
      unsigned long long count = 0;
      const char* last = words.size() == 3 ? words[2].data() + words[2].size() : nullptr;
      if(words.size() != 3)
        throw header_error("expected 'element <name> <count>'");
      const std::from_chars_result r = std::from_chars(words[2].data(), last, count);
      if(r.ec == std::errc::result_out_of_range || count > (std::numeric_limits<std::size_t>::max)())
        throw header_error("the count of element '" + excerpt(words[1]) + "' is out of range: " + excerpt(words[2]));
      if(r.ec != std::errc() || r.ptr != last)
        throw header_error("expected 'element <name> <count>', the count '" + excerpt(words[2]) +
                           "' is not a non-negative integer");
      for(const Ply_element& other : elements)
        if(other.name == words[1])
          throw header_error("a second element '" + excerpt(words[1]) + "'");
      e.name = words[1];
      e.count = std::size_t(count);
      elements.push_back(e);
    }
    else if(words[0] == "property")
    {
      if(elements.empty())
        throw header_error("a property before any element");
      Ply_property p;
      bool ok;
      if(words.size() == 5 && words[1] == "list")
      {
        p.is_list = true;
        ok = ply_type_from_name(words[2], p.count_type) && ply_type_from_name(words[3], p.type);
        p.name = words[4];
      }
      else
      {
        ok = words.size() == 3 && ply_type_from_name(words[1], p.type);
        p.name = words.size() == 3 ? words[2] : std::string();
      }
      if(!ok)
        throw header_error("expected 'property <type> <name>' or 'property list <type> <type> <name>': '" +
                           excerpt(line) + "'");
      elements.back().properties.push_back(p);
    }
    else
      throw header_error("unknown PLY header line '" + excerpt(line) + "'");
  }
  if(!have_format)
    throw header_error("no 'format' line in the PLY header");

  return elements;
}

// The positions of the properties read: x, y, z of the vertices, the
// indices and the field of the faces.
struct Fields_PLY_roles
{
  const Ply_element* vertex = nullptr;
  const Ply_element* face = nullptr;
  std::size_t px = 0, py = 0, pz = 0, pindices = 0, pfield = 0;
};

inline Fields_PLY_roles find_fields_PLY_roles(const std::vector<Ply_element>& elements, const std::string& name)
{
  Fields_PLY_roles roles;
  const Ply_element*& vertex = roles.vertex;
  const Ply_element*& face = roles.face;
  for(const Ply_element& e : elements)
  {
    if(e.name == "vertex")
      vertex = &e;
    if(e.name == "face")
      face = &e;
  }
  if(vertex == nullptr || face == nullptr)
    throw Invalid_input_error("'" + name + "': the PLY file has no 'vertex' or no 'face' element");
  auto find = [&](const Ply_element& e, std::initializer_list<const char*> names, bool list) {
    for(std::size_t k = 0; k < e.properties.size(); ++k)
      for(const char* n : names)
        if(e.properties[k].name == n && e.properties[k].is_list == list)
          return k;
    std::string wanted = *names.begin();
    throw Invalid_input_error("'" + name + "': the PLY '" + e.name + "' element has no " +
                              (list ? "list" : "scalar") + " property '" + wanted + "'");
  };
  roles.px = find(*vertex, {"x"}, false);
  roles.py = find(*vertex, {"y"}, false);
  roles.pz = find(*vertex, {"z"}, false);
  roles.pindices = find(*face, {"vertex_indices", "vertex_index"}, true);
  roles.pfield = find(*face, {"field"}, false);

  return roles;
}

// Every record takes some bytes: at least the sizes of its scalars and list
// counts in binary, two characters (a digit and a blank) per property in
// ASCII.  So the counts of the header, which nothing bounds, are checked
// against the bytes that follow it before anything is reserved or looped
// over: a record of no byte at all (no property) is an error, since its
// count could be anything.  Returns the bytes that follow the header.
inline std::size_t check_fields_PLY_counts(std::istream& in, const std::vector<Ply_element>& elements,
                                           Ply_format format, const std::string& name)
{
  auto excerpt = [](const std::string& text) { return CGAL::Boolean_isosurfacing::internal::input_excerpt(text); };
  const std::size_t remaining = CGAL::Boolean_isosurfacing::internal::remaining_bytes(in);
  std::size_t needed = 0;
  for(const Ply_element& e : elements)
  {
    std::size_t record = 0;
    for(const Ply_property& p : e.properties)
      record += format == Ply_format::ASCII ? 2 : ply_type_size(p.is_list ? p.count_type : p.type);
    if(e.count == 0)
      continue;
    if(record == 0)
      throw Invalid_input_error("'" + name + "': the PLY element '" + excerpt(e.name) + "' has " +
                                std::to_string(e.count) + " records but no property");
    if(remaining != CGAL::Boolean_isosurfacing::internal::unknown_remaining_bytes &&
       (e.count > remaining / record || needed + e.count * record > remaining + 1)) // ASCII: last newline optional
      throw Invalid_input_error("'" + name + "': the PLY header announces " + std::to_string(e.count) + " '" +
                                excerpt(e.name) + "' records of at least " + std::to_string(record) +
                                " bytes, but only " + std::to_string(remaining) + " bytes follow the header");
    needed += e.count * record;
  }

  return remaining;
}

// The records of the body, into `soup`.
template <typename Point_3>
void read_fields_PLY_body(std::istream& in, const std::vector<Ply_element>& elements, const Fields_PLY_roles& roles,
                          Ply_format format, const std::string& name, std::size_t remaining, Ply_value_reader& reader,
                          Boolean_isosurface_soup<Point_3>& soup)
{
  const Ply_element* vertex = roles.vertex;
  const Ply_element* face = roles.face;
  const std::size_t px = roles.px, py = roles.py, pz = roles.pz, pindices = roles.pindices, pfield = roles.pfield;
  CGAL_USE(in);
  CGAL_USE(format);
  const long long max_index = (std::numeric_limits<std::int32_t>::max)();
  for(const Ply_element& e : elements)
  {
    const bool is_vertex = &e == vertex, is_face = &e == face;
    if(is_vertex)
      soup.points.reserve(CGAL::Boolean_isosurfacing::internal::reservable(e.count, 1, remaining));
    for(std::size_t r = 0; r < e.count; ++r)
    {
      reader.begin_record(e.name.c_str(), r);
      std::array<double, 3> xyz{0, 0, 0};
      std::vector<std::size_t> polygon;
      int field = 0;
      for(std::size_t k = 0; k < e.properties.size(); ++k)
      {
        const Ply_property& p = e.properties[k];
        if(p.is_list)
        {
          const long long n = reader.integer(p.count_type, 0, 1 << 20, "the list length");
          for(long long i = 0; i < n; ++i)
          {
            if(is_face && k == pindices)
              polygon.push_back(std::size_t(reader.integer(p.type, 0, max_index, "the vertex index")));
            else
              reader.value(p.type);
          }
          continue;
        }
        if(is_vertex && (k == px || k == py || k == pz))
        {
          const double c = reader.value(p.type);
          if(!std::isfinite(c))
            throw Non_finite_value_error("'" + name + "': vertex " + std::to_string(r) + " has a non-finite coordinate");
          xyz[k == px ? 0 : k == py ? 1 : 2] = c;
        }
        else if(is_face && k == pfield)
          field = int(reader.integer(p.type, Boolean_isosurface_soup<Point_3>::domain_boundary,
                                     (std::numeric_limits<std::int32_t>::max)(), "the field"));
        else
          reader.value(p.type);
      }
      reader.end_record();
      if(is_vertex)
        soup.points.emplace_back(xyz[0], xyz[1], xyz[2]);
      else if(is_face)
      {
        soup.polygons.push_back(std::move(polygon));
        soup.face_fields.push_back(field);
      }
    }
  }
}

// Nothing may follow the last element (blank lines in ASCII).
inline void check_fields_PLY_end(std::istream& in, Ply_format format, const std::string& name,
                                 const Ply_value_reader& reader)
{
  auto excerpt = [](const std::string& text) { return CGAL::Boolean_isosurfacing::internal::input_excerpt(text); };
  std::string line;
  if(format == Ply_format::ASCII)
  {
    std::size_t at = reader.line_number();
    while(std::getline(in, line))
    {
      ++at;
      if(line.find_first_not_of(" \t\r\f\v") != std::string::npos)
        throw Parse_error("'" + name + "' line " + std::to_string(at) + ": text after the last element: '" +
                            excerpt(line) + "'",
                          at);
    }
  }
  else if(in.peek() != std::char_traits<char>::eof())
  {
    std::size_t extra = 0;
    while(in.get() != std::char_traits<char>::eof() && extra < 1000000)
      ++extra;
    throw Invalid_input_error("'" + name + "': " + (extra >= 1000000 ? std::string("more than 1000000") : std::to_string(extra)) +
                              " trailing bytes after the last element of the binary PLY body");
  }
}

// Every face index names a vertex of the soup.
template <typename Point_3>
void check_fields_PLY_indices(const Boolean_isosurface_soup<Point_3>& soup, const std::string& name)
{
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    for(std::size_t v : soup.polygons[f])
      if(v >= soup.points.size())
        throw Invalid_input_error("'" + name + "': face " + std::to_string(f) + " refers to vertex " +
                                  std::to_string(v) + " but there are " + std::to_string(soup.points.size()) +
                                  " vertices");
}

} // namespace soup_files_io
} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes `soup` as PLY with a `field` and an RGB colour per face (layout at
 * the top of this header), ASCII or, with `binary`, binary little-endian.
 * For `binary`, `out` must be opened in binary mode.
 * \throws Invalid_input_error if the soup cannot be written faithfully;
 * \throws std::runtime_error if writing fails.
 */
template <typename Point_3>
void write_PLY_with_fields(std::ostream& out, const Boolean_isosurface_soup<Point_3>& soup, bool binary = false)
{
  using namespace internal::soup_files_io;
  check_soup(soup, 255);
  if(soup.points.size() > std::size_t((std::numeric_limits<std::int32_t>::max)()))
    throw Invalid_input_error("too many points for PLY int indices: " + std::to_string(soup.points.size()));
  Exact_number_format format(out);
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment Boolean_isosurfacing_3: field = index of the scalar field the face lies on, "
         "-1 = domain boundary\n"
      << "element vertex " << soup.points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << soup.polygons.size() << "\n"
      << "property list uchar int vertex_indices\nproperty int field\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  if(binary)
  {
    std::string buffer;
    auto flush_if_large = [&]() {
      if(buffer.size() > (std::size_t(1) << 20))
      {
        out.write(buffer.data(), std::streamsize(buffer.size()));
        buffer.clear();
      }
    };
    for(const Point_3& p : soup.points)
    {
      for(double c : coordinates(p))
        put_little_endian(buffer, c);
      flush_if_large();
    }
    for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    {
      put_little_endian(buffer, static_cast<std::uint8_t>(soup.polygons[f].size()));
      for(std::size_t v : soup.polygons[f])
        put_little_endian(buffer, static_cast<std::int32_t>(v));
      put_little_endian(buffer, static_cast<std::int32_t>(soup.face_fields[f]));
      for(unsigned char c : field_color(soup.face_fields[f]))
        put_little_endian(buffer, static_cast<std::uint8_t>(c));
      flush_if_large();
    }
    out.write(buffer.data(), std::streamsize(buffer.size()));
  }
  else
  {
    for(const Point_3& p : soup.points)
    {
      const std::array<double, 3> c = coordinates(p);
      out << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
    }
    for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    {
      out << soup.polygons[f].size();
      for(std::size_t v : soup.polygons[f])
        out << ' ' << v;
      const std::array<unsigned char, 3> c = field_color(soup.face_fields[f]);
      out << ' ' << soup.face_fields[f] << ' ' << int(c[0]) << ' ' << int(c[1]) << ' ' << int(c[2]) << '\n';
    }
  }
  check_written(out, "PLY file");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes `soup` to the PLY file `filename` (see the stream overload).
template <typename Point_3>
void write_PLY_with_fields(const std::string& filename, const Boolean_isosurface_soup<Point_3>& soup,
                           bool binary = false)
{
  internal::soup_files_io::check_soup(soup, 255); // before creating the file
  internal::soup_files_io::write_to_file(filename, true,
                                         [&](std::ostream& out) { write_PLY_with_fields(out, soup, binary); });
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a PLY stream with a face `field` property (see the top of this
 * header) into `soup` (cleared first); `name` is used in error messages.
 * Colours and other properties are ignored.  For a binary file, `in` must be
 * opened in binary mode.
 *
 * \tparam Point_3 constructible from three doubles
 * \throws Parse_error (position() = 1-based line) on a malformed header or ASCII body;
 * \throws Non_finite_value_error on a NaN or infinite coordinate;
 * \throws Invalid_input_error on a missing element or property, an index out of range,
 *         a field label below -1, or a truncated binary body.
 */
template <typename Point_3>
void read_PLY_with_fields(std::istream& in, Boolean_isosurface_soup<Point_3>& soup,
                          const std::string& name = "<stream>")
{
  using namespace internal::soup_files_io;
  soup.clear();
  std::size_t line_number = 0;
  Ply_format format = Ply_format::ASCII;
  const std::vector<Ply_element> elements = read_fields_PLY_header(in, name, line_number, format);
  const Fields_PLY_roles roles = find_fields_PLY_roles(elements, name);
  const std::size_t remaining = check_fields_PLY_counts(in, elements, format, name);
  Ply_value_reader reader(in, format, name, line_number);
  read_fields_PLY_body(in, elements, roles, format, name, remaining, reader, soup);
  check_fields_PLY_end(in, format, name, reader);
  check_fields_PLY_indices(soup, name);
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// reads the PLY file `filename` (see the stream overload).
/// \throws Invalid_input_error if it cannot be opened, else as the stream overload.
template <typename Point_3>
void read_PLY_with_fields(const std::string& filename, Boolean_isosurface_soup<Point_3>& soup)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(filename, ec))
    throw Invalid_input_error("cannot open '" + filename + "': no such regular file");
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Invalid_input_error("cannot open '" + filename + "'");
  read_PLY_with_fields(in, soup, filename);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes the polylines of `creases` in CGAL's polylines text format: one line
 * per polyline, `n x1 y1 z1 ... xn yn zn`, with `max_digits10` digits.
 * \throws Invalid_input_error on an index out of range of `points`;
 * \throws std::runtime_error if writing fails.
 */
template <typename Point_3>
void write_polylines(std::ostream& out, const std::vector<Point_3>& points, const Crease_network& creases)
{
  using namespace internal::soup_files_io;
  for(std::size_t l = 0; l < creases.polylines.size(); ++l)
    for(std::size_t v : creases.polylines[l])
      check_point_index(v, points.size(), "polyline", l);
  Exact_number_format format(out);
  for(const std::vector<std::size_t>& polyline : creases.polylines)
  {
    out << polyline.size();
    for(std::size_t v : polyline)
    {
      const std::array<double, 3> c = coordinates(points[v]);
      out << ' ' << c[0] << ' ' << c[1] << ' ' << c[2];
    }
    out << '\n';
  }
  check_written(out, "polylines");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes the polylines of `creases` to the file `filename` (see the stream overload).
template <typename Point_3>
void write_polylines(const std::string& filename, const std::vector<Point_3>& points, const Crease_network& creases)
{
  internal::soup_files_io::write_to_file(filename, false,
                                         [&](std::ostream& out) { write_polylines(out, points, creases); });
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes the corners of `creases`, one line `x y z` per corner, with `max_digits10` digits.
 * \throws Invalid_input_error on an index out of range of `points`;
 * \throws std::runtime_error if writing fails.
 */
template <typename Point_3>
void write_corners(std::ostream& out, const std::vector<Point_3>& points, const Crease_network& creases)
{
  using namespace internal::soup_files_io;
  for(std::size_t c = 0; c < creases.corners.size(); ++c)
    check_point_index(creases.corners[c], points.size(), "corner", c);
  Exact_number_format format(out);
  for(std::size_t v : creases.corners)
  {
    const std::array<double, 3> c = coordinates(points[v]);
    out << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  }
  check_written(out, "corners");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes the corners of `creases` to the file `filename` (see the stream overload).
template <typename Point_3>
void write_corners(const std::string& filename, const std::vector<Point_3>& points, const Crease_network& creases)
{
  internal::soup_files_io::write_to_file(filename, false,
                                         [&](std::ostream& out) { write_corners(out, points, creases); });
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes the polygons of `soup` as a plain OFF file (no field labels):
 * `OFF`, `V F 0`, the points with `max_digits10` digits, one line
 * `k i1 ... ik` per polygon.
 * \throws Invalid_input_error on an index out of range or a polygon of fewer than 3 vertices;
 * \throws std::runtime_error if writing fails.
 */
template <typename Point_3>
void write_OFF_polygons(std::ostream& out, const Boolean_isosurface_soup<Point_3>& soup)
{
  using namespace internal::soup_files_io;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    if(soup.polygons[f].size() < 3)
      throw Invalid_input_error("polygon " + std::to_string(f) + " has " + std::to_string(soup.polygons[f].size()) +
                                " vertices (at least 3 are needed)");
    for(std::size_t v : soup.polygons[f])
      check_point_index(v, soup.points.size(), "polygon", f);
  }
  Exact_number_format format(out);
  out << "OFF\n" << soup.points.size() << ' ' << soup.polygons.size() << " 0\n";
  for(const Point_3& p : soup.points)
  {
    const std::array<double, 3> c = coordinates(p);
    out << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  }
  for(const std::vector<std::size_t>& polygon : soup.polygons)
  {
    out << polygon.size();
    for(std::size_t v : polygon)
      out << ' ' << v;
    out << '\n';
  }
  check_written(out, "OFF file");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes the polygons of `soup` to the OFF file `filename` (see the stream overload).
template <typename Point_3>
void write_OFF_polygons(const std::string& filename, const Boolean_isosurface_soup<Point_3>& soup)
{
  internal::soup_files_io::write_to_file(filename, false,
                                         [&](std::ostream& out) { write_OFF_polygons(out, soup); });
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_BOOLEAN_ISOSURFACE_FILES_H
