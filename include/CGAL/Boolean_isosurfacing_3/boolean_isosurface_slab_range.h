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

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_by_slabs.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Grid_slab.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_chunk.h>

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
/// layers given to part `part` of `number_of_parts`, made of whole slabs of
/// `slab_layers` layers (the grid's slabs `[s * slab_layers, (s + 1) *
/// slab_layers)`, the last one possibly shorter): the ranges are in part
/// order, cover all layers, and differ in size by at most one slab.  Whole
/// slabs make a range weld the same chunks as the single-process
/// `extract_boolean_isosurface_by_slabs()` with the same `slab_layers`, so
/// that the removal of what rounding leaves degenerate is the same too.
/// Every non-empty range but the last has at least two layers (see
/// `match_boolean_isosurface_slab_range()`): when there are too few slabs,
/// the last parts get empty ranges `[number_of_layers, number_of_layers)`.
/// \pre `part < number_of_parts` and `slab_layers >= 1`
inline std::pair<std::size_t, std::size_t> slab_range_of_part(std::size_t number_of_layers, std::size_t part,
                                                              std::size_t number_of_parts,
                                                              std::size_t slab_layers = 1)
{
  CGAL_precondition(part < number_of_parts && slab_layers >= 1);
  const std::size_t slabs = (number_of_layers + slab_layers - 1) / slab_layers;
  // Slabs of one layer: two per range, so that a range has two layers.
  const std::size_t per_range = slab_layers == 1 ? 2 : 1;
  const std::size_t active = (std::max<std::size_t>)(1, (std::min)(number_of_parts, slabs / per_range));
  if(part >= active)
    return {number_of_layers, number_of_layers};
  const std::size_t base = slabs / active, extra = slabs % active;
  const std::size_t first = part * base + (std::min)(part, extra);
  const std::size_t last = first + base + (part < extra ? 1 : 0);
  return {(std::min)(number_of_layers, first * slab_layers), (std::min)(number_of_layers, last * slab_layers)};
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
  /// The local vertices, in local order (empty when the range was streamed
  /// to a sink by `stream_boolean_isosurface_slab_range()`).
  std::vector<std::array<double, 3>> points;
  /// Polygon p has the local vertices `polygon_vertices[polygon_begin[p] .. polygon_begin[p + 1])`
  /// (empty when streamed, as `points`).
  std::vector<std::size_t> polygon_begin{0};
  std::vector<std::size_t> polygon_vertices;
  std::vector<int> labels;
  /// The number of local vertices and of polygons (also when streamed).
  std::size_t vertex_count = 0, polygon_count = 0;
  /// The vertices whose carrier lies in vertex layer `first_layer` (empty
  /// when `first_layer == 0`), and those in vertex layer `last_layer` (empty
  /// for the last range): local indices, non-decreasing, and their keys
  /// (`key_words` words each, same order).  A vertex appears once per key:
  /// the welding merges the keys of bit-identical vertices of a polygon.
  std::vector<std::size_t> bottom_vertices, top_vertices;
  std::vector<std::uint64_t> bottom_keys, top_keys;
  std::size_t number_of_evaluated_tetrahedra = 0;
  std::size_t peak_field_values = 0;
  /// True if the range was extracted without the message from the range
  /// below and its first slab has two bottom-layer vertices at one position:
  /// whether the welding merges them depends on how the range below numbered
  /// them, so the range must be extracted again with that message (see
  /// `match_boolean_isosurface_slab_range()`).
  bool depends_on_below = false;
  /// The message from below the range was extracted with (empty if none).
  std::vector<std::uint64_t> message_used;

  std::size_t number_of_vertices() const { return vertex_count; }
  std::size_t number_of_polygons() const { return polygon_count; }
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What a range sends to the range above it: its top-layer keys and local
/// indices, and its number of local vertices (see
/// `weld_boolean_isosurface_slab_range()`).  As one array of 64-bit words,
/// ready for a message: `[number of local vertices, top follows bottom (0|1),
/// number of keys m, m local indices, m * key_words key words]`.
inline std::vector<std::uint64_t> top_layer_message(const Boolean_isosurface_slab_range& range)
{
  const bool top_follows_bottom =
      range.bottom_vertices.empty() || range.top_vertices.empty() ||
      *std::min_element(range.top_vertices.begin(), range.top_vertices.end()) >
          *std::max_element(range.bottom_vertices.begin(), range.bottom_vertices.end());
  std::vector<std::uint64_t> message{std::uint64_t(range.number_of_vertices()), std::uint64_t(top_follows_bottom),
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
/// as `slab_range_of_part()` does), or if `range.depends_on_below` (extract
/// it again with this message), or if it was extracted with another message.
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
  if(range.depends_on_below)
    throw Invalid_input_error("the range [" + std::to_string(range.first_layer) + ", " +
                              std::to_string(range.last_layer) +
                              ") has bottom-layer vertices at one position: extract it again with the message "
                              "from the range below");
  if(!range.message_used.empty() && range.message_used != message_from_below)
    throw Invalid_input_error("the range was extracted with another message from the range below");
  Boolean_isosurface_slab_range_welding welding;
  welding.below_match.assign(range.bottom_vertices.size(), welding.no_match);
  std::vector<std::size_t> is_matched;
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
        // A vertex listed with several keys is one vertex, matched once.
        if(is_matched.empty())
          is_matched.assign(range.number_of_vertices(), welding.no_match);
        std::size_t& match = is_matched[range.bottom_vertices[b]];
        if(match == welding.no_match)
          ++matched;
        else if(match != found->second)
          throw Invalid_input_error("a bottom-layer vertex matches two vertices of the range below");
        match = found->second;
      }
    }
  }
  welding.number_of_new_vertices = range.number_of_vertices() - matched;
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
  std::vector<std::size_t> global(range.number_of_vertices(), welding.no_match);
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

