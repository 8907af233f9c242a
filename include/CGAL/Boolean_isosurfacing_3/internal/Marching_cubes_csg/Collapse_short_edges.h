// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_COLLAPSE_SHORT_EDGES_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_COLLAPSE_SHORT_EDGES_H

// Slivers of Marching Cubes come from edge points that land next to a
// lattice point: two points on two lattice edges of the same lattice point
// are then much closer to each other than to the rest of their triangles.
// Such an edge is collapsed (the higher-numbered point merges into the
// lower-numbered one, or the other way if that fails a test below: both
// are exact crossings) when
//  - the link condition holds (the two ends have exactly the two opposite
//    vertices of the edge as common neighbours, and do not both form a
//    triangle with them), so the closed 2-manifold stays a closed
//    2-manifold with the same topology and no two coincident triangles;
//  - no triangle that moves turns by more than 90 degrees, becomes
//    degenerate, or becomes a worse sliver than it was (unless it stays
//    above a quality of 1e-4);
//  - no moved triangle folds onto a neighbour (`max_fold_cosine`).
// Feature vertices are never moved, but an edge point next to one merges
// into it (a needle at a crease: the crease is on the exact surface, so the
// surface moves no farther than the edge is long).  In one pass each vertex takes part in
// at most one collapse, so the order of the collapses (sorted edges) cannot
// matter more than one level, and the pass is O(triangles); a few passes
// are made.  A pass after the first tries only the edges near the previous
// pass's collapses (elsewhere nothing it reads has changed since it refused
// them), and the points are renumbered once, at the end.

