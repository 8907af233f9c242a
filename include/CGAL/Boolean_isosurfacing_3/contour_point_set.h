// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H
#define CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H

// Contouring oriented point samples (the contour-tracing assignment, [ContourTracing] in the manual's references):
// Hoppe's tangent-plane signed distance (Tangent_plane_signed_distance_3.h)
// sampled at the vertices of a regular lattice and contoured with the
// package's watertight Marching Cubes table, refined on ambiguous faces by the
// asymptotic decider.  Only cubes the surface crosses are visited.
//
// Conventions (doc/Boolean_isosurfacing_3/contouring.md):
//  * f < 0 inside (normals point out of the solid).  The seed's bit is
//    fb[k] = f(p_k) >= 0 ("above the surface" = OUTSIDE); the table's code has
//    bit k = corner k INSIDE, so  table code = ~seed code & 0xFF.  f == 0 is
//    outside, as in the seed.  Corner k sits at offset (k&1, (k>>1)&1, (k>>2)&1).
//  * The vertex on lattice edge (v_i, v_j), v_i the lower end, is
//    p = v_i + t (v_j - v_i) with t = -f(v_i) / (f(v_j) - f(v_i)) exactly as in
//    the seed; it is computed once per global lattice edge and shared by the
//    (up to 4) cubes around the edge: vertices are welded by edge id.
//  * Asymptotic decider (Nielson & Hamann 1991): on a face whose inside
//    corners are one diagonal, the bilinear interpolant's saddle value is
//    (f_a f_c - f_b f_d) / (f_a + f_c - f_b - f_d) for the diagonals (a, c),
//    (b, d); the inside corners are joined iff the saddle is inside (< 0),
//    i.e. iff f_in1 * f_in2 > f_out1 * f_out2.  It reads only the face's 4
//    values, so both cubes on a face take the same decision and the output
//    stays closed and 2-manifold (Marching_cubes_table.h).
//  * Triangles are oriented outward; the seed's normal cross(p1-p0, p2-p0)
//    points out of the object.

#include <CGAL/Boolean_isosurfacing_3/Algorithm_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Bbox_3.h>
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
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// What a contouring run did; all counts are exact, times are wall clock.
/// `number_of_vertices`, `number_of_faces` (triangles), `seconds` and
/// `warnings` (holes left or repaired, border exits) are those of
/// `Algorithm_statistics`.
struct Contouring_statistics : Algorithm_statistics
{
  double cell_size = 0;                          ///< lattice spacing r
  std::array<double, 3> origin{{0, 0, 0}};       ///< lattice point (0,0,0)
  std::array<std::size_t, 3> number_of_cells{{0, 0, 0}}; ///< cells of the lattice along each axis
  std::size_t field_evaluations = 0;             ///< lattice points where f was evaluated
  std::size_t undefined_points = 0;              ///< ... of which f was undefined
  std::size_t visited_cubes = 0;                 ///< cubes examined by the traversal
  std::size_t surface_cubes = 0;                 ///< cubes that produced triangles
  std::size_t skipped_cubes = 0;                 ///< crossed cubes skipped: an undefined corner
  std::size_t border_exits = 0;                  ///< crossed faces on the lattice border (holes)
  std::size_t discontinuous_cubes = 0;           ///< skipped: f jumps across a sign-changing edge
  std::size_t ambiguous_faces = 0;               ///< (counted once per cube side)
  std::size_t joined_faces = 0;                  ///< ... where the decider joined the inside
  std::size_t centre_vertices = 0;               ///< polygon centre vertices added
  std::size_t removed_closed_components = 0;     ///< bubbles smaller than minimum_closed_component_size
  std::size_t split_vertices = 0;                ///< vertices pinched between two holes, duplicated
  std::size_t filled_holes = 0;                  ///< border loops smaller than maximum_hole_size, triangulated
  std::size_t walk_seeds = 0;                    ///< crossed cubes reached by walking down |f| from a sample
  /// No triangle came out: f changes sign in no cube reached from the samples
  /// (or only in skipped ones).  `contour_point_set` throws `Empty_contour_error`.
  bool empty_output = false;
  double seconds_field = 0;                      ///< evaluating f at lattice points
  double seconds_contouring = 0;                 ///< traversal + triangles, without field time
  std::size_t number_of_triangles = 0;           ///< \deprecated the same as `number_of_faces`
  double field_seconds = 0;                      ///< \deprecated the same as `seconds_field`
  double contouring_seconds = 0;                 ///< \deprecated the same as `seconds_contouring`
};

/// \ingroup PkgBooleanIsosurfacing3Ref
/// \deprecated the former name of `Contouring_statistics`.
typedef Contouring_statistics Contouring_report;

