// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// How a tool starts: its heap in transparent huge pages, and `--distributed`
// handed to the MPI driver, a separate executable.
//
// Why: a short run's time goes largely into first touches of fresh memory.
// On the project's virtual machine a 4 KB page fault costs 10-16 us (a
// 1.2 MB vector takes 4-5 ms to fill the first time, 0.2 ms in a 2 MB page),
// and `csg` at 128 cells takes 7,000-11,000 of them.  glibc asks the kernel
// for huge pages on its heap only when told so by the `glibc.malloc.hugetlb`
// tunable, which it reads from the environment at start-up, never later:
// so each tool, before anything else, starts itself again once with
// GLIBC_TUNABLES set.  Measured (whole processes, restart included, 128
// cells): the tray_bottom union 0.83x the time, the armadillo union 0.72x;
// at 2048 cells the peak stays under 1 GiB (the thresholds below hand the
// big arrays back as before).
//
// A GLIBC_TUNABLES already set (even empty) is the caller's choice: nothing
// is changed, which is also how the second start knows it is the second.
// Where the restart is impossible (no /proc, not glibc), the tool goes on
// with the default heap: only the speed differs, never the output.

#ifndef BISO_TOOLS_PROCESS_START_H
#define BISO_TOOLS_PROCESS_START_H

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <future>
#include <string>

#if defined(__linux__)
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

/// The path of this process's executable (empty if unknown).  Not
/// /proc/self/exe itself: under a tool such as valgrind that is the tool,
/// and only readlink is redirected.
inline std::string own_executable()
{
#if defined(__linux__)
  char path[PATH_MAX];
  const ssize_t length = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
  if(length > 0)
    return std::string(path, std::size_t(length));
#endif
  return std::string();
}

/// Replaces the process by `executable` with the arguments `argv`, with
/// `huge_page_heap_tunables` unless GLIBC_TUNABLES is set.  Returns only if
/// that failed (with the environment as it was, and errno telling why).
inline void execute_with_huge_page_heap(const std::string& executable, char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  const bool set = std::getenv("GLIBC_TUNABLES") == nullptr;
  if(set && ::setenv("GLIBC_TUNABLES", huge_page_heap_tunables, 1) != 0)
    return;
  ::execv(executable.c_str(), argv);
  const int error = errno; // why execv failed, for the caller's message
  if(set)
    ::unsetenv("GLIBC_TUNABLES");
  errno = error;
#else
  (void)executable;
  (void)argv;
#endif
}

/// Restarts the process with `huge_page_heap_tunables` unless GLIBC_TUNABLES
/// is set; returns only if it did not restart.  Call first in `main`.
inline void restart_with_huge_page_heap(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("GLIBC_TUNABLES") != nullptr)
    return;
  const std::string self = own_executable();
  if(!self.empty())
    execute_with_huge_page_heap(self, argv);
#else
  (void)argv;
#endif
}

/// `csg --distributed` and `tbiso --distributed` run `csg_distributed` and
/// `tbiso_distributed`, built beside them when MPI is found: the plain tools
/// then do not load the MPI libraries (six shared objects, about 5 ms of
/// every start on the project's VM).  Replaces the process by the sibling
/// `name` of this executable with the same arguments; returns only on
/// failure, after a one-line error.
inline int run_distributed_driver(const char* tool, const char* name, char** argv)
{
  std::string self = own_executable();
  const std::size_t slash = self.rfind('/');
  if(slash == std::string::npos)
  {
    std::fprintf(stderr, "%s: error: --distributed: cannot find this executable's directory\n", tool);
    return 1;
  }
  const std::string driver = self.substr(0, slash + 1) + name;
  execute_with_huge_page_heap(driver, argv);
  std::fprintf(stderr, "%s: error: --distributed: cannot run %s: %s\n", tool, driver.c_str(), std::strerror(errno));
  return 1;
}

/// Starts building `Table::instance()` (a table derived once per process,
/// such as the Marching Cubes table: about 1 ms) on a second thread, if the
/// run may use two, while the caller reads its input on the first.  The
/// returned future waits for it when it is destroyed, error or not; a
/// caller that needs the table first simply waits in `instance()`.
template <typename Table>
std::future<void> build_meanwhile(bool parallel)
{
  if(!parallel)
    return std::future<void>();
  return std::async(std::launch::async, [] { (void)Table::instance(); });
}

} // namespace biso_tools

#endif // BISO_TOOLS_PROCESS_START_H
