// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_TETRAHEDRON_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_TETRAHEDRON_H

// The exact TBISO evaluation of one tetrahedron.
//
// Inside a tetrahedron T every field f_i is linear.  The Boolean set B is a
// union over terms of intersections of open half-spaces {f_i < 0} / {f_i > 0};
// its regularized boundary is made of the 2-faces of the arrangement of the
// zero planes that separate a full-dimensional cell where B holds from one
// where it does not.  Such a face lies either
//  (a) inside T, on the zero plane of a field that changes sign in T: the
//      polygon P_i = {f_i = 0} n T is cut by the zero lines of the other
//      fields that change sign in T, and each piece is kept iff B differs on
//      its two sides; or
//  (b) on a face F of T on which some field vanishes identically (or on the
//      boundary of the domain, when closing): the fields are then the same on
//      both sides of F except those vanishing on F, whose sign on each side is
//      their sign at that side's apex.  The tetrahedron on the side where B
//      holds emits the face, so it is emitted once.
// This replaces the seed's C2F / F2E / E2V tables: a piece is kept by
// evaluating the expression on its two sides, and a tetrahedron is skipped
// before any of this when the expression restricted to the fields of constant
// sign in it is constant (see doc/Boolean_isosurfacing_3/tbiso.md).
//
// Exactness.  A polygon vertex is the meeting point of three planes among the
// four face planes of T (barycentric coordinate lambda_c = 0) and the zero
// planes.  It is represented by its *support* S (the corners whose
// barycentric coordinate may be non-zero: all but the face planes through it)
// and |S| - 1 fields vanishing there.  The sign of a linear function g at the
// point is sign(det[F_S; g_S]) * sign(det[F_S; 1]), a determinant of at most
// 4x4 input values (Cramer's rule), evaluated exactly.  Vertices are welded
// by a canonical key: the global indices of the corners with lambda_c > 0
// (the carrier simplex) and the set of all expression fields vanishing there.
// That pair determines the point, and tetrahedra sharing the point compute
// the same pair, so the output is welded exactly and coincidences collapse.
// Coordinates are computed in double, once, at the end.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Exact_determinant_sign.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

inline int lowest_bit(std::uint64_t x) { return lowest_bit_index(x); }

/// A term of the expression as sign requirements: the fields that must be
/// negative (literal `fi`) and those that must be positive (literal `!fi`).
struct Sign_term
{
  std::uint64_t need_negative;
  std::uint64_t need_positive;
};

/// Canonical identity of an output vertex: the sorted global indices of the
/// corners of its carrier simplex (unused slots are max) and the mask of the
/// expression fields vanishing at it (0 for a mesh vertex).
struct Tbiso_vertex_key
{
  std::array<std::size_t, 4> corners;
  std::uint64_t zero_fields;

  friend bool operator==(const Tbiso_vertex_key& a, const Tbiso_vertex_key& b)
  {
    return a.corners == b.corners && a.zero_fields == b.zero_fields;
  }
};

struct Tbiso_vertex_key_hash
{
  std::size_t operator()(const Tbiso_vertex_key& k) const
  {
    std::uint64_t h = k.zero_fields * 0x9E3779B97F4A7C15ull;
    for(std::size_t c : k.corners)
      h = (h ^ (std::uint64_t(c) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2))) * 0xBF58476D1CE4E5B9ull;
    return std::size_t(h ^ (h >> 31));
  }
};

/// One corner of a tetrahedron as the evaluator sees it.
struct Tbiso_corner
{
  std::size_t id;            // global vertex index
  const double* values;      // the N field values at the corner
  std::uint64_t negative;    // expression fields < 0 here
  std::uint64_t positive;    // expression fields > 0 here
  std::array<double, 3> position;
};

/// Per-vertex sign masks of the expression fields.
inline void field_sign_masks(const double* values, std::uint64_t fields, std::uint64_t& negative,
                             std::uint64_t& positive)
{
  negative = 0;
  positive = 0;
  for(std::uint64_t m = fields; m != 0; m &= m - 1)
  {
    const int i = lowest_bit(m);
    const double v = values[i];
    negative |= std::uint64_t(v < 0) << i;
    positive |= std::uint64_t(v > 0) << i;
  }
}

class Tbiso_tetrahedron_evaluator
{
public:
  /// An output polygon vertex: its key, and its carrier as corners of the
  /// tetrahedron being evaluated (see `point()`).
  struct Vertex
  {
    Tbiso_vertex_key key;
    std::uint8_t carrier;
  };

