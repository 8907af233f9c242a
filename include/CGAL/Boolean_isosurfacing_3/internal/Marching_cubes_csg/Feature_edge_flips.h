// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_EDGE_FLIPS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_EDGE_FLIPS_H

// The second half of Extended Marching Cubes: after each feature cube is
// fanned around its feature vertex, the feature vertices of two face
// neighbours are joined by flipping the face segment between them.  A fan
// triangle (a, b, f1) of one cube and (b, a, f2) of its neighbour become
// (a, f2, f1) and (f2, b, f1): the crease, which crosses the shared face
// between a and b, is then the edge f1 f2 instead of a saw-tooth through a.
//
// An edge flip on a closed 2-manifold mesh keeps it closed and 2-manifold as
// long as the new edge does not exist yet.  f1 f2 can only come from a flip
// across the face the two cubes share, so it is new unless that face has two
// segments whose both sides are fans of the same two vertices: such flips are
// skipped.  A flip is also skipped when a new triangle would face against
// the crossing normals at a or b (it would fold the surface).

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

/// A crease edge (two vertex indices, the smaller first) with the cosine of
/// its dihedral angle.
struct Flipped_edge
{
  std::size_t v0, v1;
  double cos_dihedral;
};

/// Flips the face segments between face-neighbouring fans.  `fans` lists
/// the triangles of the form (a, b, apex) with `a`, `b` edge points (indices
/// below `normals.size()`) and `apex` a feature vertex.  Appends the new
/// apex-apex edges to `flipped`, in a deterministic order.
template <typename Triangle, typename Normals>
void flip_feature_edges(const std::vector<Vector_3d>& points, const Normals& normals,
                        std::vector<Triangle>& triangles, const std::vector<std::size_t>& fans,
                        std::vector<Flipped_edge>& flipped)
{
  // Sorted as one 64-bit key of the two vertices and the triangle: the
  // order of (low, high, triangle) triples in fewer bytes.
  if(points.size() > (std::size_t(1) << 32))
    throw Lattice_too_large_error("more than 2^32 vertices: too many for the feature flips");
  const auto key = [](std::size_t a, std::size_t b) {
    return (std::uint64_t((std::min)(a, b)) << 32) | std::uint64_t((std::max)(a, b));
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> sides; // (segment, triangle)
  sides.reserve(fans.size());
  for(std::size_t t : fans)
    sides.emplace_back(key(triangles[t][0], triangles[t][1]), t);
  std::sort(sides.begin(), sides.end());
  // Candidate flips: (apexes, triangle t1, triangle t2).
  std::vector<std::array<std::uint64_t, 3>> candidates;
  for(std::size_t i = 0; i + 1 < sides.size(); ++i)
  {
    if(sides[i].first != sides[i + 1].first)
      continue;
    const std::size_t t1 = sides[i].second, t2 = sides[i + 1].second;
    const std::size_t f1 = triangles[t1][2], f2 = triangles[t2][2];
    if(f1 != f2)
      candidates.push_back({{key(f1, f2), t1, t2}});
    ++i;
  }
  std::sort(candidates.begin(), candidates.end());
  for(std::size_t i = 0; i < candidates.size(); ++i)
  {
    const bool repeated = (i > 0 && candidates[i][0] == candidates[i - 1][0]) ||
                          (i + 1 < candidates.size() && candidates[i][0] == candidates[i + 1][0]);
    if(repeated)
      continue;
    const std::size_t t1 = std::size_t(candidates[i][1]), t2 = std::size_t(candidates[i][2]);
    // t1 = (a, b, f1) and t2 = (b, a, f2).
    const std::size_t a = triangles[t1][0], b = triangles[t1][1], f1 = triangles[t1][2], f2 = triangles[t2][2];
    if(triangles[t2][0] != b || triangles[t2][1] != a)
      continue; // not oppositely oriented: cannot happen on a closed, oriented output
    const Vector_3d n1 = triangle_normal(points[a], points[f2], points[f1]);
    const Vector_3d n2 = triangle_normal(points[f2], points[b], points[f1]);
    const Vector_3d na = normals[a];
    const Vector_3d nb = normals[b];
    const Vector_3d nab{{na[0] + nb[0], na[1] + nb[1], na[2] + nb[2]}};
    if(!(dot3(n1, na) > 0 && dot3(n2, nb) > 0 && dot3(n1, nab) > 0 && dot3(n2, nab) > 0))
      continue;
    if(!(triangle_quality(points[a], points[f2], points[f1]) > degenerate_quality &&
         triangle_quality(points[f2], points[b], points[f1]) > degenerate_quality))
      continue;
    triangles[t1] = make_triangle<Triangle>(a, f2, f1);
    triangles[t2] = make_triangle<Triangle>(f2, b, f1);
    const double l1 = std::sqrt(dot3(n1, n1)), l2 = std::sqrt(dot3(n2, n2));
    flipped.push_back(Flipped_edge{(std::min)(f1, f2), (std::max)(f1, f2), dot3(n1, n2) / (l1 * l2)});
  }
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_FEATURE_EDGE_FLIPS_H
