// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OBJ_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OBJ_H

// Wavefront OBJ: `v x y z [w | r g b]` and `f` lines with corners `i`,
// `i/t`, `i/t/n` or `i//n` (negative indices count back from the last
// vertex); every other statement (vt, vn, o, g, s, usemtl, mtllib, l, ...)
// is skipped.  A line that does not start with a statement word is an error,
// so a file that is not OBJ is not read as an empty one.

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

inline void read_OBJ(const char* begin, const char* end, Triangle_soup_3& soup)
{
  Text_cursor in(begin, end);
  soup.points.clear();
  soup.triangles.clear();
  // No counts in OBJ: a guess from the size (a vertex line is ~30 bytes, a
  // face line ~20, about twice as many faces) saves most regrowth.
  reserve_in_huge_pages(soup.points, std::size_t(end - begin) / 80);
  reserve_in_huge_pages(soup.triangles, std::size_t(end - begin) / 40);
  std::vector<std::uint32_t> polygon;
  std::size_t face_number = 0;
  while(true)
  {
    in.skip_spaces();
    if(in.at_end())
      break;
    const char c0 = in.p[0], c1 = in.p[1];
    if(c0 == 'v' && is_text_blank(c1))
    {
      const char* line = in.p;
      in.p += 2;
      double c[3];
      for(int k = 0; k < 3; ++k)
        if(!in.parse_double(c[k]))
          in.fail("cannot parse coordinate " + std::to_string(k + 1) + " of vertex " +
                  std::to_string(soup.points.size() + 1) + ": expected a number, found " + in.found());
      if(!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        in.fail_at(line, "vertex " + std::to_string(soup.points.size() + 1) + " has a non-finite coordinate (" +
                             describe_non_finite(c[0], c[1], c[2]) + ")");
      if(soup.points.size() == std::size_t(0xffffffffu))
        check_point_count(soup.points.size() + 1);
      soup.points.push_back({c[0], c[1], c[2]});
      in.skip_line();
    }
    else if(c0 == 'f' && is_text_blank(c1))
    {
      in.p += 2;
      polygon.clear();
      const std::int64_t n = std::int64_t(soup.points.size());
      while(!in.at_end_of_line())
      {
        std::int64_t i;
        if(!in.parse_signed(i))
          in.fail("cannot parse corner " + std::to_string(polygon.size() + 1) + " of face " +
                  std::to_string(face_number + 1) + ": expected a vertex index, found " + in.found());
        const std::int64_t v = i < 0 ? n + i : i - 1;
        if(i == 0 || v < 0 || v >= n)
          in.fail("face " + std::to_string(face_number + 1) + " refers to vertex " + std::to_string(i) +
                  ", but " + std::to_string(n) + " vertices are defined before it");
        polygon.push_back(std::uint32_t(v));
        // texture and normal indices: i/t, i/t/n, i//n
        while(in.p < in.end && (*in.p == '/' || *in.p == '-' || is_text_digit(*in.p))) ++in.p;
        if(in.p < in.end && !is_text_space(*in.p) && *in.p != '#')
          in.fail("cannot parse corner " + std::to_string(polygon.size()) + " of face " +
                  std::to_string(face_number + 1) + ": unexpected " + in.found());
      }
      if(polygon.size() < 3)
        in.fail("face " + std::to_string(face_number + 1) + " has " + std::to_string(polygon.size()) +
                " vertices; a face needs at least 3");
      add_fan_of_triangles(soup, polygon.data(), polygon.size());
      ++face_number;
      in.skip_line();
    }
    else if(c0 == '#' || (c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z'))
      in.skip_line(); // comments and the statements that do not make the surface
    else
      in.fail("cannot parse it as OBJ: expected a statement (v, f, ...), found " + in.found());
  }
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_READ_OBJ_H
