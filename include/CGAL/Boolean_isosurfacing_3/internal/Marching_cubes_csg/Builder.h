// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_BUILDER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_BUILDER_H

// The machinery of marching_cubes_csg(): the output states of the lattice
// points, the edge vertices and the cube pass, after the classification.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Lattice_classifier_3.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_csg_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Csg_edge_point.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Collapse_short_edges.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_triangulation.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Resolution_check.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Weak_fan_check.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Release_free_memory.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

template <typename T>
struct Is_std_array : std::false_type {};
template <typename T, std::size_t N>
struct Is_std_array<std::array<T, N>> : std::true_type {};

// A std::vector of std::array<I, 3>, I an integer type: triangles the
// builder can write in place.
template <typename T>
struct Is_index_triple_vector : std::false_type {};
template <typename I>
struct Is_index_triple_vector<std::vector<std::array<I, 3>>> : std::is_integral<I> {};

template <typename Triangle>
Triangle make_output_triangle(const std::array<std::size_t, 3>& t)
{
  typedef typename Triangle::value_type Index;
  if constexpr(Is_std_array<Triangle>::value)
  {
    static_assert(std::tuple_size<Triangle>::value == 3, "an array triangle type must have 3 entries");
    Triangle result;
    for(int i = 0; i < 3; ++i)
      result[i] = Index(t[i]);
    return result;
  }
  else
  {
    Triangle result;
    for(int i = 0; i < 3; ++i)
      result.push_back(Index(t[i]));
    return result;
  }
}

template <typename Point>
Point make_output_point(const std::array<double, 3>& p)
{
  if constexpr(std::is_constructible<Point, double, double, double>::value)
    return Point(p[0], p[1], p[2]);
  else
    return Point{{p[0], p[1], p[2]}};
}

template <typename ConcurrencyTag>
std::size_t concurrency()
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
    return std::size_t((std::max)(1, tbb::this_task_arena::max_concurrency()));
#endif
  return 1;
}

// The input mesh of a triangle: the mesh of most of its vertices (a
// feature vertex, labelled 255, does not vote).
inline std::size_t face_mesh(const std::vector<std::uint8_t>& vertex_meshes, const std::array<std::size_t, 3>& t)
{
  const std::uint8_t a = vertex_meshes[t[0]], b = vertex_meshes[t[1]], c = vertex_meshes[t[2]];
  if(a == b || a == c)
    return a != 255 ? a : (b != 255 ? b : c);
  if(b == c)
    return b != 255 ? b : a;
  // Three different labels: the first known one.
  return a != 255 ? a : (b != 255 ? b : c);
}

// The crease edges (vertex pairs, smaller index first) and corner vertices
// of a soup, and (when asked for) the input mesh of each vertex (255 for a
// feature vertex, which lies on several).
struct Csg_features
{
  std::vector<std::array<std::size_t, 2>> crease_edges;
  std::vector<std::size_t> corner_vertices;
  bool record_vertex_meshes = false;
  std::vector<std::uint8_t> vertex_meshes;
};

// The phases after the classification: output states, vertices, cubes.
//
// The output states are stored sparsely, per x row of lattice points: the
// state of its first point and the sorted list of the row's *vertex edges*,
// coded 3 * i + axis: its x edge (i, i + 1), and the y edge to the next row
// and the z edge to the next plane at point i, whose ends have different
// states.  These lists hold one entry per output vertex, in vertex order.
// Only the rows whose x line the classifier stores (it holds crossings or
// starts inside a mesh) can differ from the state of the empty mask, and
// only the rows with a vertex edge are listed, so memory and work grow with
// the surface, not with the lattice nor its cross-sections.
template <typename ConcurrencyTag>
class Marching_cubes_csg_builder
{
public:
  typedef Marching_cubes_csg::Vector_3d Vector_3d;
  typedef Marching_cubes_csg::Feature_settings Feature_settings;
  typedef Marching_cubes_csg::Triangle_tangent Triangle_tangent;

  // `tangents` (one per input triangle, in the classifier's numbering) is
  // only read when `features.enabled`.
  Marching_cubes_csg_builder(const Lattice_classifier_3& classifier, const Boolean_expression& expression,
                             const Feature_settings& features, const std::vector<Triangle_tangent>& tangents)
    : m_classifier(classifier), m_lattice(classifier.lattice()), m_inside(expression),
      m_n(m_lattice.number_of_points()), m_features(features), m_tangents(tangents), m_normals(tangents),
      m_empty_state(m_inside(0))
  {}

  // Bytes per lattice plane and per output vertex that the builder
  // allocates on top of the classifier (for its memory estimate).
  static std::size_t bytes_per_plane() { return 2 * sizeof(Plane_rows); }
  static std::size_t bytes_per_vertex() { return 4 * sizeof(std::uint32_t); }

  // The vertex edge lists of every row; returns the number of lattice
  // boundary points inside the result.
  std::size_t compute_states(const Progress& progress)
  {
    const std::size_t nz = m_n[2];
    // The x changes of every row first: the y and z edges compare two rows.
    m_changes.assign(nz, Plane_changes());
    concurrent_for<ConcurrencyTag>(
        nz, [&](std::size_t k) { x_changes_of_plane(k, m_changes[k]); }, progress.part(0, 0.4));
    m_planes.assign(nz, Plane_rows());
    concurrent_for<ConcurrencyTag>(
        nz, [&](std::size_t k) { vertex_edges_of_plane(k, m_planes[k]); }, progress.part(0.4, 1));
    m_vertex_offset.assign(nz + 1, 0);
    for(std::size_t k = 0; k < nz; ++k)
      m_vertex_offset[k + 1] = m_vertex_offset[k] + m_planes[k].codes.size();
    return boundary_points_inside();
  }

  // Vertices are numbered plane by plane (z), and in a plane by edge id
  // 3 * (i + nx * j) + axis: the edges of plane k are its x and y edges and
  // the z edges from plane k to k + 1.
  void compute_vertices(std::vector<std::array<double, 3>>& points, const Progress& progress)
  {
    const std::size_t nz = m_n[2];
    if(m_vertex_offset[nz] >= (std::size_t(1) << 32) && sizeof(std::size_t) < 8)
      throw Lattice_too_large_error("too many output vertices for this platform");
    // Room for the feature vertices appended later (about 1 % of the edge
    // points; untouched capacity costs no memory): growing the vector then
    // would hold two copies of every point at once.
    if(m_features.enabled)
      points.reserve(m_vertex_offset[nz] + m_vertex_offset[nz] / 8 + 64);
    points.resize(m_vertex_offset[nz]);
    if(m_features.enabled)
      m_normals.resize(points.size());
    if(m_vertex_meshes != nullptr)
      m_vertex_meshes->assign(points.size(), no_mesh);
    concurrent_for<ConcurrencyTag>(
        nz, [&](std::size_t k) { vertices_of_plane(k, points); }, progress);
  }

