// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_TRIANGULATION_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_TRIANGULATION_H

// Feature-sensitive triangulation of the Marching Cubes CSG cubes (Extended
// Marching Cubes, Kobbelt et al. 2001) from exact Hermite data.
//
// Each polygon of a cube (its boundary is fixed by the face rule, so the
// neighbours see the same segments) is either triangulated as the table
// does, or, when its crossing normals disagree, fanned around a feature
// vertex strictly private to the cube.  The boundary of every cube's patch
// is therefore unchanged, and the welded output is closed and 2-manifold for
// the same reason as the plain one; the fan of a polygon with n sides is a
// disk of n triangles around one interior vertex.  The edge flips that join
// feature vertices of neighbouring cubes are done afterwards, on the welded
// soup (Feature_edge_flips.h).

#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_edge_flips.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

/// The unit normal of an input triangle and the exact signs of its
/// components (the signs orient it at a crossing).
struct Triangle_tangent
{
  Vector_3d normal;
  std::array<signed char, 3> sign;
};

inline std::vector<Triangle_tangent> triangle_tangents(const std::vector<Lattice_triangle>& triangles)
{
  std::vector<Triangle_tangent> result(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Lattice_triangle& tr = triangles[t];
    Vector_3d n = triangle_normal(tr.p[0], tr.p[1], tr.p[2]);
    const double length = std::sqrt(dot3(n, n));
    if(length > 0)
      for(int a = 0; a < 3; ++a)
        n[a] /= length;
    result[t] = Triangle_tangent{n, tr.normal_sign};
  }
  return result;
}

/// The outward unit normal at a crossing of a lattice edge along `axis` where
/// the output goes from inside to outside in the direction of increasing
/// coordinate iff `increasing`: the crossed triangle is not parallel to the
/// edge, so the exact sign of its normal's component along `axis` says which
/// of its two sides faces the outside.  Whether that is `-t.normal`:
inline bool outward_normal_is_reversed(const Triangle_tangent& t, int axis, bool increasing)
{
  return (t.sign[axis] > 0) != increasing;
}

/// The outward unit normal itself.
inline Vector_3d outward_normal(const Triangle_tangent& t, int axis, bool increasing)
{
  Vector_3d n = t.normal;
  if(outward_normal_is_reversed(t, axis, increasing))
    for(int a = 0; a < 3; ++a)
      n[a] = -n[a];
  return n;
}

/// The outward unit normal of every edge vertex, kept as the number of the
/// input triangle it lies on and a sign: 5 bytes a vertex instead of 24
/// (at 2048 cells the normals were 350 MB of the memory peak while the
/// vertices are placed), and the same bits as `outward_normal()`.
class Edge_vertex_normals
{
public:
  explicit Edge_vertex_normals(const std::vector<Triangle_tangent>& tangents) : m_tangents(&tangents) {}

  std::size_t size() const { return m_triangle.size(); }
  void resize(std::size_t n)
  {
    m_triangle.resize(n);
    m_flip.resize(n);
  }
  void clear()
  {
    std::vector<std::uint32_t>().swap(m_triangle);
    std::vector<unsigned char>().swap(m_flip);
  }
  /// Vertex v lies on input triangle t, crossed along `axis`, the inside on
  /// the lower side iff `increasing` (see `outward_normal()`).
  void set(std::size_t v, std::uint32_t t, int axis, bool increasing)
  {
    m_triangle[v] = t;
    m_flip[v] = outward_normal_is_reversed((*m_tangents)[t], axis, increasing);
  }
  Vector_3d operator[](std::size_t v) const
  {
    Vector_3d n = (*m_tangents)[m_triangle[v]].normal;
    if(m_flip[v])
      for(int a = 0; a < 3; ++a)
        n[a] = -n[a];
    return n;
  }

private:
  const std::vector<Triangle_tangent>* m_tangents;
  std::vector<std::uint32_t> m_triangle;
  std::vector<unsigned char> m_flip;
};