namespace internal {

inline Tbiso_vertex_key key_from_words(const std::uint64_t* w)
{
  Tbiso_vertex_key k;
  for(int c = 0; c < 4; ++c)
    k.corners[c] = std::size_t(w[c]);
  k.zero_fields = w[4];
  return k;
}

// The common body of both overloads of extract_boolean_isosurface_slab_range():
// `message` is the top-layer message of the range below, or null.
//
// The range welds its chunks -- the grid's slabs of `slab_layers` layers, cut
// to the range -- with internal::weld_chunk() in order, as
// extract_boolean_isosurface_by_slabs() does, so that it removes the same
// degenerate polygons (see weld_chunk()).  Only the first chunk differs: the
// single process looks its bottom-layer keys up in the slab below, which
// here is another range.  Without the message, every bottom-layer vertex is
// a local vertex (the match later finds the ones the range below has).  That
// is what the single process does unless one of its merge classes holds two
// bottom-layer keys (two bottom-layer vertices at one position): whether they
// are merged then depends on the indices the range below gave them, and the
// range is marked `depends_on_below`.  With the message, a bottom-layer key
// the range below has looks up "tag | its local index below", so weld_chunk()
// takes exactly the single-process decisions; such a vertex still gets a
// local point, at its place in the local order, and is listed with its keys.
template <typename ConcurrencyTag, typename GeomTraits, typename FieldSource, typename Sink, typename NamedParameters>
void extract_slab_range(const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                        const Boolean_expression& expression, std::size_t first_layer, std::size_t last_layer,
                        const std::vector<std::uint64_t>* message, Sink& sink, Boolean_isosurface_slab_range& range,
                        const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Tbiso_vertex_key Key;

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

  const std::size_t W = Boolean_isosurface_slab_range::key_words;
  const std::size_t tag = std::size_t(1) << (std::numeric_limits<std::size_t>::digits - 1);
  const std::size_t no_index = tbiso_no_index();
  std::unordered_map<Key, std::size_t, Tbiso_vertex_key_hash> from_below;
  if(message != nullptr && !message->empty())
  {
    const std::vector<std::uint64_t>& m = *message;
    if(m.size() < 3 || m.size() != 3 + m[2] * (1 + W))
      throw Invalid_input_error("malformed top-layer message from the range below");
    const std::size_t count = std::size_t(m[2]);
    from_below.reserve(count);
    for(std::size_t t = 0; t < count; ++t)
      from_below.emplace(key_from_words(m.data() + 3 + count + W * t), tag | std::size_t(m[3 + t]));
  }

  range = Boolean_isosurface_slab_range();
  range.first_layer = first_layer;
  range.last_layer = last_layer;
  range.number_of_layers = layers;
  if(message != nullptr)
    range.message_used = *message;
  const Tbiso_tetrahedron_evaluator prototype(expression, close);
  // The chunks: the grid's slabs [s * slab, (s + 1) * slab) cut to the range.
  std::vector<std::size_t> bounds{first_layer};
  while(bounds.back() < last_layer)
    bounds.push_back((std::min)(last_layer, (bounds.back() / slab + 1) * slab));
  const std::size_t number_of_slabs = bounds.size() - 1;
  const std::size_t window =
      is_parallel_tag<ConcurrencyTag>() ? 2 * std::max<std::size_t>(1, std::thread::hardware_concurrency()) : 1;

  struct Slot
  {
    std::size_t k_begin = 0, k_end = 0;
    std::vector<double> values;
    Tbiso_chunk chunk;
  };
  std::vector<Slot> slots((std::min)(window, (std::max<std::size_t>)(1, number_of_slabs)));
  // Each slot keeps its buffer: sized once for the largest slab (plus two
  // ghost layers and rounding), it is never reallocated.
  for(Slot& slot : slots)
    slot.values.reserve(((std::min)(slab, last_layer - first_layer) + 3) * layer_size * N);
  std::unordered_map<Key, std::size_t, Tbiso_vertex_key_hash> below, above;
  std::unordered_map<std::size_t, std::size_t> tag_to_local;
  std::size_t next_index = 0; // the points given to the sink
  std::vector<std::size_t> local; // one polygon's local vertices
  std::vector<std::array<double, 3>> bottom_points;

  for(std::size_t s0 = 0; s0 < number_of_slabs; s0 += slots.size())
  {
    const std::size_t count = (std::min)(slots.size(), number_of_slabs - s0);
    // Read in order (one file), then evaluate the window (in parallel).
    for(std::size_t w = 0; w < count; ++w)
    {
      Slot& slot = slots[w];
      slot.k_begin = bounds[s0 + w];
      slot.k_end = bounds[s0 + w + 1];
      const std::size_t lo = slot.k_begin > 0 ? slot.k_begin - 1 : 0, hi = (std::min)(n[2] - 1, slot.k_end + 1);
      source.read(lo * layer_size, (hi - lo + 1) * layer_size, slot.values);
    }
    std::size_t held = 0;
    for(const Slot& slot : slots)
      held += slot.values.capacity();
    range.peak_field_values = (std::max)(range.peak_field_values, held);
    concurrent_for<ConcurrencyTag>(count, [&](std::size_t w) {
      Slot& slot = slots[w];
      const std::size_t lo = slot.k_begin > 0 ? slot.k_begin - 1 : 0;
      for(std::size_t k = 0; k < slot.values.size(); ++k)
        if(!std::isfinite(slot.values[k]))
          throw Non_finite_value_error("field " + std::to_string(k % N) + " has a non-finite value at vertex " +
                                       std::to_string(lo * layer_size + k / N));
      slot.chunk = Tbiso_chunk();
      extract_grid_slab(grid, slot.values.data(), lo * layer_size, N, prototype, slot.k_begin, slot.k_end,
                        slot.chunk);
    });
    // Weld in slab order, as the single process does.
    for(std::size_t w = 0; w < count; ++w)
    {
      Tbiso_chunk& chunk = slots[w].chunk;
      const std::size_t k_begin = slots[w].k_begin, k_end = slots[w].k_end;
      const bool at_bottom = k_begin == first_layer && first_layer > 0;
      range.number_of_evaluated_tetrahedra += chunk.evaluated;
      if(at_bottom && message == nullptr)
      {
        bottom_points.clear();
        for(std::size_t v = 0; v < chunk.keys.size(); ++v)
          if(carrier_layer(chunk.keys[v], layer_size) == first_layer)
            bottom_points.push_back(chunk.points[v]);
        std::sort(bottom_points.begin(), bottom_points.end());
        range.depends_on_below =
            std::adjacent_find(bottom_points.begin(), bottom_points.end()) != bottom_points.end();
        std::vector<std::array<double, 3>>().swap(bottom_points);
      }
      if(!at_bottom || from_below.empty())
        chunk.index.clear(); // kept only to find the points of tagged keys
      above.clear();
      weld_chunk(
          chunk,
          [&](const Key& key) {
            if(carrier_layer(key, layer_size) != k_begin)
              return no_index;
            const auto& map = k_begin == first_layer ? from_below : below;
            const auto found = map.find(key);
            return found == map.end() ? no_index : found->second;
          },
          [&](const Key& key, std::size_t index) {
            if(index != no_index && (index & tag) != 0)
            {
              const auto inserted = tag_to_local.emplace(index, next_index);
              if(inserted.second)
              {
                sink.add_point(chunk.points[chunk.index.at(key)]);
                ++next_index;
              }
              index = inserted.first->second;
            }
            const std::size_t z = carrier_layer(key, layer_size);
            if(z == first_layer && at_bottom)
            {
              range.bottom_vertices.push_back(index);
              append_key(range.bottom_keys, key);
            }
            if(z == k_end)
            {
              if(k_end != last_layer)
                above.emplace(key, index);
              else if(last_layer < layers)
              {
                range.top_vertices.push_back(index);
                append_key(range.top_keys, key);
              }
            }
          },
          next_index, [&](const std::array<double, 3>& p) { sink.add_point(p); },
          [&](const std::size_t* v, std::size_t size, int label, int) {
            local.clear();
            for(std::size_t k = 0; k < size; ++k)
              local.push_back((v[k] & tag) != 0 ? tag_to_local.at(v[k]) : v[k]);
            sink.add_polygon(local.data(), size, label);
            ++range.polygon_count;
          });
      below.swap(above);
      tag_to_local.clear();
      chunk = Tbiso_chunk();
    }
  }
  range.vertex_count = next_index;
}

// The sink of the overloads that keep the range's surface in `range`.
struct Slab_range_sink
{
  Boolean_isosurface_slab_range& range;
  void add_point(const std::array<double, 3>& p) { range.points.push_back(p); }
  void add_polygon(const std::size_t* v, std::size_t n, int label)
  {
    range.polygon_vertices.insert(range.polygon_vertices.end(), v, v + n);
    range.polygon_begin.push_back(range.polygon_vertices.size());
    range.labels.push_back(label);
  }
};

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
/// TBISO on cube layers `[first_layer, last_layer)` of `grid`, reading from
/// `source` only the vertex layers `first_layer - 1 .. last_layer + 1`
/// (clamped to the grid; one ghost layer on each side, where the apex of a
/// neighbouring tetrahedron may lie), `slab_layers` cube layers at a time.
/// The result is `range`, with local vertex numbers; the polygons are those
/// of the sequential extraction for these layers, in the same order.
///
/// The range welds the grid's slabs (`slab_layers` layers each) in order,
/// removing what rounding to double leaves degenerate as
/// `extract_boolean_isosurface_by_slabs()` does.  When the range is made of
/// whole slabs (`slab_range_of_part()` with the same `slab_layers`), the
/// assembled ranges are that function's output exactly, degenerate inputs
/// included, except when the result is marked `range.depends_on_below`:
/// then extract the range again with the other overload, given the message
/// of the range below.
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
  internal::Slab_range_sink sink{range};
  internal::extract_slab_range<ConcurrencyTag>(grid, source, expression, first_layer, last_layer, nullptr, sink, range,
                                               np);
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// As the overload above, given `message_from_below`, the
/// `top_layer_message()` of the range just below: the welding of the first
/// slab then takes the single-process decisions whatever the input, and the
/// result never `depends_on_below`.  Pass the same message to
/// `match_boolean_isosurface_slab_range()`.  The range below must be final
/// (not itself `depends_on_below`), so ranges that depend on the one below
/// are extracted again in order, bottom up.
/// \throws Invalid_input_error as the overload above, or if the message is malformed.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename FieldSource,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void extract_boolean_isosurface_slab_range(const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                                           const Boolean_expression& expression, std::size_t first_layer,
                                           std::size_t last_layer,
                                           const std::vector<std::uint64_t>& message_from_below,
                                           Boolean_isosurface_slab_range& range,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Slab_range_sink sink{range};
  internal::extract_slab_range<ConcurrencyTag>(grid, source, expression, first_layer, last_layer, &message_from_below,
                                               sink, range, np);
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// As `extract_boolean_isosurface_slab_range()`, but the range's points and
/// polygons (local numbers, local order) go to `sink` as they are welded,
/// one slab at a time, instead of into `range`: `range` keeps only the
/// counts (`vertex_count`, `polygon_count`) and the bottom- and top-layer
/// vertices with their keys, all that the welding with the neighbours needs.
/// So memory is a few slabs of field values and of surface, whatever the
/// size of the range: `extract_boolean_isosurface_distributed()` streams to
/// a temporary file and renumbers while it copies to the output.
///
/// \param grid the whole regular grid
/// \param source the fields, a model of `ScalarFieldSource`
/// \param expression the Boolean expression of the fields
/// \param first_layer, last_layer the cube layers of the range
/// \param message_from_below null, or the `top_layer_message()` of the range
///        just below (as the second overload of `extract_boolean_isosurface_slab_range()`)
/// \param sink receives the surface, a model of `BooleanIsosurfaceSink`
/// \param range the counts and the boundary layers' vertices (overwritten)
/// \param np the named parameters of `extract_boolean_isosurface_slab_range()`
///
/// The exceptions are those of `extract_boolean_isosurface_slab_range()`.  If the result
/// `depends_on_below`, what went to `sink` must be discarded and the range
/// streamed again with the message.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename GeomTraits, typename FieldSource, typename Sink,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void stream_boolean_isosurface_slab_range(const Tetrahedral_grid_3<GeomTraits>& grid, FieldSource& source,
                                          const Boolean_expression& expression, std::size_t first_layer,
                                          std::size_t last_layer, const std::vector<std::uint64_t>* message_from_below,
                                          Sink& sink, Boolean_isosurface_slab_range& range,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::extract_slab_range<ConcurrencyTag>(grid, source, expression, first_layer, last_layer, message_from_below,
                                               sink, range, np);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_SLAB_RANGE_H
