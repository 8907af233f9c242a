// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H

#include <CGAL/Boolean_isosurfacing_3/internal/clear_output_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_csg_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Builder.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Marching Cubes CSG: the boundary of the solid `expression(meshes)`,
 * sampled on `lattice`, as a triangle soup.
 *
 * Every lattice point is classified exactly inside/outside each mesh
 * (`Lattice_classifier_3`, with its symbolic perturbation for points on a
 * mesh); its *output state* is `expression.evaluate(mask)` with bit m of
 * `mask` set iff the point is inside mesh m.  Every lattice edge whose two
 * ends have different output states gets one vertex: walking the edge from
 * its inside end through the crossings of all meshes with the edge (ordered
 * by position), the first crossing where the state changes (the seed's
 * INT_POINT, generalised).  Each cube is triangulated by
 * `Marching_cubes_table` from the states of its 8 corners.
 *
 * Guarantees: the output is a closed, 2-manifold, outward-oriented triangle
 * soup whenever `statistics.boundary_points_inside == 0` (see
 * `Marching_cubes_csg_statistics`): its topology is decided by exact
 * predicates only, and vertices are welded by lattice edge.  Vertex
 * positions are the crossing points computed in double, clamped to their
 * edge; a vertex may therefore coincide with a lattice point (or another
 * vertex) when a mesh passes exactly through a lattice point.  The output is
 * identical for `Sequential_tag` and `Parallel_tag`.
 *
 * Vertices are numbered by z plane, then by edge id 3 * (i + nx * j) + axis
 * of the edge's lower end; triangles by z layer, then by cube, then in table
 * order.
 *
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (TBB)
 * \tparam TriangleMeshRange a range of `FaceListGraph`s with triangle faces
 *         (or `std::reference_wrapper`s to them), or of `Triangle_soup_3`s,
 *         as for `Lattice_classifier_3`
 * \tparam PointRange a container with `push_back()` of points constructible
 *         from three doubles (or a `std::array<double, 3>`)
 * \tparam TriangleRange a container with `push_back()` of `std::array<I, 3>`
 *         or of a container of indices with `push_back()`
 *
 * \param lattice the domain: the sampling lattice (see `Regular_lattice_3::enclosing()`)
 * \param meshes the closed triangle meshes, variable m of `expression` is mesh m
 * \param expression a Boolean expression with `meshes.size()` variables
 * \param points, triangles the output soup; both are cleared first (the
 *        package's rule for every output)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction done, from the
 *       calling thread; returning `false` cancels the run with `Operation_cancelled_error`}
 *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_maps}
 *     \cgalParamDescription{`Boolean_isosurfacing::parameters::vertex_point_maps`: one
 *       `ReadablePropertyMap` per mesh (map m for mesh m), giving the points of its vertices}
 *     \cgalParamType{a range of property maps} \cgalParamDefault{each mesh's `vertex_point` map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_memory_bytes}
 *     \cgalParamDescription{refuse to start when the estimated memory exceeds it}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{8 GiB}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sharp_features}
 *     \cgalParamDescription{Extended Marching Cubes feature vertices, creases and corners from the
 *       exact crossing normals (doc/Boolean_isosurfacing_3/features.md); `false`: plain Marching Cubes}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{feature_angle}
 *     \cgalParamDescription{a polygon whose crossing normals differ by more than this many degrees
 *       gets a feature vertex; in (0, 180)}
 *     \cgalParamType{`double`} \cgalParamDefault{30}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sliver_edge_length}
 *     \cgalParamDescription{edges shorter than this many cells from an edge point to another
 *       edge point or to a feature vertex are collapsed (link condition, no triangle turned
 *       over, a feature vertex never moved); in [0, 0.5)}
 *     \cgalParamType{`double`} \cgalParamDefault{0.15 with sharp features, 0 without}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sharp_feature_output}
 *     \cgalParamDescription{receives the crease edges and corner vertices (cleared first)}
 *     \cgalParamType{`Marching_cubes_csg_features*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{resolution_check}
 *     \cgalParamDescription{judge every input component against the lattice
 *       (`Marching_cubes_csg_statistics::under_resolved_components`)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * With sharp features the vertex numbering above holds for the edge
 * vertices; the feature vertices follow them, and short-edge collapses
 * renumber the result compactly.
 *
 * \throws Operation_cancelled_error if the callback returned `false`.
 * \throws Invalid_input_error if `expression.number_of_variables() !=
 * meshes.size()`, if `vertex_point_maps` has not one map per mesh, for a feature angle outside (0, 180) or a sliver length
 * outside [0, 0.5); the exceptions of `Lattice_classifier_3::classify()`.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange, typename PointRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::Is_named_function_parameters<TriangleRange>::value>>
Marching_cubes_csg_statistics marching_cubes_csg(const Regular_lattice_3& lattice, const TriangleMeshRange& meshes,
                                                 const Boolean_expression& expression, PointRange& points,
                                                 TriangleRange& triangles,
                                                 const NamedParameters& np = parameters::default_values())
{
  typedef typename PointRange::value_type Point;
  typedef typename TriangleRange::value_type Triangle;
  const auto start = std::chrono::steady_clock::now();
  internal::Csg_features features;
  Marching_cubes_csg_statistics statistics;
  if constexpr(std::is_same<PointRange, std::vector<std::array<double, 3>>>::value &&
               internal::Is_index_triple_vector<TriangleRange>::value)
  {
    // The package's own soup types: written in place, no copy.
    statistics = internal::marching_cubes_csg_soup<ConcurrencyTag>(meshes, expression, lattice, points, triangles,
                                                                  features, np);
  }
  else
  {
    std::vector<std::array<double, 3>> soup_points;
    std::vector<std::array<std::size_t, 3>> soup_triangles;
    statistics = internal::marching_cubes_csg_soup<ConcurrencyTag>(meshes, expression, lattice, soup_points,
                                                                  soup_triangles, features, np);
    points.clear();
    triangles.clear();
    for(const std::array<double, 3>& p : soup_points)
      points.push_back(internal::make_output_point<Point>(p));
    std::vector<std::array<double, 3>>().swap(soup_points);
    for(const std::array<std::size_t, 3>& t : soup_triangles)
      triangles.push_back(internal::make_output_triangle<Triangle>(t));
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::sharp_feature_output_t>::value)
  {
    Marching_cubes_csg_features* output = parameters::get_parameter(np, internal_np::sharp_feature_output);
    if(output != nullptr)
    {
      output->crease_edges = std::move(features.crease_edges);
      output->corner_vertices = std::move(features.corner_vertices);
    }
  }
  statistics.seconds_triangulation += internal::seconds_since(start) - statistics.seconds_classification -
                                      statistics.seconds_edges - statistics.seconds_triangulation;
  statistics.seconds = internal::seconds_since(start);
  internal::progress_of(np).report(1.0);
  return statistics;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * As the triangle soup overload, into `output`, which is cleared first.
 * The sharp features go to the maps of the named parameters
 * `edge_is_constrained_map` (the crease edges are set to `true`) and
 * `vertex_is_constrained_map` (the corners are set to `true`); other edges
 * and vertices are not written.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{as for the soup overload; all its other named parameters apply too}
 *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{receives `true` for every crease edge of the output}
 *     \cgalParamType{a `WritablePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{receives `true` for every corner vertex of the output}
 *     \cgalParamType{a `WritablePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_patch_map}
 *     \cgalParamDescription{receives, for every face, the input mesh (variable of `expression`) whose surface
 *       it lies on: the mesh of the crossings its vertices are on, by majority (a face across the curve where
 *       two meshes meet takes the mesh of two of its vertices; one with a single edge vertex, around a
 *       feature vertex, takes that vertex's mesh)}
 *     \cgalParamType{a `WritablePropertyMap` from `face_descriptor` to an integer type} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_memory_bytes}
 *     \cgalParamDescription{refuse to start when the estimated memory exceeds it}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{8 GiB}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \tparam MutableFaceGraph a model of `MutableFaceGraph` whose vertex points
 *         are constructible from three doubles
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange, typename MutableFaceGraph,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<internal::Is_named_function_parameters<NamedParameters>::value>>
Marching_cubes_csg_statistics marching_cubes_csg(const Regular_lattice_3& lattice, const TriangleMeshRange& meshes,
                                                 const Boolean_expression& expression, MutableFaceGraph& output,
                                                 const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<
      typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type>::value_type Point;
  typedef boost::graph_traits<MutableFaceGraph> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  constexpr bool with_face_patches =
      !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  internal::Csg_features features;
  features.record_vertex_meshes = with_face_patches;
  const auto start = std::chrono::steady_clock::now();
  Marching_cubes_csg_statistics statistics =
      internal::marching_cubes_csg_soup<ConcurrencyTag>(meshes, expression, lattice, points, triangles, features, np);
  internal::clear_output_mesh(output);
  // As PMP::polygon_soup_to_polygon_mesh(), keeping the vertex of each point
  // for the feature maps.
  const auto vpm = get(CGAL::vertex_point, output);
  // MutableFaceGraph's reserve(): one allocation per property array (their
  // growth was 7 % of a 512-cell csg run); a closed soup has 3/2 edges per face.
  reserve(output, typename Graph_traits::vertices_size_type(points.size()),
          typename Graph_traits::edges_size_type(3 * triangles.size() / 2),
          typename Graph_traits::faces_size_type(triangles.size()));
  std::vector<vertex_descriptor> vertex(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex[i] = add_vertex(output);
    put(vpm, vertex[i], internal::make_output_point<Point>(points[i]));
  }
  std::vector<vertex_descriptor> face(3);
  for(const std::array<std::size_t, 3>& t : triangles)
  {
    for(int v = 0; v < 3; ++v)
      face[v] = vertex[t[v]];
    const auto f = CGAL::Euler::add_face(face, output);
    if(f == Graph_traits::null_face())
      throw std::logic_error("marching_cubes_csg: the output soup is not a 2-manifold (this is a bug)");
    if constexpr(with_face_patches)
      put(parameters::get_parameter(np, CGAL::internal_np::face_patch), f,
          internal::face_mesh(features.vertex_meshes, t));
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
  {
    auto ecm = parameters::get_parameter(np, CGAL::internal_np::edge_is_constrained);
    for(const std::array<std::size_t, 2>& e : features.crease_edges)
    {
      const auto h = halfedge(vertex[e[0]], vertex[e[1]], output);
      if(h.second)
        put(ecm, edge(h.first, output), true);
    }
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_is_constrained_t>::value)
  {
    auto vcm = parameters::get_parameter(np, CGAL::internal_np::vertex_is_constrained);
    for(std::size_t v : features.corner_vertices)
      put(vcm, vertex[v], true);
  }
  statistics.seconds_triangulation += internal::seconds_since(start) - statistics.seconds_classification -
                                      statistics.seconds_edges - statistics.seconds_triangulation;
  statistics.seconds = internal::seconds_since(start);
  internal::progress_of(np).report(1.0);
  return statistics;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H