  // Fans pass the weaker fold test (`Fold_test::SUM`) except in the cubes
  // `strict_cubes` (ids i + nx (j + ny k), sorted), which must outlive the
  // builder; weak_fans() then lists the fans only that test accepted.
  // Without this call every fan passes the strict test.
  void use_weak_fold_test(const std::vector<std::uint64_t>& strict_cubes) { m_strict_cubes = &strict_cubes; }
  // (f, cube id), increasing f: the fan of feature vertex f (0 for the
  // first feature vertex) passed only the weaker fold test.
  const std::vector<std::array<std::uint64_t, 2>>& weak_fans() const { return m_weak_fans; }

  // compute_vertices() will write into `meshes` the input mesh of each edge
  // vertex (the mesh of the crossing it is on); the face labels of the output.
  void record_vertex_meshes(std::vector<std::uint8_t>& meshes) { m_vertex_meshes = &meshes; }
  static constexpr std::uint8_t no_mesh = 255;
  static constexpr std::size_t no_normal = std::size_t(-1);

  // The edge ids 3 * (i + nx * j) + axis of the vertices of plane k, in
  // vertex order (for the welding of slab ranges).
  void plane_vertex_edges(std::size_t k, std::vector<std::uint64_t>& out) const
  {
    const Plane_rows& p = m_planes[k];
    for(std::size_t r = 0; r < p.rows.size(); ++r)
      for(std::size_t c = p.begin[r]; c < p.begin[r + 1]; ++c)
        out.push_back(std::uint64_t(p.codes[c]) + 3 * std::uint64_t(m_n[0]) * p.rows[r]);
  }

  // With sharp features: `points` (the edge vertices) gets the feature
  // vertices appended, and `soup_creases`, `soup_corners` the crease edges and
  // corner vertices.  The planes are released (release_planes()) once the
  // cubes are triangulated: the merge of the chunks, the memory peak of the
  // path, does not need them.
  template <typename Triangle>
  void compute_feature_triangles(std::vector<std::array<double, 3>>& points, std::vector<Triangle>& triangles,
                                 std::vector<std::array<std::size_t, 2>>& soup_creases,
                                 std::vector<std::size_t>& soup_corners, Marching_cubes_csg_statistics& statistics,
                                 const Progress& progress)
  {
    CGAL_precondition(m_features.enabled);
    if(m_n[0] < 2 || m_n[1] < 2 || m_n[2] < 2)
      return;
    if(points.size() >= Marching_cubes_csg::max_chunk_vertices)
      throw Lattice_too_large_error("more than 2^31 edge points: too many for the feature path");
    const std::size_t layers = m_n[2] - 1;
    {
      // The chunks only change who computes what: the output is the
      // concatenation of the layers in order, whatever the chunking.
      const std::size_t chunks =
          (std::min)(layers, is_parallel_tag<ConcurrencyTag>() ? 8 * concurrency<ConcurrencyTag>() : 1);
      std::vector<Marching_cubes_csg::Feature_chunk> buffers(chunks);
      concurrent_for<ConcurrencyTag>(
          chunks,
          [&](std::size_t c) {
            // A closed surface has about two triangles a vertex (each
            // feature vertex adds two, a handle four): reserved with room
            // to spare (untouched capacity costs no memory), the buffer is
            // not copied as it grows.
            const std::size_t first = layers * c / chunks, last = layers * (c + 1) / chunks;
            const std::size_t vertices = m_vertex_offset[last] - m_vertex_offset[first];
            buffers[c].triangles.reserve(2 * vertices + vertices / 4 + 64);
            triangulate_feature_layers(first, last, points, buffers[c]);
          },
          progress);
      release_planes();
      m_weak_fans.clear();
      std::uint64_t first_of_chunk = 0;
      for(const auto& b : buffers)
      {
        for(const std::array<std::uint64_t, 2>& w : b.weak_fans)
          m_weak_fans.push_back({{first_of_chunk + w[0], w[1]}});
        first_of_chunk += b.feature_points.size();
        statistics.plain_feature_polygons += b.plain.no_point + b.plain.folded;
        statistics.folded_feature_polygons += b.plain.folded;
      }
      std::vector<Marching_cubes_csg::Flipped_edge> flipped;
      const std::size_t first_feature = points.size();
      const std::vector<Marching_cubes_csg::Feature_kind> kinds =
          Marching_cubes_csg::merge_feature_chunks(buffers, points, m_normals, triangles, flipped);
      statistics.feature_vertices = kinds.size();
      statistics.flipped_edges = flipped.size();
      for(std::size_t f = 0; f < kinds.size(); ++f)
        if(kinds[f] == Marching_cubes_csg::Feature_kind::CORNER)
          soup_corners.push_back(first_feature + f);
      statistics.corner_vertices = soup_corners.size();
      for(const Marching_cubes_csg::Flipped_edge& e : flipped)
        if(e.cos_dihedral < m_features.cos_feature_angle)
          soup_creases.push_back({{e.v0, e.v1}});
      statistics.crease_edges = soup_creases.size();
      m_normals.clear();
    }
  }

  // Frees the per-plane vertex numbering and states: what the triangles
  // needed, and nothing after them does (the sliver passes need their memory).
  // Many small vectors filled by several threads: the heap keeps them
  // resident unless asked to give them back, which pays only when they are
  // large (90 MB less at the peak of 2048 cells).  Small ones are better
  // kept: the sliver tables reuse their pages, where pages handed back and
  // mapped again cost a page fault each (a tenth of the feature path's time
  // at 128 cells).  A second call does nothing.
  void release_planes()
  {
    if(m_changes.empty() && m_planes.empty())
      return;
    std::size_t bytes = 0;
    for(const Plane_changes& p : m_changes)
      bytes += 4 * (p.rows.capacity() + p.begin.capacity() + p.changes.capacity()) + p.first.capacity();
    for(const Plane_rows& p : m_planes)
      bytes += 4 * (p.rows.capacity() + p.begin.capacity() + p.codes.capacity());
    std::vector<Plane_changes>().swap(m_changes);
    std::vector<Plane_rows>().swap(m_planes);
    if(bytes >= min_bytes_worth_releasing)
      release_free_memory();
  }

