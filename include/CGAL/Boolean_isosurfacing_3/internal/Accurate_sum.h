// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ACCURATE_SUM_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ACCURATE_SUM_H

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// Sums many terms of number type `FT` without the two failure modes of a
// plain `s += x` loop:
//  - for floating point, cancellation: the volume of a closed mesh is a sum of
//    positive and negative tetrahedra, and a plain sum loses as many digits as
//    the terms' magnitude exceeds the result.  We use Neumaier's compensated
//    summation (an error-free TwoSum per term): the error is that of a sum
//    computed in twice the working precision, independent of the number of
//    terms for all practical sizes.
//  - for lazy exact types (Epeck), depth: a chain of N additions is a DAG of
//    depth N whose exact evaluation recurses N deep.  We add in a binary
//    cascade (a counter of partial sums), so the depth is log2(N).
template <typename FT, bool is_floating_point = std::is_floating_point<FT>::value>
class Accurate_sum;

template <typename FT>
class Accurate_sum<FT, true>
{
public:
  void add(FT x)
  {
    // Knuth's branch-free TwoSum: t + e == m_sum + x exactly.  (Do not
    // compile with -ffast-math: it is allowed to simplify e to 0.)
    const FT t = m_sum + x;
    const FT z = t - m_sum;
    const FT e = (m_sum - (t - z)) + (x - z);
    m_sum = t;
    m_compensation += e;
  }

  void add(const Accurate_sum& other)
  {
    add(other.m_sum);
    m_compensation += other.m_compensation;
  }

  FT result() const { return m_sum + m_compensation; }

private:
  FT m_sum = 0;
  FT m_compensation = 0;
};

template <typename FT>
class Accurate_sum<FT, false>
{
public:
  Accurate_sum() { m_filled.fill(false); }

  void add(const FT& x)
  {
    // Binary counter: level k holds the sum of 2^k terms.
    FT carry = x;
    for(std::size_t level = 0; level < levels; ++level)
    {
      if(!m_filled[level])
      {
        m_partial[level] = carry;
        m_filled[level] = true;
        return;
      }
      carry = m_partial[level] + carry;
      m_filled[level] = false;
    }
    m_overflow = m_overflow + carry; // only after 2^64 terms
  }

  FT result() const
  {
    FT sum = m_overflow;
    for(std::size_t level = 0; level < levels; ++level)
      if(m_filled[level])
        sum = sum + m_partial[level];
    return sum;
  }

private:
  static constexpr std::size_t levels = 64;
  std::array<FT, levels> m_partial{};
  std::array<bool, levels> m_filled{};
  FT m_overflow = FT(0);
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_ACCURATE_SUM_H
