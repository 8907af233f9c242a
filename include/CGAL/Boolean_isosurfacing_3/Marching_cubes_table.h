// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_TABLE_H
#define CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_TABLE_H

// A Marching Cubes table that is *derived* at start-up from one stated face
// rule instead of being copied from a paper.  The rule depends only on the 4
// corner states of a face (plus, optionally, one bit per face that a caller
// computes from that face alone), so two cubes sharing a face always draw the
// same segments on it: the welded output is closed, consistently oriented and
// 2-manifold by construction.  test_marching_cubes_table.cpp proves this
// exhaustively; doc/Boolean_isosurfacing_3/marching_cubes_table.md explains it.
//
// Conventions (all of them are checked against coordinates by the test):
//
// * Corner k = 0..7 of the unit cube sits at offset (k&1, (k>>1)&1, (k>>2)&1).
//   The cube *code* has bit k set iff corner k is INSIDE the solid.
// * Edge e = 4*axis + m, axis = 0 (x), 1 (y), 2 (z).  Its lower corner has
//   coordinate 0 along the axis, and along the two other axes b < c the bits
//   (m&1) and (m>>1):
//      x edges  0:(0,1)  1:(2,3)  2:(4,5)  3:(6,7)
//      y edges  4:(0,2)  5:(1,3)  6:(4,6)  7:(5,7)
//      z edges  8:(0,4)  9:(1,5) 10:(2,6) 11:(3,7)
//   A mesh builder welds vertices by the *global lattice edge*
//   (lattice index of cube origin + cube_edge_origin_offset(e),
//   cube_edge_axis(e)).
// * Face f = 2*axis + side: 0 x=0, 1 x=1, 2 y=0, 3 y=1, 4 z=0, 5 z=1.
//   cube_face_corners(f) lists its corners counterclockwise seen from outside
//   the cube (right-hand rule gives the outward normal), starting with the
//   lowest corner index; cube_face_edges(f)[i] joins corners i and i+1.
// * A face is ambiguous when its inside corners are exactly one diagonal.
// * Default face rule ("separate the inside"): on an ambiguous face the two
//   inside corners are NOT connected across the face (inside is 6-connected,
//   outside 18-connected).  Bit f of a `join_inside` mask selects the other
//   choice on face f.  Bits of non-ambiguous faces and bits above 5 are
//   ignored, so equal configurations share one table entry.
// * Table vertices 0..11 are the edge points of cube edges 0..11.  A vertex
//   12 + p is the centre vertex of polygon p of that cube (only used where a
//   polygon has no admissible triangulation, see below); a builder keys it by
//   (cube, p) and places it at the centroid of polygon(code, mask, p).
// * Triangles are oriented OUT of the solid (right-hand rule): each polygon
//   patch is oriented as part of the boundary of the cube's inside region,
//   i.e. together with the inside parts of the cube faces (outward normals)
//   it forms a closed surface around the inside corners.  This is
//   combinatorial, so it holds for any placement of the edge points strictly
//   inside their edges; e.g. code 1 gives the triangle (0, 4, 8) whose normal
//   points away from corner 0.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#if defined(__has_include)
#  if __has_include(<CGAL/assertions.h>)
#    include <CGAL/assertions.h>
#    define CGAL_BOOLEAN_ISOSURFACING_3_MCT_PRECONDITION(expr) CGAL_precondition(expr)
#  endif
#endif
#ifndef CGAL_BOOLEAN_ISOSURFACING_3_MCT_PRECONDITION
// The header must also work without CGAL (it is pure combinatorics).
#  include <cassert>
#  define CGAL_BOOLEAN_ISOSURFACING_3_MCT_PRECONDITION(expr) assert(expr)
#endif

