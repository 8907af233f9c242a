// What the MPI drivers (csg_distributed.cpp, tbiso_distributed.cpp) share:
// MPI's start and end around the shared command line of cli.h (every rank
// parses the same argv, so all fail or none; only rank 0 reports), and the
// per-rank statistics, gathered on rank 0 into a table and the JSON summary.

#ifndef BISO_TOOLS_MPI_DRIVER_H
#define BISO_TOOLS_MPI_DRIVER_H

#include "cli.h"

#include <mpi.h>

#include <sys/resource.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace biso_tools {
namespace mpi {

struct Ranks
{
  int rank = 0, size = 1;
};

/// Tool::run() between MPI_Init_thread and MPI_Finalize.
inline int run_distributed(Tool& tool, int argc, char** argv, const std::function<void()>& check,
                           const std::function<int(const Ranks&)>& body)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  Ranks ranks;
  MPI_Comm_rank(MPI_COMM_WORLD, &ranks.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks.size);
  tool.set_root(ranks.rank == 0);
  const int status = tool.run(argc, argv, check, [&] { return body(ranks); });
  MPI_Finalize();
  return status;
}

/// The whole `<tool> --distributed` entry point of a tool whose command line
/// is `Options` (read from `Option_text`): its options, then the checks of
/// the distributed run (`check(tool, options, text)`) and the run on every
/// rank (`run(tool, options, ranks)`), between MPI_Init_thread and MPI_Finalize.
template <typename Options, typename Option_text, typename AddOptions, typename Check, typename Run>
int distributed_main(const char* name, const std::string& description, int argc, char** argv,
                     const AddOptions& add_options, const Check& check, const Run& run)
{
  Tool tool(name, description);
  Options options;
  Option_text text;
  add_options(tool, options, text);
  return run_distributed(
      tool, argc, argv, [&] { check(tool, options, text); },
      [&](const Ranks& ranks) { return run(tool, options, ranks); });
}

inline double peak_resident_megabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

/// One row of named numbers per rank.
struct Rank_table
{
  std::vector<std::string> names;
  std::vector<double> all; // rank-major, on rank 0 only

  const double* row(int rank) const { return all.data() + names.size() * std::size_t(rank); }
};

/// Gathers every rank's `mine` (one value per name) on rank 0.
inline Rank_table gather_on_root(const std::vector<std::string>& names, const std::vector<double>& mine,
                                 const Ranks& ranks)
{
  Rank_table table{names, std::vector<double>(mine.size() * std::size_t(ranks.size))};
  MPI_Gather(mine.data(), int(mine.size()), MPI_DOUBLE, table.all.data(), int(mine.size()), MPI_DOUBLE, 0,
             MPI_COMM_WORLD);
  return table;
}

/// The table as the JSON array `ranks` of the summary: one object per rank.
inline void set_json_ranks(Tool& tool, const Rank_table& table, int size)
{
  std::string rows = "[";
  for(int r = 0; r < size; ++r)
  {
    Json_object row;
    row.set("rank", r);
    for(std::size_t k = 0; k < table.names.size(); ++k)
      row.set(table.names[k], table.row(r)[k]);
    rows += (r ? ", " : "") + row.str();
  }
  tool.summary().set_raw("ranks", rows + "]");
}

} // namespace mpi
} // namespace biso_tools

#endif // BISO_TOOLS_MPI_DRIVER_H
