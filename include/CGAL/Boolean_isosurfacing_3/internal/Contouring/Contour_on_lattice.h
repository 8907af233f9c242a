// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CONTOUR_ON_LATTICE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CONTOUR_ON_LATTICE_H

// The contouring of a field on a sparse lattice, and the lattice defaults.

#include <CGAL/Boolean_isosurfacing_3/internal/clear_output_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Contouring_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Flat_uint64_map.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <CGAL/Boolean_isosurfacing_3/internal/Contouring/Cube_rules.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Contouring/Repair.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_triangulation.h>

namespace CGAL {
namespace Boolean_isosurfacing {

namespace internal {

// The lattice of a contouring: point (i, j, k) is origin + (i, j, k) r,
// cells[a] cells along axis a.  Sparse: only the cubes the traversal
// reaches are ever looked at, so it may be far larger than a
// `Regular_lattice_3` (2^20 cells per axis).
struct Contouring_lattice
{
  std::array<double, 3> origin{{0, 0, 0}};
  double r = 0;
  std::array<std::int64_t, 3> cells{{1, 1, 1}};
};

// The default lattice of `field`, with the named parameters `cell_size`,
// `cells_along_longest_side` and `lattice_margin`.
template <typename ContouringField_3, typename NamedParameters>
Contouring_lattice default_contouring_lattice(const ContouringField_3& field, const NamedParameters& np)
{
  typedef typename ContouringField_3::Point_3 Point_3;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Contouring_lattice lattice;
  const auto& samples = field.points();
  std::array<double, 3> lo, hi;
  for(int a = 0; a < 3; ++a)
  {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for(const Point_3& p : samples)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], CGAL::to_double(p[a]));
      hi[a] = (std::max)(hi[a], CGAL::to_double(p[a]));
    }
  const double longest = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  double r = internal::default_cell_size(field); // ~1.25 x the mean sample spacing (CGAL's average spacing, 6 neighbours)
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::cell_size_t>::value)
    r = double(get_parameter(np, internal_np::cell_size));
  else if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                            internal_np::cells_along_longest_side_t>::value)
  {
    const double n = double(get_parameter(np, internal_np::cells_along_longest_side));
    if(!(n >= 1))
      throw Invalid_input_error("cells_along_longest_side must be at least 1");
    r = longest / n;
  }
  if(!(r > 0) || !std::isfinite(r))
    throw Invalid_input_error("the lattice cell size must be positive and finite (got " + std::to_string(r) + ")");
  // f is defined at most rho + delta beyond the samples (farther, the
  // projection onto the nearest plane is too far from every sample), so with
  // this margin the traversal stops at undefined corners, never at the
  // lattice border: the zero set of f can extend past an open border of the
  // sample (a tube continuing a cylinder, say) by up to rho + delta.
  const double default_margin = std::ceil((field.sampling_density() + field.noise_level()) / r) + 2;
  const double margin = double(choose_parameter(get_parameter(np, internal_np::lattice_margin), default_margin));
  if(!(margin >= 0) || !std::isfinite(margin))
    throw Invalid_input_error("lattice_margin must be >= 0");
  std::array<std::int64_t, 3> cells;
  for(int a = 0; a < 3; ++a)
  {
    lattice.origin[a] = lo[a] - margin * r;
    const double n = std::ceil((hi[a] - lo[a]) / r + 2 * margin);
    if(!(n < double(internal::lattice_limit - 1)))
      throw Invalid_input_error("the lattice would have more than 2^20 cells along an axis; use a larger cell size");
    cells[a] = (std::max)(std::int64_t(1), std::int64_t(n));
    lattice.cells[a] = cells[a];
  }
  lattice.r = r;
  return lattice;
}

// Whether the field has `consistent_value(p)` (a double everywhere) and
// `distance_to_samples(p)`, as `Tangent_plane_signed_distance_3` has.
template <typename Field, typename = void>
struct Has_consistent_value : std::false_type
{};
template <typename Field>
struct Has_consistent_value<
  Field, std::void_t<decltype(double(std::declval<const Field&>().consistent_value(
                        std::declval<const typename Field::Point_3&>()))),
                     decltype(double(std::declval<const Field&>().distance_to_samples(
                        std::declval<const typename Field::Point_3&>())))>> : std::true_type
{};

// Whether the field has `nearest_plane(p)` (the plane its value uses at p)
// and `uses_input_normals()`, as `Tangent_plane_signed_distance_3` has: those
// planes are the Hermite data of the sharp features.
template <typename Field, typename = void>
struct Has_tangent_planes : std::false_type
{};
template <typename Field>
struct Has_tangent_planes<
  Field, std::void_t<decltype(std::declval<const Field&>().nearest_plane(
                        std::declval<const typename Field::Point_3&>()).second),
                     decltype(bool(std::declval<const Field&>().uses_input_normals())),
                     decltype(std::size_t(std::declval<const Field&>().number_of_sharp_samples()))>> : std::true_type
{};

// One line per reason the output lacks the closed-2-manifold guarantee.
inline void add_contouring_warnings(Contouring_statistics& report)
{
  if(report.empty_output)
    report.warnings.push_back("the contour is empty");
  if(report.border_exits > 0)
    report.warnings.push_back(std::to_string(report.border_exits) +
                              " crossed face(s) on the lattice border: the output is open there");
  if(report.skipped_cubes + report.discontinuous_cubes > 0)
    report.warnings.push_back(std::to_string(report.skipped_cubes + report.discontinuous_cubes) +
                              " crossed cube(s) skipped (undefined corner or jump of f); " +
                              std::to_string(report.filled_holes) + " hole(s) filled");
}

