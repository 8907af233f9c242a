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
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_edge_flips.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
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
/// of its two sides faces the outside.
inline Vector_3d outward_normal(const Triangle_tangent& t, int axis, bool increasing)
{
  const bool flip = (t.sign[axis] > 0) != increasing;
  Vector_3d n = t.normal;
  if(flip)
    for(int a = 0; a < 3; ++a)
      n[a] = -n[a];
  return n;
}

/// Marks feature vertices in the per-chunk triangles before they get their
/// global number.
constexpr std::size_t feature_vertex_flag = ~((std::numeric_limits<std::size_t>::max)() >> 1);

/// Polygons whose normals disagree but that keep the plain triangulation:
/// no feature point in the cube, or a fan that would fold.
struct Plain_feature_counts
{
  std::size_t no_point = 0, folded = 0;
};

/// What the triangulation of a range of cubes produces.
struct Feature_chunk
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<Vector_3d> feature_points;
  std::vector<Feature_kind> feature_kinds;
  std::vector<std::size_t> fans; // fan triangles, indices into `triangles`
  Plain_feature_counts plain;
};

/// The feature decision of a polygon of the cube [low, high]: its feature
/// vertex, if it has one and the fan around it does not fold.  Counts the
/// polygons whose normals disagree but that keep the plain triangulation.
class Feature_decision
{
public:
  Feature_decision(const Vector_3d& low, const Vector_3d& high, const Feature_settings& settings,
                   Plain_feature_counts& counts)
    : m_low(low), m_high(high), m_settings(settings), m_counts(counts)
  {}

  Feature_kind operator()(const Vector_3d* p, const Vector_3d* n, std::size_t size, Vector_3d& apex) const
  {
    if(!has_feature(n, size, m_settings))
      return Feature_kind::NONE;
    // A candidate whose fan would fold is refused and the next lower rank
    // tried (a "corner" of three nearly coplanar facets of a curved surface
    // is often just a crease).
    bool folded = false;
    const auto unfolded = [&](const Vector_3d& x) {
      const bool ok = fan_is_unfolded(p, n, size, x);
      folded = folded || !ok;
      return ok;
    };
    const Feature_kind kind = feature_vertex(p, n, size, m_low, m_high, m_settings, unfolded, apex);
    if(kind != Feature_kind::NONE)
      return kind;
    if(folded)
      ++m_counts.folded;
    else
      ++m_counts.no_point;
    return Feature_kind::NONE;
  }

private:
  Vector_3d m_low, m_high;
  const Feature_settings& m_settings;
  Plain_feature_counts& m_counts;
};

/// Triangulates a cube with `code` (default face rule) into `out`.
/// `vertex_of(e)` is the global number of the vertex on cube edge e;
/// `decide(p, n, size, apex)` returns whether the polygon with these vertices
/// and normals is fanned around `apex` (`Feature_decision`; the tests use
/// others).  Whatever `decide` says, the cube's boundary is the face rule's.
template <typename VertexOf, typename Decision>
void triangulate_feature_cube(const Marching_cubes_table& table, unsigned code, const VertexOf& vertex_of,
                              const std::vector<Vector_3d>& points, const std::vector<Vector_3d>& normals,
                              const Decision& decide, Feature_chunk& out)
{
  const Marching_cubes_table::Triangle_range plain = table.triangles(code);
  const unsigned polygons = table.number_of_polygons(code);
  std::size_t first_triangle = 0; // of the current polygon in `plain`
  std::array<std::size_t, 12> ids;
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
      const std::size_t f = feature_vertex_flag | out.feature_points.size();
      out.feature_points.push_back(apex);
      out.feature_kinds.push_back(kind);
      for(std::size_t i = 0; i < size; ++i)
      {
        out.fans.push_back(out.triangles.size());
        out.triangles.push_back({{ids[i], ids[(i + 1) % size], f}});
      }
    }
    else
    {
      // The default rule never needs a centre vertex: the polygon's
      // triangles are the next size - 2 of the table, in order.
      for(std::size_t t = first_triangle; t < first_triangle + size - 2; ++t)
        out.triangles.push_back({{vertex_of(int(plain[t][0])), vertex_of(int(plain[t][1])), vertex_of(int(plain[t][2]))}});
    }
    first_triangle += size - 2;
  }
}

/// Numbers the feature vertices of the chunks after the `points` already
/// there (chunk by chunk, so the result does not depend on the chunking),
/// moves the triangles to `triangles`, flips the face segments between
/// neighbouring fans and returns the feature vertices' kinds.
inline std::vector<Feature_kind> merge_feature_chunks(std::vector<Feature_chunk>& chunks,
                                                      std::vector<Vector_3d>& points,
                                                      const std::vector<Vector_3d>& normals,
                                                      std::vector<std::array<std::size_t, 3>>& triangles,
                                                      std::vector<Flipped_edge>& flipped)
{
  std::size_t total = 0, features = 0;
  for(const Feature_chunk& c : chunks)
  {
    total += c.triangles.size();
    features += c.feature_points.size();
  }
  triangles.reserve(triangles.size() + total);
  points.reserve(points.size() + features);
  std::vector<Feature_kind> kinds;
  kinds.reserve(features);
  std::vector<std::size_t> fans;
  for(Feature_chunk& c : chunks)
  {
    const std::size_t vertex_offset = points.size(), triangle_offset = triangles.size();
    for(std::array<std::size_t, 3> t : c.triangles)
    {
      for(std::size_t& v : t)
        if(v & feature_vertex_flag)
          v = vertex_offset + (v & ~feature_vertex_flag);
      triangles.push_back(t);
    }
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
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_TRIANGULATION_H
