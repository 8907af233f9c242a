// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_GRID_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_GRID_3_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/number_utils.h>
#include <CGAL/enum.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A regular grid of `nx * ny * nz` vertices whose cubes are each split into
/// six tetrahedra around the main diagonal from the cube's lowest corner to
/// its highest (the Kuhn / Freudenthal triangulation).  Every cube face is
/// then split along the diagonal from its lowest to its highest corner, from
/// both sides, so the tetrahedra of neighbouring cubes are conforming.
///
/// The tetrahedra are *enumerated*, never stored: memory is O(1).
/// `127^3` cubes give the seed's 12,290,298 tetrahedra.
///
/// Vertex `(i, j, k)` has index `i + nx * (j + ny * k)` and position
/// `origin + (i * dx, j * dy, k * dz)`.
///
/// \tparam GeomTraits a model of `Kernel` (only `Point_3` and its constructor are used)
///
/// \cgalModels{TetrahedralDomain_3}
template <typename GeomTraits>
class Tetrahedral_grid_3
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef std::array<std::size_t, 4> Tetrahedron;

  /// No neighbour: the face is on the boundary of the grid.
  static constexpr std::size_t no_vertex = (std::numeric_limits<std::size_t>::max)();

  /// \throws Invalid_input_error if a count is below 2 or a spacing is not positive and finite.
  Tetrahedral_grid_3(const Point_3& origin, const std::array<double, 3>& spacing,
                     const std::array<std::size_t, 3>& vertex_counts)
    : m_origin(origin), m_spacing(spacing), m_n(vertex_counts)
  {
    for(int a = 0; a < 3; ++a)
    {
      if(m_n[a] < 2)
        throw Invalid_input_error("a tetrahedral grid needs at least 2 vertices along each axis, got " +
                                  std::to_string(m_n[a]) + " along axis " + std::to_string(a));
      if(!(std::isfinite(m_spacing[a]) && m_spacing[a] > 0))
        throw Invalid_input_error("the grid spacing must be positive and finite");
    }
    if(m_n[0] > (std::size_t(1) << 21) || m_n[1] > (std::size_t(1) << 21) || m_n[2] > (std::size_t(1) << 21))
      throw Lattice_too_large_error("at most 2^21 grid vertices per axis are supported");
    m_origin_coords = {CGAL::to_double(origin.x()), CGAL::to_double(origin.y()), CGAL::to_double(origin.z())};
  }

  /// The grid spanning the box `[min, max]` with `vertex_counts` vertices per axis.
  static Tetrahedral_grid_3 spanning(const Point_3& min, const Point_3& max,
                                     const std::array<std::size_t, 3>& vertex_counts)
  {
    std::array<double, 3> lo{CGAL::to_double(min.x()), CGAL::to_double(min.y()), CGAL::to_double(min.z())};
    std::array<double, 3> hi{CGAL::to_double(max.x()), CGAL::to_double(max.y()), CGAL::to_double(max.z())};
    std::array<double, 3> h;
    for(int a = 0; a < 3; ++a)
      h[a] = vertex_counts[a] > 1 ? (hi[a] - lo[a]) / double(vertex_counts[a] - 1) : 0.;
    return Tetrahedral_grid_3(min, h, vertex_counts);
  }

  const std::array<std::size_t, 3>& vertex_counts() const { return m_n; }
  const std::array<double, 3>& spacing() const { return m_spacing; }
  const Point_3& origin() const { return m_origin; }

  std::size_t number_of_vertices() const { return m_n[0] * m_n[1] * m_n[2]; }
  std::size_t number_of_cubes() const { return (m_n[0] - 1) * (m_n[1] - 1) * (m_n[2] - 1); }
  std::size_t number_of_tetrahedra() const { return 6 * number_of_cubes(); }

  std::size_t vertex_index(std::size_t i, std::size_t j, std::size_t k) const
  {
    return i + m_n[0] * (j + m_n[1] * k);
  }

  std::array<std::size_t, 3> vertex_coordinates(std::size_t v) const
  {
    return {v % m_n[0], (v / m_n[0]) % m_n[1], v / (m_n[0] * m_n[1])};
  }

  /// The position of vertex `(i, j, k)`, computed as `origin + i * dx` per axis.
  std::array<double, 3> position(std::size_t v) const
  {
    const std::array<std::size_t, 3> c = vertex_coordinates(v);
    return {m_origin_coords[0] + double(c[0]) * m_spacing[0], m_origin_coords[1] + double(c[1]) * m_spacing[1],
            m_origin_coords[2] + double(c[2]) * m_spacing[2]};
  }

  Point_3 point(std::size_t v) const
  {
    const std::array<double, 3> p = position(v);
    return Point_3(p[0], p[1], p[2]);
  }

  /// Axis permutation of the Kuhn tetrahedron `t` (0..5) of a cube: its
  /// corners are `c`, `c + e[p0]`, `c + e[p0] + e[p1]`, `c + (1,1,1)`.
  static const std::array<int, 3>& kuhn_permutation(int t)
  {
    static const std::array<int, 3> permutations[6] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                                       {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    return permutations[t];
  }

  /// Tetrahedra 0..2 are even permutations (positively oriented in Kuhn
  /// order), 3..5 odd ones: their Kuhn corners 1 and 2 are swapped in
  /// `tetrahedron()` so that every tetrahedron is positively oriented.
  static bool is_odd(int t) { return t >= 3; }

  /// Local corner `l` of `tetrahedron(.., t)` is Kuhn corner `kuhn_corner(t, l)`.
  static int kuhn_corner(int t, int l)
  {
    return (is_odd(t) && (l == 1 || l == 2)) ? 3 - l : l;
  }

  /// Integer offsets of the Kuhn corners of tetrahedron `t` from the cube's lowest corner.
  static std::array<std::array<int, 3>, 4> kuhn_offsets(int t)
  {
    const std::array<int, 3>& p = kuhn_permutation(t);
    std::array<std::array<int, 3>, 4> o{};
    o[1] = o[0];
    o[1][p[0]] += 1;
    o[2] = o[1];
    o[2][p[1]] += 1;
    o[3] = {1, 1, 1};
    return o;
  }

  /// The corners of tetrahedron `t` (0..5) of cube `(i, j, k)`, positively oriented.
  Tetrahedron tetrahedron(std::size_t i, std::size_t j, std::size_t k, int t) const
  {
    const std::array<std::array<int, 3>, 4> o = kuhn_offsets(t);
    Tetrahedron tet;
    for(int l = 0; l < 4; ++l)
    {
      const std::array<int, 3>& d = o[kuhn_corner(t, l)];
      tet[l] = vertex_index(i + d[0], j + d[1], k + d[2]);
    }
    return tet;
  }

  /// The corner opposite local corner `l` in the tetrahedron that shares with
  /// tetrahedron `t` of cube `(i, j, k)` the face opposite `l`, or `no_vertex`
  /// on the boundary of the grid.  Kuhn pivot rule: the new corner is
  /// `v[m-1] + v[m+1] - v[m]` (Kuhn indices cyclic, `v[-1] = v[3]`, `v[4] = v[0]`).
  std::size_t neighbor_apex(std::size_t i, std::size_t j, std::size_t k, int t, int l) const
  {
    const std::array<std::array<int, 3>, 4> o = kuhn_offsets(t);
    const int m = kuhn_corner(t, l);
    const std::array<int, 3>& prev = o[(m + 3) % 4];
    const std::array<int, 3>& next = o[(m + 1) % 4];
    const std::array<int, 3>& self = o[m];
    const std::array<std::size_t, 3> base{i, j, k};
    std::array<std::size_t, 3> c;
    for(int a = 0; a < 3; ++a)
    {
      const long long x = (long long)base[a] + prev[a] + next[a] - self[a];
      if(x < 0 || x >= (long long)m_n[a])
        return no_vertex;
      c[a] = std::size_t(x);
    }
    return vertex_index(c[0], c[1], c[2]);
  }

private:
  Point_3 m_origin;
  std::array<double, 3> m_origin_coords;
  std::array<double, 3> m_spacing;
  std::array<std::size_t, 3> m_n;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_GRID_3_H