  // Plain Marching Cubes, into `triangles` (whose elements are arrays of
  // three indices of any integer type that holds the vertex count): a count
  // pass, then every layer writes its triangles at its offset (Flying Edges'
  // scheme: no buffers to merge, and the output does not depend on the
  // concurrency).
  template <typename Triangle>
  void compute_plain_triangles(std::vector<Triangle>& triangles, const Progress& progress)
  {
    typedef typename Triangle::value_type Index;
    triangles.clear();
    if(m_n[0] < 2 || m_n[1] < 2 || m_n[2] < 2)
      return;
    if(m_vertex_offset.back() > std::size_t((std::numeric_limits<Index>::max)()))
      throw Lattice_too_large_error("the output has more vertices than its index type can number");
    const std::size_t layers = m_n[2] - 1;
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    std::vector<std::size_t> offset(layers + 1, 0);
    concurrent_for<ConcurrencyTag>(
        layers,
        [&](std::size_t k) {
          std::size_t count = 0;
          for_each_crossed_cube(k, k + 1, [&](std::size_t, std::size_t, std::size_t, unsigned code, const auto&) {
            count += table.triangles(code).size();
          });
          offset[k + 1] = count;
        },
        progress.part(0, 0.3));
    for(std::size_t k = 0; k < layers; ++k)
      offset[k + 1] += offset[k];
    triangles.resize(offset[layers]);
    concurrent_for<ConcurrencyTag>(
        layers,
        [&](std::size_t k) {
          Triangle* out = triangles.data() + offset[k];
          for_each_crossed_cube(k, k + 1, [&](std::size_t, std::size_t, std::size_t, unsigned code,
                                              const auto& vertex_of) {
            for(const Marching_cubes_table::Triangle& t : table.triangles(code))
              *out++ = Triangle{{Index(vertex_of(t[0])), Index(vertex_of(t[1])), Index(vertex_of(t[2]))}};
          });
        },
        progress.part(0.3, 1));
  }

private:
  // The x rows of one plane whose x line the classifier stores, by
  // increasing j: row rows[r] has first state first[r] and x changes
  // changes[begin[r] .. begin[r + 1]) (the indices i whose x edge (i, i + 1)
  // joins two different states).  Every other row has the state of the
  // empty mask everywhere.
  struct Plane_changes
  {
    std::vector<std::uint32_t> rows;
    std::vector<std::uint32_t> begin{0};
    std::vector<std::uint32_t> changes;
    std::vector<std::uint8_t> first;
  };

  // The x rows of one plane with vertex edges, by increasing j: row rows[r]
  // has the codes codes[begin[r] .. begin[r + 1]) (increasing 3 * i + axis).
  struct Plane_rows
  {
    std::vector<std::uint32_t> rows;
    std::vector<std::uint32_t> begin{0};
    std::vector<std::uint32_t> codes;
  };

  // A row's states: its first state and its x changes.
  struct Row_states
  {
    bool first = false;
    const std::uint32_t* changes = nullptr;
    const std::uint32_t* changes_end = nullptr;

    std::size_t inside_points(std::size_t nx) const
    {
      std::size_t inside = 0, from = 0;
      bool s = first;
      for(const std::uint32_t* c = changes; c != changes_end; ++c)
      {
        if(s)
          inside += *c + 1 - from;
        s = !s;
        from = *c + 1;
      }
      return inside + (s ? nx - from : 0);
    }
    bool last_state() const { return first ^ (std::size_t(changes_end - changes) % 2 == 1); }
  };

  // Position of `j` in the sorted `rows`, or rows.size().
  static std::size_t find_row(const std::vector<std::uint32_t>& rows, std::size_t j)
  {
    const auto it = std::lower_bound(rows.begin(), rows.end(), std::uint32_t(j));
    return it != rows.end() && *it == j ? std::size_t(it - rows.begin()) : rows.size();
  }

  Row_states states_of(std::size_t k, std::size_t j) const
  {
    const Plane_changes& p = m_changes[k];
    const std::size_t r = find_row(p.rows, j);
    if(r == p.rows.size())
      return Row_states{m_empty_state, nullptr, nullptr};
    return Row_states{p.first[r] != 0, p.changes.data() + p.begin[r], p.changes.data() + p.begin[r + 1]};
  }

  // The codes of row j of plane k (an empty range for a row without vertex
  // edges), and their position in the plane's codes.
  struct Row_codes
  {
    const std::uint32_t* begin = nullptr;
    const std::uint32_t* end = nullptr;
    std::size_t offset = 0;
    bool empty() const { return begin == end; }
  };

  Row_codes codes_of(std::size_t k, std::size_t j) const
  {
    const Plane_rows& p = m_planes[k];
    const std::size_t r = find_row(p.rows, j);
    if(r == p.rows.size())
      return Row_codes();
    return Row_codes{p.codes.data() + p.begin[r], p.codes.data() + p.begin[r + 1], p.begin[r]};
  }

  // The x changes of x line (j, k) (stored line `line`).
  void x_changes_of_line(const Lattice_classifier_3::Stored_line& line, std::vector<std::uint32_t>& changes,
                         std::uint8_t& first) const
  {
    std::uint64_t mask = line.start_mask;
    bool state = m_inside(mask);
    first = std::uint8_t(state);
    for(const Lattice_crossing* c = line.crossings.begin(); c != line.crossings.end();)
    {
      const std::uint32_t index = c->index; // on the edge (index - 1, index)
      for(; c != line.crossings.end() && c->index == index; ++c)
        mask ^= std::uint64_t(1) << c->mesh;
      const bool now = m_inside(mask);
      if(now != state)
      {
        changes.push_back(index - 1);
        state = now;
      }
    }
  }

  void x_changes_of_plane(std::size_t k, Plane_changes& plane) const
  {
    const Lattice_classifier_3::Stored_lines lines = m_classifier.stored_lines(0, k);
    plane.rows.reserve(lines.size());
    plane.first.reserve(lines.size());
    for(std::size_t l = 0; l < lines.size(); ++l)
    {
      const Lattice_classifier_3::Stored_line line = lines[l];
      plane.rows.push_back(std::uint32_t(line.u));
      plane.first.push_back(0);
      x_changes_of_line(line, plane.changes, plane.first.back());
      plane.begin.push_back(std::uint32_t(plane.changes.size()));
    }
  }