  /// Sign masks of the fields at the apex of the neighbour across a face.
  struct Apex
  {
    bool exists;
    std::uint64_t negative, positive;
  };

  Tbiso_tetrahedron_evaluator(const Boolean_expression& expression, bool close_at_domain_boundary)
    : m_fields(expression.support()), m_close(close_at_domain_boundary)
  {
    for(const Boolean_term& t : expression.terms())
      m_terms.push_back(Sign_term{t.pos, t.neg}); // `pos` = inside = f < 0
  }

  /// The label of the faces that close the set on the domain boundary.
  static constexpr int domain_boundary_label = -1;

  /// The fields the expression depends on: the only ones that cut, weld or label.
  std::uint64_t expression_fields() const { return m_fields; }

  bool closes_at_domain_boundary() const { return m_close; }

  /// Value of the expression for a cell where the fields of `negative` are
  /// < 0 and those of `positive` are > 0 (the others vanish on the whole cell,
  /// which satisfies neither literal).
  bool evaluate(std::uint64_t negative, std::uint64_t positive) const
  {
    for(const Sign_term& t : m_terms)
      if((t.need_negative & ~negative) == 0 && (t.need_positive & ~positive) == 0)
        return true;
    return false;
  }

  /// Is the expression constant when the fields of `free_fields` take any
  /// sign and the others are fixed to (negative, positive)?  A necessary
  /// condition for the tetrahedron to have faces inside; exact for the
  /// canonical form (a restriction of the Blake canonical form is constant
  /// only if it keeps the empty term or no term).
  bool may_vary(std::uint64_t free_fields, std::uint64_t negative, std::uint64_t positive) const
  {
    bool alive = false;
    for(const Sign_term& t : m_terms)
    {
      const std::uint64_t fixed_negative = t.need_negative & ~free_fields;
      const std::uint64_t fixed_positive = t.need_positive & ~free_fields;
      if((fixed_negative & ~negative) != 0 || (fixed_positive & ~positive) != 0)
        continue;
      if(((t.need_negative | t.need_positive) & free_fields) == 0)
        return false; // true whatever the free fields are
      alive = true;
    }
    return alive;
  }

  /// Quick test: can the tetrahedron with these corner masks produce a face?
  /// (`boundary_faces`: bit l = the face opposite corner l is on the domain boundary.)
  bool is_trivially_empty(const std::array<std::uint64_t, 4>& negative, const std::array<std::uint64_t, 4>& positive,
                          unsigned boundary_faces) const
  {
    const std::uint64_t any_negative = negative[0] | negative[1] | negative[2] | negative[3];
    const std::uint64_t any_positive = positive[0] | positive[1] | positive[2] | positive[3];
    const std::uint64_t all_nonzero = (negative[0] | positive[0]) & (negative[1] | positive[1]) &
                                      (negative[2] | positive[2]) & (negative[3] | positive[3]);
    const std::uint64_t mixed = any_negative & any_positive;
    if(mixed == 0 && (all_nonzero & m_fields) == m_fields)
    {
      // Every field has one strict sign on the closed tetrahedron.
      if(!m_close || boundary_faces == 0)
        return true;
      return !evaluate(any_negative, any_positive);
    }
    return false;
  }

  /// Evaluates one positively oriented tetrahedron.  `apex(l)` gives the
  /// neighbour across the face opposite corner `l`; `emit(label, vertices, n, face)`
  /// receives each output polygon, oriented outward from the Boolean set, with
  /// the face `l` of the tetrahedron it lies on (-1 inside the tetrahedron).
  template <typename ApexFunction, typename EmitFunction>
  void evaluate_tetrahedron(const std::array<Tbiso_corner, 4>& corner, const ApexFunction& apex,
                            const EmitFunction& emit)
  {
    m_corner = &corner;
    std::uint64_t any_negative = 0, any_positive = 0;
    std::array<std::uint64_t, 4> zero;
    for(int c = 0; c < 4; ++c)
    {
      any_negative |= corner[c].negative;
      any_positive |= corner[c].positive;
      zero[c] = m_fields & ~(corner[c].negative | corner[c].positive);
    }
    const std::uint64_t mixed = any_negative & any_positive;
    // Fields of one strict sign in the open tetrahedron; fields vanishing on
    // all of it get neither bit.
    const std::uint64_t fixed_negative = any_negative & ~mixed;
    const std::uint64_t fixed_positive = any_positive & ~mixed;

    if(mixed != 0 && may_vary(mixed, fixed_negative, fixed_positive))
      for(std::uint64_t m = mixed; m != 0; m &= m - 1)
        zero_plane_faces(lowest_bit(m), mixed, fixed_negative, fixed_positive, emit);

    for(int l = 0; l < 4; ++l)
    {
      std::uint64_t vanishing = m_fields;
      for(int c = 0; c < 4; ++c)
        if(c != l)
          vanishing &= zero[c];
      if(vanishing == 0 && !m_close)
        continue;
      const Apex a = apex(l);
      if(a.exists && vanishing == 0)
        continue;
      if(!a.exists && !m_close)
        continue;
      tetrahedron_face_faces(l, vanishing, a, emit);
    }
  }

