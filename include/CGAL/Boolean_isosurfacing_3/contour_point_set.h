// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H
#define CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H

// Contouring oriented point samples (the contour-tracing assignment, [ContourTracing] in the manual's references):
// Hoppe's tangent-plane signed distance (Tangent_plane_signed_distance_3.h)
// sampled at the vertices of a regular lattice and contoured with the
// package's watertight Marching Cubes table, refined on ambiguous faces by the
// asymptotic decider.  Only cubes the surface crosses are visited.
//
// Conventions (doc/Boolean_isosurfacing_3/contouring.md):
//  * f < 0 inside (normals point out of the solid).  The seed's bit is
//    fb[k] = f(p_k) >= 0 ("above the surface" = OUTSIDE); the table's code has
//    bit k = corner k INSIDE, so  table code = ~seed code & 0xFF.  f == 0 is
//    outside, as in the seed.  Corner k sits at offset (k&1, (k>>1)&1, (k>>2)&1).
//  * The vertex on lattice edge (v_i, v_j), v_i the lower end, is
//    p = v_i + t (v_j - v_i) with t = -f(v_i) / (f(v_j) - f(v_i)) exactly as in
//    the seed; it is computed once per global lattice edge and shared by the
//    (up to 4) cubes around the edge: vertices are welded by edge id.
//  * Asymptotic decider (Nielson & Hamann 1991): on a face whose inside
//    corners are one diagonal, the bilinear interpolant's saddle value is
//    (f_a f_c - f_b f_d) / (f_a + f_c - f_b - f_d) for the diagonals (a, c),
//    (b, d); the inside corners are joined iff the saddle is inside (< 0),
//    i.e. iff f_in1 * f_in2 > f_out1 * f_out2.  It reads only the face's 4
//    values, so both cubes on a face take the same decision and the output
//    stays closed and 2-manifold (Marching_cubes_table.h).
//  * Triangles are oriented outward; the seed's normal cross(p1-p0, p2-p0)
//    points out of the object.

