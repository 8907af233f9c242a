// The command-line layer every tool (csg, volume, contour, tbiso, and the MPI
// drivers behind --distributed) is built on, over CLI11.  The conventions,
// documented in doc/Boolean_isosurfacing_3/tools.md:
//
//   - `--help` prints the usage on stdout, exit 0; `--version` prints
//     "<tool> <version>", exit 0;
//   - a bad command line is one line `<tool>: error: ...` on stderr, exit 2
//     (`Usage_error`, and CLI11's own parse errors, flattened to one line);
//   - a problem with a file or the computation is one line, exit 1;
//   - `--threads N` / `--sequential` bound the parallelism (TBB's
//     global_control), `--json` replaces the human summary on stdout by one
//     JSON object, `--quiet` silences the progress lines on stderr;
//   - a long library call shows a live progress line on a terminal, fed by
//     CGAL's `callback` named parameter (`Tool::progress()`), and every
//     stage ends with one line "<tool>: <what> in <seconds> s".
//
// An option given twice is an error, unless the tool marks it repeatable.

#ifndef BISO_TOOLS_CLI_H
#define BISO_TOOLS_CLI_H

#include "json_writer.h"
#include "tool_support.h"

#include <CLI/CLI.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/global_control.h>
#  include <tbb/parallel_for.h>
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <vector>
#include <unistd.h>

#ifndef BISO_VERSION
#  define BISO_VERSION "unknown"
#endif

namespace biso_tools {

/// Seconds elapsed since construction (or the last `restart()`).
class Stopwatch
{
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }
  void restart() { m_start = std::chrono::steady_clock::now(); }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// The one progress line of the process on stderr (a terminal has one
/// cursor): its length on screen (0: none drawn) and its last percentage.
struct Progress_line_state
{
  int length = 0;
  int percent = -1;
};

inline Progress_line_state& progress_line_state()
{
  static Progress_line_state state;
  return state;
}

/// Erases the progress line, if one is drawn ("\r", spaces, "\r"): every
/// other line the tools print on stderr starts on a clean line.
inline void end_progress_line()
{
  Progress_line_state& state = progress_line_state();
  if(state.length > 0)
  {
    std::fprintf(stderr, "\r%*s\r", state.length, "");
    std::fflush(stderr);
  }
  state = Progress_line_state();
}

/// Seconds a call runs before its progress line appears: 1, or the
/// environment variable BISO_PROGRESS_DELAY (the tests set 0).
inline double progress_delay()
{
  const char* text = std::getenv("BISO_PROGRESS_DELAY");
  char* end = nullptr;
  const double delay = text != nullptr ? std::strtod(text, &end) : 1.0;
  return text != nullptr && end != text && delay >= 0 ? delay : 1.0;
}

/// The `callback` named parameter of a long library call
/// (`CGAL::parameters::callback(progress_callback(...))`): a progress line
/// "<tool>: <what> [####      ]  42%" on stderr, redrawn in place as the
/// library reports the fraction done, erased when it reaches 1 (or when the
/// tool prints its next line).  Only on a terminal, only once the call has
/// lasted `progress_delay()` seconds, never when `silent` (--quiet).  It
/// never cancels.
inline std::function<bool(double)> progress_callback(const char* tool, const std::string& what, bool silent)
{
  end_progress_line();
  if(silent || !isatty(2))
    return [](double) { return true; };
  const Stopwatch watch;
  const double delay = progress_delay();
  const std::string text = std::string(tool) + ": " + printable(what);
  return [watch, delay, text](double fraction) {
    if(watch.seconds() < delay)
      return true;
    if(!(fraction < 1))
    {
      end_progress_line();
      return true;
    }
    fraction = fraction > 0 ? fraction : 0;
    Progress_line_state& state = progress_line_state();
    const int percent = int(fraction * 100);
    if(percent == state.percent)
      return true;
    const int width = 30, done = int(fraction * width);
    const int length = std::fprintf(stderr, "\r%s [%s%s] %3d%%", text.c_str(), std::string(done, '#').c_str(),
                                    std::string(width - done, ' ').c_str(), percent);
    std::fflush(stderr);
    state.length = length > 1 ? length - 1 : 0;
    state.percent = percent;
    return true;
  };
}

/// One tool's command line, its common options, its reporting channels.
class Tool
{
public:
  /// `description` is the first lines of `--help` (the tool's synopsis).
  Tool(const char* name, const std::string& description) : m_name(name), m_app(description, name)
  {
    m_app.set_version_flag("--version", std::string(name) + " " + BISO_VERSION, "print the tool and version, exit 0");
    // Repetitions are found after parsing (see check_repetitions), so that
    // the message names the option.
    m_app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    m_app.allow_extras(true);
    m_app.get_formatter()->column_width(30);
    m_app.add_option("--threads", m_threads_text, "use at most N threads (TBB)")
        ->type_name("N")
        ->group("Common options");
    m_app.add_flag("--sequential", m_sequential, "run on one thread (the same output as a parallel run)")
        ->group("Common options");
    m_app.add_flag("--json", m_json, "print a JSON summary on stdout instead of the human one")
        ->group("Common options");
    m_app.add_flag("--quiet", m_quiet, "no progress lines on stderr")->group("Common options");
    m_app.footer("exit status: 0 success, 1 bad input file or failed computation, 2 bad command line");
  }