#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Feature_vertex.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Sliver_flips.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Release_free_memory.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {
namespace Marching_cubes_csg {

/// Passes of `collapse_short_edges()` at most.
constexpr int max_collapse_passes = 4;

/// A collapse may not move a triangle so that its normal and a neighbour's
/// make a cosine below this (an interior angle below about 26 degrees).
constexpr double max_fold_cosine = -0.9;

/// The smallest cosine between the normals of two triangles of `star` that
/// share an edge, one of them `moved` (1 if none do, or if one of them is
/// degenerate).  `normals` is scratch space.
template <typename Triangle>
double most_opposite_neighbours(const std::vector<Vector_3d>& points, const std::vector<Triangle>& star,
                                const std::vector<unsigned char>& moved, std::vector<Vector_3d>& normals)
{
  // Each normal once: a star has about 20 triangles, and most pairs that
  // share an edge were computing both of theirs again.
  normals.resize(star.size());
  for(std::size_t i = 0; i < star.size(); ++i)
    normals[i] = triangle_normal(points[star[i][0]], points[star[i][1]], points[star[i][2]]);
  double smallest = 1;
  for(std::size_t i = 0; i < star.size(); ++i)
    for(std::size_t j = i + 1; j < star.size(); ++j)
    {
      if(!moved[i] && !moved[j])
        continue;
      int shared = 0;
      for(const std::size_t v : star[i])
        shared += int(v == star[j][0] || v == star[j][1] || v == star[j][2]);
      if(shared != 2)
        continue;
      const Vector_3d &a = normals[i], &b = normals[j];
      const double norms = std::sqrt(dot3(a, a) * dot3(b, b));
      if(norms > 0)
        smallest = (std::min)(smallest, dot3(a, b) / norms);
    }
  return smallest;
}

/// Scratch space of `collapse_if_valid()`, kept from one call to the next.
template <typename Triangle>
struct Collapse_scratch
{
  std::vector<std::size_t> neighbours_gone, neighbours_keep, common;
  std::vector<Triangle> star_after;
  std::vector<unsigned char> moved_flags;
  std::vector<Vector_3d> normals;
};

/// Collapses the edge (keep, gone) into `keep` if it passes the tests of
/// `collapse_short_edges_once()` (the caller has checked that neither end
/// is in a collapse of this pass already).  `star(v, f)` calls `f(t)` on the
/// triangles `t` of vertex v's row, deleted ones included, until `f` returns
/// false (and then returns false).  A row holds the triangles of v when the
/// rows were made (the pass or its batch began): for an end of an earlier
/// collapse of the same batch, no longer all of them.  `moved(w)` is called
/// on each vertex of each triangle that moves.  `collapsible(u, v)` says
/// whether the edge (u, v) is short enough to be a candidate itself.
template <typename Triangle, typename Star, typename Moved, typename Collapsible>
bool collapse_if_valid(std::size_t keep, std::size_t gone, const std::vector<Vector_3d>& points,
                       std::vector<Triangle>& triangles, std::vector<unsigned char>& deleted, const Star& star,
                       const Moved& moved, const Collapsible& collapsible, Collapse_scratch<Triangle>& scratch)
{
  typedef typename Triangle::value_type Index;
  // The two triangles of the edge, and the link condition.
  std::array<std::size_t, 2> edge_triangles{{0, 0}}, opposite{{0, 0}};
  int found = 0;
  star(gone, [&](std::size_t t) {
    if(deleted[t])
      return true;
    const auto& tr = triangles[t];
    if(tr[0] == keep || tr[1] == keep || tr[2] == keep)
    {
      if(found == 2)
      {
        found = 3;
        return false;
      }
      edge_triangles[found] = t;
      opposite[found] = tr[0] != keep && tr[0] != gone ? tr[0] : (tr[1] != keep && tr[1] != gone ? tr[1] : tr[2]);
      ++found;
    }
    return true;
  });
  if(found != 2 || opposite[0] == opposite[1])
    return false;
  // The triangles of `gone` move.  Each must keep its orientation and not
  // become a worse sliver than it was (below a quality of 1e-4, about 0.25
  // degree), unless the sliver is a needle whose short side is collapsible
  // in its turn: three edge points around one lattice point make a tiny
  // triangle, and its first collapse always turns a neighbour into such a
  // needle, which the next pass removes.  Tested first: it reads only the
  // star of `gone`, and refuses the most (armadillo united with a copy at
  // 128 cells: 2,233 of the first 6,000 tries, the link condition none, the
  // fold test 3).
  const bool keep_shape = star(gone, [&](std::size_t t) {
    if(deleted[t] || t == edge_triangles[0] || t == edge_triangles[1])
      return true;
    const Triangle& before = triangles[t];
    Triangle after = before;
    for(Index& w : after)
      if(w == gone)
        w = Index(keep);
    const Vector_3d &b0 = points[before[0]], &b1 = points[before[1]], &b2 = points[before[2]];
    const Vector_3d &a0 = points[after[0]], &a1 = points[after[1]], &a2 = points[after[2]];
    const double q1 = triangle_quality(a0, a1, a2);
    const bool same_side = dot3(triangle_normal(b0, b1, b2), triangle_normal(a0, a1, a2)) > 0;
    if(same_side && q1 > 1e-4)
      return true; // most moved triangles: nothing else to compute
    const double q0 = triangle_quality(b0, b1, b2);
    const bool short_side =
        collapsible(after[0], after[1]) || collapsible(after[1], after[2]) || collapsible(after[2], after[0]);
    // A needle that was degenerate already and keeps a collapsible short
    // side: edge points within rounding of one lattice point (the surface
    // passes through it up to 1e-6 r), whose needles all have a quality of
    // about 1e-12 and a normal made of rounding; they go together, one
    // collapse at a time, and no test on such a normal can pass.
    if(q0 <= degenerate_quality && short_side)
      return true;
    return same_side && (q1 >= q0 || short_side) && q1 > degenerate_quality;
  });
  if(!keep_shape)
    return false;
  const auto neighbours = [&](std::size_t v, std::vector<std::size_t>& out) {
    out.clear();
    star(v, [&](std::size_t t) {
      if(!deleted[t])
        for(const std::size_t w : triangles[t])
          if(w != v)
            out.push_back(w);
      return true;
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  };
  neighbours(gone, scratch.neighbours_gone);
  neighbours(keep, scratch.neighbours_keep);
  scratch.common.clear();
  std::set_intersection(scratch.neighbours_gone.begin(), scratch.neighbours_gone.end(),
                        scratch.neighbours_keep.begin(), scratch.neighbours_keep.end(),
                        std::back_inserter(scratch.common));
  if(scratch.common.size() != 2)
    return false;
  // The link condition on edges too: if both ends form a triangle with the
  // two opposite vertices, the four are a tetrahedron (a tiny component of
  // its own) and the collapse would leave two coincident triangles.
  const auto has_triangle_with_opposites = [&](std::size_t v) {
    return !star(v, [&](std::size_t t) {
      const auto& tr = triangles[t];
      return deleted[t] || std::count(tr.begin(), tr.end(), opposite[0]) != 1 ||
             std::count(tr.begin(), tr.end(), opposite[1]) != 1;
    });
  };
  if(has_triangle_with_opposites(gone) && has_triangle_with_opposites(keep))
    return false;
  // No fold: a moved triangle and a triangle across one of its edges must
  // not face (nearly) opposite ways.  Squashing a tiny component (an
  // octahedron around one lattice point) flat, or turning a triangle onto
  // its outer neighbour in a lattice plane, passes every per-triangle test
  // but makes the surface overlap itself.
  std::vector<Triangle>& star_after = scratch.star_after;
  std::vector<unsigned char>& moved_flags = scratch.moved_flags;
  star_after.clear();
  moved_flags.clear();
  star(keep, [&](std::size_t t) {
    if(!deleted[t] && t != edge_triangles[0] && t != edge_triangles[1])
    {
      star_after.push_back(triangles[t]);
      moved_flags.push_back(0);
    }
    return true;
  });
  star(gone, [&](std::size_t t) {
    if(deleted[t] || t == edge_triangles[0] || t == edge_triangles[1])
      return true;
    Triangle after = triangles[t];
    std::array<std::size_t, 2> outer{{0, 0}};
    int o = 0;
    for(Index& w : after)
      if(w == gone)
        w = Index(keep);
      else if(o < 2)
        outer[o++] = w;
    star_after.push_back(after);
    moved_flags.push_back(1);
    // The triangle across the outer edge (it has a row: a neighbour of gone).
    star(outer[0], [&](std::size_t n) {
      const auto& tn = triangles[n];
      if(n != t && !deleted[n] && std::count(tn.begin(), tn.end(), outer[1]) == 1)
      {
        star_after.push_back(tn);
        moved_flags.push_back(0);
      }
      return true;
    });
    return true;
  });
  if(most_opposite_neighbours(points, star_after, moved_flags, scratch.normals) < max_fold_cosine)
    return false;
  star(gone, [&](std::size_t t) {
    if(!deleted[t])
      for(Index& w : triangles[t])
      {
        if(w == gone)
          w = Index(keep);
        moved(w);
      }
    return true;
  });
  deleted[edge_triangles[0]] = deleted[edge_triangles[1]] = 1;
  return true;
}

/// The cosine of the angle under which a triangle with two feature vertices
/// is a cap whose edge point merges into one of them (5 degrees).
constexpr double cos_crease_cap_angle = 0.99619469809174555;

/// Appends the candidate edges of a collapse pass to `candidates`: each edge
/// (a, b), a < b, whose end a is an edge point (below
/// `first_feature_vertex`: b is an edge point or a feature vertex),
/// shorter than `max_length`, with an end `flagged(v)`, of a triangle t that
/// is not `skipped(t)`; once for each triangle it appears in as a -> b.  And
/// the edge from the edge point of a triangle with two feature vertices to
/// the nearer of them, if the edge point is closer than `max_length` to
/// their side and the triangle has an angle under 5 degrees.
template <typename Triangle, typename Skipped, typename Flagged>
void append_short_edges(const std::vector<Vector_3d>& points, const std::vector<Triangle>& triangles,
                        std::size_t first_feature_vertex, double max_length, const Skipped& skipped,
                        const Flagged& flagged, std::vector<std::array<typename Triangle::value_type, 2>>& candidates)
{
  typedef typename Triangle::value_type Index;
  const double max_squared = max_length * max_length;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tr = triangles[t];
    // After the first pass most triangles have no flagged vertex: one test
    // for the three edges.
    if(skipped(t) || !(flagged(tr[0]) || flagged(tr[1]) || flagged(tr[2])))
      continue;
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = tr[i], b = tr[i == 2 ? 0 : i + 1];
      if(a < b && a < first_feature_vertex && (flagged(a) || flagged(b)))
      {
        const Vector_3d d = sub3(points[a], points[b]);
        if(dot3(d, d) < max_squared)
          candidates.push_back({{Index(a), Index(b)}});
      }
    }
    // A cap on a crease: an edge point c closer than `max_length` to the
    // side between two feature vertices, which no flip may remove (it is
    // usually a crease edge), making an angle under 5 degrees.  c merges
    // into the nearer of the two: it slides along the crease, on the exact
    // surface.  (Without the angle bound, 3 to 30 times more edge points
    // merge for the same share of slivers.)
    const int features = int(tr[0] >= first_feature_vertex) + int(tr[1] >= first_feature_vertex) +
                         int(tr[2] >= first_feature_vertex);
    if(features != 2)
      continue;
    const int k = tr[0] < first_feature_vertex ? 0 : (tr[1] < first_feature_vertex ? 1 : 2);
    const std::size_t c = tr[k], a = tr[(k + 1) % 3], b = tr[(k + 2) % 3];
    const Vector_3d ab = sub3(points[b], points[a]), ac = sub3(points[c], points[a]);
    const double along = dot3(ac, ab), squared_side = dot3(ab, ab);
    if(!(along > 0 && along < squared_side))
      continue; // c does not face the side
    const double squared_height = dot3(ac, ac) - along * (along / squared_side);
    const std::size_t nearer = 2 * along < squared_side ? a : b;
    if(squared_height < max_squared && (flagged(c) || flagged(nearer)) &&
       has_angle_below(points[a], points[b], points[c], cos_crease_cap_angle))
      candidates.push_back({{Index(c), Index(nearer)}});
  }
}

/// Whether an edge (u, v) would be a candidate of a collapse pass: an end is
/// an edge point, and it is shorter than `max_length`.
inline auto collapsible_edge(const std::vector<Vector_3d>& points, std::size_t first_feature_vertex,
                             double max_length)
{
  const double max_squared = max_length * max_length;
  return [&points, first_feature_vertex, max_squared](std::size_t u, std::size_t v) {
    if(u >= first_feature_vertex && v >= first_feature_vertex)
      return false;
    const Vector_3d d = sub3(points[u], points[v]);
    return dot3(d, d) < max_squared;
  };
}

/// A pass of `collapse_short_edges()` with more candidate edges takes them
/// in batches of about this many (bounding the memory of its tables).
constexpr std::size_t candidates_per_batch = std::size_t(1) << 18;

/// What the passes of `collapse_short_edges()` share, one flag per point.
struct Collapse_marks
{
  std::vector<unsigned char> removed; // merged into another point
  // In: try only the edges with an end flagged (all edges if empty).  Out:
  // the ends of every edge whose collapse may have become possible, i.e.
  // the vertices of the triangles that share a vertex with a triangle the
  // pass moved (empty if it collapsed nothing: the passes stop).
  std::vector<unsigned char> near_collapse;
  // If not null: 1 for the point that stays in each collapse (whose star
  // changed).
  std::vector<unsigned char>* kept = nullptr;
};

/// One pass of `collapse_short_edges()`: each vertex takes part in at most
/// one collapse.  Merged points stay in `points` (flagged in
/// `marks.removed`), and the deleted triangles are removed.
template <typename Triangle>
std::size_t collapse_short_edges_once(const std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                                      std::size_t first_feature_vertex, double max_length, Collapse_marks& marks,
                                      std::size_t batch_size = candidates_per_batch)
{
  typedef typename Triangle::value_type Index;
  typedef std::array<Index, 2> Edge; // the triangles' index type: half the memory of size_t
  // Rows of 32-bit triangle numbers with 32-bit vertex indices: no collapse
  // (never wrong) on outputs of more than about 1.4 billion triangles.
  typedef typename std::conditional<sizeof(Index) <= 4, std::uint32_t, std::size_t>::type Triangle_index;
  if(3 * triangles.size() > std::size_t((std::numeric_limits<Triangle_index>::max)()))
    return 0;
  const std::vector<unsigned char>& tried = marks.near_collapse;
  std::vector<Edge> candidates;
  append_short_edges(
      points, triangles, first_feature_vertex, max_length, [](std::size_t) { return false; },
      [&](std::size_t v) { return tried.empty() || tried[v] != 0; }, candidates);
  marks.near_collapse.clear();
  if(candidates.empty())
    return 0;
  std::sort(candidates.begin(), candidates.end());

  // Incident triangles of the candidates' ends and of their neighbours
  // (compressed rows): only their stars are read (the fold test reads the
  // triangle across each outer edge of a moved triangle), and rows for every
  // vertex were 32 bytes a triangle.  Many candidates (a fine lattice's
  // first pass) are taken in batches, in their order, each with the rows of
  // its own ends built from the triangles as the previous batches left them:
  // the rows of all ends at once were the memory peak of the feature path at
  // 2048 cells (2.1M candidates, 8.5M ends, 51M incidences).  One batch (up
  // to `batch_size`) is the single pass of before.
  const std::size_t nv = points.size();
  std::vector<unsigned char> touched(nv, 0), deleted(triangles.size(), 0);
  std::vector<unsigned char> in_collapse(nv, 0); // in a collapse of this pass
  const std::uint32_t no_row = std::uint32_t(-1);
  std::vector<std::uint32_t> row_of;
  std::vector<Index> ends; // in increasing order
  std::vector<Triangle_index> first, incident;
  bool small_rows = true;
  const auto row = [&](std::size_t v) {
    return small_rows ? std::size_t(row_of[v])
                      : std::size_t(std::lower_bound(ends.begin(), ends.end(), Index(v)) - ends.begin());
  };
  const auto build_rows = [&](const Edge* batch_begin, const Edge* batch_end) {
    // 5: an end of a candidate (either may go: its neighbours get rows).
    for(const Edge* e = batch_begin; e != batch_end; ++e)
      touched[(*e)[0]] = touched[(*e)[1]] = 5;
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      const auto& tr = triangles[t];
      if(!deleted[t] && (touched[tr[0]] == 5 || touched[tr[1]] == 5 || touched[tr[2]] == 5))
        for(const std::size_t v : tr)
          touched[v] = touched[v] == 0 ? 4 : touched[v];
    }
    ends.clear();
    for(std::size_t v = 0; v < nv; ++v)
      if(touched[v] != 0)
        ends.push_back(Index(v));
    // The row of each end (none for the other vertices).
    small_rows = ends.size() < no_row;
    if(small_rows)
    {
      if(row_of.empty())
        row_of.assign(nv, no_row);
      for(std::size_t r = 0; r < ends.size(); ++r)
        row_of[ends[r]] = std::uint32_t(r);
    }
    for(std::size_t v : ends)
      touched[v] = 3; // has a row (cleared below)
    first.assign(ends.size() + 1, 0);
    for(std::size_t t = 0; t < triangles.size(); ++t)
      if(!deleted[t])
        for(std::size_t v : triangles[t])
          if(touched[v] == 3)
            ++first[row(v) + 1];
    for(std::size_t r = 0; r < ends.size(); ++r)
      first[r + 1] += first[r];
    incident.resize(first.back());
    // Filled backwards from each row's end, the triangles in decreasing
    // order: the rows come out increasing, and `first` is both the cursor
    // and, once shifted by one, the rows' beginnings (no copy of it).
    for(std::size_t t = triangles.size(); t-- > 0;)
      if(!deleted[t])
        for(std::size_t v : triangles[t])
          if(touched[v] == 3)
            incident[--first[row(v) + 1]] = Triangle_index(t);
    std::copy(first.begin() + 1, first.end(), first.begin());
    first.back() = Triangle_index(incident.size());
    for(std::size_t v : ends)
      touched[v] = 0;
  };
  const auto clear_rows = [&]() {
    if(small_rows)
      for(std::size_t v : ends)
        row_of[v] = no_row;
  };
  const auto star = [&](std::size_t v, auto&& f) {
    const std::size_t r = row(v);
    for(std::size_t x = first[r]; x < first[r + 1]; ++x)
      if(!f(std::size_t(incident[x])))
        return false;
    return true;
  };
  std::vector<unsigned char> moved_vertex(nv, 0); // a vertex of a moved triangle
  Collapse_scratch<Triangle> scratch;
  const auto collapsible = collapsible_edge(points, first_feature_vertex, max_length);
  std::size_t collapses = 0;
  const auto try_collapse = [&](std::size_t keep, std::size_t gone) {
    if(gone >= first_feature_vertex || in_collapse[keep] || in_collapse[gone] ||
       !collapse_if_valid(keep, gone, points, triangles, deleted, star,
                          [&](std::size_t w) { moved_vertex[w] = 1; }, collapsible, scratch))
      return false;
    in_collapse[gone] = in_collapse[keep] = 1; // in no other collapse of this pass
    marks.removed[gone] = 1;
    if(marks.kept != nullptr)
      (*marks.kept)[keep] = 1;
    ++collapses;
    return true;
  };
  const std::size_t per_batch = (std::max)(batch_size, std::size_t(1));
  const std::size_t batches = (candidates.size() + per_batch - 1) / per_batch;
  for(std::size_t b = 0; b < batches; ++b)
  {
    const Edge* const batch_begin = candidates.data() + candidates.size() * b / batches;
    const Edge* const batch_end = candidates.data() + candidates.size() * (b + 1) / batches;
    build_rows(batch_begin, batch_end);
    for(const Edge* e = batch_begin; e != batch_end; ++e)
    {
      // The higher-numbered end goes; if that would spoil a triangle, the
      // lower-numbered one (both are exact crossings): measured, a third
      // fewer triangles under 5 degrees on fandisk and bunny.
      if(!try_collapse((*e)[0], (*e)[1]))
        try_collapse((*e)[1], (*e)[0]);
    }
    clear_rows();
  }
  if(collapses == 0)
    return 0;
  // The next pass tries the edges with an end within one triangle of a
  // moved triangle: every other candidate reads (its two stars, and the
  // triangles across the outer edges of the star that moves) only
  // triangles and points this pass left alone.  (An edge that a collapse
  // of the next pass itself makes collapsible waits one more pass.)
  marks.near_collapse.assign(nv, 0);
  std::size_t out = 0;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    if(!deleted[t])
    {
      const Triangle& tr = triangles[t];
      if(moved_vertex[tr[0]] || moved_vertex[tr[1]] || moved_vertex[tr[2]])
        for(const std::size_t v : tr)
          marks.near_collapse[v] = 1;
      triangles[out++] = tr;
    }
  triangles.resize(out);
  return collapses;
}

