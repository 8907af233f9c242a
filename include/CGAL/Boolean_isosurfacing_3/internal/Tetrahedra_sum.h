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
#include <memory>
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

// Structure-of-arrays batches of triangles for the double path: the
// traversal (halfedges, index arrays) only gathers coordinates, and the
// arithmetic -- the term, its permanent, and the compensated sum in
// independent lanes -- runs over whole batches in loops the compiler
// vectorizes (SSE2 is enough: no -march needed).  The lanes are
// independent TwoSum chains, so the dependency on one running sum no longer
// serializes the loop; each lane is an error-free transformation like the
// single chain, and the lanes are merged with TwoSum as well, so the error
// bound below holds with n + lanes in place of n.
class Tetrahedra_batch_sum
{
public:
  static constexpr std::size_t batch = 128;
  static constexpr std::size_t lanes = 8;

  explicit Tetrahedra_batch_sum(double cx, double cy, double cz) : m_cx(cx), m_cy(cy), m_cz(cz)
  {
    for(std::size_t l = 0; l < lanes; ++l) m_sum[l] = m_compensation[l] = m_permanent[l] = 0;
  }

  void add(double x1, double y1, double z1, double x2, double y2, double z2, double x3, double y3, double z3)
  {
    const std::size_t k = m_fill;
    m_x1[k] = x1; m_y1[k] = y1; m_z1[k] = z1;
    m_x2[k] = x2; m_y2[k] = y2; m_z2[k] = z2;
    m_x3[k] = x3; m_y3[k] = y3; m_z3[k] = z3;
    if(++m_fill == batch)
      flush();
  }

  // A full batch of triangles given as indices into flat points (only
  // when no partial batch is pending).
  template <typename Point, typename Triangle>
  void add_batch(const Point* points, const Triangle* triangles)
  {
    for(std::size_t k = 0; k < batch; ++k)
    {
      const auto& a = points[triangles[k][0]];
      const auto& b = points[triangles[k][1]];
      const auto& c = points[triangles[k][2]];
      m_x1[k] = a[0]; m_y1[k] = a[1]; m_z1[k] = a[2];
      m_x2[k] = b[0]; m_y2[k] = b[1]; m_z2[k] = b[2];
      m_x3[k] = c[0]; m_y3[k] = c[1]; m_z3[k] = c[2];
    }
    m_fill = batch;
    flush();
  }

  // The compensated sum, the sum of the permanents and the term count.
  void finish(double& sum, double& permanents, std::size_t& count)
  {
    for(std::size_t k = m_fill; k < batch; ++k) // pad with degenerate triangles at c: zero terms
    {
      m_x1[k] = m_x2[k] = m_x3[k] = m_cx;
      m_y1[k] = m_y2[k] = m_y3[k] = m_cy;
      m_z1[k] = m_z2[k] = m_z3[k] = m_cz;
    }
    const std::size_t real = m_count + m_fill;
    if(m_fill != 0)
      flush();
    Accurate_sum<double> total;
    double compensation = 0, permanent = 0;
    for(std::size_t l = 0; l < lanes; ++l)
    {
      total.add(m_sum[l]);
      compensation += m_compensation[l];
      permanent += m_permanent[l];
    }
    total.add(compensation);
    sum = total.result();
    permanents = permanent;
    count = real + lanes;
  }

private:
  void flush()
  {
    alignas(16) double term[batch], permanent[batch];
    for(std::size_t k = 0; k < batch; ++k)
    {
      const double ax = m_x2[k] - m_x1[k], ay = m_y2[k] - m_y1[k], az = m_z2[k] - m_z1[k];
      const double bx = m_x3[k] - m_x1[k], by = m_y3[k] - m_y1[k], bz = m_z3[k] - m_z1[k];
      const double dx = m_x1[k] - m_cx, dy = m_y1[k] - m_cy, dz = m_z1[k] - m_cz;
      // |u| * |v| == |u * v| exactly, so the permanent reuses the products.
      const double p1 = ay * bz, p2 = az * by, p3 = az * bx, p4 = ax * bz, p5 = ax * by, p6 = ay * bx;
      term[k] = (p1 - p2) * dx + (p3 - p4) * dy + (p5 - p6) * dz;
      permanent[k] = (std::abs(p1) + std::abs(p2)) * std::abs(dx) + (std::abs(p3) + std::abs(p4)) * std::abs(dy) +
                     (std::abs(p5) + std::abs(p6)) * std::abs(dz);
    }
    for(std::size_t k = 0; k < batch; k += lanes)
      for(std::size_t l = 0; l < lanes; ++l)
      {
        // Knuth's TwoSum per lane (no -ffast-math: it would drop e).
        const double x = term[k + l];
        const double t = m_sum[l] + x;
        const double z = t - m_sum[l];
        const double e = (m_sum[l] - (t - z)) + (x - z);
        m_sum[l] = t;
        m_compensation[l] += e;
        m_permanent[l] += permanent[k + l];
      }
    m_count += m_fill;
    m_fill = 0;
  }

