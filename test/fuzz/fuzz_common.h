// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TEST_FUZZ_COMMON_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TEST_FUZZ_COMMON_H

// Shared by the libFuzzer harnesses.  A reader may reject its input with the
// package's exceptions (Invalid_input_error and derived types); anything else
// escaping, a crash, a sanitizer report, a hang (-timeout) or a huge
// allocation (-malloc_limit_mb) is a finding.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace biso_fuzz {

// A point constructible from three doubles, without any CGAL kernel.
struct Point
{
  double c[3];
  Point(double x, double y, double z) : c{x, y, z} {}
  double x() const { return c[0]; }
  double y() const { return c[1]; }
  double z() const { return c[2]; }
};

// Readers that take a path get the input through a per-process file in
// /dev/shm (memory-backed) or /tmp, rewritten for every input.
inline std::string write_temporary(const std::uint8_t* data, std::size_t size, const std::string& extension)
{
  static const std::string directory = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path = directory + "/biso_fuzz_" + std::to_string(getpid()) + extension;
  // Removed at exit (libFuzzer ends with exit(), also on -max_total_time).
  static std::string last_path;
  static const bool registered = std::atexit([] {
    if(!last_path.empty())
      std::remove(last_path.c_str());
  }) == 0;
  (void)registered;
  if(last_path != path && !last_path.empty())
    std::remove(last_path.c_str());
  last_path = path;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if(f == nullptr)
    std::abort();
  if(size != 0 && std::fwrite(data, 1, size, f) != size)
    std::abort();
  std::fclose(f);
  return path;
}

// A check of the harness itself (round trips): a failure is a finding.
inline void require(bool condition, const char* what)
{
  if(!condition)
  {
    std::fprintf(stderr, "biso_fuzz: check failed: %s\n", what);
    std::abort();
  }
}

} // namespace biso_fuzz

#endif // CGAL_BOOLEAN_ISOSURFACING_3_TEST_FUZZ_COMMON_H
