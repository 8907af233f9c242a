// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OFF_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OFF_H

// ASCII OFF (and its COFF / NOFF / STOFF variants, whose extra vertex
// columns are ignored): line-based for vertices and faces, as CGAL's own
// reader is, so colours after the coordinates or indices are skipped.

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Input_buffer.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Mesh_readers/Soup_builder.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The keyword: [ST][C][N][4][n]OFF.  Returns false if the text does not
// start with one (the counts may then start the file, which OFF allows).
inline bool read_OFF_keyword(Text_cursor& in)
{
  const char* q = in.p;
  const char* start = q;
  while(q < in.end && !is_text_space(*q) && *q != '#') ++q;
  const std::string word(start, q);
  if(word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0)
    return false;
  const std::string prefix = word.substr(0, word.size() - 3);
  std::size_t k = 0;
  if(prefix.compare(k, 2, "ST") == 0) k += 2;
  if(k < prefix.size() && prefix[k] == 'C') ++k;
  if(k < prefix.size() && prefix[k] == 'N') ++k;
  if(k < prefix.size() && (prefix[k] == '4' || prefix[k] == 'n'))
    in.fail("only 3D OFF is supported (found the keyword '" + printable_excerpt(start, q) + "')");
  if(k != prefix.size())
    return false;
  in.p = q;
  in.skip_blanks();
  if(in.accept("BINARY"))
    in.fail_at(start, "binary OFF is not supported; write it as ASCII OFF or as binary PLY");
  return true;
}

inline void read_OFF(const char* begin, const char* end, Triangle_soup_3& soup)
{
  Text_cursor in(begin, end);
  in.skip_spaces_and_comments('#');
  if(!read_OFF_keyword(in) && !(in.p < end && is_text_digit(*in.p)))
    in.fail("cannot parse it as OFF: expected the keyword OFF, found " + in.found());
  std::uint64_t nv = 0, nf = 0, ne = 0;
  in.skip_spaces_and_comments('#');
  const char* header = in.p; // the counts
  if(!in.parse_unsigned(nv))
    in.fail("cannot parse the vertex count: expected a whole number, found " + in.found());
  in.skip_spaces_and_comments('#');
  if(!in.parse_unsigned(nf))
    in.fail("cannot parse the face count: expected a whole number, found " + in.found());
  if(!in.at_end_of_line() && !in.parse_unsigned(ne))
    in.fail("cannot parse the edge count: expected a whole number, found " + in.found());
  in.skip_line();

  // "0 0 0\n" per vertex and at least 6 bytes per face ("3 0 1 2\n" has 8):
  // a bound on memory, not a parse, so it is kept loose.
  const std::uint64_t available = std::uint64_t(end - in.p) + 1;
  if(!count_fits(nv, 6, available))
    in.fail_at(header, count_error("vertices", nv, 6, available));
  if(!count_fits(nf, 6, available - nv * 6))
    in.fail_at(header, count_error("faces after the vertices", nf, 6, available - nv * 6));
  check_point_count(nv);

  soup.points.clear();
  soup.triangles.clear();
  reserve_in_huge_pages(soup.points, std::size_t(nv));
  reserve_in_huge_pages(soup.triangles, std::size_t(nf));
  for(std::uint64_t i = 0; i < nv; ++i)
  {
    in.skip_spaces_and_comments('#');
    const char* line = in.p;
    double c[3];
    for(int k = 0; k < 3; ++k)
      if(!in.parse_double(c[k]))
      {
        if(in.at_end())
          in.fail("the file ends at vertex " + std::to_string(i) + " of the " + std::to_string(nv) +
                  " the header declares (truncated file)");
        in.fail("cannot parse coordinate " + std::to_string(k + 1) + " of vertex " + std::to_string(i) +
                ": expected a number, found " + in.found());
      }
    if(!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
      in.fail_at(line, "vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                           describe_non_finite(c[0], c[1], c[2]) + ")");
    soup.points.push_back({c[0], c[1], c[2]});
    in.skip_line();
  }

  std::vector<std::uint32_t> polygon;
  for(std::uint64_t f = 0; f < nf; ++f)
  {
    in.skip_spaces_and_comments('#');
    std::uint64_t k;
    if(!in.parse_unsigned(k))
    {
      if(in.at_end())
        in.fail("the file ends at face " + std::to_string(f) + " of the " + std::to_string(nf) +
                " the header declares (truncated file)");
      in.fail("cannot parse the vertex count of face " + std::to_string(f) + ": expected a whole number, found " +
              in.found());
    }
    if(k < 3)
      in.fail("face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; a face needs at least 3");
    if(!count_fits(k, 2, std::uint64_t(end - in.p)))
      in.fail("face " + std::to_string(f) + " claims " + std::to_string(k) +
              " vertices, more than the rest of the file can hold");
    polygon.clear();
    for(std::uint64_t j = 0; j < k; ++j)
    {
      std::uint64_t v;
      if(!in.parse_unsigned(v))
        in.fail("cannot parse index " + std::to_string(j + 1) + " of face " + std::to_string(f) +
                ": expected a whole number, found " + in.found());
      if(v >= nv)
        in.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", but there are " +
                std::to_string(nv) + " vertices");
      polygon.push_back(std::uint32_t(v));
    }
    add_fan_of_triangles(soup, polygon.data(), polygon.size());
    in.skip_line();
  }
  in.skip_spaces_and_comments('#');
  if(!in.at_end())
    in.fail("unexpected content after the last of the " + std::to_string(nf) +
            " faces the header declares: " + in.found());
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OFF_H
