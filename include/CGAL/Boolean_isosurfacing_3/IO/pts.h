// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_PTS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_PTS_H

// Reader of the `.pts` point files of the contour-tracing assignment ([ContourTracing])
// ("one point per line, x y z, optionally followed by nx ny nz") and of Hoppe's
// own 1992 files (points/cactus.pts, points/distcap.pts), which are A3dStream
// text: `p x y z` lines, colour lines `d`/`s`/`g`/`c r g b`, and `n nx ny nz`
// giving the normal of the point before it.
//
// Accepted, line by line (leading/trailing blanks ignored):
//   - a blank line, or a line whose first non-blank character is '#': skipped;
//   - `x y z` or `x y z nx ny nz`: a point, with a normal in the second form;
//   - `p x y z`: a point (A3d);  `n nx ny nz`: the normal of the previous point (A3d);
//   - `d|s|g|c` followed by 3 numbers: an A3d colour, ignored.
// Anything else is a Parse_error whose position() and message give the
// 1-based line number.  Either every point has a normal or none has (else
// Parse_error at the first line that breaks the rule).  A NaN or infinite
// number is a Non_finite_value_error naming the line.  Numbers are parsed with
// std::from_chars: independent of the locale.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Input_excerpt.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {
namespace internal {

// Splits `line` into blank-separated tokens (at most 8).
inline std::size_t split_tokens(const std::string& line, std::array<std::pair<const char*, const char*>, 8>& tokens)
{
  std::size_t n = 0;
  const char* p = line.data();
  const char* end = p + line.size();
  while(p != end)
  {
    while(p != end && (*p == ' ' || *p == '\t' || *p == '\r'))
      ++p;
    if(p == end)
      break;
    const char* start = p;
    while(p != end && !(*p == ' ' || *p == '\t' || *p == '\r'))
      ++p;
    if(n == tokens.size())
      return n + 1; // too many
    tokens[n++] = {start, p};
  }
  return n;
}

inline double parse_number(const std::pair<const char*, const char*>& token, std::size_t line_number)
{
  double value = 0;
  const char* first = token.first;
  if(first != token.second && *first == '+')
    ++first; // from_chars does not accept a leading '+'
  const std::from_chars_result result = std::from_chars(first, token.second, value);
  if(result.ec != std::errc() || result.ptr != token.second)
    throw Parse_error("line " + std::to_string(line_number) + ": '" +
                        CGAL::Boolean_isosurfacing::internal::input_excerpt(std::string_view(token.first, std::size_t(token.second - token.first))) +
                        "' is not a number",
                      line_number);
  if(!std::isfinite(value))
    throw Non_finite_value_error("line " + std::to_string(line_number) + ": non-finite value '" +
                                 CGAL::Boolean_isosurfacing::internal::input_excerpt(std::string_view(token.first, std::size_t(token.second - token.first))) +
                                 "'");
  return value;
}

enum class Point_file_format
{
  PTS, // the format above
  XYZ  // CGAL's .xyz / .pwn: `x y z` or `x y z nx ny nz`, and an optional point count alone on the first line
};

} // namespace internal

/*!
 * Reads a `.pts` stream (format above), appending to `points` and, when the
 * file has normals, to `normals`.  `Point_3` and `Vector_3` are constructible
 * from three doubles.
 * \returns whether the points came with normals.
 * \throws Parse_error (position() = 1-based line), Non_finite_value_error,
 *         Empty_input_error (no point at all).
 */
