// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_PLY_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_PLY_H

// PLY, ASCII and binary (little and big endian).  Any element order and any
// other elements and properties (skipped); `vertex` needs scalar x, y, z of
// any numeric type (char ... double and the int8 ... float64 aliases), and
// `face` a list `vertex_indices` (or `vertex_index`) with integer count and
// index types.
//
// Hostile headers: every element count is checked against the bytes that
// its instances need at least before anything is allocated, an element
// without properties (0 bytes an instance) is skipped without a loop, and
// every list length is checked against what is left of the file.

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Input_buffer.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Soup_builder.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

enum class Ply_type : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline std::size_t size_of(Ply_type t)
{
  static const std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[int(t)];
}

inline bool is_integral_ply_type(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }

inline bool parse_ply_type(const std::string& s, Ply_type& t)
{
  static const struct { const char* name; Ply_type type; } names[] = {
      {"char", Ply_type::int8},      {"int8", Ply_type::int8},      {"uchar", Ply_type::uint8},
      {"uint8", Ply_type::uint8},    {"short", Ply_type::int16},    {"int16", Ply_type::int16},
      {"ushort", Ply_type::uint16},  {"uint16", Ply_type::uint16},  {"int", Ply_type::int32},
      {"int32", Ply_type::int32},    {"uint", Ply_type::uint32},    {"uint32", Ply_type::uint32},
      {"float", Ply_type::float32},  {"float32", Ply_type::float32}, {"double", Ply_type::float64},
      {"float64", Ply_type::float64}};
  for(const auto& n : names)
    if(s == n.name)
    {
      t = n.type;
      return true;
    }
  return false;
}

struct Ply_property
{
  std::string name;
  bool is_list = false;
  Ply_type count_type = Ply_type::uint8;
  Ply_type type = Ply_type::float32;
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
  std::size_t line = 0;

  bool has_lists() const
  {
    return std::any_of(properties.begin(), properties.end(), [](const Ply_property& p) { return p.is_list; });
  }
  std::size_t fixed_size() const
  {
    std::size_t s = 0;
    for(const Ply_property& p : properties) s += size_of(p.type);
    return s;
  }
  int find(const char* property) const
  {
    for(std::size_t k = 0; k < properties.size(); ++k)
      if(properties[k].name == property)
        return int(k);
    return -1;
  }
};

enum class Ply_format { ascii, binary_little_endian, binary_big_endian };

struct Ply_header
{
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements;
  const char* data = nullptr; // the first byte after end_header's newline
};