  /// The coordinates of `v`, in double, from its key alone (so that they do
  /// not depend on which tetrahedron met the vertex first): the carrier
  /// corners in increasing global index and the lowest vanishing fields that
  /// define the point, i.e. whose system with the carrier is regular.  Valid
  /// only inside the `emit` callback of `evaluate_tetrahedron()`, and called by
  /// the drivers only for a vertex they have not seen yet.
  std::array<double, 3> point(const Vertex& v) const
  {
    const std::array<Tbiso_corner, 4>& corner = *m_corner;
    int carrier_columns[4];
    int cm = 0;
    for(int c = 0; c < 4; ++c)
      if((v.carrier >> c) & 1)
        carrier_columns[cm++] = c;
    if(cm == 1)
      return corner[carrier_columns[0]].position;
    std::array<double, 3> point;
    std::sort(carrier_columns, carrier_columns + cm,
              [&](int x, int y) { return corner[x].id < corner[y].id; });
    int chosen[3];
    if(!choose_defining_fields(carrier_columns, cm, v.key.zero_fields, chosen, 0, 0))
      CGAL_assertion_msg(false, "a TBISO vertex is not defined by its vanishing fields");
    if(cm == 2)
    {
      // The seed's interpolation t = -f_a / (f_b - f_a), from the lower index.
      const int a = carrier_columns[0], b = carrier_columns[1];
      const double fa = field_value(a, chosen[0]), fb = field_value(b, chosen[0]);
      const double t = -fa / (fb - fa);
      for(int x = 0; x < 3; ++x)
        point[x] = corner[a].position[x] + t * (corner[b].position[x] - corner[a].position[x]);
      return point;
    }
    // Solve [F; 1] lambda = (0, .., 0, 1) by Gauss-Jordan with partial pivoting.
    double A[4][5];
    for(int row = 0; row + 1 < cm; ++row)
    {
      for(int k = 0; k < cm; ++k)
        A[row][k] = field_value(carrier_columns[k], chosen[row]);
      A[row][cm] = 0;
    }
    for(int k = 0; k < cm; ++k)
      A[cm - 1][k] = 1;
    A[cm - 1][cm] = 1;
    for(int col = 0; col < cm; ++col)
    {
      int pivot = col;
      for(int row = col + 1; row < cm; ++row)
        if(std::abs(A[row][col]) > std::abs(A[pivot][col]))
          pivot = row;
      for(int k = 0; k <= cm; ++k)
        std::swap(A[col][k], A[pivot][k]);
      for(int row = 0; row < cm; ++row)
        if(row != col && A[col][col] != 0)
        {
          const double factor = A[row][col] / A[col][col];
          for(int k = col; k <= cm; ++k)
            A[row][k] -= factor * A[col][k];
        }
    }
    double lambda[4] = {0, 0, 0, 0};
    double total = 0;
    for(int k = 0; k < cm; ++k)
    {
      // The point is inside its carrier: clamping only removes rounding.
      lambda[k] = std::min(1., std::max(0., A[k][cm] / A[k][k]));
      total += lambda[k];
    }
    point = {0, 0, 0};
    for(int k = 0; k < cm; ++k)
      for(int x = 0; x < 3; ++x)
        point[x] += lambda[k] / total * corner[carrier_columns[k]].position[x];
    return point;
  }


private:
  // A point of the tetrahedron (see the header comment).
  struct Rep
  {
    std::uint8_t support = 0; // bit c: corner c
    std::uint8_t number_of_fields = 0;
    std::uint8_t field[3] = {0, 0, 0};
  };

  // Plane identifiers: 0..3 the face opposite corner c, 4 + i the zero plane of field i.
  static bool is_face_plane(int p) { return p < 4; }

