// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_POST_PROCESSING_STATISTICS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_POST_PROCESSING_STATISTICS_H

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>

#include <cstddef>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * What `simplify_keeping_creases()` and `remesh_keeping_creases()` did.
 * Both check their result for self-intersections (exactly,
 * `Polygon_mesh_processing::self_intersections()`); where one is found, they
 * run again from the input with the input's faces near it left as they were,
 * and give the input back unchanged (`reverted`, with a warning) if the last
 * run still self-intersects.
 */
struct Post_processing_statistics : Algorithm_statistics
{
  /// Runs of the operation: 1 when the first result is free of self-intersections.
  std::size_t runs = 0;
  /// Faces of the input left as they were because an earlier run self-intersected near them.
  std::size_t frozen_faces = 0;
  /// Pairs of intersecting faces in the results that were thrown away.
  std::size_t intersecting_pairs_found = 0;
  /// Input vertices farther than the allowed deviation from the results that
  /// were thrown away (`remesh_keeping_creases()`).
  std::size_t far_input_vertices_found = 0;
  /// Whether the mesh was left as it was given (every run self-intersected).
  bool reverted = false;
  /// Edges collapsed by the kept run (`simplify_keeping_creases()`).
  std::size_t edges_collapsed = 0;
  /// The self-intersection checks (included in `seconds`).
  double seconds_checks = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_POST_PROCESSING_STATISTICS_H