  double m_cx, m_cy, m_cz;
  alignas(16) double m_x1[batch], m_y1[batch], m_z1[batch], m_x2[batch], m_y2[batch], m_z2[batch], m_x3[batch],
      m_y3[batch], m_z3[batch];
  alignas(16) double m_sum[lanes], m_compensation[lanes], m_permanent[lanes];
  std::size_t m_fill = 0, m_count = 0;
};

// The decision of the double path: the compensated sum `s` of n terms whose
// permanents add up to `permanents`, if its certified error bound is small
// enough, else the exact sum of the terms that `for_each_coordinates` visits
// again (as 9 doubles each), rounded once.
template <typename ForEachCoordinates>
double certified_or_exact_sum(double s, double permanents, std::size_t n, double cx, double cy, double cz,
                              const ForEachCoordinates& for_each_coordinates)
{
  const double eps = std::numeric_limits<double>::epsilon() / 2;
  const double ne = double(n) * eps;
  // (n counts the lanes of Tetrahedra_batch_sum too.)
  // |term_i| <= (1 + 3 eps) permanent_i, so the permanents also bound the
  // terms' magnitudes in the summation error.  The bound is itself computed
  // in double: inflate it by (1 + 4 n eps) for the rounding of the running
  // sums and of these few operations.
  const double bound = (8 * eps * permanents + eps * std::abs(s) + 1.02 * ne * ne * permanents) * (1 + 4 * ne);
  if(std::isfinite(bound) && bound <= std::ldexp(std::abs(s), -48))
    return s / 6;

  typedef typename CGAL::internal::Exact_ring_selector<double>::Type Exact;
  Exact exact_sum(0);
  for_each_coordinates([&](double px1, double py1, double pz1, double px2, double py2, double pz2, double px3,
                           double py3, double pz3) {
    const Exact x1(px1), y1(py1), z1(pz1);
    const Exact ax = Exact(px2) - x1, ay = Exact(py2) - y1, az = Exact(pz2) - z1;
    const Exact bx = Exact(px3) - x1, by = Exact(py3) - y1, bz = Exact(pz3) - z1;
    const Exact dx = x1 - Exact(cx), dy = y1 - Exact(cy), dz = z1 - Exact(cz);
    exact_sum += (ay * bz - az * by) * dx + (az * bx - ax * bz) * dy + (ax * by - ay * bx) * dz;
  });
  return CGAL::to_double(exact_sum) / 6;
}

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

  auto batches = std::make_unique<Tetrahedra_batch_sum>(c.x, c.y, c.z);
  for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
    batches->add(x(t1), y(t1), z(t1), x(t2), y(t2), z(t2), x(t3), y(t3), z(t3));
  });
  double s, permanents;
  std::size_t n;
  batches->finish(s, permanents, n);
  return certified_or_exact_sum(s, permanents, n, c.x, c.y, c.z, [&](const auto& f) {
    for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
      f(x(t1), y(t1), z(t1), x(t2), y(t2), z(t2), x(t3), y(t3), z(t3));
    });
  });
}

// The same sum over flat arrays (points as 3 doubles, triangles as 3
// indices, all checked by the caller): the gather is three loads per corner.
template <typename PointArray, typename TriangleArray>
double sum_of_signed_tetrahedra_of_arrays(const PointArray& points, const TriangleArray& triangles, double cx,
                                          double cy, double cz)
{
  auto batches = std::make_unique<Tetrahedra_batch_sum>(cx, cy, cz);
  const auto* p = points.data();
  const auto* t = triangles.data();
  const std::size_t n_triangles = triangles.size(), batch = Tetrahedra_batch_sum::batch;
  std::size_t i = 0;
  for(; i + batch <= n_triangles; i += batch)
    batches->add_batch(p, t + i); // the whole batch in one call: no per-triangle bookkeeping
  for(; i < n_triangles; ++i)
  {
    const auto& a = p[t[i][0]];
    const auto& b = p[t[i][1]];
    const auto& c = p[t[i][2]];
    batches->add(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
  }
  double s, permanents;
  std::size_t n;
  batches->finish(s, permanents, n);
  return certified_or_exact_sum(s, permanents, n, cx, cy, cz, [&](const auto& f) {
    for(const auto& t : triangles)
    {
      const auto& a = p[t[0]];
      const auto& b = p[t[1]];
      const auto& c = p[t[2]];
      f(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
    }
  });
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