/// Marks feature vertices in the per-chunk triangles before they get their
/// global number (so edge points and a chunk's feature points must number
/// fewer than 2^31: `max_chunk_vertices`).
constexpr std::uint32_t feature_vertex_flag = std::uint32_t(1) << 31;
constexpr std::size_t max_chunk_vertices = feature_vertex_flag;

/// Polygons whose normals disagree but that keep the plain triangulation:
/// no feature point in the cube, or a fan that would fold.
struct Plain_feature_counts
{
  std::size_t no_point = 0, folded = 0;
};

/// What the triangulation of a range of cubes produces.
struct Feature_chunk
{
  // 32-bit: all chunks together hold every triangle of the output, at the
  // memory peak of the feature path.
  typedef std::array<std::uint32_t, 3> Triangle;
  std::vector<Triangle> triangles;
  std::vector<Vector_3d> feature_points;
  std::vector<Feature_kind> feature_kinds;
  std::vector<std::size_t> fans; // fan triangles, indices into `triangles`
  /// The feature points whose fans only the weaker fold test accepts
  /// (`Fold_test::SUM`), as (index into `feature_points`, cube id), increasing.
  std::vector<std::array<std::uint64_t, 2>> weak_fans;
  Plain_feature_counts plain;
};

/// The feature decision of a polygon of the cube [low, high]: its feature
/// vertex, if it has one and the fan around it does not fold.  Counts the
/// polygons whose normals disagree but that keep the plain triangulation in
/// `out.plain`.  Unless `strict`, a fan passes the weaker fold test
/// (`Fold_test::SUM`), and the fans only that test accepts are listed in
/// `out.weak_fans` with the id of the cube.
class Feature_decision
{
public:
  Feature_decision(const Vector_3d& low, const Vector_3d& high, const Feature_settings& settings, Feature_chunk& out,
                   std::uint64_t cube = 0, bool strict = true)
    : m_low(low), m_high(high), m_settings(settings), m_out(out), m_cube(cube), m_strict(strict)
  {}

  Feature_kind operator()(const Vector_3d* p, const Vector_3d* n, std::size_t size, Vector_3d& apex) const
  {
    if(!has_feature(n, size, m_settings))
      return Feature_kind::NONE;
    // A candidate whose fan would fold is refused and the next lower rank
    // tried (a "corner" of three nearly coplanar facets of a curved surface
    // is often just a crease).
    // The weaker test only for candidates of the quadric's own rank: a lower
    // rank tried after those were refused drops a plane, and its line can
    // leave the solid past a corner (a box whose faces are lattice planes
    // got a vertex 0.14 cells off its face from the line of two of its
    // three planes, which the weaker test let through).
    bool folded = false;
    const auto unfolded = [&](const Vector_3d& x, bool full_rank) {
      const Fold_test test = m_strict || !full_rank ? Fold_test::STRICT : Fold_test::SUM;
      const bool ok = fan_is_unfolded(p, n, size, x, test);
      folded = folded || !ok;
      return ok;
    };
    const Feature_kind kind = feature_vertex(p, n, size, m_low, m_high, m_settings, unfolded, apex);
    if(kind != Feature_kind::NONE)
    {
      // The apex is the next feature point (triangulate_feature_cube()).
      if(!m_strict && !fan_is_unfolded(p, n, size, apex, Fold_test::STRICT))
        m_out.weak_fans.push_back({{std::uint64_t(m_out.feature_points.size()), m_cube}});
      return kind;
    }
    if(folded)
      ++m_out.plain.folded;
    else
      ++m_out.plain.no_point;
    return Feature_kind::NONE;
  }

private:
  Vector_3d m_low, m_high;
  const Feature_settings& m_settings;
  Feature_chunk& m_out;
  std::uint64_t m_cube;
  bool m_strict;
};