  struct Polygon
  {
    std::vector<Rep> vertices;
    std::vector<int> edge_plane;  // plane of the edge from vertex k to vertex k+1
    std::uint64_t negative = 0;   // side of each cutting field already applied
    std::uint64_t positive = 0;
  };

  double field_value(int c, int i) const { return (*m_corner)[c].values[i]; }

  static int sign_of(double x) { return (x > 0) - (x < 0); }

  int corner_sign(int c, int i) const
  {
    const Tbiso_corner& k = (*m_corner)[c];
    return int((k.positive >> i) & 1) - int((k.negative >> i) & 1);
  }

  // Rows of the linear system of a representation: one per defining field,
  // restricted to the support columns.
  int support_columns(const Rep& r, int* columns) const
  {
    int m = 0;
    for(int c = 0; c < 4; ++c)
      if((r.support >> c) & 1)
        columns[m++] = c;
    return m;
  }

  // Sign of the linear function with corner values g[0..3] at the point r.
  int sign_at(const Rep& r, const double* g) const
  {
    int columns[4];
    const int m = support_columns(r, columns);
    if(m == 1)
      return sign_of(g[columns[0]]);
    if(m == 2)
    {
      const int i = r.field[0];
      const double fa = field_value(columns[0], i), fb = field_value(columns[1], i);
      // f_a g_b - f_b g_a over f_a - f_b (the zero of f on the edge).
      const int numerator = exact_sign_of_2x2(fa, fb, g[columns[0]], g[columns[1]]);
      const int denominator = (fa > fb) - (fa < fb);
      return numerator * denominator;
    }
    double num[16], den[16];
    for(int row = 0; row + 1 < m; ++row)
      for(int k = 0; k < m; ++k)
        num[row * m + k] = den[row * m + k] = field_value(columns[k], r.field[row]);
    for(int k = 0; k < m; ++k)
    {
      num[(m - 1) * m + k] = g[columns[k]];
      den[(m - 1) * m + k] = 1.;
    }
    return exact_sign_of_determinant(num, m) * exact_sign_of_determinant(den, m);
  }

  int field_sign_at(const Rep& r, int i) const
  {
    double g[4];
    for(int c = 0; c < 4; ++c)
      g[c] = field_value(c, i);
    return sign_at(r, g);
  }

  static Rep rep_of_planes(int p, int q, int s)
  {
    Rep r;
    r.support = 0xF;
    const int planes[3] = {p, q, s};
    for(int k = 0; k < 3; ++k)
    {
      if(is_face_plane(planes[k]))
        r.support &= std::uint8_t(~(1u << planes[k]));
      else
        r.field[r.number_of_fields++] = std::uint8_t(planes[k] - 4);
    }
    return r;
  }

  // --- initial polygons ---------------------------------------------------

  // An item of a zero polygon: corner a (b < 0) or the crossing on edge (a, b).
  struct Item
  {
    std::int8_t a, b;
  };
  struct Item_polygon
  {
    int size = 0;
    Item item[4];
  };

