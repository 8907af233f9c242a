// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_POINT_SAMPLES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_POINT_SAMPLES_H

// One entry point for every point format the contouring tool accepts: the
// seed's `.pts` (IO/pts.h, also from a stream), `.xyz` and `.pwn` (read by
// IO/pts.h too, so that an error is one line naming the file and the line,
// unlike CGAL's reader, which prints two lines on std::cerr without the file
// name), and CGAL's other formats (`.ply`, `.off`, `.las` if built) through
// CGAL::IO::read_point_set into a Point_set_3, which keeps a normal map only
// when the file has normals.  (A separate header because IO/pts.h must stay
// light: it is standard-library only.)

#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace IO {

/*!
 * Reads `path` (".pts", ".xyz", ".pwn", or any extension CGAL::IO::read_point_set knows),
 * appending to `points` and, when the file has normals, to `normals`.
 * \returns whether the points came with normals.
 * \throws as read_pts() for `.pts`, `.xyz` and `.pwn`, the message prefixed
 *         with the file name; Invalid_input_error for a directory or if CGAL
 *         cannot read the file; Empty_input_error if it holds no point.
 */
namespace internal {

// Runs `read`, prefixing the message of any input error with the file name
// (the type, and the line of a Parse_error, are kept).
template <typename Read>
bool with_file_name(const std::string& path, Read read)
{
  const std::string prefix = "'" + path + "' ";
  try
  {
    return read();
  }
  catch(const Parse_error& e)
  {
    throw Parse_error(prefix + e.what(), e.position());
  }
  catch(const Non_finite_value_error& e)
  {
    throw Non_finite_value_error(prefix + e.what());
  }
  catch(const Empty_input_error& e)
  {
    throw Empty_input_error(prefix + e.what());
  }
  catch(const Invalid_input_error& e)
  {
    throw Invalid_input_error(prefix + e.what());
  }
}

} // namespace internal

template <typename Point_3, typename Vector_3>
bool read_point_samples(const std::string& path, std::vector<Point_3>& points, std::vector<Vector_3>& normals)
{
  std::string extension = path.substr(std::min(path.size(), path.find_last_of('.') + 1));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  std::error_code ec;
  if(std::filesystem::is_directory(path, ec))
    throw Invalid_input_error("cannot read '" + path + "': it is a directory");
  if(extension == "pts" || extension == "xyz" || extension == "pwn")
  {
    std::ifstream in(path);
    if(!in)
      throw Invalid_input_error("cannot open '" + path + "'");
    const IO::internal::Point_file_format format =
        extension == "pts" ? IO::internal::Point_file_format::PTS : IO::internal::Point_file_format::XYZ;
    return internal::with_file_name(path, [&] { return read_pts(in, points, normals, format); });
  }
  if(!std::ifstream(path)) // before CGAL, which would also print its own message
    throw Invalid_input_error("cannot open '" + path + "'");
  CGAL::Point_set_3<Point_3, Vector_3> point_set;
  if(!CGAL::IO::read_point_set(path, point_set))
    throw Invalid_input_error("cannot read the point set '" + path + "'");
  if(point_set.empty())
    throw Empty_input_error("no point in '" + path + "'");
  const bool has_normals = point_set.has_normal_map();
  for(auto index : point_set)
  {
    points.push_back(point_set.point(index));
    if(has_normals)
      normals.push_back(point_set.normal(index));
  }
  return has_normals;
}

} // namespace IO
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_IO_READ_POINT_SAMPLES_H
