// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_SCALAR_FIELDS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_SCALAR_FIELDS_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// `N` scalar fields sampled at the vertices of a tetrahedral domain, stored
/// vertex-major: the `N` values of vertex `v` are contiguous, at
/// `data()[v * N]`.  This is also the order of the raw binary file layout
/// (see `IO/scalar_fields.h`), so that a slab of grid layers is one
/// contiguous range of memory or of a file.
///
/// A field is piecewise linear: linear inside every tetrahedron, defined by
/// its values at the tetrahedron's corners.  The literal `fi` of a
/// `Boolean_expression` is the region `f_i < 0`, `!fi` the region `f_i > 0`.
class Scalar_fields
{
public:
  Scalar_fields() = default;

  /// `number_of_fields` fields over `number_of_vertices` vertices, all zero.
  Scalar_fields(std::size_t number_of_vertices, std::size_t number_of_fields)
    : m_number_of_vertices(number_of_vertices), m_number_of_fields(number_of_fields),
      m_values(number_of_vertices * number_of_fields, 0.)
  {
    if(number_of_fields > 64)
      throw Invalid_input_error("at most 64 scalar fields are supported, got " +
                                std::to_string(number_of_fields));
  }

  /// Takes `values` (vertex-major, `number_of_vertices * number_of_fields` entries).
  Scalar_fields(std::size_t number_of_fields, std::vector<double> values)
    : m_number_of_fields(number_of_fields), m_values(std::move(values))
  {
    if(number_of_fields == 0 || number_of_fields > 64)
      throw Invalid_input_error("the number of scalar fields must be between 1 and 64, got " +
                                std::to_string(number_of_fields));
    if(m_values.size() % number_of_fields != 0)
      throw Invalid_input_error("the number of field values (" + std::to_string(m_values.size()) +
                                ") is not a multiple of the number of fields (" +
                                std::to_string(number_of_fields) + ")");
    m_number_of_vertices = m_values.size() / number_of_fields;
  }

  std::size_t number_of_vertices() const { return m_number_of_vertices; }
  std::size_t number_of_fields() const { return m_number_of_fields; }

  double value(std::size_t vertex, std::size_t field) const
  {
    return m_values[vertex * m_number_of_fields + field];
  }
  double& value(std::size_t vertex, std::size_t field)
  {
    return m_values[vertex * m_number_of_fields + field];
  }

  /// The `number_of_fields()` values of `vertex`.
  const double* values_at(std::size_t vertex) const { return m_values.data() + vertex * m_number_of_fields; }

  const std::vector<double>& data() const { return m_values; }
  std::vector<double>& data() { return m_values; }

  /// \throws Non_finite_value_error naming the first NaN or infinite value.
  void check_finite() const
  {
    for(std::size_t k = 0; k < m_values.size(); ++k)
      if(!std::isfinite(m_values[k]))
        throw Non_finite_value_error("field " + std::to_string(k % m_number_of_fields) +
                                     " has a non-finite value (" + std::to_string(m_values[k]) +
                                     ") at vertex " + std::to_string(k / m_number_of_fields));
  }

private:
  std::size_t m_number_of_vertices = 0;
  std::size_t m_number_of_fields = 0;
  std::vector<double> m_values;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_SCALAR_FIELDS_H
