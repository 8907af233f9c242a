// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_STATISTICS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_STATISTICS_H

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Resolution_check.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `marching_cubes_csg()` did, and how long each phase took (wall clock).
///
/// `number_of_vertices`, `number_of_faces` (triangles), `seconds` and
/// `warnings` (an open output, under-resolved components) are those of
/// `Algorithm_statistics`.
struct Marching_cubes_csg_statistics : Algorithm_statistics
{
  /// Reading the meshes, binning, the x lines and the output state of every point.
  double seconds_classification = 0;
  /// The y and z lines and the output vertices (INT_POINT on every edge that needs one).
  double seconds_edges = 0;
  /// The cube pass and the output arrays.
  double seconds_triangulation = 0;
  /// Points of the lattice.
  std::size_t lattice_points = 0;
  /// Crossings of the meshes with lattice edges (all axes).
  std::size_t crossings = 0;
  /// Lattice points on the boundary of the lattice that are inside the
  /// result.  When it is 0 the output is closed; otherwise the output is
  /// open where the result meets the lattice boundary (or empty, if every
  /// point is inside).  It is 0 for a lattice from
  /// `Regular_lattice_3::enclosing()` (margin >= 1) around the meshes and an
  /// expression that is false outside all of them (`evaluate(0) == false`).
  std::size_t boundary_points_inside = 0;
  /// Sharp features (named parameter `sharp_features`): polygons fanned
  /// around a feature vertex, of which corners (rank 3); polygons whose
  /// normals disagree but that keep the plain triangulation (no feature point
  /// in the cube, or the fan would fold); face segments flipped to join
  /// neighbouring feature vertices; crease edges output.
  std::size_t feature_vertices = 0;
  /// Feature vertices of rank 3 (corners).
  std::size_t corner_vertices = 0;
  /// Polygons whose normals disagree by more than the feature angle but that
  /// keep the plain triangulation.
  std::size_t plain_feature_polygons = 0;
  /// Of `plain_feature_polygons`, those whose fan would have folded.
  std::size_t folded_feature_polygons = 0;
  /// Fans that only the weaker fold test accepts (features.md, "Fold
  /// tests") in the output, and the cubes given the strict test because such
  /// a fan met another triangle (each such finding costs one more run of
  /// the extraction: `extraction_runs`).
  std::size_t weak_fans = 0;
  std::size_t strict_fold_cubes = 0;
  std::size_t extraction_runs = 1;
  /// Face segments flipped to join the feature vertices of neighbouring cubes.
  std::size_t flipped_edges = 0;
  /// Flipped edges whose dihedral angle is above the feature angle: the output creases.
  std::size_t crease_edges = 0;
  /// Edges shorter than `sliver_edge_length` cells, from an edge point to
  /// another edge point or to a feature vertex, that were collapsed (see the
  /// named parameter).
  std::size_t collapsed_edges = 0;
  /// Resolution check (named parameter `resolution_check`, default true):
  /// the connected components of the inputs inside the lattice's box that
  /// were judged, and those the lattice does not resolve -- no crossing with
  /// a lattice edge, or (lattice points inside) x spacing^3 off the exact
  /// volume by more than a factor 2.  Such a component may be missing from
  /// the output, or be much too thick there.
  std::size_t checked_components = 0;
  /// The components the lattice does not resolve (see `checked_components`).
  std::vector<Marching_cubes_csg_component_report> under_resolved_components;
  /// Resolution of the result itself (same named parameter): along the
  /// lattice lines, the intervals inside or outside the result between two
  /// of its surface crossings, and those that hold no lattice point --
  /// walls thinner than a cell, missing from the output, or gaps filled in
  /// (a difference of nearly coincident solids, say).
  std::size_t result_intervals = 0;
  /// The intervals of `result_intervals` that hold no lattice point.
  std::size_t thin_result_intervals = 0;
  /// The volume of the thin intervals (line lengths times spacing^2),
  /// beside `result_line_volume`, the result's volume measured the same way,
  /// along the axis where their ratio is largest (the lines that cross a
  /// thin wall see it): a lower bound of the part the output gets wrong.
  double thin_result_volume = 0;
  /// The result's volume as the lengths of its line intervals times
  /// spacing^2, along the axis of `thin_result_volume`.
  double result_line_volume = 0;
  /// A spacing that puts lattice points in most thin intervals (half their
  /// median length), or 0 when there is none.
  double thin_result_suggested_spacing = 0;

