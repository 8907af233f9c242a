// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_PERTURBED_LINE_PREDICATES_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_PERTURBED_LINE_PREDICATES_3_H

// The exact predicates of the lattice classification, for the *perturbed*
// lattice: every lattice point p is replaced by p + (d1, d2, d3) with
// d1 >> d2 >> d3 > 0 infinitesimal (see doc/Boolean_isosurfacing_3/
// marching_cubes_csg.md).  Each predicate is the exact sign of a polynomial
// in the d's: the sign of its constant term (an exact predicate on the
// unperturbed doubles) when that is not zero, otherwise the sign of the
// leading perturbation term, which is a sign of a coordinate difference or
// of a normal component.  Lines along axis a run through (u, v) = the two
// other coordinates, u < v, so the perturbation of u dominates that of v.

#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Predicate_kernel;

/// The two coordinates of a line along `axis`, smaller axis first.
constexpr int line_u_axis(int axis) { return axis == 0 ? 1 : 0; }
constexpr int line_v_axis(int axis) { return axis == 2 ? 1 : 2; }

inline int sign_of(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0); }

/// A triangle of an input mesh, in doubles, with the exact signs of the
/// components of its normal n = (b - a) x (c - a).
struct Lattice_triangle
{
  std::array<std::array<double, 3>, 3> p;
  std::uint32_t mesh = 0;
  std::array<signed char, 3> normal_sign{{0, 0, 0}};
  // sign of n.(d1, d2, d3): the first non-zero normal component, 0 iff degenerate.
  signed char perturbation_sign = 0;

  bool is_degenerate() const { return perturbation_sign == 0; }

  /// Orientation of the projection of the triangle onto the (u, v) plane of
  /// lines along `axis` (u < v): n_x, -n_y, n_z.  Zero when the lines along
  /// `axis` are parallel to the triangle's plane: such lines never cross it.
  int projected_orientation(int axis) const { return axis == 1 ? -normal_sign[1] : normal_sign[axis]; }
};

inline Lattice_triangle make_lattice_triangle(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                              const std::array<double, 3>& c, std::uint32_t mesh)
{
  typedef Predicate_kernel::Point_2 P2;
  const Predicate_kernel::Orientation_2 orientation;
  Lattice_triangle t;
  t.p = {{a, b, c}};
  t.mesh = mesh;
  // n_x = orient2d in (y, z), n_y = orient2d in (z, x), n_z = orient2d in (x, y).
  for(int axis = 0; axis < 3; ++axis)
  {
    const int s = (axis + 1) % 3, r = (axis + 2) % 3;
    t.normal_sign[axis] = static_cast<signed char>(
        sign_of(orientation(P2(a[s], a[r]), P2(b[s], b[r]), P2(c[s], c[r]))));
  }
  t.perturbation_sign = t.normal_sign[0] != 0 ? t.normal_sign[0]
                        : (t.normal_sign[1] != 0 ? t.normal_sign[1] : t.normal_sign[2]);
  return t;
}

/// Sign of orient2d(a, b, p + (eu, ev)), eu >> ev > 0 infinitesimal, in a
/// (u, v) plane.  orient2d(a, b, p + e) = orient2d(a, b, p)
/// - (b_v - a_v) eu + (b_u - a_u) ev.  Antisymmetric in (a, b), so two
/// triangles sharing an edge see opposite signs on it.  Zero only if a and b
/// coincide (then the triangle's projection is degenerate anyway).
inline int perturbed_orientation_2(double au, double av, double bu, double bv, double pu, double pv)
{
  typedef Predicate_kernel::Point_2 P2;
  const int s = sign_of(Predicate_kernel::Orientation_2()(P2(au, av), P2(bu, bv), P2(pu, pv)));
  if(s != 0)
    return s;
  if(av != bv)
    return av > bv ? 1 : -1;
  if(au != bu)
    return bu > au ? 1 : -1;
  return 0;
}

/// Whether the perturbed lattice line along `axis` through (pu, pv) crosses
/// the triangle: iff the perturbed point is strictly inside the projection.
/// The perturbed line never meets an edge or a vertex, so the crossing is a
/// single point interior to the triangle.
inline bool line_crosses_triangle(const Lattice_triangle& t, int axis, double pu, double pv)
{
  const int s = t.projected_orientation(axis);
  if(s == 0)
    return false;
  const int u = line_u_axis(axis), v = line_v_axis(axis);
  for(int e = 0; e < 3; ++e)
  {
    const std::array<double, 3>& a = t.p[e];
    const std::array<double, 3>& b = t.p[(e + 1) % 3];
    if(perturbed_orientation_2(a[u], a[v], b[u], b[v], pu, pv) != s)
      return false;
  }
  return true;
}

