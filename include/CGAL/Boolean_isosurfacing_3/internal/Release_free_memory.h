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
#include <cstdint>
#include <cstdlib>
#include <type_traits>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
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

/// Hands back the pages of `v`'s storage beyond its size: a vector shrunk
/// by `resize()` keeps the pages its former elements touched resident
/// (after the sliver collapses, 70 MB of points and triangles at 2048
/// cells), and `shrink_to_fit()` would copy it, holding both at once.  The
/// pages stay mapped: growing the vector again finds them zeroed.  Only for
/// trivially copyable elements (nothing reads the storage past the size).
template <typename T, typename Allocator>
void release_unused_capacity(std::vector<T, Allocator>& v)
{
  static_assert(std::is_trivially_copyable<T>::value, "the storage past the size must hold no object");
#if defined(__linux__) && defined(MADV_DONTNEED)
  const std::uintptr_t page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t data = reinterpret_cast<std::uintptr_t>(v.data());
  // Whole pages inside the storage only: the heap's own data may share the
  // first and the last page.
  const std::uintptr_t begin = (data + v.size() * sizeof(T) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (data + v.capacity() * sizeof(T)) & ~(page - 1);
  if(v.data() != nullptr && end > begin && end - begin >= (std::uintptr_t(8) << 20))
    ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
#else
  (void)v;
#endif
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_RELEASE_FREE_MEMORY_H
