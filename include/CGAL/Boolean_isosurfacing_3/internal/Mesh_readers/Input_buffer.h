// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_INPUT_BUFFER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_INPUT_BUFFER_H

// The whole file in memory, and a cursor over it for the text formats.
//
// The readers parse from one buffer filled by one read(): no stream, no
// per-line allocation, no locale.  The buffer is followed by zero bytes, so
// a scan that looks at *p before checking p < end never leaves it, and a
// number at the very end of the file still ends at a non-digit.
//
// Text positions are not tracked while parsing (counting newlines in the hot
// loop costs more than the parse): an error computes its line number by
// counting the newlines before it, once.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <fast_float/fast_float.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <memory>
#include <new>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

class Input_buffer
{
public:
  static constexpr std::size_t padding = 64;

  Input_buffer() = default;
  explicit Input_buffer(std::size_t size) : m_data(allocate(size + padding)), m_size(size)
  {
    std::memset(m_data.get() + size, 0, padding);
  }
  // A copy of caller-owned bytes (tests, in-memory files).
  Input_buffer(const char* bytes, std::size_t size) : Input_buffer(size)
  {
    if(size != 0)
      std::memcpy(m_data.get(), bytes, size);
  }

  char* data() { return m_data.get(); }
  const char* begin() const { return m_data.get(); }
  const char* end() const { return m_data.get() + m_size; }
  std::size_t size() const { return m_size; }

private:
  struct Free
  {
    void operator()(char* p) const { std::free(p); }
  };

  // Large buffers are asked for in transparent huge pages: on a virtual
  // machine a page fault per 4 KB page of a fresh buffer costs as much as
  // parsing it (measured: half of the time of a 60 MB OFF file).
  static char* allocate(std::size_t bytes)
  {
    constexpr std::size_t huge = std::size_t(2) << 20;
    char* p;
    if(bytes >= 2 * huge)
    {
      const std::size_t rounded = (bytes + huge - 1) / huge * huge;
      p = static_cast<char*>(std::aligned_alloc(huge, rounded));
#ifdef MADV_HUGEPAGE
      if(p != nullptr)
        ::madvise(p, rounded, MADV_HUGEPAGE);
#endif
    }
    else
      p = static_cast<char*>(std::malloc(bytes));
    if(p == nullptr)
      throw std::bad_alloc();
    return p;
  }

  std::unique_ptr<char[], Free> m_data;
  std::size_t m_size = 0;
};

