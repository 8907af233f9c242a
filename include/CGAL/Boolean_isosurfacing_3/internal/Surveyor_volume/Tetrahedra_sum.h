// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H

#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>

#include <CGAL/Number_types/internal/Exact_type_selector.h>
#include <CGAL/number_utils.h>
#include <CGAL/use.h>

#include <cmath>
#include <cstdint>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// The same four lanes on 256-bit AVX registers where the processor has them,
// chosen at run time: the default build targets SSE2 only (no -march).
#if defined(__SSE2__) && defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX__)
#define CGAL_BOOLEAN_ISOSURFACING_AVX_DISPATCH 1
#include <immintrin.h>
#endif

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

// The double path's arithmetic on two triangles at a time (SSE2, which
// every x86-64 has: no -march needed), or on four at a time with AVX where
// the processor has it (chosen at run time; same lanes, same result bit for
// bit; on a 1.2M torus 0.67x the time of a plain loop, SSE2 alone 1.07x).
// Each corner is given as a pointer to its three doubles; the two triangles' coordinates are gathered straight
// into the halves of SSE registers, so nothing is stored to a buffer and
// read back.  For each triangle it computes the term 6 vol = n . (t1 - c),
// n = (t2 - t1) x (t3 - t1), its permanent (the same expression on absolute
// values, which bounds its rounding error), and adds the term to one of two
// independent TwoSum chains of two lanes each (4 lanes), so that the add
// latency does not serialize the loop.  Exactly the operations, in the same
// order, of the scalar code below: the same terms, bit for bit.
class Tetrahedra_pair_sum
{
public:
  static constexpr std::size_t lanes = 4;

  // `allow_avx` = false keeps the SSE2 code even where AVX is available (the
  // tests compare the two).
  Tetrahedra_pair_sum(double cx, double cy, double cz, bool allow_avx = true) : m_c{cx, cy, cz}
  {
#if defined(CGAL_BOOLEAN_ISOSURFACING_AVX_DISPATCH)
    m_avx = allow_avx && has_avx();
#else
    CGAL_USE(allow_avx);
#endif
#if defined(__SSE2__)
    m_cx = _mm_set1_pd(cx);
    m_cy = _mm_set1_pd(cy);
    m_cz = _mm_set1_pd(cz);
    m_s[0] = m_s[1] = m_e[0] = m_e[1] = m_q[0] = m_q[1] = _mm_setzero_pd();
#else
    for(std::size_t l = 0; l < lanes; ++l) m_s[l] = m_e[l] = m_q[l] = 0;
#endif
  }

  // `corners(i, k)` is a pointer to the 3 coordinates of corner k of
  // triangle i < n.
  template <typename Corners>
  void add(std::size_t n, const Corners& corners)
  {
    std::size_t i = 0;
#if defined(CGAL_BOOLEAN_ISOSURFACING_AVX_DISPATCH)
    if(m_avx)
      i = add_quads_avx(n, corners);
#endif
    for(; i + 4 <= n; i += 4)
    {
      add_pair(0, corners(i, 0), corners(i, 1), corners(i, 2), corners(i + 1, 0), corners(i + 1, 1), corners(i + 1, 2));
      add_pair(1, corners(i + 2, 0), corners(i + 2, 1), corners(i + 2, 2), corners(i + 3, 0), corners(i + 3, 1),
               corners(i + 3, 2));
    }
    for(; i < n; ++i) // degenerate triangles at c as partners: zero terms, zero permanents
      add_pair(0, corners(i, 0), corners(i, 1), corners(i, 2), m_c, m_c, m_c);
    m_count += n;
  }

