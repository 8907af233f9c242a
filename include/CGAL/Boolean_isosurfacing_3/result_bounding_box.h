// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_RESULT_BOUNDING_BOX_H
#define CGAL_BOOLEAN_ISOSURFACING_3_RESULT_BOUNDING_BOX_H

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Where the solid `expression(inputs)` can be, from the inputs' bounding
/// boxes (see `result_bounding_box()`).
struct Result_bounding_box
{
  /// `false` if the result can be unbounded: a term of the expression's
  /// disjunctive normal form has no positive literal (`!A`, `A | !B`), so it
  /// holds outside every input.  `box` is then the union of all the inputs'
  /// boxes.
  bool bounded = true;
  /// `true` if no term can hold anywhere: every term needs a point inside
  /// inputs whose boxes do not meet (or the expression is `false`).  `box`
  /// is then `CGAL::Bbox_3()` (empty: its minimum above its maximum).
  bool empty = false;
  /// The union, over the terms, of the intersection of the boxes of the
  /// term's positive variables (a superset of the result).
  CGAL::Bbox_3 box;
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * The box where the solid `expression(inputs)` can be: a point of the result
 * satisfies some term of the expression's disjunctive normal form, hence is
 * inside every positive variable of that term, hence in the intersection of
 * their boxes.  So `A & X` lies in the intersection of the boxes of A and X,
 * `A & !B` in A's box, and a union in the union of the boxes.  A lattice
 * sized on this box (`Regular_lattice_3::enclosing()`) samples only where
 * the result can be, instead of the box of all inputs: a part 10^5 wide
 * intersected with an operand 10^38 wide gets its cells from the part.
 *
 * \param expression the Boolean expression, variable `i` for `boxes[i]`
 * \param boxes the inputs' bounding boxes, one per variable
 *
 * \throws Invalid_input_error if `boxes.size() != expression.number_of_variables()`.
 */
inline Result_bounding_box result_bounding_box(const Boolean_expression& expression,
                                               const std::vector<CGAL::Bbox_3>& boxes)
{
  if(boxes.size() != expression.number_of_variables())
    throw Invalid_input_error("result_bounding_box: " + std::to_string(boxes.size()) + " box(es) for " +
                              std::to_string(expression.number_of_variables()) + " variable(s)");
  const auto is_empty = [](const CGAL::Bbox_3& b) {
    return !(b.xmin() <= b.xmax() && b.ymin() <= b.ymax() && b.zmin() <= b.zmax());
  };
  Result_bounding_box result;
  result.box = CGAL::Bbox_3();
  for(const Boolean_term& term : expression.terms())
  {
    if(term.pos == 0)
    {
      result.bounded = false;
      result.box = CGAL::Bbox_3();
      for(const CGAL::Bbox_3& b : boxes)
        result.box += b;
      return result;
    }
    // The intersection of the boxes of the positive variables.
    double low[3], high[3];
    for(int a = 0; a < 3; ++a)
    {
      low[a] = -std::numeric_limits<double>::infinity();
      high[a] = std::numeric_limits<double>::infinity();
    }
    for(std::size_t v = 0; v < boxes.size(); ++v)
      if((term.pos >> v) & 1)
        for(int a = 0; a < 3; ++a)
        {
          low[a] = (std::max)(low[a], boxes[v].min(a));
          high[a] = (std::min)(high[a], boxes[v].max(a));
        }
    const CGAL::Bbox_3 part(low[0], low[1], low[2], high[0], high[1], high[2]);
    if(!is_empty(part))
      result.box += part;
  }
  result.empty = is_empty(result.box);
  return result;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_RESULT_BOUNDING_BOX_H
