// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EXACT_DETERMINANT_SIGN_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EXACT_DETERMINANT_SIGN_H

// The exact sign of a small (1x1 .. 4x4) determinant of doubles: an interval
// evaluation first, and when the interval contains zero an exact one with
// CGAL::Mpzf (products and sums of doubles are exact there).  This is the
// only arithmetic decision TBISO makes; everything else is combinatorics.

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Uncertain.h>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Laplace expansion, no division: exact for exact number types.
template <typename NT>
NT determinant_by_cofactors(const NT* a, int m)
{
  switch(m)
  {
  case 1:
    return a[0];
  case 2:
    return a[0] * a[3] - a[1] * a[2];
  case 3:
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
  default:
  {
    // 2x2 minors of the first two rows, combined with those of the last two.
    const NT m01 = a[0] * a[5] - a[1] * a[4], m02 = a[0] * a[6] - a[2] * a[4];
    const NT m03 = a[0] * a[7] - a[3] * a[4], m12 = a[1] * a[6] - a[2] * a[5];
    const NT m13 = a[1] * a[7] - a[3] * a[5], m23 = a[2] * a[7] - a[3] * a[6];
    const NT n01 = a[8] * a[13] - a[9] * a[12], n02 = a[8] * a[14] - a[10] * a[12];
    const NT n03 = a[8] * a[15] - a[11] * a[12], n12 = a[9] * a[14] - a[10] * a[13];
    const NT n13 = a[9] * a[15] - a[11] * a[13], n23 = a[10] * a[15] - a[11] * a[14];
    return m01 * n23 - m02 * n13 + m03 * n12 + m12 * n03 - m13 * n02 + m23 * n01;
  }
  }
}

/// Exact sign (-1, 0, +1) of the determinant of the `m` x `m` row-major matrix `a`, `m <= 4`.
inline int exact_sign_of_determinant(const double* a, int m)
{
  {
    typedef CGAL::Interval_nt<false> I;
    CGAL::Protect_FPU_rounding<true> protection;
    I b[16];
    for(int k = 0; k < m * m; ++k)
      b[k] = I(a[k]);
    const I d = determinant_by_cofactors(b, m);
    if(d.inf() > 0)
      return 1;
    if(d.sup() < 0)
      return -1;
    if(d.inf() == 0 && d.sup() == 0)
      return 0;
  }
  CGAL::Mpzf b[16];
  for(int k = 0; k < m * m; ++k)
    b[k] = CGAL::Mpzf(a[k]);
  const CGAL::Mpzf d = determinant_by_cofactors(b, m);
  return d.sign();
}

/// Exact sign of `a * d - b * c`.
inline int exact_sign_of_2x2(double a, double b, double c, double d)
{
  const double m[4] = {a, b, c, d};
  return exact_sign_of_determinant(m, 2);
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_EXACT_DETERMINANT_SIGN_H