  // Appends the indices i < nx where the states of two rows differ,
  // increasing.
  static void differences(Row_states a, Row_states b, std::size_t nx, std::vector<std::uint32_t>& out)
  {
    std::size_t i = 0;
    while(i < nx)
    {
      // Both states are constant on [i, next].
      std::size_t next = nx - 1;
      if(a.changes != a.changes_end)
        next = (std::min)(next, std::size_t(*a.changes));
      if(b.changes != b.changes_end)
        next = (std::min)(next, std::size_t(*b.changes));
      if(a.first != b.first)
        for(std::size_t x = i; x <= next; ++x)
          out.push_back(std::uint32_t(x));
      if(a.changes != a.changes_end && *a.changes == next)
      {
        a.first = !a.first;
        ++a.changes;
      }
      if(b.changes != b.changes_end && *b.changes == next)
      {
        b.first = !b.first;
        ++b.changes;
      }
      i = next + 1;
    }
  }

  // Calls f(j) for every j in [0, limit) of the union of the sorted lists,
  // each shifted by its offset (-1 or 0), in increasing order, once.
  template <typename F>
  static void for_each_row_of_union(const std::array<const std::vector<std::uint32_t>*, 3>& lists,
                                    const std::array<int, 3>& shift, std::size_t limit, const F& f)
  {
    std::array<std::size_t, 3> at{{0, 0, 0}};
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    for(;;)
    {
      std::size_t j = none;
      for(int l = 0; l < 3; ++l)
      {
        if(lists[l] == nullptr)
          continue;
        // Skip the entries the shift moves below 0.
        while(at[l] < lists[l]->size() && std::ptrdiff_t((*lists[l])[at[l]]) + shift[l] < 0)
          ++at[l];
        if(at[l] < lists[l]->size())
          j = (std::min)(j, std::size_t(std::ptrdiff_t((*lists[l])[at[l]]) + shift[l]));
      }
      if(j == none || j >= limit)
        return;
      f(j);
      for(int l = 0; l < 3; ++l)
        if(lists[l] != nullptr && at[l] < lists[l]->size() &&
           std::size_t(std::ptrdiff_t((*lists[l])[at[l]]) + shift[l]) == j)
          ++at[l];
    }
  }

  void vertex_edges_of_plane(std::size_t k, Plane_rows& plane) const
  {
    const std::size_t nx = m_n[0], ny = m_n[1], nz = m_n[2];
    const bool has_above = k + 1 < nz;
    std::vector<std::uint32_t> y, z;
    // A row can have vertex edges only if it, the next row or the row above
    // is listed: otherwise all three have the state of the empty mask.
    const std::array<const std::vector<std::uint32_t>*, 3> lists{
        {&m_changes[k].rows, &m_changes[k].rows, has_above ? &m_changes[k + 1].rows : nullptr}};
    for_each_row_of_union(lists, {{0, -1, 0}}, ny, [&](std::size_t j) {
      const Row_states here = states_of(k, j);
      y.clear();
      z.clear();
      if(j + 1 < ny)
        differences(here, states_of(k, j + 1), nx, y);
      if(has_above)
        differences(here, states_of(k + 1, j), nx, z);
      // Merge the three increasing lists into codes 3 * i + axis.
      const std::size_t before = plane.codes.size();
      const std::uint32_t* x = here.changes;
      const std::uint32_t* yc = y.data();
      const std::uint32_t* zc = z.data();
      const std::uint32_t* y_end = y.data() + y.size();
      const std::uint32_t* z_end = z.data() + z.size();
      while(x != here.changes_end || yc != y_end || zc != z_end)
      {
        std::uint32_t i = std::numeric_limits<std::uint32_t>::max();
        if(x != here.changes_end) i = (std::min)(i, *x);
        if(yc != y_end) i = (std::min)(i, *yc);
        if(zc != z_end) i = (std::min)(i, *zc);
        if(x != here.changes_end && *x == i) { plane.codes.push_back(3 * i); ++x; }
        if(yc != y_end && *yc == i) { plane.codes.push_back(3 * i + 1); ++yc; }
        if(zc != z_end && *zc == i) { plane.codes.push_back(3 * i + 2); ++zc; }
      }
      if(plane.codes.size() == before)
        return;
      if(plane.codes.size() >= std::numeric_limits<std::uint32_t>::max())
        throw Lattice_too_large_error("more than 2^32 output vertices in one lattice plane");
      plane.rows.push_back(std::uint32_t(j));
      plane.begin.push_back(std::uint32_t(plane.codes.size()));
    });
  }

  // Points on the lattice boundary inside the result: whole rows on the
  // boundary planes and the rows j = 0 and ny - 1, the two ends of the
  // other rows.  Unlisted rows have the empty mask's state: counted in bulk.
  std::size_t boundary_points_inside() const
  {
    const std::size_t nx = m_n[0], ny = m_n[1], nz = m_n[2];
    const std::size_t ends = nx > 1 ? 2 : 1;
    std::size_t inside = 0;
    for(std::size_t k = 0; k < nz; ++k)
    {
      const bool boundary_plane = k == 0 || k + 1 == nz;
      const Plane_changes& p = m_changes[k];
      std::size_t listed_whole = 0, listed_ends = 0;
      for(std::size_t r = 0; r < p.rows.size(); ++r)
      {
        const Row_states row{p.first[r] != 0, p.changes.data() + p.begin[r], p.changes.data() + p.begin[r + 1]};
        const std::size_t j = p.rows[r];
        if(boundary_plane || j == 0 || j + 1 == ny)
        {
          inside += row.inside_points(nx);
          ++listed_whole;
        }
        else
        {
          inside += std::size_t(row.first) + (nx > 1 ? std::size_t(row.last_state()) : 0);
          ++listed_ends;
        }
      }
      if(m_empty_state)
      {
        const std::size_t whole = boundary_plane ? ny : (ny > 1 ? 2 : 1);
        inside += (whole - listed_whole) * nx + (ny - whole - listed_ends) * ends;
      }
    }
    return inside;
  }

