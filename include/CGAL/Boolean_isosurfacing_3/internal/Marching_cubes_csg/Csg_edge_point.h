// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CSG_EDGE_POINT_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CSG_EDGE_POINT_H

// The seed's INT_POINT, generalised to N meshes and any Boolean expression.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// The value of a Boolean expression on a mesh mask: a truth table for up to
/// 16 variables (64 KiB at most), `evaluate()` otherwise.
class Expression_evaluator
{
public:
  static constexpr std::size_t max_table_variables = 16;

  explicit Expression_evaluator(const Boolean_expression& expression) : m_expression(&expression)
  {
    const std::size_t n = expression.number_of_variables();
    if(n <= max_table_variables)
    {
      const std::vector<bool> table = expression.truth_table();
      m_table.assign(table.begin(), table.end());
      m_table_mask = (std::uint64_t(1) << n) - 1;
    }
  }

  bool operator()(std::uint64_t mask) const
  {
    if(!m_table.empty())
      return m_table[std::size_t(mask & m_table_mask)] != 0;
    return m_expression->evaluate(mask);
  }

private:
  const Boolean_expression* m_expression;
  std::vector<std::uint8_t> m_table;
  std::uint64_t m_table_mask = 0;
};

/// The crossing where the output surface cuts a lattice edge whose ends have
/// different values of the expression.  `crossings[0 .. n)` are the crossings
/// of all meshes with the edge, sorted by position from the low end; the
/// walk starts at the inside end (the low one iff `from_low`), whose mesh
/// mask is `mask`, toggles the mesh bit at each crossing and stops at the
/// first crossing after which the point is outside.  Returns its index, or
/// `n` if there is none (impossible when the crossings are consistent with
/// the classification of the two ends).
///
/// For two meshes and one crossing each this is the seed's rule: for a union
/// the walk leaves the first mesh but is still inside the second, so it
/// stops at the farther crossing; for an intersection or a difference the
/// first crossing already leaves the result, the nearer one.
template <typename Crossing, typename Inside>
std::size_t csg_edge_crossing(const Crossing* crossings, std::size_t n, bool from_low, std::uint64_t mask,
                              const Inside& inside)
{
  for(std::size_t s = 0; s < n; ++s)
  {
    const std::size_t c = from_low ? s : n - 1 - s;
    mask ^= std::uint64_t(1) << crossings[c].mesh;
    if(!inside(mask))
      return c;
  }
  return n;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CSG_EDGE_POINT_H
