// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_BY_SLABS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_BY_SLABS_H

// Out-of-core TBISO on a regular grid: the fields are read slab by slab of
// cube layers along z, and the output is handed to a sink as soon as a slab
// is welded.  Peak memory is a few slabs of field values plus the keys of one
// vertex layer, whatever the number of slabs.
//
// Welding across slabs: a vertex can be shared by two slabs only if its
// carrier simplex lies in the vertex layer between them (its key says so:
// all carrier corners in that layer).  Slabs are welded in order, so the keys
// of one layer are all that must be remembered, and the vertex numbering is
// the order of first appearance -- the same as the in-core
// `extract_boolean_isosurface()` with the same `slab_layers`, for both
// concurrency tags.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Grid_slab.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Slab_pipeline.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_chunk.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_tetrahedron.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/parallel_pipeline.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

// The concepts `ScalarFieldSource` (number_of_fields(), read(first_vertex,
// count, values)) and `BooleanIsosurfaceSink` (add_point(p), add_polygon(
// vertices, n, field)) are documented in doc/Boolean_isosurfacing_3/Concepts/.

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A `ScalarFieldSource` over fields already in memory.
///
/// \cgalModels{ScalarFieldSource}
class Scalar_fields_source
{
public:
  explicit Scalar_fields_source(const Scalar_fields& fields) : m_fields(fields) {}
  std::size_t number_of_fields() const { return m_fields.number_of_fields(); }
  void read(std::size_t first, std::size_t count, std::vector<double>& values) const
  {
    const std::size_t N = m_fields.number_of_fields();
    values.assign(m_fields.data().begin() + first * N, m_fields.data().begin() + (first + count) * N);
  }

private:
  const Scalar_fields& m_fields;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A `BooleanIsosurfaceSink` appending to a `Boolean_isosurface_soup`.
///
/// \cgalModels{BooleanIsosurfaceSink}
template <typename Point_3>
class Boolean_isosurface_soup_sink
{
public:
  explicit Boolean_isosurface_soup_sink(Boolean_isosurface_soup<Point_3>& soup) : m_soup(soup) { m_soup.clear(); }
  void add_point(const std::array<double, 3>& p) { m_soup.points.push_back(Point_3(p[0], p[1], p[2])); }
  void add_polygon(const std::size_t* v, std::size_t n, int field)
  {
    m_soup.polygons.emplace_back(v, v + n);
    m_soup.face_fields.push_back(field);
  }

private:
  Boolean_isosurface_soup<Point_3>& m_soup;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Statistics of `extract_boolean_isosurface_by_slabs()`.
struct Boolean_isosurface_slab_statistics : Boolean_isosurface_statistics
{
  /// Slabs of `slab_layers` cube layers.
  std::size_t number_of_slabs = 0;
  /// Time spent reading field values (the reading stage, all slabs).
  double seconds_reading = 0;
  /// Largest number of field values held at once (the buffers of all slab slots).
  /// `seconds_extraction` is the wall time of the whole pipeline here.
  std::size_t peak_field_values = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO on a regular grid whose fields are read from `source` one slab of
/// `slab_layers` cube layers at a time (plus one ghost vertex layer on each
/// side: the apex of a neighbouring tetrahedron may lie there).  Under
/// `Parallel_tag` the slabs go through a pipeline: read in order (one file,
/// read sequentially), evaluated in parallel, welded and passed to `sink` in
/// slab order, with at most `slabs_in_flight` slabs in memory (default: twice
/// the number of hardware threads, so that reading overlaps evaluation).  The
/// output does not depend on the tag.
/// Each slab slot keeps its buffer from one window to the next: allocating
/// (and first touching) a fresh buffer per slab cost more than reading the
/// file, on the virtual machine this was measured on.
///
/// \param grid the regular grid
/// \param source the fields, a model of `ScalarFieldSource`
/// \param expression the Boolean expression of the fields
/// \param sink receives the surface, a model of `BooleanIsosurfaceSink`
/// \param np an optional sequence of named parameters among the ones listed below
/// \param slabs_in_flight the most slabs in memory at once (0: the default)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{slab_layers}
///     \cgalParamDescription{cube layers per slab (the unit of reading and of parallel work); 0 means the default}
///     \cgalParamType{`std::size_t`} \cgalParamDefault{8}
///   \cgalParamNEnd
///   \cgalParamNBegin{close_at_domain_boundary}
///     \cgalParamDescription{close the set where it reaches the boundary of the grid, as if the expression were false outside}
///     \cgalParamType{`bool`} \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction of slabs done, from
///       the calling thread; returning `false` cancels with `Operation_cancelled_error`}
///     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input_error if the source does not have the fields the
/// expression names; Non_finite_value_error on a NaN or infinite value
/// (checked slab by slab, naming the global vertex).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename FieldSource,
          typename Sink, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boolean_isosurface_slab_statistics
extract_boolean_isosurface_by_slabs(const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                                    const Boolean_expression& expression, Sink& sink,
                                    const NamedParameters& np = CGAL::parameters::default_values(),
                                    std::size_t slabs_in_flight = 0)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Tbiso_tetrahedron_evaluator Evaluator;