/// Thrown by `contour_point_set` when the contour has no triangle: an empty
/// mesh is never a silent success.  `report()` tells what the traversal saw.
class Empty_contour_error : public std::runtime_error
{
public:
  explicit Empty_contour_error(const Contouring_report& report)
    : std::runtime_error(message(report)), m_report(report)
  {}
  const Contouring_report& report() const { return m_report; }

private:
  static std::string message(const Contouring_report& report)
  {
    return "the contour is empty: f changes sign in no usable lattice cube (cell " + std::to_string(report.cell_size) +
           ", " + std::to_string(report.visited_cubes) + " cubes visited, " + std::to_string(report.skipped_cubes) +
           " skipped for an undefined corner, " + std::to_string(report.discontinuous_cubes) +
           " for a jump of f, " + std::to_string(report.removed_closed_components) +
           " closed pieces smaller than rho removed)";
  }
  Contouring_report m_report;
};

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

/// Removes, from the triangles appended from `first_triangle` on (whose
/// vertices are the points from `first_vertex` on), every connected component
/// that is closed (each of its edges in exactly 2 of its triangles) and whose
/// bounding box has a diagonal below `min_diagonal`.  Returns how many.
template <typename PointOutRange, typename TriangleRange>
std::size_t remove_small_closed_components(PointOutRange& points, TriangleRange& triangles, std::size_t first_vertex,
                                           std::size_t first_triangle, double min_diagonal)
{
  const std::size_t nv = points.size() - first_vertex;
  std::vector<std::size_t> parent(nv);
  for(std::size_t v = 0; v < nv; ++v)
    parent[v] = v;
  auto find = [&parent](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    for(int i = 1; i < 3; ++i)
    {
      const std::size_t a = find(std::size_t(triangles[t][0]) - first_vertex);
      const std::size_t b = find(std::size_t(triangles[t][i]) - first_vertex);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  std::vector<std::array<double, 6>> box(nv, {{std::numeric_limits<double>::infinity(),
                                              std::numeric_limits<double>::infinity(),
                                              std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity()}});
  for(std::size_t v = 0; v < nv; ++v)
  {
    std::array<double, 6>& b = box[find(v)];
    for(int a = 0; a < 3; ++a)
    {
      const double x = CGAL::to_double(points[first_vertex + v][a]);
      b[a] = (std::min)(b[a], x);
      b[3 + a] = (std::max)(b[3 + a], x);
    }
  }
  std::vector<char> small(nv, 0);
  bool any = false;
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] == v)
    {
      const std::array<double, 6>& b = box[v];
      const double d2 = (b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) + (b[5] - b[2]) * (b[5] - b[2]);
      small[v] = d2 < min_diagonal * min_diagonal;
      any = any || small[v];
    }
  if(!any)
    return 0;
  // Closedness of the small components: their undirected edges, sorted.
  std::vector<std::array<std::size_t, 3>> edges; // root, lower vertex, upper vertex
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
  {
    const std::size_t root = find(std::size_t(triangles[t][0]) - first_vertex);
    if(small[root])
      for(int i = 0; i < 3; ++i)
      {
        const std::size_t a = std::size_t(triangles[t][i]), b = std::size_t(triangles[t][(i + 1) % 3]);
        edges.push_back({{root, (std::min)(a, b), (std::max)(a, b)}});
      }
  }
  std::sort(edges.begin(), edges.end());
  for(std::size_t e = 0; e < edges.size();)
  {
    std::size_t end = e + 1;
    while(end < edges.size() && edges[end] == edges[e])
      ++end;
    if(end - e != 2)
      small[edges[e][0]] = 0; // has a border or non-manifold edge: not a bubble
    e = end;
  }
  std::size_t removed = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(parent[v] == v && small[v])
      ++removed;
  if(removed == 0)
    return 0;
  // Compact, keeping the order of what stays.
  std::vector<std::size_t> new_index(nv, std::size_t(-1));
  std::vector<typename PointOutRange::value_type> kept_points;
  for(std::size_t v = 0; v < nv; ++v)
    if(!small[find(v)])
    {
      new_index[v] = first_vertex + kept_points.size();
      kept_points.push_back(points[first_vertex + v]);
    }
  std::vector<typename TriangleRange::value_type> kept_triangles;
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    if(!small[find(std::size_t(triangles[t][0]) - first_vertex)])
    {
      const auto& tri = triangles[t];
      kept_triangles.push_back(typename TriangleRange::value_type{new_index[std::size_t(tri[0]) - first_vertex],
                                                                  new_index[std::size_t(tri[1]) - first_vertex],
                                                                  new_index[std::size_t(tri[2]) - first_vertex]});
    }
  points.erase(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  points.insert(points.end(), kept_points.begin(), kept_points.end());
  triangles.erase(triangles.begin() + std::ptrdiff_t(first_triangle), triangles.end());
  triangles.insert(triangles.end(), kept_triangles.begin(), kept_triangles.end());
  return removed;
}

/// Repairs the holes that skipped cubes leave (issue 18), on the triangles
/// appended from `first_triangle` on (vertices from `first_vertex` on):
///  1. vertices pinched between two holes (two skipped cubes diagonal around
///     a lattice edge) are split (PMP::orient_polygon_soup), so the soup is an
///     oriented 2-manifold with border;
///  2. each border loop whose bounding box has a diagonal of at most
///     `max_hole_diagonal` is filled (PMP::triangulate_hole, no new vertex).
/// Larger loops (the border of an open sample, an unsampled region wider
/// than the hole limit) stay.  Returns (vertices split, holes filled).
template <typename PointOutRange, typename TriangleRange>
std::pair<std::size_t, std::size_t> close_small_holes(PointOutRange& points, TriangleRange& triangles,
                                                      std::size_t first_vertex, std::size_t first_triangle,
                                                      double max_hole_diagonal)
{
  typedef typename std::decay<decltype(points[0])>::type Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point_3> soup_points(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  std::vector<std::array<std::size_t, 3>> soup;
  soup.reserve(triangles.size() - first_triangle);
  for(std::size_t t = first_triangle; t < triangles.size(); ++t)
    soup.push_back({{std::size_t(triangles[t][0]) - first_vertex, std::size_t(triangles[t][1]) - first_vertex,
                     std::size_t(triangles[t][2]) - first_vertex}});
  const std::size_t before = soup_points.size();
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup))
    PMP::orient_polygon_soup(soup_points, soup);
  const std::size_t split = soup_points.size() - before;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, soup, mesh);
  std::vector<typename Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  // A loop is a hole of a surface only if its component is larger than the
  // loop limit: a small open piece (one cube's triangles) bounded by the loop
  // would become a doubled patch.
  auto component = mesh.template add_property_map<typename Mesh::Face_index, std::size_t>("f:biso_cc", 0).first;
  const std::size_t number_of_components = PMP::connected_components(mesh, component);
  std::vector<Bbox_3> component_box(number_of_components);
  for(const auto f : mesh.faces())
    for(const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      component_box[component[f]] += mesh.point(v).bbox();
  std::size_t filled = 0;
  for(const auto h : cycles)
  {
    if(!mesh.is_border(h))
      continue;
    const Bbox_3& piece = component_box[component[mesh.face(mesh.opposite(h))]];
    if(CGAL::square(piece.xmax() - piece.xmin()) + CGAL::square(piece.ymax() - piece.ymin()) +
         CGAL::square(piece.zmax() - piece.zmin()) <= max_hole_diagonal * max_hole_diagonal)
      continue;
    Bbox_3 box;
    for(const auto g : CGAL::halfedges_around_face(h, mesh))
      box += mesh.point(mesh.target(g)).bbox();
    const double d2 = CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                      CGAL::square(box.zmax() - box.zmin());
    if(!(d2 <= max_hole_diagonal * max_hole_diagonal))
      continue;
    PMP::triangulate_hole(mesh, h, CGAL::Emptyset_iterator());
    ++filled;
  }
  // Back to the soup: vertex order is kept (the hole filling adds no vertex).
  std::vector<Point_3> new_points;
  std::vector<std::array<std::size_t, 3>> new_soup;
  mesh.remove_property_map(component);
  PMP::polygon_mesh_to_polygon_soup(mesh, new_points, new_soup);
  points.erase(points.begin() + std::ptrdiff_t(first_vertex), points.end());
  for(const Point_3& p : new_points)
    points.push_back(p);
  triangles.erase(triangles.begin() + std::ptrdiff_t(first_triangle), triangles.end());
  for(const auto& t : new_soup)
    triangles.push_back(typename TriangleRange::value_type{t[0] + first_vertex, t[1] + first_vertex,
                                                           t[2] + first_vertex});
  return {split, filled};
}

} // namespace internal

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

