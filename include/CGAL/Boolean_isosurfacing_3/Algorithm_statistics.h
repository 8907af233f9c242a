// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_ALGORITHM_STATISTICS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_ALGORITHM_STATISTICS_H

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * The members every algorithm of the package reports, under one name:
 * `Marching_cubes_csg_statistics`, `Contouring_statistics` and
 * `Boolean_isosurface_statistics` derive from it and add their own counts
 * and their stage times, all named `seconds_<stage>` (wall clock).
 */
struct Algorithm_statistics
{
  /// Vertices of the output.
  std::size_t number_of_vertices = 0;
  /// Faces (triangles or polygons) of the output.
  std::size_t number_of_faces = 0;
  /// The whole run, wall clock.
  double seconds = 0;
  /// One line per thing the caller should know about the result (an open
  /// output, an under-resolved input, a repaired hole...); empty when the
  /// result has every guarantee the algorithm documents.
  std::vector<std::string> warnings;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_ALGORITHM_STATISTICS_H