// The traversal of a contouring, one method per stage: the field at the
// lattice points (cached), the seeds in the samples' cubes and the flood
// through crossed faces, the walks down |f| from the other samples, the
// triangles of the crossed cubes.  Counts go to `report`.
template <typename ContouringField_3>
class Contour_traversal
{
public:
  typedef typename ContouringField_3::Point_3 Point_3;

  // `consistent`: the values are the field's `consistent_value()`, defined everywhere.
  Contour_traversal(const Contouring_lattice& lattice, const ContouringField_3& field, double max_jump,
                    bool consistent, Contouring_statistics& report, const Progress& progress)
    : field(field), samples(field.points()), r(lattice.r), cells(lattice.cells), origin(lattice.origin),
      max_jump(max_jump), consistent(consistent), report(report), progress(progress)
  {
    value_cache.reserve(4 * samples.size());
    visited.reserve(4 * samples.size());
  }

  // Seeds, first pass: the cubes that hold a sample.  With a cell of about
  // the sample spacing f changes sign in most of them.  Then the flood from
  // them (flood()).
  //
  // Under Parallel_tag the same flood runs breadth first, one level at a
  // time, and the field is evaluated at each level's new lattice points on
  // TBB's threads (the field is 40-60 % of the traversal's time with
  // Tangent_plane_signed_distance_3).  The cubes a flood visits are a
  // closure (the seeds, and the neighbours of each crossed cube across its
  // crossed faces) that does not depend on the order of the visits, and the
  // crossed cubes are sorted before they are triangulated: the output and
  // the counts are the sequential ones, bit for bit.
  template <typename ConcurrencyTag>
  void seed_from_samples()
  {
    sample_xyz.resize(samples.size());
    for(std::size_t s = 0; s < samples.size(); ++s)
    {
      for(int a = 0; a < 3; ++a)
        sample_xyz[s][a] = CGAL::to_double(samples[s][a]);
      const std::array<std::int64_t, 3> c = cube_of(sample_xyz[s]);
      const std::uint64_t key = internal::lattice_key(c[0], c[1], c[2]);
      if(visited.insert(key, 1).second)
        stack.push_back(key);
    }
    if constexpr(is_parallel_tag<ConcurrencyTag>())
    {
      std::vector<std::uint64_t> level;
      std::vector<std::pair<std::uint64_t, double*>> new_corners; // (key, slot in the cache)
      std::vector<double*> corner_slots;
      level.swap(stack);
      while(!level.empty())
      {
        // The level's new corners, each once: a placeholder in the cache
        // marks it taken (no second lookup), and the evaluation writes the
        // value into its slot before any visit reads the cache; the visits
        // read the corners through `corner_slots`.  If the cache grew
        // meanwhile, its slots moved: they are looked up again.
        auto corner_key = [](const std::array<std::int64_t, 3>& c, int k) {
          return internal::lattice_key(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1));
        };
        new_corners.clear();
        corner_slots.resize(8 * level.size());
        const std::size_t capacity = value_cache.capacity();
        for(std::size_t q = 0; q < level.size(); ++q)
        {
          const std::array<std::int64_t, 3> c = internal::lattice_index(level[q]);
          for(int k = 0; k < 8; ++k)
          {
            const std::pair<double*, bool> inserted = value_cache.insert(corner_key(c, k), 0.);
            corner_slots[8 * q + std::size_t(k)] = inserted.first;
            if(inserted.second)
              new_corners.emplace_back(corner_key(c, k), inserted.first);
          }
        }
        if(value_cache.capacity() != capacity)
        {
          for(auto& corner : new_corners)
            corner.second = value_cache.insert(corner.first, 0.).first;
          for(std::size_t q = 0; q < level.size(); ++q)
          {
            const std::array<std::int64_t, 3> c = internal::lattice_index(level[q]);
            for(int k = 0; k < 8; ++k)
              corner_slots[8 * q + std::size_t(k)] = value_cache.insert(corner_key(c, k), 0.).first;
          }
        }
        // In key order: neighbouring lattice points one after the other, so
        // that the field's searches find their tree nodes in cache (200K
        // samples: the field took 1.8x as long in insertion order).
        std::sort(new_corners.begin(), new_corners.end());
        const auto start = std::chrono::steady_clock::now();
        concurrent_for_blocks<ConcurrencyTag>(new_corners.size(), 64, [&](std::size_t first, std::size_t last) {
          for(std::size_t e = first; e < last; ++e)
          {
            const std::array<std::int64_t, 3> p = internal::lattice_index(new_corners[e].first);
            *new_corners[e].second = evaluate(p[0], p[1], p[2]);
          }
        });
        m_field_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        report.field_evaluations += new_corners.size();
        for(const auto& corner : new_corners)
          report.undefined_points += std::isnan(*corner.second) ? 1 : 0;
        // The next level, in `stack` (visits insert no lattice point: the
        // slots stay where they are).
        for(std::size_t q = 0; q < level.size(); ++q)
        {
          for(int k = 0; k < 8; ++k)
            values[k] = *corner_slots[8 * q + std::size_t(k)];
          visit(level[q], internal::lattice_index(level[q]));
        }
        level.clear();
        level.swap(stack);
      }
    }
    else
    {
      std::sort(stack.begin(), stack.end(), std::greater<std::uint64_t>()); // pop smallest first
      flood();
    }
  }

  // Second pass, for cells finer than the offset of the zero set from the
  // samples (noise, curvature: sphere.pwn's zero set lies 1.4e-3 inside its
  // samples): from each sample whose cube f does not cross, walk down |f|
  // (along the gradient of the cube's trilinear interpolant, which is the
  // tangent plane's normal where the cube's corners share a plane) in steps
  // of half a cell, to the first crossed cube, at most rho + delta away (the
  // largest distance at which f is defined).  A walk ends at an undefined
  // cube, a jump, or a cube already crossed (its piece is traversed).
  void walk_from_samples()
  {
    Flat_uint64_map<char> crossed_cubes(surface_cubes.size()); // a set
    for(const std::uint64_t cube : surface_cubes)
      crossed_cubes.insert(cube, 1);
    const double walk_length = field.sampling_density() + field.noise_level() + r;
    const int max_steps = int((std::min)(std::ceil(walk_length / (0.5 * r)), 1e6));
    for(std::size_t s = 0; s < samples.size(); ++s)
    {
      if((s & 1023) == 0)
        progress.report(0.5 * double(s) / double(samples.size()));
      std::array<double, 3> q = sample_xyz[s];
      std::array<std::int64_t, 3> c = cube_of(q);
      if(crossed_cubes.contains(internal::lattice_key(c[0], c[1], c[2])))
        continue;
      if(cube_state(c, values) != Cube_state::uncrossed) // undefined or a jump: nothing to follow
        continue;
      for(int step = 0; step < max_steps; ++step)
      {
        // The trilinear interpolant of the cube at q: value and gradient.
        double u[3];
        for(int a = 0; a < 3; ++a)
          u[a] = (std::min)(1.0, (std::max)(0.0, (q[a] - origin[a]) / r - double(c[a])));
        double value = 0, g[3] = {0, 0, 0};
        for(int k = 0; k < 8; ++k)
        {
          double w[3], dw[3];
          for(int a = 0; a < 3; ++a)
          {
            const bool upper = ((k >> a) & 1) != 0;
            w[a] = upper ? u[a] : 1 - u[a];
            dw[a] = upper ? 1.0 : -1.0;
          }
          value += values[k] * w[0] * w[1] * w[2];
          g[0] += values[k] * dw[0] * w[1] * w[2];
          g[1] += values[k] * w[0] * dw[1] * w[2];
          g[2] += values[k] * w[0] * w[1] * dw[2];
        }
        const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if(!(norm > 0) || !std::isfinite(norm))
          break;
        // Half a cell towards f = 0 (g is per cell, so g / norm is a unit direction).
        const double length = (value < 0 ? 0.5 : -0.5) * r / norm;
        bool outside = false;
        for(int a = 0; a < 3; ++a)
        {
          q[a] += length * g[a];
          outside = outside || !(q[a] >= origin[a] && q[a] < origin[a] + double(cells[a]) * r);
        }
        if(outside)
          break;
        const std::array<std::int64_t, 3> next = cube_of(q);
        if(next == c)
          continue;
        c = next;
        const std::uint64_t key = internal::lattice_key(c[0], c[1], c[2]);
        const Cube_state state = cube_state(c, values);
        if(state == Cube_state::crossed)
        {
          if(visited.insert(key, 1).second)
          {
            const std::size_t before = surface_cubes.size();
            stack.push_back(key);
            ++report.walk_seeds;
            flood();
            for(std::size_t e = before; e < surface_cubes.size(); ++e)
              crossed_cubes.insert(surface_cubes[e], 1);
          }
          break;
        }
        if(state != Cube_state::uncrossed)
          break;
      }
    }

  }

  // Sorts the crossed cubes by key (the triangulation's order, which does
  // not depend on the order of the visits), their corner values with them.
  void sort_surface_cubes()
  {
    std::vector<std::pair<std::uint64_t, std::size_t>> order(surface_cubes.size());
    for(std::size_t q = 0; q < surface_cubes.size(); ++q)
      order[q] = {surface_cubes[q], q};
    std::sort(order.begin(), order.end());
    std::vector<std::array<double, 8>> sorted_values(order.size());
    for(std::size_t q = 0; q < order.size(); ++q)
    {
      surface_cubes[q] = order[q].first;
      sorted_values[q] = surface_values[order[q].second];
    }
    surface_values.swap(sorted_values);
    report.surface_cubes = surface_cubes.size();
  }

  // The table code and the decider's join mask of the crossed cube q of
  // `surface_cubes` (its values copied to `values`), counting its ambiguous
  // and joined faces.
  void cube_configuration(std::size_t q, unsigned& code, unsigned& join)
  {
    values = surface_values[q];
    code = internal::inside_cube_code(values);
    join = internal::asymptotic_decider_mask(values, code);
    const unsigned ambiguous = ambiguous_face_mask(code);
    for(int f = 0; f < 6; ++f)
      if((ambiguous >> f) & 1u)
      {
        ++report.ambiguous_faces;
        if((join >> f) & 1u)
          ++report.joined_faces;
      }
  }

  // The triangles of the crossed cubes, cube by cube in key order, appended;
  // vertices are welded by lattice edge.  Returns the number of points.
  template <typename PointOutRange, typename TriangleRange>
  std::size_t triangulate(PointOutRange& out_points, TriangleRange& out_triangles)
  {
    sort_surface_cubes();
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    Flat_uint64_map<std::size_t> edge_vertex;
    edge_vertex.reserve(3 * surface_cubes.size());
    std::size_t next_vertex = out_points.size();
    for(std::size_t q = 0; q < surface_cubes.size(); ++q)
    {
      const std::array<std::int64_t, 3> c = internal::lattice_index(surface_cubes[q]);
      unsigned code, join;
      cube_configuration(q, code, join);
      std::array<std::size_t, 12 + Marching_cubes_table::max_number_of_polygons> local;
      local.fill(std::size_t(-1));
      auto edge_point = [&](int e) -> Point_3 {
        const std::array<int, 2> ends = cube_edge_corners(e);
        const std::array<int, 3> o0 = cube_corner_offset(ends[0]), o1 = cube_corner_offset(ends[1]);
        const Point_3 vi = lattice_point(c[0] + o0[0], c[1] + o0[1], c[2] + o0[2]);
        const Point_3 vj = lattice_point(c[0] + o1[0], c[1] + o1[1], c[2] + o1[2]);
        const double t = internal::vertex_edge_parameter(values[ends[0]], values[ends[1]]);
        return vi + t * (vj - vi);
      };
      auto vertex = [&](unsigned v) -> std::size_t {
        if(local[v] != std::size_t(-1))
          return local[v];
        if(Marching_cubes_table::is_centre_vertex(v))
        {
          // Private to this cube: the centroid of its polygon's edge points.
          double x = 0, y = 0, z = 0;
          const auto polygon = table.polygon(code, join, v - 12);
          for(std::size_t i = 0; i < polygon.size(); ++i)
          {
            const Point_3 p = edge_point(polygon[i]);
            x += CGAL::to_double(p.x());
            y += CGAL::to_double(p.y());
            z += CGAL::to_double(p.z());
          }
          const double m = double(polygon.size());
          out_points.push_back(Point_3(x / m, y / m, z / m));
          ++report.centre_vertices;
          return local[v] = next_vertex++;
        }
        const int e = int(v);
        const std::array<int, 3> o = cube_edge_origin_offset(e);
        const std::uint64_t edge_key =
          4 * internal::lattice_key(c[0] + o[0], c[1] + o[1], c[2] + o[2]) + std::uint64_t(cube_edge_axis(e));
        const auto inserted = edge_vertex.insert(edge_key, next_vertex);
        if(inserted.second)
        {
          out_points.push_back(edge_point(e));
          ++next_vertex;
        }
        return local[v] = *inserted.first;
      };
      for(const auto& t : table.triangles(code, join))
      {
        const std::size_t a = vertex(t[0]), b = vertex(t[1]), d = vertex(t[2]);
        out_triangles.push_back(typename TriangleRange::value_type{a, b, d});
        ++report.number_of_faces;
      }
    }
    return next_vertex;
  }

  // As triangulate(), but a polygon whose Hermite normals (the normal of
  // the tangent plane nearest to each of its edge points) disagree by more
  // than the feature angle is fanned around a feature vertex (Extended
  // Marching Cubes, as in the CSG, internal/Marching_cubes_csg/), and the
  // face segments between neighbouring fans are flipped afterwards so that
  // the feature vertices join into feature lines.  The boundary of every
  // cube's patch is the plain one, so the soup stays closed and 2-manifold.
  template <typename PointOutRange, typename TriangleRange>
  std::size_t triangulate_with_features(PointOutRange& out_points, TriangleRange& out_triangles,
                                        const Marching_cubes_csg::Feature_settings& settings)
  {
    namespace MC = Marching_cubes_csg;
    sort_surface_cubes();
    const Marching_cubes_table& table = Marching_cubes_table::instance();
    Flat_uint64_map<std::size_t> edge_vertex;
    edge_vertex.reserve(3 * surface_cubes.size());
    const std::size_t first_vertex = out_points.size();
    std::vector<MC::Vector_3d> points, hermite_points, normals; // from first_vertex
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<std::size_t> fans;
    MC::Plain_feature_counts plain;
    for(std::size_t q = 0; q < surface_cubes.size(); ++q)
    {
      const std::array<std::int64_t, 3> c = internal::lattice_index(surface_cubes[q]);
      unsigned code, join;
      cube_configuration(q, code, join);
      auto edge_point = [&](int e) -> MC::Vector_3d {
        const std::array<int, 2> ends = cube_edge_corners(e);
        const std::array<int, 3> o0 = cube_corner_offset(ends[0]), o1 = cube_corner_offset(ends[1]);
        const double t = internal::vertex_edge_parameter(values[ends[0]], values[ends[1]]);
        MC::Vector_3d p;
        for(int a = 0; a < 3; ++a)
          p[a] = origin[a] + double(c[a] + o0[a]) * r + t * (double(o1[a] - o0[a]) * r);
        return p;
      };
      auto edge_vertex_of = [&](int e) -> std::size_t {
        const std::array<int, 3> o = cube_edge_origin_offset(e);
        const std::uint64_t edge_key =
          4 * internal::lattice_key(c[0] + o[0], c[1] + o[1], c[2] + o[2]) + std::uint64_t(cube_edge_axis(e));
        const auto inserted = edge_vertex.insert(edge_key, first_vertex + points.size());
        if(inserted.second)
        {
          const MC::Vector_3d p = edge_point(e);
          const Point_3 q(p[0], p[1], p[2]);
          const auto plane = field.nearest_plane(q);
          const MC::Vector_3d normal{
            {CGAL::to_double(plane.second.x()), CGAL::to_double(plane.second.y()), CGAL::to_double(plane.second.z())}};
          const double d = CGAL::to_double((q - plane.first) * plane.second);
          points.push_back(p);
          normals.push_back(normal);
          hermite_points.push_back({{p[0] - d * normal[0], p[1] - d * normal[1], p[2] - d * normal[2]}});
        }
        return *inserted.first;
      };
      const MC::Vector_3d low{{origin[0] + double(c[0]) * r, origin[1] + double(c[1]) * r, origin[2] + double(c[2]) * r}};
      const MC::Vector_3d high{{low[0] + r, low[1] + r, low[2] + r}};
      const auto plain_triangles = table.triangles(code, join);
      const unsigned polygons = table.number_of_polygons(code, join);
      // First the decision of every polygon, then, if the cube has several
      // polygons and a fan, the test that no two polygons intersect (a fan
      // can pierce another polygon of the same cube, as in the CSG), then
      // the triangles.
      struct Polygon_plan
      {
        std::array<std::size_t, 12> ids;
        std::size_t size, first_plain, plain_count;
        bool centre;
        MC::Feature_kind kind = MC::Feature_kind::NONE;
        MC::Vector_3d apex;
      };
      std::array<Polygon_plan, Marching_cubes_table::max_number_of_polygons> plans;
      // The table's centre vertex of a polygon: the centroid of its edge points.
      const auto centroid = [&](const Polygon_plan& plan) {
        MC::Vector_3d x{{0, 0, 0}};
        for(std::size_t i = 0; i < plan.size; ++i)
          for(int a = 0; a < 3; ++a)
            x[a] += points[plan.ids[i] - first_vertex][a] / double(plan.size);
        return x;
      };
      std::size_t next_triangle = 0, fanned = 0;
      for(unsigned q = 0; q < polygons; ++q)
      {
        Polygon_plan& plan = plans[q];
        const auto polygon = table.polygon(code, join, q);
        plan.size = polygon.size();
        std::array<MC::Vector_3d, 12> p, hp, n;
        for(std::size_t i = 0; i < plan.size; ++i)
        {
          plan.ids[i] = edge_vertex_of(int(polygon[i]));
          p[i] = points[plan.ids[i] - first_vertex];
          hp[i] = hermite_points[plan.ids[i] - first_vertex];
          n[i] = normals[plan.ids[i] - first_vertex];
        }
        const auto& first = plain_triangles[next_triangle];
        plan.centre = Marching_cubes_table::is_centre_vertex(first[0]) ||
                      Marching_cubes_table::is_centre_vertex(first[1]) ||
                      Marching_cubes_table::is_centre_vertex(first[2]);
        plan.first_plain = next_triangle;
        plan.plain_count = plan.centre ? plan.size : plan.size - 2;
        next_triangle += plan.plain_count;
        if(plan.size >= 3 && MC::has_feature(n.data(), plan.size, settings))
        {
          bool folded = false;
          plan.kind = MC::feature_vertex(hp.data(), n.data(), plan.size, low, high, settings,
                                         [&](const MC::Vector_3d& x) {
                                           const bool ok = MC::fan_is_unfolded(p.data(), n.data(), plan.size, x);
                                           folded = folded || !ok;
                                           return ok;
                                         },
                                         plan.apex);
          if(plan.kind == MC::Feature_kind::NONE)
            ++(folded ? plain.folded : plain.no_point);
          else
            ++fanned;
        }
        if(plan.kind == MC::Feature_kind::NONE && plan.centre)
          plan.apex = centroid(plan);
      }
      if(fanned > 0 && polygons > 1)
      {
        typedef Exact_predicates_inexact_constructions_kernel EK;
        const auto point = [&](const MC::Vector_3d& x) { return EK::Point_3(x[0], x[1], x[2]); };
        const auto vertex_point = [&](std::size_t v) { return point(points[v - first_vertex]); };
        std::vector<EK::Triangle_3> pieces;
        std::vector<unsigned> polygon_of;
        for(unsigned q = 0; q < polygons; ++q)
        {
          const Polygon_plan& plan = plans[q];
          const auto add = [&](const EK::Triangle_3& t) {
            if(!t.is_degenerate())
            {
              pieces.push_back(t);
              polygon_of.push_back(q);
            }
          };
          if(plan.kind != MC::Feature_kind::NONE || plan.centre)
            for(std::size_t i = 0; i < plan.size; ++i)
              add(EK::Triangle_3(vertex_point(plan.ids[i]), vertex_point(plan.ids[(i + 1) % plan.size]),
                                 point(plan.apex)));
          else
            for(std::size_t t = plan.first_plain; t < plan.first_plain + plan.plain_count; ++t)
              add(EK::Triangle_3(vertex_point(edge_vertex_of(int(plain_triangles[t][0]))),
                                 vertex_point(edge_vertex_of(int(plain_triangles[t][1]))),
                                 vertex_point(edge_vertex_of(int(plain_triangles[t][2])))));
        }
        bool pierced = false;
        for(std::size_t i = 0; i < pieces.size() && !pierced; ++i)
          for(std::size_t j = i + 1; j < pieces.size() && !pierced; ++j)
            pierced = polygon_of[i] != polygon_of[j] && CGAL::do_intersect(pieces[i], pieces[j]);
        if(pierced)
        {
          plain.folded += fanned;
          for(unsigned q = 0; q < polygons; ++q)
            if(plans[q].kind != MC::Feature_kind::NONE)
            {
              plans[q].kind = MC::Feature_kind::NONE;
              // A polygon whose table entry fans around a centre vertex keeps that fan.
              if(plans[q].centre)
                plans[q].apex = centroid(plans[q]);
            }
        }
      }
      for(unsigned q = 0; q < polygons; ++q)
      {
        const Polygon_plan& plan = plans[q];
        if(plan.kind != MC::Feature_kind::NONE || plan.centre)
        {
          if(plan.kind == MC::Feature_kind::NONE)
            ++report.centre_vertices;
          else
            ++(plan.kind == MC::Feature_kind::CORNER ? report.feature_corners : report.feature_creases);
          const std::size_t f = first_vertex + points.size();
          points.push_back(plan.apex);
          normals.push_back({{0, 0, 0}});
          hermite_points.push_back(plan.apex);
          for(std::size_t i = 0; i < plan.size; ++i)
          {
            if(plan.kind != MC::Feature_kind::NONE)
              fans.push_back(triangles.size());
            triangles.push_back({{plan.ids[i], plan.ids[(i + 1) % plan.size], f}});
          }
        }
        else
          for(std::size_t t = plan.first_plain; t < plan.first_plain + plan.plain_count; ++t)
          {
            const auto& tr = plain_triangles[t];
            triangles.push_back({{edge_vertex_of(int(tr[0])), edge_vertex_of(int(tr[1])), edge_vertex_of(int(tr[2]))}});
          }
      }
    }
    // Flips between neighbouring fans, on indices relative to first_vertex.
    std::vector<std::array<std::size_t, 3>> local(triangles.size());
    for(std::size_t t = 0; t < triangles.size(); ++t)
      for(int k = 0; k < 3; ++k)
        local[t][k] = triangles[t][k] - first_vertex;
    std::vector<MC::Flipped_edge> flipped;
    MC::flip_feature_edges(points, normals, local, fans, flipped);
    report.feature_flips = flipped.size();
    for(const MC::Vector_3d& p : points)
      out_points.push_back(Point_3(p[0], p[1], p[2]));
    for(const auto& t : local)
    {
      out_triangles.push_back(typename TriangleRange::value_type{t[0] + first_vertex, t[1] + first_vertex,
                                                                 t[2] + first_vertex});
      ++report.number_of_faces;
    }
    return out_points.size();
  }

  double field_seconds() const { return m_field_seconds; }