/// How `collapse_short_edge_passes()` finds the triangles of a vertex.
enum class Collapse_rows
{
  /// Merged rows for outputs of at most `max_merged_rows_corners` corners,
  /// rows by pass above.
  AUTOMATIC,
  /// Rows of the candidates' ends and their neighbours, made again for each
  /// pass (or batch) from all the triangles: its memory is bounded by the
  /// batch size (`collapse_short_edges_once()`).
  BY_PASS,
  /// The rows of every vertex, made once: a collapse adds the row of the
  /// vertex that goes to the one that stays (a list of merged vertices), and
  /// the deleted triangles stay in place, flagged, until the end.  4 bytes a
  /// corner and 18 a vertex.
  MERGED
};

/// Outputs of up to this many corners (about 2.8M triangles: 60 MB of merged
/// rows) take `Collapse_rows::MERGED`.  Above, the memory of the feature path
/// matters more (the 2048-cell lattice's peak is its corner table), and the
/// passes take the rows by pass.
constexpr std::size_t max_merged_rows_corners = std::size_t(1) << 23;

/// The rows of every vertex's triangles, made once, and the vertices
/// merged into each vertex by the collapses: the triangles a vertex has now
/// are those of its row and of the rows of the vertices merged into it, the
/// deleted ones apart.
template <typename Index>
class Merged_rows
{
public:
  template <typename Triangle>
  Merged_rows(std::size_t number_of_points, const std::vector<Triangle>& triangles)
      : m_first(number_of_points + 1, 0), m_incident(3 * triangles.size()), m_merged_first(number_of_points, none),
        m_merged_next(number_of_points, none), m_merge_batch(number_of_points, 0)
  {
    for(const Triangle& t : triangles)
      for(const std::size_t v : t)
        ++m_first[v + 1];
    for(std::size_t v = 0; v < number_of_points; ++v)
      m_first[v + 1] += m_first[v];
    // Filled backwards from each row's end (as the rows by pass): `m_first`
    // is the cursor and, once shifted by one, the rows' beginnings.
    for(std::size_t t = triangles.size(); t-- > 0;)
      for(const std::size_t v : triangles[t])
        m_incident[--m_first[v + 1]] = std::uint32_t(t);
    std::copy(m_first.begin() + 1, m_first.end(), m_first.begin());
    m_first.back() = std::uint32_t(m_incident.size());
  }