inline Ply_header read_PLY_header(const char* begin, const char* end)
{
  Text_cursor in(begin, end);
  Ply_header header;
  bool has_format = false;
  std::size_t line_number = 0;
  std::vector<std::string> words;
  for(;;)
  {
    if(in.at_end())
      in.fail("the PLY header has no 'end_header' line");
    const char* line = in.p;
    const void* nl = std::memchr(line, '\n', std::size_t(end - line));
    const char* line_end = nl ? static_cast<const char*>(nl) : end;
    in.p = nl ? line_end + 1 : end;
    ++line_number;
    words.clear();
    for(const char* q = line; q < line_end;)
    {
      while(q < line_end && is_text_blank(*q)) ++q;
      const char* w = q;
      while(q < line_end && !is_text_blank(*q)) ++q;
      if(q > w) words.emplace_back(w, q);
    }
    const auto fail = [&](const std::string& message) {
      throw Parse_error("line " + std::to_string(line_number) + ": " + message, line_number);
    };
    if(line_number == 1)
    {
      if(words.size() != 1 || words[0] != "ply")
        fail("cannot parse it as PLY: the first line is not 'ply'");
      continue;
    }
    if(words.empty())
      continue;
    const std::string& key = words[0];
    if(key == "comment" || key == "obj_info")
      continue;
    if(key == "format")
    {
      if(words.size() != 3 || words[2] != "1.0")
        fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0', found '" +
             printable_excerpt(line, line_end, 60) + "'");
      if(words[1] == "ascii") header.format = Ply_format::ascii;
      else if(words[1] == "binary_little_endian") header.format = Ply_format::binary_little_endian;
      else if(words[1] == "binary_big_endian") header.format = Ply_format::binary_big_endian;
      else fail("unknown PLY format '" + printable_excerpt(words[1].data(), words[1].data() + words[1].size()) + "'");
      has_format = true;
    }
    else if(key == "element")
    {
      Ply_element e;
      Text_cursor count(words.size() == 3 ? words[2].data() : "", words.size() == 3 ? words[2].data() + words[2].size() : "");
      if(words.size() != 3 || !count.parse_unsigned(e.count) || !count.at_end())
        fail("expected 'element NAME COUNT' with a whole-number count below 2^59, found '" +
             printable_excerpt(line, line_end, 60) + "'");
      e.name = words[1];
      e.line = line_number;
      header.elements.push_back(std::move(e));
    }
    else if(key == "property")
    {
      if(header.elements.empty())
        fail("'property' before any 'element'");
      Ply_property p;
      bool ok;
      if(words.size() == 5 && words[1] == "list")
      {
        p.is_list = true;
        ok = parse_ply_type(words[2], p.count_type) && parse_ply_type(words[3], p.type) && is_integral_ply_type(p.count_type);
        p.name = words[4];
      }
      else
      {
        ok = words.size() == 3 && parse_ply_type(words[1], p.type);
        p.name = words.size() == 3 ? words[2] : std::string();
      }
      if(!ok)
        fail("expected 'property TYPE NAME' or 'property list INTEGER_TYPE TYPE NAME' with a PLY type, found '" +
             printable_excerpt(line, line_end, 60) + "'");
      header.elements.back().properties.push_back(p);
    }
    else if(key == "end_header")
    {
      if(!has_format)
        fail("the PLY header has no 'format' line");
      header.data = in.p;
      return header;
    }
    else
      fail("unknown PLY header line '" + printable_excerpt(line, line_end, 60) + "'");
  }
}

// A value of type `t` at `p` (in the file's byte order) as double / as a
// signed 64-bit integer.  The switch is on a type that is the same for every
// instance, so the branch predictor makes it nearly free.
template <bool Swap, typename T>
T load(const char* p)
{
  T v;
  std::memcpy(&v, p, sizeof(T));
  if constexpr(Swap && sizeof(T) > 1)
  {
    unsigned char* b = reinterpret_cast<unsigned char*>(&v);
    std::reverse(b, b + sizeof(T));
  }
  return v;
}

template <bool Swap>
double load_double(const char* p, Ply_type t)
{
  switch(t)
  {
  case Ply_type::int8: return load<Swap, std::int8_t>(p);
  case Ply_type::uint8: return load<Swap, std::uint8_t>(p);
  case Ply_type::int16: return load<Swap, std::int16_t>(p);
  case Ply_type::uint16: return load<Swap, std::uint16_t>(p);
  case Ply_type::int32: return load<Swap, std::int32_t>(p);
  case Ply_type::uint32: return load<Swap, std::uint32_t>(p);
  case Ply_type::float32: return load<Swap, float>(p);
  default: return load<Swap, double>(p);
  }
}

template <bool Swap>
std::int64_t load_integer(const char* p, Ply_type t)
{
  switch(t)
  {
  case Ply_type::int8: return load<Swap, std::int8_t>(p);
  case Ply_type::uint8: return load<Swap, std::uint8_t>(p);
  case Ply_type::int16: return load<Swap, std::int16_t>(p);
  case Ply_type::uint16: return load<Swap, std::uint16_t>(p);
  case Ply_type::int32: return load<Swap, std::int32_t>(p);
  default: return load<Swap, std::uint32_t>(p);
  }
}

struct Ply_reader_context
{
  const char* begin;
  const char* end;
  std::uint64_t vertex_count;

