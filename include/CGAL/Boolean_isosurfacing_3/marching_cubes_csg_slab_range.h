// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_SLAB_RANGE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_SLAB_RANGE_H

// Marching Cubes CSG on one range of cube layers [k0, k1) of a lattice, for
// callers that split the lattice themselves (one range per MPI rank): the
// building block of `MPI/distributed_marching_cubes_csg.h`, with no MPI
// dependency.
//
// Why it is the sequential result: the range classifies the sub-lattice of
// planes k0 .. k1 (`Regular_lattice_3::z_range()`: the same coordinate
// doubles), with only the triangles that can meet it.  Classification is by
// x lines, one plane at a time, and the crossings of an edge depend only on
// the edge, so every point and edge of the range gets the sequential state
// and vertex, bit for bit.
//
// Why the ranges weld by lattice-edge id: the sequential numbering is plane
// by plane, and in a plane by edge id 3 * (i + nx * j) + axis (the x and y
// edges of the plane and the z edges up to the next plane).  A range owns
// the vertices of its planes k0 .. k1 - 1 (and k1 for the last range); its
// cubes of layer k1 - 1 also use the x and y edges of plane k1, owned by the
// range above, which numbers them among its plane-k0 edges, z edges
// included.  So the range above sends down the sorted edge ids of its first
// plane's vertices (`bottom_edges`), and a top edge's global index is the
// offset of the range above plus its rank in that list.
//
// Plain Marching Cubes only: the sharp features of `marching_cubes_csg()`
// (doc/Boolean_isosurfacing_3/features.md) number their vertices after all
// edge vertices, flip edges across the faces between cubes (also between two
// ranges) and collapse short edges on the whole soup, none of which a range
// can do alone.  So here `sharp_features` defaults to false, and true is
// refused rather than silently ignored.