  // The compensated sum, the sum of the permanents and the number of terms
  // the bound must count (the terms plus the lanes merged at the end).
  void finish(double& sum, double& permanents, std::size_t& count) const
  {
    double s[lanes], e[lanes], q[lanes];
#if defined(__SSE2__)
    _mm_storeu_pd(s, m_s[0]);
    _mm_storeu_pd(s + 2, m_s[1]);
    _mm_storeu_pd(e, m_e[0]);
    _mm_storeu_pd(e + 2, m_e[1]);
    _mm_storeu_pd(q, m_q[0]);
    _mm_storeu_pd(q + 2, m_q[1]);
#else
    for(std::size_t l = 0; l < lanes; ++l) s[l] = m_s[l], e[l] = m_e[l], q[l] = m_q[l];
#endif
    Accurate_sum<double> total;
    double compensation = 0, permanent = 0;
    for(std::size_t l = 0; l < lanes; ++l)
    {
      total.add(s[l]);
      compensation += e[l];
      permanent += q[l];
    }
    total.add(compensation);
    sum = total.result();
    permanents = permanent;
    count = m_count + lanes;
  }

private:
#if defined(CGAL_BOOLEAN_ISOSURFACING_AVX_DISPATCH)
  static bool has_avx()
  {
    static const bool avx = __builtin_cpu_supports("avx");
    return avx;
  }

  // Triangles i, i+1, i+2, i+3 on the lanes of one 256-bit register, whose
  // halves are the two SSE chains: lane for lane the operations of add_pair(),
  // so the sum is bit for bit the SSE2 path's.  No FMA (it would change the
  // terms).  Returns how many triangles it added (a multiple of 4).
  template <typename Corners>
  __attribute__((target("avx"))) std::size_t add_quads_avx(std::size_t n, const Corners& corners)
  {
    const __m256d cx = _mm256_set1_pd(m_c[0]), cy = _mm256_set1_pd(m_c[1]), cz = _mm256_set1_pd(m_c[2]);
    const __m256d sign = _mm256_set1_pd(-0.0);
    __m256d s = _mm256_insertf128_pd(_mm256_castpd128_pd256(m_s[0]), m_s[1], 1);
    __m256d es = _mm256_insertf128_pd(_mm256_castpd128_pd256(m_e[0]), m_e[1], 1);
    __m256d qs = _mm256_insertf128_pd(_mm256_castpd128_pd256(m_q[0]), m_q[1], 1);
    std::size_t i = 0;
    for(; i + 4 <= n; i += 4)
    {
      const double* c[4][3];
      for(int t = 0; t < 4; ++t)
        for(int k = 0; k < 3; ++k)
          c[t][k] = corners(i + std::size_t(t), k);
#define CGAL_BISO_GATHER(k, d) _mm256_set_pd(c[3][k][d], c[2][k][d], c[1][k][d], c[0][k][d])
      const __m256d x1 = CGAL_BISO_GATHER(0, 0), y1 = CGAL_BISO_GATHER(0, 1), z1 = CGAL_BISO_GATHER(0, 2);
      const __m256d ax = _mm256_sub_pd(CGAL_BISO_GATHER(1, 0), x1), ay = _mm256_sub_pd(CGAL_BISO_GATHER(1, 1), y1),
                    az = _mm256_sub_pd(CGAL_BISO_GATHER(1, 2), z1);
      const __m256d bx = _mm256_sub_pd(CGAL_BISO_GATHER(2, 0), x1), by = _mm256_sub_pd(CGAL_BISO_GATHER(2, 1), y1),
                    bz = _mm256_sub_pd(CGAL_BISO_GATHER(2, 2), z1);
      const __m256d dx = _mm256_sub_pd(x1, cx), dy = _mm256_sub_pd(y1, cy), dz = _mm256_sub_pd(z1, cz);
      const __m256d p1 = _mm256_mul_pd(ay, bz), p2 = _mm256_mul_pd(az, by), p3 = _mm256_mul_pd(az, bx),
                    p4 = _mm256_mul_pd(ax, bz), p5 = _mm256_mul_pd(ax, by), p6 = _mm256_mul_pd(ay, bx);
      const __m256d term =
          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(p1, p2), dx), _mm256_mul_pd(_mm256_sub_pd(p3, p4), dy)),
                        _mm256_mul_pd(_mm256_sub_pd(p5, p6), dz));