#include <CGAL/Boolean_isosurfacing_3/Contouring_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Contouring/Contour_on_lattice.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// Thrown by `contour_point_set` when the contour has no triangle: an empty
/// mesh is never a silent success.  `report()` tells what the traversal saw.
class Empty_contour_error : public std::runtime_error
{
public:
  explicit Empty_contour_error(const Contouring_statistics& report)
    : std::runtime_error(message(report)), m_report(report)
  {}
  const Contouring_statistics& report() const { return m_report; }

private:
  static std::string message(const Contouring_statistics& report)
  {
    return "the contour is empty: f changes sign in no usable lattice cube (cell " + std::to_string(report.cell_size) +
           ", " + std::to_string(report.visited_cubes) + " cubes visited, " + std::to_string(report.skipped_cubes) +
           " skipped for an undefined corner, " + std::to_string(report.discontinuous_cubes) +
           " for a jump of f, " + std::to_string(report.removed_closed_components) +
           " closed pieces smaller than rho removed)";
  }
  Contouring_statistics m_report;
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * The default contouring lattice of `field`: spacing `cell_size` (or the
 * longest side of the samples' bounding box / `cells_along_longest_side`,
 * or the field's default), `lattice_margin` cells around the bounding box
 * of the samples (see `contour_signed_distance()` for the defaults).
 * \throws Invalid_input_error for a non-positive or non-finite spacing, or a negative margin.
 * \throws Lattice_too_large_error if the lattice has more than
 *         `Regular_lattice_3::max_number_of_points` points.
 */
template <typename ContouringField_3, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Regular_lattice_3 contouring_lattice(const ContouringField_3& field,
                                     const NamedParameters& np = parameters::default_values())
{
  const internal::Contouring_lattice l = internal::default_contouring_lattice(field, np);
  return Regular_lattice_3(l.origin, l.r,
                           {{std::size_t(l.cells[0]) + 1, std::size_t(l.cells[1]) + 1, std::size_t(l.cells[2]) + 1}});
}


/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * Contours the zero set of `field` on `lattice`, visiting only the
 * cubes connected, through faces the surface crosses, to the cubes that
 * contain `field.points()`.  The outputs are cleared first (the package's
 * rule for every output), then receive the points and outward-oriented
 * triangles (f < 0 is inside).
 *
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: with
 *         the latter the field is evaluated on TBB's threads (so `field` must
 *         be safe to call concurrently, as `Tangent_plane_signed_distance_3`
 *         is), at the lattice points the traversal from the samples' cubes
 *         reads, one breadth-first level at a time; the traversal itself, and
 *         so the output, are the sequential ones bit for bit.
 *
 * \param lattice the domain: lattice point (i, j, k) is `lattice.coordinate()`s;
 *   `contouring_lattice(field, np)` is the default one (the named parameters
 *   `cell_size`, `cells_along_longest_side` and `lattice_margin` below are
 *   those of `contouring_lattice()`, and ignored here)
 * \param field a model of `ContouringField_3`, e.g. `Tangent_plane_signed_distance_3<K>`:
 *   `typedef Point_3` (constructible from 3 doubles, `p[a]` coordinates);
 *   `points()`: a range of `Point_3`, the seeds (the samples);
 *   `sampling_density()`, `noise_level()`: doubles (default cell size, margin, bubbles);
 *   optionally `default_cell_size()`: a double, the default lattice spacing;
 *   `operator()(const Point_3&)`: `std::optional<double>`, empty = undefined.
 * \param out_points a `std::vector`-like container of `K::Point_3`
 *        (`push_back`, `size`, `operator[]`, `erase`, `insert`)
 * \param out_triangles a `std::vector`-like container of 3-index polygons
 *        (the same, and construction from `{a, b, c}`)
 * \param np an optional sequence of named parameters among the ones listed
 *        below, then the notes on them.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction done; returning
 *       `false` cancels the run with `Operation_cancelled_error`}
 *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{`field.default_cell_size()` when the field has it, else `field.sampling_density() / 3`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{with Hoppe's f alone (`consistent_signs(false)`): a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{consistent_signs}
 *     \cgalParamDescription{one consistent value per lattice point, the field's `consistent_value()` (Hoppe's f where the winding number of the samples does not contradict it): no cube is skipped and the contour is closed and 2-manifold, then cut open only across openings wider than `maximum_hole_size`; `false` gives Hoppe's f alone (cubes with an undefined corner or a jump of f skipped, holes up to `maximum_hole_size` filled)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true` when the field has `consistent_value()` and `distance_to_samples()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{with consistent signs: the widest opening of the samples that stays closed (a piece of the contour farther than rho + delta from every sample and reaching farther than half of it is cut away); with Hoppe's f alone: the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{max(6 (rho + delta), the samples' bounding-box diagonal / 5) with consistent signs, 2 rho otherwise}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * Notes on the named parameters (`Boolean_isosurfacing::parameters::`):
 *  - `cell_size(r)`: lattice spacing;
 *  - `cells_along_longest_side(N)`: r = longest bounding-box side / N
 *    (ignored when `cell_size` is given);
 *  - default r = `field.default_cell_size()` when the field has it, else
 *    sampling_density / 3 (for Tangent_plane_signed_distance_3, a third of
 *    the *estimated* rho, even when rho is given),
 *    about 1.25 times the mean sample spacing: finer lattices only resolve
 *    the facets of the piecewise-planar f, coarser ones lose detail;
 *  - `maximum_jump(j)`: a cube with a sign-changing edge along which f
 *    changes by more than j is a discontinuity of f, not a surface, and is
 *    skipped (default 3 r + 2 delta; `std::numeric_limits<double>::infinity()`
 *    gives Hoppe's plain rule);
 *  - `minimum_closed_component_size(s)`: closed pieces of the output (each
 *    edge in two of their triangles) whose bounding box has a diagonal below
 *    s are removed: the "bubbles" Hoppe's f leaves in concave regions, around
 *    one or two lattice points.  Default rho (`field.sampling_density()`):
 *    a rho-dense sample cannot witness a smaller closed piece; 0 keeps all;
 *  - `lattice_margin(m)`: cells added around the bounding box of the samples
 *    (default ceil((rho + delta) / r) + 2, so that the traversal ends at
 *    undefined corners before it reaches the lattice border).
 * \throws Invalid_input_error a non-positive or non-finite r, or more than
 *         2^20 lattice cells along an axis.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename ContouringField_3, typename PointOutRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Contouring_statistics contour_signed_distance(const Regular_lattice_3& lattice, const ContouringField_3& field,
                                              PointOutRange& out_points, TriangleRange& out_triangles,
                                              const NamedParameters& np = parameters::default_values())
{
  internal::check_concurrency_tag<ConcurrencyTag>();
  out_points.clear();
  out_triangles.clear();
  return internal::contour_on_lattice<ConcurrencyTag>(internal::to_contouring_lattice(lattice), field, out_points,
                                                      out_triangles, np);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * Points (+ optional normals) to an outward-oriented triangle soup:
 * `Tangent_plane_signed_distance_3` then `contour_signed_distance()`.
 *
 * \tparam ConcurrencyTag as for `contour_signed_distance()`; it also runs the
 *         k-NN queries and plane fits of the field on TBB's threads
 *         (`Tangent_plane_signed_distance_3<Geom_traits, ConcurrencyTag>`)
 * \param lattice the domain (e.g. `contouring_lattice()` of the samples' field)
 * \param points the samples
 * \param out_points, out_triangles the output soup, cleared first
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{point_map}
 *     \cgalParamDescription{the point of each element of `points`}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Point_3`} \cgalParamDefault{`CGAL::Identity_property_map`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{normal_map}
 *     \cgalParamDescription{the (roughly) outward normal of each sample, used only to orient the tangent planes}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Vector_3`} \cgalParamDefault{none: the planes are oriented along a minimum spanning tree}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_neighbors}
 *     \cgalParamDescription{k, the size of each neighbourhood (the sample itself included), from 3 to 1024}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{15}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sampling_density}
 *     \cgalParamDescription{Hoppe's rho, the radius of the largest disk on the surface free of samples}
 *     \cgalParamType{`double`} \cgalParamDefault{1.5 sqrt(15 / k) times the median distance to the k-th nearest neighbour}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{noise_level}
 *     \cgalParamDescription{Hoppe's delta}
 *     \cgalParamType{`double`} \cgalParamDefault{twice the median RMS distance of a neighbourhood to its PCA plane}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{rho / 3 with the *estimated* rho: about 1.25 times the mean sample spacing}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{with Hoppe's f alone (`consistent_signs(false)`): a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{consistent_signs}
 *     \cgalParamDescription{one consistent value per lattice point, the field's `consistent_value()` (Hoppe's f where the winding number of the samples does not contradict it): no cube is skipped and the contour is closed and 2-manifold, then cut open only across openings wider than `maximum_hole_size`; `false` gives Hoppe's f alone (cubes with an undefined corner or a jump of f skipped, holes up to `maximum_hole_size` filled)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true` when the field has `consistent_value()` and `distance_to_samples()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{with consistent signs: the widest opening of the samples that stays closed (a piece of the contour farther than rho + delta from every sample and reaching farther than half of it is cut away); with Hoppe's f alone: the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{max(6 (rho + delta), the samples' bounding-box diagonal / 5) with consistent signs, 2 rho otherwise}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 * \returns the contouring statistics.
 * \throws Empty_contour_error when no triangle comes out.
 * \throws Operation_cancelled_error when the `callback` named parameter returns `false`.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename PointRange, typename PointOutRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::Is_named_function_parameters<TriangleRange>::value>>
Contouring_statistics contour_point_set(const Regular_lattice_3& lattice, const PointRange& points,
                                        PointOutRange& out_points, TriangleRange& out_triangles,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  const Tangent_plane_signed_distance_3<Geom_traits, ConcurrencyTag> field(points, np);
  const Contouring_statistics report =
      contour_signed_distance<ConcurrencyTag>(lattice, field, out_points, out_triangles, np);
  if(report.empty_output)
    throw Empty_contour_error(report);
  return report;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * As above, into a `MutableFaceGraph` (e.g. `Surface_mesh`), which is cleared
 * first (the package's rule for every output), with the same named parameters.  With consistent signs (the
 * default) no cube is skipped: the soup is a closed 2-manifold by construction
 * (the table is watertight), cut open only across openings of the samples
 * wider than `maximum_hole_size`, along simple border loops.  With Hoppe's f
 * alone, skipped cubes leave holes, and two
 * holes can pinch a vertex (two skipped cubes diagonal around a lattice edge):
 * such vertices are duplicated (PMP::orient_polygon_soup) so that the mesh is
 * a valid, still consistently oriented, surface with border.
 *
 * \param lattice the domain
 * \param points the samples
 * \param mesh the output (cleared first)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{point_map}
 *     \cgalParamDescription{the point of each element of `points`}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Point_3`} \cgalParamDefault{`CGAL::Identity_property_map`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{normal_map}
 *     \cgalParamDescription{the (roughly) outward normal of each sample, used only to orient the tangent planes}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Vector_3`} \cgalParamDefault{none: the planes are oriented along a minimum spanning tree}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_neighbors}
 *     \cgalParamDescription{k, the size of each neighbourhood (the sample itself included), from 3 to 1024}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{15}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sampling_density}
 *     \cgalParamDescription{Hoppe's rho, the radius of the largest disk on the surface free of samples}
 *     \cgalParamType{`double`} \cgalParamDefault{1.5 sqrt(15 / k) times the median distance to the k-th nearest neighbour}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{noise_level}
 *     \cgalParamDescription{Hoppe's delta}
 *     \cgalParamType{`double`} \cgalParamDefault{twice the median RMS distance of a neighbourhood to its PCA plane}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{rho / 3 with the *estimated* rho}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{with Hoppe's f alone (`consistent_signs(false)`): a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{consistent_signs}
 *     \cgalParamDescription{one consistent value per lattice point, the field's `consistent_value()` (Hoppe's f where the winding number of the samples does not contradict it): no cube is skipped and the contour is closed and 2-manifold, then cut open only across openings wider than `maximum_hole_size`; `false` gives Hoppe's f alone (cubes with an undefined corner or a jump of f skipped, holes up to `maximum_hole_size` filled)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true` when the field has `consistent_value()` and `distance_to_samples()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{with consistent signs: the widest opening of the samples that stays closed (a piece of the contour farther than rho + delta from every sample and reaching farther than half of it is cut away); with Hoppe's f alone: the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{max(6 (rho + delta), the samples' bounding-box diagonal / 5) with consistent signs, 2 rho otherwise}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename PointRange, typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<internal::Is_named_function_parameters<NamedParameters>::value>>
Contouring_statistics contour_point_set(const Regular_lattice_3& lattice, const PointRange& points, PolygonMesh& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  std::vector<typename Geom_traits::Point_3> soup_points;
  std::vector<std::array<std::size_t, 3>> soup_triangles;
  const Contouring_statistics report =
      contour_point_set<ConcurrencyTag>(lattice, points, soup_points, soup_triangles, np);
  internal::contour_soup_to_mesh(soup_points, soup_triangles, mesh);
  return report;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H