  // The zero polygon of a linear function for each of the 81 corner sign
  // patterns (index sum (s_c + 1) 3^c), counterclockwise seen from the
  // positive side, in a positively oriented tetrahedron.  The order only
  // depends on the signs, so it is computed once on a reference tetrahedron.
  static const std::array<Item_polygon, 81>& zero_polygon_table()
  {
    static const std::array<Item_polygon, 81> table = [] {
      std::array<Item_polygon, 81> t{};
      const double P[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for(int code = 0; code < 81; ++code)
      {
        int s[4];
        for(int c = 0, x = code; c < 4; ++c, x /= 3)
          s[c] = x % 3 - 1;
        bool has_negative = false, has_positive = false;
        for(int c = 0; c < 4; ++c)
        {
          has_negative |= s[c] < 0;
          has_positive |= s[c] > 0;
        }
        if(!has_negative || !has_positive)
          continue;
        std::vector<Item> items;
        std::vector<std::array<double, 3>> points;
        for(int c = 0; c < 4; ++c)
          if(s[c] == 0)
          {
            items.push_back(Item{std::int8_t(c), -1});
            points.push_back({P[c][0], P[c][1], P[c][2]});
          }
        for(int a = 0; a < 4; ++a)
          for(int b = a + 1; b < 4; ++b)
            if(s[a] * s[b] < 0)
            {
              items.push_back(Item{std::int8_t(a), std::int8_t(b)});
              points.push_back({(P[a][0] + P[b][0]) / 2, (P[a][1] + P[b][1]) / 2, (P[a][2] + P[b][2]) / 2});
            }
        const double n[3] = {double(s[1] - s[0]), double(s[2] - s[0]), double(s[3] - s[0])};
        order_counterclockwise(items, points, n);
        t[code].size = int(items.size());
        for(std::size_t k = 0; k < items.size(); ++k)
          t[code].item[k] = items[k];
      }
      return t;
    }();
    return table;
  }

  // Corners of the face opposite corner l, counterclockwise seen from outside.
  static const std::array<std::array<int, 3>, 4>& face_table()
  {
    static const std::array<std::array<int, 3>, 4> table = [] {
      std::array<std::array<int, 3>, 4> t{};
      const double P[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for(int l = 0; l < 4; ++l)
      {
        std::vector<Item> items;
        std::vector<std::array<double, 3>> points;
        double centroid[3] = {0, 0, 0};
        for(int c = 0; c < 4; ++c)
          if(c != l)
          {
            items.push_back(Item{std::int8_t(c), -1});
            points.push_back({P[c][0], P[c][1], P[c][2]});
            for(int a = 0; a < 3; ++a)
              centroid[a] += P[c][a] / 3;
          }
        const double n[3] = {centroid[0] - P[l][0], centroid[1] - P[l][1], centroid[2] - P[l][2]};
        order_counterclockwise(items, points, n);
        for(int k = 0; k < 3; ++k)
          t[l][k] = items[k].a;
      }
      return t;
    }();
    return table;
  }

  static void order_counterclockwise(std::vector<Item>& items, const std::vector<std::array<double, 3>>& points,
                                     const double n[3])
  {
    double c[3] = {0, 0, 0};
    for(const auto& p : points)
      for(int a = 0; a < 3; ++a)
        c[a] += p[a] / double(points.size());
    double u[3] = {points[0][0] - c[0], points[0][1] - c[1], points[0][2] - c[2]};
    const double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    std::vector<std::pair<double, Item>> keyed;
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      const double d[3] = {points[k][0] - c[0], points[k][1] - c[1], points[k][2] - c[2]};
      keyed.emplace_back(std::atan2(d[0] * v[0] + d[1] * v[1] + d[2] * v[2], d[0] * u[0] + d[1] * u[1] + d[2] * u[2]),
                         items[k]);
    }
    std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for(std::size_t k = 0; k < keyed.size(); ++k)
      items[k] = keyed[k].second;
  }

  static std::uint8_t item_support(const Item& it)
  {
    return std::uint8_t((1u << it.a) | (it.b >= 0 ? (1u << it.b) : 0u));
  }

  // Edge planes of a polygon built from items: the face plane through both
  // ends (never `own_face`, the polygon's own plane when it is a face).
  static void set_edge_planes(Polygon& poly, const std::vector<std::uint8_t>& supports, int own_face)
  {
    const std::size_t n = supports.size();
    poly.edge_plane.resize(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const unsigned both = supports[k] | supports[(k + 1) % n];
      int plane = -1;
      for(int c = 0; c < 4 && plane < 0; ++c)
        if(!((both >> c) & 1) && c != own_face)
          plane = c;
      CGAL_assertion(plane >= 0);
      poly.edge_plane[k] = plane;
    }
  }

  // --- clipping -----------------------------------------------------------

  // Cuts every polygon of `pieces` by the zero line of field j.
  void cut(std::vector<Polygon>& pieces, int own_plane, int j)
  {
    const std::uint64_t bit = std::uint64_t(1) << j;
    m_next_pieces.clear();
    for(Polygon& poly : pieces)
    {
      const std::size_t n = poly.vertices.size();
      m_signs.resize(n);
      bool has_negative = false, has_positive = false;
      for(std::size_t k = 0; k < n; ++k)
      {
        const Rep& r = poly.vertices[k];
        bool defining = false;
        for(int f = 0; f < r.number_of_fields; ++f)
          defining |= (r.field[f] == j);
        m_signs[k] = defining ? 0 : (r.number_of_fields == 0 ? corner_sign(lowest_bit(r.support), j)
                                                              : field_sign_at(r, j));
        has_negative |= m_signs[k] < 0;
        has_positive |= m_signs[k] > 0;
      }
      if(!has_negative || !has_positive)
      {
        // All vertices zero would mean f_j vanishes on the polygon: excluded by the callers.
        CGAL_assertion(has_negative || has_positive);
        (has_negative ? poly.negative : poly.positive) |= bit;
        m_next_pieces.push_back(std::move(poly));
        continue;
      }
      Polygon below, above;
      below.negative = poly.negative | bit;
      below.positive = poly.positive;
      above.negative = poly.negative;
      above.positive = poly.positive | bit;
      for(std::size_t k = 0; k < n; ++k)
      {
        const std::size_t next = (k + 1) % n;
        const int su = m_signs[k], sv = m_signs[next];
        const int q = poly.edge_plane[k];
        const Rep& u = poly.vertices[k];
        Rep w;
        const bool crossing = su * sv < 0;
        if(crossing)
          w = rep_of_planes(own_plane, q, 4 + j);
        // Below (f_j <= 0).
        if(su <= 0)
        {
          below.vertices.push_back(u);
          below.edge_plane.push_back((sv <= 0 || su < 0) ? q : 4 + j);
          if(crossing)
          {
            below.vertices.push_back(w);
            below.edge_plane.push_back(4 + j);
          }
        }
        else if(sv < 0)
        {
          below.vertices.push_back(w);
          below.edge_plane.push_back(q);
        }
        // Above (f_j >= 0).
        if(su >= 0)
        {
          above.vertices.push_back(u);
          above.edge_plane.push_back((sv >= 0 || su > 0) ? q : 4 + j);
          if(crossing)
          {
            above.vertices.push_back(w);
            above.edge_plane.push_back(4 + j);
          }
        }
        else if(sv > 0)
        {
          above.vertices.push_back(w);
          above.edge_plane.push_back(q);
        }
      }
      m_next_pieces.push_back(std::move(below));
      m_next_pieces.push_back(std::move(above));
    }
    pieces.swap(m_next_pieces);
  }

  // --- output -------------------------------------------------------------

  Vertex make_vertex(const Rep& r) const
  {
    const std::array<Tbiso_corner, 4>& corner = *m_corner;
    int columns[4];
    const int m = support_columns(r, columns);
    Vertex out;
    out.key.corners = {no_id(), no_id(), no_id(), no_id()};
    out.key.zero_fields = 0;

    // Carrier simplex: the support corners with a positive barycentric coordinate.
    std::uint8_t carrier = r.support;
    if(m == 2)
    {
      const int i = r.field[0];
      if(sign_of(field_value(columns[0], i)) * sign_of(field_value(columns[1], i)) == 0)
        carrier = std::uint8_t(1u << (field_value(columns[0], i) == 0 ? columns[0] : columns[1]));
    }
    else if(m > 2)
    {
      for(int k = 0; k < m; ++k)
      {
        double e[4] = {0, 0, 0, 0};
        e[columns[k]] = 1;
        if(sign_at(r, e) == 0)
          carrier &= std::uint8_t(~(1u << columns[k]));
      }
    }
    int carrier_columns[4];
    int cm = 0;
    for(int c = 0; c < 4; ++c)
      if((carrier >> c) & 1)
        carrier_columns[cm++] = c;
    CGAL_assertion(cm >= 1);
    out.carrier = carrier;
    for(int k = 0; k < cm; ++k)
      out.key.corners[k] = corner[carrier_columns[k]].id;
    std::sort(out.key.corners.begin(), out.key.corners.begin() + cm);
    if(cm == 1)
      return out;

    // Fields vanishing at the point: only those not of one strict sign on the carrier can.
    std::uint64_t candidates = 0;
    {
      std::uint64_t any_negative = 0, any_positive = 0, all_nonzero = ~std::uint64_t(0);
      for(int k = 0; k < cm; ++k)
      {
        const Tbiso_corner& c = corner[carrier_columns[k]];
        any_negative |= c.negative;
        any_positive |= c.positive;
        all_nonzero &= (c.negative | c.positive);
      }
      candidates = m_fields & ((any_negative & any_positive) | ~all_nonzero);
    }
    std::uint64_t defining = 0;
    for(int f = 0; f < r.number_of_fields; ++f)
      defining |= std::uint64_t(1) << r.field[f];
    std::uint64_t zero_fields = defining;
    for(std::uint64_t mk = candidates & ~defining; mk != 0; mk &= mk - 1)
    {
      const int i = lowest_bit(mk);
      if(field_sign_at(r, i) == 0)
        zero_fields |= std::uint64_t(1) << i;
    }
    out.key.zero_fields = zero_fields;
    return out;
  }

  // The lexicographically first cm - 1 fields of `candidates` whose zero
  // sets meet the carrier's affine hull in one point (exact test).
  bool choose_defining_fields(const int* columns, int cm, std::uint64_t candidates, int* chosen, int depth,
                              int from) const
  {
    if(depth == cm - 1)
    {
      if(cm == 2) // det[f_a f_b; 1 1] = f_a - f_b: an exact comparison
        return field_value(columns[0], chosen[0]) != field_value(columns[1], chosen[0]);
      double den[16];
      for(int row = 0; row < depth; ++row)
        for(int k = 0; k < cm; ++k)
          den[row * cm + k] = field_value(columns[k], chosen[row]);
      for(int k = 0; k < cm; ++k)
        den[depth * cm + k] = 1.;
      return exact_sign_of_determinant(den, cm) != 0;
    }
    for(int i = from; i < 64; ++i)
      if((candidates >> i) & 1)
      {
        chosen[depth] = i;
        if(choose_defining_fields(columns, cm, candidates, chosen, depth + 1, i + 1))
          return true;
      }
    return false;
  }

  static std::size_t no_id() { return (std::numeric_limits<std::size_t>::max)(); }

  template <typename EmitFunction>
  void emit_polygon(const Polygon& poly, bool reverse, int label, int face, const EmitFunction& emit)
  {
    const std::size_t n = poly.vertices.size();
    m_out.resize(n);
    for(std::size_t k = 0; k < n; ++k)
      m_out[reverse ? n - 1 - k : k] = make_vertex(poly.vertices[k]);
    emit(label, m_out.data(), n, face);
  }

  // (a) faces on the zero plane of field i, which changes sign in the tetrahedron.
  template <typename EmitFunction>
  void zero_plane_faces(int i, std::uint64_t mixed, std::uint64_t fixed_negative, std::uint64_t fixed_positive,
                        const EmitFunction& emit)
  {
    // Fields proportional to f_i on the tetrahedron share its zero plane: the
    // lowest index of such a group emits, knowing on which side each member is negative.
    std::uint64_t same_side = std::uint64_t(1) << i, opposite_side = 0;
    const std::uint64_t negative_i = pattern(i, true), positive_i = pattern(i, false);
    for(std::uint64_t m = mixed & ~(std::uint64_t(1) << i); m != 0; m &= m - 1)
    {
      const int j = lowest_bit(m);
      const std::uint64_t negative_j = pattern(j, true), positive_j = pattern(j, false);
      const bool same = negative_j == negative_i && positive_j == positive_i;
      const bool opposite = negative_j == positive_i && positive_j == negative_i;
      if(!(same || opposite) || !proportional(i, j))
        continue;
      if(j < i)
        return;
      (same ? same_side : opposite_side) |= std::uint64_t(1) << j;
    }
    const std::uint64_t group = same_side | opposite_side;

    int code = 0;
    for(int c = 3; c >= 0; --c)
      code = code * 3 + corner_sign(c, i) + 1;
    const Item_polygon& items = zero_polygon_table()[code];
    m_pieces.clear();
    m_pieces.emplace_back();
    Polygon& poly = m_pieces.back();
    m_supports.clear();
    for(int k = 0; k < items.size; ++k)
    {
      const Item& it = items.item[k];
      Rep r;
      r.support = item_support(it);
      if(it.b >= 0)
      {
        r.number_of_fields = 1;
        r.field[0] = std::uint8_t(i);
      }
      poly.vertices.push_back(r);
      m_supports.push_back(r.support);
    }
    set_edge_planes(poly, m_supports, -1);

    for(std::uint64_t m = mixed & ~group; m != 0; m &= m - 1)
      cut(m_pieces, 4 + i, lowest_bit(m));

    for(const Polygon& piece : m_pieces)
    {
      const std::uint64_t negative = fixed_negative | piece.negative, positive = fixed_positive | piece.positive;
      // Side "below" f_i < 0: same-side members negative, opposite ones positive.
      const bool below = evaluate(negative | same_side, positive | opposite_side);
      const bool above = evaluate(negative | opposite_side, positive | same_side);
      if(below == above)
        continue;
      // The polygon's normal points to f_i > 0; it must point out of the set.
      emit_polygon(piece, /*reverse=*/above, i, -1, emit);
    }
  }

  // Corners where field i is negative (or positive), as a 4-bit mask.
  std::uint64_t pattern(int i, bool negative) const
  {
    std::uint64_t p = 0;
    for(int c = 0; c < 4; ++c)
      p |= std::uint64_t(((negative ? (*m_corner)[c].negative : (*m_corner)[c].positive) >> i) & 1) << c;
    return p;
  }

  // f_i and f_j proportional on the tetrahedron: all 2x2 minors of their corner values vanish.
  bool proportional(int i, int j) const
  {
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b)
        if(exact_sign_of_2x2(field_value(a, i), field_value(b, i), field_value(a, j), field_value(b, j)) != 0)
          return false;
    return true;
  }

