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

#include <CGAL/Boolean_isosurfacing_3/Lattice_classifier_3.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Accurate_sum.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>
#include <unordered_map>
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
// shared vertex positions (the readers weld equal points), so two shells
// touching at a point count as one component, which only makes the check
// coarser there.
struct Component_labels
{
  std::vector<std::uint32_t> of_triangle;
  struct Component
  {
    std::size_t mesh = 0, number = 0, triangles = 0;
    double volume = 0, area = 0;
    std::array<double, 3> low{{0, 0, 0}}, high{{0, 0, 0}};
  };
  std::vector<Component> components;
};

inline Component_labels label_components(const std::vector<Lattice_triangle>& triangles)
{
  struct Key
  {
    std::array<double, 3> p;
    std::uint32_t mesh;
    bool operator==(const Key& o) const { return p == o.p && mesh == o.mesh; }
  };
  struct Key_hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::size_t h = std::hash<std::uint32_t>()(k.mesh);
      for(double c : k.p)
      {
        std::uint64_t bits;
        const double d = c == 0 ? 0.0 : c; // -0 and +0 are one point
        std::memcpy(&bits, &d, sizeof bits);
        h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      }
      return h;
    }
  };
  std::unordered_map<Key, std::uint32_t, Key_hash> vertex_of;
  vertex_of.reserve(triangles.size());
  std::vector<std::uint32_t> parent;
  auto find = [&](std::uint32_t v) {
    while(parent[v] != v)
    {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  std::vector<std::array<std::uint32_t, 3>> corner(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int c = 0; c < 3; ++c)
    {
      const auto inserted = vertex_of.emplace(Key{triangles[t].p[c], triangles[t].mesh}, std::uint32_t(parent.size()));
      if(inserted.second)
        parent.push_back(std::uint32_t(parent.size()));
      corner[t][c] = inserted.first->second;
    }
  for(const auto& c : corner)
    for(int k = 1; k < 3; ++k)
    {
      const std::uint32_t a = find(c[0]), b = find(c[k]);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  Component_labels labels;
  labels.of_triangle.resize(triangles.size());
  std::unordered_map<std::uint32_t, std::uint32_t> component_of_root;
  std::vector<std::size_t> per_mesh;
  std::vector<Accurate_sum<double>> volume;
  std::vector<std::array<double, 3>> reference;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Lattice_triangle& tri = triangles[t];
    const auto inserted = component_of_root.emplace(find(corner[t][0]), std::uint32_t(labels.components.size()));
    if(inserted.second)
    {
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
    const std::uint32_t id = inserted.first->second;
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
  return labels;
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
    for(std::size_t line = 0; line < classifier.number_of_lines(axis); ++line)
    {
      // The open crossing of each component on this line (few at a time).
      std::vector<std::pair<std::uint32_t, std::uint32_t>> open;
      for(const Lattice_crossing& c : classifier.crossings_on_line(axis, line))
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

} // namespace Marching_cubes_csg
} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_MARCHING_CUBES_CSG_RESOLUTION_CHECK_H
