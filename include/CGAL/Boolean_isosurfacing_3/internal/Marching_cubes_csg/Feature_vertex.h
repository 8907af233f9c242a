// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_VERTEX_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_VERTEX_H

// The feature vertex of one Marching Cubes polygon, as in Extended Marching
// Cubes (Kobbelt, Botsch, Schwanecke, Seidel, SIGGRAPH 2001): every vertex of
// the polygon is an exact crossing of a lattice edge with a known input
// triangle, so it comes with that triangle's tangent plane.  Where the
// normals disagree (their cone is wider than the feature angle), the point
// that minimises the sum of squared distances to the tangent planes is a
// point of the crease (rank 2) or the corner (rank 3) that the polygon cuts
// off.  The quadric is solved relative to the polygon's mass point with the
// small eigenvalues truncated, so that a crease gives the point of the crease
// line nearest to the mass point rather than an arbitrary, far one.

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

typedef std::array<double, 3> Vector_3d;

inline double dot3(const Vector_3d& a, const Vector_3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vector_3d sub3(const Vector_3d& a, const Vector_3d& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vector_3d add3(const Vector_3d& a, const Vector_3d& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
inline Vector_3d cross3(const Vector_3d& a, const Vector_3d& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
// The normal (b - a) x (c - a) of triangle abc, not normalised.
inline Vector_3d triangle_normal(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  return cross3(sub3(b, a), sub3(c, a));
}

/// The triangle (a, b, c) in the index type of `Triangle` (an array of three
/// unsigned integers; the caller makes sure the indices fit).
template <typename Triangle>
Triangle make_triangle(std::size_t a, std::size_t b, std::size_t c)
{
  typedef typename Triangle::value_type Index;
  return Triangle{{Index(a), Index(b), Index(c)}};
}

/// What kind of feature a polygon's tangent planes describe.
enum class Feature_kind : unsigned char { NONE = 0, CREASE = 2, CORNER = 3 };

/// Parameters of the feature test.
struct Feature_settings
{
  bool enabled = true;
  /// cos of the feature angle: a polygon has a feature iff two of its normals
  /// make a larger angle.
  double cos_feature_angle = 0.8660254037844387; // 30 degrees
  /// Singular values of the normal matrix below this fraction of the largest
  /// are truncated (EMC uses 0.1 as well): planes closer than ~6 degrees
  /// then count as one.
  double singular_value_threshold = 0.1;
};

/// Whether the normals (unit vectors) of a polygon disagree by more than the feature angle.
inline bool has_feature(const Vector_3d* normals, std::size_t n, const Feature_settings& settings)
{
  for(std::size_t a = 0; a < n; ++a)
    for(std::size_t b = a + 1; b < n; ++b)
      if(dot3(normals[a], normals[b]) < settings.cos_feature_angle)
        return true;
  return false;
}

/// The tangent-plane quadric of `n` points with unit normals, around their
/// mass point, decomposed once (one 3x3 eigen-solve a feature cube, where
/// its rank and then each truncation tried took one each: the solver was
/// the largest single cost of the feature triangulation).
class Feature_quadric
{
public:
  Feature_quadric(const Vector_3d* points, const Vector_3d* normals, std::size_t n, const Feature_settings& settings)
  {
    m_mass = Eigen::Vector3d::Zero();
    for(std::size_t i = 0; i < n; ++i)
      m_mass += Eigen::Vector3d(points[i][0], points[i][1], points[i][2]);
    m_mass /= double(n);
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    m_b = Eigen::Vector3d::Zero();
    for(std::size_t i = 0; i < n; ++i)
    {
      const Eigen::Vector3d normal(normals[i][0], normals[i][1], normals[i][2]);
      const Eigen::Vector3d p(points[i][0], points[i][1], points[i][2]);
      a += normal * normal.transpose();
      m_b += normal * normal.dot(p - m_mass);
    }
    // A = N^T N, so its eigenvalues are the squared singular values of N.
    m_solver.compute(a);
    const Eigen::Vector3d& lambda = m_solver.eigenvalues(); // increasing
    if(m_solver.info() != Eigen::Success || !(lambda[2] > 0))
      return;
    const double threshold = settings.singular_value_threshold * settings.singular_value_threshold * lambda[2];
    for(int i = 0; i < 3; ++i)
      if(lambda[i] >= threshold)
        ++m_rank;
  }

  /// The rank the quadric supports (0, 1, 2 or 3) after truncation.
  int rank() const { return m_rank; }

  /// The minimiser truncated to `rank` (2 or 3, at most `rank()`), and the
  /// direction of the crease line (the null direction for rank 2).  False
  /// if the quadric has a smaller rank or the point is not finite.
  bool minimiser(int rank, Vector_3d& result, Vector_3d& direction) const
  {
    if(rank > m_rank)
      return false;
    Eigen::Vector3d x = m_mass;
    for(int i = 3 - rank; i < 3; ++i)
    {
      const Eigen::Vector3d u = m_solver.eigenvectors().col(i);
      x += (u.dot(m_b) / m_solver.eigenvalues()[i]) * u;
    }
    result = {{x[0], x[1], x[2]}};
    const Eigen::Vector3d d = m_solver.eigenvectors().col(0);
    direction = {{d[0], d[1], d[2]}};
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
  }

private:
  Eigen::Vector3d m_mass, m_b;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> m_solver;
  int m_rank = 0;
};

// The parameter interval [t0, t1] of the line x + t d inside the box [low,
// high] (empty iff t0 > t1).
inline void clip_line_to_box(const Vector_3d& x, const Vector_3d& d, const Vector_3d& low, const Vector_3d& high,
                             double& t0, double& t1)
{
  t0 = -std::numeric_limits<double>::infinity();
  t1 = std::numeric_limits<double>::infinity();
  for(int a = 0; a < 3; ++a)
  {
    if(d[a] == 0)
    {
      if(x[a] < low[a] || x[a] > high[a])
        t0 = std::numeric_limits<double>::infinity();
      continue;
    }
    double s0 = (low[a] - x[a]) / d[a], s1 = (high[a] - x[a]) / d[a];
    if(s0 > s1)
      std::swap(s0, s1);
    t0 = (std::max)(t0, s0);
    t1 = (std::min)(t1, s1);
  }
}

/// Points of a crease line tried as a feature vertex: the one nearest to the
/// polygon's mass point, then 8 evenly spaced ones across the cube.
constexpr std::size_t crease_candidates = 9;

/// The feature vertex of a polygon inside the cube [low, high], if it has
/// one.  A corner whose point falls outside the cube is tried as a crease (the
/// cube then sees the planes of a corner that lies in a neighbour).  A crease
/// vertex is a point of the crease line inside the cube: the nearest to the
/// polygon's mass point (the crease may clip a corner of the cube, far from
/// the mass point), else, if `accept` refuses it, other points of the line
/// across the cube, nearest first; a crease line that misses the cube is no
/// feature of this cube.  A point within rounding of the cube is clamped
/// into it.
/// `accept(x)` may refuse a candidate point (a fan that would fold): when
/// every candidate of a rank is refused, the next lower rank is tried.  An
/// `accept(x, full_rank)` is told whether x is a candidate of the quadric's
/// own rank (not a lower rank tried after those were refused).
template <typename Accept>
Feature_kind feature_vertex(const Vector_3d* points, const Vector_3d* normals, std::size_t n, const Vector_3d& low,
                            const Vector_3d& high, const Feature_settings& settings, const Accept& accept,
                            Vector_3d& result)
{
  if(!settings.enabled || n < 3 || !has_feature(normals, n, settings))
    return Feature_kind::NONE;
  const Feature_quadric quadric(points, normals, n, settings);
  const double tolerance = 1e-9 * (high[0] - low[0]);
  const auto accepted = [&](const Vector_3d& x, int rank) {
    if constexpr(std::is_invocable_r<bool, const Accept&, const Vector_3d&, bool>::value)
      return accept(x, rank == quadric.rank());
    else
      return accept(x);
  };
  for(int r = quadric.rank(); r >= 2; --r)
  {
    Vector_3d x, d;
    if(!quadric.minimiser(r, x, d))
      continue;
    const auto clamped = [&](Vector_3d y) {
      for(int a = 0; a < 3; ++a)
        y[a] = (std::min)((std::max)(y[a], low[a]), high[a]);
      return y;
    };
    if(r == 3)
    {
      bool inside = true;
      for(int a = 0; a < 3; ++a)
        inside = inside && x[a] >= low[a] - tolerance && x[a] <= high[a] + tolerance;
      if(inside && accepted(clamped(x), r))
      {
        result = clamped(x);
        return Feature_kind::CORNER;
      }
      continue;
    }
    // A crease: the points of the crease line inside the cube, the one
    // nearest to the mass point first.  When its fan folds (the polygon is
    // not star-shaped from there), other points of the line inside the cube
    // are tried, nearest first: any of them is on the crease.
    double t0, t1;
    clip_line_to_box(x, d, low, high, t0, t1);
    if(!(t0 <= t1 + tolerance))
      continue;
    const double best = (std::min)((std::max)(0.0, t0), t1);
    std::array<double, crease_candidates> ts;
    ts[0] = best;
    for(std::size_t c = 1; c < crease_candidates; ++c)
      ts[c] = t0 + (t1 - t0) * double(c - 1) / double(crease_candidates - 2);
    std::sort(ts.begin() + 1, ts.end(),
              [&](double u, double v) { return std::abs(u - best) < std::abs(v - best); });
    for(double t : ts)
    {
      Vector_3d y;
      for(int a = 0; a < 3; ++a)
        y[a] = x[a] + t * d[a];
      y = clamped(y);
      if(accepted(y, r))
      {
        result = y;
        return Feature_kind::CREASE;
      }
    }
  }
  return Feature_kind::NONE;
}

/// The shape quality |cross|^2 / (sum of squared sides)^2 of a triangle: 0
/// for a degenerate one, 1/12 for an equilateral one (about 2e-3 at a
/// smallest angle of 5 degrees).
inline double triangle_quality(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const Vector_3d n = triangle_normal(a, b, c);
  const Vector_3d u = sub3(b, a), v = sub3(c, b), w = sub3(a, c);
  const double sides = dot3(u, u) + dot3(v, v) + dot3(w, w);
  return sides > 0 ? dot3(n, n) / (sides * sides) : 0;
}

/// Below this quality a triangle counts as degenerate (smallest angle about
/// 0.01 degree): fans and collapses that would create one are refused.
constexpr double degenerate_quality = 1e-9;

/// Which fan triangles count as folded (`fan_is_unfolded()`).
enum class Fold_test
{
  /// A fan triangle must make an acute angle with the normals of both its
  /// polygon vertices.
  STRICT,
  /// A fan triangle must make an acute angle with the sum of the two
  /// normals.  A chamfer triangle from a vertex of one plane to a vertex of
  /// the other across a crease of 90 degrees or more is often obtuse to one
  /// of them without any fold, so this test keeps far more crease points
  /// (sharp edges p95 0.26 -> 0.07 r on mechpart minus a moved copy); but it
  /// can let a fan cross a neighbouring triangle, so `marching_cubes_csg()`
  /// checks those fans and gives their cubes the strict test where one does
  /// (`Weak_fan_check.h`).
  SUM
};

/// Whether the fan of the polygon `points[0..n)` (directed, outward) around
/// `apex` keeps the orientation the crossing normals give (`test`), and no
/// fan triangle is degenerate.  Otherwise the apex would fold the surface,
/// and the next candidate is tried (or the cube keeps its plain
/// triangulation).
inline bool fan_is_unfolded(const Vector_3d* points, const Vector_3d* normals, std::size_t n, const Vector_3d& apex,
                            Fold_test test = Fold_test::STRICT)
{
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    const Vector_3d t = triangle_normal(points[i], points[j], apex);
    if(test == Fold_test::STRICT)
    {
      if(!(dot3(t, normals[i]) > 0 && dot3(t, normals[j]) > 0))
        return false;
    }
    else if(!(dot3(t, add3(normals[i], normals[j])) > 0))
      return false;
    if(!(triangle_quality(points[i], points[j], apex) > degenerate_quality))
      return false;
  }
  return true;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_VERTEX_H
