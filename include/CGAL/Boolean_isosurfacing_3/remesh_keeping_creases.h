// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Isotropic remeshing of a closed triangle mesh that keeps its creases and
 * corners, typically a `marching_cubes_csg()` result (`--remesh` of the `csg`
 * tool): `CGAL::Polygon_mesh_processing::isotropic_remeshing()` towards edges
 * of length `edge_length`, with the crease edges as constrained polylines
 * (split and collapsed along themselves, never moved off them) and the
 * corners as constrained vertices (never moved or removed).  Marching Cubes
 * gives triangles of every shape; this gives nearly equilateral ones.
 *
 * \param mesh the closed triangle mesh, remeshed in place
 * \param edge_length the target edge length (for a CSG result, about the
 *        lattice spacing)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{the crease edges (`true`); kept up to date on the remeshed mesh}
 *     \cgalParamType{a `ReadWritePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{no crease}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{the corners (`true`)}
 *     \cgalParamType{a `ReadWritePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{no corner}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{iterations of split, collapse, flip, smoothing}
 *     \cgalParamType{`unsigned int`} \cgalParamDefault{5}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws Invalid_input_error if `edge_length` is not positive and finite or
 *         the mesh is not a closed triangle mesh.
 */
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void remesh_keeping_creases(TriangleMesh& mesh, double edge_length,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  if(!(edge_length > 0 && std::isfinite(edge_length)))
    throw Invalid_input_error("remesh_keeping_creases: the edge length must be positive and finite, got " +
                              std::to_string(edge_length));
  if(!CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    throw Invalid_input_error("remesh_keeping_creases: the mesh must be a closed triangle mesh");
  CGAL::Static_boolean_property_map<edge_descriptor, false> no_crease;
  CGAL::Static_boolean_property_map<vertex_descriptor, false> no_corner;
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained), no_crease);
  const auto vcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained), no_corner);
  const unsigned int iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5u);
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
      faces(mesh), edge_length, mesh,
      CGAL::parameters::edge_is_constrained_map(ecm).vertex_is_constrained_map(vcm).number_of_iterations(
          iterations).protect_constraints(false));
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H
