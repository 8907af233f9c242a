// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_TETRAHEDRAL_MESH_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_TETRAHEDRAL_MESH_H

// Readers of tetrahedral meshes into `Tetrahedral_mesh_3`, and a Medit writer.
//
// Medit `.mesh` (ASCII only).  The file is read line by line; a '#' starts a
// comment that runs to the end of the line; blank lines are ignored; keywords
// are case-insensitive.  Accepted:
//
//   MeshVersionFormatted v       (v in 1..4; the value may be on the next line)
//   Dimension 3                  (3 only; the value may be on the next line)
//   Vertices                     (the count may be on the keyword's line)
//   n
//   x y z ref                    (n lines, exactly 4 numbers each)
//   Tetrahedra
//   m
//   a b c d ref                  (m lines, exactly 5 integers, indices 1-based)
//   <Keyword> k                  (any other block, e.g. Triangles, Edges,
//   ...                           Corners, Ridges, RequiredVertices: its count
//                                 k then k lines, skipped)
//   End                          (optional; anything after it is ignored)
//
// Exactly one Vertices and one Tetrahedra block are required.  Every record is
// one line: a record split over several lines, or two records on one line,
// is an error.
//
// TetGen `.node` / `.ele` (ASCII).  '#' comments and blank lines as above.
//
//   .node:  n [dim [nattr [nbm]]]       header (defaults 3, 0, 0; dim must be 3, nbm 0 or 1)
//           i x y z [nattr attributes] [marker if nbm = 1]   (n lines)
//   .ele:   m [npt [nattr]]             header (defaults 4, 0; npt 4 or 10)
//           j a b c d [6 more nodes if npt = 10] [nattr attributes]   (m lines)
//
// The first vertex number of the `.node` file (0 or 1) is the base of the
// numbering; vertex numbers must then be consecutive, and the corners in the
// `.ele` file use the same base.  Element numbers are consecutive from 0 or 1.
// For 10-node (quadratic) tetrahedra only the first four nodes, the corners,
// are used.  Attributes and markers are ignored.
//
// Numbers are parsed with std::from_chars: independent of the locale.
//
// Errors: a file that cannot be opened is an Invalid_input_error naming it;
// a problem in a file is a Parse_error (position() = the 1-based line number)
// or a Non_finite_value_error, whose one-line message starts with
// `'<file>' line <n>:`.  The Tetrahedral_mesh_3 constructor then validates
// the mesh (degenerate or non-conforming tetrahedra, ...) and throws its own
// Invalid_input_error, which is not caught.

#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_mesh_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Byte_order.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Input_excerpt.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
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
namespace internal {
namespace tet_mesh_io {

// Meaningful lines of a text file: comments ('#' to the end of the line) and
// blank lines skipped, the rest split into blank-separated tokens.
class Line_reader
{
public:
  Line_reader(std::istream& in, const std::string& name) : m_in(in), m_name(name) {}

  // The next meaningful line; false at the end of the input.
  bool next()
  {
    while(std::getline(m_in, m_line))
    {
      ++m_line_number;
      split();
      if(!m_tokens.empty())
        return true;
    }
    if(m_in.bad())
      throw Invalid_input_error("'" + m_name + "': read error after line " + std::to_string(m_line_number));
    m_tokens.clear();
    return false;
  }

  std::size_t size() const { return m_tokens.size(); }
  std::string_view operator[](std::size_t i) const { return m_tokens[i]; }
  std::size_t line_number() const { return m_line_number; }
  const std::string& name() const { return m_name; }

  // Bytes left after the current line (unknown_remaining_bytes if the stream cannot seek).
  std::size_t remaining_bytes() const { return CGAL::Boolean_isosurfacing::internal::remaining_bytes(m_in); }