  // The mask along an x line, walked with increasing i.
  class Line_mask
  {
  public:
    Line_mask(const Lattice_classifier_3& classifier, std::size_t line)
      : m_mask(classifier.start_mask(line))
    {
      const Lattice_classifier_3::Crossing_range c = classifier.crossings_on_line(0, line);
      m_next = c.begin();
      m_end = c.end();
    }
    // The mask of point i; i never decreases from call to call.
    std::uint64_t at(std::size_t i)
    {
      for(; m_next != m_end && m_next->index <= i; ++m_next)
        m_mask ^= std::uint64_t(1) << m_next->mesh;
      return m_mask;
    }
    // The crossings on the edge (i, i + 1), after at(i).
    Lattice_classifier_3::Crossing_range edge_after(std::size_t i) const
    {
      const Lattice_crossing* last = m_next;
      while(last != m_end && last->index == i + 1)
        ++last;
      return Lattice_classifier_3::Crossing_range(m_next, last);
    }

  private:
    std::uint64_t m_mask;
    const Lattice_crossing* m_next;
    const Lattice_crossing* m_end;
  };

  // The stored lines of one row along y or z, looked up with increasing u.
  class Line_cursor
  {
  public:
    Line_cursor(const Lattice_classifier_3& classifier, int axis, std::size_t row)
      : m_lines(classifier.stored_lines(axis, row))
    {}
    // The crossings of the line at `u` on the edge ending at point `index`;
    // `u` never decreases from call to call.
    Lattice_classifier_3::Crossing_range edge(std::size_t u, std::uint32_t index)
    {
      // A few steps, then a binary search: a row of points uses a few of the
      // plane's lines, far apart.
      for(int step = 0; m_at < m_lines.size() && m_lines.u(m_at) < u; ++step)
        if(step < 4)
          ++m_at;
        else
        {
          m_at = m_lines.lower_bound(u, m_at);
          break;
        }
      if(m_at == m_lines.size() || m_lines.u(m_at) != u)
        return Lattice_classifier_3::Crossing_range();
      const Lattice_classifier_3::Crossing_range line = m_lines[m_at].crossings;
      const Lattice_crossing* first = std::lower_bound(
          line.begin(), line.end(), index, [](const Lattice_crossing& c, std::uint32_t x) { return c.index < x; });
      const Lattice_crossing* last = first;
      while(last != line.end() && last->index == index)
        ++last;
      return Lattice_classifier_3::Crossing_range(first, last);
    }

  private:
    Lattice_classifier_3::Stored_lines m_lines;
    std::size_t m_at = 0;
  };

  void vertices_of_plane(std::size_t k, std::vector<std::array<double, 3>>& points)
  {
    const std::size_t ny = m_n[1];
    const Plane_rows& p = m_planes[k];
    std::size_t id = m_vertex_offset[k];
    for(std::size_t r = 0; r < p.rows.size(); ++r)
    {
      const std::size_t j = p.rows[r];
      Line_mask here(m_classifier, j + ny * k);
      // The masks of the next row and of the row above, made when needed;
      // the y lines of plane k and the z lines of row j, walked with i.
      std::optional<Line_mask> next_row, row_above;
      Line_cursor y_lines(m_classifier, 1, k), z_lines(m_classifier, 2, j);
      for(std::size_t c = p.begin[r]; c < p.begin[r + 1]; ++c, ++id)
      {
        const std::size_t i = p.codes[c] / 3;
        const int axis = int(p.codes[c] % 3);
        const std::uint64_t low_mask = here.at(i);
        const bool from_low = m_inside(low_mask);
        Lattice_classifier_3::Crossing_range crossings;
        std::uint64_t inside_mask = low_mask;
        if(axis == 0)
        {
          crossings = here.edge_after(i);
          if(!from_low)
            for(const Lattice_crossing& x : crossings)
              inside_mask ^= std::uint64_t(1) << x.mesh;
        }
        else if(axis == 1)
        {
          crossings = y_lines.edge(i, std::uint32_t(j + 1));
          if(!from_low)
          {
            if(!next_row)
              next_row.emplace(m_classifier, j + 1 + ny * k);
            inside_mask = next_row->at(i);
          }
        }
        else
        {
          crossings = z_lines.edge(i, std::uint32_t(k + 1));
          if(!from_low)
          {
            if(!row_above)
              row_above.emplace(m_classifier, j + ny * (k + 1));
            inside_mask = row_above->at(i);
          }
        }
        points[id] = vertex_position(crossings, i, j, k, axis, from_low, inside_mask,
                                     m_features.enabled ? id : no_normal,
                                     m_vertex_meshes != nullptr ? &(*m_vertex_meshes)[id] : nullptr);
      }
    }
  }

  // The vertex of a lattice edge with these crossings whose inside end has
  // mask `mask`; records the outward unit normal of the input triangle it
  // lies on as that of vertex `normal` (unless it is `no_normal`).
  std::array<double, 3> vertex_position(const Lattice_classifier_3::Crossing_range& crossings, std::size_t i,
                                        std::size_t j, std::size_t k, int axis, bool from_low, std::uint64_t mask,
                                        std::size_t normal, std::uint8_t* mesh)
  {
    const std::size_t c = csg_edge_crossing(crossings.begin(), crossings.size(), from_low, mask, m_inside);
    if(c == crossings.size())
      throw std::logic_error("marching_cubes_csg: the crossings of a lattice edge contradict the classification "
                             "of its ends (this is a bug)");
    std::array<double, 3> p{{m_lattice.coordinate(0, i), m_lattice.coordinate(1, j), m_lattice.coordinate(2, k)}};
    p[axis] = crossings[c].position;
    if(normal != no_normal)
      m_normals.set(normal, crossings[c].triangle, axis, from_low);
    if(mesh != nullptr)
      *mesh = std::uint8_t(crossings[c].mesh);
    return p;
  }