#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The surface of cube layers `[first_layer, last_layer)` of a lattice,
/// before welding with its neighbours.
struct Marching_cubes_csg_slab_range
{
  std::size_t first_layer = 0, last_layer = 0, number_of_layers = 0;
  /// The vertices this range owns (planes `first_layer .. last_layer - 1`,
  /// and plane `last_layer` for the last range), in the sequential order:
  /// they are one contiguous block of the output.
  std::vector<std::array<double, 3>> points;
  /// Index `t < points.size()`: an owned vertex; `t >= points.size()`: the
  /// vertex on lattice edge `top_edges[t - points.size()]` of plane `last_layer`.
  /// 32-bit: a range's own numbering, and 12 bytes a triangle instead of 24
  /// (a range of more than 2^32 vertices throws `Lattice_too_large_error`).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Edge ids `3 * (i + nx * j) + axis`, increasing, of the vertices of plane
  /// `first_layer` (x, y and z edges): the first `bottom_edges.size()` points.
  std::vector<std::uint64_t> bottom_edges;
  /// Edge ids of the x and y edges of plane `last_layer` that carry a vertex
  /// used here (empty for the last range), increasing.
  std::vector<std::uint64_t> top_edges;
  /// Their positions (for the volume, which needs whole triangles).
  std::vector<std::array<double, 3>> top_points;
  Marching_cubes_csg_statistics statistics;
  /// Triangles of the input meshes that can meet the range's planes.
  std::size_t number_of_input_triangles = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The global vertex index of each of `range.top_edges`, given `offset_above`
/// (the global index of the first vertex of the range above) and
/// `bottom_edges_above` (that range's `bottom_edges`).
/// \throws std::logic_error if a top edge is not among them (the two ranges
/// disagree on the classification: a bug).
inline std::vector<std::size_t> top_vertex_indices(const Marching_cubes_csg_slab_range& range,
                                                   const std::vector<std::uint64_t>& bottom_edges_above,
                                                   std::size_t offset_above)
{
  std::vector<std::size_t> global(range.top_edges.size());
  for(std::size_t t = 0; t < range.top_edges.size(); ++t)
  {
    const auto found = std::lower_bound(bottom_edges_above.begin(), bottom_edges_above.end(), range.top_edges[t]);
    if(found == bottom_edges_above.end() || *found != range.top_edges[t])
      throw std::logic_error("marching_cubes_csg_slab_range: lattice edge " + std::to_string(range.top_edges[t]) +
                             " of plane " + std::to_string(range.last_layer) +
                             " has a vertex below but not above (this is a bug)");
    global[t] = offset_above + std::size_t(found - bottom_edges_above.begin());
  }
  return global;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Marching Cubes CSG (`marching_cubes_csg()`) restricted to cube layers
 * `[first_layer, last_layer)` of `lattice`: classifies only the lattice
 * lines of planes `first_layer .. last_layer` with the triangles that can
 * meet them, and returns that part of the sequential output in `range`:
 * the output of `marching_cubes_csg()` with `sharp_features(false)`
 * (sharp features are not available on slab ranges).
 *
 * \param lattice the whole lattice
 * \param meshes the closed triangle meshes (the same for every range)
 * \param expression a Boolean expression with `meshes.size()` variables
 * \param first_layer, last_layer the cube layers of the range
 * \param range the output (overwritten)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{max_memory_bytes}
 *     \cgalParamDescription{refuse to start when the estimated memory exceeds it}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{8 GiB}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sharp_features}
 *     \cgalParamDescription{must be `false`: `true` throws `Invalid_input_error`}
 *     \cgalParamType{`bool`} \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \pre `first_layer <= last_layer <= lattice.number_of_points(2) - 1`
 * \throws the exceptions of `marching_cubes_csg()`, Invalid_input_error
 * for `sharp_features(true)`, and Lattice_too_large_error when the range has
 * more than 2^32 vertices (its triangles number them with 32 bits).
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void marching_cubes_csg_slab_range(const Regular_lattice_3& lattice, const TriangleMeshRange& meshes,
                                   const Boolean_expression& expression, std::size_t first_layer, std::size_t last_layer,
                                   Marching_cubes_csg_slab_range& range,
                                   const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t nz = lattice.number_of_points(2);
  if(nz < 2 || !(first_layer <= last_layer && last_layer <= nz - 1))
    throw Invalid_input_error("the cube layers [" + std::to_string(first_layer) + ", " + std::to_string(last_layer) +
                              ") are not within the lattice's " + std::to_string(nz > 0 ? nz - 1 : 0) + " layers");
  if(choose_parameter(get_parameter(np, internal_np::sharp_features), false))
    throw Invalid_input_error("sharp features are not available on slab ranges (distributed Marching Cubes CSG): "
                              "pass sharp_features(false)");
  range = Marching_cubes_csg_slab_range();
  range.first_layer = first_layer;
  range.last_layer = last_layer;
  range.number_of_layers = nz - 1;
  const std::size_t number_of_meshes = std::size_t(std::distance(std::begin(meshes), std::end(meshes)));
  if(expression.number_of_variables() != number_of_meshes)
    throw Invalid_input_error("the Boolean expression " + expression.to_string() + " has " +
                              std::to_string(expression.number_of_variables()) + " variable(s) but " +
                              std::to_string(number_of_meshes) + " mesh(es) were given");
  std::size_t read_meshes = 0;
  std::vector<internal::Lattice_triangle> triangles = Lattice_classifier_3::read_meshes(meshes, read_meshes);
  if(first_layer == last_layer)
    return;

  auto start = std::chrono::steady_clock::now();
  const Regular_lattice_3 sub = lattice.z_range(first_layer, last_layer);
  // Only triangles reaching z in [z(k0), z(k1)] can cross a line of the
  // planes or a z edge between them (the perturbation moves points up by an
  // infinitesimal, so touching counts: keep it).
  const double z0 = sub.coordinate(2, 0), z1 = sub.coordinate(2, sub.number_of_points(2) - 1);
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                 [&](const internal::Lattice_triangle& t) {
                                   const double lo = (std::min)({t.p[0][2], t.p[1][2], t.p[2][2]});
                                   const double hi = (std::max)({t.p[0][2], t.p[1][2], t.p[2][2]});
                                   return hi < z0 || lo > z1;
                                 }),
                  triangles.end());
  range.number_of_input_triangles = triangles.size();
  const std::size_t max_memory = choose_parameter(get_parameter(np, internal_np::max_memory_bytes),
                                                  Lattice_classifier_3::default_max_memory_bytes);
  typedef internal::Marching_cubes_csg_builder<ConcurrencyTag> Builder;
  const std::size_t reserved = sub.number_of_points(2) * Builder::bytes_per_plane();
  Lattice_classifier_3 classifier = Lattice_classifier_3::classify_triangles<ConcurrencyTag>(
      std::move(triangles), number_of_meshes, sub, max_memory, reserved, internal::Progress());
  internal::Marching_cubes_csg::Feature_settings plain;
  plain.enabled = false;
  const std::vector<internal::Marching_cubes_csg::Triangle_tangent> no_tangents;
  Builder builder(classifier, expression, plain, no_tangents);
  builder.compute_states(internal::Progress());
  range.statistics.lattice_points = sub.total_number_of_points();
  range.statistics.crossings = classifier.number_of_crossings();
  range.statistics.seconds_classification = internal::seconds_since(start);

  start = std::chrono::steady_clock::now();
  builder.compute_vertices(range.points, internal::Progress());
  range.statistics.seconds_edges = internal::seconds_since(start);
  // As marching_cubes_csg() does: the triangles need the vertices' numbering,
  // not the crossings, which are most of the memory of a fine lattice.
  classifier.release_crossings();
  start = std::chrono::steady_clock::now();
  builder.compute_plain_triangles(range.triangles, internal::Progress());
  range.statistics.seconds_triangulation = internal::seconds_since(start);

  // The boundary planes' vertex edges, in the builder's order: j, then i,
  // then axis (the top plane of the sub-lattice has no z edges).
  const std::size_t top = sub.number_of_points(2) - 1;
  if(first_layer > 0)
    builder.plane_vertex_edges(0, range.bottom_edges);
  if(last_layer < nz - 1)
  {
    builder.plane_vertex_edges(top, range.top_edges);
    // The top plane's vertices are the builder's last ones: move them out.
    const std::size_t owned = range.points.size() - range.top_edges.size();
    range.top_points.assign(range.points.begin() + std::ptrdiff_t(owned), range.points.end());
    range.points.resize(owned);
  }
  range.statistics.number_of_vertices = range.points.size();
  range.statistics.number_of_faces = range.triangles.size();
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_SLAB_RANGE_H