  // A header announcing `count` records of at least `min_bytes` bytes each
  // (one line each) must fit in what is left of the file: checked before
  // anything is reserved, so that a wrong count is an error naming it, not
  // gigabytes of memory.  Returns how many records may be reserved.
  std::size_t check_count(std::size_t count, std::size_t min_bytes, const std::string& what) const
  {
    const std::size_t remaining = remaining_bytes();
    if(remaining != CGAL::Boolean_isosurfacing::internal::unknown_remaining_bytes && count != 0 &&
       count - 1 > remaining / min_bytes) // the last line may lack its newline
      fail("the header announces " + std::to_string(count) + " " + what + " of at least " +
           std::to_string(min_bytes) + " bytes each, but only " + std::to_string(remaining) + " bytes follow");
    return CGAL::Boolean_isosurfacing::internal::reservable(count, min_bytes, remaining);
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Parse_error("'" + m_name + "' line " + std::to_string(m_line_number) + ": " + what, m_line_number);
  }

  // Fails, quoting the offending line.
  [[noreturn]] void fail_quoting(const std::string& what) const
  {
    fail(what + ": '" + CGAL::Boolean_isosurfacing::internal::input_excerpt(m_line, 77) + "'");
  }

  double number(std::size_t i) const
  {
    std::string_view t = m_tokens[i];
    const char* first = t.data();
    const char* last = t.data() + t.size();
    if(first != last && *first == '+')
      ++first; // from_chars does not accept a leading '+'
    double value = 0;
    const std::from_chars_result r = std::from_chars(first, last, value);
    if(r.ec == std::errc::result_out_of_range)
      fail("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(t) + "' is out of the range of a double");
    if(r.ec != std::errc() || r.ptr != last)
      fail_quoting("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(t) + "' is not a number");
    return value;
  }

  // A finite coordinate.
  double coordinate(std::size_t i) const
  {
    const double value = number(i);
    if(!std::isfinite(value))
      throw Non_finite_value_error("'" + m_name + "' line " + std::to_string(m_line_number) +
                                   ": non-finite coordinate '" + CGAL::Boolean_isosurfacing::internal::input_excerpt(m_tokens[i]) + "'");
    return value;
  }

  // A non-negative integer.
  std::size_t index(std::size_t i) const
  {
    std::string_view t = m_tokens[i];
    const char* first = t.data();
    const char* last = t.data() + t.size();
    if(first != last && *first == '+')
      ++first;
    unsigned long long value = 0;
    const std::from_chars_result r = std::from_chars(first, last, value);
    if(r.ec != std::errc() || r.ptr != last || value > (std::numeric_limits<std::size_t>::max)())
      fail_quoting("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(t) + "' is not a non-negative integer");
    return std::size_t(value);
  }

  // Any integer (Medit references may be negative).
  long long integer(std::size_t i) const
  {
    std::string_view t = m_tokens[i];
    const char* first = t.data();
    const char* last = t.data() + t.size();
    if(first != last && *first == '+')
      ++first;
    long long value = 0;
    const std::from_chars_result r = std::from_chars(first, last, value);
    if(r.ec != std::errc() || r.ptr != last)
      fail_quoting("'" + CGAL::Boolean_isosurfacing::internal::input_excerpt(t) + "' is not an integer");
    return value;
  }

private:
  void split()
  {
    m_tokens.clear();
    const char* p = m_line.data();
    const char* end = p + m_line.size();
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while(p != end)
    {
      while(p != end && blank(*p))
        ++p;
      if(p == end || *p == '#')
        return;
      const char* start = p;
      while(p != end && !blank(*p) && *p != '#')
        ++p;
      m_tokens.emplace_back(start, std::size_t(p - start));
    }
  }

  std::istream& m_in;
  std::string m_name;
  std::string m_line;
  std::size_t m_line_number = 0;
  std::vector<std::string_view> m_tokens;
};

inline std::string lower(std::string_view s)
{
  std::string out(s);
  for(char& c : out)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

inline bool is_keyword(std::string_view token)
{
  return !token.empty() && std::isalpha(static_cast<unsigned char>(token[0]));
}

// A readable regular file, or Invalid_input_error naming it.
inline void open_for_reading(std::ifstream& in, const std::string& path)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec))
    throw Invalid_input_error("cannot open '" + path + "': no such regular file");
  in.open(path, std::ios::binary); // binary: '\r' of CRLF files is handled as a blank
  if(!in)
    throw Invalid_input_error("cannot open '" + path + "'");
}

inline bool ends_with(const std::string& s, const std::string& suffix)
{
  return CGAL::Boolean_isosurfacing::internal::ends_with_lowercase(s, suffix);
}

// `n` in a "Keyword n" pair, on the keyword's line or alone on the next one.
inline std::size_t medit_value(Line_reader& r, const std::string& keyword)
{
  if(r.size() == 2)
    return r.index(1);
  if(r.size() > 2)
    r.fail_quoting("expected '" + keyword + "' followed by one integer");
  if(!r.next())
    r.fail("the file ends after the keyword '" + keyword + "' (its value is missing)");
  if(r.size() != 1)
    r.fail_quoting("expected the value of '" + keyword + "' (one integer)");
  return r.index(0);
}

// Reads the next line of a block of `count` records of `tokens` tokens each.
// `element` is "vertex" or "tetrahedron" (plural: `elements`).
inline void next_record(Line_reader& r, const char* element, const char* elements, std::size_t k,
                        std::size_t count, std::size_t tokens, const char* layout)
{
  if(!r.next())
    r.fail("the file ends after " + std::to_string(k) + " of the " + std::to_string(count) + " " + elements +
           " its header announces");
  if(r.size() != tokens)
    r.fail_quoting(std::string("expected '") + layout + "' (" + std::to_string(tokens) + " fields) for " +
                   element + " " + std::to_string(k + 1) + " of " + std::to_string(count) + ", found " +
                   std::to_string(r.size()) + " fields");
}

// TetGen numbers its records from 0 or 1 (the first record decides, and sets
// `base`), consecutively.
inline void check_record_number(Line_reader& r, const char* what, std::size_t k, std::size_t& base)
{
  const std::size_t i = r.index(0);
  if(k == 0)
  {
    if(i > 1)
      r.fail(std::string("the first ") + what + " number must be 0 or 1, found " + std::to_string(i));
    base = i;
  }
  else if(i != base + k)
    r.fail(std::string("expected ") + what + " number " + std::to_string(base + k) + ", found " + std::to_string(i) +
           " (" + what + " numbers must be consecutive)");
}

} // namespace tet_mesh_io
} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a Medit `.mesh` stream (format at the top of this header); `name`
 * is used in error messages.  Only the Vertices and Tetrahedra blocks are
 * used; references are ignored.
 *
 * \tparam GeomTraits a model of `Kernel` whose `Point_3` is constructible from three doubles
 * \throws Parse_error (position() = 1-based line number), Non_finite_value_error,
 *         Empty_input_error (no Tetrahedra block), Invalid_input_error (no Vertices
 *         block), and whatever the `Tetrahedral_mesh_3` constructor throws.
 */
template <typename GeomTraits>
Tetrahedral_mesh_3<GeomTraits> read_MEDIT(std::istream& in, const std::string& name = "<stream>")
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename Tetrahedral_mesh_3<GeomTraits>::Tetrahedron Tetrahedron;
  using namespace internal::tet_mesh_io;

