// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CALLBACK_PARAMETER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CALLBACK_PARAMETER_H

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The progress of a run, from CGAL's `callback` named parameter (a callable
// `bool(double)`: false cancels).
template <typename NamedParameters>
Progress progress_of(const NamedParameters& np)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::callback_t>::value)
    return Progress(std::function<bool(double)>(CGAL::parameters::get_parameter(np, CGAL::internal_np::callback)));
  else
    return Progress();
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CALLBACK_PARAMETER_H