  CLI::App& app() { return m_app; }
  const char* name() const { return m_name; }
  /// Options that may be given more than once (e.g. tbiso's --field).
  void allow_repeated(const std::string& option) { m_repeatable.insert(option); }

  bool parallel() const { return !m_sequential && m_threads != 1; }
  bool sequential() const { return !parallel(); }

  /// Calls `body(i)` for each i in [0, n): on TBB's threads if the run is
  /// parallel, else in order.  Independent tasks (one input file each).  An
  /// exception is rethrown for the smallest i that threw, as a sequential
  /// loop that stops at the first failure would report it.
  template <typename Body>
  void for_each_index(std::size_t n, const Body& body) const
  {
    std::vector<std::exception_ptr> errors(n);
    auto run_one = [&](std::size_t i) {
      try
      {
        body(i);
      }
      catch(...)
      {
        errors[i] = std::current_exception();
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel() && n > 1)
      tbb::parallel_for(std::size_t(0), n, run_one);
    else
#endif
      for(std::size_t i = 0; i < n && (i == 0 || !errors[i - 1]); ++i)
        run_one(i);
    for(const std::exception_ptr& e : errors)
      if(e)
        std::rethrow_exception(e);
  }
  bool json() const { return m_json; }
  bool quiet() const { return m_quiet; }

  /// Where the human summary goes: stdout, or nowhere under --json.
  std::FILE* human()
  {
    if(!m_json && m_root)
      return stdout;
    if(m_null == nullptr)
      m_null = std::fopen("/dev/null", "w");
    return m_null;
  }
  std::ostream& human_stream() { return m_json || !m_root ? m_null_stream : std::cout; }

  /// Under MPI, only the root rank reports (summary, progress, warnings,
  /// errors, JSON); the other ranks run silently.
  void set_root(bool root) { m_root = root; }
  bool root() const { return m_root; }

  /// A stage that ended: "<tool>: <what> in <seconds> s" on stderr (it
  /// replaces the stage's progress line), and its time in the JSON summary
  /// under times.<key>.
  void stage(const std::string& key, const std::string& what, double seconds)
  {
    m_times.set(key, seconds);
    end_progress_line();
    if(!m_quiet && m_root)
      std::fprintf(stderr, "%s: %s in %.3g s\n", m_name, printable(what).c_str(), seconds);
  }

  /// The `callback` named parameter of a long library call: the live
  /// progress line of `progress_callback()`, silent under --quiet and on
  /// ranks other than the root.
  std::function<bool(double)> progress(const std::string& what) const
  {
    return progress_callback(m_name, what, m_quiet || !m_root);
  }

  /// A time without a progress line (sub-stages the library reports).
  void time(const std::string& key, double seconds) { m_times.set(key, seconds); }

  /// "<tool>: warning: <text>" on stderr (always), and in the JSON warnings.
  void warning(const std::string& text)
  {
    end_progress_line();
    m_warnings.push_back(text);
    if(m_root)
      print_error(m_name, "warning: " + text);
  }
  /// "<tool>: note: <text>" on stderr (always), and in the JSON notes.
  void note(const std::string& text)
  {
    end_progress_line();
    m_notes.push_back(text);
    if(m_root)
      print_error(m_name, "note: " + text);
  }
  void input(const std::string& path) { m_inputs.push_back(path); }
  void output(const std::string& path) { m_outputs.push_back(path); }

  /// The tool's own keys of the JSON summary.
  Json_object& summary() { return m_summary; }

  /// Parses the command line; then runs `body` (its exit status) with the
  /// thread limit in place, maps exceptions to one line and an exit status,
  /// and prints the JSON summary of a successful run.
  int run(int argc, char** argv, const std::function<void()>& check, const std::function<int()>& body)
  {
    try
    {
      try
      {
        m_app.parse(argc, argv);
      }
      catch(const CLI::ParseError& e)
      {
        if(e.get_exit_code() == 0) // --help, --version
          return m_root ? m_app.exit(e) : 0;
        throw Usage_error(flatten(e));
      }
      check_repetitions();
      check_extras();
      if(m_app.count("--threads") && m_sequential)
        throw Usage_error("--threads and --sequential are exclusive");
      if(m_app.count("--threads"))
        m_threads = parse_count("--threads", m_threads_text, 1, 4096, "a sane thread count");
      check();
#ifdef CGAL_LINKED_WITH_TBB
      std::optional<tbb::global_control> limit;
      if(sequential() || m_threads > 0)
        limit.emplace(tbb::global_control::max_allowed_parallelism, sequential() ? 1 : m_threads);
#endif
      const int status = body();
      if(m_json && m_root) // also for a run that failed on some inputs (volume), or --strict
        print_json();
      return status;
    }
    catch(const Usage_error& e)
    {
      error(e.what());
      return 2;
    }
    catch(const std::bad_alloc&)
    {
      error("out of memory (use a coarser lattice)");
      return 1;
    }
    catch(const std::exception& e)
    {
      error(e.what());
      return 1;
    }
  }

  /// The positional arguments CLI11 left (allow_extras) that are not
  /// options: the tool's inputs.
  const std::vector<std::string>& positionals() const { return m_positionals; }

  ~Tool()
  {
    if(m_null != nullptr)
      std::fclose(m_null);
  }

  /// "<tool>: error: <text>" on stderr (the root rank only).
  void error(const std::string& text) const
  {
    end_progress_line();
    if(m_root)
      print_error(m_name, "error: " + text);
  }

private:
  // CLI11's messages, one line, with the phrases the tools always used.
  static std::string flatten(const CLI::ParseError& e)
  {
    std::string message = e.what();
    for(char& c : message)
      if(c == '\n')
        c = ' ';
    if(dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr)
    {
      const std::size_t colon = message.find(':');
      if(colon != std::string::npos)
        return message.substr(0, colon) + " needs a value";
    }
    return message;
  }

  void check_repetitions() const
  {
    for(const CLI::Option* option : m_app.get_options())
      if(option->count() > 1 && m_repeatable.count(option->get_name()) == 0)
        throw Usage_error(option->get_name() + " is given more than once");
  }

  // allow_extras() keeps unknown words; a word that looks like an option is
  // an unknown option (CLI11 treats "--\x01" as a positional), the rest
  // are the tool's positional arguments.
  void check_extras()
  {
    for(const std::string& word : m_app.remaining())
    {
      if(word.size() > 1 && word[0] == '-')
        throw Usage_error("unknown option " + quote_arg(word) + " (" + m_name + " --help for usage)");
      m_positionals.push_back(word);
    }
  }

  void print_json()
  {
    Json_object all;
    all.set("tool", std::string(m_name));
    all.set("version", std::string(BISO_VERSION));
    all.set_raw("inputs", json_string_array(m_inputs));
    all.set_raw("outputs", json_string_array(m_outputs));
    all.append(m_summary);
    all.set_raw("times", m_times.str());
    all.set_raw("warnings", json_string_array(m_warnings));
    all.set_raw("notes", json_string_array(m_notes));
    std::cout << all.str() << "\n";
  }

  const char* m_name;
  CLI::App m_app;
  std::string m_threads_text;
  std::size_t m_threads = 0;
  bool m_sequential = false, m_json = false, m_quiet = false, m_root = true;
  std::set<std::string> m_repeatable;
  std::vector<std::string> m_positionals, m_inputs, m_outputs, m_warnings, m_notes;
  Json_object m_summary, m_times;
  std::FILE* m_null = nullptr;
  std::ostream m_null_stream{nullptr}; // no buffer: writes are dropped
};

/// The mesh output formats every tool writes, chosen by extension.
inline bool is_mesh_format(const std::string& path)
{
  const std::string e = extension(path);
  return e == "off" || e == "obj" || e == "ply" || e == "stl";
}

/// \throws Usage_error unless `path` ends in a mesh format (or one of `extra`).
inline void check_mesh_extension(const std::string& flag, const std::string& path,
                                 const std::vector<std::string>& extra = {})
{
  if(path.empty())
    throw Usage_error(flag + " needs a file name, got an empty argument");
  for(const std::string& e : extra)
    if(extension(path) == e)
      return;
  if(!is_mesh_format(path))
  {
    std::string list;
    for(const std::string& e : extra)
      list += "." + e + ", ";
    throw Usage_error(flag + ": " + quote_arg(path) + " has no supported extension (" + list + ".off, .obj, .ply, .stl)");
  }
}

/// The lattice flags, the same in every tool that samples a lattice:
/// `--cells N` (cells along the longest side of `extent`) and `--spacing h`
/// (the cell side); their text is converted by the tool, which knows its limits.
inline void add_lattice_options(CLI::App& app, std::string& cells, std::string& spacing, const std::string& extent,
                                const std::string& cells_help = "")
{
  app.add_option("--cells", cells,
                 cells_help.empty() ? "N lattice cells along the longest side of " + extent : cells_help)
      ->type_name("N")
      ->group("Lattice");
  app.add_option("--spacing", spacing, "the lattice spacing (the side of a cell)")->type_name("h")->group("Lattice");
}

} // namespace biso_tools

#endif // BISO_TOOLS_CLI_H
