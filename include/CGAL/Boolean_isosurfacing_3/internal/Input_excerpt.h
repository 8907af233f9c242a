// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_INPUT_EXCERPT_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_INPUT_EXCERPT_H

// Helpers of the readers for hostile input: quoting a piece of a file in an
// error message without sending raw (binary, control, escape) bytes to the
// user's terminal, and bounding what a header count may reserve by the bytes
// the stream still holds.

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// `text` for an error message: printable ASCII kept, every other byte as
// \xNN (a trailing '\r' dropped), cut to about `max_length` characters with "...".
inline std::string input_excerpt(std::string_view text, std::size_t max_length = 60)
{
  if(!text.empty() && text.back() == '\r')
    text.remove_suffix(1);
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for(std::size_t i = 0; i < text.size(); ++i)
  {
    if(out.size() >= max_length)
    {
      out += "...";
      break;
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c >= 0x20 && c < 0x7f)
      out += char(c);
    else
    {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

// The number of bytes left in `in` from its current position, or `unknown`
// (a pipe, a terminal) when the stream cannot seek.  Leaves the position and
// the state as they were.
constexpr std::size_t unknown_remaining_bytes = ~std::size_t(0);

inline std::size_t remaining_bytes(std::istream& in)
{
  if(!in)
    return unknown_remaining_bytes;
  const std::istream::pos_type here = in.tellg();
  if(here == std::istream::pos_type(-1))
  {
    in.clear();
    return unknown_remaining_bytes;
  }
  in.seekg(0, std::ios::end);
  const std::istream::pos_type end = in.tellg();
  in.clear();
  in.seekg(here);
  if(end == std::istream::pos_type(-1) || end < here)
    return unknown_remaining_bytes;
  return std::size_t(end - here);
}

// How many records a reader may reserve for a header announcing `count`
// records of at least `min_record_bytes` bytes each, with `remaining` bytes
// left: never more than the bytes can hold, and at most 2^16 when the size
// is unknown (the vector then grows with the records actually read).
inline std::size_t reservable(std::size_t count, std::size_t min_record_bytes, std::size_t remaining)
{
  const std::size_t cap = remaining == unknown_remaining_bytes ? (std::size_t(1) << 16)
                                                                : remaining / (min_record_bytes == 0 ? 1 : min_record_bytes);
  return count < cap ? count : cap;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_INPUT_EXCERPT_H
