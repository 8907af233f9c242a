// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_H

#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>
#include <CGAL/Boolean_isosurfacing_3/Scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_mesh_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Grid_slab.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_chunk.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_tetrahedron.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {


/// \ingroup PkgBooleanIsosurfacing3Ref
/// Samples callables at the vertices of a domain (`Tetrahedral_grid_3` or
/// `Tetrahedral_mesh_3`): field `i` at vertex `v` is `functions[i](point(v))`.
template <typename Domain, typename Function>
Scalar_fields sample_fields(const Domain& domain, const std::vector<Function>& functions)
{
  Scalar_fields fields(domain.number_of_vertices(), functions.size());
  const std::size_t n = functions.size();
  for(std::size_t v = 0; v < domain.number_of_vertices(); ++v)
  {
    const auto p = domain.point(v);
    for(std::size_t i = 0; i < n; ++i)
      fields.data()[v * n + i] = functions[i](p);
  }
  return fields;
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO on a regular tetrahedral grid: the boundary of the regularized
/// Boolean set `expression(f_0, ..., f_{N-1})` (literal `fi`: f_i < 0), as a
/// welded polygon soup labelled by field (see `Boolean_isosurface_soup`).
///
/// The grid is processed by slabs of cube layers along z, in parallel under
/// `Parallel_tag`; the output is identical for both tags.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{close_at_domain_boundary}
///     \cgalParamDescription{close the set where it reaches the boundary of the grid, as if the expression were false outside}
///     \cgalParamType{bool} \cgalParamDefault{false}
///   \cgalParamNEnd
///   \cgalParamNBegin{slab_layers}
///     \cgalParamDescription{cube layers per slab (the unit of parallel work); 0 means the default}
///     \cgalParamType{std::size_t} \cgalParamDefault{about 1/64 of the grid's layers}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction done, from the
///       calling thread; returning `false` cancels with `Operation_cancelled_error`}
///     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input_error if the fields do not match the grid, are not
/// finite, or the expression names a field that does not exist.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename Point_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boolean_isosurface_statistics
extract_boolean_isosurface(const Tetrahedral_grid_3<GeomTraits>& grid, const Scalar_fields& fields,
                           const Boolean_expression& expression, Boolean_isosurface_soup<Point_3>& out,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Tbiso_tetrahedron_evaluator Evaluator;

  internal::check_fields<Point_3>(grid.number_of_vertices(), fields, expression);
  const bool close = choose_parameter(get_parameter(np, internal_np::close_at_domain_boundary), false);
  const internal::Progress progress = internal::progress_of(np);
  const auto total_start = std::chrono::steady_clock::now();

  Boolean_isosurface_statistics stats;
  stats.number_of_tetrahedra = grid.number_of_tetrahedra();
  auto start = std::chrono::steady_clock::now();
  const Evaluator prototype(expression, close);
  stats.seconds_tables = internal::seconds_since(start);

  const std::array<std::size_t, 3>& n = grid.vertex_counts();
  const std::size_t layers = n[2] - 1;
  const std::size_t default_slab = std::max<std::size_t>(1, (layers + 63) / 64);
  const std::size_t requested_slab = choose_parameter(get_parameter(np, internal_np::slab_layers), std::size_t(0));
  const std::size_t slab = requested_slab > 0 ? requested_slab : default_slab; // 0: the default
  const std::size_t number_of_slabs = (layers + slab - 1) / slab;
  const std::size_t layer_size = n[0] * n[1];
  const std::size_t N = fields.number_of_fields();
  const double* values = fields.data().data();

  start = std::chrono::steady_clock::now();
  std::vector<internal::Tbiso_chunk> chunks(number_of_slabs);
  internal::concurrent_for<ConcurrencyTag>(
      number_of_slabs,
      [&](std::size_t s) {
        internal::extract_grid_slab(grid, values, 0, N, prototype, s * slab, std::min(layers, (s + 1) * slab),
                                    chunks[s]);
      },
      progress);
  stats.seconds_extraction = internal::seconds_since(start);

  start = std::chrono::steady_clock::now();
  for(const internal::Tbiso_chunk& chunk : chunks)
    stats.number_of_evaluated_tetrahedra += chunk.evaluated;
  // A vertex can be shared by two slabs only if it lies in a vertex layer
  // that bounds a slab: all its carrier corners are in that layer.
  internal::weld_chunks(chunks, out, [&](const internal::Tbiso_vertex_key& key) {
    return internal::shared_layer(key, layer_size, slab) != (std::numeric_limits<std::size_t>::max)();
  });
  stats.seconds_welding = internal::seconds_since(start);
  stats.number_of_vertices = out.points.size();
  stats.number_of_faces = out.polygons.size();
  stats.seconds = internal::seconds_since(total_start);
  progress.report(1.0);
  return stats;
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO on an unstructured tetrahedral mesh; as the grid overload.
/// `close_at_domain_boundary` closes the set on the boundary faces of the mesh.
///
/// \param mesh the tetrahedral mesh
/// \param fields the values of the fields at the vertices of `mesh`
/// \param expression the Boolean expression of the fields (variable i is field i)
/// \param out the output soup (cleared first)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{close_at_domain_boundary}
///     \cgalParamDescription{close the set on the boundary faces of the mesh, as if the expression were false outside}
///     \cgalParamType{`bool`} \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction done, from the
///       calling thread; returning `false` cancels with `Operation_cancelled_error`}
///     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename Point_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boolean_isosurface_statistics
extract_boolean_isosurface(const Tetrahedral_mesh_3<GeomTraits>& mesh, const Scalar_fields& fields,
                           const Boolean_expression& expression, Boolean_isosurface_soup<Point_3>& out,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Tbiso_tetrahedron_evaluator Evaluator;

  internal::check_fields<Point_3>(mesh.number_of_vertices(), fields, expression);
  const bool close = choose_parameter(get_parameter(np, internal_np::close_at_domain_boundary), false);
  const internal::Progress progress = internal::progress_of(np);
  const auto total_start = std::chrono::steady_clock::now();

  Boolean_isosurface_statistics stats;
  stats.number_of_tetrahedra = mesh.number_of_tetrahedra();
  auto start = std::chrono::steady_clock::now();
  const Evaluator prototype(expression, close);
  const std::uint64_t expression_fields = prototype.expression_fields();
  stats.seconds_tables = internal::seconds_since(start);

  start = std::chrono::steady_clock::now();
  const std::size_t N = fields.number_of_fields();
  const double* values = fields.data().data();
  std::vector<std::uint64_t> negative(mesh.number_of_vertices()), positive(mesh.number_of_vertices());
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
    internal::field_sign_masks(values + v * N, expression_fields, negative[v], positive[v]);

  const std::size_t T = mesh.number_of_tetrahedra();
  // The planes of the boundary: closing faces of different planes meet at creases.
  const std::unordered_map<std::size_t, int> boundary_planes =
      close ? internal::boundary_planes(mesh) : std::unordered_map<std::size_t, int>();
  const std::size_t chunk_size = std::max<std::size_t>(4096, (T + 63) / 64);
  const std::size_t number_of_chunks = (T + chunk_size - 1) / chunk_size;
  std::vector<internal::Tbiso_chunk> chunks(number_of_chunks);
  internal::concurrent_for<ConcurrencyTag>(
      number_of_chunks,
      [&](std::size_t s) {
        internal::Tbiso_chunk& chunk = chunks[s];
        Evaluator evaluator = prototype;
        std::array<internal::Tbiso_corner, 4> corner;
        std::array<std::uint64_t, 4> tet_negative, tet_positive;
        for(std::size_t t = s * chunk_size; t < std::min(T, (s + 1) * chunk_size); ++t)
        {
          const typename Tetrahedral_mesh_3<GeomTraits>::Tetrahedron& tet = mesh.tetrahedron(t);
          unsigned boundary_faces = 0;
          for(int l = 0; l < 4; ++l)
          {
            tet_negative[l] = negative[tet[l]];
            tet_positive[l] = positive[tet[l]];
            if(close && mesh.neighbor_apex(t, l) == Tetrahedral_mesh_3<GeomTraits>::no_vertex)
              boundary_faces |= 1u << l;
          }
          if(evaluator.is_trivially_empty(tet_negative, tet_positive, boundary_faces))
            continue;
          ++chunk.evaluated;
          for(int l = 0; l < 4; ++l)
          {
            corner[l].id = tet[l];
            corner[l].values = values + tet[l] * N;
            corner[l].negative = tet_negative[l];
            corner[l].positive = tet_positive[l];
            corner[l].position = mesh.position(tet[l]);
          }
          evaluator.evaluate_tetrahedron(
              corner,
              [&](int l) {
                Evaluator::Apex a{false, 0, 0};
                const std::size_t v = mesh.neighbor_apex(t, l);
                if(v != Tetrahedral_mesh_3<GeomTraits>::no_vertex)
                {
                  a.exists = true;
                  a.negative = negative[v];
                  a.positive = positive[v];
                }
                return a;
              },
              [&](int label, const Evaluator::Vertex* v, std::size_t count, int face) {
                chunk.add(label, v, count, evaluator,
                          label == Evaluator::domain_boundary_label ? boundary_planes.at(4 * t + std::size_t(face))
                                                                    : -1);
              });
        }
      },
      progress);
  stats.seconds_extraction = internal::seconds_since(start);

  start = std::chrono::steady_clock::now();
  for(const internal::Tbiso_chunk& chunk : chunks)
    stats.number_of_evaluated_tetrahedra += chunk.evaluated;
  internal::weld_chunks(chunks, out, [](const internal::Tbiso_vertex_key&) { return true; });
  stats.seconds_welding = internal::seconds_since(start);
  stats.number_of_vertices = out.points.size();
  stats.number_of_faces = out.polygons.size();
  stats.seconds = internal::seconds_since(total_start);
  progress.report(1.0);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_H
