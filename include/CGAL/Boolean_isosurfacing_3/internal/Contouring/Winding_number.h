// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_WINDING_NUMBER_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_WINDING_NUMBER_H

// The generalized winding number of oriented point samples (Barill, Dickson,
// Schmidt, Levin and Jacobson, "Fast winding numbers for soups and clouds",
// SIGGRAPH 2018), regularized:
//
//   w(p) = sum_i a_i n_i . (x_i - p) / (4 pi (|x_i - p|^2 + eps_i^2)^(3/2)),
//
// a_i the area a sample stands for, n_i its outward unit normal.  For a
// closed, densely sampled surface w is 1 inside and 0 outside; it fills gaps
// in the sampling smoothly (the level set 1/2 spans a hole like a membrane),
// and it is a sum over all samples, so a plane fitted to the wrong sheet of a
// thin wall, which flips Hoppe's nearest-plane sign, moves w only a little.
// The regularization eps_i (about the local spacing) makes w smooth across
// the samples: near a flat sheet at signed height h, w - 1/2 = -h / (2 sqrt(h^2
// + eps^2)), monotone in h and 0 on the sheet.
//
// Evaluated by Barnes-Hut on a kd-tree of the samples: a node seen from
// farther than `beta` times its radius is one regularized dipole at its
// area-weighted centre plus the first-order correction (the 3x3 moment
// sum_i a_i (x_i - c) n_i^T), as in Barill et al.; nearer nodes are opened
// down to leaves of at most 8 samples, summed exactly.  Deterministic: the
// same traversal order for every query.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

class Fast_winding_number
{
public:
  typedef std::array<double, 3> Vec;

  Fast_winding_number() = default;

