// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Exhaustive proof that the derived Marching Cubes table is watertight,
// consistently (outward) oriented and 2-manifold.  Every oracle here is
// independent of the table's derivation: cube geometry comes from
// coordinates, the face rule is re-implemented from its statement, the
// orientation is checked against the cube's own outward faces, and the
// global topology (components, Euler characteristic) is predicted from the
// lattice alone.

#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
using Table = BI::Marching_cubes_table;

namespace {

typedef std::array<double, 3> Vec3;
typedef std::pair<int, int> Segment; // undirected, first < second

// ---------------------------------------------------------------------------
// Geometry of the unit cube, from coordinates only.
// ---------------------------------------------------------------------------

Vec3 corner_point(int k) { return {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}; }
bool inside(unsigned code, int k) { return ((code >> k) & 1u) != 0; }

Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double det(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

Segment make_segment(int a, int b) { return a < b ? Segment(a, b) : Segment(b, a); }

int popcount(unsigned x)
{
  int n = 0;
  for(; x; x &= x - 1)
    ++n;
  return n;
}

bool edge_on_face(int e, int axis, int side)
{
  const std::array<int, 2> c = BI::cube_edge_corners(e);
  return corner_point(c[0])[axis] == side && corner_point(c[1])[axis] == side;
}

bool edges_share_face(int e1, int e2)
{
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
      if(edge_on_face(e1, axis, side) && edge_on_face(e2, axis, side))
        return true;
  return false;
}

bool is_changing(unsigned code, int e)
{
  const std::array<int, 2> c = BI::cube_edge_corners(e);
  return inside(code, c[0]) != inside(code, c[1]);
}

// Statement of the face rule, re-implemented: a face with 2 sign-changing
// edges joins them; a face with 4 (ambiguous) pairs the edges that share an
// inside corner (default: cut off, i.e. separate, the inside corners) or that
// share an outside corner (join_inside).
std::set<Segment> face_rule_segments(unsigned code, int axis, int side, bool join)
{
  std::vector<int> changing;
  for(int e = 0; e < 12; ++e)
    if(edge_on_face(e, axis, side) && is_changing(code, e))
      changing.push_back(e);
  std::set<Segment> segments;
  if(changing.size() == 2)
    segments.insert(make_segment(changing[0], changing[1]));
  else if(changing.size() == 4)
    for(std::size_t i = 0; i < 4; ++i)
      for(std::size_t j = i + 1; j < 4; ++j)
      {
        const std::array<int, 2> a = BI::cube_edge_corners(changing[i]), b = BI::cube_edge_corners(changing[j]);
        for(int ca : a)
          for(int cb : b)
            if(ca == cb && inside(code, ca) != join)
              segments.insert(make_segment(changing[i], changing[j]));
      }
  return segments;
}

std::set<Segment> cube_segments(unsigned code, unsigned mask)
{
  std::set<Segment> all;
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      const std::set<Segment> s = face_rule_segments(code, axis, side, (mask >> (2 * axis + side)) & 1u);
      all.insert(s.begin(), s.end());
    }
  return all;
}

// The join masks that select distinct entries of `code`.
std::vector<unsigned> normalized_masks(unsigned code)
{
  std::vector<unsigned> masks;
  const unsigned ambiguous = BI::ambiguous_face_mask(code);
  for(unsigned m = 0; m < 64; ++m)
    if((m & ~ambiguous) == 0)
      masks.push_back(m);
  return masks;
}

// An oriented triangle up to rotation.
std::array<int, 3> rotate_smallest_first(std::array<int, 3> t)
{
  while(t[0] > t[1] || t[0] > t[2])
    t = {t[1], t[2], t[0]};
  return t;
}

std::set<std::array<int, 3>> oriented_triangles(const Table& table, unsigned code, unsigned mask, bool reversed)
{
  std::set<std::array<int, 3>> result;
  for(const Table::Triangle& t : table.triangles(code, mask))
    result.insert(rotate_smallest_first(reversed ? std::array<int, 3>{t[0], t[2], t[1]}
                                                 : std::array<int, 3>{t[0], t[1], t[2]}));
  return result;
}

// ---------------------------------------------------------------------------
// Conventions
// ---------------------------------------------------------------------------

TEST(Cube_conventions, edges_match_coordinates)
{
  const int documented[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                 {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::set<Segment> seen;
  for(int e = 0; e < 12; ++e)
  {
    const std::array<int, 2> c = BI::cube_edge_corners(e);
    EXPECT_EQ(c[0], documented[e][0]);
    EXPECT_EQ(c[1], documented[e][1]);
    const Vec3 d = corner_point(c[1]) - corner_point(c[0]);
    // one unit step along the axis, lower corner first
    EXPECT_EQ(dot(d, d), 1.0);
    EXPECT_EQ(d[BI::cube_edge_axis(e)], 1.0);
    const std::array<int, 3> o = BI::cube_edge_origin_offset(e);
    for(int i = 0; i < 3; ++i)
      EXPECT_EQ(double(o[i]), corner_point(c[0])[i]);
    EXPECT_EQ(BI::cube_edge_origin_corner(e), c[0]);
    EXPECT_EQ(BI::cube_edge_index(c[0], c[1]), e);
    EXPECT_EQ(BI::cube_edge_index(c[1], c[0]), e);
    seen.insert(make_segment(c[0], c[1]));
    const std::array<int, 2> f = BI::cube_edge_faces(e);
    EXPECT_LT(f[0], f[1]);
    for(int face : f)
      EXPECT_TRUE(edge_on_face(e, face >> 1, face & 1));
  }
  EXPECT_EQ(seen.size(), 12u);
}

TEST(Cube_conventions, faces_are_counterclockwise_from_outside)
{
  for(int f = 0; f < 6; ++f)
  {
    EXPECT_EQ(BI::cube_face_axis(f), f >> 1);
    EXPECT_EQ(BI::cube_face_side(f), f & 1);
    const std::array<int, 4> c = BI::cube_face_corners(f);
    const std::array<int, 4> e = BI::cube_face_edges(f);
    Vec3 outward = {0, 0, 0};
    outward[f >> 1] = (f & 1) ? 1 : -1;
    std::set<int> distinct(c.begin(), c.end());
    EXPECT_EQ(distinct.size(), 4u);
    EXPECT_EQ(c[0], *std::min_element(c.begin(), c.end()));
    for(int i = 0; i < 4; ++i)
    {
      EXPECT_EQ(corner_point(c[i])[f >> 1], double(f & 1));
      const Vec3 a = corner_point(c[i]), b = corner_point(c[(i + 1) % 4]), d = corner_point(c[(i + 2) % 4]);
      EXPECT_GT(dot(cross(b - a, d - b), outward), 0.0) << "face " << f;
      const std::array<int, 2> ec = BI::cube_edge_corners(e[i]);
      EXPECT_EQ(make_segment(ec[0], ec[1]), make_segment(c[i], c[(i + 1) % 4]));
    }
  }
}

TEST(Cube_conventions, ambiguity_and_sign_changes)
{
  for(unsigned code = 0; code < 256; ++code)
  {
    unsigned expected_mask = 0;
    for(int f = 0; f < 6; ++f)
    {
      std::vector<int> in;
      for(int k = 0; k < 8; ++k)
        if(corner_point(k)[f >> 1] == (f & 1) && inside(code, k))
          in.push_back(k);
      // two inside corners that are not joined by an edge: a diagonal
      const bool ambiguous = in.size() == 2 && popcount(unsigned(in[0] ^ in[1])) == 2;
      EXPECT_EQ(BI::is_ambiguous_face(code, f), ambiguous) << code << " " << f;
      if(ambiguous)
        expected_mask |= 1u << f;
    }
    EXPECT_EQ(BI::ambiguous_face_mask(code), expected_mask);
    for(unsigned m = 0; m < 256; ++m)
      EXPECT_EQ(BI::normalized_join_mask(code, m), m & expected_mask);
    for(int e = 0; e < 12; ++e)
      EXPECT_EQ(BI::is_sign_changing_edge(code, e), is_changing(code, e));
  }
}

// Corner 0 alone inside: one triangle on edges (0,1), (0,2), (0,4) whose
// normal points away from corner 0, wherever its vertices sit on the edges.
TEST(Marching_cubes_table, seed_convention_single_corner)
{
  const Table& table = Table::instance();
  const Table::Triangle_range r = BI::marching_cubes_triangles(1u);
  ASSERT_EQ(r.size(), 1u);
  std::set<int> vertices(r[0].begin(), r[0].end());
  EXPECT_EQ(vertices, (std::set<int>{BI::cube_edge_index(0, 1), BI::cube_edge_index(0, 2), BI::cube_edge_index(0, 4)}));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> t(0.01, 0.99);
  for(int trial = 0; trial < 100; ++trial)
  {
    Vec3 p[3];
    for(int i = 0; i < 3; ++i)
    {
      const std::array<int, 2> c = BI::cube_edge_corners(r[0][i]);
      const double s = trial == 0 ? 0.5 : t(random);
      p[i] = corner_point(c[0]) + s * (corner_point(c[1]) - corner_point(c[0]));
    }
    EXPECT_GT(dot(cross(p[1] - p[0], p[2] - p[0]), Vec3{1, 1, 1}), 0.0);
  }
  // and the complement: the normal points toward the single outside corner
  const Table::Triangle_range s = table.triangles(0xFEu);
  ASSERT_EQ(s.size(), 1u);
  Vec3 p[3];
  for(int i = 0; i < 3; ++i)
  {
    const std::array<int, 2> c = BI::cube_edge_corners(s[0][i]);
    p[i] = 0.5 * (corner_point(c[0]) + corner_point(c[1]));
  }
  EXPECT_LT(dot(cross(p[1] - p[0], p[2] - p[0]), Vec3{1, 1, 1}), 0.0);
}

TEST(Marching_cubes_table, masks_are_normalized)
{
  const Table& table = Table::instance();
  std::size_t expected_entries = 0;
  for(unsigned code = 0; code < 256; ++code)
  {
    const unsigned ambiguous = BI::ambiguous_face_mask(code);
    expected_entries += std::size_t(1) << popcount(ambiguous);
    std::set<const Table::Triangle*> distinct;
    for(unsigned m = 0; m < 256; ++m)
    {
      const Table::Triangle_range a = table.triangles(code, m), b = table.triangles(code, m & ambiguous);
      EXPECT_EQ(a.begin(), b.begin());
      EXPECT_EQ(a.size(), b.size());
      if(!a.empty())
        distinct.insert(a.begin());
    }
    if(code != 0 && code != 255)
    {
      EXPECT_EQ(distinct.size(), std::size_t(1) << popcount(ambiguous)) << code;
    }
  }
  EXPECT_EQ(table.number_of_entries(), expected_entries);
}

// ---------------------------------------------------------------------------
// 1. Each entry is a disk-like patch per polygon whose boundary is exactly the
//    face rule's segments and which has no same-face chord.
// ---------------------------------------------------------------------------

void check_local_patch(const Table& table, unsigned code, unsigned mask)
{
  const Table::Triangle_range triangles = table.triangles(code, mask);
  const unsigned polygons = table.number_of_polygons(code, mask);
  const std::set<Segment> segments = cube_segments(code, mask);

  // Polygons: consecutive vertices are exactly the face segments, every
  // sign-changing edge appears in exactly one polygon.
  std::set<Segment> polygon_sides;
  std::map<int, unsigned> polygon_of;
  for(unsigned p = 0; p < polygons; ++p)
  {
    const Table::Vertex_range cycle = table.polygon(code, mask, p);
    ASSERT_GE(cycle.size(), 3u);
    for(std::size_t i = 0; i < cycle.size(); ++i)
    {
      ASSERT_TRUE(polygon_of.emplace(cycle[i], p).second) << "edge point in two polygons";
      polygon_sides.insert(make_segment(cycle[i], cycle[(i + 1) % cycle.size()]));
    }
  }
  EXPECT_EQ(polygon_sides, segments);
  for(int e = 0; e < 12; ++e)
    EXPECT_EQ(polygon_of.count(e) == 1, is_changing(code, e)) << "edge " << e;

  // Triangles: valid vertices, one polygon each, no repeated vertex.
  std::map<std::pair<int, int>, int> directed;
  std::set<int> used;
  std::vector<int> triangles_of_polygon(polygons, 0);
  for(const Table::Triangle& t : triangles)
  {
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "degenerate triangle";
    int owner = -1;
    for(int v : t)
    {
      used.insert(v);
      int p;
      if(Table::is_centre_vertex(v))
      {
        p = v - 12;
        ASSERT_LT(unsigned(p), polygons);
      }
      else
      {
        ASSERT_TRUE(is_changing(code, v)) << "vertex on an edge without sign change";
        p = int(polygon_of.at(v));
      }
      ASSERT_TRUE(owner == -1 || owner == p) << "triangle spans two polygons";
      owner = p;
    }
    ++triangles_of_polygon[owner];
    for(int i = 0; i < 3; ++i)
      ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for(int e = 0; e < 12; ++e)
    EXPECT_EQ(used.count(e) == 1, is_changing(code, e)) << "edge " << e;

  // Edges of the complex: face segments once, everything else twice with
  // opposite directions; no chord between edge points of a common face.
  std::set<Segment> boundary;
  for(const auto& d : directed)
  {
    const int a = d.first.first, b = d.first.second;
    EXPECT_EQ(d.second, 1) << "directed edge used twice";
    const auto reverse = directed.find({b, a});
    const int back = reverse == directed.end() ? 0 : reverse->second;
    if(back == 0)
      boundary.insert(make_segment(a, b));
    else if(a < 12 && b < 12)
    {
      EXPECT_FALSE(edges_share_face(a, b)) << "same-face chord " << a << "-" << b;
    }
  }
  EXPECT_EQ(boundary, segments);

  // Every vertex's link is one path (edge point) or one cycle (centre), and
  // each polygon's patch has Euler characteristic 1: a disk.
  for(int v : used)
  {
    std::map<int, int> next, previous;
    for(const Table::Triangle& t : triangles)
      for(int i = 0; i < 3; ++i)
        if(t[i] == v)
        {
          const int a = t[(i + 1) % 3], b = t[(i + 2) % 3];
          ASSERT_TRUE(next.emplace(a, b).second);
          ASSERT_TRUE(previous.emplace(b, a).second);
        }
    int start = next.begin()->first;
    for(const auto& n : next)
      if(previous.count(n.first) == 0)
        start = n.first;
    std::size_t walked = 0;
    int current = start;
    for(auto it = next.find(current); it != next.end() && walked <= next.size(); it = next.find(current))
    {
      current = it->second;
      ++walked;
      if(current == start)
        break;
    }
    EXPECT_EQ(walked, next.size()) << "link of vertex " << v << " is not a single fan";
    EXPECT_EQ(current == start, Table::is_centre_vertex(v)) << "link of vertex " << v;
  }
  std::vector<int> vertices_of_polygon(polygons, 0), edges_of_polygon(polygons, 0);
  for(int v : used)
    ++vertices_of_polygon[Table::is_centre_vertex(v) ? v - 12 : int(polygon_of.at(v))];
  for(const auto& d : directed)
  {
    const int a = d.first.first, b = d.first.second;
    if(a < b || directed.count({b, a}) == 0)
      ++edges_of_polygon[Table::is_centre_vertex(a) ? a - 12 : int(polygon_of.at(a))];
  }
  for(unsigned p = 0; p < polygons; ++p)
    EXPECT_EQ(vertices_of_polygon[p] - edges_of_polygon[p] + triangles_of_polygon[p], 1) << "polygon " << p;
  EXPECT_EQ(table.uses_centre_vertex(code, mask),
            std::any_of(used.begin(), used.end(), [](int v) { return Table::is_centre_vertex(v); }));
}

TEST(Marching_cubes_table, every_entry_is_a_patch_bounded_by_the_face_rule)
{
  const Table& table = Table::instance();
  for(unsigned code = 0; code < 256; ++code)
    for(unsigned mask : normalized_masks(code))
    {
      SCOPED_TRACE("code " + std::to_string(code) + " mask " + std::to_string(mask));
      check_local_patch(table, code, mask);
      if(::testing::Test::HasFatalFailure())
        return;
    }
}

TEST(Marching_cubes_table, statistics_match_the_manual)
{
  const Table& table = Table::instance();
  std::size_t fallback = 0, fallback_default = 0, max_triangles = 0, max_default = 0;
  for(unsigned code = 0; code < 256; ++code)
    for(unsigned mask : normalized_masks(code))
    {
      const std::size_t n = table.triangles(code, mask).size();
      max_triangles = std::max(max_triangles, n);
      fallback += table.uses_centre_vertex(code, mask);
      if(mask == 0)
      {
        fallback_default += table.uses_centre_vertex(code, mask);
        max_default = std::max(max_default, n);
      }
    }
  EXPECT_EQ(fallback, table.number_of_fallback_entries());
  EXPECT_EQ(max_triangles, table.max_number_of_triangles());
  EXPECT_LE(max_triangles, std::size_t(Table::max_number_of_triangles_bound));
  // Numbers stated in doc/Boolean_isosurfacing_3/marching_cubes_table.md.
  EXPECT_EQ(table.number_of_entries(), 656u);
  EXPECT_EQ(fallback_default, 0u); // the default rule never needs a centre vertex
  EXPECT_EQ(fallback, 116u);
  EXPECT_EQ(max_default, 5u); // as in the classic table
  EXPECT_EQ(max_triangles, 12u);
}

// ---------------------------------------------------------------------------
// 2. Orientation: the table's triangles plus the inside part of the cube's own
//    (outward oriented) faces form a closed 2-cycle, whose volume is the
//    inside volume: positive, and complementary to the complement's.
// ---------------------------------------------------------------------------

const int corner_key = 100; // key of corner k is corner_key + k; 0..15 as in the table

struct Cycle_2
{
  std::vector<std::array<int, 3>> triangles;
  std::map<int, Vec3> points;
};

// Inside part of face (axis, side), fan-triangulated, oriented outward of the
// cube: walk the face's boundary counterclockwise (seen from outside) through
// the inside corners and jump across the face rule's segments.
void add_inside_face_region(unsigned code, int axis, int side, bool join, Cycle_2& z)
{
  int b = (axis + 1) % 3, c = (axis + 2) % 3; // e_b x e_c = e_axis
  if(side == 0)
    std::swap(b, c);
  std::vector<int> corner;
  for(int k = 0; k < 8; ++k)
    if(corner_point(k)[axis] == side)
      corner.push_back(k);
  std::sort(corner.begin(), corner.end(), [&](int p, int q) {
    return std::atan2(corner_point(p)[c] - 0.5, corner_point(p)[b] - 0.5) <
           std::atan2(corner_point(q)[c] - 0.5, corner_point(q)[b] - 0.5);
  });
  int edge[4];
  bool changing[4];
  for(int i = 0; i < 4; ++i)
  {
    edge[i] = -1;
    for(int e = 0; e < 12; ++e)
      if(make_segment(BI::cube_edge_corners(e)[0], BI::cube_edge_corners(e)[1]) ==
         make_segment(corner[i], corner[(i + 1) % 4]))
        edge[i] = e;
    ASSERT_NE(edge[i], -1);
    changing[i] = inside(code, corner[i]) != inside(code, corner[(i + 1) % 4]);
  }
  std::map<int, int> partner;
  for(const Segment& s : face_rule_segments(code, axis, side, join))
  {
    partner[s.first] = s.second;
    partner[s.second] = s.first;
  }
  std::vector<std::vector<int>> loops;
  if(std::none_of(changing, changing + 4, [](bool x) { return x; }))
  {
    if(inside(code, corner[0]))
      loops.push_back({corner_key + corner[0], corner_key + corner[1], corner_key + corner[2], corner_key + corner[3]});
  }
  else
  {
    bool used[4] = {false, false, false, false};
    for(int i = 0; i < 4; ++i)
    {
      if(used[i] || !inside(code, corner[i]) || inside(code, corner[(i + 1) % 4]))
        continue; // start at a leaving edge
      std::vector<int> loop;
      int current = i;
      do
      {
        used[current] = true;
        loop.push_back(edge[current]);
        ASSERT_EQ(partner.count(edge[current]), 1u);
        const int j = int(std::find(edge, edge + 4, partner[edge[current]]) - edge);
        ASSERT_LT(j, 4);
        ASSERT_TRUE(!inside(code, corner[j]) && inside(code, corner[(j + 1) % 4])) << "segment does not enter";
        loop.push_back(edge[j]);
        int m = (j + 1) % 4;
        for(;;)
        {
          loop.push_back(corner_key + corner[m]);
          if(changing[m])
            break;
          m = (m + 1) % 4;
        }
        current = m;
      } while(current != i);
      loops.push_back(loop);
    }
  }
  for(const std::vector<int>& loop : loops)
    for(std::size_t j = 1; j + 1 < loop.size(); ++j)
      z.triangles.push_back({loop[0], loop[j], loop[j + 1]});
}

// `t[e]`: position of edge point e along its edge, from its lower corner.
Cycle_2 inside_boundary(const Table& table, unsigned code, unsigned mask, const std::array<double, 12>& t)
{
  Cycle_2 z;
  for(int k = 0; k < 8; ++k)
    z.points[corner_key + k] = corner_point(k);
  for(int e = 0; e < 12; ++e)
  {
    const std::array<int, 2> c = BI::cube_edge_corners(e);
    z.points[e] = corner_point(c[0]) + t[e] * (corner_point(c[1]) - corner_point(c[0]));
  }
  for(unsigned p = 0; p < table.number_of_polygons(code, mask); ++p)
  {
    Vec3 centre = {0, 0, 0};
    const Table::Vertex_range cycle = table.polygon(code, mask, p);
    for(std::uint8_t e : cycle)
      centre = centre + (1.0 / double(cycle.size())) * z.points[e];
    z.points[Table::centre_vertex(p)] = centre;
  }
  for(const Table::Triangle& tr : table.triangles(code, mask))
    z.triangles.push_back({tr[0], tr[1], tr[2]});
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
      add_inside_face_region(code, axis, side, (mask >> (2 * axis + side)) & 1u, z);
  return z;
}

bool is_closed(const std::vector<std::array<int, 3>>& triangles)
{
  std::map<std::pair<int, int>, int> balance;
  for(const std::array<int, 3>& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      const int a = t[i], b = t[(i + 1) % 3];
      balance[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  return std::all_of(balance.begin(), balance.end(), [](const std::pair<const std::pair<int, int>, int>& x) {
    return x.second == 0;
  });
}

double volume(const Cycle_2& z, const Vec3& origin)
{
  double v = 0;
  for(const std::array<int, 3>& t : z.triangles)
    v += det(z.points.at(t[0]) - origin, z.points.at(t[1]) - origin, z.points.at(t[2]) - origin);
  return v / 6;
}

TEST(Marching_cubes_table, triangles_point_out_of_the_inside)
{
  const Table& table = Table::instance();
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> position(0.001, 0.999);
  bool control_done = false;
  for(unsigned code = 0; code < 256; ++code)
    for(unsigned mask : normalized_masks(code))
    {
      SCOPED_TRACE("code " + std::to_string(code) + " mask " + std::to_string(mask));
      const unsigned complement = ~code & 0xFFu;
      const unsigned complement_mask = BI::ambiguous_face_mask(code) & ~mask;
      for(int trial = 0; trial < 25; ++trial)
      {
        std::array<double, 12> t;
        for(double& x : t)
          x = trial == 0 ? 0.5 : position(random);
        const Cycle_2 z = inside_boundary(table, code, mask, t);
        if(::testing::Test::HasFatalFailure())
          return;
        ASSERT_TRUE(is_closed(z.triangles));
        const double v = volume(z, {0.5, 0.5, 0.5});
        EXPECT_NEAR(v, volume(z, {-3.0, 7.0, 2.5}), 1e-12);
        if(trial == 0)
        {
          // edge midpoints: a genuine solid, strictly inside the cube
          if(code != 0)
          {
            EXPECT_GT(v, 0.0);
          }
          if(code != 255)
          {
            EXPECT_LT(v, 1.0);
          }
        }
        const Cycle_2 w = inside_boundary(table, complement, complement_mask, t);
        ASSERT_TRUE(is_closed(w.triangles));
        EXPECT_NEAR(v + volume(w, {0.5, 0.5, 0.5}), 1.0, 1e-12);

        // Negative control: the same check rejects one flipped triangle.
        if(!control_done && !table.triangles(code, mask).empty())
        {
          Cycle_2 flipped = z;
          std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
          EXPECT_FALSE(is_closed(flipped.triangles));
          EXPECT_GT(std::abs(volume(flipped, {0.5, 0.5, 0.5}) - volume(flipped, {-3.0, 7.0, 2.5})), 1e-9);
          control_done = true;
        }
      }
    }
  EXPECT_TRUE(control_done);
}

// Complementing every corner and taking the opposite choice on every
// ambiguous face describes the same surface seen from the other side: the
// table must give exactly the same triangles, reversed.
TEST(Marching_cubes_table, complement_with_opposite_rule_reverses_triangles)
{
  const Table& table = Table::instance();
  for(unsigned code = 0; code < 256; ++code)
    for(unsigned mask : normalized_masks(code))
    {
      const unsigned complement = ~code & 0xFFu;
      const unsigned complement_mask = BI::ambiguous_face_mask(code) & ~mask;
      EXPECT_EQ(BI::ambiguous_face_mask(complement), BI::ambiguous_face_mask(code));
      EXPECT_EQ(oriented_triangles(table, code, mask, false), oriented_triangles(table, complement, complement_mask, true))
        << "code " << code << " mask " << mask;
      EXPECT_EQ(table.number_of_polygons(code, mask), table.number_of_polygons(complement, complement_mask));
    }
}

// ---------------------------------------------------------------------------
// 3. Any two cubes sharing a face agree on it.
// ---------------------------------------------------------------------------

TEST(Marching_cubes_table, face_neighbours_agree_on_the_shared_face)
{
  const Table& table = Table::instance();
  std::mt19937 random(11);
  // Global key of an edge point: lattice point of the edge's lower corner on a
  // 3x3x3 patch, times 3, plus axis.
  auto key = [](const std::array<int, 3>& origin, int e) {
    const std::array<int, 3> o = BI::cube_edge_origin_offset(e);
    return (((origin[0] + o[0]) * 3 + origin[1] + o[1]) * 3 + origin[2] + o[2]) * 3 + BI::cube_edge_axis(e);
  };
  std::size_t pairs = 0;
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::array<int, 3> origin_a = {0, 0, 0};
    std::array<int, 3> origin_b = {0, 0, 0};
    origin_b[axis] = 1;
    const int shared_a = 2 * axis + 1, shared_b = 2 * axis; // face indices in each cube
    for(unsigned code_a = 0; code_a < 256; ++code_a)
      for(unsigned free_bits = 0; free_bits < 16; ++free_bits)
      {
        // B's corners on the shared face copy A's; its other 4 are free.
        unsigned code_b = 0;
        int next_free = 0;
        for(int k = 0; k < 8; ++k)
        {
          const bool state = (k >> axis) & 1 ? ((free_bits >> next_free++) & 1u) != 0 : inside(code_a, k | (1 << axis));
          code_b |= unsigned(state) << k;
        }
        for(int variant = 0; variant < 4; ++variant)
        {
          // variant 0: default rule; 1, 2: shared bit forced, others random; 3: all random
          const unsigned shared_bit = variant == 0 ? 0u : variant == 3 ? (random() & 1u) : unsigned(variant - 1);
          unsigned mask_a = variant == 0 ? 0u : unsigned(random() & 63u), mask_b = variant == 0 ? 0u : unsigned(random() & 63u);
          mask_a = (mask_a & ~(1u << shared_a)) | (shared_bit << shared_a);
          mask_b = (mask_b & ~(1u << shared_b)) | (shared_bit << shared_b);
          ++pairs;

          std::map<std::pair<int, int>, int> directed;
          std::set<Segment> boundary_a, boundary_b;
          auto on_shared_plane = [&](const std::array<int, 3>& origin, int v) {
            if(Table::is_centre_vertex(v))
              return false;
            const std::array<int, 2> c = BI::cube_edge_corners(v);
            return origin[axis] + BI::cube_corner_offset(c[0], axis) == 1 &&
                   origin[axis] + BI::cube_corner_offset(c[1], axis) == 1;
          };
          auto add = [&](unsigned code, unsigned mask, const std::array<int, 3>& origin, int cube) {
            for(const Table::Triangle& t : table.triangles(code, mask))
              for(int i = 0; i < 3; ++i)
              {
                const int u = t[i], v = t[(i + 1) % 3];
                if(!on_shared_plane(origin, u) || !on_shared_plane(origin, v))
                  continue;
                ++directed[{key(origin, u), key(origin, v)}];
                (cube == 0 ? boundary_a : boundary_b).insert(make_segment(key(origin, u), key(origin, v)));
              }
          };
          add(code_a, mask_a, origin_a, 0);
          add(code_b, mask_b, origin_b, 1);
          ASSERT_EQ(boundary_a, boundary_b) << "axis " << axis << " codes " << code_a << " " << code_b << " masks "
                                            << mask_a << " " << mask_b;
          for(const auto& d : directed)
          {
            ASSERT_EQ(d.second, 1);
            ASSERT_EQ(directed.count({d.first.second, d.first.first}), 1u) << "edge not matched with opposite direction";
          }
          // and those segments are the face rule's
          std::set<Segment> expected;
          for(const Segment& s : face_rule_segments(code_a, axis, 1, (mask_a >> shared_a) & 1u))
            expected.insert(make_segment(key(origin_a, s.first), key(origin_a, s.second)));
          ASSERT_EQ(boundary_a, expected);
        }
      }
  }
  EXPECT_EQ(pairs, 3u * 4096u * 4u);
}

// ---------------------------------------------------------------------------
// 4, 5. Whole lattices.
// ---------------------------------------------------------------------------

struct Lattice
{
  explicit Lattice(int n) : n(n), in(std::size_t(n) * n * n, 0), join(3 * std::size_t(n) * n * n, 0) {}
  int index(int x, int y, int z) const { return (z * n + y) * n + x; }
  bool at(int x, int y, int z) const { return in[index(x, y, z)] != 0; }
  // Decision of the lattice face spanned at point (x,y,z) normal to `axis`.
  bool join_at(int x, int y, int z, int axis) const { return join[3 * index(x, y, z) + axis] != 0; }

  int n;
  std::vector<std::uint8_t> in;
  std::vector<std::uint8_t> join;
};

struct Mesh
{
  std::vector<std::array<int, 3>> triangles;
  std::vector<Vec3> points;
  std::vector<std::int64_t> keys; // global key of each vertex
};

unsigned cube_code(const Lattice& l, int x, int y, int z)
{
  unsigned code = 0;
  for(int k = 0; k < 8; ++k)
    code |= unsigned(l.at(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1))) << k;
  return code;
}

unsigned cube_mask(const Lattice& l, int x, int y, int z)
{
  unsigned mask = 0;
  for(int f = 0; f < 6; ++f)
  {
    const int axis = f >> 1, side = f & 1;
    std::array<int, 3> p = {x, y, z};
    p[axis] += side;
    mask |= unsigned(l.join_at(p[0], p[1], p[2], axis)) << f;
  }
  return mask;
}

// Welds edge points by (lower lattice point, axis) and centre vertices by
// (cube, polygon); edge points at midpoints.
Mesh build_mesh(const Lattice& l, const Table& table)
{
  Mesh mesh;
  const int n = l.n;
  std::vector<int> edge_vertex(3 * std::size_t(n) * n * n, -1);
  std::map<std::pair<int, int>, int> centre_vertex;
  for(int z = 0; z + 1 < n; ++z)
    for(int y = 0; y + 1 < n; ++y)
      for(int x = 0; x + 1 < n; ++x)
      {
        const unsigned code = cube_code(l, x, y, z), mask = cube_mask(l, x, y, z);
        const int cube = l.index(x, y, z);
        auto edge_point = [&](int e) {
          const std::array<int, 3> o = BI::cube_edge_origin_offset(e);
          const int axis = BI::cube_edge_axis(e);
          const int key = 3 * l.index(x + o[0], y + o[1], z + o[2]) + axis;
          if(edge_vertex[key] == -1)
          {
            edge_vertex[key] = int(mesh.points.size());
            Vec3 p = {double(x + o[0]), double(y + o[1]), double(z + o[2])};
            p[axis] += 0.5;
            mesh.points.push_back(p);
            mesh.keys.push_back(key);
          }
          return edge_vertex[key];
        };
        for(const Table::Triangle& t : table.triangles(code, mask))
        {
          std::array<int, 3> tri;
          for(int i = 0; i < 3; ++i)
          {
            if(!Table::is_centre_vertex(t[i]))
            {
              tri[i] = edge_point(t[i]);
              continue;
            }
            const int p = t[i] - 12;
            auto found = centre_vertex.find({cube, p});
            if(found == centre_vertex.end())
            {
              Vec3 c = {0, 0, 0};
              const Table::Vertex_range cycle = table.polygon(code, mask, unsigned(p));
              for(std::uint8_t e : cycle)
                c = c + (1.0 / double(cycle.size())) * mesh.points[edge_point(e)];
              found = centre_vertex.emplace(std::make_pair(cube, p), int(mesh.points.size())).first;
              mesh.points.push_back(c);
              mesh.keys.push_back(3 * std::int64_t(n) * n * n + 4 * std::int64_t(cube) + p);
            }
            tri[i] = found->second;
          }
          mesh.triangles.push_back(tri);
        }
      }
  return mesh;
}

struct Mesh_topology
{
  std::string error; // empty if closed, oriented, 2-manifold, no duplicates
  int components = 0;
  long euler = 0;
};

Mesh_topology analyse(const Mesh& mesh)
{
  Mesh_topology r;
  const std::size_t nv = mesh.points.size();
  std::vector<std::uint64_t> directed;
  std::set<std::array<int, 3>> unordered;
  for(const std::array<int, 3>& t : mesh.triangles)
  {
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      r.error = "degenerate triangle";
    std::array<int, 3> s = t;
    std::sort(s.begin(), s.end());
    if(!unordered.insert(s).second)
      r.error = "duplicated triangle";
    for(int i = 0; i < 3; ++i)
      directed.push_back((std::uint64_t(t[i]) << 32) | std::uint64_t(t[(i + 1) % 3]));
  }
  std::sort(directed.begin(), directed.end());
  for(std::size_t i = 0; i < directed.size(); ++i)
  {
    if(i > 0 && directed[i] == directed[i - 1])
      r.error = "directed edge in two triangles (non-manifold or inconsistent orientation)";
    const std::uint64_t reverse = (directed[i] << 32) | (directed[i] >> 32);
    if(!std::binary_search(directed.begin(), directed.end(), reverse))
      r.error = "edge without an opposite twin (border or inconsistent orientation)";
  }
  // Vertex links: the edges (a -> b) opposite to v in its triangles must form
  // a single cycle.
  std::vector<std::vector<std::pair<int, int>>> link(nv);
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const std::array<int, 3>& t : mesh.triangles)
    for(int i = 0; i < 3; ++i)
    {
      link[t[i]].push_back({t[(i + 1) % 3], t[(i + 2) % 3]});
      parent[find(t[i])] = find(t[(i + 1) % 3]);
    }
  for(std::size_t v = 0; v < nv && r.error.empty(); ++v)
  {
    std::map<int, int> next;
    for(const std::pair<int, int>& e : link[v])
      if(!next.emplace(e.first, e.second).second)
        r.error = "vertex link branches";
    if(link[v].empty())
    {
      r.error = "isolated vertex";
      break;
    }
    std::size_t steps = 0;
    int current = link[v][0].first;
    do
    {
      const auto it = next.find(current);
      if(it == next.end())
      {
        r.error = "vertex link is not closed";
        break;
      }
      current = it->second;
      ++steps;
    } while(current != link[v][0].first && steps <= link[v].size());
    if(r.error.empty() && steps != link[v].size())
      r.error = "vertex link has several cycles (pinched vertex)";
  }
  std::set<int> roots;
  for(std::size_t v = 0; v < nv; ++v)
    roots.insert(find(int(v)));
  r.components = int(roots.size());
  r.euler = long(nv) - long(directed.size() / 2) + long(mesh.triangles.size());
  return r;
}

// Predictions from the lattice alone.  Connectivity: corners of equal state
// are connected along lattice edges, and across the diagonal of an ambiguous
// face if the face decision joins that state.  The surface separates exactly
// these regions, and since the regions of space and the surface components
// form a tree, #surface components = #regions - 1.
int predicted_components(const Lattice& l)
{
  const int n = l.n;
  std::vector<int> parent(l.in.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  auto unite = [&](int a, int b) {
    if(l.in[a] == l.in[b])
      parent[find(a)] = find(b);
  };
  for(int z = 0; z < n; ++z)
    for(int y = 0; y < n; ++y)
      for(int x = 0; x < n; ++x)
        for(int a = 0; a < 3; ++a)
        {
          std::array<int, 3> p = {x, y, z};
          std::array<int, 3> q = p;
          if(++q[a] >= n)
            continue;
          unite(l.index(x, y, z), l.index(q[0], q[1], q[2]));
          // the lattice face at p normal to a
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          std::array<int, 3> pb = p, pc = p, pbc = p;
          pb[b]++, pc[c]++, pbc[b]++, pbc[c]++;
          if(pbc[b] >= n || pbc[c] >= n)
            continue;
          const int i00 = l.index(x, y, z), i10 = l.index(pb[0], pb[1], pb[2]), i01 = l.index(pc[0], pc[1], pc[2]),
                    i11 = l.index(pbc[0], pbc[1], pbc[2]);
          if(l.in[i00] == l.in[i11] && l.in[i10] == l.in[i01] && l.in[i00] != l.in[i10])
          {
            const bool join = l.join_at(x, y, z, a);
            if((l.in[i00] != 0) == join)
              unite(i00, i11);
            else
              unite(i10, i01);
          }
        }
  std::set<int> roots;
  for(std::size_t v = 0; v < l.in.size(); ++v)
    roots.insert(find(int(v)));
  return int(roots.size()) - 1;
}

// Euler characteristic of the solid, as a sum over the open cells of the
// lattice of the compactly supported Euler characteristic of the solid inside
// each (see the manual): inside points count +1, edges with both ends inside
// -1, faces entirely inside +1, joined ambiguous faces -1, and each cube
// (number of outside pieces - 1), the pieces being the outside corners
// connected by cube edges and by the diagonals of unjoined ambiguous faces.
// The surface is the boundary of this compact 3-manifold: chi = 2 chi(solid).
long predicted_solid_euler(const Lattice& l)
{
  const int n = l.n;
  long chi = 0;
  for(int z = 0; z < n; ++z)
    for(int y = 0; y < n; ++y)
      for(int x = 0; x < n; ++x)
      {
        const std::array<int, 3> p = {x, y, z};
        chi += l.at(x, y, z);
        for(int a = 0; a < 3; ++a)
        {
          std::array<int, 3> q = p;
          if(++q[a] < n && l.at(x, y, z) && l.at(q[0], q[1], q[2]))
            --chi;
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          if(p[b] + 1 >= n || p[c] + 1 >= n)
            continue;
          std::array<int, 3> pb = p, pc = p, pbc = p;
          pb[b]++, pc[c]++, pbc[b]++, pbc[c]++;
          const bool s00 = l.at(x, y, z), s10 = l.at(pb[0], pb[1], pb[2]), s01 = l.at(pc[0], pc[1], pc[2]),
                     s11 = l.at(pbc[0], pbc[1], pbc[2]);
          if(s00 && s10 && s01 && s11)
            ++chi;
          if(s00 == s11 && s10 == s01 && s00 != s10 && l.join_at(x, y, z, a))
            --chi;
        }
        if(x + 1 >= n || y + 1 >= n || z + 1 >= n)
          continue;
        const unsigned code = cube_code(l, x, y, z), mask = cube_mask(l, x, y, z);
        int parent[8];
        std::iota(parent, parent + 8, 0);
        auto find = [&](int v) {
          while(parent[v] != v)
            v = parent[v];
          return v;
        };
        for(int k = 0; k < 8; ++k)
          for(int m = k + 1; m < 8; ++m)
          {
            if(inside(code, k) || inside(code, m))
              continue;
            const unsigned d = unsigned(k ^ m);
            bool connected = popcount(d) == 1;
            if(popcount(d) == 2)
            {
              // the face containing both: the axis where they agree
              const int a = (d & 1u) == 0 ? 0 : (d & 2u) == 0 ? 1 : 2;
              const int f = 2 * a + ((k >> a) & 1);
              connected = BI::is_ambiguous_face(code, f) && !((mask >> f) & 1u);
            }
            if(connected)
              parent[find(k)] = find(m);
          }
        int outside_pieces = 0;
        for(int k = 0; k < 8; ++k)
          if(!inside(code, k) && find(k) == k)
            ++outside_pieces;
        chi += outside_pieces - 1;
      }
  return chi;
}

double mesh_volume(const Mesh& mesh, const Vec3& origin)
{
  double v = 0;
  for(const std::array<int, 3>& t : mesh.triangles)
    v += det(mesh.points[t[0]] - origin, mesh.points[t[1]] - origin, mesh.points[t[2]] - origin);
  return v / 6;
}

// Inside volume of each entry with midpoints, from the closed 2-cycle of test 2.
double entry_midpoint_volume(const Table& table, unsigned code, unsigned mask)
{
  static std::map<unsigned, double> cache;
  const unsigned key = code * 64 + BI::normalized_join_mask(code, mask);
  const auto found = cache.find(key);
  if(found != cache.end())
    return found->second;
  std::array<double, 12> t;
  t.fill(0.5);
  const double v = volume(inside_boundary(table, code, BI::normalized_join_mask(code, mask), t), {0.5, 0.5, 0.5});
  cache[key] = v;
  return v;
}

// Checks everything a lattice's mesh must satisfy; returns the topology.
Mesh_topology check_lattice(const Lattice& l, const Table& table)
{
  const Mesh mesh = build_mesh(l, table);
  const Mesh_topology topology = analyse(mesh);
  EXPECT_EQ(topology.error, "");
  EXPECT_EQ(topology.components, predicted_components(l));
  EXPECT_EQ(topology.euler % 2, 0);
  EXPECT_EQ(topology.euler, 2 * predicted_solid_euler(l));
  // Orientation: the signed volume is the sum of the cubes' inside volumes
  // (their face regions cancel pairwise), hence positive.
  double expected_volume = 0;
  for(int z = 0; z + 1 < l.n; ++z)
    for(int y = 0; y + 1 < l.n; ++y)
      for(int x = 0; x + 1 < l.n; ++x)
        expected_volume += entry_midpoint_volume(table, cube_code(l, x, y, z), cube_mask(l, x, y, z));
  const double centre = 0.5 * (l.n - 1);
  const double v = mesh_volume(mesh, {centre, centre, centre});
  EXPECT_NEAR(v, expected_volume, 1e-9);
  if(!mesh.triangles.empty())
  {
    EXPECT_GT(v, 0.0);
  }
  return topology;
}

enum class Rule { separate, join, random };

void set_rule(Lattice& l, Rule rule, std::mt19937& random)
{
  for(std::uint8_t& j : l.join)
    j = rule == Rule::separate ? 0 : rule == Rule::join ? 1 : std::uint8_t(random() & 1u);
}

// Border points outside, so every surface is closed.
Lattice random_lattice(int n, double density, Rule rule, std::mt19937& random)
{
  Lattice l(n);
  std::uniform_real_distribution<double> u(0, 1);
  for(int z = 1; z + 1 < n; ++z)
    for(int y = 1; y + 1 < n; ++y)
      for(int x = 1; x + 1 < n; ++x)
        l.in[l.index(x, y, z)] = u(random) < density;
  set_rule(l, rule, random);
  return l;
}

TEST(Lattice, random_lattices_give_closed_oriented_manifolds)
{
  const Table& table = Table::instance();
  std::mt19937 random(20260101);
  std::uniform_real_distribution<double> density(0.1, 0.9);
  std::map<long, int> euler_seen;
  for(int seed = 0; seed < 3000; ++seed)
  {
    const int n = seed % 10 == 0 ? 9 : 6;
    const Rule rule = seed % 3 == 0 ? Rule::separate : seed % 3 == 1 ? Rule::random : Rule::join;
    const Lattice l = random_lattice(n, density(random), rule, random);
    SCOPED_TRACE("lattice " + std::to_string(seed));
    const Mesh_topology t = check_lattice(l, table);
    ++euler_seen[t.euler];
    if(::testing::Test::HasFailure())
      return;
  }
  // the sample really exercises several topologies (spheres, tori, several components)
  EXPECT_GE(euler_seen.size(), 5u);
  EXPECT_GT(euler_seen.count(0), 0u);
  EXPECT_GT(euler_seen.count(2), 0u);
}

TEST(Lattice, structured_shapes_have_the_expected_topology)
{
  const Table& table = Table::instance();
  std::mt19937 random(5);
  for(Rule rule : {Rule::separate, Rule::join, Rule::random})
  {
    SCOPED_TRACE("rule " + std::to_string(int(rule)));
    {
      SCOPED_TRACE("single inside point: an octahedron");
      Lattice l(5);
      l.in[l.index(2, 2, 2)] = 1;
      set_rule(l, rule, random);
      const Mesh mesh = build_mesh(l, table);
      EXPECT_EQ(mesh.points.size(), 6u);
      EXPECT_EQ(mesh.triangles.size(), 8u);
      const Mesh_topology t = check_lattice(l, table);
      EXPECT_EQ(t.euler, 2);
      EXPECT_EQ(t.components, 1);
    }
    {
      SCOPED_TRACE("all inside but the border: a box");
      Lattice l(7);
      for(int z = 1; z < 6; ++z)
        for(int y = 1; y < 6; ++y)
          for(int x = 1; x < 6; ++x)
            l.in[l.index(x, y, z)] = 1;
      set_rule(l, rule, random);
      const Mesh_topology t = check_lattice(l, table);
      EXPECT_EQ(t.euler, 2);
      EXPECT_EQ(t.components, 1);
      // and with a one-point cavity: two spheres, the inner one facing inward
      l.in[l.index(3, 3, 3)] = 0;
      const Mesh_topology u = check_lattice(l, table);
      EXPECT_EQ(u.euler, 4);
      EXPECT_EQ(u.components, 2);
    }
    {
      SCOPED_TRACE("digital balls");
      for(int trial = 0; trial < 40; ++trial)
      {
        std::uniform_real_distribution<double> centre(4.5, 6.5), radius(0.9, 3.9);
        const double cx = centre(random), cy = centre(random), cz = centre(random), r = radius(random);
        Lattice l(12);
        for(int z = 0; z < 12; ++z)
          for(int y = 0; y < 12; ++y)
            for(int x = 0; x < 12; ++x)
              l.in[l.index(x, y, z)] = (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) <= r * r;
        set_rule(l, rule, random);
        const Mesh_topology t = check_lattice(l, table);
        if(std::count(l.in.begin(), l.in.end(), 1) > 0)
        {
          EXPECT_EQ(t.euler, 2) << cx << " " << cy << " " << cz << " " << r;
          EXPECT_EQ(t.components, 1);
        }
      }
    }
    {
      SCOPED_TRACE("a ring of points: a torus");
      Lattice l(7);
      for(int i = 1; i <= 5; ++i)
        for(int z = 2; z <= 3; ++z)
        {
          l.in[l.index(i, 1, z)] = l.in[l.index(i, 5, z)] = 1;
          l.in[l.index(1, i, z)] = l.in[l.index(5, i, z)] = 1;
        }
      set_rule(l, rule, random);
      const Mesh_topology t = check_lattice(l, table);
      EXPECT_EQ(t.euler, 0);
      EXPECT_EQ(t.components, 1);
    }
    {
      SCOPED_TRACE("checkerboard");
      Lattice l(8);
      int count = 0;
      for(int z = 1; z < 7; ++z)
        for(int y = 1; y < 7; ++y)
          for(int x = 1; x < 7; ++x)
            if((x + y + z) % 2 == 0)
            {
              l.in[l.index(x, y, z)] = 1;
              ++count;
            }
      set_rule(l, rule, random);
      const Mesh_topology t = check_lattice(l, table);
      if(rule == Rule::separate)
      {
        // 6-connected inside: every point is its own octahedron
        EXPECT_EQ(t.components, count);
        EXPECT_EQ(t.euler, 2 * count);
      }
    }
    {
      SCOPED_TRACE("two points sharing only a lattice face diagonal");
      Lattice l(5);
      l.in[l.index(1, 1, 2)] = l.in[l.index(2, 2, 2)] = 1;
      set_rule(l, rule, random);
      const Mesh_topology t = check_lattice(l, table);
      const bool joined = l.join_at(1, 1, 2, 2);
      EXPECT_EQ(t.components, joined ? 1 : 2);
      EXPECT_EQ(t.euler, joined ? 2 : 4);
    }
    {
      SCOPED_TRACE("two points sharing only a cube diagonal");
      Lattice l(5);
      l.in[l.index(1, 1, 1)] = l.in[l.index(2, 2, 2)] = 1;
      set_rule(l, rule, random);
      const Mesh_topology t = check_lattice(l, table);
      EXPECT_EQ(t.components, 2);
      EXPECT_EQ(t.euler, 4);
    }
  }
}

// Global form of the duality: complement every lattice point and every face
// decision; the mesh is the same, with every triangle reversed.
TEST(Lattice, complement_with_opposite_rule_reverses_the_mesh)
{
  const Table& table = Table::instance();
  std::mt19937 random(99);
  std::uniform_real_distribution<double> density(0.2, 0.8);
  for(int seed = 0; seed < 300; ++seed)
  {
    const Rule rule = seed % 3 == 0 ? Rule::separate : seed % 3 == 1 ? Rule::random : Rule::join;
    const Lattice l = random_lattice(7, density(random), rule, random);
    Lattice c = l;
    for(std::uint8_t& s : c.in)
      s = !s;
    for(std::uint8_t& j : c.join)
      j = !j;
    auto keyed = [](const Mesh& m, bool reversed) {
      std::set<std::array<std::int64_t, 3>> s;
      for(const std::array<int, 3>& t : m.triangles)
      {
        std::array<std::int64_t, 3> k = {m.keys[t[0]], m.keys[t[1]], m.keys[t[2]]};
        if(reversed)
          std::swap(k[1], k[2]);
        while(k[0] > k[1] || k[0] > k[2])
          k = {k[1], k[2], k[0]};
        s.insert(k);
      }
      return s;
    };
    const Mesh a = build_mesh(l, table), b = build_mesh(c, table);
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    ASSERT_EQ(keyed(a, false), keyed(b, true)) << "lattice " << seed;
  }
}

} // namespace
