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
  /// \deprecated the same as `number_of_faces`.
  std::size_t number_of_polygons = 0;
  /// \deprecated the same as `seconds_tables`.
  double table_seconds = 0;
  /// \deprecated the same as `seconds_extraction`.
  double extraction_seconds = 0;
  /// \deprecated the same as `seconds_welding`.
  double welding_seconds = 0;

  /// \cond SKIP_IN_MANUAL
  // Fills the deprecated names from the new ones.
  void set_deprecated_names()
  {
    number_of_polygons = number_of_faces;
    table_seconds = seconds_tables;
    extraction_seconds = seconds_extraction;
    welding_seconds = seconds_welding;
  }
  /// \endcond
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_STATISTICS_H