// The contouring on `lattice` (appends to the outputs).
template <typename ContouringField_3, typename PointOutRange, typename TriangleRange, typename NamedParameters>
Contouring_statistics contour_on_lattice(const Contouring_lattice& lattice, const ContouringField_3& field,
                                         PointOutRange& out_points, TriangleRange& out_triangles,
                                         const NamedParameters& np)
{
  typedef typename ContouringField_3::Point_3 Point_3;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto total_start = std::chrono::steady_clock::now();
  const Progress progress = progress_of(np);
  Contouring_statistics report;
  const auto& samples = field.points();
  const double r = lattice.r;
  const std::array<std::int64_t, 3> cells = lattice.cells;
  report.origin = lattice.origin;
  for(int a = 0; a < 3; ++a)
    report.number_of_cells[a] = std::size_t(cells[a]);
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
  const double max_jump = choose_parameter(get_parameter(np, internal_np::maximum_jump),
                                           3 * r + 2 * field.noise_level());
  const std::array<double, 3> origin = report.origin;
  // One formula for every lattice point, so shared corners get identical coordinates.
  auto lattice_point = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return Point_3(origin[0] + double(i) * r, origin[1] + double(j) * r, origin[2] + double(k) * r);
  };

  // ---- field at lattice points, cached (NaN = undefined) -------------------
  std::unordered_map<std::uint64_t, double> value_cache;
  value_cache.reserve(4 * samples.size());
  double field_seconds = 0;
  auto value_at = [&](std::int64_t i, std::int64_t j, std::int64_t k) -> double {
    const std::uint64_t key = internal::lattice_key(i, j, k);
    auto found = value_cache.find(key);
    if(found != value_cache.end())
      return found->second;
    const auto start = std::chrono::steady_clock::now();
    const std::optional<double> f = field(lattice_point(i, j, k));
    field_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++report.field_evaluations;
    double v = std::numeric_limits<double>::quiet_NaN();
    if(f)
      v = *f;
    else
      ++report.undefined_points;
    value_cache.emplace(key, v);
    return v;
  };
  auto cube_values = [&](const std::array<std::int64_t, 3>& c, std::array<double, 8>& values) {
    bool defined = true;
    for(int k = 0; k < 8; ++k)
    {
      values[k] = value_at(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1));
      defined = defined && !std::isnan(values[k]);
    }
    return defined;
  };

  // ---- traversal: seeds, then flood through crossed faces ----------------
  // A cube is "crossed" when its 8 corners are defined, not all of one sign,
  // and f does not jump along a sign-changing edge.
  enum class Cube_state { undefined, undefined_crossed, uncrossed, jump, crossed };
  auto cube_state = [&](const std::array<std::int64_t, 3>& c, std::array<double, 8>& v) {
    const bool defined = cube_values(c, v);
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
  };
  auto cube_of = [&](const std::array<double, 3>& p) {
    std::array<std::int64_t, 3> c;
    for(int a = 0; a < 3; ++a)
      c[a] = (std::min)(cells[a] - 1, (std::max)(std::int64_t(0), std::int64_t(std::floor((p[a] - origin[a]) / r))));
    return c;
  };
  std::vector<std::uint64_t> stack;
  std::unordered_set<std::uint64_t> visited;
  visited.reserve(4 * samples.size());
  std::vector<std::uint64_t> surface_cubes;
  std::array<double, 8> values;
  auto flood = [&]() {
    while(!stack.empty())
    {
      const std::uint64_t key = stack.back();
      stack.pop_back();
      ++report.visited_cubes;
      // The traversal's extent is unknown beforehand: report 0 as a chance to cancel.
      if((report.visited_cubes & 0xFFFF) == 0)
        progress.report(0);
      const std::array<std::int64_t, 3> c = internal::lattice_index(key);
      const Cube_state state = cube_state(c, values);
      if(state == Cube_state::undefined_crossed)
        ++report.skipped_cubes; // Hoppe: a cube with an undefined corner is skipped
      else if(state == Cube_state::jump)
        ++report.discontinuous_cubes; // a jump of f between two planes, not a surface
      if(state != Cube_state::crossed)
        continue;
      const unsigned code = internal::inside_cube_code(values);
      surface_cubes.push_back(key);
      for(int f = 0; f < 6; ++f)
      {
        const std::array<int, 4> corners = cube_face_corners(f);
        const bool first = is_inside_corner(code, corners[0]);
        bool crossed = false;
        for(int i = 1; i < 4; ++i)
          crossed = crossed || (is_inside_corner(code, corners[i]) != first);
        if(!crossed)
          continue;
        std::array<std::int64_t, 3> n = c;
        n[cube_face_axis(f)] += cube_face_side(f) ? 1 : -1;
        const int a = cube_face_axis(f);
        if(n[a] < 0 || n[a] >= cells[a])
        {
          ++report.border_exits; // the default margin prevents this; it leaves a hole
          continue;
        }
        const std::uint64_t neighbour = internal::lattice_key(n[0], n[1], n[2]);
        if(visited.insert(neighbour).second)
          stack.push_back(neighbour);
      }
    }
  };
  // Seeds, first pass: the cubes that hold a sample.  With a cell of about
  // the sample spacing f changes sign in most of them.
  std::vector<std::array<double, 3>> sample_xyz(samples.size());
  for(std::size_t s = 0; s < samples.size(); ++s)
  {
    for(int a = 0; a < 3; ++a)
      sample_xyz[s][a] = CGAL::to_double(samples[s][a]);
    const std::array<std::int64_t, 3> c = cube_of(sample_xyz[s]);
    const std::uint64_t key = internal::lattice_key(c[0], c[1], c[2]);
    if(visited.insert(key).second)
      stack.push_back(key);
  }
  std::sort(stack.begin(), stack.end(), std::greater<std::uint64_t>()); // pop smallest first
  flood();
  // Second pass, for cells finer than the offset of the zero set from the
  // samples (noise, curvature: sphere.pwn's zero set lies 1.4e-3 inside its
  // samples): from each sample whose cube f does not cross, walk down |f|
  // (along the gradient of the cube's trilinear interpolant, which is the
  // tangent plane's normal where the cube's corners share a plane) in steps
  // of half a cell, to the first crossed cube, at most rho + delta away (the
  // largest distance at which f is defined).  A walk ends at an undefined
  // cube, a jump, or a cube already crossed (its piece is traversed).
  std::unordered_set<std::uint64_t> crossed_cubes(surface_cubes.begin(), surface_cubes.end());
  const double walk_length = field.sampling_density() + field.noise_level() + r;
  const int max_steps = int((std::min)(std::ceil(walk_length / (0.5 * r)), 1e6));
  for(std::size_t s = 0; s < samples.size(); ++s)
  {
    if((s & 1023) == 0)
      progress.report(0.5 * double(s) / double(samples.size()));
    std::array<double, 3> q = sample_xyz[s];
    std::array<std::int64_t, 3> c = cube_of(q);
    if(crossed_cubes.count(internal::lattice_key(c[0], c[1], c[2])) != 0)
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
        if(visited.insert(key).second)
        {
          const std::size_t before = surface_cubes.size();
          stack.push_back(key);
          ++report.walk_seeds;
          flood();
          crossed_cubes.insert(surface_cubes.begin() + std::ptrdiff_t(before), surface_cubes.end());
        }
        break;
      }
      if(state != Cube_state::uncrossed)
        break;
    }
  }

  // ---- triangles, cube by cube in key order -------------------------------
  std::sort(surface_cubes.begin(), surface_cubes.end());
  report.surface_cubes = surface_cubes.size();
  const Marching_cubes_table& table = Marching_cubes_table::instance();
  std::unordered_map<std::uint64_t, std::size_t> edge_vertex;
  edge_vertex.reserve(3 * surface_cubes.size());
  std::size_t next_vertex = out_points.size();
  const std::size_t first_vertex = next_vertex;
  const std::size_t first_triangle = out_triangles.size();
  for(const std::uint64_t key : surface_cubes)
  {
    const std::array<std::int64_t, 3> c = internal::lattice_index(key);
    cube_values(c, values); // cached
    const unsigned code = internal::inside_cube_code(values);
    const unsigned join = internal::asymptotic_decider_mask(values, code);
    const unsigned ambiguous = ambiguous_face_mask(code);
    for(int f = 0; f < 6; ++f)
      if((ambiguous >> f) & 1u)
      {
        ++report.ambiguous_faces;
        if((join >> f) & 1u)
          ++report.joined_faces;
      }
    std::array<std::size_t, 12 + Marching_cubes_table::max_number_of_polygons> local;
    local.fill(std::size_t(-1));
    auto edge_point = [&](int e) -> Point_3 {
      const std::array<int, 2> ends = cube_edge_corners(e);
      const std::array<int, 3> o0 = cube_corner_offset(ends[0]), o1 = cube_corner_offset(ends[1]);
      const Point_3 vi = lattice_point(c[0] + o0[0], c[1] + o0[1], c[2] + o0[2]);
      const Point_3 vj = lattice_point(c[0] + o1[0], c[1] + o1[1], c[2] + o1[2]);
      const double t = internal::edge_parameter(values[ends[0]], values[ends[1]]);
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
      auto inserted = edge_vertex.emplace(edge_key, next_vertex);
      if(inserted.second)
      {
        out_points.push_back(edge_point(e));
        ++next_vertex;
      }
      return local[v] = inserted.first->second;
    };
    for(const auto& t : table.triangles(code, join))
    {
      const std::size_t a = vertex(t[0]), b = vertex(t[1]), d = vertex(t[2]);
      out_triangles.push_back(typename TriangleRange::value_type{a, b, d});
      ++report.number_of_triangles;
    }
  }
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
    report.number_of_triangles = out_triangles.size() - first_triangle;
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
    report.number_of_triangles = out_triangles.size() - first_triangle;
  }
  report.number_of_vertices = next_vertex - first_vertex;
  report.number_of_faces = report.number_of_triangles;
  report.empty_output = report.number_of_triangles == 0;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - total_start).count();
  report.seconds_field = field_seconds;
  report.seconds_contouring = report.seconds - field_seconds;
  report.field_seconds = report.seconds_field;
  report.contouring_seconds = report.seconds_contouring;
  add_contouring_warnings(report);
  progress.report(1.0);
  return report;
}

} // namespace internal