namespace CGAL {
namespace Boolean_isosurfacing {

// ---------------------------------------------------------------------------
// Cube conventions.  constexpr and check-free because they sit in hot loops;
// their preconditions are the index ranges stated and are proved by the test.
// ---------------------------------------------------------------------------

/// Offset (0 or 1) of corner `k` along `axis`.  \pre 0 <= k < 8, 0 <= axis < 3
constexpr int cube_corner_offset(int k, int axis) { return (k >> axis) & 1; }

/// Offset of corner `k` in x, y, z.  \pre 0 <= k < 8
constexpr std::array<int, 3> cube_corner_offset(int k)
{
  return {{k & 1, (k >> 1) & 1, (k >> 2) & 1}};
}

/// Axis (0 = x, 1 = y, 2 = z) along which edge `e` runs.  \pre 0 <= e < 12
constexpr int cube_edge_axis(int e) { return e >> 2; }

/// Index of the lower corner of edge `e` (the one with offset 0 along its axis).
/// \pre 0 <= e < 12
constexpr int cube_edge_origin_corner(int e)
{
  const int axis = e >> 2;
  const int b = (axis == 0) ? 1 : 0; // the two other axes, b < c
  const int c = (axis == 2) ? 1 : 2;
  return ((e & 1) << b) | (((e >> 1) & 1) << c);
}

/// Offset in x, y, z of the lower corner of edge `e`: the global lattice edge
/// of `e` in the cube with origin lattice point o is (o + this, cube_edge_axis(e)).
/// \pre 0 <= e < 12
constexpr std::array<int, 3> cube_edge_origin_offset(int e)
{
  return cube_corner_offset(cube_edge_origin_corner(e));
}

/// The two corners of edge `e`, lower one first.  \pre 0 <= e < 12
constexpr std::array<int, 2> cube_edge_corners(int e)
{
  return {{cube_edge_origin_corner(e), cube_edge_origin_corner(e) | (1 << cube_edge_axis(e))}};
}

/// The edge joining corners `p` and `q`.
/// \pre p and q differ in exactly one bit (they are the ends of a cube edge).
constexpr int cube_edge_index(int p, int q)
{
  const int d = p ^ q;
  const int axis = (d == 1) ? 0 : (d == 2) ? 1 : 2;
  const int lower = p & q;
  const int b = (axis == 0) ? 1 : 0;
  const int c = (axis == 2) ? 1 : 2;
  return 4 * axis + ((lower >> b) & 1) + 2 * ((lower >> c) & 1);
}

/// Axis normal to face `f`.  \pre 0 <= f < 6
constexpr int cube_face_axis(int f) { return f >> 1; }

/// Side (0: coordinate 0, 1: coordinate 1) of face `f`.  \pre 0 <= f < 6
constexpr int cube_face_side(int f) { return f & 1; }

/// Corners of face `f`, counterclockwise seen from outside the cube, lowest
/// index first.  \pre 0 <= f < 6
constexpr std::array<int, 4> cube_face_corners(int f)
{
  const int a = f >> 1, s = f & 1;
  // (b, c) is a right-handed basis of the face plane for the normal +e_a;
  // swapping the two coordinates reverses the turn for the face at side 0,
  // whose outward normal is -e_a.
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const int u[4] = {0, 1, 1, 0};
  const int v[4] = {0, 0, 1, 1};
  std::array<int, 4> corners{{0, 0, 0, 0}};
  for(int i = 0; i < 4; ++i)
  {
    const int ub = s ? u[i] : v[i];
    const int vc = s ? v[i] : u[i];
    corners[i] = (s << a) | (ub << b) | (vc << c);
  }
  return corners;
}

/// Edges of face `f`: entry i joins cube_face_corners(f)[i] and [(i+1)%4].
/// \pre 0 <= f < 6
constexpr std::array<int, 4> cube_face_edges(int f)
{
  const std::array<int, 4> corners = cube_face_corners(f);
  std::array<int, 4> edges{{0, 0, 0, 0}};
  for(int i = 0; i < 4; ++i)
    edges[i] = cube_edge_index(corners[i], corners[(i + 1) % 4]);
  return edges;
}

/// The two faces that contain edge `e`, lower face index first.  \pre 0 <= e < 12
constexpr std::array<int, 2> cube_edge_faces(int e)
{
  const int axis = e >> 2;
  const int lower = cube_edge_origin_corner(e);
  const int b = (axis == 0) ? 1 : 0;
  const int c = (axis == 2) ? 1 : 2;
  return {{2 * b + ((lower >> b) & 1), 2 * c + ((lower >> c) & 1)}};
}

/// Whether corner `k` is inside for cube code `code`.
constexpr bool is_inside_corner(unsigned code, int k) { return ((code >> k) & 1u) != 0; }

/// Whether edge `e` has one inside and one outside corner (carries a vertex).
constexpr bool is_sign_changing_edge(unsigned code, int e)
{
  return is_inside_corner(code, cube_edge_corners(e)[0]) != is_inside_corner(code, cube_edge_corners(e)[1]);
}

/// Whether face `f` is ambiguous for `code`: its inside corners are exactly one
/// of its two diagonals.  \pre 0 <= f < 6
constexpr bool is_ambiguous_face(unsigned code, int f)
{
  const std::array<int, 4> c = cube_face_corners(f);
  const bool s0 = is_inside_corner(code, c[0]), s1 = is_inside_corner(code, c[1]);
  return s0 == is_inside_corner(code, c[2]) && s1 == is_inside_corner(code, c[3]) && s0 != s1;
}

/// Bit f set iff face f is ambiguous for `code`.
constexpr unsigned ambiguous_face_mask(unsigned code)
{
  unsigned mask = 0;
  for(int f = 0; f < 6; ++f)
    if(is_ambiguous_face(code, f))
      mask |= 1u << f;
  return mask;
}

/// `join_inside` with the bits that cannot matter removed (non-ambiguous faces,
/// bits above 5): two masks give the same triangles iff their normal forms agree.
constexpr unsigned normalized_join_mask(unsigned code, unsigned join_inside)
{
  return join_inside & ambiguous_face_mask(code);
}

namespace internal {

// ---------------------------------------------------------------------------
// Derivation of the table.  Runs once; clarity over speed, but no allocation
// inside the per-polygon search, so that start-up costs about 1 ms.
// ---------------------------------------------------------------------------

// Face rule: next_vertex[e] = edge point that follows edge point e along the
// boundary of the surface patch (every sign-changing edge is the start of
// exactly one segment, see below).
//
// Direction: walking a face counterclockwise seen from outside the cube, an
// "entering" edge goes outside -> inside and a "leaving" edge inside ->
// outside.  The surface boundary on a face must run opposite to the boundary
// of the inside region of that face (which is counterclockwise, as the cube
// surface is outward oriented), so each segment runs from an entering edge to
// a leaving edge.  An edge is entering on one of its two faces and leaving on
// the other (the two faces traverse the shared edge in opposite directions),
// hence every edge point has one outgoing and one incoming segment and the
// segments form disjoint directed cycles.
inline bool draw_face_segments(unsigned code, unsigned join_inside, std::array<int, 12>& next_vertex)
{
  next_vertex.fill(-1);
  for(int f = 0; f < 6; ++f)
  {
    const std::array<int, 4> corner = cube_face_corners(f);
    const std::array<int, 4> edge = cube_face_edges(f);
    bool in[4];
    for(int i = 0; i < 4; ++i)
      in[i] = is_inside_corner(code, corner[i]);
    const bool join = is_ambiguous_face(code, f) && ((join_inside >> f) & 1u);
    for(int i = 0; i < 4; ++i)
    {
      if(in[i] || !in[(i + 1) % 4])
        continue; // edge[i] is not entering
      int target;
      if(join)
        // Connect the inside corners: cut off the outside corner i instead,
        // whose other edge edge[i-1] is leaving.
        target = edge[(i + 3) % 4];
      else
      {
        // Cut off the run of inside corners that starts at corner i+1.  On an
        // ambiguous face the run has length one: this is what keeps the two
        // inside corners apart.
        int j = (i + 1) % 4;
        while(in[(j + 1) % 4])
          j = (j + 1) % 4;
        target = edge[j];
      }
      if(next_vertex[edge[i]] != -1)
        return false;
      next_vertex[edge[i]] = target;
    }
  }
  for(int e = 0; e < 12; ++e)
    if(is_sign_changing_edge(code, e) != (next_vertex[e] != -1))
      return false;
  return true;
}

// Whether the points of edges e1 and e2 lie on a common cube face.
constexpr bool cube_edges_share_face(int e1, int e2)
{
  return cube_edge_faces(e1)[0] == cube_edge_faces(e2)[0] || cube_edge_faces(e1)[0] == cube_edge_faces(e2)[1] ||
         cube_edge_faces(e1)[1] == cube_edge_faces(e2)[0] || cube_edge_faces(e1)[1] == cube_edge_faces(e2)[1];
}

// Triangle quality used only to choose among admissible triangulations:
// q = |cross|^2 / (sum of squared side lengths)^2 with edge points at the
// edge midpoints.  Coordinates are doubled (midpoints become integers), so
// comparisons are exact and the table is the same on every platform.
struct Triangle_quality
{
  std::int64_t area2 = 0; // |cross product|^2
  std::int64_t norm = 1;  // (sum of squared side lengths)^2