#define CGAL_BISO_ABS(v) _mm256_andnot_pd(sign, v)
      const __m256d permanent = _mm256_add_pd(
          _mm256_add_pd(_mm256_mul_pd(_mm256_add_pd(CGAL_BISO_ABS(p1), CGAL_BISO_ABS(p2)), CGAL_BISO_ABS(dx)),
                        _mm256_mul_pd(_mm256_add_pd(CGAL_BISO_ABS(p3), CGAL_BISO_ABS(p4)), CGAL_BISO_ABS(dy))),
          _mm256_mul_pd(_mm256_add_pd(CGAL_BISO_ABS(p5), CGAL_BISO_ABS(p6)), CGAL_BISO_ABS(dz)));
#undef CGAL_BISO_ABS
#undef CGAL_BISO_GATHER
      const __m256d t = _mm256_add_pd(s, term);
      const __m256d z = _mm256_sub_pd(t, s);
      const __m256d e = _mm256_add_pd(_mm256_sub_pd(s, _mm256_sub_pd(t, z)), _mm256_sub_pd(term, z));
      s = t;
      es = _mm256_add_pd(es, e);
      qs = _mm256_add_pd(qs, permanent);
    }
    m_s[0] = _mm256_castpd256_pd128(s);
    m_s[1] = _mm256_extractf128_pd(s, 1);
    m_e[0] = _mm256_castpd256_pd128(es);
    m_e[1] = _mm256_extractf128_pd(es, 1);
    m_q[0] = _mm256_castpd256_pd128(qs);
    m_q[1] = _mm256_extractf128_pd(qs, 1);
    _mm256_zeroupper();
    return i;
  }
#endif
#if defined(__SSE2__)
  static __m128d gather(const double* a, const double* b) { return _mm_loadh_pd(_mm_load_sd(a), b); }
  static __m128d abs(__m128d v) { return _mm_andnot_pd(_mm_set1_pd(-0.0), v); }

  void add_pair(int chain, const double* a1, const double* a2, const double* a3, const double* b1, const double* b2,
                const double* b3)
  {
    const __m128d x1 = gather(a1, b1), y1 = gather(a1 + 1, b1 + 1), z1 = gather(a1 + 2, b1 + 2);
    const __m128d ax = _mm_sub_pd(gather(a2, b2), x1), ay = _mm_sub_pd(gather(a2 + 1, b2 + 1), y1),
                  az = _mm_sub_pd(gather(a2 + 2, b2 + 2), z1);
    const __m128d bx = _mm_sub_pd(gather(a3, b3), x1), by = _mm_sub_pd(gather(a3 + 1, b3 + 1), y1),
                  bz = _mm_sub_pd(gather(a3 + 2, b3 + 2), z1);
    const __m128d dx = _mm_sub_pd(x1, m_cx), dy = _mm_sub_pd(y1, m_cy), dz = _mm_sub_pd(z1, m_cz);
    const __m128d p1 = _mm_mul_pd(ay, bz), p2 = _mm_mul_pd(az, by), p3 = _mm_mul_pd(az, bx),
                  p4 = _mm_mul_pd(ax, bz), p5 = _mm_mul_pd(ax, by), p6 = _mm_mul_pd(ay, bx);
    const __m128d term = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_sub_pd(p1, p2), dx), _mm_mul_pd(_mm_sub_pd(p3, p4), dy)),
                                    _mm_mul_pd(_mm_sub_pd(p5, p6), dz));
    const __m128d permanent =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_add_pd(abs(p1), abs(p2)), abs(dx)),
                              _mm_mul_pd(_mm_add_pd(abs(p3), abs(p4)), abs(dy))),
                   _mm_mul_pd(_mm_add_pd(abs(p5), abs(p6)), abs(dz)));
    // Knuth's TwoSum (no -ffast-math: it would drop e).
    const __m128d s = m_s[chain];
    const __m128d t = _mm_add_pd(s, term);
    const __m128d z = _mm_sub_pd(t, s);
    const __m128d e = _mm_add_pd(_mm_sub_pd(s, _mm_sub_pd(t, z)), _mm_sub_pd(term, z));
    m_s[chain] = t;
    m_e[chain] = _mm_add_pd(m_e[chain], e);
    m_q[chain] = _mm_add_pd(m_q[chain], permanent);
  }

  __m128d m_cx, m_cy, m_cz;
  __m128d m_s[2], m_e[2], m_q[2];