  // The walk both triangulations share: calls f(i, j, k, code, vertex_of)
  // for every cube of the layers [first, last) whose corners do not all have
  // the same state, layer by layer, then by cube (i fastest).  `code` has
  // bit c set iff corner c is inside; `vertex_of(e)` is the output vertex on
  // cube edge e.  Only the rows of cubes next to a row with vertex edges are
  // looked at, and in them only the runs between x changes, so the work
  // grows with the surface.
  template <typename F>
  void for_each_crossed_cube(std::size_t first, std::size_t last, const F& f) const
  {
    const std::size_t nx = m_n[0], ny = m_n[1];
    for(std::size_t k = first; k < last; ++k)
    {
      // A cube row whose first three point rows have no vertex edge: no x
      // change, and the same state as the next row and the row above, so
      // all four rows are uniform and equal.
      const std::array<const std::vector<std::uint32_t>*, 3> lists{
          {&m_planes[k].rows, &m_planes[k].rows, &m_planes[k + 1].rows}};
      for_each_row_of_union(lists, {{0, -1, 0}}, ny - 1, [&](std::size_t j) {
        // The point rows of the cube row: corner c is on row (c >> 1) & 3
        // (its y and z offsets), at x offset c & 1.
        const std::array<Row_codes, 4> rows{{codes_of(k, j), codes_of(k, j + 1), codes_of(k + 1, j),
                                             codes_of(k + 1, j + 1)}};
        const std::array<std::size_t, 4> plane_offset{
            {m_vertex_offset[k], m_vertex_offset[k], m_vertex_offset[k + 1], m_vertex_offset[k + 1]}};
        // Per row: the next x change (a code 3 i), the current state, and
        // the cursor of vertex_of().
        std::array<const std::uint32_t*, 4> x_next, cursor;
        std::array<bool, 4> state;
        auto next_x_change = [&](int r, const std::uint32_t* c) {
          while(c != rows[r].end && *c % 3 != 0)
            ++c;
          return c;
        };
        for(int r = 0; r < 4; ++r)
        {
          x_next[r] = next_x_change(r, rows[r].begin);
          cursor[r] = rows[r].begin;
          // A row without codes is uniform: its first state is its state.
          state[r] = states_of(k + std::size_t(r >> 1), j + std::size_t(r & 1)).first;
        }
        std::size_t cube = 0; // the vertices of this cube: vertex_of reads it
        const auto vertex_of = [&](int e) {
          // The default face rule never needs a polygon centre vertex.
          CGAL_assertion(!Marching_cubes_table::is_centre_vertex(unsigned(e)));
          const std::array<int, 3> o = cube_edge_origin_offset(e);
          const int r = o[1] + 2 * o[2];
          const std::uint32_t code = std::uint32_t(3 * (cube + std::size_t(o[0])) + std::size_t(cube_edge_axis(e)));
          // The cursor stays at the first code of this cube (monotone over
          // the cubes of the row); this edge's code is a few entries on.
          const std::uint32_t* c = cursor[r];
          while(*c < 3 * cube)
            ++c;
          cursor[r] = c;
          while(*c < code)
            ++c;
          CGAL_assertion(c != rows[r].end && *c == code);
          return plane_offset[r] + rows[r].offset + std::size_t(c - rows[r].begin);
        };
        auto code_of = [](const std::array<bool, 4>& low, const std::array<bool, 4>& high) {
          unsigned code = 0;
          for(int c = 0; c < 8; ++c)
            code |= unsigned((c & 1) ? high[(c >> 1) & 3] : low[(c >> 1) & 3]) << c;
          return code;
        };
        std::size_t i = 0;
        while(i + 1 < nx)
        {
          // States are constant on the points i .. e: cubes i .. e - 1 have
          // their corners' states; cube e joins them to the next ones.
          std::size_t e = nx - 1;
          for(int r = 0; r < 4; ++r)
            if(x_next[r] != rows[r].end)
              e = (std::min)(e, std::size_t(*x_next[r] / 3));
          if(!(state[0] == state[1] && state[0] == state[2] && state[0] == state[3]))
          {
            const unsigned code = code_of(state, state);
            for(cube = i; cube < e; ++cube)
              f(cube, j, k, code, vertex_of);
          }
          if(e + 1 >= nx)
            break;
          std::array<bool, 4> after = state;
          for(int r = 0; r < 4; ++r)
            if(x_next[r] != rows[r].end && *x_next[r] / 3 == e)
            {
              after[r] = !after[r];
              x_next[r] = next_x_change(r, x_next[r] + 1);
            }
          cube = e;
          f(cube, j, k, code_of(state, after), vertex_of);
          state = after;
          i = e + 1;
        }
      });
    }
  }

  // The cubes of layers [first, last), the polygons whose normals disagree
  // fanned around their feature vertex.
  void triangulate_feature_layers(std::size_t first, std::size_t last, const std::vector<Vector_3d>& points,
                                  Marching_cubes_csg::Feature_chunk& out) const
  {
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    for_each_crossed_cube(first, last, [&](std::size_t i, std::size_t j, std::size_t k, unsigned code,
                                           const auto& vertex_of) {
      const Vector_3d cube_low{{m_lattice.coordinate(0, i), m_lattice.coordinate(1, j), m_lattice.coordinate(2, k)}};
      const Vector_3d cube_high{
          {m_lattice.coordinate(0, i + 1), m_lattice.coordinate(1, j + 1), m_lattice.coordinate(2, k + 1)}};
      const std::uint64_t cube = i + m_n[0] * (j + m_n[1] * std::uint64_t(k));
      const bool strict =
          m_strict_cubes == nullptr || std::binary_search(m_strict_cubes->begin(), m_strict_cubes->end(), cube);
      const Marching_cubes_csg::Feature_decision decide(cube_low, cube_high, m_features, out, cube, strict);
      Marching_cubes_csg::triangulate_feature_cube(table, code, vertex_of, points, m_normals, decide, out);
    });
  }

  const Lattice_classifier_3& m_classifier;
  const Regular_lattice_3& m_lattice;
  Expression_evaluator m_inside;
  std::array<std::size_t, 3> m_n;
  std::vector<Plane_changes> m_changes;
  std::vector<Plane_rows> m_planes;
  std::vector<std::size_t> m_vertex_offset;
  Feature_settings m_features;
  const std::vector<Triangle_tangent>& m_tangents;
  Marching_cubes_csg::Edge_vertex_normals m_normals; // of each edge vertex (features only)
  std::vector<std::uint8_t>* m_vertex_meshes = nullptr;
  bool m_empty_state;               // the state of a point inside no mesh
  const std::vector<std::uint64_t>* m_strict_cubes = nullptr; // null: all strict (use_weak_fold_test())
  std::vector<std::array<std::uint64_t, 2>> m_weak_fans;
};