  const std::size_t N = source.number_of_fields();
  if(expression.number_of_variables() > N)
    throw Invalid_input_error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                              " but there are only " + std::to_string(N) + " fields");
  const bool close = choose_parameter(get_parameter(np, internal_np::close_at_domain_boundary), false);
  const internal::Progress progress = internal::progress_of(np);
  const auto total_start = std::chrono::steady_clock::now();
  const std::size_t slab =
      std::max<std::size_t>(1, choose_parameter(get_parameter(np, internal_np::slab_layers), std::size_t(8)));

  Boolean_isosurface_slab_statistics stats;
  stats.number_of_tetrahedra = grid.number_of_tetrahedra();
  auto start = std::chrono::steady_clock::now();
  const Evaluator prototype(expression, close);
  stats.seconds_tables = internal::seconds_since(start);

  const std::array<std::size_t, 3>& n = grid.vertex_counts();
  const std::size_t layers = n[2] - 1, layer_size = n[0] * n[1];
  const std::size_t number_of_slabs = (layers + slab - 1) / slab;
  stats.number_of_slabs = number_of_slabs;
  if(slabs_in_flight == 0)
    slabs_in_flight = internal::is_parallel_tag<ConcurrencyTag>()
                          ? 2 * std::max<std::size_t>(1, std::thread::hardware_concurrency())
                          : 1;

  // One slot per slab in flight: slab s uses slot s % slabs_in_flight.
  typedef internal::Tbiso_slab_slot Slot;
  std::vector<Slot> slots(slabs_in_flight);
  for(Slot& slot : slots)
    slot.values.reserve((std::min(slab, layers) + 3) * layer_size * N);

  // The three stages: read (in slab order: one file, read sequentially),
  // evaluate (any order, in parallel), weld and emit (in slab order).
  auto read = [&](Slot& slot) {
    const internal::Slab_window w(slot.slab, slab, layers);
    const auto read_start = std::chrono::steady_clock::now();
    source.read(w.first_layer * layer_size, (w.last_layer - w.first_layer + 1) * layer_size, slot.values);
    stats.seconds_reading += internal::seconds_since(read_start);
    std::size_t held = 0;
    for(const Slot& other : slots)
      held += other.values.capacity();
    stats.peak_field_values = std::max(stats.peak_field_values, held);
  };
  auto evaluate = [&](Slot& slot) {
    const internal::Slab_window w(slot.slab, slab, layers);
    for(std::size_t k = 0; k < slot.values.size(); ++k)
      if(!std::isfinite(slot.values[k]))
        throw Non_finite_value_error("field " + std::to_string(k % N) + " has a non-finite value at vertex " +
                                     std::to_string(w.first_layer * layer_size + k / N));
    slot.chunk = internal::Tbiso_chunk();
    internal::extract_grid_slab(grid, slot.values.data(), w.first_layer * layer_size, N, prototype, w.k_begin,
                                w.k_end, slot.chunk);
  };
  std::unordered_map<internal::Tbiso_vertex_key, std::size_t, internal::Tbiso_vertex_key_hash> below, above;
  std::size_t next_index = 0;
  auto weld = [&](Slot& slot) {
    const auto weld_start = std::chrono::steady_clock::now();
    const std::size_t s = slot.slab;
    const internal::Slab_window w(s, slab, layers);
    const std::size_t k_begin = w.k_begin, k_end = w.k_end;
    internal::Tbiso_chunk& chunk = slot.chunk;
    stats.number_of_evaluated_tetrahedra += chunk.evaluated;
    chunk.index.clear();
    above.clear();
    internal::weld_chunk(
        chunk,
        [&](const internal::Tbiso_vertex_key& key) {
          if(s == 0 || internal::shared_layer(key, layer_size, slab) != k_begin)
            return internal::tbiso_no_index();
          const auto found = below.find(key);
          return found == below.end() ? internal::tbiso_no_index() : found->second;
        },
        [&](const internal::Tbiso_vertex_key& key, std::size_t index) {
          if(internal::shared_layer(key, layer_size, slab) == k_end)
            above.emplace(key, index);
        },
        next_index, [&](const std::array<double, 3>& p) { sink.add_point(p); },
        [&](const std::size_t* v, std::size_t count, int label, int) {
          sink.add_polygon(v, count, label);
          ++stats.number_of_faces;
        });
    below.swap(above);
    chunk = internal::Tbiso_chunk();
    stats.seconds_welding += internal::seconds_since(weld_start);
    progress.report(double(s + 1) / double(number_of_slabs));
  };

  start = std::chrono::steady_clock::now();
  internal::run_slab_pipeline<ConcurrencyTag>(number_of_slabs, slots, read, evaluate, weld);
  stats.seconds_extraction = internal::seconds_since(start);
  stats.number_of_vertices = next_index;
  stats.seconds = internal::seconds_since(total_start);
  return stats;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_BY_SLABS_H
