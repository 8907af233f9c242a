// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Shared by the two translation units of the Python module: numpy arrays in
// (checked, viewed without copying when they already are C-contiguous arrays
// of the right type) and out (numpy arrays that own the std::vector the
// library filled, through a capsule), and the file-error exception.

#ifndef BOOLEAN_ISOSURFACING_PYTHON_BINDINGS_H
#define BOOLEAN_ISOSURFACING_PYTHON_BINDINGS_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/task_arena.h>
#endif

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

namespace biso_python {

namespace py = pybind11;
namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

// Output points are returned as the buffer of the library's
// std::vector<Point_3>: Epick stores a point as three doubles and nothing else.
static_assert(sizeof(Point_3) == 3 * sizeof(double), "Epick::Point_3 must be three doubles");
static_assert(sizeof(std::size_t) == sizeof(std::int64_t), "64-bit indices expected");

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style> Index_array;

/// The library's progress callback (CGAL's `callback` named parameter),
/// used to make long calls interruptible: called from the calling thread
/// between batches of work, it takes the GIL back for a moment and lets
/// Python run its signal handlers, so that Ctrl-C (KeyboardInterrupt) stops
/// the call there.  It never asks the library to cancel: the exception does.
struct Check_python_signals
{
  bool operator()(double) const
  {
    py::gil_scoped_acquire gil;
    if(PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    return true;
  }
};

/// `Check_python_signals` as the type of CGAL's `callback` named parameter.
inline std::function<bool(double)> python_signals_callback()
{
  return std::function<bool(double)>(Check_python_signals());
}

/// A file that cannot be opened: becomes OSError(errno, message, path), so
/// FileNotFoundError / PermissionError where errno says so.
struct File_error : std::runtime_error
{
  File_error(int error_number, const std::string& message, const std::string& path)
    : std::runtime_error(message), error_number(error_number), path(path)
  {}
  int error_number;
  std::string path;
};

/// Throws File_error unless `path` is a regular file that can be opened for reading.
inline void check_readable(const std::string& path)
{
  struct stat info;
  errno = 0;
  if(stat(path.c_str(), &info) != 0)
    throw File_error(errno, "cannot open the file for reading", path);
  if(S_ISDIR(info.st_mode))
    throw File_error(EISDIR, "cannot open the file for reading: it is a directory", path);
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw File_error(errno != 0 ? errno : EACCES, "cannot open the file for reading", path);
}

/// Throws File_error unless `path` can be opened for writing (it is created,
/// empty if new; the writer then truncates it).
inline void check_writable(const std::string& path)
{
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::app);
  if(!out)
    throw File_error(errno != 0 ? errno : EACCES, "cannot open the file for writing", path);
}

/// A C-contiguous float64 array of shape (n, columns) (or (n,) when
/// columns == 0 is allowed as a 1-D array), converted only if needed; with
/// `check_finite`, a NaN or infinite value raises Non_finite_value_error
/// naming its row.
inline Double_array as_double_rows(const py::handle& object, std::size_t columns, const char* name,
                                   bool check_finite = true)
{
  if(object.is_none())
    throw BI::Invalid_input_error(std::string(name) + " is None");
  Double_array array;
  try
  {
    array = py::cast<Double_array>(object);
  }
  catch(const py::cast_error&)
  {
    throw BI::Invalid_input_error(std::string(name) + " is not an array of numbers");
  }
  if(!array)
    throw BI::Invalid_input_error(std::string(name) + " is not an array of numbers");
  if(array.ndim() != 2 || std::size_t(array.shape(1)) != columns)
    throw BI::Invalid_input_error(std::string(name) + " must have shape (n, " + std::to_string(columns) +
                                  "), got " + [&] {
                                    std::string s = "(";
                                    for(py::ssize_t d = 0; d < array.ndim(); ++d)
                                      s += (d ? ", " : "") + std::to_string(array.shape(d));
                                    return s + (array.ndim() == 1 ? ",)" : ")");
                                  }());
  if(check_finite)
  {
    const double* data = array.data();
    const std::size_t total = std::size_t(array.size());
    for(std::size_t i = 0; i < total; ++i)
      if(!std::isfinite(data[i]))
        throw BI::Non_finite_value_error(std::string(name) + " row " + std::to_string(i / columns) +
                                         " has a non-finite value (" + std::to_string(data[i]) + ")");
  }
  return array;
}

/// An integer array of shape (m, columns), as C-contiguous int64 (a view
/// when it already is one); float arrays are refused rather than truncated.
/// Every index must be in [0, number_of_points) unless number_of_points is
/// the maximum of std::size_t (no check).
inline Index_array as_index_rows(const py::handle& object, std::size_t columns, const char* name,
                                 std::size_t number_of_points, const char* point_name = "V")
{
  if(object.is_none())
    throw BI::Invalid_input_error(std::string(name) + " is None");
  py::array array = py::array::ensure(object);
  if(!array)
    throw BI::Invalid_input_error(std::string(name) + " is not an array of indices");
  const char kind = array.dtype().kind();
  if(array.size() != 0 && kind != 'i' && kind != 'u')
    throw BI::Invalid_input_error(std::string(name) + " must be an array of integers, got dtype " +
                                  std::string(py::str(array.dtype())));
  if(array.ndim() != 2 || std::size_t(array.shape(1)) != columns)
  {
    std::string shape = "(";
    for(py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(array.shape(d));
    shape += array.ndim() == 1 ? ",)" : ")";
    throw BI::Invalid_input_error(std::string(name) + " must have shape (m, " + std::to_string(columns) +
                                  "), got " + shape);
  }
  Index_array indices = Index_array::ensure(array);
  if(!indices)
    throw BI::Invalid_input_error(std::string(name) + " cannot be converted to int64 indices");
  if(number_of_points != std::size_t(-1))
  {
    const std::int64_t* data = indices.data();
    const std::size_t total = std::size_t(indices.size());
    for(std::size_t i = 0; i < total; ++i)
      if(data[i] < 0 || std::uint64_t(data[i]) >= number_of_points)
        throw BI::Invalid_input_error(std::string(name) + " row " + std::to_string(i / columns) + " refers to " +
                                      point_name + " row " + std::to_string(data[i]) + ", but there are " +
                                      std::to_string(number_of_points));
  }
  return indices;
}

/// A numpy array of `shape` that owns `values` (moved to the heap and freed
/// with the array): no copy.  `Scalar` is the element type numpy sees;
/// `Container::value_type` must be an array of `Scalar`s (layout-checked by
/// the caller).
template <typename Scalar, typename Container>
py::array_t<Scalar> owning_array(Container&& values, std::vector<py::ssize_t> shape)
{
  typedef std::decay_t<Container> Vector;
  auto* heap = new Vector(std::move(values));
  py::capsule owner(heap, [](void* p) { delete static_cast<Vector*>(p); });
  return py::array_t<Scalar>(shape, reinterpret_cast<const Scalar*>(heap->data()), owner);
}

/// (n, 3) float64 array owning the points.
inline py::array_t<double> points_array(std::vector<Point_3>&& points)
{
  const py::ssize_t n = py::ssize_t(points.size());
  return owning_array<double>(std::move(points), {n, 3});
}

inline py::array_t<double> points_array(std::vector<std::array<double, 3>>&& points)
{
  const py::ssize_t n = py::ssize_t(points.size());
  return owning_array<double>(std::move(points), {n, 3});
}

/// (m, K) int64 array owning the index rows (size_t and int64 share their
/// representation for values below 2^63, and may alias).
template <std::size_t Columns>
py::array_t<std::int64_t> index_array(std::vector<std::array<std::size_t, Columns>>&& rows)
{
  const py::ssize_t m = py::ssize_t(rows.size());
  return owning_array<std::int64_t>(std::move(rows), {m, py::ssize_t(Columns)});
}

inline py::array_t<std::int64_t> index_array(std::vector<std::size_t>&& values)
{
  const py::ssize_t m = py::ssize_t(values.size());
  return owning_array<std::int64_t>(std::move(values), {m});
}

/// Points of a checked (n, 3) array, copied to Point_3 (for library calls
/// that own their points).
inline std::vector<Point_3> copy_points(const Double_array& V)
{
  std::vector<Point_3> points;
  points.reserve(std::size_t(V.shape(0)));
  const double* d = V.data();
  for(py::ssize_t i = 0; i < V.shape(0); ++i)
    points.emplace_back(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
  return points;
}

/// A list of polygons (each a sequence of indices) or an (m, k) index array,
/// as vectors of indices, each checked against `number_of_points`.
std::vector<std::vector<std::size_t>> polygons_from(const py::handle& object, std::size_t number_of_points,
                                                    const char* name = "polygons");

/// Polygons as a list of 1-D int64 arrays.
py::list polygons_to_list(const std::vector<std::vector<std::size_t>>& polygons);

/// Runs `f` with at most `threads` TBB worker threads (0: all).  The
/// library's parallel code reads the arena's concurrency, so threads=1 runs
/// the parallel code path on one thread, with the same output.
template <typename F>
auto with_threads(int threads, F&& f)
{
  if(threads < 0)
    throw BI::Invalid_input_error("threads must be >= 0 (0: all cores), got " + std::to_string(threads));
#ifdef CGAL_LINKED_WITH_TBB
  if(threads > 0)
  {
    tbb::task_arena arena(threads);
    return arena.execute(std::forward<F>(f));
  }
#endif
  return f();
}

void bind_tbiso(py::module_& m);

} // namespace biso_python

#endif // BOOLEAN_ISOSURFACING_PYTHON_BINDINGS_H