// The triangles of the input meshes, each read through its map of the
// named parameter `vertex_point_maps` (map m for mesh m) when it is given,
// else through the mesh's own `vertex_point` map.
template <typename TriangleMeshRange, typename NamedParameters>
std::vector<Lattice_triangle> read_csg_meshes(const TriangleMeshRange& meshes, std::size_t& number_of_meshes,
                                              const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::vertex_point_maps_t>::value)
    return Lattice_classifier_3::read_meshes(meshes, number_of_meshes);
  else
  {
    const auto& maps = parameters::get_parameter(np, internal_np::vertex_point_maps);
    const std::size_t given = std::size_t(std::distance(std::begin(maps), std::end(maps)));
    const std::size_t expected = std::size_t(std::distance(std::begin(meshes), std::end(meshes)));
    if(given != expected)
      throw Invalid_input_error("vertex_point_maps has " + std::to_string(given) + " map(s) for " +
                                std::to_string(expected) + " mesh(es): give one map per mesh");
    return Lattice_classifier_3::read_meshes(meshes, number_of_meshes,
                                             [&](const auto& mesh, std::uint32_t m, auto& out) {
                                               append_lattice_triangles(mesh, *std::next(std::begin(maps), m), m, out);
                                             });
  }
}

// One line per reason the output lacks a documented guarantee.
inline void add_csg_warnings(Marching_cubes_csg_statistics& statistics)
{
  if(statistics.boundary_points_inside > 0)
    statistics.warnings.push_back(std::to_string(statistics.boundary_points_inside) +
                                  " lattice boundary point(s) inside the result: the output is open there");
  for(const Marching_cubes_csg_component_report& c : statistics.under_resolved_components)
    statistics.warnings.push_back("component " + std::to_string(c.component) + " of mesh #" +
                                  std::to_string(c.mesh) + " is not resolved by the lattice");
  if(statistics.under_resolved_components.empty() && statistics.has_thin_result())
    statistics.warnings.push_back(std::to_string(statistics.thin_result_intervals) + " of " +
                                  std::to_string(statistics.result_intervals) +
                                  " intervals of lattice lines through the result hold no lattice point: "
                                  "walls or gaps thinner than a cell are missing or filled in; a spacing of " +
                                  std::to_string(statistics.thin_result_suggested_spacing) + " would see most");
  else if(statistics.under_resolved_components.empty() && statistics.has_sparse_result())
    statistics.warnings.push_back(std::to_string(100 * statistics.sparse_result_fraction) +
                                  " % of the result lies in walls or gaps that hold at most one lattice point "
                                  "across: Marching Cubes may break them into pieces; a spacing of " +
                                  std::to_string(statistics.sparse_result_suggested_spacing) + " would see most");
}

// One run of marching_cubes_csg_soup(): with sharp features, the fans pass
// the weaker fold test except in `strict_cubes` (all of them if it is null),
// and `intersecting_cubes` receives the cubes of the weak fans that meet
// another triangle of the output.
template <typename ConcurrencyTag, typename TriangleMeshRange, typename NamedParameters, typename Triangle>
Marching_cubes_csg_statistics marching_cubes_csg_soup_run(const TriangleMeshRange& meshes,
                                                          const Boolean_expression& expression,
                                                          const Regular_lattice_3& lattice,
                                                          std::vector<std::array<double, 3>>& points,
                                                          std::vector<Triangle>& triangles,
                                                          Csg_features& soup_features, const NamedParameters& np,
                                                          const std::vector<std::uint64_t>* strict_cubes,
                                                          std::vector<std::uint64_t>& intersecting_cubes)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  check_concurrency_tag<ConcurrencyTag>();
  const Progress progress = progress_of(np);
  const std::size_t max_memory = choose_parameter(get_parameter(np, internal_np::max_memory_bytes),
                                                  Lattice_classifier_3::default_max_memory_bytes);

  const std::size_t number_of_meshes = std::size_t(std::distance(std::begin(meshes), std::end(meshes)));
  if(expression.number_of_variables() != number_of_meshes)
    throw Invalid_input_error("the Boolean expression " + expression.to_string() + " has " +
                              std::to_string(expression.number_of_variables()) + " variable(s) but " +
                              std::to_string(number_of_meshes) +
                              " mesh(es) were given: variable m is mesh m, so the counts must be equal");

  Marching_cubes_csg_statistics statistics;
  statistics.lattice_points = lattice.total_number_of_points();
  auto start = std::chrono::steady_clock::now();
  std::size_t read_meshes = 0;
  std::vector<Lattice_triangle> input_triangles = read_csg_meshes(meshes, read_meshes, np);
  const bool check_resolution = choose_parameter(get_parameter(np, internal_np::resolution_check), true);
  const Marching_cubes_csg::Component_labels components =
      check_resolution ? Marching_cubes_csg::label_input_components(meshes, input_triangles)
                       : Marching_cubes_csg::Component_labels();
  const Marching_cubes_csg::Feature_settings features = feature_settings(np);
  const std::vector<Marching_cubes_csg::Triangle_tangent> tangents =
      features.enabled ? Marching_cubes_csg::triangle_tangents(input_triangles)
                       : std::vector<Marching_cubes_csg::Triangle_tangent>();
  typedef Marching_cubes_csg_builder<ConcurrencyTag> Builder;
  const std::size_t reserved = lattice.number_of_points(2) * Builder::bytes_per_plane();
  Lattice_classifier_3 classifier = Lattice_classifier_3::classify_triangles<ConcurrencyTag>(
      std::move(input_triangles), number_of_meshes, lattice, max_memory, reserved, progress.part(0, 0.6));
#if defined(CGAL_BOOLEAN_ISOSURFACING_3_CHECK_CONSISTENCY) || !defined(NDEBUG)
  // O(points): only where the lattice is small enough to walk point by point.
  if(lattice.total_number_of_points() <= (std::size_t(1) << 27) && classifier.number_of_inconsistent_edges() != 0)
    throw std::logic_error("marching_cubes_csg: crossings inconsistent with the classification (this is a bug)");
