// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H

#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Lattice_classifier_3.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Csg_edge_point.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Collapse_short_edges.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_triangulation.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Resolution_check.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/task_arena.h>
#endif

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What `marching_cubes_csg()` did, and how long each phase took (wall clock).
struct Marching_cubes_csg_statistics
{
  /// Reading the meshes, binning, the x lines and the output state of every point.
  double seconds_classification = 0;
  /// The y and z lines and the output vertices (INT_POINT on every edge that needs one).
  double seconds_edges = 0;
  /// The cube pass and the output arrays.
  double seconds_triangulation = 0;
  std::size_t lattice_points = 0;
  /// Crossings of the meshes with lattice edges (all axes).
  std::size_t crossings = 0;
  std::size_t output_vertices = 0;
  std::size_t output_triangles = 0;
  /// Lattice points on the boundary of the lattice that are inside the
  /// result.  When it is 0 the output is closed; otherwise the output is
  /// open where the result meets the lattice boundary (or empty, if every
  /// point is inside).  It is 0 for a lattice from
  /// `Regular_lattice_3::enclosing()` (margin >= 1) around the meshes and an
  /// expression that is false outside all of them (`evaluate(0) == false`).
  std::size_t boundary_points_inside = 0;
  /// Sharp features (named parameter `sharp_features`): polygons fanned
  /// around a feature vertex, of which corners (rank 3); polygons whose
  /// normals disagree but that keep the plain triangulation (no feature point
  /// in the cube, or the fan would fold); face segments flipped to join
  /// neighbouring feature vertices; crease edges output.
  std::size_t feature_vertices = 0;
  /// Feature vertices of rank 3 (corners).
  std::size_t corner_vertices = 0;
  /// Polygons whose normals disagree by more than the feature angle but that
  /// keep the plain triangulation.
  std::size_t plain_feature_polygons = 0;
  /// Of `plain_feature_polygons`, those whose fan would have folded.
  std::size_t folded_feature_polygons = 0;
  /// Face segments flipped to join the feature vertices of neighbouring cubes.
  std::size_t flipped_edges = 0;
  /// Flipped edges whose dihedral angle is above the feature angle: the output creases.
  std::size_t crease_edges = 0;
  /// Edges between two edge points shorter than `sliver_edge_length` cells
  /// that were collapsed (see the named parameter).
  std::size_t collapsed_edges = 0;
  /// Resolution check (named parameter `resolution_check`, default true):
  /// the connected components of the inputs inside the lattice's box that
  /// were judged, and those the lattice does not resolve -- no crossing with
  /// a lattice edge, or (lattice points inside) x spacing^3 off the exact
  /// volume by more than a factor 2.  Such a component may be missing from
  /// the output, or be much too thick there.
  std::size_t checked_components = 0;
  /// The components the lattice does not resolve (see `checked_components`).
  std::vector<Marching_cubes_csg_component_report> under_resolved_components;
  /// Resolution of the result itself (same named parameter): along the
  /// lattice lines, the intervals inside or outside the result between two
  /// of its surface crossings, and those that hold no lattice point --
  /// walls thinner than a cell, missing from the output, or gaps filled in
  /// (a difference of nearly coincident solids, say).
  std::size_t result_intervals = 0;
  /// The intervals of `result_intervals` that hold no lattice point.
  std::size_t thin_result_intervals = 0;
  /// The volume of the thin intervals (line lengths times spacing^2),
  /// beside `result_line_volume`, the result's volume measured the same way,
  /// along the axis where their ratio is largest (the lines that cross a
  /// thin wall see it): a lower bound of the part the output gets wrong.
  double thin_result_volume = 0;
  /// The result's volume as the lengths of its line intervals times
  /// spacing^2, along the axis of `thin_result_volume`.
  double result_line_volume = 0;
  /// A spacing that puts lattice points in most thin intervals (half their
  /// median length), or 0 when there is none.
  double thin_result_suggested_spacing = 0;
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The sharp features of a `marching_cubes_csg()` soup (named parameter
/// `sharp_feature_output(&features)`): crease edges as pairs of output vertex
/// indices (smaller first), and corner vertices.  Indices are offset like the
/// triangles'.
struct Marching_cubes_csg_features
{
  /// Crease edges, as pairs of output vertex indices (smaller first).
  std::vector<std::array<std::size_t, 2>> crease_edges;
  /// Corner vertices (rank-3 feature vertices).
  std::vector<std::size_t> corner_vertices;
};

namespace internal {

template <typename T>
struct Is_std_array : std::false_type {};
template <typename T, std::size_t N>
struct Is_std_array<std::array<T, N>> : std::true_type {};

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

// The soup, before it is appended to the caller's containers.
struct Csg_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  // Crease edges (vertex pairs, smaller index first) and corner vertices.
  std::vector<std::array<std::size_t, 2>> crease_edges;
  std::vector<std::size_t> corner_vertices;
};

// The phases after the classification: output states, vertices, cubes.
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
      m_n(m_lattice.number_of_points()), m_features(features), m_tangents(tangents)
  {}

  // Bytes per lattice point and per xy-plane that the builder allocates on
  // top of the classifier.
  static std::size_t bytes_per_point() { return 1; }
  static std::size_t bytes_per_plane_point() { return 2 * 3 * sizeof(std::uint32_t) * concurrency<ConcurrencyTag>() + 1; }

  std::size_t compute_states(const Progress& progress)
  {
    const std::size_t nx = m_n[0], ny = m_n[1];
    m_state.clear();
    m_state.resize(m_lattice.total_number_of_points()); // written below, in parallel
    m_row_kind.assign(ny * m_n[2], MIXED_ROW);
    m_classifier.visit_masks([&](const auto* masks) {
      concurrent_for<ConcurrencyTag>(
          m_n[2],
          [&](std::size_t k) {
            for(std::size_t j = 0; j < ny; ++j)
            {
              const std::size_t first = m_lattice.linear_index(0, j, k), last = first + nx;
              std::uint8_t* row = m_state.data() + first;
              if(m_classifier.crossings_on_line(0, j + ny * k).empty())
              {
                // No crossing on the x line: the masks, hence the states, are constant.
                const std::uint8_t s = m_inside(std::uint64_t(masks[first])) ? 1 : 0;
                std::fill(row, row + nx, s);
                m_row_kind[j + ny * k] = s;
                continue;
              }
              unsigned any = 0, all = 1;
              for(std::size_t idx = first; idx < last; ++idx)
              {
                const unsigned s = m_inside(std::uint64_t(masks[idx])) ? 1u : 0u;
                m_state[idx] = std::uint8_t(s);
                any |= s;
                all &= s;
              }
              m_row_kind[j + ny * k] = any == all ? std::uint8_t(all) : MIXED_ROW;
            }
          },
          progress);
    });
    // Points on the lattice boundary: whole rows on the boundary planes,
    // the two ends of the other rows.
    std::size_t boundary_inside = 0;
    for(std::size_t k = 0; k < m_n[2]; ++k)
      for(std::size_t j = 0; j < m_n[1]; ++j)
      {
        const std::size_t row = m_lattice.linear_index(0, j, k);
        if(k == 0 || j == 0 || k + 1 == m_n[2] || j + 1 == m_n[1])
          boundary_inside += std::size_t(std::count(m_state.begin() + row, m_state.begin() + row + m_n[0], 1));
        else
          boundary_inside += m_state[row] + (m_n[0] > 1 ? m_state[row + m_n[0] - 1] : 0);
      }
    return boundary_inside;
  }

  // Vertices are numbered plane by plane (z), and in a plane by edge id
  // 3 * (i + nx * j) + axis: the edges of plane k are its x and y edges and
  // the z edges from plane k to k + 1.
  void compute_vertices(std::vector<std::array<double, 3>>& points, const Progress& progress)
  {
    const std::size_t nz = m_n[2];
    m_vertex_offset.assign(nz + 1, 0);
    concurrent_for<ConcurrencyTag>(nz, [&](std::size_t k) {
      std::size_t count = 0;
      for_each_vertex_edge(k, [&](std::size_t, std::size_t, int, std::size_t) { ++count; });
      m_vertex_offset[k + 1] = count;
    });
    for(std::size_t k = 0; k < nz; ++k)
      m_vertex_offset[k + 1] += m_vertex_offset[k];
    if(m_vertex_offset[nz] >= (std::size_t(1) << 32) && sizeof(std::size_t) < 8)
      throw Lattice_too_large_error("too many output vertices for this platform");
    points.resize(m_vertex_offset[nz]);
    if(m_features.enabled)
      m_normals.resize(points.size());
    concurrent_for<ConcurrencyTag>(
        nz,
        [&](std::size_t k) {
          std::size_t id = m_vertex_offset[k];
          for_each_vertex_edge(k, [&](std::size_t i, std::size_t j, int axis, std::size_t idx) {
            points[id] = vertex_position(i, j, k, axis, idx, m_features.enabled ? &m_normals[id] : nullptr);
            ++id;
          });
        },
        progress);
  }

  // With sharp features, `points` (the edge vertices) gets the feature
  // vertices appended, and `soup_creases`, `soup_corners` the crease edges and
  // corner vertices.
  void compute_triangles(std::vector<std::array<double, 3>>& points,
                         std::vector<std::array<std::size_t, 3>>& triangles,
                         std::vector<std::array<std::size_t, 2>>& soup_creases, std::vector<std::size_t>& soup_corners,
                         Marching_cubes_csg_statistics& statistics, const Progress& progress)
  {
    if(m_n[0] < 2 || m_n[1] < 2 || m_n[2] < 2)
      return;
    const std::size_t layers = m_n[2] - 1;
    // The chunks only change who computes what: the output is the
    // concatenation of the layers in order, whatever the chunking.
    const std::size_t chunks = (std::min)(layers, is_parallel_tag<ConcurrencyTag>() ? 8 * concurrency<ConcurrencyTag>() : 1);
    if(m_features.enabled)
    {
      std::vector<Marching_cubes_csg::Feature_chunk> buffers(chunks);
      concurrent_for<ConcurrencyTag>(
          chunks,
          [&](std::size_t c) {
            triangulate_feature_layers(layers * c / chunks, layers * (c + 1) / chunks, points, buffers[c]);
          },
          progress);
      for(const auto& b : buffers)
      {
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
      std::vector<Vector_3d>().swap(m_normals);
      return;
    }
    std::vector<std::vector<std::array<std::size_t, 3>>> buffers(chunks);
    concurrent_for<ConcurrencyTag>(
        chunks,
        [&](std::size_t c) { triangulate_layers(layers * c / chunks, layers * (c + 1) / chunks, buffers[c]); },
        progress);
    std::size_t total = 0;
    for(const auto& b : buffers)
      total += b.size();
    triangles.reserve(total);
    for(auto& b : buffers)
    {
      triangles.insert(triangles.end(), b.begin(), b.end());
      std::vector<std::array<std::size_t, 3>>().swap(b);
    }
  }

private:
  // Calls f(i, j, axis, linear index of (i, j, k)) for the edges of plane k
  // whose ends have different states, in vertex order.
  // Rows of lattice points (along x) whose states are all 0 or all 1 are
  // skipped wholesale: away from the surface a pass costs O(1) per row.
  static constexpr std::uint8_t MIXED_ROW = 2;

  // Whether all the rows given have the same constant state (no vertex
  // between them, no surface in the cubes they span).
  bool uniform_rows(std::uint8_t a, std::uint8_t b) const { return a == b && a != MIXED_ROW; }

  template <typename F>
  void for_each_vertex_edge(std::size_t k, const F& f) const
  {
    const std::size_t nx = m_n[0], ny = m_n[1], nz = m_n[2];
    const std::size_t plane = nx * ny;
    const bool has_z = k + 1 < nz;
    for(std::size_t j = 0; j < ny; ++j)
    {
      const bool has_y = j + 1 < ny;
      const std::uint8_t kind = m_row_kind[j + ny * k];
      if(kind != MIXED_ROW && (!has_y || uniform_rows(kind, m_row_kind[j + 1 + ny * k])) &&
         (!has_z || uniform_rows(kind, m_row_kind[j + ny * (k + 1)])))
        continue;
      std::size_t idx = m_lattice.linear_index(0, j, k);
      for(std::size_t i = 0; i < nx; ++i, ++idx)
      {
        const std::uint8_t s = m_state[idx];
        if(i + 1 < nx && s != m_state[idx + 1])
          f(i, j, 0, idx);
        if(has_y && s != m_state[idx + nx])
          f(i, j, 1, idx);
        if(has_z && s != m_state[idx + plane])
          f(i, j, 2, idx);
      }
    }
  }

  // The vertex of a lattice edge, and (if `normal` is not null) the outward
  // unit normal of the input triangle it lies on.
  std::array<double, 3> vertex_position(std::size_t i, std::size_t j, std::size_t k, int axis, std::size_t idx,
                                        Vector_3d* normal) const
  {
    const std::size_t stride = axis == 0 ? 1 : (axis == 1 ? m_n[0] : m_n[0] * m_n[1]);
    const bool from_low = m_state[idx] != 0;
    const std::uint64_t mask = m_classifier.mask(from_low ? idx : idx + stride);
    const Lattice_classifier_3::Crossing_range crossings = m_classifier.crossings_on_edge(axis, i, j, k);
    const std::size_t c = csg_edge_crossing(crossings.begin(), crossings.size(), from_low, mask, m_inside);
    if(c == crossings.size())
      throw std::logic_error("marching_cubes_csg: the crossings of a lattice edge contradict the classification "
                             "of its ends (this is a bug)");
    std::array<double, 3> p{{m_lattice.coordinate(0, i), m_lattice.coordinate(1, j), m_lattice.coordinate(2, k)}};
    p[axis] = crossings[c].position;
    if(normal != nullptr)
      *normal = Marching_cubes_csg::outward_normal(m_tangents[crossings[c].triangle], axis, from_low);
    return p;
  }

  // Local vertex number, in plane k, of each vertex edge: entry 3 * (i + nx * j) + axis.
  void number_plane_vertices(std::size_t k, std::vector<std::uint32_t>& ids) const
  {
    std::uint32_t next = 0;
    const std::size_t nx = m_n[0];
    for_each_vertex_edge(k, [&](std::size_t i, std::size_t j, int axis, std::size_t) {
      ids[3 * (i + nx * j) + std::size_t(axis)] = next++;
    });
  }

  void triangulate_layers(std::size_t first, std::size_t last, std::vector<std::array<std::size_t, 3>>& out) const
  {
    if(first >= last)
      return;
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    const std::size_t nx = m_n[0], ny = m_n[1];
    const std::size_t plane = nx * ny;
    std::vector<std::uint32_t> low(3 * plane), high(3 * plane);
    number_plane_vertices(first, low);
    // Corner c of the cube at idx is at idx + corner_offset[c].
    std::array<std::size_t, 8> corner_offset;
    for(int c = 0; c < 8; ++c)
      corner_offset[c] = std::size_t(c & 1) + nx * std::size_t((c >> 1) & 1) + plane * std::size_t((c >> 2) & 1);
    for(std::size_t k = first; k < last; ++k)
    {
      number_plane_vertices(k + 1, high);
      const std::array<const std::vector<std::uint32_t>*, 2> ids{{&low, &high}};
      const std::array<std::size_t, 2> offset{{m_vertex_offset[k], m_vertex_offset[k + 1]}};
      for(std::size_t j = 0; j + 1 < ny; ++j)
      {
        const std::uint8_t kind = m_row_kind[j + ny * k];
        if(uniform_rows(kind, m_row_kind[j + 1 + ny * k]) && uniform_rows(kind, m_row_kind[j + ny * (k + 1)]) &&
           uniform_rows(kind, m_row_kind[j + 1 + ny * (k + 1)]))
          continue;
        std::size_t idx = m_lattice.linear_index(0, j, k);
        for(std::size_t i = 0; i + 1 < nx; ++i, ++idx)
        {
          unsigned code = 0;
          for(int c = 0; c < 8; ++c)
            code |= unsigned(m_state[idx + corner_offset[c]]) << c;
          if(code == 0 || code == 255)
            continue;
          for(const Marching_cubes_table::Triangle& t : table.triangles(code))
          {
            std::array<std::size_t, 3> triangle;
            for(int v = 0; v < 3; ++v)
            {
              const int e = t[v];
              // The default face rule never needs a polygon centre vertex.
              CGAL_assertion(!Marching_cubes_table::is_centre_vertex(unsigned(e)));
              const std::array<int, 3> o = cube_edge_origin_offset(e);
              const std::size_t entry = 3 * ((i + std::size_t(o[0])) + nx * (j + std::size_t(o[1]))) +
                                        std::size_t(cube_edge_axis(e));
              triangle[v] = offset[o[2]] + (*ids[o[2]])[entry];
            }
            out.push_back(triangle);
          }
        }
      }
      std::swap(low, high);
    }
  }

  // As triangulate_layers(), with the polygons whose normals disagree fanned
  // around their feature vertex.
  void triangulate_feature_layers(std::size_t first, std::size_t last, const std::vector<Vector_3d>& points,
                                  Marching_cubes_csg::Feature_chunk& out) const
  {
    if(first >= last)
      return;
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    const std::size_t nx = m_n[0], ny = m_n[1];
    const std::size_t plane = nx * ny;
    std::vector<std::uint32_t> low(3 * plane), high(3 * plane);
    number_plane_vertices(first, low);
    std::array<std::size_t, 8> corner_offset;
    for(int c = 0; c < 8; ++c)
      corner_offset[c] = std::size_t(c & 1) + nx * std::size_t((c >> 1) & 1) + plane * std::size_t((c >> 2) & 1);
    for(std::size_t k = first; k < last; ++k)
    {
      number_plane_vertices(k + 1, high);
      const std::array<const std::vector<std::uint32_t>*, 2> ids{{&low, &high}};
      const std::array<std::size_t, 2> offset{{m_vertex_offset[k], m_vertex_offset[k + 1]}};
      for(std::size_t j = 0; j + 1 < ny; ++j)
      {
        const std::uint8_t kind = m_row_kind[j + ny * k];
        if(uniform_rows(kind, m_row_kind[j + 1 + ny * k]) && uniform_rows(kind, m_row_kind[j + ny * (k + 1)]) &&
           uniform_rows(kind, m_row_kind[j + 1 + ny * (k + 1)]))
          continue;
        std::size_t idx = m_lattice.linear_index(0, j, k);
        for(std::size_t i = 0; i + 1 < nx; ++i, ++idx)
        {
          unsigned code = 0;
          for(int c = 0; c < 8; ++c)
            code |= unsigned(m_state[idx + corner_offset[c]]) << c;
          if(code == 0 || code == 255)
            continue;
          const auto vertex_of = [&](int e) {
            CGAL_assertion(!Marching_cubes_table::is_centre_vertex(unsigned(e)));
            const std::array<int, 3> o = cube_edge_origin_offset(e);
            const std::size_t entry =
                3 * ((i + std::size_t(o[0])) + nx * (j + std::size_t(o[1]))) + std::size_t(cube_edge_axis(e));
            return std::size_t(offset[o[2]] + (*ids[o[2]])[entry]);
          };
          const Vector_3d cube_low{{m_lattice.coordinate(0, i), m_lattice.coordinate(1, j), m_lattice.coordinate(2, k)}};
          const Vector_3d cube_high{
              {m_lattice.coordinate(0, i + 1), m_lattice.coordinate(1, j + 1), m_lattice.coordinate(2, k + 1)}};
          const Marching_cubes_csg::Feature_decision decide(cube_low, cube_high, m_features,
                                                            out.plain);
          Marching_cubes_csg::triangulate_feature_cube(table, code, vertex_of, points, m_normals, decide, out);
        }
      }
      std::swap(low, high);
    }
  }

  const Lattice_classifier_3& m_classifier;
  const Regular_lattice_3& m_lattice;
  Expression_evaluator m_inside;
  std::array<std::size_t, 3> m_n;
  std::vector<std::uint8_t, Default_init_allocator<std::uint8_t>> m_state;
  std::vector<std::uint8_t> m_row_kind; // per x row (j + ny * k): 0, 1 or MIXED_ROW
  std::vector<std::size_t> m_vertex_offset;
  Feature_settings m_features;
  const std::vector<Triangle_tangent>& m_tangents;
  std::vector<Vector_3d> m_normals; // outward normal of each edge vertex (features only)
};

// The named parameters `sharp_features` (default true) and `feature_angle`
// (degrees, default 30).
template <typename NamedParameters>
Marching_cubes_csg::Feature_settings feature_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Marching_cubes_csg::Feature_settings settings;
  settings.enabled = choose_parameter(get_parameter(np, internal_np::sharp_features), true);
  const double angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 30.0);
  if(!(angle > 0 && angle < 180))
    throw Invalid_input_error("the feature angle must be in (0, 180) degrees, got " + std::to_string(angle));
  settings.cos_feature_angle = std::cos(angle * 3.14159265358979323846 / 180.0);
  return settings;
}