  /// The part of the result's line volume in thin intervals,
  /// `thin_result_volume / result_line_volume` (0 when nothing was measured).
  double thin_result_fraction() const
  {
    return result_line_volume > 0 ? thin_result_volume / result_line_volume : 0;
  }

  /// Above this `thin_result_fraction()` the output is visibly wrong and a
  /// warning is added (unless an input component was already reported as
  /// under-resolved: the spacing that resolves it comes first).  Why 2 %:
  /// hull-body - hull-mask at 128 cells has 8 % thin and loses 40 % of its
  /// volume, while lines grazing a smooth surface give about 1 % at 16-32
  /// cells on pairs the output gets right.
  static constexpr double thin_result_warning_fraction = 0.02;

  /// Whether the result has enough walls or gaps thinner than a cell to be
  /// warned about (see `thin_result_warning_fraction`).
  bool has_thin_result() const
  {
    return thin_result_fraction() > thin_result_warning_fraction && thin_result_suggested_spacing > 0;
  }

  /// The result's walls or gaps that hold fewer than two lattice points
  /// across: Marching Cubes joins the points of a wall one point thick only
  /// through the cube faces its table connects, so an oblique one comes out
  /// in pieces (a ball minus a ball 1.3 spacings smaller: -3.5 % of the
  /// volume; hull-body - hull-mask at 200 cells: -7 %, with almost no
  /// interval empty).  The part of the result's line volume in such
  /// intervals, per axis, leaving out those between two faces perpendicular
  /// to the line (an axis-aligned plate one point thick, or the margin
  /// inside a clipping box, which the output gets right); the second largest
  /// of the three, since an oblique wall is sparse along two axes or three.
  double sparse_result_fraction = 0;
  /// A spacing that puts two lattice points in most of those intervals (half
  /// their median length), or 0 when there is none.
  double sparse_result_suggested_spacing = 0;

  /// Above this `sparse_result_fraction` a warning is added (unless a thin
  /// result or an under-resolved component was reported already).  Why
  /// 15 %: on 66 runs (the shared pairs, six CAD and organic meshes against
  /// moved copies at 32-256 cells, thin shells), the runs above it without
  /// another warning were thin shells that lost 3.5-31 % of their volume
  /// (a ball minus a ball 1.14 spacings smaller: 18 %; hull-body - hull-mask
  /// at 200 cells: 21 %); the highest below it lost at most 0.37 %
  /// (hull-body - hull-mask at 256 cells: 11.5 %), and no smooth or CAD pair
  /// reached 4 %.
  static constexpr double sparse_result_warning_fraction = 0.15;

  /// Whether the result has enough walls or gaps fewer than two lattice
  /// points thick to be warned about (see `sparse_result_warning_fraction`).
  bool has_sparse_result() const
  {
    return sparse_result_fraction > sparse_result_warning_fraction && sparse_result_suggested_spacing > 0;
  }
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The sharp features of a `marching_cubes_csg()` soup (named parameter
/// `sharp_feature_output(&features)`): crease edges as pairs of output vertex
/// indices (smaller first), and corner vertices.  Indices are offset like the
/// triangles'.
struct Marching_cubes_csg_features
{
  /// Crease edges, as pairs of output vertex indices (smaller first).
  std::vector<std::array<std::size_t, 2>> crease_edges;
  /// Corner vertices (rank-3 feature vertices).
  std::vector<std::size_t> corner_vertices;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_STATISTICS_H
