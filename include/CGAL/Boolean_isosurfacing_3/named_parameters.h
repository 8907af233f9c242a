// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_NAMED_PARAMETERS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

// The package's own named parameters.  CGAL 5.5 has no hook to add members
// to `CGAL::Named_function_parameters`, so ours are free functions in
// `CGAL::Boolean_isosurfacing::parameters` that start a chain; CGAL's own
// parameters are then chained after them:
//
//   namespace BI = CGAL::Boolean_isosurfacing;
//   BI::surveyor_volume(mesh, BI::parameters::signed_volume(true).geom_traits(k));
//
// Each parameter also has a two-argument form that appends it to an existing
// chain: `BI::parameters::signed_volume(true, CGAL::parameters::geom_traits(k))`.
//
// To add a parameter, add one line to the list below.
#define CGAL_BOOLEAN_ISOSURFACING_NAMED_PARAMETERS(X) \
  X(signed_volume_t, signed_volume)                   \
  X(check_self_intersections_t, check_self_intersections) \
  X(check_closedness_t, check_closedness)             \
  X(max_memory_bytes_t, max_memory_bytes)             \
  X(sampling_density_t, sampling_density)             \
  X(noise_level_t, noise_level)                       \
  X(cell_size_t, cell_size)                           \
  X(cells_along_longest_side_t, cells_along_longest_side) \
  X(lattice_margin_t, lattice_margin)                 \
  X(number_of_neighbors_t, number_of_neighbors)       \
  X(maximum_jump_t, maximum_jump)                     \
  X(minimum_closed_component_size_t, minimum_closed_component_size) \
  X(maximum_hole_size_t, maximum_hole_size)           \
  X(consistent_signs_t, consistent_signs)             \
  X(close_at_domain_boundary_t, close_at_domain_boundary) \
  X(slab_layers_t, slab_layers)                       \
  X(sharp_features_t, sharp_features)                 \
  X(feature_angle_t, feature_angle)                   \
  X(sharp_feature_output_t, sharp_feature_output)   \
  X(sliver_edge_length_t, sliver_edge_length)         \
  X(sharp_edge_angle_t, sharp_edge_angle)             \
  X(resolution_check_t, resolution_check)             \
  X(vertex_point_maps_t, vertex_point_maps)

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal_np {

#define CGAL_BI_DECLARE_TAG(TAG, NAME) enum TAG { NAME };
CGAL_BOOLEAN_ISOSURFACING_NAMED_PARAMETERS(CGAL_BI_DECLARE_TAG)
#undef CGAL_BI_DECLARE_TAG

} // namespace internal_np

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::default_values;

#define CGAL_BI_DECLARE_FUNCTION(TAG, NAME)                                          \
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
CGAL_BOOLEAN_ISOSURFACING_NAMED_PARAMETERS(CGAL_BI_DECLARE_FUNCTION)
#undef CGAL_BI_DECLARE_FUNCTION

} // namespace parameters

namespace internal {

// Tells overloads `f(a, b, np)` and `f(a, np)` apart, where `b` is a range.
template <typename T>
struct Is_named_function_parameters : std::false_type {};

template <typename T, typename Tag, typename Base>
struct Is_named_function_parameters<CGAL::Named_function_parameters<T, Tag, Base>> : std::true_type {};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_NAMED_PARAMETERS_H