  // (b) faces on the face opposite corner l of the tetrahedron.
  template <typename EmitFunction>
  void tetrahedron_face_faces(int l, std::uint64_t vanishing, const Apex& apex, const EmitFunction& emit)
  {
    const std::array<Tbiso_corner, 4>& corner = *m_corner;
    std::uint64_t any_negative = 0, any_positive = 0;
    for(int c = 0; c < 4; ++c)
      if(c != l)
      {
        any_negative |= corner[c].negative;
        any_positive |= corner[c].positive;
      }
    const std::uint64_t mixed = any_negative & any_positive & m_fields;
    const std::uint64_t fixed_negative = any_negative & ~mixed, fixed_positive = any_positive & ~mixed;
    const std::uint64_t inner_negative = corner[l].negative & vanishing;
    const std::uint64_t inner_positive = corner[l].positive & vanishing;
    const std::uint64_t outer_negative = apex.exists ? apex.negative & vanishing : 0;
    const std::uint64_t outer_positive = apex.exists ? apex.positive & vanishing : 0;
    if(apex.exists && inner_negative == outer_negative && inner_positive == outer_positive)
      return;
    if(!may_vary(mixed, fixed_negative | inner_negative, fixed_positive | inner_positive) &&
       !evaluate(fixed_negative | inner_negative, fixed_positive | inner_positive))
      return; // false on the inner side everywhere on the face

    const std::array<int, 3>& f = face_table()[l];
    m_pieces.clear();
    m_pieces.emplace_back();
    Polygon& poly = m_pieces.back();
    m_supports.clear();
    for(int k = 0; k < 3; ++k)
    {
      Rep r;
      r.support = std::uint8_t(1u << f[k]);
      poly.vertices.push_back(r);
      m_supports.push_back(r.support);
    }
    set_edge_planes(poly, m_supports, l);
    for(std::uint64_t m = mixed; m != 0; m &= m - 1)
      cut(m_pieces, l, lowest_bit(m));

    int label = domain_boundary_label;
    if(apex.exists)
      label = lowest_bit((inner_negative ^ outer_negative) | (inner_positive ^ outer_positive));
    for(const Polygon& piece : m_pieces)
    {
      const std::uint64_t negative = fixed_negative | piece.negative, positive = fixed_positive | piece.positive;
      if(!evaluate(negative | inner_negative, positive | inner_positive))
        continue;
      if(apex.exists && evaluate(negative | outer_negative, positive | outer_positive))
        continue;
      int piece_label = label;
      if(!apex.exists)
      {
        // A face on the domain boundary on which a field vanishes identically
        // lies on that field's zero set.  If the field bounds the set there
        // (with its sign reversed on the inner side the expression is false),
        // the face is that field's, not a closing face: the lowest such field.
        // (The bunny inside its convex hull: f0, the distance to the bunny,
        // vanishes on the hull faces where the bunny touches its hull.)
        const std::uint64_t in_negative = negative | inner_negative, in_positive = positive | inner_positive;
        for(std::uint64_t m = inner_negative | inner_positive; m != 0; m &= m - 1)
        {
          const std::uint64_t bit = m & (~m + 1);
          if(!evaluate((in_negative & ~bit) | (in_positive & bit), (in_positive & ~bit) | (in_negative & bit)))
          {
            piece_label = lowest_bit(bit);
            break;
          }
        }
      }
      emit_polygon(piece, false, piece_label, l, emit);
    }
  }

  std::uint64_t m_fields;
  bool m_close;
  std::vector<Sign_term> m_terms;

  const std::array<Tbiso_corner, 4>* m_corner = nullptr;
  std::vector<Polygon> m_pieces, m_next_pieces;
  std::vector<std::uint8_t> m_supports;
  std::vector<int> m_signs;
  std::vector<Vertex> m_out;
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_TETRAHEDRON_H