  friend bool operator<(const Triangle_quality& a, const Triangle_quality& b)
  {
    return a.area2 * b.norm < b.area2 * a.norm;
  }
  friend bool operator==(const Triangle_quality& a, const Triangle_quality& b)
  {
    return a.area2 * b.norm == b.area2 * a.norm;
  }
};

inline std::array<int, 3> doubled_edge_midpoint(int e)
{
  const std::array<int, 2> c = cube_edge_corners(e);
  return {{cube_corner_offset(c[0], 0) + cube_corner_offset(c[1], 0), cube_corner_offset(c[0], 1) + cube_corner_offset(c[1], 1),
           cube_corner_offset(c[0], 2) + cube_corner_offset(c[1], 2)}};
}

inline Triangle_quality triangle_quality(int e0, int e1, int e2)
{
  const std::array<int, 3> p = doubled_edge_midpoint(e0), q = doubled_edge_midpoint(e1), r = doubled_edge_midpoint(e2);
  std::int64_t u[3], v[3], w[3];
  for(int i = 0; i < 3; ++i)
  {
    u[i] = q[i] - p[i];
    v[i] = r[i] - p[i];
    w[i] = r[i] - q[i];
  }
  const std::int64_t cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  const std::int64_t sides =
    u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  Triangle_quality t;
  t.area2 = cx * cx + cy * cy + cz * cz;
  t.norm = sides * sides;
  return t;
}

// A triangulation of a sub-polygon, with the two keys that order candidates.
// Both keys ignore orientation, so a polygon and its reverse (the same cube
// with all states complemented) get the same triangles.
struct Triangulation_candidate
{
  static constexpr int capacity = 10; // a 12-gon has 10 triangles
  int size = 0;
  std::array<std::array<int, 3>, capacity> triangles{}; // polygon positions, increasing
  std::array<Triangle_quality, capacity> qualities{};   // ascending
  std::array<int, capacity> ids{};                      // sorted edge triple ids, ascending
};

// Total order "a is better than b":
//  1. leximin on qualities (larger worst triangle, then larger second worst, ...);
//  2. then the set of triangles (as sets of cube edges) whose smallest
//     differing element is smaller.
// Both are orders on multisets in which adding the same disjoint triangles to
// two candidates preserves the order, so the interval dynamic programme below
// finds the global optimum; distinct triangulations never tie on 2.
inline bool is_better(const Triangulation_candidate& a, const Triangulation_candidate& b)
{
  for(int i = 0; i < a.size; ++i)
    if(!(a.qualities[i] == b.qualities[i]))
      return b.qualities[i] < a.qualities[i];
  for(int i = 0; i < a.size; ++i)
    if(a.ids[i] != b.ids[i])
      return a.ids[i] < b.ids[i];
  return false;
}

inline int triangle_id(int e0, int e1, int e2)
{
  int t[3] = {e0, e1, e2};
  std::sort(t, t + 3);
  return (t[0] * 12 + t[1]) * 12 + t[2];
}

// Triangulates the directed polygon `vertex[0..n)` (cube edge indices) with
// no chord between two edge points of a common face.  Why: such a chord lies
// in that face, which the neighbouring cube may also triangulate (non-manifold
// edge), and a triangle using it would be flat in the face.  Returns false if
// no admissible triangulation exists.  Output triangles follow the polygon's
// direction (positions i < k < j), which is the outward orientation.
inline bool triangulate_polygon(const int* vertex, int n, std::vector<Triangulation_candidate>& workspace,
                                std::vector<std::array<int, 3>>& out)
{
  constexpr int max_n = 12;
  bool admissible[max_n][max_n] = {};
  for(int i = 0; i < n; ++i)
    for(int j = i + 1; j < n; ++j)
    {
      const bool side = (j == i + 1) || (i == 0 && j == n - 1);
      admissible[i][j] = side || !cube_edges_share_face(vertex[i], vertex[j]);
    }

  // best[i][j]: best triangulation of the sub-polygon i, i+1, ..., j closed by
  // the chord (i, j); has[i][j] tells whether one exists (true for j = i + 1).
  workspace.resize(max_n * max_n);
  auto best = [&workspace](int i, int j) -> Triangulation_candidate& { return workspace[i * max_n + j]; };
  bool has[max_n][max_n] = {};
  for(int i = 0; i + 1 < n; ++i)
  {
    has[i][i + 1] = true;
    best(i, i + 1).size = 0;
  }
  for(int length = 2; length < n; ++length)
    for(int i = 0; i + length < n; ++i)
    {
      const int j = i + length;
      if(!admissible[i][j])
        continue;
      for(int k = i + 1; k < j; ++k)
      {
        if(!has[i][k] || !has[k][j])
          continue;
        const Triangulation_candidate& left = best(i, k);
        const Triangulation_candidate& right = best(k, j);
        Triangulation_candidate candidate;
        candidate.size = left.size + right.size + 1;
        int m = 0;
        for(int t = 0; t < left.size; ++t)
          candidate.triangles[m++] = left.triangles[t];
        for(int t = 0; t < right.size; ++t)
          candidate.triangles[m++] = right.triangles[t];
        candidate.triangles[m] = {{i, k, j}};
        // Keys stay sorted: merge the two halves, then insert the new triangle.
        const Triangle_quality quality = triangle_quality(vertex[i], vertex[k], vertex[j]);
        const int id = triangle_id(vertex[i], vertex[k], vertex[j]);
        std::merge(left.qualities.begin(), left.qualities.begin() + left.size, right.qualities.begin(),
                   right.qualities.begin() + right.size, candidate.qualities.begin());
        std::merge(left.ids.begin(), left.ids.begin() + left.size, right.ids.begin(), right.ids.begin() + right.size,
                   candidate.ids.begin());
        int q = m;
        for(; q > 0 && quality < candidate.qualities[q - 1]; --q)
          candidate.qualities[q] = candidate.qualities[q - 1];
        candidate.qualities[q] = quality;
        q = m;
        for(; q > 0 && id < candidate.ids[q - 1]; --q)
          candidate.ids[q] = candidate.ids[q - 1];
        candidate.ids[q] = id;
        if(!has[i][j] || is_better(candidate, best(i, j)))
        {
          best(i, j) = candidate;
          has[i][j] = true;
        }
      }
    }
  if(!has[0][n - 1])
    return false;
  const Triangulation_candidate& chosen = best(0, n - 1);
  out.clear();
  for(int t = 0; t < chosen.size; ++t)
    out.push_back(chosen.triangles[t]);
  std::sort(out.begin(), out.end());
  return true;
}

} // namespace internal

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The Marching Cubes table derived from the face rule stated at the top of
/// this header.  One entry per (code, normalized join mask): 256 codes, 1 or
/// 2^(number of ambiguous faces) entries each.  An entry holds its polygons
/// (the closed boundary curves of the surface patch, as cycles of edge
/// indices) and their triangles.
///
/// Lookups do not allocate and are two array reads plus a loop over the
/// ambiguous faces.  In a hot loop keep a reference to `instance()`.
class Marching_cubes_table
{
public:
  /// Three vertex indices: 0..11 cube edge points, 12 + p centre of polygon p.
  typedef std::array<std::uint8_t, 3> Triangle;