  /// Calls `f(t)` on the triangles of v's row and of the rows of the
  /// vertices merged into v in batches before `batch`, until `f` returns
  /// false (then returns false).  (A vertex merged into v in the current
  /// batch is left out: the rows by pass do not see it either.)
  template <typename F>
  bool for_each(std::size_t v, std::uint32_t batch, const F& f) const
  {
    for(std::size_t x = m_first[v]; x < m_first[v + 1]; ++x)
      if(!f(std::size_t(m_incident[x])))
        return false;
    for(Index c = m_merged_first[v]; c != none; c = m_merged_next[c])
      // What was merged into c was merged before c was.
      if(m_merge_batch[c] < batch && !for_each(c, batch, f))
        return false;
    return true;
  }

  void merge(std::size_t gone, std::size_t keep, std::uint32_t batch)
  {
    m_merged_next[gone] = m_merged_first[keep];
    m_merged_first[keep] = Index(gone);
    m_merge_batch[gone] = batch;
  }

private:
  static constexpr Index none = Index(-1);
  std::vector<std::uint32_t> m_first, m_incident;
  std::vector<Index> m_merged_first, m_merged_next; // lists of the merged vertices
  std::vector<std::uint32_t> m_merge_batch;
};

/// The passes of `collapse_short_edges()` on merged rows: the same
/// candidates, batches and tests as `collapse_short_edges_once()` repeated
/// (so the same collapses), but the rows are made once instead of by three
/// scans of the triangles each pass, and the deleted triangles are removed
/// once, at the end.  Merged points are flagged in `removed`, and the
/// points that stay in a collapse in `*kept` if it is not null.
template <typename Triangle>
std::size_t collapse_short_edges_with_merged_rows(const std::vector<Vector_3d>& points,
                                                  std::vector<Triangle>& triangles, std::size_t first_feature_vertex,
                                                  double max_length, std::vector<unsigned char>& removed,
                                                  std::size_t batch_size = candidates_per_batch,
                                                  const std::vector<unsigned char>* only_near = nullptr,
                                                  std::vector<unsigned char>* kept = nullptr)
{
  typedef typename Triangle::value_type Index;
  typedef std::array<Index, 2> Edge;
  if(3 * triangles.size() >= std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    return 0;
  const std::size_t nv = points.size();
  std::vector<Edge> candidates;
  append_short_edges(
      points, triangles, first_feature_vertex, max_length, [](std::size_t) { return false; },
      [&](std::size_t v) { return only_near == nullptr || (*only_near)[v] != 0; }, candidates);
  if(candidates.empty())
    return 0;

  Merged_rows<Index> rows(nv, triangles);
  // moved: 1 for a vertex of a moved triangle, 2 for a vertex of a triangle
  // with one (an end of the next pass's candidates).
  std::vector<unsigned char> deleted(triangles.size(), 0), in_collapse(nv, 0), moved(nv, 0);
  std::vector<Index> collapsed;
  std::uint32_t batch = 0;
  Collapse_scratch<Triangle> scratch;
  const auto collapsible = collapsible_edge(points, first_feature_vertex, max_length);
  std::size_t total = 0;
  for(int pass = 0; pass < max_collapse_passes && !candidates.empty(); ++pass)
  {
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::size_t collapses = 0;
    const std::size_t per_batch = (std::max)(batch_size, std::size_t(1));
    const std::size_t batches = (candidates.size() + per_batch - 1) / per_batch;
    for(std::size_t b = 0; b < batches; ++b)
    {
      ++batch;
      const auto star = [&](std::size_t v, auto&& f) { return rows.for_each(v, batch, f); };
      const auto try_collapse = [&](std::size_t keep, std::size_t gone) {
        if(gone >= first_feature_vertex || in_collapse[keep] || in_collapse[gone] ||
           !collapse_if_valid(keep, gone, points, triangles, deleted, star,
                              [&](std::size_t w) { moved[w] = 1; }, collapsible, scratch))
          return false;
        in_collapse[gone] = in_collapse[keep] = 1; // in no other collapse of this pass
        collapsed.push_back(Index(gone));
        collapsed.push_back(Index(keep));
        rows.merge(gone, keep, batch);
        removed[gone] = 1;
        if(kept != nullptr)
          (*kept)[keep] = 1;
        ++collapses;
        return true;
      };
      for(std::size_t e = candidates.size() * b / batches; e < candidates.size() * (b + 1) / batches; ++e)
        if(!try_collapse(candidates[e][0], candidates[e][1]))
          try_collapse(candidates[e][1], candidates[e][0]);
    }
    for(const Index v : collapsed)
      in_collapse[v] = 0;
    collapsed.clear();
    total += collapses;
    candidates.clear();
    if(collapses == 0 || pass + 1 == max_collapse_passes)
      break;
    // The next pass's candidates (as `Collapse_marks::near_collapse`): the
    // edges with an end on a triangle with a moved vertex.  Two scans of the
    // triangles: the second ring of thousands of collapses is most of the
    // vertices, and its stars were slower to walk (armadillo united with a
    // copy at 128 cells, 7 against 1.5 ms).
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      const Triangle& tr = triangles[t];
      if(!deleted[t] && (moved[tr[0]] & 1 || moved[tr[1]] & 1 || moved[tr[2]] & 1))
        for(const std::size_t v : tr)
          moved[v] |= 2;
    }
    append_short_edges(
        points, triangles, first_feature_vertex, max_length, [&](std::size_t t) { return deleted[t] != 0; },
        [&](std::size_t v) { return (moved[v] & 2) != 0; }, candidates);
    std::fill(moved.begin(), moved.end(), 0);
  }
  if(total > 0)
  {
    std::size_t out = 0;
    for(std::size_t t = 0; t < triangles.size(); ++t)
      if(!deleted[t])
        triangles[out++] = triangles[t];
    triangles.resize(out);
  }
  return total;
}