#endif
  Builder builder(classifier, expression, features, tangents);
  if(strict_cubes != nullptr)
    builder.use_weak_fold_test(*strict_cubes);
  statistics.boundary_points_inside = builder.compute_states(progress.part(0.6, 0.65));
  statistics.crossings = classifier.number_of_crossings();
  if(check_resolution)
  {
    statistics.checked_components = Marching_cubes_csg::under_resolved_components(
        components, classifier, statistics.under_resolved_components);
    const Marching_cubes_csg::Thin_result_measure thin = Marching_cubes_csg::measure_thin_result(classifier, expression, components);
    statistics.result_intervals = thin.intervals;
    statistics.thin_result_intervals = thin.thin_intervals;
    statistics.thin_result_volume = thin.thin_volume;
    statistics.result_line_volume = thin.line_volume;
    statistics.thin_result_suggested_spacing = 0.5 * thin.median_thin_length;
    statistics.sparse_result_fraction = thin.sparse_fraction;
    statistics.sparse_result_suggested_spacing = 0.5 * thin.median_sparse_length;
  }
  const double seconds_yz = classifier.seconds(1) + classifier.seconds(2);
  statistics.seconds_classification = seconds_since(start) - seconds_yz;

  const double sliver = choose_parameter(get_parameter(np, internal_np::sliver_edge_length), features.enabled ? 0.15 : 0.0);
  if(!(sliver >= 0 && sliver < 0.5))
    throw Invalid_input_error("sliver_edge_length must be in [0, 0.5) cells, got " + std::to_string(sliver));

  start = std::chrono::steady_clock::now();
  points.clear();
  triangles.clear();
  const bool record_meshes = soup_features.record_vertex_meshes;
  soup_features = Csg_features();
  if(record_meshes)
    builder.record_vertex_meshes(soup_features.vertex_meshes);
  builder.compute_vertices(points, progress.part(0.65, 0.8));
  const std::size_t edge_vertices = points.size();
  statistics.seconds_edges = seconds_yz + seconds_since(start);
  // Nothing after the vertices reads the crossings: most of the memory of
  // a fine lattice, released before the triangles take theirs.
  classifier.release_crossings();

  start = std::chrono::steady_clock::now();
  if(!features.enabled && sliver == 0)
    builder.compute_plain_triangles(triangles, progress.part(0.8, 0.98));
  else
  {
    // The feature triangulation and the sliver passes work on 32-bit
    // indices: half the memory of std::size_t ones, and no copy for a caller
    // who wants them (the tools).
    typedef std::array<std::uint32_t, 3> Work_triangle;
    std::vector<Work_triangle> work;
    if(features.enabled)
      builder.compute_feature_triangles(points, work, soup_features.crease_edges, soup_features.corner_vertices,
                                        statistics, progress.part(0.8, 0.98));
    else
      builder.compute_plain_triangles(work, progress.part(0.8, 0.98));
    builder.release_planes(); // before the sliver passes allocate their tables
    if(record_meshes)
      soup_features.vertex_meshes.resize(points.size(), Builder::no_mesh); // the feature vertices
    if(sliver > 0)
      statistics.collapsed_edges = Marching_cubes_csg::collapse_short_edges<ConcurrencyTag>(
          points, work, edge_vertices, sliver * lattice.spacing(), soup_features.crease_edges,
          soup_features.corner_vertices, record_meshes ? &soup_features.vertex_meshes : nullptr);
    intersecting_cubes.clear();
    if(features.enabled && strict_cubes != nullptr)
    {
      // The feature vertices follow the edge points, in order: the
      // collapses move and remove edge points only.
      statistics.weak_fans = builder.weak_fans().size();
      intersecting_cubes = Marching_cubes_csg::cubes_of_intersecting_weak_fans<ConcurrencyTag>(
          points, work, points.size() - statistics.feature_vertices, builder.weak_fans(), lattice);
    }
    if constexpr(std::is_same<Triangle, Work_triangle>::value)
      triangles.swap(work);
    else
    {
      typedef typename Triangle::value_type Index;
      if(points.size() > std::size_t((std::numeric_limits<Index>::max)()))
        throw Lattice_too_large_error("the output has more vertices than its index type can number");
      triangles.resize(work.size());
      for(std::size_t t = 0; t < work.size(); ++t)
        triangles[t] = Triangle{{Index(work[t][0]), Index(work[t][1]), Index(work[t][2])}};
    }
  }
  statistics.number_of_vertices = points.size();
  statistics.number_of_faces = triangles.size();
  statistics.seconds_triangulation = seconds_since(start);
  return statistics;
}

// How many runs may use the weaker fold test; the next one uses the strict
// test everywhere (the output before the weaker test existed).
constexpr std::size_t max_weak_fold_runs = 3;

// Into `points` and `triangles` (arrays of three indices of any integer type
// that holds the vertex count), both cleared first.  With sharp features,
// the fans pass the weaker fold test, except in the cubes where such a fan
// met another triangle: there the whole extraction runs again with the
// strict test (the meshes are read again: the classifier consumed them, and
// a run on a crossed cube's polygons needs the states and crossings it
// released).  Deterministic: the cubes found do not depend on the
// concurrency.
template <typename ConcurrencyTag, typename TriangleMeshRange, typename NamedParameters, typename Triangle>
Marching_cubes_csg_statistics marching_cubes_csg_soup(const TriangleMeshRange& meshes,
                                                      const Boolean_expression& expression,
                                                      const Regular_lattice_3& lattice,
                                                      std::vector<std::array<double, 3>>& points,
                                                      std::vector<Triangle>& triangles, Csg_features& soup_features,
                                                      const NamedParameters& np)
{
  std::vector<std::uint64_t> strict, intersecting;
  double seconds[3] = {0, 0, 0};
  for(std::size_t run = 1;; ++run)
  {
    Marching_cubes_csg_statistics statistics = marching_cubes_csg_soup_run<ConcurrencyTag>(
        meshes, expression, lattice, points, triangles, soup_features, np,
        run <= max_weak_fold_runs ? &strict : nullptr, intersecting);
    seconds[0] += statistics.seconds_classification;
    seconds[1] += statistics.seconds_edges;
    seconds[2] += statistics.seconds_triangulation;
    if(intersecting.empty())
    {
      statistics.extraction_runs = run;
      statistics.strict_fold_cubes = strict.size();
      statistics.seconds_classification = seconds[0];
      statistics.seconds_edges = seconds[1];
      statistics.seconds_triangulation = seconds[2];
      add_csg_warnings(statistics);
      return statistics;
    }
    std::vector<std::uint64_t> merged;
    std::set_union(strict.begin(), strict.end(), intersecting.begin(), intersecting.end(),
                   std::back_inserter(merged));
    strict.swap(merged);
  }
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_BUILDER_H