  [[noreturn]] void fail_at_byte(const char* at, const std::string& message) const
  {
    throw Invalid_input_error("byte " + std::to_string(std::size_t(at - begin)) + ": " + message);
  }
};

// The vertex and face elements' indices in the header.
struct Ply_roles
{
  int vertex = -1, face = -1;
  int x = -1, y = -1, z = -1, indices = -1;
};

template <bool Swap>
const char* read_binary_PLY_element(const Ply_reader_context& cx, const Ply_element& e, const Ply_roles& roles,
                                    bool is_vertex, bool is_face, const char* p, Triangle_soup_3& soup)
{
  const char* const end = cx.end;
  const std::size_t n_props = e.properties.size();
  if(!e.has_lists())
  {
    const std::size_t size = e.fixed_size();
    if(!count_fits(e.count, size, std::uint64_t(end - p)))
      cx.fail_at_byte(p, "the file ends inside element '" + e.name + "' (truncated file)");
    if(!is_vertex)
      return p + e.count * size; // also for size 0: no loop over a huge count
    // Offsets and types of x, y, z within a vertex.
    std::size_t offset[3] = {0, 0, 0};
    Ply_type type[3];
    const int which[3] = {roles.x, roles.y, roles.z};
    for(int k = 0; k < 3; ++k)
    {
      for(int j = 0; j < which[k]; ++j) offset[k] += size_of(e.properties[std::size_t(j)].type);
      type[k] = e.properties[std::size_t(which[k])].type;
    }
    for(std::uint64_t i = 0; i < e.count; ++i, p += size)
    {
      const double x = load_double<Swap>(p + offset[0], type[0]);
      const double y = load_double<Swap>(p + offset[1], type[1]);
      const double z = load_double<Swap>(p + offset[2], type[2]);
      if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
        cx.fail_at_byte(p, "vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                               describe_non_finite(x, y, z) + ")");
      soup.points.push_back({x, y, z});
    }
    return p;
  }
  std::vector<std::uint32_t> polygon;
  double xyz[3] = {0, 0, 0};
  for(std::uint64_t i = 0; i < e.count; ++i)
  {
    const char* instance = p;
    for(std::size_t k = 0; k < n_props; ++k)
    {
      const Ply_property& prop = e.properties[k];
      const std::size_t item = size_of(prop.type);
      if(!prop.is_list)
      {
        if(std::size_t(end - p) < item)
          cx.fail_at_byte(p, "the file ends inside " + e.name + " " + std::to_string(i) + " (truncated file)");
        if(is_vertex && (int(k) == roles.x || int(k) == roles.y || int(k) == roles.z))
          xyz[int(k) == roles.x ? 0 : int(k) == roles.y ? 1 : 2] = load_double<Swap>(p, prop.type);
        p += item;
        continue;
      }
      const std::size_t count_size = size_of(prop.count_type);
      if(std::size_t(end - p) < count_size)
        cx.fail_at_byte(p, "the file ends inside " + e.name + " " + std::to_string(i) + " (truncated file)");
      const std::int64_t count = load_integer<Swap>(p, prop.count_type);
      p += count_size;
      if(count < 0 || !count_fits(std::uint64_t(count), item, std::uint64_t(end - p)))
        cx.fail_at_byte(p - count_size, e.name + " " + std::to_string(i) + ": list '" + prop.name +
                                            "' claims " + std::to_string(count) +
                                            " items, more than the rest of the file holds");
      if(is_face && int(k) == roles.indices)
      {
        if(count < 3)
          cx.fail_at_byte(instance, "face " + std::to_string(i) + " has " + std::to_string(count) +
                                        " vertices; a face needs at least 3");
        polygon.clear();
        for(std::int64_t j = 0; j < count; ++j, p += item)
        {
          const std::int64_t v = load_integer<Swap>(p, prop.type);
          if(v < 0 || std::uint64_t(v) >= cx.vertex_count)
            cx.fail_at_byte(instance, "face " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                                          ", but there are " + std::to_string(cx.vertex_count) + " vertices");
          polygon.push_back(std::uint32_t(v));
        }
        add_fan_of_triangles(soup, polygon.data(), polygon.size());
      }
      else
        p += std::size_t(count) * item;
    }
    if(is_vertex)
    {
      if(!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        cx.fail_at_byte(instance, "vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                                      describe_non_finite(xyz[0], xyz[1], xyz[2]) + ")");
      soup.points.push_back({xyz[0], xyz[1], xyz[2]});
    }
  }
  return p;
}

// Faces in the common layout (one list property, count and index types
// fixed): one tight loop.
template <bool Swap, typename Count, typename Index>
const char* read_binary_PLY_faces(const Ply_reader_context& cx, const Ply_element& e, const char* p,
                                  Triangle_soup_3& soup)
{
  const char* const end = cx.end;
  std::vector<std::uint32_t> polygon;
  const std::uint64_t nv = cx.vertex_count;
  for(std::uint64_t i = 0; i < e.count; ++i)
  {
    if(std::size_t(end - p) < sizeof(Count) + 3 * sizeof(Index))
      cx.fail_at_byte(p, "the file ends inside face " + std::to_string(i) + " (truncated file)");
    const std::int64_t count = std::int64_t(load<Swap, Count>(p));
    const char* instance = p;
    p += sizeof(Count);
    if(count == 3)
    {
      const std::int64_t a = std::int64_t(load<Swap, Index>(p)), b = std::int64_t(load<Swap, Index>(p + sizeof(Index))),
                         c = std::int64_t(load<Swap, Index>(p + 2 * sizeof(Index)));
      if(std::uint64_t(a) < nv && std::uint64_t(b) < nv && std::uint64_t(c) < nv) // negative ones wrap high
      {
        soup.triangles.push_back({std::uint32_t(a), std::uint32_t(b), std::uint32_t(c)});
        p += 3 * sizeof(Index);
        continue;
      }
    }
    if(count < 3)
      cx.fail_at_byte(instance, "face " + std::to_string(i) + " has " + std::to_string(count) +
                                    " vertices; a face needs at least 3");
    if(!count_fits(std::uint64_t(count), sizeof(Index), std::uint64_t(end - p)))
      cx.fail_at_byte(instance, "face " + std::to_string(i) + " claims " + std::to_string(count) +
                                    " vertices, more than the rest of the file holds");
    polygon.clear();
    for(std::int64_t j = 0; j < count; ++j, p += sizeof(Index))
    {
      const std::int64_t v = std::int64_t(load<Swap, Index>(p));
      if(v < 0 || std::uint64_t(v) >= nv)
        cx.fail_at_byte(instance, "face " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                                      ", but there are " + std::to_string(nv) + " vertices");
      polygon.push_back(std::uint32_t(v));
    }
    add_fan_of_triangles(soup, polygon.data(), polygon.size());
  }
  return p;
}

template <bool Swap>
const char* read_binary_PLY_face_element(const Ply_reader_context& cx, const Ply_element& e, const Ply_roles& roles,
                                         const char* p, Triangle_soup_3& soup)
{
  if(e.properties.size() == 1)
  {
    const Ply_type c = e.properties[0].count_type, i = e.properties[0].type;
    if(c == Ply_type::uint8 && i == Ply_type::int32)
      return read_binary_PLY_faces<Swap, std::uint8_t, std::int32_t>(cx, e, p, soup);
    if(c == Ply_type::uint8 && i == Ply_type::uint32)
      return read_binary_PLY_faces<Swap, std::uint8_t, std::uint32_t>(cx, e, p, soup);
    if(c == Ply_type::int32 && i == Ply_type::int32)
      return read_binary_PLY_faces<Swap, std::int32_t, std::int32_t>(cx, e, p, soup);
  }
  return read_binary_PLY_element<Swap>(cx, e, roles, false, true, p, soup);
}

inline const char* read_ASCII_PLY_element(const Ply_reader_context& cx, const Ply_element& e,
                                          const Ply_roles& roles, bool is_vertex, bool is_face, Text_cursor& in,
                                          Triangle_soup_3& soup)
{
  if(e.properties.empty())
    return in.p; // nothing to read, whatever the count
  std::vector<std::uint32_t> polygon;
  double xyz[3] = {0, 0, 0};
  const auto where = [&](std::uint64_t i) { return e.name + " " + std::to_string(i); };
  for(std::uint64_t i = 0; i < e.count; ++i)
  {
    in.skip_spaces();
    const char* instance = in.p;
    for(std::size_t k = 0; k < e.properties.size(); ++k)
    {
      const Ply_property& prop = e.properties[k];
      in.skip_spaces();
      if(in.at_end())
        in.fail("the file ends at " + where(i) + " of the " + std::to_string(e.count) + " the header declares "
                "(truncated file)");
      if(!prop.is_list)
      {
        double v;
        if(!in.parse_double(v))
          in.fail(where(i) + ": cannot parse property '" + prop.name + "': expected a number, found " + in.found());
        if(is_vertex && (int(k) == roles.x || int(k) == roles.y || int(k) == roles.z))
          xyz[int(k) == roles.x ? 0 : int(k) == roles.y ? 1 : 2] = v;
        continue;
      }
      std::uint64_t count;
      if(!in.parse_unsigned(count))
        in.fail(where(i) + ": cannot parse the length of list '" + prop.name + "': expected a whole number, found " +
                in.found());
      if(!count_fits(count, 2, std::uint64_t(in.end - in.p) + 1))
        in.fail(where(i) + ": list '" + prop.name + "' claims " + std::to_string(count) +
                " items, more than the rest of the file holds");
      const bool indices = is_face && int(k) == roles.indices;
      if(indices && count < 3)
        in.fail("face " + std::to_string(i) + " has " + std::to_string(count) + " vertices; a face needs at least 3");
      polygon.clear();
      for(std::uint64_t j = 0; j < count; ++j)
      {
        in.skip_spaces();
        if(indices)
        {
          std::uint64_t v;
          if(!in.parse_unsigned(v))
            in.fail("face " + std::to_string(i) + ": cannot parse index " + std::to_string(j + 1) +
                    ": expected a whole number, found " + in.found());
          if(v >= cx.vertex_count)
            in.fail("face " + std::to_string(i) + " refers to vertex " + std::to_string(v) + ", but there are " +
                    std::to_string(cx.vertex_count) + " vertices");
          polygon.push_back(std::uint32_t(v));
        }
        else
        {
          double ignored;
          if(!in.parse_double(ignored))
            in.fail(where(i) + ": cannot parse an item of list '" + prop.name + "': expected a number, found " +
                    in.found());
        }
      }
      if(indices)
        add_fan_of_triangles(soup, polygon.data(), polygon.size());
    }
    if(is_vertex)
    {
      if(!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        in.fail_at(instance, "vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                                 describe_non_finite(xyz[0], xyz[1], xyz[2]) + ")");
      soup.points.push_back({xyz[0], xyz[1], xyz[2]});
    }
  }
  return in.p;
}

// The least number of bytes an instance of `e` takes in the file: what its
// count is checked against.
inline std::uint64_t min_instance_bytes(const Ply_element& e, bool ascii, int face_list)
{
  std::uint64_t s = 0;
  for(std::size_t k = 0; k < e.properties.size(); ++k)
  {
    const Ply_property& p = e.properties[k];
    const std::uint64_t indices = int(k) == face_list ? 3 : 0;
    if(ascii)
      s += 2 + 2 * indices;
    else
      s += p.is_list ? size_of(p.count_type) + indices * size_of(p.type) : size_of(p.type);
  }
  return ascii && s > 0 ? s - 1 : s; // the last separator may be missing
}

inline void read_PLY(const char* begin, const char* end, Triangle_soup_3& soup)
{
  const Ply_header header = read_PLY_header(begin, end);
  Ply_roles roles;
  for(std::size_t k = 0; k < header.elements.size(); ++k)
  {
    const Ply_element& e = header.elements[k];
    if(e.name == "vertex" && roles.vertex < 0) roles.vertex = int(k);
    if(e.name == "face" && roles.face < 0) roles.face = int(k);
  }
  if(roles.vertex < 0)
    throw Invalid_input_error("the PLY header has no 'vertex' element");
  if(roles.face < 0)
    throw Invalid_input_error("the PLY header has no 'face' element");
  const Ply_element& vertex = header.elements[std::size_t(roles.vertex)];
  const Ply_element& face = header.elements[std::size_t(roles.face)];
  int* const xyz[3] = {&roles.x, &roles.y, &roles.z};
  const char* const names[3] = {"x", "y", "z"};
  for(int k = 0; k < 3; ++k)
  {
    *xyz[k] = vertex.find(names[k]);
    if(*xyz[k] < 0 || vertex.properties[std::size_t(*xyz[k])].is_list)
      throw Parse_error("line " + std::to_string(vertex.line) + ": element 'vertex' has no scalar property '" +
                            names[k] + "'",
                        vertex.line);
  }
  roles.indices = face.find("vertex_indices");
  if(roles.indices < 0)
    roles.indices = face.find("vertex_index");
  if(roles.indices < 0 || !face.properties[std::size_t(roles.indices)].is_list ||
     !is_integral_ply_type(face.properties[std::size_t(roles.indices)].type))
    throw Parse_error("line " + std::to_string(face.line) +
                          ": element 'face' has no list property 'vertex_indices' of an integer type",
                      face.line);

  const bool ascii = header.format == Ply_format::ascii;
  const std::uint64_t available = std::uint64_t(end - header.data) + (ascii ? 1 : 0);
  std::uint64_t needed = 0;
  for(std::size_t k = 0; k < header.elements.size(); ++k)
  {
    const Ply_element& e = header.elements[k];
    const std::uint64_t each = min_instance_bytes(e, ascii, int(k) == roles.face ? roles.indices : -1);
    if(!count_fits(e.count, each, available - needed))
      throw Parse_error("line " + std::to_string(e.line) + ": " +
                            count_error("'" + e.name + "' elements", e.count, each, available - needed),
                        e.line);
    needed += e.count * each;
  }
  check_point_count(vertex.count);
  soup.points.clear();
  soup.triangles.clear();
  reserve_in_huge_pages(soup.points, std::size_t(vertex.count));
  reserve_in_huge_pages(soup.triangles, std::size_t(face.count));

  const Ply_reader_context cx{begin, end, vertex.count};
  const char* p = header.data;
  Text_cursor in(begin, end);
  in.p = p;
  const bool swap = (header.format == Ply_format::binary_big_endian) == host_is_little_endian();
  for(std::size_t k = 0; k < header.elements.size(); ++k)
  {
    const Ply_element& e = header.elements[k];
    const bool is_vertex = int(k) == roles.vertex, is_face = int(k) == roles.face;
    if(ascii)
      p = read_ASCII_PLY_element(cx, e, roles, is_vertex, is_face, in, soup);
    else if(is_face)
      p = swap ? read_binary_PLY_face_element<true>(cx, e, roles, p, soup)
               : read_binary_PLY_face_element<false>(cx, e, roles, p, soup);
    else
      p = swap ? read_binary_PLY_element<true>(cx, e, roles, is_vertex, false, p, soup)
               : read_binary_PLY_element<false>(cx, e, roles, is_vertex, false, p, soup);
  }
  while(p < end && is_text_space(*p)) ++p;
  if(p != end)
  {
    if(ascii)
    {
      in.p = p;
      in.fail("unexpected content after the last element: " + in.found());
    }
    cx.fail_at_byte(p, std::to_string(std::size_t(end - p)) +
                           " bytes after the last element (wrong counts or types in the header?)");
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_PLY_H