/// The collapse passes of `collapse_short_edges()`, without its
/// renumbering: merged points are flagged in `removed` (one per point) and
/// the deleted triangles removed.  Returns the number of collapses.  The
/// candidates of a pass are taken in batches of about `batch_size`; those
/// of the first pass are the edges with an end flagged in `*only_near` (one
/// flag per point), or all of them if it is null.  If `kept` is not null
/// (one flag per point), the point that stays in each collapse is flagged.
template <typename Triangle>
std::size_t collapse_short_edge_passes(const std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                                       std::size_t first_feature_vertex, double max_length,
                                       std::vector<unsigned char>& removed,
                                       Collapse_rows method = Collapse_rows::AUTOMATIC,
                                       std::size_t batch_size = candidates_per_batch,
                                       const std::vector<unsigned char>* only_near = nullptr,
                                       std::vector<unsigned char>* kept = nullptr)
{
  if(only_near != nullptr && std::find(only_near->begin(), only_near->end(), 1) == only_near->end())
    return 0; // no end flagged (an empty flag vector would mean all edges below)
  if(method == Collapse_rows::MERGED ||
     (method == Collapse_rows::AUTOMATIC && 3 * triangles.size() <= max_merged_rows_corners))
    return collapse_short_edges_with_merged_rows(points, triangles, first_feature_vertex, max_length, removed,
                                                 batch_size, only_near, kept);
  Collapse_marks marks;
  marks.kept = kept;
  marks.removed.swap(removed);
  if(only_near != nullptr)
    marks.near_collapse = *only_near;
  std::size_t total = 0;
  for(int pass = 0; pass < max_collapse_passes; ++pass)
  {
    const std::size_t collapses =
        collapse_short_edges_once(points, triangles, first_feature_vertex, max_length, marks, batch_size);
    total += collapses;
    if(collapses == 0)
      break;
  }
  marks.removed.swap(removed);
  return total;
}