  /// `points[i]`, unit outward `normals[i]`, `areas[i]` and regularization
  /// widths `eps[i]` (all the same size, at least 1).  `beta`: a node is
  /// approximated when the query is farther than beta times its radius.
  Fast_winding_number(const std::vector<Vec>& points, const std::vector<Vec>& normals, const std::vector<double>& areas,
                      const std::vector<double>& eps, double beta = 2.0)
    : m_beta2(beta * beta)
  {
    const std::size_t n = points.size();
    m_order.resize(n);
    std::iota(m_order.begin(), m_order.end(), std::size_t(0));
    m_nodes.reserve(2 * (n / leaf_size + 1) + 1);
    m_points = points;
    build(0, n, points);
    // Leaf data in leaf order: a_i n_i, x_i, eps_i^2, contiguous per leaf.
    m_x.resize(n);
    m_an.resize(n);
    m_e2.resize(n);
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t i = m_order[j];
      m_x[j] = points[i];
      for(int a = 0; a < 3; ++a)
        m_an[j][a] = areas[i] * normals[i][a];
      m_e2[j] = eps[i] * eps[i];
    }
    for(std::size_t k = m_nodes.size(); k-- > 0;)
      summarize(m_nodes[k], areas, eps);
    m_points.clear();
    m_points.shrink_to_fit();
  }

  /// w(p): about 1 inside, 0 outside.
  double operator()(const Vec& p) const
  {
    if(m_nodes.empty())
      return 0;
    double w = 0;
    std::size_t stack[128];
    std::size_t top = 0;
    stack[top++] = 0;
    while(top > 0)
    {
      const Node& node = m_nodes[stack[--top]];
      const double y0 = node.c[0] - p[0], y1 = node.c[1] - p[1], y2 = node.c[2] - p[2];
      const double d2 = y0 * y0 + y1 * y1 + y2 * y2;
      if(d2 > m_beta2 * node.r2)
      {
        // Dipole N at c, regularized with the node's mean eps^2, plus the
        // first-order term tr(grad G M) (G(y) = y / |y|^3 up to 1/(4 pi)).
        const double s2 = d2 + node.e2;
        const double inv = 1.0 / std::sqrt(s2);
        const double inv3 = inv * inv * inv;
        const double inv5 = inv3 * inv * inv;
        double value = (node.N[0] * y0 + node.N[1] * y1 + node.N[2] * y2) * inv3;
        // x_i - p = y + (x_i - c): the first-order term is tr(J M) with the
        // symmetric J = grad G(y) = I/|y|^3 - 3 y y^T/|y|^5, M[k][j] = sum a (x - c)_k n_j.
        const double* M = node.M;
        const double yMy = y0 * (M[0] * y0 + M[1] * y1 + M[2] * y2) + y1 * (M[3] * y0 + M[4] * y1 + M[5] * y2) +
                           y2 * (M[6] * y0 + M[7] * y1 + M[8] * y2);
        value += (M[0] + M[4] + M[8]) * inv3 - 3.0 * yMy * inv5;
        w += value;
        continue;
      }
      if(node.leaf)
      {
        for(std::size_t j = node.begin; j < node.end; ++j)
        {
          const double z0 = m_x[j][0] - p[0], z1 = m_x[j][1] - p[1], z2 = m_x[j][2] - p[2];
          const double s2 = z0 * z0 + z1 * z1 + z2 * z2 + m_e2[j];
          const double inv = 1.0 / std::sqrt(s2);
          w += (m_an[j][0] * z0 + m_an[j][1] * z1 + m_an[j][2] * z2) * inv * inv * inv;
        }
        continue;
      }
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
    return w * (0.25 / 3.14159265358979323846);
  }

private:
  static constexpr std::size_t leaf_size = 8;

  struct Node
  {
    std::size_t begin = 0, end = 0, left = 0, right = 0;
    bool leaf = true;
    double c[3] = {0, 0, 0}; // area-weighted centre
    double N[3] = {0, 0, 0}; // sum a n
    double M[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}; // sum a (x - c)_k n_j, row k
    double r2 = 0;           // squared radius around c
    double e2 = 0;           // area-weighted mean eps^2
  };

  // Splits at the median of the longest side of the points' box.
  std::size_t build(std::size_t begin, std::size_t end, const std::vector<Vec>& points)
  {
    const std::size_t id = m_nodes.size();
    m_nodes.emplace_back();
    m_nodes[id].begin = begin;
    m_nodes[id].end = end;
    if(end - begin <= leaf_size)
      return id;
    Vec lo = points[m_order[begin]], hi = lo;
    for(std::size_t j = begin; j < end; ++j)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], points[m_order[j]][a]);
        hi[a] = (std::max)(hi[a], points[m_order[j]][a]);
      }
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(hi[a] - lo[a] > hi[axis] - lo[axis])
        axis = a;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(m_order.begin() + std::ptrdiff_t(begin), m_order.begin() + std::ptrdiff_t(mid),
                     m_order.begin() + std::ptrdiff_t(end), [&points, axis](std::size_t a, std::size_t b) {
                       return points[a][axis] < points[b][axis] || (points[a][axis] == points[b][axis] && a < b);
                     });
    const std::size_t left = build(begin, mid, points);
    const std::size_t right = build(mid, end, points);
    m_nodes[id].leaf = false;
    m_nodes[id].left = left;
    m_nodes[id].right = right;
    return id;
  }

  void summarize(Node& node, const std::vector<double>& areas, const std::vector<double>& eps)
  {
    double area = 0;
    for(std::size_t j = node.begin; j < node.end; ++j)
    {
      const double a = areas[m_order[j]];
      area += a;
      for(int k = 0; k < 3; ++k)
        node.c[k] += a * m_x[j][k];
      node.e2 += a * eps[m_order[j]] * eps[m_order[j]];
    }
    if(area > 0)
    {
      for(int k = 0; k < 3; ++k)
        node.c[k] /= area;
      node.e2 /= area;
    }
    else
      for(int k = 0; k < 3; ++k)
        node.c[k] = m_x[node.begin][k];
    for(std::size_t j = node.begin; j < node.end; ++j)
    {
      double d2 = 0;
      for(int k = 0; k < 3; ++k)
      {
        const double dk = m_x[j][k] - node.c[k];
        d2 += dk * dk;
        node.N[k] += m_an[j][k];
        for(int l = 0; l < 3; ++l)
          node.M[3 * k + l] += dk * m_an[j][l];
      }
      node.r2 = (std::max)(node.r2, d2);
    }
  }

  double m_beta2 = 6.25;
  std::vector<Node> m_nodes;
  std::vector<std::size_t> m_order;
  std::vector<Vec> m_points, m_x, m_an;
  std::vector<double> m_e2;
};

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CONTOURING_WINDING_NUMBER_H
