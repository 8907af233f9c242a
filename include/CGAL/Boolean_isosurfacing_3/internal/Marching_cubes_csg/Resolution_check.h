// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_RESOLUTION_CHECK_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_RESOLUTION_CHECK_H

// What the lattice saw of each connected component of each input mesh,
// against the exact component: its volume against (lattice points inside
// it) x r^3, and whether it crosses any lattice edge at all.  A component
// thinner than the spacing, or smaller than a cell, can fall between the
// lattice points and vanish from the output without any other sign; this
// check makes that visible (`Marching_cubes_csg_statistics`).
//
// Why it is cheap and exact enough: the classifier already stores every
// crossing with the input triangle it crosses, and on one x line the
// crossings of one closed component pair up by parity (the symbolic
// perturbation makes every crossing count), so the points between a pair
// are exactly the lattice points of the line inside the component.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Lattice_classifier_3.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>
#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Mesh_triangles_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A connected component of an input mesh that the lattice does not resolve
/// (see `Marching_cubes_csg_statistics::under_resolved_components`).
struct Marching_cubes_csg_component_report
{
  /// The input mesh (variable) and its component, numbered in the order of
  /// their first face in `faces()`.
  std::size_t mesh = 0, component = 0;
  std::size_t triangles = 0;
  /// Crossings of the component with lattice edges (0: the lattice does not
  /// see it at all).
  std::size_t crossings = 0;
  /// Lattice points inside the component.
  std::size_t inside_points = 0;
  /// The component's exact enclosed volume (divergence theorem, absolute
  /// value) and `inside_points * spacing^3`.
  double volume = 0, lattice_volume = 0;
  /// A spacing that puts lattice points into it: volume / area (half the
  /// thickness of a slab, a sixth of the diameter of a ball), at most half
  /// the current spacing.
  double suggested_spacing = 0;
};