/// Removes the points flagged in `removed`, renumbering the others in order
/// (the triangles, the crease edges, the corners and `labels`, if not null,
/// with them).  Returns how many of the points below `first_feature_vertex`
/// remain: the feature vertices still follow the edge points.
template <typename Triangle>
std::size_t remove_merged_points(std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                                 const std::vector<unsigned char>& removed, std::size_t first_feature_vertex,
                                 std::vector<std::array<std::size_t, 2>>& creases, std::vector<std::size_t>& corners,
                                 std::vector<std::uint8_t>* labels)
{
  typedef typename Triangle::value_type Index;
  // The triangles' index type numbers them all: half the memory of size_t.
  std::vector<Index> new_index(points.size());
  std::size_t next = 0, edge_points = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    new_index[v] = Index(next);
    if(!removed[v])
    {
      if(labels != nullptr)
        (*labels)[next] = (*labels)[v];
      points[next++] = points[v];
      if(v < first_feature_vertex)
        ++edge_points;
    }
  }
  points.resize(next);
  if(labels != nullptr)
    labels->resize(next);
  for(Triangle& tr : triangles)
    for(Index& v : tr)
      v = new_index[v];
  for(auto& c : creases)
    c = {{std::size_t(new_index[c[0]]), std::size_t(new_index[c[1]])}};
  for(auto& c : corners)
    c = std::size_t(new_index[c]);
  return edge_points;
}

