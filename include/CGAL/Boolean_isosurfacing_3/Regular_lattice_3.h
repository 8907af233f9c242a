// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_REGULAR_LATTICE_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_REGULAR_LATTICE_3_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The one formula for lattice coordinates.  The product is forced through a
// volatile so that it is rounded to double before the addition: a compiler
// that contracts `o + i * s` into a fused multiply-add (GCC does by default
// in GNU mode on FMA hardware) could otherwise produce a different double at
// different call sites, and the exact predicates would then see two
// different lattices.
inline double lattice_coordinate(double origin, double spacing, std::size_t i)
{
  volatile double offset = double(i) * spacing;
  return origin + offset;
}

inline std::string to_string_precise(double x)
{
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * An axis-aligned regular lattice of points: point `(i, j, k)`, `0 <= i <
 * nx`, `0 <= j < ny`, `0 <= k < nz`, is `origin + (i, j, k) * spacing`.
 *
 * Every coordinate is the double `coordinate(axis, i)`, computed by one
 * formula, `origin[axis] + double(i) * spacing`, with the product rounded
 * before the sum (never fused).  Algorithms that make exact decisions on
 * lattice points (`Lattice_classifier_3`) use exactly these doubles, so a
 * lattice point is a well-defined point with double coordinates.  The
 * constructor checks that the coordinates are strictly increasing along each
 * axis (the spacing is not lost in the rounding of the coordinates).
 *
 * The lattice is a small value type (no per-point storage).
 */
class Regular_lattice_3
{
public:
  /// The largest number of points a lattice may have (2^62), so that
  /// `linear_index()` never overflows.  The lattice itself stores nothing per
  /// point; each algorithm checks what it needs (`Lattice_classifier_3`
  /// stores the crossings, not the points, and estimates its memory before
  /// allocating).
  static constexpr std::size_t max_number_of_points = std::size_t(1) << 62;

  /// The default offset of `enclosing()`, in cells: (3 - sqrt 5) / 2, the
  /// golden section.  Without it the lattice planes would pass through the
  /// box's extreme coordinates, which are the planes of the axis-aligned
  /// faces of CAD meshes (and often of other "round" coordinates): a
  /// Marching Cubes vertex then sits on a lattice point and the output has
  /// zero-area triangles.  The golden section keeps the planes away from every
  /// coordinate at a simple rational fraction of the spacing from the box.
  static constexpr double default_offset_cells = 0.381966011250105;

  /// Points `origin + (i, j, k) * spacing`, `0 <= i < number_of_points[0]` etc.
  /// \throws Invalid_input_error if `spacing` is not positive and finite, an
  /// origin coordinate is not finite, a count is 0, or the spacing is too
  /// small for the magnitude of the coordinates (two consecutive coordinates
  /// round to the same double).
  /// \throws Lattice_too_large_error if the lattice has more than
  /// `max_number_of_points` points.
  Regular_lattice_3(const std::array<double, 3>& origin, double spacing,
                    const std::array<std::size_t, 3>& number_of_points)
    : m_origin(origin), m_spacing(spacing), m_number_of_points(number_of_points)
  {
    if(!(std::isfinite(spacing) && spacing > 0))
      throw Invalid_input_error("the lattice spacing must be positive and finite, got " +
                                internal::to_string_precise(spacing));
    for(int a = 0; a < 3; ++a)
    {
      if(!std::isfinite(origin[a]))
        throw Invalid_input_error("the lattice origin must be finite, got coordinate " +
                                  internal::to_string_precise(origin[a]) + " on axis " + axis_name(a));
      if(number_of_points[a] == 0)
        throw Invalid_input_error(std::string("the lattice needs at least one point along ") + axis_name(a));
    }
    check_size(double(number_of_points[0]) * double(number_of_points[1]) * double(number_of_points[2]),
               "");
    for(int a = 0; a < 3; ++a)
    {
      const double last = coordinate(a, number_of_points[a] - 1);
      if(!std::isfinite(last))
        throw Invalid_input_error(std::string("the lattice coordinates overflow along ") + axis_name(a));
      // Rounding is monotone, so the coordinates never decrease; they are
      // strictly increasing iff no two consecutive ones coincide.  Checking
      // them all is O(nx + ny + nz), negligible next to any use of the lattice.
      double previous = coordinate(a, 0);
      for(std::size_t i = 1; i < number_of_points[a]; ++i)
      {
        const double current = coordinate(a, i);
        if(!(current > previous))
          throw Invalid_input_error("the lattice spacing " + internal::to_string_precise(spacing) +
                                    " is below the resolution of doubles near " +
                                    internal::to_string_precise(current) + " (points " +
                                    std::to_string(i - 1) + " and " + std::to_string(i) + " along " +
                                    axis_name(a) + " have the same coordinate)");
        previous = current;
      }
    }
  }

  /// The lattice of spacing `spacing` that encloses `box` with at least
  /// `margin_cells` cells on every side: along each axis, point
  /// `margin_cells` is at or below the box minimum and the last
  /// `margin_cells + 1` points are at or above the box maximum.  With
  /// `margin_cells >= 1` the lattice boundary lies strictly outside the box,
  /// which is what makes a Marching Cubes output closed.  Point
  /// `margin_cells` is `offset_cells * spacing` below the box minimum
  /// (rounded down): the default offset keeps the box's faces off the lattice
  /// planes (see `default_offset_cells`); 0 puts a lattice plane on each
  /// box minimum.
  /// \pre `0 <= offset_cells < 1`
  /// \throws Invalid_input_error if the box is empty or not finite, or the
  /// spacing is not positive and finite (or too small for the coordinates).
  /// \throws Lattice_too_large_error beyond `max_number_of_points` points.
  static Regular_lattice_3 enclosing(const CGAL::Bbox_3& box, double spacing, std::size_t margin_cells = 1,
                                     double offset_cells = default_offset_cells)
  {
    check_box(box);
    if(!(offset_cells >= 0 && offset_cells < 1))
      throw Invalid_input_error("the lattice offset must be in [0, 1) cells, got " +
                                internal::to_string_precise(offset_cells));
    if(!(std::isfinite(spacing) && spacing > 0))
      throw Invalid_input_error("the lattice spacing must be positive and finite, got " +
                                internal::to_string_precise(spacing));
    // Size check in double first: the counts may not fit any integer type.
    double estimated_points = 1;
    for(int a = 0; a < 3; ++a)
      estimated_points *= std::floor((box.max(a) - box.min(a)) / spacing) + 2.0 * double(margin_cells) + 3.0;
    if(!(estimated_points <= double(max_number_of_points)))
      check_size(estimated_points, " with spacing " + internal::to_string_precise(spacing) + " around the box " +
                                       box_to_string(box));

    std::array<double, 3> origin;
    std::array<std::size_t, 3> counts;
    for(int a = 0; a < 3; ++a)
    {
      const double low = box.min(a), high = box.max(a);
      double o = low - (double(margin_cells) + offset_cells) * spacing;
      // Make point `margin_cells` no larger than the box minimum despite rounding.
      while(internal::lattice_coordinate(o, spacing, margin_cells) > low)
        o = std::nextafter(o, -std::numeric_limits<double>::infinity());
      if(!std::isfinite(o))
        throw Invalid_input_error("the lattice origin overflows: the box " + box_to_string(box) +
                                  " is too close to the largest double");
      // top = the smallest index whose coordinate is >= high.
      const double estimate = std::ceil((high - o) / spacing);
      std::size_t top = estimate > 0 ? std::size_t(estimate) : 0;
      while(top > 0 && internal::lattice_coordinate(o, spacing, top - 1) >= high)
        --top;
      while(internal::lattice_coordinate(o, spacing, top) < high)
        ++top;
      origin[a] = o;
      counts[a] = top + margin_cells + 1;
    }
    return Regular_lattice_3(origin, spacing, counts);
  }

  /// The lattice that encloses `box` as `enclosing()` does, with the spacing
  /// chosen so that the longest side of the box is `cells` cells long (the
  /// margin comes on top; rounding may add one cell).
  /// \throws Invalid_input_error if `cells == 0`, or the box is empty, not
  /// finite, or a single point.
  /// \throws Lattice_too_large_error as `enclosing()`.
  static Regular_lattice_3 enclosing_with_cells(const CGAL::Bbox_3& box, std::size_t cells,
                                                std::size_t margin_cells = 1,
                                                double offset_cells = default_offset_cells)
  {
    check_box(box);
    if(cells == 0)
      throw Invalid_input_error("the number of lattice cells along the longest side must be positive");
    const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    if(!(longest > 0))
      throw Invalid_input_error("the box " + box_to_string(box) +
                                " is a single point: give the lattice spacing explicitly");
    return enclosing(box, longest / double(cells), margin_cells, offset_cells);
  }

  /// The points of this lattice whose z index is in `[k_begin, k_end]`, as
  /// a lattice of their own with *the same coordinates*: its point
  /// `(i, j, k)` is point `(i, j, k_begin + k)` of this one, its coordinate
  /// `coordinate(2, k)` is `origin[2] + double(k_begin + k) * spacing`
  /// (bit for bit).  A lattice `origin + ...` starting at the first point's
  /// coordinate would round differently, and the exact predicates would see
  /// another lattice.  This is what lets a z slab of a lattice be classified
  /// on its own (`marching_cubes_csg_slab_range()`).
  /// \pre `k_begin <= k_end < number_of_points(2)`
  Regular_lattice_3 z_range(std::size_t k_begin, std::size_t k_end) const
  {
    if(!(k_begin <= k_end && k_end < m_number_of_points[2]))
      throw Invalid_input_error("the z range [" + std::to_string(k_begin) + ", " + std::to_string(k_end) +
                                "] is not within the lattice's " + std::to_string(m_number_of_points[2]) +
                                " planes");
    Regular_lattice_3 result(*this);
    result.m_first[2] += k_begin;
    result.m_number_of_points[2] = k_end - k_begin + 1;
    return result;
  }

  /// The index, in the lattice this one was cut from by `z_range()`, of
  /// this lattice's first point along `axis` (0 for a lattice of its own).
  std::size_t first_index(int axis) const { return m_first[axis]; }

  double spacing() const { return m_spacing; }
  /// The origin of the coordinate formula: for a lattice made by `z_range()`
  /// it is that of the lattice it was cut from.
  const std::array<double, 3>& origin() const { return m_origin; }
  const std::array<std::size_t, 3>& number_of_points() const { return m_number_of_points; }
  std::size_t number_of_points(int axis) const { return m_number_of_points[axis]; }
  std::size_t total_number_of_points() const
  {
    return m_number_of_points[0] * m_number_of_points[1] * m_number_of_points[2];
  }

  /// `origin[axis] + double(i) * spacing`, the product rounded first.
  /// \pre `0 <= axis < 3`; `i` may exceed the number of points (the formula extends the lattice).
  double coordinate(int axis, std::size_t i) const
  {
    return internal::lattice_coordinate(m_origin[axis], m_spacing, m_first[axis] + i);
  }

  /// Index of point `(i, j, k)` in arrays over the lattice: `i` varies fastest.
  std::size_t linear_index(std::size_t i, std::size_t j, std::size_t k) const
  {
    return i + m_number_of_points[0] * (j + m_number_of_points[1] * k);
  }

  /// The smallest `i` in `[0, number_of_points(axis)]` with
  /// `coordinate(axis, i) >= value` (`number_of_points(axis)` if there is
  /// none).  Exact: the double estimate is corrected by comparisons.
  std::size_t first_index_not_below(int axis, double value) const
  {
    const std::size_t n = m_number_of_points[axis];
    const double estimate = std::ceil((value - m_origin[axis]) / m_spacing) - double(m_first[axis]);
    std::size_t i;
    if(!(estimate > 0)) // also NaN
      i = 0;
    else if(estimate >= double(n))
      i = n;
    else
      i = std::size_t(estimate);
    while(i > 0 && coordinate(axis, i - 1) >= value)
      --i;
    while(i < n && coordinate(axis, i) < value)
      ++i;
    return i;
  }

  /// The bounding box of the lattice points.
  CGAL::Bbox_3 bbox() const
  {
    return CGAL::Bbox_3(coordinate(0, 0), coordinate(1, 0), coordinate(2, 0),
                        coordinate(0, m_number_of_points[0] - 1), coordinate(1, m_number_of_points[1] - 1),
                        coordinate(2, m_number_of_points[2] - 1));
  }

  friend bool operator==(const Regular_lattice_3& a, const Regular_lattice_3& b)
  {
    return a.m_origin == b.m_origin && a.m_spacing == b.m_spacing && a.m_number_of_points == b.m_number_of_points &&
           a.m_first == b.m_first;
  }
  friend bool operator!=(const Regular_lattice_3& a, const Regular_lattice_3& b) { return !(a == b); }

private:
  static const char* axis_name(int a) { return a == 0 ? "x" : (a == 1 ? "y" : "z"); }

  static std::string box_to_string(const CGAL::Bbox_3& box)
  {
    std::ostringstream out;
    out.precision(17);
    out << "[" << box.xmin() << ", " << box.ymin() << ", " << box.zmin() << "] - [" << box.xmax() << ", "
        << box.ymax() << ", " << box.zmax() << "]";
    return out.str();
  }

  static void check_box(const CGAL::Bbox_3& box)
  {
    for(int a = 0; a < 3; ++a)
    {
      if(!(std::isfinite(box.min(a)) && std::isfinite(box.max(a))))
        throw Invalid_input_error("the box " + box_to_string(box) + " is empty or not finite");
      if(!(box.min(a) <= box.max(a)))
        throw Invalid_input_error("the box " + box_to_string(box) + " is empty");
    }
  }

  static void check_size(double points, const std::string& context)
  {
    if(points <= double(max_number_of_points))
      return;
    std::ostringstream out;
    out.precision(3);
    out << "the lattice" << context << " would have " << points << " points; at most "
        << max_number_of_points << " (2^62) are supported: use a larger spacing";
    throw Lattice_too_large_error(out.str());
  }

  std::array<double, 3> m_origin;
  double m_spacing;
  std::array<std::size_t, 3> m_number_of_points;
  std::array<std::size_t, 3> m_first{{0, 0, 0}}; // see z_range()
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_REGULAR_LATTICE_3_H
