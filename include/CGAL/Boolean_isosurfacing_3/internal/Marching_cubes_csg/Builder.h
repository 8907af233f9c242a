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
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Collapse_short_edges.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_triangulation.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Resolution_check.h>
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

  // The walk both triangulations share: calls f(i, j, k, code, vertex_of)
  // for every cube of the layers [first, last) whose corners do not all have
  // the same state, layer by layer, then by cube (i fastest).  `code` has
  // bit c set iff corner c is inside; `vertex_of(e)` is the output vertex on
  // cube edge e.  Rows of cubes whose four bounding point rows are uniform
  // and equal are skipped wholesale.
  template <typename F>
  void for_each_crossed_cube(std::size_t first, std::size_t last, const F& f) const
  {
    if(first >= last)
      return;
    const std::size_t nx = m_n[0], ny = m_n[1];
    const std::size_t plane = nx * ny;
    // Local vertex numbers of the planes k and k + 1 (see number_plane_vertices()).
    std::vector<std::uint32_t> low(3 * plane), high(3 * plane);
    number_plane_vertices(first, low);
    // Corner c of the cube at idx is at idx + corner_offset[c].
    std::array<std::size_t, 8> corner_offset;
    for(int c = 0; c < 8; ++c)
      corner_offset[c] = std::size_t(c & 1) + nx * std::size_t((c >> 1) & 1) + plane * std::size_t((c >> 2) & 1);
    for(std::size_t k = first; k < last; ++k)
    {
      number_plane_vertices(k + 1, high);
      const std::array<const std::uint32_t*, 2> ids{{low.data(), high.data()}};
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
            // The default face rule never needs a polygon centre vertex.
            CGAL_assertion(!Marching_cubes_table::is_centre_vertex(unsigned(e)));
            const std::array<int, 3> o = cube_edge_origin_offset(e);
            const std::size_t entry =
                3 * ((i + std::size_t(o[0])) + nx * (j + std::size_t(o[1]))) + std::size_t(cube_edge_axis(e));
            return std::size_t(offset[o[2]] + ids[o[2]][entry]);
          };
          f(i, j, k, code, vertex_of);
        }
      }
      std::swap(low, high);
    }
  }

  void triangulate_layers(std::size_t first, std::size_t last, std::vector<std::array<std::size_t, 3>>& out) const
  {
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    for_each_crossed_cube(first, last, [&](std::size_t, std::size_t, std::size_t, unsigned code, const auto& vertex_of) {
      for(const Marching_cubes_table::Triangle& t : table.triangles(code))
        out.push_back({{vertex_of(t[0]), vertex_of(t[1]), vertex_of(t[2])}});
    });
  }

  // As triangulate_layers(), with the polygons whose normals disagree fanned
  // around their feature vertex.
  void triangulate_feature_layers(std::size_t first, std::size_t last, const std::vector<Vector_3d>& points,
                                  Marching_cubes_csg::Feature_chunk& out) const
  {
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    for_each_crossed_cube(first, last, [&](std::size_t i, std::size_t j, std::size_t k, unsigned code,
                                           const auto& vertex_of) {
      const Vector_3d cube_low{{m_lattice.coordinate(0, i), m_lattice.coordinate(1, j), m_lattice.coordinate(2, k)}};
      const Vector_3d cube_high{
          {m_lattice.coordinate(0, i + 1), m_lattice.coordinate(1, j + 1), m_lattice.coordinate(2, k + 1)}};
      const Marching_cubes_csg::Feature_decision decide(cube_low, cube_high, m_features, out.plain);
      Marching_cubes_csg::triangulate_feature_cube(table, code, vertex_of, points, m_normals, decide, out);
    });
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
}

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
  std::vector<Lattice_triangle> triangles = read_csg_meshes(meshes, read_meshes, np);
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
  statistics.number_of_vertices = soup.points.size();
  statistics.number_of_faces = soup.triangles.size();
  statistics.seconds_triangulation = seconds_since(start);
  add_csg_warnings(statistics);
  return statistics;
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_BUILDER_H
