// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H

#include <CGAL/Boolean_isosurfacing_3/Post_processing_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/angle_raising_flips.h>
#include <CGAL/Boolean_isosurfacing_3/internal/post_process_without_self_intersections.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

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
 * Edges sharper than `sharp_edge_angle` that are not creases (a CAD
 * input's own edges where the crease network has a gap, the steps of a
 * ragged crease) are kept as constrained polylines too, so that the
 * remeshing does not round them off; they are not reported as creases.
 * Where a crease or such an edge turns by more than 45 degrees, its vertex
 * is held fixed, as the corners are, so that collapses along it do not cut
 * the bend off.
 *
 * The result is checked for self-intersections exactly
 * (`Polygon_mesh_processing::self_intersections()`), and for a lost part of
 * the input (an input vertex farther than `edge_length` / 4 from it).  Where
 * a wall or a gap is thinner than `edge_length`, a vertex projected back
 * onto the surface can land through the other sheet, and the wall can be
 * flattened; then the remeshing runs again from the input with the input's
 * faces within an edge length of there kept as they are, and after 4 such
 * runs the mesh is left as it was (`Post_processing_statistics::reverted`,
 * with a warning).  Caps (an angle above 160 degrees) left where the
 * remeshing meets the kept faces are flipped away where that is valid.
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
 *   \cgalParamNBegin{sharp_edge_angle}
 *     \cgalParamDescription{the angle, in degrees, between the normals of an edge's two faces above which
 *       the edge is kept as a constrained polyline even if it is not a crease; 0 keeps the creases only}
 *     \cgalParamType{`double`, in [0, 180]} \cgalParamDefault{50}
 *     \cgalParamExtra{a package parameter: `CGAL::Boolean_isosurfacing::parameters::sharp_edge_angle()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{iterations of split, collapse, flip, smoothing}
 *     \cgalParamType{`unsigned int`} \cgalParamDefault{5}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns what was done (the runs, the frozen faces, whether the mesh was
 *          left as it was).
 * \throws Invalid_input_error if `edge_length` is not positive and finite,
 *         `sharp_edge_angle` is not in [0, 180], or the mesh is not a closed
 *         triangle mesh.
 */
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Post_processing_statistics remesh_keeping_creases(TriangleMesh& mesh, double edge_length,
                                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
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
  const double sharp_edge_angle = choose_parameter(get_parameter(np, internal_np::sharp_edge_angle), 50.0);
  if(!(sharp_edge_angle >= 0 && sharp_edge_angle <= 180))
    throw Invalid_input_error("remesh_keeping_creases: the sharp edge angle must be in [0, 180] degrees, got " +
                              std::to_string(sharp_edge_angle));
  const auto process = [&](TriangleMesh& work, auto crease, auto corner, auto is_frozen) -> std::size_t {
    std::vector<face_descriptor> remeshed;
    for(const face_descriptor f : faces(work))
      if(!get(is_frozen, f))
        remeshed.push_back(f);
    // The constrained edges: 1 a crease, 2 only sharp.  The remeshing
    // copies an edge's value to the halves it splits it into, so the creases
    // are told apart from the other sharp edges afterwards.
    // Why: with the creases alone, the first run at 128 cells left 36-1935
    // input vertices of 8 CSG results farther than a quarter edge (fandisk
    // united with a moved copy: 159 of 164 on edges sharper than 60 degrees
    // that are not creases), hence 3-4 runs and their frozen Marching Cubes
    // faces.  50 degrees: 14 runs for the 8 results, against 27 with the
    // creases alone, 13 at 40 degrees (more triangles under 20 degrees on
    // the organic results) and 17 at 60.
    auto sharp = get(CGAL::dynamic_edge_property_t<bool>(), work);
    for(const edge_descriptor e : edges(work))
      put(sharp, e, false);
    if(sharp_edge_angle > 0)
      CGAL::Polygon_mesh_processing::detect_sharp_edges(work, sharp_edge_angle, sharp);
    auto constrained = get(CGAL::dynamic_edge_property_t<unsigned char>(), work);
    for(const edge_descriptor e : edges(work))
      put(constrained, e, get(crease, e) ? 1 : (get(sharp, e) ? 2 : 0));
    // Where a crease meets one other sharp edge, the remeshing sees one
    // polyline and would collapse the crease's end along the other edge;
    // where a polyline turns by more than 45 degrees, a collapse along it
    // cuts the bend off, by up to two thirds of an edge times the sine of
    // half the turn: more than the quarter edge the check below allows.
    // Such vertices stay where they are, as the corners do.  (64-cell
    // sweep, 19 results: 32 runs with 55 far input vertices without the
    // bends, 26 runs with 17 with them; 30 degrees gave as many runs and
    // more triangles under 20 degrees.)
    auto fixed = get(CGAL::dynamic_vertex_property_t<bool>(), work);
    const auto vpm = get(CGAL::vertex_point, work);
    const auto bends = [&](const vertex_descriptor v, const vertex_descriptor a, const vertex_descriptor b) {
      const auto u = get(vpm, v) - get(vpm, a);
      const auto w = get(vpm, b) - get(vpm, v);
      const double cos_45 = 0.70710678118654752;
      return CGAL::to_double(u * w) < cos_45 * std::sqrt(CGAL::to_double(u.squared_length() * w.squared_length()));
    };
    for(const vertex_descriptor v : vertices(work))
    {
      unsigned char seen = 0;
      std::size_t polyline_edges = 0;
      vertex_descriptor ends[2];
      for(const auto h : CGAL::halfedges_around_target(v, work))
      {
        const unsigned char c = get(constrained, edge(h, work));
        seen |= static_cast<unsigned char>(1u << c);
        if(c != 0 && polyline_edges++ < 2)
          ends[polyline_edges - 1] = source(h, work);
      }
      put(fixed, v,
          get(corner, v) || (seen & 6) == 6 || (polyline_edges == 2 && bends(v, ends[0], ends[1])));
    }
    CGAL::Polygon_mesh_processing::isotropic_remeshing(
        remeshed, edge_length, work,
        CGAL::parameters::edge_is_constrained_map(constrained)
            .vertex_is_constrained_map(fixed)
            .number_of_iterations(iterations)
            .protect_constraints(false));
    internal::flip_caps(work, constrained);
    for(const edge_descriptor e : edges(work))
      put(crease, e, get(constrained, e) == 1);
    return 0;
  };
  // A result that self-intersects, or that lost a part of the input (an
  // input vertex farther than a quarter edge from it: a wall thinner than an
  // edge flattened), is redone with the input frozen within an edge length
  // of where it did.  (Half an edge let the tray's walls, thinner than that,
  // lose 2-17 % of the volume.)
  return internal::post_process_without_self_intersections(mesh, ecm, vcm, edge_length, 0.25 * edge_length,
                                                           "remesh_keeping_creases", process);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_REMESH_KEEPING_CREASES_H