  /// A contiguous read-only view (begin/end/size/operator[]), valid as long as
  /// the table (for `instance()`: the program).
  template <typename T>
  class Range
  {
  public:
    Range() = default;
    Range(const T* first, std::size_t size) : m_first(first), m_size(size) {}
    const T* begin() const { return m_first; }
    const T* end() const { return m_first + m_size; }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    const T& operator[](std::size_t i) const { return m_first[i]; }

  private:
    const T* m_first = nullptr;
    std::size_t m_size = 0;
  };
  typedef Range<Triangle> Triangle_range;
  typedef Range<std::uint8_t> Vertex_range;

  /// Table vertex index of the centre vertex of polygon `p`.
  static constexpr std::uint8_t centre_vertex(unsigned p) { return static_cast<std::uint8_t>(12 + p); }
  /// Whether table vertex `v` is a polygon centre rather than an edge point.
  static constexpr bool is_centre_vertex(unsigned v) { return v >= 12; }
  /// A cube has at most 4 polygons (each needs 3 of the 12 edge points).
  static constexpr unsigned max_number_of_polygons = 4;
  /// Upper bound valid for any face rule: an n-gon uses n - 2 triangles, or n
  /// with a centre vertex, and the polygons share at most 12 edge points.
  static constexpr unsigned max_number_of_triangles_bound = 12;

