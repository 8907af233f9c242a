// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CUBE_RULES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CUBE_RULES_H

// The per-cube rules of the contouring: lattice keys, cube codes, the
// asymptotic decider, the jump test, the default cell size.

#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Boolean_isosurfacing {

namespace internal {

// Lattice point (i, j, k), each < 2^20, packed as i | j << 20 | k << 40; a
// lattice edge as 4 * point + axis.  Sorting cube keys orders cubes by k, then
// j, then i: the output order.
constexpr unsigned lattice_bits = 20;
constexpr std::int64_t lattice_limit = std::int64_t(1) << lattice_bits;

inline std::uint64_t lattice_key(std::int64_t i, std::int64_t j, std::int64_t k)
{
  return std::uint64_t(i) | (std::uint64_t(j) << lattice_bits) | (std::uint64_t(k) << (2 * lattice_bits));
}

inline std::array<std::int64_t, 3> lattice_index(std::uint64_t key)
{
  const std::uint64_t mask = std::uint64_t(lattice_limit - 1);
  return {{std::int64_t(key & mask), std::int64_t((key >> lattice_bits) & mask),
           std::int64_t(key >> (2 * lattice_bits))}};
}

/// The seed's code: bit k = f(p_k) >= 0 (the corner is outside / above).
inline unsigned seed_cube_code(const std::array<double, 8>& values)
{
  unsigned code = 0;
  for(int k = 0; k < 8; ++k)
    if(values[k] >= 0.0)
      code |= 1u << k;
  return code;
}

/// The table's code: bit k = corner k inside (f < 0) = the seed's code complemented.
inline unsigned inside_cube_code(const std::array<double, 8>& values)
{
  return ~seed_cube_code(values) & 0xFFu;
}

/// The seed's interpolation parameter on edge (v_i, v_j):  t = -f_i / (f_j - f_i).
/// \pre f_i and f_j lie on different sides (one < 0, the other >= 0).
inline double edge_parameter(double f_i, double f_j) { return -f_i / (f_j - f_i); }

/// The smallest distance, in edge lengths, from an output vertex to a lattice
/// point: `vertex_edge_parameter()` keeps t in [min_vertex_edge_parameter,
/// 1 - min_vertex_edge_parameter].
constexpr double min_vertex_edge_parameter = 1e-3;

/// Where the vertex on edge (v_i, v_j) goes: `edge_parameter()`, kept a
/// thousandth of the edge away from its ends.  Where f vanishes at a lattice
/// point (to rounding: samples of a flat face in a lattice plane, as CGAL's
/// cube.pwn on its bounding box), every edge from that point to the other
/// side put its vertex on the point itself: distinct vertices at one
/// position, zero-area triangles, and triangles that touch away from their
/// shared vertices (2,649 such pairs on cube.pwn).  The vertices stay on
/// their own edges, at most r / 1000 from where the seed puts them.
inline double vertex_edge_parameter(double f_i, double f_j)
{
  const double t = edge_parameter(f_i, f_j);
  return (std::min)((std::max)(t, min_vertex_edge_parameter), 1 - min_vertex_edge_parameter);
}

/// Asymptotic decider: whether the inside corners of ambiguous face `face`
/// are connected, from the face's 4 values only (the same double operations in
/// both cubes that share the face, so they agree).
inline bool asymptotic_decider_joins_inside(const std::array<double, 8>& values, int face)
{
  const std::array<int, 4> c = cube_face_corners(face);
  const double diagonal_02 = values[c[0]] * values[c[2]];
  const double diagonal_13 = values[c[1]] * values[c[3]];
  const bool inside_02 = values[c[0]] < 0.0;
  return inside_02 ? (diagonal_02 > diagonal_13) : (diagonal_13 > diagonal_02);
}

/// Whether a sign-changing edge of the cube has |f_j - f_i| > max_jump.
inline bool has_jump_edge(const std::array<double, 8>& values, unsigned inside_code, double max_jump)
{
  for(int e = 0; e < 12; ++e)
    if(is_sign_changing_edge(inside_code, e))
    {
      const std::array<int, 2> c = cube_edge_corners(e);
      if(std::abs(values[c[1]] - values[c[0]]) > max_jump)
        return true;
    }
  return false;
}

/// The join mask of a cube (bit f set = on ambiguous face f the inside corners are joined).
inline unsigned asymptotic_decider_mask(const std::array<double, 8>& values, unsigned inside_code)
{
  unsigned mask = 0;
  const unsigned ambiguous = ambiguous_face_mask(inside_code);
  for(int f = 0; f < 6; ++f)
    if(((ambiguous >> f) & 1u) && asymptotic_decider_joins_inside(values, f))
      mask |= 1u << f;
  return mask;
}

/// The field's `default_cell_size()` if it has one, else sampling_density() / 3.
template <typename Field, typename = void>
struct Has_default_cell_size : std::false_type
{};
template <typename Field>
struct Has_default_cell_size<Field, std::void_t<decltype(std::declval<const Field&>().default_cell_size())>>
  : std::true_type
{};

template <typename Field>
double default_cell_size(const Field& field)
{
  if constexpr(Has_default_cell_size<Field>::value)
    return double(field.default_cell_size());
  else
    return double(field.sampling_density()) / 3;
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_CUBE_RULES_H