/// Whether two triangles of different polygons of one cube intersect: the
/// triangles of polygon q are `out.triangles[end[q - 1] .. end[q])` (from
/// `first` for q = 0).  Polygons share no vertex, so any common point is a
/// crossing.  Exact predicates; degenerate triangles are skipped.
inline bool polygons_intersect(const Feature_chunk& out, std::size_t first, const std::size_t* end,
                               unsigned polygons, const std::vector<Vector_3d>& points)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  const auto point = [&](std::uint32_t v) {
    const Vector_3d& p = (v & feature_vertex_flag) ? out.feature_points[v & ~feature_vertex_flag] : points[v];
    return K::Point_3(p[0], p[1], p[2]);
  };
  std::vector<K::Triangle_3> triangles;
  std::vector<unsigned> polygon_of;
  unsigned q = 0;
  for(std::size_t t = first; t < end[polygons - 1]; ++t)
  {
    while(t >= end[q])
      ++q;
    const auto& tr = out.triangles[t];
    const K::Triangle_3 triangle(point(tr[0]), point(tr[1]), point(tr[2]));
    if(!triangle.is_degenerate())
    {
      triangles.push_back(triangle);
      polygon_of.push_back(q);
    }
  }
  for(std::size_t i = 0; i < triangles.size(); ++i)
    for(std::size_t j = i + 1; j < triangles.size(); ++j)
      if(polygon_of[i] != polygon_of[j] && CGAL::do_intersect(triangles[i], triangles[j]))
        return true;
  return false;
}

/// Triangulates a cube with `code` (default face rule) into `out`.
/// `vertex_of(e)` is the global number of the vertex on cube edge e;
/// `decide(p, n, size, apex)` returns whether the polygon with these vertices
/// and normals is fanned around `apex` (`Feature_decision`; the tests use
/// others).  `normals[v]` is the outward unit normal of edge vertex v (a
/// `std::vector<Vector_3d>` or `Edge_vertex_normals`).  Whatever `decide` says, the cube's boundary is the face rule's.
/// The polygons of one cube are disjoint, but a fan around a feature vertex
/// can pierce another polygon of the same cube (seen on fandisk minus a
/// moved copy at 256 cells): then the whole cube keeps the plain
/// triangulation.
template <typename VertexOf, typename Normals, typename Decision>
void triangulate_feature_cube(const Marching_cubes_table& table, unsigned code, const VertexOf& vertex_of,
                              const std::vector<Vector_3d>& points, const Normals& normals,
                              const Decision& decide, Feature_chunk& out)
{
  const Marching_cubes_table::Triangle_range plain = table.triangles(code);
  const unsigned polygons = table.number_of_polygons(code);
  std::size_t first_triangle = 0; // of the current polygon in `plain`
  const std::size_t triangles_before = out.triangles.size(), features_before = out.feature_points.size(),
                    fans_before = out.fans.size();
  std::array<std::size_t, 12> ids;
  std::array<std::size_t, 5> polygon_end; // the end of each polygon's triangles in `out`
  std::array<Vector_3d, 12> p, n;
  for(unsigned q = 0; q < polygons; ++q)
  {
    const Marching_cubes_table::Vertex_range polygon = table.polygon(code, 0, q);
    const std::size_t size = polygon.size();
    for(std::size_t i = 0; i < size; ++i)
    {
      ids[i] = vertex_of(int(polygon[i]));
      p[i] = points[ids[i]];
      n[i] = normals[ids[i]];
    }
    Vector_3d apex;
    const Feature_kind kind = decide(p.data(), n.data(), size, apex);
    if(kind != Feature_kind::NONE)
    {
      CGAL_assertion(out.feature_points.size() < max_chunk_vertices);
      const std::size_t f = feature_vertex_flag | out.feature_points.size();
      out.feature_points.push_back(apex);
      out.feature_kinds.push_back(kind);
      for(std::size_t i = 0; i < size; ++i)
      {
        out.fans.push_back(out.triangles.size());
        out.triangles.push_back(make_triangle<Feature_chunk::Triangle>(ids[i], ids[(i + 1) % size], f));
      }
    }
    else
    {
      // The default rule never needs a centre vertex: the polygon's
      // triangles are the next size - 2 of the table, in order.
      for(std::size_t t = first_triangle; t < first_triangle + size - 2; ++t)
        out.triangles.push_back(make_triangle<Feature_chunk::Triangle>(
            vertex_of(int(plain[t][0])), vertex_of(int(plain[t][1])), vertex_of(int(plain[t][2]))));
    }
    first_triangle += size - 2;
    polygon_end[q] = out.triangles.size();
  }
  if(polygons < 2 || out.feature_points.size() == features_before ||
     !polygons_intersect(out, triangles_before, polygon_end.data(), polygons, points))
    return;
  out.plain.folded += out.feature_points.size() - features_before;
  while(!out.weak_fans.empty() && out.weak_fans.back()[0] >= features_before)
    out.weak_fans.pop_back();
  out.triangles.resize(triangles_before);
  out.feature_points.resize(features_before);
  out.feature_kinds.resize(features_before);
  out.fans.resize(fans_before);
  for(const Marching_cubes_table::Triangle& t : plain)
    out.triangles.push_back(make_triangle<Feature_chunk::Triangle>(vertex_of(int(t[0])), vertex_of(int(t[1])),
                                                                   vertex_of(int(t[2]))));
}

