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
 * and outward (a positive volume) unless `allow_inward`.  Non-manifold
 * vertices are allowed (the soup has no connectivity to break); see
 * `read_closed_triangle_mesh()` for a `FaceGraph`.
 *
 * \returns the soup, in flat arrays, without building any mesh.
 * \throws Invalid_input_error (or a derived type) whose message states the
 *   problem in one line, without the file name.
 */
inline Triangle_soup_3 read_closed_triangle_soup(const std::string& path, bool allow_inward = false)
{
  Triangle_soup_3 soup = read_triangle_soup(path);
  surveyor_volume(soup, parameters::signed_volume(allow_inward));
  return soup;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_CLOSED_TRIANGLE_SOUP_H
