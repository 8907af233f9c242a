// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SOUP_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SOUP_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The output of `extract_boolean_isosurface()`: an indexed polygon soup,
/// welded (each point appears once), whose polygons are convex, planar,
/// oriented outward from the Boolean set, and labelled by the field whose
/// zero set they lie on.
template <typename Point_3>
struct Boolean_isosurface_soup
{
  /// Label of the polygons that close the set on the boundary of the domain
  /// (the `close_at_domain_boundary` option).
  static constexpr int domain_boundary = -1;

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  /// `face_fields[p]`: the index of the field polygon `p` lies on (the lowest
  /// index when several fields vanish on it), or `domain_boundary`.
  std::vector<int> face_fields;
  /// `face_boundary_planes[p]`: for a polygon labelled `domain_boundary`, the
  /// plane of the domain boundary it lies on, else -1.  On a grid the planes
  /// are the box faces: 2 a + 0 at the minimum of axis a, 2 a + 1 at its
  /// maximum.  On a tetrahedral mesh they are the maximal connected sets of
  /// coplanar boundary faces (exact test).  Where closing faces of two planes
  /// meet, `extract_crease_network()` makes a crease.  May be empty (a soup
  /// read from a file): closing faces then count as one label.
  std::vector<int> face_boundary_planes;

  std::size_t number_of_polygons() const { return polygons.size(); }
  void clear()
  {
    points.clear();
    polygons.clear();
    face_fields.clear();
    face_boundary_planes.clear();
  }
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Crease polylines and corners of a labelled polygon soup (see
/// `extract_crease_network()`).  Indices refer to the soup's points.
struct Crease_network
{
  /// Each polyline is a chain of crease edges between two corners; a closed
  /// crease without corner repeats its first point at the end.
  std::vector<std::vector<std::size_t>> polylines;
  /// Vertices where three or more labels meet, or where creases end or branch.
  std::vector<std::size_t> corners;
  /// Number of crease edges.
  std::size_t number_of_crease_edges = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SOUP_H