namespace internal {

// The mesh of a contouring soup (cleared first); pinched vertices between two
// holes are duplicated (PMP::orient_polygon_soup) so that the mesh is valid.
template <typename Point, typename PolygonMesh>
void contour_soup_to_mesh(std::vector<Point>& soup_points, std::vector<std::array<std::size_t, 3>>& soup_triangles,
                          PolygonMesh& mesh)
{
  CGAL::clear(mesh);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup_triangles))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup_triangles);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup_points, soup_triangles, mesh);
}

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * The default contouring lattice of `field`: spacing `cell_size` (or the
 * longest side of the samples' bounding box / `cells_along_longest_side`,
 * or the field's default), `lattice_margin` cells around the bounding box
 * of the samples (see `contour_signed_distance()` for the defaults).
 * \throws Invalid_input_error for a non-positive or non-finite spacing, or a negative margin.
 * \throws Lattice_too_large_error if the lattice has more than
 *         `Regular_lattice_3::max_number_of_points` points.
 */
template <typename ContouringField_3, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Regular_lattice_3 contouring_lattice(const ContouringField_3& field,
                                     const NamedParameters& np = parameters::default_values())
{
  const internal::Contouring_lattice l = internal::default_contouring_lattice(field, np);
  return Regular_lattice_3(l.origin, l.r,
                           {{std::size_t(l.cells[0]) + 1, std::size_t(l.cells[1]) + 1, std::size_t(l.cells[2]) + 1}});
}

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

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * Contours the zero set of `field` on `lattice`, visiting only the
 * cubes connected, through faces the surface crosses, to the cubes that
 * contain `field.points()`.  The outputs are cleared first (the package's
 * rule for every output), then receive the points and outward-oriented
 * triangles (f < 0 is inside).
 *
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the
 *         traversal is sequential today whatever the tag (it is there so that
 *         every algorithm of the package has the same signature).
 *
 * \param lattice the domain: lattice point (i, j, k) is `lattice.coordinate()`s;
 *   `contouring_lattice(field, np)` is the default one (the named parameters
 *   `cell_size`, `cells_along_longest_side` and `lattice_margin` below are
 *   those of `contouring_lattice()`, and ignored here)
 * \param field a model of `ContouringField_3`, e.g. `Tangent_plane_signed_distance_3<K>`:
 *   `typedef Point_3` (constructible from 3 doubles, `p[a]` coordinates);
 *   `points()`: a range of `Point_3`, the seeds (the samples);
 *   `sampling_density()`, `noise_level()`: doubles (default cell size, margin, bubbles);
 *   optionally `default_cell_size()`: a double, the default lattice spacing;
 *   `operator()(const Point_3&)`: `std::optional<double>`, empty = undefined.
 * \param out_points a `std::vector`-like container of `K::Point_3`
 *        (`push_back`, `size`, `operator[]`, `erase`, `insert`)
 * \param out_triangles a `std::vector`-like container of 3-index polygons
 *        (the same, and construction from `{a, b, c}`)
 * \param np an optional sequence of named parameters among the ones listed
 *        below, then the notes on them.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{`CGAL::parameters::callback`: called with the fraction done; returning
 *       `false` cancels the run with `Operation_cancelled_error`}
 *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{`field.default_cell_size()` when the field has it, else `field.sampling_density() / 3`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{2 rho}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * Notes on the named parameters (`Boolean_isosurfacing::parameters::`):
 *  - `cell_size(r)`: lattice spacing;
 *  - `cells_along_longest_side(N)`: r = longest bounding-box side / N
 *    (ignored when `cell_size` is given);
 *  - default r = `field.default_cell_size()` when the field has it, else
 *    sampling_density / 3 (for Tangent_plane_signed_distance_3, a third of
 *    the *estimated* rho, even when rho is given),
 *    about 1.25 times the mean sample spacing: finer lattices only resolve
 *    the facets of the piecewise-planar f, coarser ones lose detail;
 *  - `maximum_jump(j)`: a cube with a sign-changing edge along which f
 *    changes by more than j is a discontinuity of f, not a surface, and is
 *    skipped (default 3 r + 2 delta; `std::numeric_limits<double>::infinity()`
 *    gives Hoppe's plain rule);
 *  - `minimum_closed_component_size(s)`: closed pieces of the output (each
 *    edge in two of their triangles) whose bounding box has a diagonal below
 *    s are removed: the "bubbles" Hoppe's f leaves in concave regions, around
 *    one or two lattice points.  Default rho (`field.sampling_density()`):
 *    a rho-dense sample cannot witness a smaller closed piece; 0 keeps all;
 *  - `lattice_margin(m)`: cells added around the bounding box of the samples
 *    (default ceil((rho + delta) / r) + 2, so that the traversal ends at
 *    undefined corners before it reaches the lattice border).
 * \throws Invalid_input_error a non-positive or non-finite r, or more than
 *         2^20 lattice cells along an axis.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename ContouringField_3, typename PointOutRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Contouring_statistics contour_signed_distance(const Regular_lattice_3& lattice, const ContouringField_3& field,
                                              PointOutRange& out_points, TriangleRange& out_triangles,
                                              const NamedParameters& np = parameters::default_values())
{
  internal::check_concurrency_tag<ConcurrencyTag>();
  out_points.clear();
  out_triangles.clear();
  return internal::contour_on_lattice(internal::to_contouring_lattice(lattice), field, out_points, out_triangles, np);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * \deprecated The former shape, the lattice from the named parameters: the
 * contouring on `contouring_lattice(field, np)` (without its limit of 2^31
 * lattice points: the traversal is sparse).  The outputs are cleared first.
 */
template <typename ContouringField_3, typename PointOutRange, typename TriangleRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!std::is_same<ContouringField_3, Regular_lattice_3>::value>>
Contouring_statistics contour_signed_distance(const ContouringField_3& field, PointOutRange& out_points,
                                              TriangleRange& out_triangles,
                                              const NamedParameters& np = parameters::default_values())
{
  out_points.clear();
  out_triangles.clear();
  return internal::contour_on_lattice(internal::default_contouring_lattice(field, np), field, out_points,
                                      out_triangles, np);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * Points (+ optional normals) to an outward-oriented triangle soup:
 * `Tangent_plane_signed_distance_3` then `contour_signed_distance()`.
 *
 * \tparam ConcurrencyTag as for `contour_signed_distance()`
 * \param lattice the domain (e.g. `contouring_lattice()` of the samples' field)
 * \param points the samples
 * \param out_points, out_triangles the output soup, cleared first
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{point_map}
 *     \cgalParamDescription{the point of each element of `points`}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Point_3`} \cgalParamDefault{`CGAL::Identity_property_map`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{normal_map}
 *     \cgalParamDescription{the (roughly) outward normal of each sample, used only to orient the tangent planes}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Vector_3`} \cgalParamDefault{none: the planes are oriented along a minimum spanning tree}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_neighbors}
 *     \cgalParamDescription{k, the size of each neighbourhood (the sample itself included), from 3 to 1024}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{15}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sampling_density}
 *     \cgalParamDescription{Hoppe's rho, the radius of the largest disk on the surface free of samples}
 *     \cgalParamType{`double`} \cgalParamDefault{1.5 sqrt(15 / k) times the median distance to the k-th nearest neighbour}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{noise_level}
 *     \cgalParamDescription{Hoppe's delta}
 *     \cgalParamType{`double`} \cgalParamDefault{twice the median RMS distance of a neighbourhood to its PCA plane}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{rho / 3 with the *estimated* rho: about 1.25 times the mean sample spacing}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{2 rho}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 * \returns the contouring statistics.
 * \throws Empty_contour_error when no triangle comes out.
 * \throws Operation_cancelled_error when the `callback` named parameter returns `false`.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename PointRange, typename PointOutRange,
          typename TriangleRange, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::Is_named_function_parameters<TriangleRange>::value>>
Contouring_statistics contour_point_set(const Regular_lattice_3& lattice, const PointRange& points,
                                        PointOutRange& out_points, TriangleRange& out_triangles,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  const Tangent_plane_signed_distance_3<Geom_traits> field(points, np);
  const Contouring_statistics report =
      contour_signed_distance<ConcurrencyTag>(lattice, field, out_points, out_triangles, np);
  if(report.empty_output)
    throw Empty_contour_error(report);
  return report;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * \deprecated The former shape, the lattice from the named parameters
 * (`contouring_lattice()` of the samples' field).  The outputs are cleared first.
 */
template <typename PointRange, typename PointOutRange, typename TriangleRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::Is_named_function_parameters<TriangleRange>::value &&
                                      !std::is_same<PointRange, Regular_lattice_3>::value>>
Contouring_statistics contour_point_set(const PointRange& points, PointOutRange& out_points,
                                        TriangleRange& out_triangles,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  const Tangent_plane_signed_distance_3<Geom_traits> field(points, np);
  const Contouring_statistics report = contour_signed_distance(field, out_points, out_triangles, np);
  if(report.empty_output)
    throw Empty_contour_error(report);
  return report;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * As above, into a `MutableFaceGraph` (e.g. `Surface_mesh`), which is cleared
 * first (the package's rule for every output), with the same named parameters.  When no cube was skipped the soup is a closed 2-manifold by
 * construction (the table is watertight).  Skipped cubes leave holes, and two
 * holes can pinch a vertex (two skipped cubes diagonal around a lattice edge):
 * such vertices are duplicated (PMP::orient_polygon_soup) so that the mesh is
 * a valid, still consistently oriented, surface with border.
 *
 * \param lattice the domain
 * \param points the samples
 * \param mesh the output (cleared first)
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{point_map}
 *     \cgalParamDescription{the point of each element of `points`}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Point_3`} \cgalParamDefault{`CGAL::Identity_property_map`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{normal_map}
 *     \cgalParamDescription{the (roughly) outward normal of each sample, used only to orient the tangent planes}
 *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Vector_3`} \cgalParamDefault{none: the planes are oriented along a minimum spanning tree}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_neighbors}
 *     \cgalParamDescription{k, the size of each neighbourhood (the sample itself included), from 3 to 1024}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{15}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{sampling_density}
 *     \cgalParamDescription{Hoppe's rho, the radius of the largest disk on the surface free of samples}
 *     \cgalParamType{`double`} \cgalParamDefault{1.5 sqrt(15 / k) times the median distance to the k-th nearest neighbour}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{noise_level}
 *     \cgalParamDescription{Hoppe's delta}
 *     \cgalParamType{`double`} \cgalParamDefault{twice the median RMS distance of a neighbourhood to its PCA plane}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cell_size}
 *     \cgalParamDescription{the lattice spacing r}
 *     \cgalParamType{`double`} \cgalParamDefault{rho / 3 with the *estimated* rho}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{cells_along_longest_side}
 *     \cgalParamDescription{N: r = the longest side of the bounding box of the samples / N (ignored when `cell_size` is given)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{unused}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_jump}
 *     \cgalParamDescription{a cube with a sign-changing edge along which f changes by more than it is a discontinuity of f and is skipped; `std::numeric_limits<double>::infinity()` gives Hoppe's plain rule}
 *     \cgalParamType{`double`} \cgalParamDefault{3 r + 2 delta}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimum_closed_component_size}
 *     \cgalParamDescription{closed pieces of the output whose bounding box has a smaller diagonal are removed (the "bubbles" of Hoppe's f); 0 keeps all}
 *     \cgalParamType{`double`} \cgalParamDefault{rho (`field.sampling_density()`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_hole_size}
 *     \cgalParamDescription{the largest hole, left by skipped cubes, that is closed}
 *     \cgalParamType{`double`} \cgalParamDefault{2 rho}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{lattice_margin}
 *     \cgalParamDescription{cells added around the bounding box of the samples}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{ceil((rho + delta) / r) + 2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename PointRange, typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<internal::Is_named_function_parameters<NamedParameters>::value>>
Contouring_statistics contour_point_set(const Regular_lattice_3& lattice, const PointRange& points, PolygonMesh& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  std::vector<typename Geom_traits::Point_3> soup_points;
  std::vector<std::array<std::size_t, 3>> soup_triangles;
  const Contouring_statistics report =
      contour_point_set<ConcurrencyTag>(lattice, points, soup_points, soup_triangles, np);
  internal::contour_soup_to_mesh(soup_points, soup_triangles, mesh);
  return report;
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * \deprecated The former shape, the lattice from the named parameters.  The mesh is cleared first.
 */
template <typename PointRange, typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = std::enable_if_t<internal::Is_named_function_parameters<NamedParameters>::value &&
                                      !std::is_same<PointRange, Regular_lattice_3>::value>>
Contouring_statistics contour_point_set(const PointRange& points, PolygonMesh& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  std::vector<typename Geom_traits::Point_3> soup_points;
  std::vector<std::array<std::size_t, 3>> soup_triangles;
  const Contouring_statistics report = contour_point_set(points, soup_points, soup_triangles, np);
  internal::contour_soup_to_mesh(soup_points, soup_triangles, mesh);
  return report;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_CONTOUR_POINT_SET_H
