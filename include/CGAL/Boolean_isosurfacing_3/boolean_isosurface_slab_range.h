// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SLAB_RANGE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SLAB_RANGE_H

// TBISO on one contiguous range of cube layers of a regular grid, for callers
// that split the grid themselves (one range per MPI rank, per node, per job):
// the building block of `MPI/distributed_boolean_isosurface.h`, with no MPI
// dependency.
//
// Why ranges weld exactly: a polygon vertex can be met by the tetrahedra of
// two ranges only if its carrier simplex lies in the vertex layer between
// them (its exact key says so: all carrier corners in that layer).  So a
// range lists the vertices of its bottom and top layers with their keys, and
// neighbours match keys -- equal keys are the same exact point, and the
// coordinates are computed from the key, so both sides even agree on the
// doubles.
//
// Why the result is the sequential one, numbering included: every driver
// numbers vertices in order of first appearance over tetrahedra visited in
// (layer, row, cube, tetrahedron) order.  A range numbers its own vertices in
// that order; a bottom-layer vertex that the range below also has keeps the
// lower number; every other vertex gets the next one.  With an exclusive
// prefix sum of the counts of *new* vertices this is exactly the sequential
// numbering.
//
// One message per boundary: the range below sends its top-layer keys with
// their local indices and its local vertex count n.  If its top-layer
// vertices all come after its bottom-layer ones in its local order (true for
// ranges of two layers or more: bottom vertices first appear in the first
// cube layer, top ones in the last), a top vertex of local index l has the
// global index offset_above - n + l, where offset_above is the prefix sum the
// range above gets anyway: the duplicates the range below dropped cancel.

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The contiguous cube-layer range `[first, last)` of `number_of_layers`
/// layers given to part `part` of `number_of_parts`: the ranges are in part
/// order, cover all layers, and differ in size by at most one layer.  Every
/// non-empty range has at least two layers (see
/// `weld_boolean_isosurface_slab_range()`): when there are fewer than
/// `2 * number_of_parts` layers, the last parts get empty ranges
/// `[number_of_layers, number_of_layers)`.
/// \pre `part < number_of_parts`
inline std::pair<std::size_t, std::size_t> slab_range_of_part(std::size_t number_of_layers, std::size_t part,
                                                              std::size_t number_of_parts)
{
  CGAL_precondition(part < number_of_parts);
  const std::size_t active = (std::max<std::size_t>)(1, (std::min)(number_of_parts, number_of_layers / 2));
  if(part >= active)
    return {number_of_layers, number_of_layers};
  const std::size_t base = number_of_layers / active, extra = number_of_layers % active;
  const std::size_t first = part * base + (std::min)(part, extra);
  return {first, first + base + (part < extra ? 1 : 0)};
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A `ScalarFieldSource` over the values of a range of grid vertices held by
/// the caller (for example the slab range plus ghost layers received from
/// elsewhere): vertex `first_vertex + c` has the values
/// `values[c * number_of_fields ...]`.
class Scalar_field_range_source
{
public:
  Scalar_field_range_source(const double* values, std::size_t first_vertex, std::size_t number_of_vertices,
                            std::size_t number_of_fields)
    : m_values(values), m_first(first_vertex), m_count(number_of_vertices), m_fields(number_of_fields)
  {}
  std::size_t number_of_fields() const { return m_fields; }
  /// \throws std::out_of_range if the vertices asked for are not all held.
  void read(std::size_t first, std::size_t count, std::vector<double>& values) const
  {
    if(first < m_first || first + count > m_first + m_count)
      throw std::out_of_range("vertices [" + std::to_string(first) + ", " + std::to_string(first + count) +
                              ") are not within the held range [" + std::to_string(m_first) + ", " +
                              std::to_string(m_first + m_count) + ")");
    values.assign(m_values + (first - m_first) * m_fields, m_values + (first + count - m_first) * m_fields);
  }

private:
  const double* m_values;
  std::size_t m_first, m_count, m_fields;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The surface of one cube-layer range of a grid, with range-local vertex
/// numbers (order of first appearance), before welding with its neighbours.
struct Boolean_isosurface_slab_range
{
  /// Number of 64-bit words of a serialized vertex key: the four carrier
  /// corners (global grid vertex indices, all ones for none) and the mask of
  /// the fields vanishing at the vertex.
  static constexpr std::size_t key_words = 5;

  /// Cube layers `[first_layer, last_layer)` of a grid of `number_of_layers`.
  std::size_t first_layer = 0, last_layer = 0, number_of_layers = 0;
  std::vector<std::array<double, 3>> points;
  /// Polygon p has the local vertices `polygon_vertices[polygon_begin[p] .. polygon_begin[p + 1])`.
  std::vector<std::size_t> polygon_begin{0};
  std::vector<std::size_t> polygon_vertices;
  std::vector<int> labels;
  /// The vertices whose carrier lies in vertex layer `first_layer` (empty
  /// when `first_layer == 0`), and those in vertex layer `last_layer` (empty
  /// for the last range): local indices, increasing, and their keys
  /// (`key_words` words each, same order).
  std::vector<std::size_t> bottom_vertices, top_vertices;
  std::vector<std::uint64_t> bottom_keys, top_keys;
  std::size_t number_of_evaluated_tetrahedra = 0;
  std::size_t peak_field_values = 0;

  std::size_t number_of_polygons() const { return labels.size(); }
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What a range sends to the range above it: its top-layer keys and local
/// indices, and its number of local vertices (see
/// `weld_boolean_isosurface_slab_range()`).  As one array of 64-bit words,
/// ready for a message: `[number of local vertices, top follows bottom (0|1),
/// number of keys m, m local indices, m * key_words key words]`.
inline std::vector<std::uint64_t> top_layer_message(const Boolean_isosurface_slab_range& range)
{
  const bool top_follows_bottom = range.bottom_vertices.empty() || range.top_vertices.empty() ||
                                  range.top_vertices.front() > range.bottom_vertices.back();
  std::vector<std::uint64_t> message{std::uint64_t(range.points.size()), std::uint64_t(top_follows_bottom),
                                     std::uint64_t(range.top_vertices.size())};
  message.insert(message.end(), range.top_vertices.begin(), range.top_vertices.end());
  message.insert(message.end(), range.top_keys.begin(), range.top_keys.end());
  return message;
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// How a range's local vertices map to the global numbering.
struct Boolean_isosurface_slab_range_welding
{
  static constexpr std::size_t no_match = (std::numeric_limits<std::size_t>::max)();
  /// For each bottom-layer vertex (in `bottom_vertices` order): the local
  /// index, in the range below, of the vertex with the same key, or `no_match`.
  std::vector<std::size_t> below_match;
  /// Local vertex count of the range below (0 for the first range).
  std::size_t below_vertices = 0;
  /// The vertices this range adds to the surface: its local vertices minus
  /// the matched bottom-layer ones.  The exclusive prefix sum of this count
  /// over the ranges below is the range's `offset`.
  std::size_t number_of_new_vertices = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Matches the bottom layer of `range` with `message_from_below`, the
/// `top_layer_message()` of the range just below (empty for the first
/// range or when the range below is empty).
/// \throws Invalid_input_error if the message is malformed, or if the range
/// below has top-layer vertices before bottom-layer ones in its local order
/// (a one-layer range in the middle: give every range two layers or more,
/// as `slab_range_of_part()` does).
inline Boolean_isosurface_slab_range_welding
match_boolean_isosurface_slab_range(const Boolean_isosurface_slab_range& range,
                                    const std::vector<std::uint64_t>& message_from_below)
{
  typedef internal::Tbiso_vertex_key Key;
  const std::size_t W = Boolean_isosurface_slab_range::key_words;
  auto key_at = [](const std::uint64_t* w) {
    Key k;
    for(int c = 0; c < 4; ++c)
      k.corners[c] = std::size_t(w[c]);
    k.zero_fields = w[4];
    return k;
  };
  Boolean_isosurface_slab_range_welding welding;
  welding.below_match.assign(range.bottom_vertices.size(), welding.no_match);
  std::size_t matched = 0;
  if(!message_from_below.empty())
  {
    if(message_from_below.size() < 3 || message_from_below.size() != 3 + message_from_below[2] * (1 + W))
      throw Invalid_input_error("malformed top-layer message from the range below");
    if(message_from_below[1] == 0)
      throw Invalid_input_error("the range below has top-layer vertices before bottom-layer ones: give every "
                                "range at least two cube layers");
    welding.below_vertices = std::size_t(message_from_below[0]);
    const std::size_t m = std::size_t(message_from_below[2]);
    std::unordered_map<Key, std::size_t, internal::Tbiso_vertex_key_hash> below;
    below.reserve(m);
    for(std::size_t t = 0; t < m; ++t)
      below.emplace(key_at(message_from_below.data() + 3 + m + W * t), std::size_t(message_from_below[3 + t]));
    for(std::size_t b = 0; b < range.bottom_vertices.size(); ++b)
    {
      const auto found = below.find(key_at(range.bottom_keys.data() + W * b));
      if(found != below.end())
      {
        welding.below_match[b] = found->second;
        ++matched;
      }
    }
  }
  welding.number_of_new_vertices = range.points.size() - matched;
  return welding;
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The global index of every local vertex of `range` (`no_match` for none:
/// every vertex has one), given `offset`, the number of new vertices of all
/// ranges below.  The new vertices get `offset, offset + 1, ...` in local
/// order, so a range's own points are one contiguous block of the output.
inline std::vector<std::size_t> global_vertex_indices(const Boolean_isosurface_slab_range& range,
                                                      const Boolean_isosurface_slab_range_welding& welding,
                                                      std::size_t offset)
{
  std::vector<std::size_t> global(range.points.size(), welding.no_match);
  // The range below numbered its new vertices offset - new_below ...; its
  // local vertex l (after all its bottom ones) is offset - n_below + l.
  for(std::size_t b = 0; b < range.bottom_vertices.size(); ++b)
    if(welding.below_match[b] != welding.no_match)
      global[range.bottom_vertices[b]] = offset - welding.below_vertices + welding.below_match[b];
  std::size_t next = offset;
  for(std::size_t& g : global)
    if(g == welding.no_match)
      g = next++;
  return global;
}

namespace internal {

// The vertex layer holding a key's whole carrier, or no_layer.
inline std::size_t carrier_layer(const Tbiso_vertex_key& key, std::size_t layer_size)
{
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  const std::size_t z = key.corners[0] / layer_size;
  for(int c = 1; c < 4 && key.corners[c] != none; ++c)
    if(key.corners[c] / layer_size != z)
      return none;
  return z;
}

inline void append_key(std::vector<std::uint64_t>& out, const Tbiso_vertex_key& key)
{
  for(std::size_t c : key.corners)
    out.push_back(std::uint64_t(c));
  out.push_back(key.zero_fields);
}

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO on cube layers `[first_layer, last_layer)` of `grid`, reading from
/// `source` only the vertex layers `first_layer - 1 .. last_layer + 1`
/// (clamped to the grid; one ghost layer on each side, where the apex of a
/// neighbouring tetrahedron may lie), `slab_layers` cube layers at a time.
/// The result is `range`, with local vertex numbers; the polygons are those
/// of the sequential extraction for these layers, in the same order.
///
/// \param grid the whole regular grid
/// \param source the fields, a model of `ScalarFieldSource`
/// \param expression the Boolean expression of the fields
/// \param first_layer, last_layer the cube layers of the range
/// \param range the output (overwritten)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{close_at_domain_boundary}
///     \cgalParamDescription{close the set on the *grid's* boundary (the range's z boundaries are not closed)}
///     \cgalParamType{`bool`} \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{slab_layers}
///     \cgalParamDescription{cube layers read at a time: memory is a few slabs of field values plus the output of the range}
///     \cgalParamType{`std::size_t`} \cgalParamDefault{8}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Under
/// `Parallel_tag` a window of slabs is evaluated in parallel; the output does
/// not depend on the tag.
///
/// \throws Invalid_input_error if the range is not within the grid or the
/// expression names a field the source does not have; Non_finite_value_error
/// on a NaN or infinite value (naming the global vertex).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename FieldSource,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void extract_boolean_isosurface_slab_range(const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                                           const Boolean_expression& expression, std::size_t first_layer,
                                           std::size_t last_layer, Boolean_isosurface_slab_range& range,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Tbiso_vertex_key Key;

  const std::array<std::size_t, 3>& n = grid.vertex_counts();
  const std::size_t layers = n[2] - 1, layer_size = n[0] * n[1];
  if(!(first_layer <= last_layer && last_layer <= layers))
    throw Invalid_input_error("the cube layers [" + std::to_string(first_layer) + ", " + std::to_string(last_layer) +
                              ") are not within the grid's " + std::to_string(layers) + " layers");
  const std::size_t N = source.number_of_fields();
  if(expression.number_of_variables() > N)
    throw Invalid_input_error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                              " but there are only " + std::to_string(N) + " fields");
  const bool close = choose_parameter(get_parameter(np, internal_np::close_at_domain_boundary), false);
  const std::size_t slab =
      std::max<std::size_t>(1, choose_parameter(get_parameter(np, internal_np::slab_layers), std::size_t(8)));

  range = Boolean_isosurface_slab_range();
  range.first_layer = first_layer;
  range.last_layer = last_layer;
  range.number_of_layers = layers;
  const internal::Tbiso_tetrahedron_evaluator prototype(expression, close);
  const std::size_t number_of_slabs = (last_layer - first_layer + slab - 1) / slab;
  const std::size_t window =
      internal::is_parallel_tag<ConcurrencyTag>() ? 2 * std::max<std::size_t>(1, std::thread::hardware_concurrency()) : 1;

  struct Slot
  {
    std::size_t k_begin = 0, k_end = 0;
    std::vector<double> values;
    internal::Tbiso_chunk chunk;
  };
  std::vector<Slot> slots((std::min)(window, (std::max<std::size_t>)(1, number_of_slabs)));
  // Each slot keeps its buffer: sized once for the largest slab (plus two
  // ghost layers and rounding), it is never reallocated.
  for(Slot& slot : slots)
    slot.values.reserve(((std::min)(slab, last_layer - first_layer) + 3) * layer_size * N);
  std::unordered_map<Key, std::size_t, internal::Tbiso_vertex_key_hash> below, above;
  std::vector<std::size_t> to_local;

  for(std::size_t s0 = 0; s0 < number_of_slabs; s0 += slots.size())
  {
    const std::size_t count = (std::min)(slots.size(), number_of_slabs - s0);
    // Read in order (one file), then evaluate the window (in parallel).
    for(std::size_t w = 0; w < count; ++w)
    {
      Slot& slot = slots[w];
      slot.k_begin = first_layer + (s0 + w) * slab;
      slot.k_end = (std::min)(last_layer, slot.k_begin + slab);
      const std::size_t lo = slot.k_begin > 0 ? slot.k_begin - 1 : 0, hi = (std::min)(n[2] - 1, slot.k_end + 1);
      source.read(lo * layer_size, (hi - lo + 1) * layer_size, slot.values);
    }
    std::size_t held = 0;
    for(const Slot& slot : slots)
      held += slot.values.capacity();
    range.peak_field_values = (std::max)(range.peak_field_values, held);
    internal::concurrent_for<ConcurrencyTag>(count, [&](std::size_t w) {
      Slot& slot = slots[w];
      const std::size_t lo = slot.k_begin > 0 ? slot.k_begin - 1 : 0;
      for(std::size_t k = 0; k < slot.values.size(); ++k)
        if(!std::isfinite(slot.values[k]))
          throw Non_finite_value_error("field " + std::to_string(k % N) + " has a non-finite value at vertex " +
                                       std::to_string(lo * layer_size + k / N));
      slot.chunk = internal::Tbiso_chunk();
      internal::extract_grid_slab(grid, slot.values.data(), lo * layer_size, N, prototype, slot.k_begin, slot.k_end,
                                  slot.chunk);
    });
    // Weld in slab order: the vertices of an inner slab boundary through
    // `below`, those of the range's boundaries listed for the neighbours.
    for(std::size_t w = 0; w < count; ++w)
    {
      internal::Tbiso_chunk& chunk = slots[w].chunk;
      const std::size_t k_begin = slots[w].k_begin, k_end = slots[w].k_end;
      range.number_of_evaluated_tetrahedra += chunk.evaluated;
      chunk.index.clear();
      above.clear();
      to_local.resize(chunk.keys.size());
      for(std::size_t v = 0; v < chunk.keys.size(); ++v)
      {
        const std::size_t z = internal::carrier_layer(chunk.keys[v], layer_size);
        if(z == k_begin && k_begin != first_layer)
        {
          const auto found = below.find(chunk.keys[v]);
          if(found != below.end())
          {
            to_local[v] = found->second;
            continue;
          }
        }
        to_local[v] = range.points.size();
        range.points.push_back(chunk.points[v]);
        if(z == k_begin && k_begin == first_layer && first_layer > 0)
        {
          range.bottom_vertices.push_back(to_local[v]);
          internal::append_key(range.bottom_keys, chunk.keys[v]);
        }
        if(z == k_end)
        {
          if(k_end != last_layer)
            above.emplace(chunk.keys[v], to_local[v]);
          else if(last_layer < layers)
          {
            range.top_vertices.push_back(to_local[v]);
            internal::append_key(range.top_keys, chunk.keys[v]);
          }
        }
      }
      for(std::size_t p = 0; p + 1 < chunk.polygon_begin.size(); ++p)
      {
        for(std::size_t k = chunk.polygon_begin[p]; k < chunk.polygon_begin[p + 1]; ++k)
          range.polygon_vertices.push_back(to_local[chunk.polygon_vertices[k]]);
        range.polygon_begin.push_back(range.polygon_vertices.size());
        range.labels.push_back(chunk.labels[p]);
      }
      below.swap(above);
      chunk = internal::Tbiso_chunk();
    }
  }
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SLAB_RANGE_H