// Reads the regular file `path` whole, or throws Invalid_input_error naming
// the reason (missing, a directory, unreadable).
inline Input_buffer read_whole_file(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if(fd < 0)
    throw Invalid_input_error(std::string("cannot open the file (") + std::strerror(errno) + ")");
  struct Closer
  {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info;
  if(::fstat(fd, &info) != 0)
    throw Invalid_input_error(std::string("cannot open the file (") + std::strerror(errno) + ")");
  if(S_ISDIR(info.st_mode))
    throw Invalid_input_error("cannot open the file: it is a directory");
  if(!S_ISREG(info.st_mode))
    throw Invalid_input_error("cannot open the file: it is not a regular file");
  Input_buffer buffer(std::size_t(info.st_size));
  std::size_t done = 0;
  while(done < buffer.size())
  {
    const ssize_t n = ::read(fd, buffer.data() + done, buffer.size() - done);
    if(n < 0 && errno == EINTR)
      continue;
    if(n < 0)
      throw Invalid_input_error(std::string("cannot read the file (") + std::strerror(errno) + ")");
    if(n == 0)
      throw Invalid_input_error("cannot read the file: it shrank while being read");
    done += std::size_t(n);
  }
  return buffer;
}

// At most `length` bytes from `p`, with anything unprintable escaped, for
// error messages: a binary file must not write control bytes to a terminal.
inline std::string printable_excerpt(const char* p, const char* end, std::size_t length = 24)
{
  std::string out;
  for(std::size_t k = 0; p + k < end && k < length; ++k)
  {
    const unsigned char c = static_cast<unsigned char>(p[k]);
    if(c == '\n' || c == '\r')
      break;
    if(c >= 0x20 && c < 0x7f)
      out += char(c);
    else
    {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

inline std::string describe_non_finite(double x, double y, double z)
{
  std::ostringstream out;
  const auto put = [&](double v) {
    if(std::isnan(v)) out << "nan";
    else if(std::isinf(v)) out << (v > 0 ? "inf" : "-inf");
    else out << v;
  };
  put(x);
  out << ' ';
  put(y);
  out << ' ';
  put(z);
  return out.str();
}

inline bool is_text_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline bool is_text_space(char c) { return is_text_blank(c) || c == '\n'; }
inline bool is_text_digit(char c) { return unsigned(c - '0') < 10u; }

// A cursor over the text of a buffer.  Every `parse_*` skips blanks (not
// newlines) first and returns false, without moving, on a malformed token.
struct Text_cursor
{
  const char* begin;
  const char* p;
  const char* end;

  Text_cursor(const char* b, const char* e) : begin(b), p(b), end(e) {}

  std::size_t line_at(const char* at) const { return 1 + std::size_t(std::count(begin, at, '\n')); }
  std::size_t line() const { return line_at(p); }

  [[noreturn]] void fail_at(const char* at, const std::string& message) const
  {
    const std::size_t l = line_at(std::min(at, end));
    throw Parse_error("line " + std::to_string(l) + ": " + message, l);
  }
  [[noreturn]] void fail(const std::string& message) const { fail_at(p, message); }

  // What the parser found instead of what it expected, quoted.
  std::string found() const
  {
    const char* q = p;
    while(q < end && is_text_blank(*q)) ++q;
    if(q >= end) return "the end of the file";
    if(*q == '\n') return "the end of the line";
    return "'" + printable_excerpt(q, end) + "'";
  }

  bool at_end() const { return p >= end; }
  void skip_blanks()
  {
    while(p < end && is_text_blank(*p)) ++p;
  }
  void skip_spaces()
  {
    while(p < end && is_text_space(*p)) ++p;
  }
  // Skips whitespace, newlines and comments that start with `comment`.
  void skip_spaces_and_comments(char comment)
  {
    for(;;)
    {
      skip_spaces();
      if(p < end && *p == comment)
        skip_line();
      else
        return;
    }
  }
  // Moves past the next newline (or to the end).
  void skip_line()
  {
    const void* nl = std::memchr(p, '\n', std::size_t(end - p));
    p = nl ? static_cast<const char*>(nl) + 1 : end;
  }
  // True at a newline, a comment or the end, after blanks.
  bool at_end_of_line(char comment = '#')
  {
    skip_blanks();
    return p >= end || *p == '\n' || *p == comment;
  }

  bool parse_double(double& value)
  {
    skip_blanks();
    const char* q = p;
    if(q < end && *q == '+')
      ++q;
    // fast_float parses "nan", "inf" and "infinity" too: the caller names
    // them in its error instead of "cannot parse".
    const auto r = fast_float::from_chars(q, end, value);
    if(r.ec != std::errc() || (r.ptr < end && !is_text_space(*r.ptr) && *r.ptr != '#'))
    {
      if(r.ec == std::errc::result_out_of_range && (r.ptr >= end || is_text_space(*r.ptr)))
      { // beyond the double range: report it as the infinity it rounds to
        value = (*q == '-') ? -HUGE_VAL : HUGE_VAL;
        p = r.ptr;
        return true;
      }
      return false;
    }
    p = r.ptr;
    return true;
  }

  // A non-negative decimal integer below 2^63.
  bool parse_unsigned(std::uint64_t& value)
  {
    skip_blanks();
    const char* q = p;
    if(q < end && *q == '+')
      ++q;
    if(q >= end || !is_text_digit(*q))
      return false;
    std::uint64_t v = 0;
    for(; q < end && is_text_digit(*q); ++q)
    {
      if(v > (std::uint64_t(1) << 59))
        return false; // far beyond any count or index this reader accepts
      v = v * 10 + std::uint64_t(*q - '0');
    }
    p = q;
    value = v;
    return true;
  }

  bool parse_signed(std::int64_t& value)
  {
    skip_blanks();
    const bool negative = p < end && *p == '-';
    if(negative && !(p + 1 < end && is_text_digit(p[1])))
      return false;
    const char* start = p;
    if(negative)
      ++p;
    std::uint64_t v;
    if(!parse_unsigned(v))
    {
      p = start;
      return false;
    }
    value = negative ? -std::int64_t(v) : std::int64_t(v);
    return true;
  }

  // The next token is `word` (then followed by a space or the end).
  bool accept(const char* word)
  {
    skip_spaces();
    const std::size_t n = std::strlen(word);
    if(std::size_t(end - p) >= n && std::memcmp(p, word, n) == 0 && (p + n == end || is_text_space(p[n])))
    {
      p += n;
      return true;
    }
    return false;
  }
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MESH_READERS_INPUT_BUFFER_H
