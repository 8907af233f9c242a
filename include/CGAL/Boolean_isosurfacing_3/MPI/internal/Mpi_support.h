// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MPI_INTERNAL_MPI_SUPPORT_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MPI_INTERNAL_MPI_SUPPORT_H

// The MPI plumbing shared by the distributed drivers: agreeing on errors (so
// that a failure on one rank never leaves the others waiting in a
// collective), prefix sums, the one neighbour exchange, and byte-range file
// I/O in pieces below MPI's int counts.

// Only MPI's C interface is used: skip the deprecated C++ bindings (and their warnings).
#ifndef OMPI_SKIP_MPICXX
#  define OMPI_SKIP_MPICXX 1
#endif
#ifndef MPICH_SKIP_MPICXX
#  define MPICH_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Thrown on every rank of a distributed run when some rank failed; the
/// message is that of the lowest failing rank.
class Distributed_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

namespace internal {
namespace mpi {

inline void check(int code, const char* what)
{
  if(code != MPI_SUCCESS)
  {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(std::string(what) + ": " + std::string(text, std::size_t(length)));
  }
}

// Runs `f` on every rank; if it threw on any rank, every rank throws
// Distributed_error with the message of the lowest failing rank.  Every
// phase between two collectives goes through this.
template <typename F>
void on_all_ranks(MPI_Comm comm, const F& f)
{
  std::string message;
  bool failed = false;
  try
  {
    f();
  }
  catch(const std::bad_alloc&)
  {
    failed = true;
    message = "out of memory";
  }
  catch(const std::exception& e)
  {
    failed = true;
    message = e.what();
  }
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int first = failed ? rank : size, first_failed = size;
  MPI_Allreduce(&first, &first_failed, 1, MPI_INT, MPI_MIN, comm);
  if(first_failed == size)
    return;
  int length = int(message.size());
  MPI_Bcast(&length, 1, MPI_INT, first_failed, comm);
  message.resize(std::size_t(length));
  MPI_Bcast(&message[0], length, MPI_CHAR, first_failed, comm);
  throw Distributed_error(size > 1 ? "rank " + std::to_string(first_failed) + ": " + message : message);
}

inline std::uint64_t exclusive_sum(MPI_Comm comm, std::uint64_t value)
{
  std::uint64_t result = 0;
  MPI_Exscan(&value, &result, 1, MPI_UINT64_T, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank == 0 ? 0 : result; // MPI leaves rank 0's result undefined
}

inline std::uint64_t total_sum(MPI_Comm comm, std::uint64_t value)
{
  std::uint64_t result = 0;
  MPI_Allreduce(&value, &result, 1, MPI_UINT64_T, MPI_SUM, comm);
  return result;
}

inline double maximum(MPI_Comm comm, double value)
{
  double result = 0;
  MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_MAX, comm);
  return result;
}

// Sends `message` to rank `to` and returns what rank `from` sent (either may
// be MPI_PROC_NULL: nothing sent, an empty result).  One message each way;
// the receiver learns the length by probing.
inline std::vector<std::uint64_t> exchange(MPI_Comm comm, const std::vector<std::uint64_t>& message, int to, int from)
{
  const int tag = 16;
  if(message.size() > std::size_t(INT_MAX))
    throw std::runtime_error("a boundary message of " + std::to_string(message.size()) +
                             " words exceeds MPI's int counts: use more ranks");
  MPI_Request request = MPI_REQUEST_NULL;
  if(to != MPI_PROC_NULL)
    check(MPI_Isend(message.data(), int(message.size()), MPI_UINT64_T, to, tag, comm, &request), "MPI_Isend");
  std::vector<std::uint64_t> received;
  if(from != MPI_PROC_NULL)
  {
    MPI_Status status;
    check(MPI_Probe(from, tag, comm, &status), "MPI_Probe");
    int count = 0;
    MPI_Get_count(&status, MPI_UINT64_T, &count);
    received.resize(std::size_t(count));
    check(MPI_Recv(received.data(), count, MPI_UINT64_T, from, tag, comm, MPI_STATUS_IGNORE), "MPI_Recv");
  }
  if(to != MPI_PROC_NULL)
    check(MPI_Wait(&request, MPI_STATUS_IGNORE), "MPI_Wait");
  return received;
}

// Pieces of at most 1 GiB: MPI counts are ints.
constexpr std::size_t max_io_bytes = std::size_t(1) << 30;

inline void read_at(MPI_File file, std::uint64_t offset, void* data, std::size_t bytes, const std::string& name)
{
  char* p = static_cast<char*>(data);
  for(std::size_t done = 0; done < bytes;)
  {
    const int piece = int((std::min)(max_io_bytes, bytes - done));
    MPI_Status status;
    check(MPI_File_read_at(file, MPI_Offset(offset + done), p + done, piece, MPI_BYTE, &status),
          ("reading '" + name + "'").c_str());
    int got = 0;
    MPI_Get_count(&status, MPI_BYTE, &got);
    if(got != piece)
      throw std::runtime_error("'" + name + "': short read at byte " + std::to_string(offset + done));
    done += std::size_t(piece);
  }
}

inline void write_at(MPI_File file, std::uint64_t offset, const void* data, std::size_t bytes, const std::string& name)
{
  const char* p = static_cast<const char*>(data);
  for(std::size_t done = 0; done < bytes;)
  {
    const int piece = int((std::min)(max_io_bytes, bytes - done));
    check(MPI_File_write_at(file, MPI_Offset(offset + done), p + done, piece, MPI_BYTE, MPI_STATUS_IGNORE),
          ("writing '" + name + "'").c_str());
    done += std::size_t(piece);
  }
}

// A file opened by all ranks of `comm`, closed (collectively) on destruction.
class Shared_file
{
public:
  Shared_file(MPI_Comm comm, const std::string& name, int mode) : m_comm(comm), m_name(name)
  {
    // Collective; the outcome is the same on every rank, so a failure
    // throws everywhere.
    const int code = MPI_File_open(comm, name.c_str(), mode, MPI_INFO_NULL, &m_file);
    if(code != MPI_SUCCESS)
    {
      m_file = MPI_FILE_NULL;
      throw std::runtime_error("cannot open '" + name + ((mode & MPI_MODE_RDONLY) ? "' for reading" : "' for writing"));
    }
  }
  Shared_file(const Shared_file&) = delete;
  Shared_file& operator=(const Shared_file&) = delete;
  ~Shared_file()
  {
    if(m_file != MPI_FILE_NULL)
      MPI_File_close(&m_file);
  }
  MPI_File get() const { return m_file; }
  const std::string& name() const { return m_name; }
  std::uint64_t size() const
  {
    MPI_Offset s = 0;
    check(MPI_File_get_size(m_file, &s), "MPI_File_get_size");
    return std::uint64_t(s);
  }

private:
  MPI_Comm m_comm;
  std::string m_name;
  MPI_File m_file = MPI_FILE_NULL;
};

// A rank's temporary file: appended to, then read back in order once; removed
// on destruction.  The drivers keep a rank's part of the output there until
// the offsets are known, instead of in memory.
class Temporary_file
{
public:
  explicit Temporary_file(const std::string& name) : m_name(name)
  {
    m_out.open(name, std::ios::binary | std::ios::trunc);
    if(!m_out)
      throw std::runtime_error("cannot write the temporary file '" + name + "' (next to the output)");
  }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  ~Temporary_file()
  {
    m_out.close();
    m_in.close();
    std::remove(m_name.c_str());
  }
  /// Appends `bytes`; returns their number.
  std::size_t append(const std::string& bytes)
  {
    m_out.write(bytes.data(), std::streamsize(bytes.size()));
    return bytes.size();
  }
  /// Ends the writing; the reading starts at the beginning.
  void finish()
  {
    m_out.close();
    if(!m_out)
      throw std::runtime_error("failed writing the temporary file '" + m_name + "'");
    m_in.open(m_name, std::ios::binary);
    if(!m_in)
      throw std::runtime_error("cannot read the temporary file '" + m_name + "'");
  }
  /// Appends the next `bytes` bytes to `out`.
  void read(std::string& out, std::size_t bytes)
  {
    const std::size_t at = out.size();
    out.resize(at + bytes);
    if(bytes > 0 && !m_in.read(&out[at], std::streamsize(bytes)))
      throw std::runtime_error("short read in the temporary file '" + m_name + "'");
  }

private:
  std::string m_name;
  std::ofstream m_out;
  std::ifstream m_in;
};

// Writes a file made of sections, each the concatenation of the ranks' parts
// in rank order: for every section the ranks produce their part in pieces
// (`produce(section, piece)` appends up to ~64 MiB per call and returns
// false when done) after announcing its size.  Offsets come from one
// exclusive prefix sum per section.  The file is truncated to its size.
inline void write_sections(MPI_Comm comm, const std::string& name, const std::vector<std::uint64_t>& part_bytes,
                           const std::function<bool(std::size_t, std::string&)>& produce)
{
  const std::size_t S = part_bytes.size();
  std::vector<std::uint64_t> offsets(S), totals(S);
  MPI_Exscan(part_bytes.data(), offsets.data(), int(S), MPI_UINT64_T, MPI_SUM, comm);
  MPI_Allreduce(part_bytes.data(), totals.data(), int(S), MPI_UINT64_T, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if(rank == 0)
    std::fill(offsets.begin(), offsets.end(), 0);
  std::uint64_t base = 0;
  for(std::size_t s = 0; s < S; ++s)
  {
    offsets[s] += base;
    base += totals[s];
  }
  std::unique_ptr<Shared_file> file;
  on_all_ranks(comm, [&] { file.reset(new Shared_file(comm, name, MPI_MODE_CREATE | MPI_MODE_WRONLY)); });
  on_all_ranks(comm, [&] { check(MPI_File_set_size(file->get(), MPI_Offset(base)), ("truncating '" + name + "'").c_str()); });
  on_all_ranks(comm, [&] {
    std::string piece;
    for(std::size_t s = 0; s < S; ++s)
    {
      std::uint64_t at = offsets[s], written = 0;
      bool more = true;
      while(more)
      {
        piece.clear();
        more = produce(s, piece);
        write_at(file->get(), at, piece.data(), piece.size(), name);
        at += piece.size();
        written += piece.size();
      }
      if(written != part_bytes[s])
        throw std::logic_error("section " + std::to_string(s) + " of '" + name + "': " + std::to_string(written) +
                               " bytes written, " + std::to_string(part_bytes[s]) + " announced (this is a bug)");
    }
  });
  on_all_ranks(comm, [&] { file.reset(); });
}

} // namespace mpi
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MPI_INTERNAL_MPI_SUPPORT_H