#else
  void add_one(std::size_t l, const double* a, const double* b, const double* c)
  {
    const double ax = b[0] - a[0], ay = b[1] - a[1], az = b[2] - a[2];
    const double bx = c[0] - a[0], by = c[1] - a[1], bz = c[2] - a[2];
    const double dx = a[0] - m_c[0], dy = a[1] - m_c[1], dz = a[2] - m_c[2];
    const double p1 = ay * bz, p2 = az * by, p3 = az * bx, p4 = ax * bz, p5 = ax * by, p6 = ay * bx;
    const double term = (p1 - p2) * dx + (p3 - p4) * dy + (p5 - p6) * dz;
    const double permanent = (std::abs(p1) + std::abs(p2)) * std::abs(dx) + (std::abs(p3) + std::abs(p4)) * std::abs(dy) +
                             (std::abs(p5) + std::abs(p6)) * std::abs(dz);
    const double t = m_s[l] + term;
    const double z = t - m_s[l];
    m_e[l] += (m_s[l] - (t - z)) + (term - z);
    m_s[l] = t;
    m_q[l] += permanent;
  }
  void add_pair(int chain, const double* a1, const double* a2, const double* a3, const double* b1, const double* b2,
                const double* b3)
  {
    add_one(std::size_t(2 * chain), a1, a2, a3);
    add_one(std::size_t(2 * chain + 1), b1, b2, b3);
  }

  double m_s[lanes], m_e[lanes], m_q[lanes];
#endif
  double m_c[3];
  std::size_t m_count = 0;
#if defined(CGAL_BOOLEAN_ISOSURFACING_AVX_DISPATCH)
  bool m_avx = false;
#endif
};

// The middle tier of the double path: the same terms, permanents and
// compensated sum in `long double`, where it has more digits than double
// (x87's 64 bits on x86-64: 2^11 times tighter bounds).  A rotated, thin-walled
// CAD part has permanents 10-20 times its volume, which fails the double
// bound (it needs them under 4 times) but passes this one (under ~8000
// times), at a few ns a term instead of the exact sum's ~1 us.  Returns false,
// doing nothing, where long double is no wider than double; otherwise sets
// `result` and returns true when the bound certifies it: the bound of the
// double path with long double's unit roundoff, at most 2^-49 |s|, so that
// the final rounding to double keeps the relative error below 2^-48.
template <typename ForEachCoordinates>
bool certified_extended_sum(std::size_t n, double cx, double cy, double cz,
                            const ForEachCoordinates& for_each_coordinates, double& result)
{
  typedef long double Wide;
  if(std::numeric_limits<Wide>::digits <= std::numeric_limits<double>::digits)
    return false;
  // The bound assumes long double's own precision; x87's precision control
  // can be set lower (to 53 or 24 bits) by other code in the process.  Then
  // 1 + epsilon rounds to 1 in an addition made at run time (the volatile
  // keeps the compiler from folding it).
  volatile Wide one = 1;
  if(!(one + std::numeric_limits<Wide>::epsilon() > Wide(1)))
    return false;
  Wide s = 0, e = 0, permanents = 0;
  const Wide wcx = cx, wcy = cy, wcz = cz;
  for_each_coordinates([&](double px1, double py1, double pz1, double px2, double py2, double pz2, double px3,
                           double py3, double pz3) {
    const Wide x1 = px1, y1 = py1, z1 = pz1;
    const Wide ax = Wide(px2) - x1, ay = Wide(py2) - y1, az = Wide(pz2) - z1;
    const Wide bx = Wide(px3) - x1, by = Wide(py3) - y1, bz = Wide(pz3) - z1;
    const Wide dx = x1 - wcx, dy = y1 - wcy, dz = z1 - wcz;
    const Wide p1 = ay * bz, p2 = az * by, p3 = az * bx, p4 = ax * bz, p5 = ax * by, p6 = ay * bx;
    const Wide term = (p1 - p2) * dx + (p3 - p4) * dy + (p5 - p6) * dz;
    permanents += (std::fabs(p1) + std::fabs(p2)) * std::fabs(dx) + (std::fabs(p3) + std::fabs(p4)) * std::fabs(dy) +
                  (std::fabs(p5) + std::fabs(p6)) * std::fabs(dz);
    const Wide t = s + term;
    const Wide z = t - s;
    e += (s - (t - z)) + (term - z);
    s = t;
  });
  const Wide sum = s + e;
  const Wide u = std::numeric_limits<Wide>::epsilon() / 2;
  const Wide nu = Wide(n) * u;
  const Wide bound = (8 * u * permanents + u * std::fabs(sum) + Wide(1.02) * nu * nu * permanents) * (1 + 4 * nu);
  if(!(std::isfinite(bound) && bound <= std::ldexp(std::fabs(sum), -49)))
    return false;
  result = double(sum / 6);
  return true;
}