/// Whether the crossing of the perturbed line along `axis` with `t` lies
/// before (at a smaller `axis` coordinate than) the perturbed lattice point
/// `p + (d1, d2, d3)`.  With O(q) = orient3d(a, b, c, q) = n.(q - a), the
/// line q(s) = p + d + s e_axis crosses the plane at s* = -O(p + d) / n_axis,
/// and s* < 0 iff sign O(p + d) = sign n_axis, where
/// O(p + d) = O(p) + n_x d1 + n_y d2 + n_z d3.
/// \pre line_crosses_triangle(t, axis, p[u], p[v])
inline bool crossing_is_before(const Lattice_triangle& t, int axis, const std::array<double, 3>& p)
{
  typedef Predicate_kernel::Point_3 P3;
  const int o = sign_of(Predicate_kernel::Orientation_3()(P3(t.p[0][0], t.p[0][1], t.p[0][2]),
                                                          P3(t.p[1][0], t.p[1][1], t.p[1][2]),
                                                          P3(t.p[2][0], t.p[2][1], t.p[2][2]),
                                                          P3(p[0], p[1], p[2])));
  return (o != 0 ? o : t.perturbation_sign) == t.normal_sign[axis];
}

/// The `axis` coordinate where the line through (pu, pv) meets the plane of
/// `t`, in double: the barycentric combination of the vertices with the
/// weights of the 2D sub-areas, which stays within the triangle's range even
/// for nearly parallel triangles.  Only used for the position of output
/// vertices and as a first guess of the crossing index.
/// \pre line_crosses_triangle(t, axis, pu, pv)
inline double crossing_coordinate(const Lattice_triangle& t, int axis, double pu, double pv)
{
  const int u = line_u_axis(axis), v = line_v_axis(axis);
  const double s = double(t.projected_orientation(axis));
  double w[3], sum = 0;
  for(int e = 0; e < 3; ++e)
  {
    const std::array<double, 3>& a = t.p[(e + 1) % 3];
    const std::array<double, 3>& b = t.p[(e + 2) % 3];
    const double area = s * ((b[u] - a[u]) * (pv - a[v]) - (b[v] - a[v]) * (pu - a[u]));
    w[e] = area > 0 ? area : 0; // rounding may make a tiny weight negative
    sum += w[e];
  }
  const double low = (std::min)({t.p[0][axis], t.p[1][axis], t.p[2][axis]});
  const double high = (std::max)({t.p[0][axis], t.p[1][axis], t.p[2][axis]});
  if(!(sum > 0))
    return low + (high - low) / 2;
  // Rounding may leave the convex hull of the vertices by an ulp; clamping
  // also makes a face orthogonal to the axis give its exact coordinate.
  const double x = (w[0] * t.p[0][axis] + w[1] * t.p[1][axis] + w[2] * t.p[2][axis]) / sum;
  return x < low ? low : (x > high ? high : x);
}

/// The smallest i in [0, n] with `coordinates[i] >= value` (n if none), for
/// the n increasing lattice coordinates along an axis.  Exact: the double
/// estimate only says where to start comparing.
inline std::size_t first_index_not_below(const double* coordinates, std::size_t n, double spacing, double value)
{
  const double estimate = std::ceil((value - coordinates[0]) / spacing);
  std::size_t i = !(estimate > 0) ? 0 : (estimate >= double(n) ? n : std::size_t(estimate));
  while(i > 0 && coordinates[i - 1] >= value)
    --i;
  while(i < n && coordinates[i] < value)
    ++i;
  return i;
}

/// The index of the crossing: the smallest i in [0, n] such that the
/// crossing lies before lattice point i of the line along `axis` through
/// `p[u]`, `p[v]`, where `coordinates[0 .. n)` are the lattice coordinates
/// along `axis`.  The crossing then lies on lattice edge (i - 1, i); 0 means
/// before the first point and n after the last.  `guess` is where to start
/// (any value in [0, n]); the answer is exact.  The predicate is monotone in
/// i (O(p_i + d) is affine in the coordinate of p_i, with slope n_axis).
inline std::size_t crossing_index(const Lattice_triangle& t, int axis, const double* coordinates, std::size_t n,
                                  std::array<double, 3> p, std::size_t guess)
{
  auto before = [&](std::size_t i) {
    if(i >= n)
      return true;
    p[axis] = coordinates[i];
    return crossing_is_before(t, axis, p);
  };
  // Smallest i in [lo, hi] with before(i), given before(hi).
  auto search = [&](std::size_t lo, std::size_t hi) {
    while(lo < hi)
    {
      const std::size_t mid = lo + (hi - lo) / 2;
      if(before(mid))
        hi = mid;
      else
        lo = mid + 1;
    }
    return lo;
  };
  std::size_t i = guess > n ? n : guess;
  if(!before(i))
  {
    // The answer is above i: try the next point, then bisect.
    if(before(i + 1))
      return i + 1;
    return search(i + 2, n);
  }
  if(i == 0 || !before(i - 1))
    return i;
  if(i == 1 || !before(i - 2))
    return i - 1;
  return search(0, i - 2);
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_PERTURBED_LINE_PREDICATES_3_H
