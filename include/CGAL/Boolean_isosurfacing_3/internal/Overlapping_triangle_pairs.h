// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_OVERLAPPING_TRIANGLE_PAIRS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_OVERLAPPING_TRIANGLE_PAIRS_H

// The pairs of triangles of a soup whose bounding boxes overlap, found on a
// uniform grid of cells about the size of a triangle: each triangle is
// listed in the cells its box meets, the lists are one radix sort of
// (cell, triangle) keys, and a pair is visited in the one cell that holds
// the lowest corner of the two boxes' intersection (the cell of the larger
// of two lower bounds is the larger of their cells), so once.  Linear in the
// triangles and the pairs when the triangles are about a cell: Marching
// Cubes output, and most meshes a cell sized from their mean triangle.
// CGAL's box_intersection_d() (a segment tree, O(n log^3 n)) took half of
// `PMP::does_self_intersect()`'s 6.6 s of CPU on 1.6M triangles, and 5-20 ms
// on the few thousand boxes of the weak-fan check: as long as what it filters.

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Flat_uint64_map.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

/// A uniform grid of `cells[0] x cells[1] x cells[2]` cells of side
/// `1 / inverse_cell_size` from `origin`; coordinates outside it map to the
/// border cells (any nondecreasing map of a coordinate to its cell finds
/// each pair once).
struct Triangle_grid_3
{
  /// At most this many cells when every triangle is listed: a cell id and
  /// a triangle index share one 64-bit sort key.
  static constexpr std::size_t max_cells = std::size_t(1) << 26;
  /// At most this many when only the cells of selected triangles are
  /// (they are numbered apart: the grid is sparse).
  static constexpr std::size_t max_sparse_cells = std::size_t(1) << 62;

  std::array<double, 3> origin{{0, 0, 0}};
  double inverse_cell_size = 1;
  std::array<std::uint32_t, 3> cells{{1, 1, 1}};

  std::size_t number_of_cells() const { return std::size_t(cells[0]) * cells[1] * cells[2]; }

  // A product, not a division.
  std::uint32_t cell_of(int axis, double x) const
  {
    const double c = std::floor((x - origin[axis]) * inverse_cell_size);
    return c >= 0 ? std::uint32_t((std::min)(c, double(cells[axis] - 1))) : std::uint32_t(0);
  }

  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return i + cells[0] * (j + cells[1] * k); }

  /// The number of cells of side `cell_size` from the low corner of `box`
  /// that cover it (a double: it may be beyond any integer type).
  static double number_of_cells_covering(const CGAL::Bbox_3& box, double cell_size)
  {
    double n = 1;
    for(int a = 0; a < 3; ++a)
      n *= std::floor((box.max(a) - box.min(a)) / cell_size) + 1;
    return n;
  }

  /// That grid.  \pre number_of_cells_covering(box, cell_size) <= max_cells
  static Triangle_grid_3 covering(const CGAL::Bbox_3& box, double cell_size)
  {
    Triangle_grid_3 grid;
    for(int a = 0; a < 3; ++a)
    {
      grid.origin[a] = box.min(a);
      grid.cells[a] = std::uint32_t(std::floor((box.max(a) - box.min(a)) / cell_size) + 1);
    }
    grid.inverse_cell_size = 1 / cell_size;
    return grid;
  }
};

/// A triangle's bounding box and the cells it meets, from `lo` to `hi`.
struct Triangle_cell_box
{
  CGAL::Bbox_3 box;
  std::array<std::uint32_t, 3> lo, hi;
};

template <typename Triangle>
Triangle_cell_box triangle_cell_box(const std::vector<std::array<double, 3>>& points, const Triangle& t,
                                    const Triangle_grid_3& grid)
{
  const std::array<double, 3>&p = points[std::size_t(t[0])], &q = points[std::size_t(t[1])],
                              &r = points[std::size_t(t[2])];
  Triangle_cell_box c;
  c.box = CGAL::Bbox_3((std::min)({p[0], q[0], r[0]}), (std::min)({p[1], q[1], r[1]}), (std::min)({p[2], q[2], r[2]}),
                       (std::max)({p[0], q[0], r[0]}), (std::max)({p[1], q[1], r[1]}), (std::max)({p[2], q[2], r[2]}));
  for(int a = 0; a < 3; ++a)
  {
    c.lo[a] = grid.cell_of(a, c.box.min(a));
    c.hi[a] = grid.cell_of(a, c.box.max(a));
  }
  return c;
}

/// Calls `f(cell)` for each cell of `grid` that `c` meets.
template <typename Function>
void for_each_cell(const Triangle_cell_box& c, const Triangle_grid_3& grid, const Function& f)
{
  for(std::size_t k = c.lo[2]; k <= c.hi[2]; ++k)
    for(std::size_t j = c.lo[1]; j <= c.hi[1]; ++j)
      for(std::size_t i = c.lo[0]; i <= c.hi[0]; ++i)
        f(grid.index(i, j, k));
}