template <typename ConcurrencyTag, typename TriangleMeshRange, typename NamedParameters>
Marching_cubes_csg_statistics marching_cubes_csg_soup(const TriangleMeshRange& meshes,
                                                      const Boolean_expression& expression,
                                                      const Regular_lattice_3& lattice, Csg_soup& soup,
                                                      const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  check_concurrency_tag<ConcurrencyTag>();
  std::function<void(double)> callback;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::progress_t>::value)
    callback = get_parameter(np, internal_np::progress);
  const Progress progress(callback);
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
  std::vector<Lattice_triangle> triangles = Lattice_classifier_3::read_meshes(meshes, read_meshes);
  const bool check_resolution = choose_parameter(get_parameter(np, internal_np::resolution_check), true);
  const Marching_cubes_csg::Component_labels components =
      check_resolution ? Marching_cubes_csg::label_components(triangles) : Marching_cubes_csg::Component_labels();
  const Marching_cubes_csg::Feature_settings features = feature_settings(np);
  const std::vector<Marching_cubes_csg::Triangle_tangent> tangents =
      features.enabled ? Marching_cubes_csg::triangle_tangents(triangles)
                       : std::vector<Marching_cubes_csg::Triangle_tangent>();
  typedef Marching_cubes_csg_builder<ConcurrencyTag> Builder;
  const std::size_t plane = lattice.number_of_points(0) * lattice.number_of_points(1);
  const std::size_t reserved = lattice.total_number_of_points() * Builder::bytes_per_point() +
                               plane * Builder::bytes_per_plane_point();
  const Lattice_classifier_3 classifier = Lattice_classifier_3::classify_triangles<ConcurrencyTag>(
      std::move(triangles), number_of_meshes, lattice, max_memory, reserved, progress.part(0, 0.6));
