// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_EXTRACT_CREASE_NETWORK_H
#define CGAL_BOOLEAN_ISOSURFACING_3_EXTRACT_CREASE_NETWORK_H

#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The crease network of a labelled polygon soup: an edge is a crease when
/// the polygons around it carry different labels (faces of different fields
/// meet there; the domain boundary counts as a label, and so does each plane
/// of it when the soup has `face_boundary_planes`: the closing faces on two
/// faces of a grid's box meet at a crease along the box's edge, and three at a
/// corner of the box).  Corners are crease
/// vertices whose number of crease edges is not 2 (ends and branchings) or
/// around which three or more labels meet.  The crease edges are chained
/// into polylines from corner to corner; a closed crease without a corner
/// becomes one closed polyline.  Exact: only labels and indices are compared.
template <typename Point_3>
Crease_network extract_crease_network(const Boolean_isosurface_soup<Point_3>& soup)
{
  const std::size_t nv = soup.points.size();
  // Undirected edges with the label of each incident polygon, sorted.
  struct Edge_use
  {
    std::size_t a, b;
    int label;
  };
  std::vector<Edge_use> uses;
  // Closing faces: one label per plane of the domain boundary, below all
  // field labels and the plain domain_boundary label.
  const bool has_planes = soup.face_boundary_planes.size() == soup.polygons.size();
  auto label = [&](std::size_t p) {
    const int field = soup.face_fields[p];
    if(field != Boolean_isosurface_soup<Point_3>::domain_boundary || !has_planes || soup.face_boundary_planes[p] < 0)
      return field;
    return Boolean_isosurface_soup<Point_3>::domain_boundary - 1 - soup.face_boundary_planes[p];
  };
  for(std::size_t p = 0; p < soup.polygons.size(); ++p)
  {
    const std::vector<std::size_t>& poly = soup.polygons[p];
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
      if(b < a)
        std::swap(a, b);
      uses.push_back(Edge_use{a, b, label(p)});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Edge_use& x, const Edge_use& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.label < y.label);
  });

  Crease_network network;
  std::vector<std::pair<std::size_t, std::size_t>> creases;
  // Labels seen around each vertex on crease edges (at most 3 remembered).
  std::vector<std::array<int, 3>> labels(nv, {{0, 0, 0}});
  std::vector<int> label_count(nv, 0);
  auto remember = [&](std::size_t v, int label) {
    for(int k = 0; k < label_count[v]; ++k)
      if(labels[v][k] == label)
        return;
    if(label_count[v] < 3)
      labels[v][label_count[v]++] = label;
  };
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while(j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b)
      ++j;
    if(uses[j - 1].label != uses[i].label)
    {
      creases.emplace_back(uses[i].a, uses[i].b);
      for(std::size_t k = i; k < j; ++k)
      {
        remember(uses[i].a, uses[k].label);
        remember(uses[i].b, uses[k].label);
      }
    }
    i = j;
  }
  network.number_of_crease_edges = creases.size();

  // Crease adjacency in CSR form.
  std::vector<std::size_t> begin(nv + 1, 0), adjacent(2 * creases.size());
  for(const auto& e : creases)
  {
    ++begin[e.first + 1];
    ++begin[e.second + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    begin[v + 1] += begin[v];
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  for(std::size_t e = 0; e < creases.size(); ++e)
  {
    adjacent[fill[creases[e].first]++] = e;
    adjacent[fill[creases[e].second]++] = e;
  }
  std::vector<bool> is_corner(nv, false);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::size_t degree = begin[v + 1] - begin[v];
    if(degree != 0 && (degree != 2 || label_count[v] >= 3))
    {
      is_corner[v] = true;
      network.corners.push_back(v);
    }
  }

  std::vector<bool> used(creases.size(), false);
  auto other = [&](std::size_t e, std::size_t v) { return creases[e].first == v ? creases[e].second : creases[e].first; };
  auto walk = [&](std::size_t start, std::size_t first_edge) {
    std::vector<std::size_t> line{start};
    std::size_t v = start, e = first_edge;
    while(true)
    {
      used[e] = true;
      v = other(e, v);
      line.push_back(v);
      if(is_corner[v] || v == start)
        break;
      std::size_t next = creases.size();
      for(std::size_t k = begin[v]; k < begin[v + 1]; ++k)
        if(!used[adjacent[k]])
          next = adjacent[k];
      if(next == creases.size())
        break;
      e = next;
    }
    network.polylines.push_back(std::move(line));
  };
  for(std::size_t c : network.corners)
    for(std::size_t k = begin[c]; k < begin[c + 1]; ++k)
      if(!used[adjacent[k]])
        walk(c, adjacent[k]);
  for(std::size_t e = 0; e < creases.size(); ++e)
    if(!used[e])
      walk(creases[e].first, e); // a closed loop without corner
  return network;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_EXTRACT_CREASE_NETWORK_H
