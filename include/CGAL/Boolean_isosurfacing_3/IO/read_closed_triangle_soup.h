// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_SOUP_H

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/*!
 * \ingroup PkgBooleanIsosurfacing3IO
 *
 * reads `path` with `read_triangle_soup()` and checks that the soup bounds a
 * solid: non-empty, every index in range, no repeated vertex in a triangle,
 * closed and consistently oriented (every directed edge matched by its
 * opposite: the linear-time check of the soup `surveyor_volume()`), finite,
 * and outward (a positive volume) unless `allow_inward`, with at least 4
 * triangles (fewer can only cover one triangle twice).  Non-manifold
 * vertices are allowed (the soup has no connectivity to break); see
 * `read_closed_triangle_mesh()` for a `FaceGraph`.
 *
 * \returns the soup, in flat arrays, without building any mesh; if
 *   `signed_volume` is not null, it receives the soup's signed volume (the
 *   check computes it: negative for an inward soup).
 * \throws Invalid_input_error (or a derived type) whose message states the
 *   problem in one line, without the file name.
 */
inline Triangle_soup_3 read_closed_triangle_soup(const std::string& path, bool allow_inward = false,
                                                 double* signed_volume = nullptr)
{
  Triangle_soup_3 soup = read_triangle_soup(path);
  const double volume = surveyor_volume(soup, parameters::signed_volume(allow_inward));
  if(signed_volume != nullptr)
    *signed_volume = volume;
  // A closed soup of fewer than 4 triangles is a doubly covered triangle (the
  // edge check cannot tell it from a solid), and an outward soup of volume 0
  // (certified: exactly 0) is flat: neither bounds a solid.
  if(soup.triangles.size() < 4)
    throw Invalid_input_error("the closed surface has only " + std::to_string(soup.triangles.size()) +
                              " triangles: a doubly covered triangle bounds no solid");
  if(!allow_inward && volume == 0)
    throw Invalid_input_error("the closed surface encloses no volume (it is flat, or its faces cover each other)");
  return soup;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_SOUP_H