  /// Derives the whole table (see the user manual for the time it takes).
  /// \throws std::logic_error if the derivation contradicts its own invariants
  /// (cannot happen unless this file is edited wrongly).
  Marching_cubes_table() { build(); }

  /// The table shared by the whole program, built on first use (thread-safe).
  static const Marching_cubes_table& instance()
  {
    static const Marching_cubes_table table;
    return table;
  }

  /// Triangles of a cube with inside corners `code` and face decisions
  /// `join_inside` (bit f: connect the inside corners across face f if it is
  /// ambiguous).  \pre code < 256
  Triangle_range triangles(unsigned code, unsigned join_inside = 0) const
  {
    const Entry& e = entry(code, join_inside);
    return Triangle_range(m_triangles.data() + e.first_triangle, e.number_of_triangles);
  }

  /// Number of polygons (boundary cycles, = connected surface pieces) in the cube.
  /// \pre code < 256
  unsigned number_of_polygons(unsigned code, unsigned join_inside = 0) const
  {
    return entry(code, join_inside).number_of_polygons;
  }

  /// Polygon `p` as a cycle of cube edge indices in the direction of the
  /// triangles' boundary.  Polygons are numbered by their smallest edge index,
  /// and each cycle starts at its smallest edge index.
  /// \pre code < 256, p < number_of_polygons(code, join_inside)
  Vertex_range polygon(unsigned code, unsigned join_inside, unsigned p) const
  {
    const Entry& e = entry(code, join_inside);
    CGAL_BOOLEAN_ISOSURFACING_3_MCT_PRECONDITION(p < e.number_of_polygons);
    std::size_t first = e.first_polygon_vertex;
    for(unsigned i = 0; i < p; ++i)
      first += e.polygon_size[i];
    return Vertex_range(m_polygon_vertices.data() + first, e.polygon_size[p]);
  }