  Line_reader r(in, name);
  std::vector<Point_3> points;
  std::vector<Tetrahedron> tetrahedra;
  bool have_vertices = false, have_tetrahedra = false;
  // Tetrahedra read before the Vertices block: the largest index and its line.
  std::size_t deferred_max_index = 0, deferred_line = 0;

  while(r.next())
  {
    if(!is_keyword(r[0]))
      r.fail_quoting("expected a keyword (Vertices, Tetrahedra, End, ...)");
    const std::string keyword = lower(r[0]);
    if(keyword == "end")
    {
      if(r.size() != 1)
        r.fail_quoting("'End' takes no value");
      break;
    }
    if(keyword == "meshversionformatted")
    {
      const std::size_t v = medit_value(r, "MeshVersionFormatted");
      if(v < 1 || v > 4)
        r.fail("unsupported MeshVersionFormatted " + std::to_string(v) + " (1 to 4 are read)");
    }
    else if(keyword == "dimension")
    {
      const std::size_t d = medit_value(r, "Dimension");
      if(d != 3)
        r.fail("only 3D meshes are read (Dimension 3), found Dimension " + std::to_string(d));
    }
    else if(keyword == "vertices")
    {
      if(have_vertices)
        r.fail("a second Vertices block");
      have_vertices = true;
      const std::size_t n = medit_value(r, "Vertices");
      points.reserve(r.check_count(n, 8, "vertices")); // "x y z r\n"
      for(std::size_t k = 0; k < n; ++k)
      {
        next_record(r, "vertex", "vertices", k, n, 4, "x y z ref");
        const double x = r.coordinate(0), y = r.coordinate(1), z = r.coordinate(2);
        r.integer(3);
        points.emplace_back(x, y, z);
      }
    }
    else if(keyword == "tetrahedra")
    {
      if(have_tetrahedra)
        r.fail("a second Tetrahedra block");
      have_tetrahedra = true;
      const std::size_t m = medit_value(r, "Tetrahedra");
      tetrahedra.reserve(r.check_count(m, 10, "tetrahedra")); // "a b c d r\n"
      for(std::size_t k = 0; k < m; ++k)
      {
        next_record(r, "tetrahedron", "tetrahedra", k, m, 5, "a b c d ref");
        Tetrahedron t;
        for(int l = 0; l < 4; ++l)
        {
          const std::size_t i = r.index(std::size_t(l));
          if(i == 0 || (have_vertices && i > points.size()))
            r.fail_quoting("vertex index " + std::to_string(i) + " out of range [1, " +
                           (have_vertices ? std::to_string(points.size()) : std::string("n")) +
                           "] (Medit indices are 1-based)");
          if(!have_vertices && i > deferred_max_index)
          {
            deferred_max_index = i;
            deferred_line = r.line_number();
          }
          t[l] = i - 1;
        }
        r.integer(4);
        tetrahedra.push_back(t);
      }
    }
    else
    {
      // Another block (Triangles, Edges, Corners, ...): its records are skipped.
      const std::string block = CGAL::Boolean_isosurfacing::internal::input_excerpt(r[0]);
      const std::size_t n = medit_value(r, block);
      r.check_count(n, 2, "records of the " + block + " block");
      for(std::size_t k = 0; k < n; ++k)
        if(!r.next())
          r.fail("the file ends after " + std::to_string(k) + " of the " + std::to_string(n) + " records of the " +
                 block + " block");
    }
  }
  if(!have_vertices)
    throw Invalid_input_error("'" + name + "': no Vertices block");
  if(!have_tetrahedra)
    throw Empty_input_error("'" + name + "': no Tetrahedra block (only tetrahedral meshes are read)");
  if(deferred_max_index > points.size())
    throw Parse_error("'" + name + "' line " + std::to_string(deferred_line) + ": vertex index " +
                        std::to_string(deferred_max_index) + " out of range [1, " + std::to_string(points.size()) +
                        "] (Medit indices are 1-based)",
                      deferred_line);
  return Tetrahedral_mesh_3<GeomTraits>(std::move(points), std::move(tetrahedra));
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads the Medit `.mesh` file `filename`.  Usage: `IO::read_MEDIT<K>("bunny.mesh")`.
 * \throws Invalid_input_error if the file cannot be opened, else as the stream overload.
 */
template <typename GeomTraits>
Tetrahedral_mesh_3<GeomTraits> read_MEDIT(const std::string& filename)
{
  std::ifstream in;
  internal::tet_mesh_io::open_for_reading(in, filename);
  return read_MEDIT<GeomTraits>(in, filename);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a TetGen mesh from its `.node` and `.ele` streams (format at the top
 * of this header); the names are used in error messages.
 *
 * \tparam GeomTraits a model of `Kernel` whose `Point_3` is constructible from three doubles
 * \throws Parse_error (position() = 1-based line number of the file named in the message),
 *         Non_finite_value_error, Empty_input_error (no vertex or no tetrahedron),
 *         and whatever the `Tetrahedral_mesh_3` constructor throws.
 */
template <typename GeomTraits>
Tetrahedral_mesh_3<GeomTraits> read_TetGen(std::istream& node, std::istream& ele,
                                           const std::string& node_name = "<node stream>",
                                           const std::string& ele_name = "<ele stream>")
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename Tetrahedral_mesh_3<GeomTraits>::Tetrahedron Tetrahedron;
  using namespace internal::tet_mesh_io;

  // .node
  Line_reader r(node, node_name);
  if(!r.next())
    throw Empty_input_error("'" + node_name + "': no header line 'n dim nattr nbm'");
  if(r.size() > 4)
    r.fail_quoting("expected the header 'n dim nattr nbm' (at most 4 integers)");
  const std::size_t n = r.index(0);
  const std::size_t dim = r.size() > 1 ? r.index(1) : 3;
  const std::size_t nattr = r.size() > 2 ? r.index(2) : 0;
  const std::size_t nbm = r.size() > 3 ? r.index(3) : 0;
  if(n == 0)
    throw Empty_input_error("'" + node_name + "' line " + std::to_string(r.line_number()) + ": the header announces no vertex");
  if(dim != 3)
    r.fail("only 3D meshes are read (dimension 3), found dimension " + std::to_string(dim));
  if(nbm > 1)
    r.fail("the number of boundary markers must be 0 or 1, found " + std::to_string(nbm));
  if(nattr > 1024)
    r.fail("implausible number of attributes " + std::to_string(nattr));
  std::vector<Point_3> points;
  points.reserve(r.check_count(n, 2 * (4 + nattr + nbm), "vertices"));
  std::size_t base = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    next_record(r, "vertex", "vertices", k, n, 4 + nattr + nbm, "i x y z [attributes] [marker]");
    check_record_number(r, "vertex", k, base);
    const double x = r.coordinate(1), y = r.coordinate(2), z = r.coordinate(3);
    for(std::size_t a = 4; a < r.size(); ++a)
      r.number(a); // attributes and marker: checked, ignored
    points.emplace_back(x, y, z);
  }
  if(r.next())
    r.fail_quoting("more vertex lines than the " + std::to_string(n) + " the header announces");

