// The tools' value checks and file checks, under the command-line layer of
// cli.h (which parses the command line with CLI11 and maps these errors to
// exit statuses):
//
//   - `Usage_error` (exit 2) and `File_error` (exit 1);
//   - an error message never carries raw control bytes or invalid UTF-8 from
//     a file or an argument to the terminal: they are shown as \xNN;
//   - numbers are parsed strictly: the whole argument, no leading blank, NaN
//     and infinities refused by name, the range of each flag checked before
//     any file is read;
//   - input files are checked to be readable files, output files to be
//     writable, before any computation.

#ifndef BISO_TOOLS_TOOL_SUPPORT_H
#define BISO_TOOLS_TOOL_SUPPORT_H

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace biso_tools {

/// A bad command line: exit status 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// A problem with a file named on the command line: exit status 1.
struct File_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The length of the valid UTF-8 sequence at s[i] (0 if none): its bytes
// print as one character, anything else would garble the terminal.
inline std::size_t utf8_sequence_length(const std::string& s, std::size_t i)
{
  const unsigned char c = static_cast<unsigned char>(s[i]);
  std::size_t n = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
  if(n == 0 || c > 0xf4 || i + n > s.size())
    return 0;
  for(std::size_t k = 1; k < n; ++k)
    if((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80)
      return 0;
  return n;
}

/// `s` with control bytes (newlines included), DEL and bytes that are not
/// valid UTF-8 replaced by `\xNN`: safe to print on one terminal line.
inline std::string printable(const std::string& s)
{
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for(std::size_t i = 0; i < s.size();)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if(c >= 0x20 && c < 0x7f)
    {
      out += char(c);
      ++i;
      continue;
    }
    if(const std::size_t n = c >= 0x80 ? utf8_sequence_length(s, i) : 0)
    {
      out.append(s, i, n);
      i += n;
      continue;
    }
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
    ++i;
  }
  return out;
}

/// Quotes a command-line argument for an error message.
inline std::string quote_arg(const std::string& s) { return "'" + printable(s) + "'"; }

/// Prints `tool: message` as one line on stderr.
inline void print_error(const char* tool, const std::string& message)
{
  std::cerr << tool << ": " << printable(message) << "\n";
}

enum class Sign_rule
{
  POSITIVE,     ///< > 0
  NON_NEGATIVE, ///< >= 0
  ANY           ///< any sign (the caller checks the range)
};

/// The value of `text`, a finite number (or `inf` when `allow_infinity`),
/// for flag `flag`.  \throws Usage_error naming the flag and the problem.
inline double parse_real(const std::string& flag, const std::string& text, Sign_rule rule,
                         bool allow_infinity = false)
{
  if(text.empty())
    throw Usage_error(flag + " needs a number, got an empty argument");
  if(std::isspace(static_cast<unsigned char>(text[0])))
    throw Usage_error(flag + ": " + quote_arg(text) + " is not a number (leading blank)");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if(end == text.c_str() || *end != '\0')
    throw Usage_error(flag + ": " + quote_arg(text) + " is not a number");
  if(std::isnan(v))
    throw Usage_error(flag + ": " + quote_arg(text) + " is NaN; a number is needed");
  if(std::isinf(v) && (!allow_infinity || v < 0))
  {
    const bool overflow = errno == ERANGE; // "1e999" is a number, but not a double
    throw Usage_error(flag + ": " + quote_arg(text) + (overflow ? " is too large (beyond the range of doubles)"
                                                            : " is infinite; a finite number is needed"));
  }
  if(rule == Sign_rule::POSITIVE && !(v > 0))
    throw Usage_error(flag + " must be positive, got " + quote_arg(text));
  if(rule == Sign_rule::NON_NEGATIVE && !(v >= 0))
    throw Usage_error(flag + " must not be negative, got " + quote_arg(text));
  return v;
}

/// The value of `text`, a whole number in [minimum, maximum], for `flag`.
/// `limit_reason` says why `maximum` is the limit.
inline std::size_t parse_count(const std::string& flag, const std::string& text, std::size_t minimum,
                               std::size_t maximum, const std::string& limit_reason)
{
  const double v = parse_real(flag, text, Sign_rule::ANY);
  if(v != std::floor(v))
    throw Usage_error(flag + ": " + quote_arg(text) + " is not a whole number");
  if(v < double(minimum))
    throw Usage_error(flag + " must be at least " + std::to_string(minimum) + ", got " + quote_arg(text));
  if(v > double(maximum))
    throw Usage_error(flag + " " + printable(text) + " is above the limit of " + std::to_string(maximum) + " (" +
                      limit_reason + ")");
  return std::size_t(v);
}

/// The lower-case extension of `path` (after the last dot of the last
/// component), empty if none.
inline std::string extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = path.substr(dot + 1);
  for(char& c : e)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

/// Checks that `path` names a readable regular file (or a FIFO, such as
/// `/dev/stdin` or a process substitution).  \throws File_error naming the problem.
inline void check_input_file(const std::string& path)
{
  if(path.empty())
    throw Usage_error("an input file name is empty");
  struct stat info;
  if(stat(path.c_str(), &info) != 0)
    throw File_error(path + ": cannot open (" + std::strerror(errno) + ")");
  if(S_ISDIR(info.st_mode))
    throw File_error(path + ": is a directory, not a file");
  if(!S_ISREG(info.st_mode) && !S_ISFIFO(info.st_mode) && !S_ISCHR(info.st_mode))
    throw File_error(path + ": is not a regular file");
  if(access(path.c_str(), R_OK) != 0)
    throw File_error(path + ": cannot open (" + std::strerror(errno) + ")");
}

/// Checks, before any computation, that `path` can be written: it is not a
/// directory and can be opened for writing.  An existing file is opened
/// for appending (its content is kept); a file this creates is removed.
/// \throws File_error naming the problem.
inline void check_output_file(const std::string& path)
{
  struct stat info;
  const bool existed = stat(path.c_str(), &info) == 0;
  if(existed && S_ISDIR(info.st_mode))
    throw File_error(path + ": cannot write, it is a directory");
  std::FILE* probe = std::fopen(path.c_str(), "a");
  if(probe == nullptr)
    throw File_error(path + ": cannot write (" + std::strerror(errno) + ")");
  std::fclose(probe);
  if(!existed)
    std::remove(path.c_str());
}

} // namespace biso_tools

#endif // BISO_TOOLS_TOOL_SUPPORT_H
