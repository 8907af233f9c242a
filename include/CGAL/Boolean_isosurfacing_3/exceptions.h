// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_EXCEPTIONS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Base class of every error this package reports about its *input*: the
/// caller gave something the algorithm cannot give a meaningful answer for.
/// Catch this one type to handle all of them; catch a derived type to react
/// to one problem.  `what()` always names the problem (and, where there is
/// one, the offending element).
class Invalid_input_error : public std::invalid_argument
{
public:
  explicit Invalid_input_error(const std::string& message)
    : std::invalid_argument(message) {}
};

/// The mesh, polygon soup or point set has no element at all.
class Empty_input_error : public Invalid_input_error
{
public:
  explicit Empty_input_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// A face that should be a triangle has another number of vertices.
class Non_triangle_face_error : public Invalid_input_error
{
public:
  explicit Non_triangle_face_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// The surface has a border (an edge with only one incident face), or, for a
/// polygon soup, an edge that is not matched by exactly one oppositely
/// oriented edge: it does not bound a solid.
class Open_mesh_error : public Invalid_input_error
{
public:
  explicit Open_mesh_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// A coordinate or a field value is NaN or infinite.
class Non_finite_value_error : public Invalid_input_error
{
public:
  explicit Non_finite_value_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// A closed surface is oriented inward (its signed volume is negative) where
/// an outward one was required.
class Inward_oriented_mesh_error : public Invalid_input_error
{
public:
  explicit Inward_oriented_mesh_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// Two faces of the surface intersect where a simple surface was required.
class Self_intersecting_mesh_error : public Invalid_input_error
{
public:
  explicit Self_intersecting_mesh_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// A lattice (or another discretisation) would have more points than the
/// documented limit, or would need more memory than the caller allows.
class Lattice_too_large_error : public Invalid_input_error
{
public:
  explicit Lattice_too_large_error(const std::string& message)
    : Invalid_input_error(message) {}
};

/// A textual input (a Boolean expression, a line of a point file, ...)
/// could not be parsed.  `position()` is the 0-based character offset (or
/// the 1-based line number, as the message states) of the first problem.
class Parse_error : public Invalid_input_error
{
public:
  Parse_error(const std::string& message, std::size_t position)
    : Invalid_input_error(message), m_position(position) {}

  std::size_t position() const { return m_position; }

private:
  std::size_t m_position;
};

/// Thrown by every algorithm of the package when the `callback` named
/// parameter (`CGAL::parameters::callback`) returns `false`: the run is
/// abandoned and the outputs are left in an unspecified but valid state
/// (they may be empty or partly filled).  It is not an input error.
class Operation_cancelled_error : public std::runtime_error
{
public:
  /// `message` names the algorithm that was cancelled.
  explicit Operation_cancelled_error(const std::string& message)
    : std::runtime_error(message) {}
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_EXCEPTIONS_H