  /// Whether this entry needed the centre-vertex fallback.  \pre code < 256
  bool uses_centre_vertex(unsigned code, unsigned join_inside = 0) const
  {
    return entry(code, join_inside).uses_centre_vertex != 0;
  }

  /// Number of distinct (code, normalized join mask) entries.
  std::size_t number_of_entries() const { return m_entries.size(); }
  /// Number of entries with at least one centre-vertex fan.
  std::size_t number_of_fallback_entries() const { return m_number_of_fallback_entries; }
  /// Largest number of triangles of one entry.
  std::size_t max_number_of_triangles() const { return m_max_number_of_triangles; }

private:
  struct Code_record
  {
    std::uint16_t first_entry;
    std::uint8_t ambiguous_faces; // mask
  };
  struct Entry
  {
    std::uint16_t first_triangle;
    std::uint16_t first_polygon_vertex;
    std::uint8_t number_of_triangles;
    std::uint8_t number_of_polygons;
    std::uint8_t uses_centre_vertex;
    std::array<std::uint8_t, max_number_of_polygons> polygon_size;
  };

  // Rank of the join bits among the code's ambiguous faces: entries of one
  // code are stored for masks 0 .. 2^#ambiguous - 1 in this compressed form.
  const Entry& entry(unsigned code, unsigned join_inside) const
  {
    CGAL_BOOLEAN_ISOSURFACING_3_MCT_PRECONDITION(code < 256);
    const Code_record& record = m_codes[code];
    unsigned index = 0;
    unsigned ambiguous = record.ambiguous_faces;
    if(ambiguous & join_inside)
      for(unsigned bit = 1; ambiguous != 0; ambiguous &= ambiguous - 1, bit <<= 1)
        if(join_inside & ambiguous & (0u - ambiguous))
          index |= bit;
    return m_entries[record.first_entry + index];
  }