// The decision of the double path: the compensated sum `s` of n terms whose
// permanents add up to `permanents`, if its certified error bound is small
// enough; else the same sum in long double (certified_extended_sum()), if its
// bound is; else the exact sum of the terms that `for_each_coordinates`
// visits again (as 9 doubles each), rounded once.
template <typename ForEachCoordinates>
double certified_or_exact_sum(double s, double permanents, std::size_t n, double cx, double cy, double cz,
                              const ForEachCoordinates& for_each_coordinates)
{
  const double eps = std::numeric_limits<double>::epsilon() / 2;
  const double ne = double(n) * eps;
  // (n counts the lanes of Tetrahedra_pair_sum too.)
  // |term_i| <= (1 + 3 eps) permanent_i, so the permanents also bound the
  // terms' magnitudes in the summation error.  The bound is itself computed
  // in double: inflate it by (1 + 4 n eps) for the rounding of the running
  // sums and of these few operations.
  const double bound = (8 * eps * permanents + eps * std::abs(s) + 1.02 * ne * ne * permanents) * (1 + 4 * ne);
  if(std::isfinite(bound) && bound <= std::ldexp(std::abs(s), -48))
    return s / 6;

  double extended = 0;
  if(certified_extended_sum(n, cx, cy, cz, for_each_coordinates, extended))
    return extended;

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

// Whether the traits' accessors return a point's coordinates by reference,
// and whether those are three doubles side by side (as in Epick's points):
// the pair kernel can then read them where they are.
template <typename GeomTraits>
constexpr bool returns_coordinate_references()
{
  typedef typename GeomTraits::Point_3 Point_3;
  return std::is_lvalue_reference<decltype(
      std::declval<const GeomTraits&>().compute_x_3_object()(std::declval<const Point_3&>()))>::value;
}

template <typename GeomTraits>
bool has_adjacent_double_coordinates(const GeomTraits& gt)
{
  const auto x = gt.compute_x_3_object();
  const auto y = gt.compute_y_3_object();
  const auto z = gt.compute_z_3_object();
  const typename GeomTraits::Point_3 probe = gt.construct_point_3_object()(0, 0, 0);
  return &y(probe) == &x(probe) + 1 && &z(probe) == &x(probe) + 2;
}

// `PointsOutliveTheVisit`: the points that `for_each_triangle` passes stay
// where they are until the sum is done (references into the mesh, not
// temporaries), so the traversal may keep pointers to them.
template <bool PointsOutliveTheVisit = false, typename GeomTraits, typename ForEachTriangle>
double sum_of_signed_tetrahedra(const GeomTraits& gt,
                                const Reference_point<typename GeomTraits::Point_3>& c,
                                const ForEachTriangle& for_each_triangle,
                                std::true_type /* FT is double */)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const auto x = gt.compute_x_3_object();
  const auto y = gt.compute_y_3_object();
  const auto z = gt.compute_z_3_object();

  // The traversal only records each triangle's corners in a small buffer
  // that stays in L1; the pair kernel then runs over the buffer.  Where the
  // points stay put, it records pointers to them and prefetches them: 3
  // stores a triangle instead of 9, and the kernel's loads hit the cache
  // (with the border checks settled by counts, 0.70-0.78x the time of
  // surveyor_volume on a Surface_mesh).  Otherwise it copies the coordinates.
  constexpr std::size_t batch = 64;
  Tetrahedra_pair_sum sum(c.x, c.y, c.z);
  // `record(slot, t1, t2, t3)` stores a triangle in the buffer that
  // `corners` reads; the kernel runs on each full buffer.
  const auto add_in_batches = [&](const auto& record, const auto& corners) {
    std::size_t fill = 0;
    for_each_triangle([&](const Point_3& t1, const Point_3& t2, const Point_3& t3) {
      record(fill, t1, t2, t3);
      if(++fill == batch)
      {
        sum.add(batch, corners);
        fill = 0;
      }
    });
    sum.add(fill, corners);
  };
  bool by_pointer = false;
  if constexpr(PointsOutliveTheVisit && returns_coordinate_references<GeomTraits>())
  {
    by_pointer = has_adjacent_double_coordinates(gt);
    if(by_pointer)
    {
      const double* pointers[3 * batch];
      add_in_batches(
          [&](std::size_t slot, const Point_3& t1, const Point_3& t2, const Point_3& t3) {
            const double** q = pointers + 3 * slot;
            q[0] = &x(t1);
            q[1] = &x(t2);
            q[2] = &x(t3);
#if defined(__GNUC__)
            __builtin_prefetch(q[0]);
            __builtin_prefetch(q[1]);
            __builtin_prefetch(q[2]);
#endif
          },
          [&pointers](std::size_t i, int k) { return pointers[3 * i + std::size_t(k)]; });
    }
  }
  if(!by_pointer)
  {
    double coordinates[9 * batch];
    add_in_batches(
        [&](std::size_t slot, const Point_3& t1, const Point_3& t2, const Point_3& t3) {
          double* q = coordinates + 9 * slot;
          q[0] = x(t1); q[1] = y(t1); q[2] = z(t1);
          q[3] = x(t2); q[4] = y(t2); q[5] = z(t2);
          q[6] = x(t3); q[7] = y(t3); q[8] = z(t3);
        },
        [&coordinates](std::size_t i, int k) { return coordinates + 9 * i + 3 * k; });
  }
  double s, permanents;
  std::size_t n;
  sum.finish(s, permanents, n);
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
  const auto* p = points.data();
  const auto* t = triangles.data();
  Tetrahedra_pair_sum sum(cx, cy, cz);
  // Straight from the index array: no copy of the coordinates.
  sum.add(triangles.size(), [&](std::size_t i, int k) { return &p[t[i][k]][0]; });
  double s, permanents;
  std::size_t n;
  sum.finish(s, permanents, n);
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

template <bool PointsOutliveTheVisit = false, typename GeomTraits, typename ForEachTriangle>
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

template <bool PointsOutliveTheVisit = false, typename GeomTraits, typename ForEachTriangle>
typename GeomTraits::FT sum_of_signed_tetrahedra(const GeomTraits& gt,
                                                 const Reference_point<typename GeomTraits::Point_3>& c,
                                                 const ForEachTriangle& for_each_triangle)
{
  return sum_of_signed_tetrahedra<PointsOutliveTheVisit>(gt, c, for_each_triangle,
                                                         std::is_same<typename GeomTraits::FT, double>());
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TETRAHEDRA_SUM_H