/// Collapses the edges shorter than `max_length` between two edge points
/// (indices below `first_feature_vertex`), or an edge point and a feature
/// vertex (the edge point goes), then removes the merged
/// points and the deleted triangles, renumbering the points in order (and
/// the crease edges and corners with them).  Returns the number of collapses.
/// The passes are repeated (at most `max_collapse_passes`) while they
/// collapse something: a vertex next to a lattice point often ends two
/// short edges, and one pass moves each vertex once.  Then the remaining
/// slivers are flipped away where the surface is nearly flat
/// (`flip_slivers()`, the crease edges kept), and the collapses and flips
/// are tried once more where the flips changed the triangles.  `labels`
/// (one per point, if not null) follows the renumbering.  `ConcurrencyTag`
/// is for the flips' corner table; the collapses are sequential.
template <typename ConcurrencyTag = Sequential_tag, typename Triangle>
std::size_t collapse_short_edges(std::vector<Vector_3d>& points, std::vector<Triangle>& triangles,
                                 std::size_t first_feature_vertex, double max_length,
                                 std::vector<std::array<std::size_t, 2>>& creases, std::vector<std::size_t>& corners,
                                 std::vector<std::uint8_t>* labels = nullptr)
{
  std::vector<unsigned char> removed(points.size(), 0);
  std::size_t total = collapse_short_edge_passes(points, triangles, first_feature_vertex, max_length, removed);
  if(total > 0)
    first_feature_vertex =
        remove_merged_points(points, triangles, removed, first_feature_vertex, creases, corners, labels);
  // The flips' corner table is the memory peak of the feature path: what the
  // collapses freed goes back first.
  std::vector<unsigned char>().swap(removed);
  release_unused_capacity(points);
  release_unused_capacity(triangles);
  if(labels != nullptr)
    release_unused_capacity(*labels);
  // The passes' smaller tables, freed into the heap, stay resident beside
  // the corner table (60 MB at 2048 cells); on small outputs the table
  // reuses their pages, which is cheaper than fresh ones.
  if(triangles.size() * sizeof(Triangle) >= min_bytes_worth_releasing)
    release_free_memory();
  // What a collapse cannot remove (caps, needles at feature vertices):
  // Lawson flips between nearly coplanar triangles, moving the surface by
  // at most a fifth of the sliver length (Sliver_flips.h).
  Sliver_flip_settings flip;
  flip.max_deviation = 0.2 * max_length;
  std::vector<unsigned char> flipped;
  if(flip_slivers<ConcurrencyTag>(points, triangles, creases, flip, &flipped) == 0)
    return total;
  // Most needles left by the passes are next to a cap: collapsing the short
  // edge either way would squash that cap flat, and is refused.  Once the
  // flips have removed the cap, it passes.  So the edges with an end in a
  // flipped triangle (whose stars the flips changed) are tried again, and
  // the flips run again if any collapses.
  // The flips then run only near the stars these collapses changed
  // (`flip_slivers_near()`): a second full run cost as much as the first.
  removed.assign(points.size(), 0);
  std::vector<unsigned char> kept(points.size(), 0);
  const std::size_t again = collapse_short_edge_passes(points, triangles, first_feature_vertex, max_length, removed,
                                                       Collapse_rows::AUTOMATIC, candidates_per_batch, &flipped,
                                                       &kept);
  std::vector<unsigned char>().swap(flipped);
  if(again == 0)
    return total;
  // Before the renumbering, which the flips do not need (the merged points
  // are in no triangle), so `kept` keeps its numbering.
  flip_slivers_near(points, triangles, creases, flip, kept);
  remove_merged_points(points, triangles, removed, first_feature_vertex, creases, corners, labels);
  return total + again;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_COLLAPSE_SHORT_EDGES_H
