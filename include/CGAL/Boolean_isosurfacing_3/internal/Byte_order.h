// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_BYTE_ORDER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_BYTE_ORDER_H

// Little-endian files on any host, and case-insensitive file extensions:
// shared by the package's readers and writers.

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

inline bool host_is_little_endian()
{
  const std::uint32_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Appends the little-endian bytes of `value` to `out`.
template <typename T>
void put_little_endian(std::string& out, T value)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if(!host_is_little_endian())
    std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// Values read from a little-endian file, in place: a no-op on x86 and ARM,
// a byte reversal per value on a big-endian host (its own inverse).
template <typename T>
void little_endian_to_host(T* values, std::size_t n)
{
  if(host_is_little_endian())
    return;
  for(std::size_t k = 0; k < n; ++k)
  {
    unsigned char* b = reinterpret_cast<unsigned char*>(values + k);
    std::reverse(b, b + sizeof(T));
  }
}

// `s` ends with `suffix` (given in lower case), ignoring the case of `s`.
inline bool ends_with_lowercase(const std::string& s, const std::string& suffix)
{
  if(s.size() < suffix.size())
    return false;
  for(std::size_t k = 0; k < suffix.size(); ++k)
    if(std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + k])) != suffix[k])
      return false;
  return true;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_BYTE_ORDER_H
