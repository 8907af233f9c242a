// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_NAMED_PARAMETERS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_NAMED_PARAMETERS_H

// Named parameters of the point-set contouring component
// (Tangent_plane_signed_distance_3.h, contour_point_set.h).  They follow the
// pattern of named_parameters.h (free functions in
// `CGAL::Boolean_isosurfacing::parameters` that start a chain, CGAL's own
// parameters chained after them):
//
//   BI::contour_point_set(points, out_points, out_triangles,
//       BI::parameters::cell_size(0.01).number_of_neighbors(15).normal_map(nm));
//
// They live in their own list because named_parameters.h is owned by another
// component; folding this list into CGAL_BOOLEAN_ISOSURFACING_NAMED_PARAMETERS
// later changes nothing for users.

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

#define CGAL_BOOLEAN_ISOSURFACING_CONTOURING_NAMED_PARAMETERS(X) \
  X(sampling_density_t, sampling_density)                         \
  X(noise_level_t, noise_level)                                   \
  X(cell_size_t, cell_size)                                       \
  X(cells_along_longest_side_t, cells_along_longest_side)         \
  X(lattice_margin_t, lattice_margin)                             \
  X(number_of_neighbors_t, number_of_neighbors)                   \
  X(maximum_jump_t, maximum_jump)

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal_np {

#define CGAL_BI_CONTOURING_DECLARE_TAG(TAG, NAME) enum TAG { NAME };
CGAL_BOOLEAN_ISOSURFACING_CONTOURING_NAMED_PARAMETERS(CGAL_BI_CONTOURING_DECLARE_TAG)
#undef CGAL_BI_CONTOURING_DECLARE_TAG

} // namespace internal_np

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::default_values;

#define CGAL_BI_CONTOURING_DECLARE_FUNCTION(TAG, NAME)                              \
  template <typename T>                                                              \
  CGAL::Named_function_parameters<T, internal_np::TAG> NAME(const T& value)          \
  {                                                                                  \
    return CGAL::Named_function_parameters<T, internal_np::TAG>(value);              \
  }                                                                                  \
  template <typename T, typename NP_T, typename NP_Tag, typename NP_Base>            \
  CGAL::Named_function_parameters<T, internal_np::TAG,                               \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>> \
  NAME(const T& value, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& rest) \
  {                                                                                  \
    return CGAL::Named_function_parameters<                                          \
        T, internal_np::TAG, CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>(value, rest); \
  }
CGAL_BOOLEAN_ISOSURFACING_CONTOURING_NAMED_PARAMETERS(CGAL_BI_CONTOURING_DECLARE_FUNCTION)
#undef CGAL_BI_CONTOURING_DECLARE_FUNCTION

} // namespace parameters

namespace internal {

// Whether T is a named-parameter chain (to tell overloads apart).
template <typename T>
struct Is_contouring_np : std::false_type {};
template <typename T, typename Tag, typename Base>
struct Is_contouring_np<CGAL::Named_function_parameters<T, Tag, Base>> : std::true_type {};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_NAMED_PARAMETERS_H
