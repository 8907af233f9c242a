// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H

#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>

#include <CGAL/Number_types/internal/Exact_type_selector.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The sum over triangles (t1, t2, t3) of the signed volume of the
// tetrahedron (c, t1, t2, t3): the Surveyor's formula.
//
// `for_each_triangle(f)` must call `f(t1, t2, t3)` for every triangle; it may
// be called twice (see below), so it must visit the same triangles each time.
//
// Double coordinates (the common case) are summed with a *certified* error
// bound, in the manner of CGAL's filtered predicates:
//  1. each term 6 vol = n . (t1 - c), n = (t2 - t1) x (t3 - t1), is evaluated
//     in double together with its permanent (the same expression on absolute
//     values), which bounds its rounding error as in Shewchuk's orient3d
//     (|error| <= (7 eps + 56 eps^2) * permanent, eps = 2^-53);
//  2. the terms are added with compensated summation, whose own error is
//     bounded by eps |S| + (n eps)^2 sum |term_i| (Ogita, Rump, Oishi 2005);
//  3. if the total bound is at most 2^-48 |S| the double result is returned
//     (relative error below 4e-15), otherwise every term is recomputed and
//     added exactly (CGAL's exact ring type for doubles, Mpzf or Gmpzf) and
//     the exact sum is rounded once.  The fallback only runs for badly
//     conditioned inputs: sums that cancel (volume near zero, e.g. coincident
//     opposite shells) or many sliver faces far from the reference point.
// Other number types (exact kernels) are summed with `Accurate_sum`, whose
// cascade keeps lazy-evaluation DAGs shallow.
template <typename Point_3>
struct Reference_point
{
  double x, y, z;     // the centroid, rounded to double
  Point_3 point;      // the same point as a traits point
};

template <typename GeomTraits, typename ForEachTriangle>
double sum_of_signed_tetrahedra(const GeomTraits& gt,
                                const Reference_point<typename GeomTraits::Point_3>& c,
                                const ForEachTriangle& for_each_triangle,
                                std::true_type /* FT is double */)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const auto x = gt.compute_x_3_object();
  const auto y = gt.compute_y_3_object();
  const auto z = gt.compute_z_3_object();

  Accurate_sum<double> sum;
  double permanents = 0;
  std::size_t n = 0;
  for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
    const double x1 = x(t1), y1 = y(t1), z1 = z(t1);
    const double ax = x(t2) - x1, ay = y(t2) - y1, az = z(t2) - z1;
    const double bx = x(t3) - x1, by = y(t3) - y1, bz = z(t3) - z1;
    const double dx = x1 - c.x, dy = y1 - c.y, dz = z1 - c.z;
    sum.add((ay * bz - az * by) * dx + (az * bx - ax * bz) * dy + (ax * by - ay * bx) * dz);
    permanents += (std::abs(ay) * std::abs(bz) + std::abs(az) * std::abs(by)) * std::abs(dx) +
                  (std::abs(az) * std::abs(bx) + std::abs(ax) * std::abs(bz)) * std::abs(dy) +
                  (std::abs(ax) * std::abs(by) + std::abs(ay) * std::abs(bx)) * std::abs(dz);
    ++n;
  });

  const double eps = std::numeric_limits<double>::epsilon() / 2;
  const double s = sum.result();
  const double ne = double(n) * eps;
  // |term_i| <= (1 + 3 eps) permanent_i, so the permanents also bound the
  // terms' magnitudes in the summation error.  The bound is itself computed
  // in double: inflate it by (1 + 4 n eps) for the rounding of the running
  // sums and of these few operations.
  const double bound = (8 * eps * permanents + eps * std::abs(s) + 1.02 * ne * ne * permanents) * (1 + 4 * ne);
  if(std::isfinite(bound) && bound <= std::ldexp(std::abs(s), -48))
    return s / 6;

  typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
  Exact exact_sum(0);
  for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
    const Exact x1(x(t1)), y1(y(t1)), z1(z(t1));
    const Exact ax = Exact(x(t2)) - x1, ay = Exact(y(t2)) - y1, az = Exact(z(t2)) - z1;
    const Exact bx = Exact(x(t3)) - x1, by = Exact(y(t3)) - y1, bz = Exact(z(t3)) - z1;
    const Exact dx = x1 - Exact(c.x), dy = y1 - Exact(c.y), dz = z1 - Exact(c.z);
    exact_sum += (ay * bz - az * by) * dx + (az * bx - ax * bz) * dy + (ax * by - ay * bx) * dz;
  });
  return CGAL::to_double(exact_sum) / 6;
}

template <typename GeomTraits, typename ForEachTriangle>
typename GeomTraits::FT sum_of_signed_tetrahedra(const GeomTraits& gt,
                                                 const Reference_point<typename GeomTraits::Point_3>& c,
                                                 const ForEachTriangle& for_each_triangle,
                                                 std::false_type /* FT is not double */)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const auto volume = gt.compute_volume_3_object();
  Accurate_sum<typename GeomTraits::FT> sum;
  // vol(c, t1, t2, t3) = -vol(t1, t2, t3, c): this order makes kernels cross
  // the short edge vectors t2 - t1, t3 - t1, as the double path does.
  for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
    sum.add(-volume(t1, t2, t3, c.point));
  });
  return sum.result();
}

template <typename GeomTraits, typename ForEachTriangle>
typename GeomTraits::FT sum_of_signed_tetrahedra(const GeomTraits& gt,
                                                 const Reference_point<typename GeomTraits::Point_3>& c,
                                                 const ForEachTriangle& for_each_triangle)
{
  return sum_of_signed_tetrahedra(gt, c, for_each_triangle,
                                  std::is_same<typename GeomTraits::FT, double>());
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H