#if defined(CGAL_BOOLEAN_ISOSURFACING_3_CHECK_CONSISTENCY) || !defined(NDEBUG)
  if(classifier.number_of_inconsistent_edges() != 0)
    throw std::logic_error("marching_cubes_csg: crossings inconsistent with the classification (this is a bug)");
#endif
  Builder builder(classifier, expression, features, tangents);
  statistics.boundary_points_inside = builder.compute_states(progress.part(0.6, 0.65));
  statistics.crossings = classifier.number_of_crossings();
  if(check_resolution)
  {
    statistics.checked_components = Marching_cubes_csg::under_resolved_components(
        components, classifier, statistics.under_resolved_components);
    const Marching_cubes_csg::Thin_result_measure thin = Marching_cubes_csg::measure_thin_result(classifier, expression);
    statistics.result_intervals = thin.intervals;
    statistics.thin_result_intervals = thin.thin_intervals;
    statistics.thin_result_volume = thin.thin_volume;
    statistics.result_line_volume = thin.line_volume;
    statistics.thin_result_suggested_spacing = 0.5 * thin.median_thin_length;
  }
  const double seconds_yz = classifier.seconds(1) + classifier.seconds(2);
  statistics.seconds_classification = seconds_since(start) - seconds_yz;

  start = std::chrono::steady_clock::now();
  builder.compute_vertices(soup.points, progress.part(0.65, 0.8));
  const std::size_t edge_vertices = soup.points.size();
  statistics.seconds_edges = seconds_yz + seconds_since(start);

  start = std::chrono::steady_clock::now();
  builder.compute_triangles(soup.points, soup.triangles, soup.crease_edges, soup.corner_vertices, statistics,
                            progress.part(0.8, 0.98));
  const double sliver = choose_parameter(get_parameter(np, internal_np::sliver_edge_length), features.enabled ? 0.1 : 0.0);
  if(!(sliver >= 0 && sliver < 0.5))
    throw Invalid_input_error("sliver_edge_length must be in [0, 0.5) cells, got " + std::to_string(sliver));
  if(sliver > 0)
    statistics.collapsed_edges = Marching_cubes_csg::collapse_short_edges(
        soup.points, soup.triangles, edge_vertices, sliver * lattice.spacing(), soup.crease_edges, soup.corner_vertices);
  statistics.output_vertices = soup.points.size();
  statistics.output_triangles = soup.triangles.size();
  statistics.seconds_triangulation = seconds_since(start);
  return statistics;
}

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Marching Cubes CSG: the boundary of the solid `expression(meshes)`,
 * sampled on `lattice`, as a polygon soup.
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
 *         (or `std::reference_wrapper`s to them), as for `Lattice_classifier_3`
 * \tparam PointRange a container with `push_back()` of points constructible
 *         from three doubles (or a `std::array<double, 3>`)
 * \tparam TriangleRange a container with `push_back()` of `std::array<I, 3>`
 *         or of a container of indices with `push_back()`
 *
 * \param meshes the closed triangle meshes, variable m of `expression` is mesh m
 * \param expression a Boolean expression with `meshes.size()` variables
 * \param lattice the sampling lattice (see `Regular_lattice_3::enclosing()`)
 * \param points, triangles the soup is appended to them (indices are offset
 *        by the initial size of `points`)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{progress}
 *     \cgalParamDescription{called with the fraction done, from the calling thread}
 *     \cgalParamType{a callable `f(double)`} \cgalParamDefault{none}
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
 *     \cgalParamDescription{edges between two edge points shorter than this many cells are
 *       collapsed (link condition, no triangle turned over); in [0, 0.5)}
 *     \cgalParamType{`double`} \cgalParamDefault{0.1 with sharp features, 0 without}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sharp_feature_output}
 *     \cgalParamDescription{receives the crease edges and corner vertices}
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
 * \throws Invalid_input_error if `expression.number_of_variables() !=
 * meshes.size()`, for a feature angle outside (0, 180) or a sliver length
 * outside [0, 0.5); the exceptions of `Lattice_classifier_3::classify()`.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange, typename PointRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::Is_named_function_parameters<TriangleRange>::value>>