private:
  // A cube is "crossed" when its 8 corners are defined, not all of one sign,
  // and f does not jump along a sign-changing edge.
  enum class Cube_state { undefined, undefined_crossed, uncrossed, jump, crossed };

  // One formula for every lattice point, so shared corners get identical coordinates.
  Point_3 lattice_point(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    return Point_3(origin[0] + double(i) * r, origin[1] + double(j) * r, origin[2] + double(k) * r);
  }

  // The field at a lattice point (NaN = undefined), not cached.
  double evaluate(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    std::optional<double> f;
    if constexpr(Has_consistent_value<ContouringField_3>::value)
    {
      if(consistent)
        f = field.consistent_value(lattice_point(i, j, k));
      else
        f = field(lattice_point(i, j, k));
    }
    else
      f = field(lattice_point(i, j, k));
    return f ? *f : std::numeric_limits<double>::quiet_NaN();
  }

  void cache_value(std::uint64_t key, double v)
  {
    ++report.field_evaluations;
    if(std::isnan(v))
      ++report.undefined_points;
    value_cache.insert(key, v);
  }

  // The field at a lattice point, cached (NaN = undefined).
  double value_at(std::int64_t i, std::int64_t j, std::int64_t k)
  {
    const std::uint64_t key = internal::lattice_key(i, j, k);
    if(const double* found = value_cache.find(key))
      return *found;
    const auto start = std::chrono::steady_clock::now();
    const double v = evaluate(i, j, k);
    m_field_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cache_value(key, v);
    return v;
  }

  bool cube_values(const std::array<std::int64_t, 3>& c, std::array<double, 8>& values)
  {
    bool defined = true;
    for(int k = 0; k < 8; ++k)
    {
      values[k] = value_at(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1));
      defined = defined && !std::isnan(values[k]);
    }
    return defined;
  }

  Cube_state cube_state(const std::array<std::int64_t, 3>& c, std::array<double, 8>& v)
  {
    cube_values(c, v);
    return state_of_values(v);
  }

  // The state of a cube whose corner values are `v`.
  Cube_state state_of_values(const std::array<double, 8>& v) const
  {
    bool defined = true;
    for(int k = 0; k < 8; ++k)
      defined = defined && !std::isnan(v[k]);
    // Signs with undefined corners: only the defined ones can witness a crossing.
    bool has_in = false, has_out = false;
    for(int k = 0; k < 8; ++k)
      if(!std::isnan(v[k]))
        (v[k] < 0 ? has_in : has_out) = true;
    if(!defined)
      return (has_in && has_out) ? Cube_state::undefined_crossed : Cube_state::undefined;
    const unsigned code = internal::inside_cube_code(v);
    if(code == 0 || code == 0xFF)
      return Cube_state::uncrossed;
    return internal::has_jump_edge(v, code, max_jump) ? Cube_state::jump : Cube_state::crossed;
  }

  std::array<std::int64_t, 3> cube_of(const std::array<double, 3>& p) const
  {
    std::array<std::int64_t, 3> c;
    for(int a = 0; a < 3; ++a)
      c[a] = (std::min)(cells[a] - 1, (std::max)(std::int64_t(0), std::int64_t(std::floor((p[a] - origin[a]) / r))));
    return c;
  }

  // Whether the surface crosses face f of a cube whose inside corners are `code`.
  static bool face_is_crossed(unsigned code, int f)
  {
    const std::array<int, 4> corners = cube_face_corners(f);
    const bool first = is_inside_corner(code, corners[0]);
    bool crossed = false;
    for(int i = 1; i < 4; ++i)
      crossed = crossed || (is_inside_corner(code, corners[i]) != first);
    return crossed;
  }

  // Moves cube `c` across its face f; false if that leaves the lattice.
  bool neighbour_across(int f, std::array<std::int64_t, 3>& c) const
  {
    const int a = cube_face_axis(f);
    c[a] += cube_face_side(f) ? 1 : -1;
    return c[a] >= 0 && c[a] < cells[a];
  }

  // Pops cubes off `stack` and visits them, until it is empty.
  void flood()
  {
    while(!stack.empty())
    {
      const std::uint64_t key = stack.back();
      stack.pop_back();
      visit(key);
    }
  }

  // Counts cube `key` as visited; if the surface crosses it, adds it to the
  // surface cubes and pushes its unvisited neighbours across crossed faces
  // onto `stack`.
  void visit(std::uint64_t key)
  {
    const std::array<std::int64_t, 3> c = internal::lattice_index(key);
    cube_values(c, values);
    visit(key, c);
  }

  // As visit(key), with the cube's corner values already in `values`.
  void visit(std::uint64_t key, const std::array<std::int64_t, 3>& c)
  {
    ++report.visited_cubes;
    // The traversal's extent is unknown beforehand: report 0 as a chance to cancel.
    if((report.visited_cubes & 0xFFFF) == 0)
      progress.report(0);
    const Cube_state state = state_of_values(values);
    if(state == Cube_state::undefined_crossed)
      ++report.skipped_cubes; // Hoppe: a cube with an undefined corner is skipped
    else if(state == Cube_state::jump)
      ++report.discontinuous_cubes; // a jump of f between two planes, not a surface
    if(state != Cube_state::crossed)
      return;
    const unsigned code = internal::inside_cube_code(values);
    surface_cubes.push_back(key);
    surface_values.push_back(values);
    for(int f = 0; f < 6; ++f)
    {
      if(!face_is_crossed(code, f))
        continue;
      std::array<std::int64_t, 3> n = c;
      if(!neighbour_across(f, n))
      {
        ++report.border_exits; // the default margin prevents this; it leaves a hole
        continue;
      }
      const std::uint64_t neighbour = internal::lattice_key(n[0], n[1], n[2]);
      if(visited.insert(neighbour, 1).second)
        stack.push_back(neighbour);
    }
  }

  const ContouringField_3& field;
  // The samples, by reference when `points()` returns one, else a copy.
  typedef decltype(std::declval<const ContouringField_3&>().points()) Samples_result;
  const std::conditional_t<std::is_reference<Samples_result>::value, Samples_result, std::decay_t<Samples_result>>
      samples;
  const double r;
  const std::array<std::int64_t, 3> cells;
  const std::array<double, 3> origin;
  const double max_jump;
  const bool consistent;
  Contouring_statistics& report;
  const Progress& progress;
  Flat_uint64_map<double> value_cache;
  double m_field_seconds = 0;
  std::vector<std::uint64_t> stack;
  Flat_uint64_map<char> visited; // a set
  std::vector<std::uint64_t> surface_cubes;
  std::vector<std::array<double, 8>> surface_values; // the corner values of each surface cube
  std::vector<std::array<double, 3>> sample_xyz;
  std::array<double, 8> values;
};