/// Numbers the feature vertices of the chunks after the `points` already
/// there (chunk by chunk, so the result does not depend on the chunking),
/// moves the triangles to `triangles`, flips the face segments between
/// neighbouring fans and returns the feature vertices' kinds.  Throws
/// `Lattice_too_large_error` if the index type of `Triangle` cannot number
/// all the points.
template <typename Triangle, typename Normals>
std::vector<Feature_kind> merge_feature_chunks(std::vector<Feature_chunk>& chunks, std::vector<Vector_3d>& points,
                                               const Normals& normals, std::vector<Triangle>& triangles,
                                               std::vector<Flipped_edge>& flipped)
{
  std::size_t total = 0, features = 0;
  for(const Feature_chunk& c : chunks)
  {
    total += c.triangles.size();
    features += c.feature_points.size();
  }
  const std::size_t vertices = points.size() + features;
  if(vertices != 0 && vertices - 1 > std::size_t((std::numeric_limits<typename Triangle::value_type>::max)()))
    throw Lattice_too_large_error("the output has more vertices than its index type can number");
  // The first chunk's buffer becomes the output when their types agree (all
  // of it with one chunk): no second copy of the triangles to allocate and
  // fill, the memory peak of the path.
  bool first_in_place = false;
  if constexpr(std::is_same<Triangle, Feature_chunk::Triangle>::value)
    if(triangles.empty() && !chunks.empty())
    {
      triangles.swap(chunks.front().triangles);
      first_in_place = true;
    }
  triangles.reserve(first_in_place ? total : triangles.size() + total);
  points.reserve(points.size() + features);
  std::vector<Feature_kind> kinds;
  kinds.reserve(features);
  std::vector<std::size_t> fans;
  for(Feature_chunk& c : chunks)
  {
    const std::size_t vertex_offset = points.size();
    const auto with_features = [&](std::size_t v) {
      return (v & feature_vertex_flag) ? vertex_offset + (v & ~feature_vertex_flag) : v;
    };
    std::size_t triangle_offset = triangles.size();
    if(first_in_place)
    {
      triangle_offset = 0;
      for(Triangle& t : triangles)
        t = make_triangle<Triangle>(with_features(t[0]), with_features(t[1]), with_features(t[2]));
      first_in_place = false;
    }
    else
      for(const Feature_chunk::Triangle& t : c.triangles)
        triangles.push_back(make_triangle<Triangle>(with_features(t[0]), with_features(t[1]), with_features(t[2])));
    points.insert(points.end(), c.feature_points.begin(), c.feature_points.end());
    kinds.insert(kinds.end(), c.feature_kinds.begin(), c.feature_kinds.end());
    for(std::size_t f : c.fans)
      fans.push_back(triangle_offset + f);
    c = Feature_chunk();
  }
  flip_feature_edges(points, normals, triangles, fans, flipped);
  return kinds;
}

} // namespace Marching_cubes_csg

// The named parameters `sharp_features` (default true) and `feature_angle`
// (degrees, default 30), read by the CSG and by the contouring.
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

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_TRIANGULATION_H
