// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_SECONDS_SINCE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_SECONDS_SINCE_H

#include <chrono>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The one stage timer of the package: every statistics struct reports wall
// seconds measured with it, so that the stages of all four capabilities are
// comparable (and so that two headers never define it twice).
inline double seconds_since(const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_SECONDS_SINCE_H