  void build()
  {
    std::vector<std::array<int, 3>> local;
    std::vector<internal::Triangulation_candidate> workspace;
    for(unsigned code = 0; code < 256; ++code)
    {
      const unsigned ambiguous = ambiguous_face_mask(code);
      m_codes[code].first_entry = static_cast<std::uint16_t>(m_entries.size());
      m_codes[code].ambiguous_faces = static_cast<std::uint8_t>(ambiguous);
      int ambiguous_face[6];
      int number_of_ambiguous = 0;
      for(int f = 0; f < 6; ++f)
        if((ambiguous >> f) & 1u)
          ambiguous_face[number_of_ambiguous++] = f;
      for(unsigned index = 0; index < (1u << number_of_ambiguous); ++index)
      {
        unsigned join_inside = 0;
        for(int i = 0; i < number_of_ambiguous; ++i)
          if((index >> i) & 1u)
            join_inside |= 1u << ambiguous_face[i];
        add_entry(code, join_inside, workspace, local);
      }
    }
  }

  void add_entry(unsigned code, unsigned join_inside, std::vector<internal::Triangulation_candidate>& workspace,
                 std::vector<std::array<int, 3>>& local)
  {
    std::array<int, 12> next_vertex;
    if(!internal::draw_face_segments(code, join_inside, next_vertex))
      throw std::logic_error("Marching_cubes_table: face segments do not form cycles");

    Entry entry{};
    entry.first_triangle = static_cast<std::uint16_t>(m_triangles.size());
    entry.first_polygon_vertex = static_cast<std::uint16_t>(m_polygon_vertices.size());
    bool visited[12] = {};
    for(int start = 0; start < 12; ++start)
    {
      if(next_vertex[start] == -1 || visited[start])
        continue;
      int cycle[12];
      int n = 0;
      for(int e = start; !visited[e]; e = next_vertex[e])
      {
        visited[e] = true;
        cycle[n++] = e;
      }
      if(n < 3 || entry.number_of_polygons == max_number_of_polygons)
        throw std::logic_error("Marching_cubes_table: impossible polygon");
      const unsigned p = entry.number_of_polygons++;
      entry.polygon_size[p] = static_cast<std::uint8_t>(n);
      for(int i = 0; i < n; ++i)
        m_polygon_vertices.push_back(static_cast<std::uint8_t>(cycle[i]));

      if(internal::triangulate_polygon(cycle, n, workspace, local))
      {
        for(const std::array<int, 3>& t : local)
          m_triangles.push_back(Triangle{{static_cast<std::uint8_t>(cycle[t[0]]), static_cast<std::uint8_t>(cycle[t[1]]),
                                          static_cast<std::uint8_t>(cycle[t[2]])}});
      }
      else
      {
        // Every chord is forbidden somewhere: fan around a vertex interior to
        // the cube, which no neighbouring cube can see.
        entry.uses_centre_vertex = 1;
        for(int i = 0; i < n; ++i)
          m_triangles.push_back(Triangle{{static_cast<std::uint8_t>(cycle[i]), static_cast<std::uint8_t>(cycle[(i + 1) % n]),
                                          centre_vertex(p)}});
      }
    }
    const std::size_t count = m_triangles.size() - entry.first_triangle;
    entry.number_of_triangles = static_cast<std::uint8_t>(count);
    m_max_number_of_triangles = (std::max)(m_max_number_of_triangles, count);
    if(entry.uses_centre_vertex)
      ++m_number_of_fallback_entries;
    m_entries.push_back(entry);
  }

  std::array<Code_record, 256> m_codes{};
  std::vector<Entry> m_entries;
  std::vector<Triangle> m_triangles;
  std::vector<std::uint8_t> m_polygon_vertices;
  std::size_t m_number_of_fallback_entries = 0;
  std::size_t m_max_number_of_triangles = 0;
};

/// Triangles of a cube from the shared table; see Marching_cubes_table::triangles().
/// \pre code < 256
inline Marching_cubes_table::Triangle_range marching_cubes_triangles(unsigned code, unsigned join_inside = 0)
{
  return Marching_cubes_table::instance().triangles(code, join_inside);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_MARCHING_CUBES_TABLE_H
