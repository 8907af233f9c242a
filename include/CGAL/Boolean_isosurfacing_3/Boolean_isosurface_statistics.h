// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_STATISTICS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_STATISTICS_H

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>

#include <cstddef>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `extract_boolean_isosurface()` did, and how long each stage took.
/// `number_of_vertices`, `number_of_faces` (polygons), `seconds` and
/// `warnings` are those of `Algorithm_statistics`.
struct Boolean_isosurface_statistics : Algorithm_statistics
{
  /// Tetrahedra of the domain.
  std::size_t number_of_tetrahedra = 0;
  /// Tetrahedra that needed more than the sign test on their corner values.
  std::size_t number_of_evaluated_tetrahedra = 0;
  /// Preparing the expression (the replacement of the seed's tables).
  double seconds_tables = 0;
  /// Visiting the tetrahedra and building the polygons.
  double seconds_extraction = 0;
  /// Welding the pieces of the parallel chunks into one soup.
  double seconds_welding = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_STATISTICS_H