Marching_cubes_csg_statistics marching_cubes_csg(const TriangleMeshRange& meshes, const Boolean_expression& expression,
                                                 const Regular_lattice_3& lattice, PointRange& points,
                                                 TriangleRange& triangles,
                                                 const NamedParameters& np = parameters::default_values())
{
  typedef typename PointRange::value_type Point;
  typedef typename TriangleRange::value_type Triangle;
  internal::Csg_soup soup;
  const auto start = std::chrono::steady_clock::now();
  Marching_cubes_csg_statistics statistics =
      internal::marching_cubes_csg_soup<ConcurrencyTag>(meshes, expression, lattice, soup, np);
  const std::size_t first = std::size_t(std::distance(std::begin(points), std::end(points)));
  for(const std::array<double, 3>& p : soup.points)
    points.push_back(internal::make_output_point<Point>(p));
  std::vector<std::array<double, 3>>().swap(soup.points);
  for(const std::array<std::size_t, 3>& t : soup.triangles)
    triangles.push_back(internal::make_output_triangle<Triangle>({{t[0] + first, t[1] + first, t[2] + first}}));
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::sharp_feature_output_t>::value)
  {
    Marching_cubes_csg_features* features = parameters::get_parameter(np, internal_np::sharp_feature_output);
    if(features != nullptr)
    {
      for(const std::array<std::size_t, 2>& e : soup.crease_edges)
        features->crease_edges.push_back({{e[0] + first, e[1] + first}});
      for(std::size_t v : soup.corner_vertices)
        features->corner_vertices.push_back(v + first);
    }
  }
  statistics.seconds_triangulation += internal::seconds_since(start) - statistics.seconds_classification -
                                      statistics.seconds_edges - statistics.seconds_triangulation;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::progress_t>::value)
    parameters::get_parameter(np, internal_np::progress)(1.0);
  return statistics;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * As the polygon soup overload, and adds the result to `output` with
 * `PMP::polygon_soup_to_polygon_mesh()`.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{progress}
 *     \cgalParamDescription{called with the fraction done, from the calling thread}
 *     \cgalParamType{a callable `f(double)`} \cgalParamDefault{none}
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
Marching_cubes_csg_statistics marching_cubes_csg(const TriangleMeshRange& meshes, const Boolean_expression& expression,
                                                 const Regular_lattice_3& lattice, MutableFaceGraph& output,
                                                 const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<
      typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type>::value_type Point;
  typedef boost::graph_traits<MutableFaceGraph> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  Marching_cubes_csg_features features;
  const auto start = std::chrono::steady_clock::now();
  Marching_cubes_csg_statistics statistics = marching_cubes_csg<ConcurrencyTag>(
      meshes, expression, lattice, points, triangles, parameters::sharp_feature_output(&features, np));
  // As PMP::polygon_soup_to_polygon_mesh(), keeping the vertex of each point
  // for the feature maps.
  const auto vpm = get(CGAL::vertex_point, output);
  std::vector<vertex_descriptor> vertex(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex[i] = add_vertex(output);
    put(vpm, vertex[i], points[i]);
  }
  std::vector<vertex_descriptor> face(3);
  for(const std::array<std::size_t, 3>& t : triangles)
  {
    for(int v = 0; v < 3; ++v)
      face[v] = vertex[t[v]];
    if(CGAL::Euler::add_face(face, output) == Graph_traits::null_face())
      throw std::logic_error("marching_cubes_csg: the output soup is not a 2-manifold (this is a bug)");
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
  return statistics;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_CSG_H
