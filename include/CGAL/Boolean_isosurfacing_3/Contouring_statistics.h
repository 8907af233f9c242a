// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_CONTOURING_STATISTICS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_CONTOURING_STATISTICS_H

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What a contouring run did; all counts are exact, times are wall clock.
/// `number_of_vertices`, `number_of_faces` (triangles), `seconds` and
/// `warnings` (holes left or repaired, border exits) are those of
/// `Algorithm_statistics`.
struct Contouring_statistics : Algorithm_statistics
{
  double cell_size = 0;                          ///< lattice spacing r
  std::array<double, 3> origin{{0, 0, 0}};       ///< lattice point (0,0,0)
  std::array<std::size_t, 3> number_of_cells{{0, 0, 0}}; ///< cells of the lattice along each axis
  std::size_t field_evaluations = 0;             ///< lattice points where f was evaluated
  std::size_t undefined_points = 0;              ///< ... of which f was undefined
  std::size_t visited_cubes = 0;                 ///< cubes examined by the traversal
  std::size_t surface_cubes = 0;                 ///< cubes that produced triangles
  std::size_t skipped_cubes = 0;                 ///< crossed cubes skipped: an undefined corner
  std::size_t border_exits = 0;                  ///< crossed faces on the lattice border (holes)
  std::size_t discontinuous_cubes = 0;           ///< skipped: f jumps across a sign-changing edge
  std::size_t ambiguous_faces = 0;               ///< (counted once per cube side)
  std::size_t joined_faces = 0;                  ///< ... where the decider joined the inside
  std::size_t centre_vertices = 0;               ///< polygon centre vertices added
  std::size_t removed_closed_components = 0;     ///< bubbles smaller than minimum_closed_component_size
  std::size_t split_vertices = 0;                ///< vertices pinched between two holes, duplicated
  std::size_t filled_holes = 0;                  ///< border loops smaller than maximum_hole_size, triangulated
  std::size_t walk_seeds = 0;                    ///< crossed cubes reached by walking down |f| from a sample
  /// One consistent value per lattice point (the field's `consistent_value()`):
  /// no cube is skipped, so the contour is closed and 2-manifold before the
  /// membranes are removed.
  bool consistent_signs = false;
  std::size_t removed_membranes = 0;             ///< surface pieces far from every sample, spanning a wide opening, removed
  std::size_t feature_creases = 0;               ///< polygons fanned around a crease vertex (sharp features)
  std::size_t feature_corners = 0;               ///< ... around a corner vertex
  std::size_t feature_flips = 0;                 ///< face segments flipped to join feature vertices into lines
  /// No triangle came out: f changes sign in no cube reached from the samples
  /// (or only in skipped ones).  `contour_point_set` throws `Empty_contour_error`.
  bool empty_output = false;
  double seconds_field = 0;                      ///< evaluating f at lattice points
  double seconds_contouring = 0;                 ///< traversal + triangles, without field time
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_CONTOURING_STATISTICS_H