namespace internal {
namespace Marching_cubes_csg {

// Per input triangle, its component; per component, its mesh, number within
// the mesh, size, volume, area and bounding box.  Triangles are joined by
// shared vertices: the indices of a soup, or equal positions in a mesh given
// as a FaceGraph (there two shells touching at a point count as one
// component, which only makes the check coarser).
struct Component_labels
{
  std::vector<std::uint32_t> of_triangle;
  // Bit `axis` set: the triangle's plane is perpendicular to that axis (its
  // normal's other two components are exactly 0), a face of an axis-aligned
  // plate or of a clipping box.
  std::vector<std::uint8_t> perpendicular_axes;
  struct Component
  {
    std::size_t mesh = 0, number = 0, triangles = 0;
    double volume = 0, area = 0;
    std::array<double, 3> low{{0, 0, 0}}, high{{0, 0, 0}};
  };
  std::vector<Component> components;
};

// The labels of `triangles` whose corner c is vertex `vertex_of_corner[c]`
// (numbers below `number_of_vertices`, distinct between meshes).
inline Component_labels label_components(const std::vector<Lattice_triangle>& triangles,
                                         const std::vector<std::uint32_t>& vertex_of_corner,
                                         std::size_t number_of_vertices);

// Joins the triangles by shared (position, mesh): for meshes whose vertices
// the caller numbers in another way (any FaceGraph).
inline Component_labels label_components(const std::vector<Lattice_triangle>& triangles)
{
  // Weld equal (position, mesh) corners with an open-addressing table of
  // corner numbers: no allocation per entry (an unordered_map made this
  // check ~10 % of a whole csg run).
  const std::size_t corners = 3 * triangles.size();
  auto point_of = [&](std::size_t c) -> const std::array<double, 3>& { return triangles[c / 3].p[c % 3]; };
  auto hash = [&](std::size_t c) {
    std::uint64_t h = triangles[c / 3].mesh * 0x9e3779b97f4a7c15ULL;
    for(double x : point_of(c))
    {
      std::uint64_t bits;
      const double d = x == 0 ? 0.0 : x; // -0 and +0 are one point
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 0xff51afd7ed558ccdULL;
      h ^= h >> 32;
    }
    return h;
  };
  std::size_t table_size = 16;
  while(table_size < 2 * corners)
    table_size *= 2;
  const std::uint32_t empty = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> table(table_size, empty); // a corner number, or empty
  std::vector<std::uint32_t> vertex_of_corner(corners);
  std::uint32_t vertices = 0;
  for(std::size_t c = 0; c < corners; ++c)
  {
    std::size_t slot = hash(c) & (table_size - 1);
    for(;; slot = (slot + 1) & (table_size - 1))
    {
      const std::uint32_t other = table[slot];
      if(other == empty)
      {
        table[slot] = std::uint32_t(c);
        vertex_of_corner[c] = vertices++;
        break;
      }
      const std::array<double, 3>& p = point_of(c);
      const std::array<double, 3>& q = point_of(other);
      if(triangles[other / 3].mesh == triangles[c / 3].mesh && p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
      {
        vertex_of_corner[c] = vertex_of_corner[other];
        break;
      }
    }
  }
  std::vector<std::uint32_t>().swap(table);
  return label_components(triangles, vertex_of_corner, vertices);
}

inline Component_labels label_components(const std::vector<Lattice_triangle>& triangles,
                                         const std::vector<std::uint32_t>& vertex_of_corner,
                                         std::size_t number_of_vertices)
{
  const std::uint32_t empty = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> parent(number_of_vertices);
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  auto find = [&](std::uint32_t v) {
    while(parent[v] != v)
    {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 1; k < 3; ++k)
    {
      const std::uint32_t a = find(vertex_of_corner[3 * t]), b = find(vertex_of_corner[3 * t + k]);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  Component_labels labels;
  labels.of_triangle.resize(triangles.size());
  std::vector<std::uint32_t> component_of_root(parent.size(), empty);
  std::vector<std::size_t> per_mesh;
  std::vector<Accurate_sum<double>> volume;
  std::vector<std::array<double, 3>> reference;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Lattice_triangle& tri = triangles[t];
    std::uint32_t& id = component_of_root[find(vertex_of_corner[3 * t])];
    if(id == empty)
    {
      id = std::uint32_t(labels.components.size());
      if(per_mesh.size() <= tri.mesh)
        per_mesh.resize(tri.mesh + 1, 0);
      Component_labels::Component c;
      c.mesh = tri.mesh;
      c.number = per_mesh[tri.mesh]++;
      c.low = c.high = tri.p[0];
      labels.components.push_back(c);
      volume.emplace_back();
      reference.push_back(tri.p[0]); // tetrahedra about a point of the component: less cancellation
    }
    labels.of_triangle[t] = id;
    Component_labels::Component& c = labels.components[id];
    ++c.triangles;
    std::array<std::array<double, 3>, 3> q;
    for(int v = 0; v < 3; ++v)
      for(int a = 0; a < 3; ++a)
      {
        q[v][a] = tri.p[v][a] - reference[id][a];
        c.low[a] = (std::min)(c.low[a], tri.p[v][a]);
        c.high[a] = (std::max)(c.high[a], tri.p[v][a]);
      }
    volume[id].add((q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                    q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0])) /
                   6);
    std::array<double, 3> u, w;
    for(int a = 0; a < 3; ++a)
    {
      u[a] = q[1][a] - q[0][a];
      w[a] = q[2][a] - q[0][a];
    }
    const double nx = u[1] * w[2] - u[2] * w[1], ny = u[2] * w[0] - u[0] * w[2], nz = u[0] * w[1] - u[1] * w[0];
    c.area += 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
  }
  for(std::size_t id = 0; id < labels.components.size(); ++id)
    labels.components[id].volume = std::abs(volume[id].result());
  labels.perpendicular_axes.resize(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::array<signed char, 3>& n = triangles[t].normal_sign;
    labels.perpendicular_axes[t] = std::uint8_t((n[1] == 0 && n[2] == 0 ? 1 : 0) | (n[0] == 0 && n[2] == 0 ? 2 : 0) |
                                                (n[0] == 0 && n[1] == 0 ? 4 : 0));
  }
  return labels;
}

// The components of the input meshes: soups (what the tools read) by their
// vertex indices, which the closedness check has already matched edge by
// edge, so each component is a closed shell; other meshes by position.
template <typename TriangleMeshRange>
Component_labels label_input_components(const TriangleMeshRange& meshes, const std::vector<Lattice_triangle>& triangles)
{
  if constexpr(std::is_same<Mesh_of_range<TriangleMeshRange>, Triangle_soup_3>::value)
  {
    std::vector<std::uint32_t> vertex_of_corner;
    vertex_of_corner.reserve(3 * triangles.size());
    std::size_t offset = 0;
    for(const auto& mesh : meshes)
    {
      const Triangle_soup_3& soup = unwrap_mesh(mesh);
      if(offset + soup.points.size() >= std::numeric_limits<std::uint32_t>::max())
        return label_components(triangles);
      for(const Triangle_soup_3::Triangle& t : soup.triangles)
        for(int i = 0; i < 3; ++i)
          vertex_of_corner.push_back(std::uint32_t(offset + t[i]));
      offset += soup.points.size();
    }
    if(vertex_of_corner.size() == 3 * triangles.size())
      return label_components(triangles, vertex_of_corner, offset);
  }
  return label_components(triangles);
}

// The components of `labels` that `classifier`'s lattice does not resolve:
// no crossing, or a lattice volume off by more than a factor 2.  Components
// not inside the lattice's box are not judged (a caller's lattice may cut
// them on purpose).  Returns the number of components judged.
inline std::size_t under_resolved_components(const Component_labels& labels, const Lattice_classifier_3& classifier,
                                             std::vector<Marching_cubes_csg_component_report>& out)
{
  const Regular_lattice_3& lattice = classifier.lattice();
  const std::size_t n = labels.components.size();
  std::vector<std::size_t> crossings(n, 0), inside(n, 0);
  for(int axis = 0; axis < 3; ++axis)
    for(std::size_t v = 0; v < classifier.number_of_rows(axis); ++v)
    {
      const Lattice_classifier_3::Stored_lines lines = classifier.stored_lines(axis, v);
      for(std::size_t l = 0; l < lines.size(); ++l)
      {
        // The open crossing of each component on this line (few at a time).
        std::vector<std::pair<std::uint32_t, std::uint32_t>> open;
        for(const Lattice_crossing& c : lines[l].crossings)
        {
          const std::uint32_t id = labels.of_triangle[c.triangle];
          ++crossings[id];
          if(axis != 0)
            continue;
          const auto found = std::find_if(open.begin(), open.end(), [&](const auto& o) { return o.first == id; });
          if(found == open.end())
            open.emplace_back(id, c.index);
          else
          {
            // Entering at edge (a - 1, a), leaving at (b - 1, b): points a .. b - 1.
            inside[id] += std::size_t(c.index - found->second);
            open.erase(found);
          }
        }
      }
    }
  const CGAL::Bbox_3 box = lattice.bbox();
  const double r = lattice.spacing();
  std::size_t judged = 0;
  for(std::size_t id = 0; id < n; ++id)
  {
    const Component_labels::Component& c = labels.components[id];
    bool within = true;
    for(int a = 0; a < 3; ++a)
      within = within && c.low[a] > box.min(a) && c.high[a] < box.max(a);
    if(!within)
      continue;
    ++judged;
    const double lattice_volume = double(inside[id]) * r * r * r;
    if(crossings[id] != 0 && lattice_volume >= 0.5 * c.volume && lattice_volume <= 2 * c.volume)
      continue;
    Marching_cubes_csg_component_report report;
    report.mesh = c.mesh;
    report.component = c.number;
    report.triangles = c.triangles;
    report.crossings = crossings[id];
    report.inside_points = inside[id];
    report.volume = c.volume;
    report.lattice_volume = lattice_volume;
    const double thickness = c.area > 0 ? c.volume / c.area : 0;
    report.suggested_spacing = thickness > 0 ? (std::min)(thickness, 0.5 * r) : 0.5 * r;
    out.push_back(report);
  }
  return judged;
}

// The result seen along the lattice lines.  Between two consecutive changes
// of the result's value along a line (its surface crossings, exactly
// ordered by the classifier) lies an interval inside or outside the result.
// One that holds no lattice point -- both crossings on the same lattice
// edge -- is invisible to Marching Cubes: a wall missing from the output or a
// gap filled in.  The input-component check cannot see this (each input may
// be well resolved while their difference is a thin shell), so it is
// measured on the result itself, in one pass over the crossings.
struct Thin_result_measure
{
  std::size_t intervals = 0;      // result intervals between two crossings, all lines
  std::size_t thin_intervals = 0; // ... of which hold no lattice point
  // Along the axis where thin_volume / line_volume is largest (a thin wall
  // is seen by the lines that cross it, not by those parallel to it):
  double line_volume = 0;        // the result's volume as line lengths x spacing^2
  double thin_volume = 0;        // the thin intervals' part, the same way (inside and outside ones)
  double median_thin_length = 0; // of the thin intervals, all axes
  // Intervals that hold fewer than two lattice points: a wall (or gap) only
  // one point thick, which Marching Cubes connects only through the faces
  // the table joins -- an oblique one falls apart into pieces (a ball minus a
  // ball 1.3 spacings smaller: -3.5 % of the volume).  A wall between two
  // faces perpendicular to the line is fine (every line through it sees the
  // same points) and is not counted, and an oblique wall is sparse along at
  // least two axes: so, the second largest over the axes of the sparse
  // intervals' part of the line volume.
  double sparse_fraction = 0;
  double median_sparse_length = 0; // of the sparse intervals, all axes
};

inline Thin_result_measure measure_thin_result(const Lattice_classifier_3& classifier,
                                               const Boolean_expression& expression, const Component_labels& labels)
{
  const Regular_lattice_3& lattice = classifier.lattice();
  const std::array<std::size_t, 3>& n = lattice.number_of_points();
  const double area = lattice.spacing() * lattice.spacing();
  Thin_result_measure m;
  std::vector<double> thin_lengths, sparse_lengths;
  std::array<double, 3> line_volume{{0, 0, 0}}, thin_volume{{0, 0, 0}}, sparse_volume{{0, 0, 0}};
  for(int axis = 0; axis < 3; ++axis)
    for(std::size_t row = 0; row < classifier.number_of_rows(axis); ++row)
    {
      const Lattice_classifier_3::Stored_lines lines = classifier.stored_lines(axis, row);
      for(std::size_t l = 0; l < lines.size(); ++l)
      {
        const Lattice_classifier_3::Crossing_range crossings = lines[l].crossings;
        if(crossings.empty())
          continue;
        // The line's first point; its mask gives the state the crossings toggle.
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        std::array<std::size_t, 3> first{{0, 0, 0}};
        first[u] = lines[l].u;
        first[v] = row;
        std::uint64_t state = axis == 0 ? lines[l].start_mask : classifier.mask(first[0], first[1], first[2]);
        bool inside = expression.evaluate(state);
        bool have_change = false;
        std::uint32_t change_index = 0, change_triangle = 0;
        const std::uint8_t axis_bit = std::uint8_t(1u << axis);
        double change_position = lattice.coordinate(axis, 0);
        for(const Lattice_crossing& c : crossings)
        {
          state ^= std::uint64_t(1) << c.mesh;
          const bool now = expression.evaluate(state);
          if(now == inside)
            continue;
          if(have_change)
          {
            ++m.intervals;
            // Entering at edge (a - 1, a), leaving at (b - 1, b): points a .. b - 1.
            if(c.index == change_index)
            {
              ++m.thin_intervals;
              thin_volume[axis] += (c.position - change_position) * area;
              thin_lengths.push_back(c.position - change_position);
            }
            // The triangles' flags are read only for the few short intervals.
            if(c.index <= change_index + 1 && ((labels.perpendicular_axes[c.triangle] & axis_bit) == 0 ||
                                               (labels.perpendicular_axes[change_triangle] & axis_bit) == 0))
            {
              sparse_volume[axis] += (c.position - change_position) * area;
              sparse_lengths.push_back(c.position - change_position);
            }
          }
          if(inside)
            line_volume[axis] += (c.position - change_position) * area;
          inside = now;
          have_change = true;
          change_index = c.index;
          change_triangle = c.triangle;
          change_position = c.position;
        }
        if(inside)
          line_volume[axis] += (lattice.coordinate(axis, n[axis] - 1) - change_position) * area;
      }
    }
  for(int axis = 0; axis < 3; ++axis)
    if(thin_volume[axis] * m.line_volume > m.thin_volume * line_volume[axis] || m.line_volume == 0)
    {
      m.line_volume = line_volume[axis];
      m.thin_volume = thin_volume[axis];
    }
  std::array<double, 3> sparse_part{{0, 0, 0}};
  for(int axis = 0; axis < 3; ++axis)
    sparse_part[axis] = line_volume[axis] > 0 ? sparse_volume[axis] / line_volume[axis] : 0;
  std::sort(sparse_part.begin(), sparse_part.end());
  m.sparse_fraction = sparse_part[1];
  const auto median = [](std::vector<double>& lengths) {
    if(lengths.empty())
      return 0.0;
    std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
    return lengths[lengths.size() / 2];
  };
  m.median_thin_length = median(thin_lengths);
  m.median_sparse_length = median(sparse_lengths);
  return m;
}

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_RESOLUTION_CHECK_H