// The contouring on `lattice` (appends to the outputs): the traversal, then
// the repairs (bubbles removed, small holes closed).
template <typename ConcurrencyTag, typename ContouringField_3, typename PointOutRange, typename TriangleRange,
          typename NamedParameters>
Contouring_statistics contour_on_lattice(const Contouring_lattice& lattice, const ContouringField_3& field,
                                         PointOutRange& out_points, TriangleRange& out_triangles,
                                         const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto total_start = std::chrono::steady_clock::now();
  const Progress progress = progress_of(np);
  Contouring_statistics report;
  const double r = lattice.r;
  report.origin = lattice.origin;
  for(int a = 0; a < 3; ++a)
    report.number_of_cells[a] = std::size_t(lattice.cells[a]);
  report.cell_size = r;
  // A signed distance is 1-Lipschitz: across a lattice edge of length r a true
  // zero crossing changes f by at most r, plus the noise on both ends.  Hoppe's
  // f is piecewise planar and jumps where the nearest centre changes; near the
  // surface those jumps are small, but where two oppositely oriented sheets
  // are closer than a neighbourhood (thin walls) the nearest centre alternates
  // between them and f flips sign with a jump of twice the distance to the
  // wall: "phantom" sheets that run away from the surface.  Such cubes are
  // skipped (holes instead of phantom sheets).  Factor 3: slack for the plane
  // switches near the surface; with 2 r, cactus.pts lost 4 genuine cubes.
  // One consistent value per lattice point when the field has one (and the
  // caller did not ask for Hoppe's f alone): then no cube is skipped and the
  // contour is closed and 2-manifold by the table's theorem.
  bool consistent = false;
  if constexpr(Has_consistent_value<ContouringField_3>::value)
    consistent = choose_parameter(get_parameter(np, internal_np::consistent_signs), true);
  report.consistent_signs = consistent;
  // With consistent values a jump of f is a steep crossing, not a gap: kept.
  const double max_jump = consistent ? std::numeric_limits<double>::infinity()
                                     : double(choose_parameter(get_parameter(np, internal_np::maximum_jump),
                                                               3 * r + 2 * field.noise_level()));
  Contour_traversal<ContouringField_3> traversal(lattice, field, max_jump, consistent, report, progress);
  traversal.template seed_from_samples<ConcurrencyTag>();
  traversal.walk_from_samples();
  const std::size_t first_vertex = out_points.size();
  const std::size_t first_triangle = out_triangles.size();
  std::size_t next_vertex = 0;
  bool features = false;
  const Marching_cubes_csg::Feature_settings settings = feature_settings(np);
  if constexpr(Has_tangent_planes<ContouringField_3>::value)
  {
    // By default, only where a sharp feature can be: input normals, and a
    // sample whose neighbours' normals disagree (sphere.pwn has none, and
    // the Hermite data cost 15 % of its contouring for nothing).
    features = choose_parameter(get_parameter(np, internal_np::sharp_features),
                                field.uses_input_normals() && field.number_of_sharp_samples() > 0);
    if(features)
      next_vertex = traversal.triangulate_with_features(out_points, out_triangles, settings);
  }
  if(!features)
    next_vertex = traversal.triangulate(out_points, out_triangles);
  const double field_seconds = traversal.field_seconds();
  // Bubbles: Hoppe's f is piecewise planar and switches planes at the
  // Voronoi faces of the centres; in concave regions a lattice point can fall
  // on the wrong side of a plane that is not the one that matters, and
  // becomes a closed surface around one or two lattice points.  A closed
  // component smaller than rho is below what a rho-dense sample can witness.
  const double bubble_size = choose_parameter(get_parameter(np, internal_np::minimum_closed_component_size),
                                              field.sampling_density());
  if(!(bubble_size >= 0))
    throw Invalid_input_error("minimum_closed_component_size must be >= 0");
  if(bubble_size > 0)
  {
    report.removed_closed_components =
      internal::remove_small_closed_components(out_points, out_triangles, first_vertex, first_triangle, bubble_size);
    next_vertex = out_points.size();
    report.number_of_faces = out_triangles.size() - first_triangle;
  }
  // Membranes: with consistent values the contour closes every opening of
  // the samples; the pieces far from every sample that span a wide opening
  // (the rim of an open scan, Hoppe's distcap.pts) are cut away, the narrow
  // ones (gaps, unsampled socket bottoms) stay.
  if constexpr(Has_consistent_value<ContouringField_3>::value)
  {
    // Witnessed: within rho + delta of a sample (f is defined that far).
    // Default widest gap closed: 6 (rho + delta), and at least a fifth of the
    // samples' extent: a gap left by occlusion in merged scans can be many
    // sample spacings wide, an open rim (distcap.pts: 0.70 across, diagonal
    // 1.26) spans a good part of the object.
    const double reach = field.sampling_density() + field.noise_level();
    Bbox_3 extent;
    for(const auto& p : field.points())
      extent += Bbox_3(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]),
                       CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
    const double diagonal = std::sqrt(CGAL::square(extent.xmax() - extent.xmin()) +
                                      CGAL::square(extent.ymax() - extent.ymin()) +
                                      CGAL::square(extent.zmax() - extent.zmin()));
    const double max_hole = choose_parameter(get_parameter(np, internal_np::maximum_hole_size),
                                             (std::max)(6 * reach, diagonal / 5));
    if(!(max_hole >= 0))
      throw Invalid_input_error("maximum_hole_size must be >= 0");
    if(consistent && out_triangles.size() > first_triangle)
    {
      report.removed_membranes = internal::remove_unwitnessed_membranes<ConcurrencyTag>(
        out_points, out_triangles, first_vertex, first_triangle, field.points(),
        [&field](const auto& p) { return double(field.distance_to_samples(p)); }, reach, max_hole / 2);
      next_vertex = out_points.size();
      report.number_of_faces = out_triangles.size() - first_triangle;
    }
  }
  // Holes: a skipped cube (undefined corner, jump of f)
  // leaves a hole in an otherwise closed surface.  Without one the soup is a
  // closed 2-manifold by construction, and nothing is done.
  // (Lattice-border exits are not repaired: the default margin prevents them,
  // and a lattice cut short by lattice_margin is open there on purpose.)
  if(report.skipped_cubes + report.discontinuous_cubes > 0 &&
     out_triangles.size() > first_triangle)
  {
    const double hole_size = choose_parameter(get_parameter(np, internal_np::maximum_hole_size),
                                              2 * field.sampling_density());
    const auto repaired =
      internal::close_small_holes(out_points, out_triangles, first_vertex, first_triangle, hole_size);
    report.split_vertices = repaired.first;
    report.filled_holes = repaired.second;
    next_vertex = out_points.size();
    report.number_of_faces = out_triangles.size() - first_triangle;
  }
  report.number_of_vertices = next_vertex - first_vertex;
  report.empty_output = report.number_of_faces == 0;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - total_start).count();
  report.seconds_field = field_seconds;
  report.seconds_contouring = report.seconds - field_seconds;
  add_contouring_warnings(report);
  progress.report(1.0);
  return report;}

} // namespace internal


