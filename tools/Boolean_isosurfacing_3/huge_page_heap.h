// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// The tools' heap in transparent huge pages.
//
// Why: a short run's time goes largely into first touches of fresh memory.
// On the project's virtual machine a 4 KB page fault costs 10-16 us (a
// 1.2 MB vector takes 4-5 ms to fill the first time, 0.2 ms in a 2 MB page),
// and `csg` at 128 cells takes 7,000-11,000 of them.  glibc asks the kernel
// for huge pages on its heap only when told so by the `glibc.malloc.hugetlb`
// tunable, which it reads from the environment at start-up, never later:
// so each tool, before anything else, starts itself again once with
// GLIBC_TUNABLES set.  Measured (whole processes, 128 cells): the tray_bottom
// union 0.78x the time, the armadillo union 0.69x; at 2048 cells the peak
// stays under 1 GiB (the thresholds below hand the big arrays back as before).
//
// A GLIBC_TUNABLES already set (even empty) is the caller's choice: nothing
// is changed, which is also how the second start knows it is the second.
// Where the restart is impossible (no /proc, not glibc), the tool goes on
// with the default heap: only the speed differs, never the output.

#ifndef BISO_TOOLS_HUGE_PAGE_HEAP_H
#define BISO_TOOLS_HUGE_PAGE_HEAP_H

#include <cstdlib>

#if defined(__linux__) && defined(__GLIBC__)
#include <climits>
#include <unistd.h>
#endif

namespace biso_tools {

/// The tunables: huge pages for the heap; blocks from 4 MiB up mapped on
/// their own (handed back whole when freed, as the 2048-cell memory bound
/// needs), smaller ones reused from the heap, whose top is kept up to
/// 32 MiB (each page given back and touched again is another fault).
constexpr const char* huge_page_heap_tunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=4194304:glibc.malloc.trim_threshold=33554432";

/// Restarts the process with `huge_page_heap_tunables` unless GLIBC_TUNABLES
/// is set; returns only if it did not restart.  Call first in `main`.
inline void restart_with_huge_page_heap(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("GLIBC_TUNABLES") != nullptr)
    return;
  // The executable's own path, not /proc/self/exe itself: under a tool such
  // as valgrind, /proc/self/exe is the tool, and only readlink is redirected.
  char path[PATH_MAX];
  const ssize_t length = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
  if(length <= 0)
    return;
  path[length] = '\0';
  if(::setenv("GLIBC_TUNABLES", huge_page_heap_tunables, 1) != 0)
    return;
  ::execv(path, argv);
  ::unsetenv("GLIBC_TUNABLES"); // the restart failed: go on as started
#else
  (void)argv;
#endif
}

} // namespace biso_tools

#endif // BISO_TOOLS_HUGE_PAGE_HEAP_H
