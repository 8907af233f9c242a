// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_RELEASE_FREE_MEMORY_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_RELEASE_FREE_MEMORY_H

// Hands the heap's free pages back to the system.  Many small vectors
// filled by several threads (the per-plane numbering of Marching Cubes:
// 160 MB at 2048 cells) stay resident in glibc's arenas once freed, and the
// large vectors allocated next (the corner table) are mapped beside them
// instead of reusing them: measured, the peak of the CSG feature path at
// 2048 cells fell by 90 MB.  A hint only: nothing happens elsewhere.

#include <cstddef>
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// Below this much freed memory, handing it back costs more (a page fault
/// per page when it is used again) than it saves.
constexpr std::size_t min_bytes_worth_releasing = std::size_t(64) << 20;

inline void release_free_memory()
{
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_RELEASE_FREE_MEMORY_H