template <typename Point_3, typename Vector_3>
bool read_pts(std::istream& in, std::vector<Point_3>& points, std::vector<Vector_3>& normals,
              internal::Point_file_format format = internal::Point_file_format::PTS)
{
  const bool xyz = format == internal::Point_file_format::XYZ;
  bool first_meaningful_line = true;
  std::string line;
  std::size_t line_number = 0;
  std::size_t read = 0, with_normal = 0;
  bool a3d_normal_allowed = false; // an `n` line may follow a `p` line
  std::array<std::pair<const char*, const char*>, 8> tokens;
  auto mixed = [&](std::size_t at) {
    return Parse_error("line " + std::to_string(at) +
                         ": some points have a normal and others do not (all or none must)",
                       at);
  };
  while(std::getline(in, line))
  {
    ++line_number;
    const std::size_t n = internal::split_tokens(line, tokens);
    if(n == 0 || *tokens[0].first == '#')
      continue;
    if(xyz && first_meaningful_line && n == 1)
    {
      first_meaningful_line = false;
      std::size_t count = 0;
      const std::from_chars_result r = std::from_chars(tokens[0].first, tokens[0].second, count);
      if(r.ec != std::errc() || r.ptr != tokens[0].second)
        throw Parse_error("line " + std::to_string(line_number) + ": expected the number of points or 'x y z', found '" +
                            CGAL::Boolean_isosurfacing::internal::input_excerpt(line) + "'",
                          line_number);
      continue; // the optional point count of .xyz files: not needed
    }
    first_meaningful_line = false;
    const char head = *tokens[0].first;
    const bool keyword = !xyz && (tokens[0].second - tokens[0].first == 1) &&
                         (head == 'p' || head == 'n' || head == 'd' || head == 's' || head == 'g' || head == 'c');
    auto bad = [&](const std::string& why) {
      return Parse_error("line " + std::to_string(line_number) + ": " + why + ": '" + CGAL::Boolean_isosurfacing::internal::input_excerpt(line) + "'", line_number);
    };
    if(keyword)
    {
      if(n != 4)
        throw bad(std::string("'") + head + "' must be followed by 3 numbers");
      std::array<double, 3> v;
      for(int i = 0; i < 3; ++i)
        v[i] = internal::parse_number(tokens[i + 1], line_number);
      if(head == 'p')
      {
        if(with_normal != 0 && with_normal != read) // the previous point has no 'n'
          throw mixed(line_number);
        points.emplace_back(v[0], v[1], v[2]);
        ++read;
        a3d_normal_allowed = true;
      }
      else if(head == 'n')
      {
        if(!a3d_normal_allowed)
          throw bad("a normal 'n' must follow its point 'p'");
        if(with_normal != read - 1)
          throw mixed(line_number);
        normals.emplace_back(v[0], v[1], v[2]);
        ++with_normal;
        a3d_normal_allowed = false;
      }
      continue; // colours are ignored
    }
    if(n != 3 && n != 6)
      throw bad("expected 'x y z' or 'x y z nx ny nz' (3 or 6 numbers), found " + std::to_string(n) + " fields");
    std::array<double, 6> v;
    for(std::size_t i = 0; i < n; ++i)
      v[i] = internal::parse_number(tokens[i], line_number);
    if(read != 0 && (n == 6) != (with_normal == read))
      throw mixed(line_number);
    points.emplace_back(v[0], v[1], v[2]);
    ++read;
    if(n == 6)
    {
      normals.emplace_back(v[3], v[4], v[5]);
      ++with_normal;
    }
    a3d_normal_allowed = false;
  }
  if(in.bad())
    throw Invalid_input_error("read error after line " + std::to_string(line_number));
  if(read == 0)
    throw Empty_input_error("no point in the input (" + std::to_string(line_number) + " lines)");
  if(with_normal != 0 && with_normal != read)
    throw mixed(line_number);
  return with_normal != 0;
}

/// As above, from the file `path`.  \throws Invalid_input_error if it cannot be opened.
template <typename Point_3, typename Vector_3>
bool read_pts(const std::string& path, std::vector<Point_3>& points, std::vector<Vector_3>& normals)
{
  std::ifstream in(path);
  if(!in)
    throw Invalid_input_error("cannot open '" + path + "'");
  return read_pts(in, points, normals);
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_PTS_H