/// The number of parts the visits are split into: `visit(part, t, u)` is
/// called with `part` below it, and the calls of one part in order, on one
/// thread at a time (a caller collects into one buffer a part).
constexpr std::size_t overlapping_pair_parts = 64;

/// Calls `visit(part, t, u)`, t < u, once for each pair of distinct triangles
/// whose bounding boxes overlap (closed boxes) and one of which at least is
/// `selected(t)`; `visit` returns `true` to stop the search.  With
/// `all_selected`, `selected` is not called: every pair.  Returns `false`,
/// visiting nothing, if the grid would list more than `max_listed`
/// (cell, triangle) entries or compare more than `max_box_pairs` pairs of
/// boxes: the triangles are not about a cell (a few long ones across many
/// cells, or many small ones in a few cells), and the caller takes another
/// way.  Under `Parallel_tag` the parts run concurrently.  Without
/// `all_selected` the grid may have up to `max_sparse_cells` cells: only
/// those a selected triangle meets are stored (a weak-fan check on a thin
/// shell at 65536 cells: 2 10^13 lattice cubes, a few million marked).
template <typename ConcurrencyTag, typename Triangle, typename Selected, typename Visit>
bool for_each_overlapping_triangle_pair(const std::vector<std::array<double, 3>>& points,
                                        const std::vector<Triangle>& triangles, const Triangle_grid_3& grid,
                                        bool all_selected, const Selected& selected, std::size_t max_listed,
                                        std::size_t max_box_pairs, const Visit& visit)
{
  CGAL_precondition(grid.number_of_cells() <=
                    (all_selected ? Triangle_grid_3::max_cells : Triangle_grid_3::max_sparse_cells));
  CGAL_precondition(triangles.size() <= (std::size_t(1) << 32));
  // Without all_selected, only the cells a selected triangle meets matter:
  // `marked_cells` lists them in increasing order, and the sort keys carry
  // their rank there (`rank_of_marked`) instead of the cell id.
  std::vector<std::uint64_t> marked_cells;
  Flat_uint64_map<std::uint32_t> rank_of_marked;
  if(!all_selected)
  {
    for(std::size_t t = 0; t < triangles.size(); ++t)
      if(selected(t))
        for_each_cell(triangle_cell_box(points, triangles[t], grid), grid,
                      [&](std::size_t cell) { marked_cells.push_back(cell); });
    std::sort(marked_cells.begin(), marked_cells.end());
    marked_cells.erase(std::unique(marked_cells.begin(), marked_cells.end()), marked_cells.end());
    if(marked_cells.size() >= (std::size_t(1) << 32))
      return false;
    rank_of_marked.reserve(marked_cells.size());
    for(std::size_t r = 0; r < marked_cells.size(); ++r)
      rank_of_marked.insert(marked_cells[r], std::uint32_t(r));
  }

  // The keys (cell << 32 | triangle), by ranges of triangles: one vector a
  // range, in triangle order.  The total is watched as they grow, and each
  // triangle's cells are counted before they are listed: a triangle across
  // the whole grid would list up to 2^26 keys (512 MB).
  typedef std::vector<std::uint64_t, Default_init_allocator<std::uint64_t>> Keys;
  const std::size_t parts = overlapping_pair_parts;
  const auto range = [&](std::size_t part, std::size_t n) {
    return std::array<std::size_t, 2>{{n * part / parts, n * (part + 1) / parts}};
  };
  std::vector<Keys> listed(parts);
  std::atomic<std::size_t> total_listed(0);
  std::atomic<bool> over_budget(false);
  concurrent_for<ConcurrencyTag>(parts, [&](std::size_t part) {
    Keys& out = listed[part];
    const std::array<std::size_t, 2> r = range(part, triangles.size());
    if(all_selected)
      out.reserve(4 * (r[1] - r[0])); // about 2.4 cells a triangle; a selection lists few
    std::size_t reported = 0;
    for(std::size_t t = r[0]; t < r[1]; ++t)
    {
      const Triangle_cell_box c = triangle_cell_box(points, triangles[t], grid);
      const std::size_t cells = std::size_t(c.hi[0] - c.lo[0] + 1) * std::size_t(c.hi[1] - c.lo[1] + 1) *
                                std::size_t(c.hi[2] - c.lo[2] + 1); // all of them listed at most
      if(over_budget.load(std::memory_order_relaxed) ||
         total_listed.load(std::memory_order_relaxed) + (out.size() - reported) + cells > max_listed)
      {
        over_budget = true;
        return;
      }
      for_each_cell(c, grid, [&](std::size_t cell) {
        if(all_selected)
          out.push_back((std::uint64_t(cell) << 32) | t);
        else if(const std::uint32_t* rank = rank_of_marked.find(cell))
          out.push_back((std::uint64_t(*rank) << 32) | t);
      });
      if(out.size() - reported >= 4096 || t + 1 == r[1])
      {
        if((total_listed += out.size() - reported) > max_listed)
        {
          over_budget = true;
          return;
        }
        reported = out.size();
      }
    }
  });
  if(over_budget)
    return false;

  // A stable LSD radix sort on the cell bits: within a cell the triangles
  // stay in increasing order.  The first pass reads the ranges' vectors.
  Keys keys(total_listed), sorted(total_listed);
  {
    int cell_bits = 0;
    while((std::size_t(1) << cell_bits) < (all_selected ? grid.number_of_cells() : marked_cells.size()))
      ++cell_bits;
    const int digit_bits = 13;
    const std::uint64_t mask = (std::uint64_t(1) << digit_bits) - 1;
    std::vector<std::size_t> count(std::size_t(1) << digit_bits);
    for(int shift = 32; shift < 32 + (std::max)(cell_bits, 1); shift += digit_bits)
    {
      const bool first = shift == 32;
      std::fill(count.begin(), count.end(), 0);
      const auto for_each_key = [&](const auto& f) {
        if(first)
        {
          for(const Keys& l : listed)
            for(const std::uint64_t key : l)
              f(key);
        }
        else
          for(const std::uint64_t key : keys)
            f(key);
      };
      for_each_key([&](std::uint64_t key) { ++count[(key >> shift) & mask]; });
      std::size_t sum = 0;
      for(std::size_t& c : count)
      {
        const std::size_t here = c;
        c = sum;
        sum += here;
      }
      for_each_key([&](std::uint64_t key) { sorted[count[(key >> shift) & mask]++] = key; });
      if(first)
        std::vector<Keys>().swap(listed);
      keys.swap(sorted);
    }
  }
  Keys().swap(sorted);
  // The runs of one cell, and the pairs of boxes they compare.
  std::vector<std::size_t> run_begin;
  for(std::size_t e = 0; e < keys.size(); ++e)
    if(e == 0 || (keys[e] >> 32) != (keys[e - 1] >> 32))
      run_begin.push_back(e);
  run_begin.push_back(keys.size());
  const std::size_t runs = run_begin.size() - 1;
  std::size_t box_pairs = 0;
  for(std::size_t run = 0; run < runs; ++run)
  {
    const std::size_t m = run_begin[run + 1] - run_begin[run];
    box_pairs += m * (m - 1) / 2;
  }
  if(box_pairs > max_box_pairs)
    return false;

  // Parts of about the same number of pairs would balance better; parts of
  // runs are what the entries allow without a second pass.
  std::atomic<bool> stop(false);
  concurrent_for<ConcurrencyTag>(parts, [&](std::size_t part) {
    std::vector<Triangle_cell_box> boxes;
    std::vector<char> is_selected;
    const std::array<std::size_t, 2> r = range(part, runs);
    for(std::size_t run = r[0]; run < r[1] && !stop.load(std::memory_order_relaxed); ++run)
    {
      const std::size_t begin = run_begin[run], end = run_begin[run + 1];
      if(end - begin < 2)
        continue;
      const std::size_t cell =
          all_selected ? std::size_t(keys[begin] >> 32) : std::size_t(marked_cells[std::size_t(keys[begin] >> 32)]);
      const std::array<std::uint32_t, 3> ijk{{std::uint32_t(cell % grid.cells[0]),
                                             std::uint32_t(cell / grid.cells[0] % grid.cells[1]),
                                             std::uint32_t(cell / grid.cells[0] / grid.cells[1])}};
      boxes.clear();
      is_selected.clear();
      for(std::size_t e = begin; e < end; ++e)
      {
        const std::size_t t = std::size_t(keys[e] & 0xffffffffu);
        boxes.push_back(triangle_cell_box(points, triangles[t], grid));
        is_selected.push_back(all_selected || selected(t));
      }
      for(std::size_t a = 0; a + 1 < boxes.size(); ++a)
        for(std::size_t b = a + 1; b < boxes.size(); ++b)
        {
          if(!(is_selected[a] || is_selected[b]) || !CGAL::do_overlap(boxes[a].box, boxes[b].box))
            continue;
          bool here = true;
          for(int x = 0; x < 3 && here; ++x)
            here = (std::max)(boxes[a].lo[x], boxes[b].lo[x]) == ijk[x];
          if(here && visit(part, std::size_t(keys[begin + a] & 0xffffffffu), std::size_t(keys[begin + b] & 0xffffffffu)))
          {
            stop = true;
            return;
          }
        }
    }
  });
  return true;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_OVERLAPPING_TRIANGLE_PAIRS_H