namespace internal {

// The mesh of a contouring soup (cleared first); pinched vertices between two
// holes are duplicated (PMP::orient_polygon_soup) so that the mesh is valid.
template <typename Point, typename PolygonMesh>
void contour_soup_to_mesh(std::vector<Point>& soup_points, std::vector<std::array<std::size_t, 3>>& soup_triangles,
                          PolygonMesh& mesh)
{
  internal::clear_output_mesh(mesh);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup_triangles))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup_triangles);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup_points, soup_triangles, mesh);
}

} // namespace internal

namespace internal {

inline Contouring_lattice to_contouring_lattice(const Regular_lattice_3& lattice)
{
  Contouring_lattice l;
  l.r = lattice.spacing();
  for(int a = 0; a < 3; ++a)
  {
    l.origin[a] = lattice.coordinate(a, 0);
    if(lattice.number_of_points(a) < 2)
      throw Invalid_input_error("a contouring lattice needs at least 2 points along every axis");
    if(lattice.number_of_points(a) - 1 >= std::size_t(lattice_limit - 1))
      throw Invalid_input_error("the lattice has more than 2^20 cells along an axis");
    l.cells[a] = std::int64_t(lattice.number_of_points(a) - 1);
  }
  return l;
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CONTOUR_ON_LATTICE_H