  // .ele
  Line_reader e(ele, ele_name);
  if(!e.next())
    throw Empty_input_error("'" + ele_name + "': no header line 'm nodes_per_tetrahedron nattr'");
  if(e.size() > 3)
    e.fail_quoting("expected the header 'm nodes_per_tetrahedron nattr' (at most 3 integers)");
  const std::size_t m = e.index(0);
  const std::size_t npt = e.size() > 1 ? e.index(1) : 4;
  const std::size_t eattr = e.size() > 2 ? e.index(2) : 0;
  if(m == 0)
    throw Empty_input_error("'" + ele_name + "' line " + std::to_string(e.line_number()) +
                            ": the header announces no tetrahedron");
  if(npt != 4 && npt != 10)
    e.fail("the number of nodes per tetrahedron must be 4 or 10, found " + std::to_string(npt));
  if(eattr > 1024)
    e.fail("implausible number of attributes " + std::to_string(eattr));
  std::vector<Tetrahedron> tetrahedra;
  tetrahedra.reserve(e.check_count(m, 2 * (1 + npt + eattr), "tetrahedra"));
  std::size_t element_base = 0;
  for(std::size_t k = 0; k < m; ++k)
  {
    next_record(e, "tetrahedron", "tetrahedra", k, m, 1 + npt + eattr, "j a b c d [attributes]");
    check_record_number(e, "tetrahedron", k, element_base);
    Tetrahedron t;
    for(std::size_t l = 0; l < npt; ++l)
    {
      const std::size_t i = e.index(1 + l);
      if(i < base || i - base >= n)
        e.fail_quoting("vertex index " + std::to_string(i) + " out of range [" + std::to_string(base) + ", " +
                       std::to_string(base + n - 1) + "] (the .node file numbers its vertices from " +
                       std::to_string(base) + ")");
      if(l < 4)
        t[l] = i - base;
    }
    for(std::size_t a = 1 + npt; a < e.size(); ++a)
      e.number(a);
    tetrahedra.push_back(t);
  }
  if(e.next())
    e.fail_quoting("more tetrahedron lines than the " + std::to_string(m) + " the header announces");
  return Tetrahedral_mesh_3<GeomTraits>(std::move(points), std::move(tetrahedra));
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads the TetGen mesh `base.node` + `base.ele`, where `node_or_ele_or_basename`
 * is `base.node`, `base.ele` or `base` itself.
 * \throws Invalid_input_error if a file cannot be opened, else as the stream overload.
 */
template <typename GeomTraits>
Tetrahedral_mesh_3<GeomTraits> read_TetGen(const std::string& node_or_ele_or_basename)
{
  using namespace internal::tet_mesh_io;
  std::string base = node_or_ele_or_basename;
  if(ends_with(base, ".node"))
    base.resize(base.size() - 5);
  else if(ends_with(base, ".ele"))
    base.resize(base.size() - 4);
  std::ifstream node, ele;
  open_for_reading(node, base + ".node");
  open_for_reading(ele, base + ".ele");
  return read_TetGen<GeomTraits>(node, ele, base + ".node", base + ".ele");
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * reads a tetrahedral mesh, choosing the format by the extension
 * (case-insensitive): `.mesh` is Medit (`read_MEDIT()`), `.node` and `.ele`
 * are TetGen (`read_TetGen()`).
 * \throws Invalid_input_error for another extension, else as the reader.
 */
template <typename GeomTraits>
Tetrahedral_mesh_3<GeomTraits> read_tetrahedral_mesh(const std::string& filename)
{
  using namespace internal::tet_mesh_io;
  if(ends_with(filename, ".mesh"))
    return read_MEDIT<GeomTraits>(filename);
  if(ends_with(filename, ".node") || ends_with(filename, ".ele"))
    return read_TetGen<GeomTraits>(filename);
  throw Invalid_input_error("'" + filename +
                            "': unknown tetrahedral mesh format (expected the extension .mesh, .node or .ele)");
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * writes `mesh` as an ASCII Medit `.mesh` stream: `MeshVersionFormatted 2`,
 * `Dimension 3`, the Vertices (coordinates with `max_digits10` significant
 * digits, so that reading gives back the same doubles) and the Tetrahedra
 * (1-based, in the mesh's positive orientation), all references 0, `End`.
 * \throws std::runtime_error if writing fails.
 */
template <typename GeomTraits>
void write_MEDIT(std::ostream& out, const Tetrahedral_mesh_3<GeomTraits>& mesh)
{
  const std::locale old_locale = out.imbue(std::locale::classic());
  const std::streamsize old_precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << mesh.number_of_vertices() << '\n';
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
  {
    const std::array<double, 3> p = mesh.position(v);
    out << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
  }
  out << "Tetrahedra\n" << mesh.number_of_tetrahedra() << '\n';
  for(const auto& t : mesh.tetrahedra())
    out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << " 0\n";
  out << "End\n";
  out.precision(old_precision);
  out.imbue(old_locale);
  out.flush();
  if(!out)
    throw std::runtime_error("writing the Medit mesh failed");
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// writes `mesh` to the Medit file `filename` (see the stream overload).
/// \throws std::runtime_error if the file cannot be opened or written.
template <typename GeomTraits>
void write_MEDIT(const std::string& filename, const Tetrahedral_mesh_3<GeomTraits>& mesh)
{
  std::ofstream out(filename, std::ios::binary);
  if(!out)
    throw std::runtime_error("cannot open '" + filename + "' for writing");
  try
  {
    write_MEDIT(out, mesh);
  }
  catch(const std::runtime_error&)
  {
    throw std::runtime_error("cannot write '" + filename + "'");
  }
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_TETRAHEDRAL_MESH_H
