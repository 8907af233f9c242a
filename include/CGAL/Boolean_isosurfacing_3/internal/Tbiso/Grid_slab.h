// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_GRID_SLAB_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_GRID_SLAB_H

// The pieces extract_boolean_isosurface() shares with the slab code
// (boolean_isosurface_by_slabs.h, boolean_isosurface_slab_range.h): the
// checks of the fields, the extraction of one slab of a grid, the welding of
// the chunks, the planes of a mesh's boundary.

#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>
#include <CGAL/Boolean_isosurfacing_3/Scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_mesh_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_chunk.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Tbiso/Tbiso_tetrahedron.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

namespace internal {


template <typename Point_3>
void check_fields(std::size_t number_of_vertices, const Scalar_fields& fields, const Boolean_expression& expression)
{
  if(fields.number_of_vertices() != number_of_vertices)
    throw Invalid_input_error("the fields have values at " + std::to_string(fields.number_of_vertices()) +
                              " vertices but the domain has " + std::to_string(number_of_vertices));
  if(expression.number_of_variables() > fields.number_of_fields())
    throw Invalid_input_error("the expression names field f" + std::to_string(expression.number_of_variables() - 1) +
                              " but there are only " + std::to_string(fields.number_of_fields()) + " fields");
  fields.check_finite();
}

// Appends the chunks, in order, to `out` (see `weld_chunk()`).  Vertices
// are welded by key; `shared(key)` tells whether a key may occur in another
// chunk (only those go through the global map).  The order is that of first
// appearance, so the result does not depend on how the chunks were scheduled.
template <typename Point_3, typename SharedKey>
void weld_chunks(std::vector<Tbiso_chunk>& chunks, Boolean_isosurface_soup<Point_3>& out, const SharedKey& shared)
{
  out.clear();
  std::unordered_map<Tbiso_vertex_key, std::size_t, Tbiso_vertex_key_hash> global;
  std::size_t next_index = 0;
  for(Tbiso_chunk& chunk : chunks)
  {
    chunk.index.clear();
    weld_chunk(
        chunk,
        [&](const Tbiso_vertex_key& key) {
          if(!shared(key))
            return tbiso_no_index();
          const auto found = global.find(key);
          return found == global.end() ? tbiso_no_index() : found->second;
        },
        [&](const Tbiso_vertex_key& key, std::size_t index) {
          if(shared(key))
            global.emplace(key, index);
        },
        next_index, [&](const std::array<double, 3>& p) { out.points.push_back(Point_3(p[0], p[1], p[2])); },
        [&](const std::size_t* v, std::size_t n, int label, int plane) {
          out.polygons.emplace_back(v, v + n);
          out.face_fields.push_back(label);
          out.face_boundary_planes.push_back(plane);
        });
    chunk = Tbiso_chunk(); // release memory early
  }
}


// The box face (2 axis + 0 at the minimum, + 1 at the maximum) that the face
// opposite corner l of a grid tetrahedron lies on; -1 if none.
template <typename GeomTraits, typename Tetrahedron>
int grid_boundary_plane(const Tetrahedral_grid_3<GeomTraits>& grid, const Tetrahedron& tet, int l)
{
  const std::array<std::size_t, 3>& n = grid.vertex_counts();
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      bool on = true;
      for(int c = 0; c < 4 && on; ++c)
        if(c != l)
        {
          std::size_t v = tet[c];
          const std::size_t i = v % n[0], j = (v / n[0]) % n[1], k = v / (n[0] * n[1]);
          const std::size_t coordinate = axis == 0 ? i : (axis == 1 ? j : k);
          on = coordinate == (side == 0 ? 0 : n[axis] - 1);
        }
      if(on)
        return 2 * axis + side;
    }
  return -1;
}

// The boundary faces of a tetrahedral mesh (key 4 t + l: the face of
// tetrahedron t opposite its corner l) grouped into planes: the maximal sets
// of boundary faces connected across boundary edges and coplanar (exact
// predicate on the input points).  Numbered in order of first face.
template <typename GeomTraits>
std::unordered_map<std::size_t, int> boundary_planes(const Tetrahedral_mesh_3<GeomTraits>& mesh)
{
  typedef Tetrahedral_mesh_3<GeomTraits> Mesh;
  std::vector<std::size_t> faces;
  for(std::size_t t = 0; t < mesh.number_of_tetrahedra(); ++t)
    for(int l = 0; l < 4; ++l)
      if(mesh.neighbor_apex(t, l) == Mesh::no_vertex)
        faces.push_back(4 * t + std::size_t(l));
  auto corners = [&](std::size_t f) {
    const typename Mesh::Tetrahedron& tet = mesh.tetrahedron(f / 4);
    std::array<std::size_t, 3> c;
    int m = 0;
    for(int k = 0; k < 4; ++k)
      if(k != int(f % 4))
        c[m++] = tet[k];
    return c;
  };
  std::vector<std::size_t> parent(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i)
    parent[i] = i;
  auto find = [&](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  // Each boundary edge is shared by exactly two boundary faces of a conforming mesh
  // (by more at a non-manifold boundary edge: all pairs are tried).
  std::unordered_map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>,
                     boost::hash<std::pair<std::size_t, std::size_t>>>
      edge_faces;
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const std::array<std::size_t, 3> c = corners(faces[i]);
    for(int k = 0; k < 3; ++k)
      edge_faces[std::minmax(c[k], c[(k + 1) % 3])].push_back(i);
  }
  const typename GeomTraits::Coplanar_3 coplanar = GeomTraits().coplanar_3_object();
  for(const auto& e : edge_faces)
    for(std::size_t a = 0; a < e.second.size(); ++a)
      for(std::size_t b = a + 1; b < e.second.size(); ++b)
      {
        const std::array<std::size_t, 3> p = corners(faces[e.second[a]]), q = corners(faces[e.second[b]]);
        std::size_t apex = q[0];
        for(std::size_t v : q)
          if(v != e.first.first && v != e.first.second)
            apex = v;
        if(coplanar(mesh.point(p[0]), mesh.point(p[1]), mesh.point(p[2]), mesh.point(apex)))
        {
          const std::size_t x = find(e.second[a]), y = find(e.second[b]);
          parent[(std::max)(x, y)] = (std::min)(x, y);
        }
      }
  std::unordered_map<std::size_t, int> planes;
  std::vector<int> number(faces.size(), -1);
  int next = 0;
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const std::size_t r = find(i);
    if(number[r] < 0)
      number[r] = next++;
    planes.emplace(faces[i], number[r]);
  }
  return planes;
}

// Evaluates the tetrahedra of cube layers [k_begin, k_end) of the grid into
// `chunk`.  `values` holds the field values of the grid vertices from global
// index `first_vertex` on; it must cover vertex layers k_begin - 1 .. k_end + 1
// (clamped to the grid): the apex of a neighbouring tetrahedron across a face
// can lie one layer beyond the cube layer.
template <typename GeomTraits>
void extract_grid_slab(const Tetrahedral_grid_3<GeomTraits>& grid, const double* values, std::size_t first_vertex,
                       std::size_t N, const Tbiso_tetrahedron_evaluator& prototype, std::size_t k_begin,
                       std::size_t k_end, Tbiso_chunk& chunk)
{
  typedef Tbiso_tetrahedron_evaluator Evaluator;
  typedef Tetrahedral_grid_3<GeomTraits> Grid;
  Evaluator evaluator = prototype;
  const std::uint64_t expression_fields = evaluator.expression_fields();
  const bool close = evaluator.closes_at_domain_boundary();
  const std::array<std::size_t, 3>& n = grid.vertex_counts();
  const std::size_t layer_size = n[0] * n[1];
  auto values_at = [&](std::size_t v) { return values + (v - first_vertex) * N; };
  // Sign masks of two vertex layers, rolled along z.  Kept per thread from
  // one slab to the next: first-touching fresh pages is slow, and page
  // faults of concurrent threads serialize in the kernel.
  thread_local std::vector<std::uint64_t> negative[2], positive[2];
  auto fill_masks = [&](std::size_t k, int slot) {
    negative[slot].resize(layer_size);
    positive[slot].resize(layer_size);
    const double* layer = values_at(k * layer_size);
    for(std::size_t v = 0; v < layer_size; ++v)
      field_sign_masks(layer + v * N, expression_fields, negative[slot][v], positive[slot][v]);
  };
  fill_masks(k_begin, 0);
  std::array<Tbiso_corner, 4> corner;
  std::array<std::uint64_t, 4> tet_negative, tet_positive;
  for(std::size_t k = k_begin; k < k_end; ++k)
  {
    const int lower = int((k - k_begin) & 1), upper = 1 - lower;
    fill_masks(k + 1, upper);
    for(std::size_t j = 0; j + 1 < n[1]; ++j)
      for(std::size_t i = 0; i + 1 < n[0]; ++i)
      {
        // The 8 cube corners' masks; a cube whose corners all agree and have
        // no zero is skipped whole (the common case).
        std::uint64_t cube_negative[8], cube_positive[8];
        bool uniform = true;
        for(int c = 0; c < 8; ++c)
        {
          const std::size_t v = (i + (c & 1)) + n[0] * (j + ((c >> 1) & 1));
          const int slot = (c >> 2) ? upper : lower;
          cube_negative[c] = negative[slot][v];
          cube_positive[c] = positive[slot][v];
          uniform &= cube_negative[c] == cube_negative[0] && cube_positive[c] == cube_positive[0];
        }
        const bool on_boundary = i == 0 || j == 0 || k == 0 || i + 2 == n[0] || j + 2 == n[1] || k + 2 == n[2];
        if(uniform && (cube_negative[0] | cube_positive[0]) == expression_fields &&
           (!close || !on_boundary || !evaluator.evaluate(cube_negative[0], cube_positive[0])))
          continue;
        for(int t = 0; t < 6; ++t)
        {
          const std::array<std::array<int, 3>, 4> offsets = Grid::kuhn_offsets(t);
          unsigned boundary_faces = 0;
          for(int l = 0; l < 4; ++l)
          {
            const std::array<int, 3>& d = offsets[Grid::kuhn_corner(t, l)];
            const int c = d[0] | (d[1] << 1) | (d[2] << 2);
            tet_negative[l] = cube_negative[c];
            tet_positive[l] = cube_positive[c];
          }
          if(close && on_boundary)
            for(int l = 0; l < 4; ++l)
              if(grid.neighbor_apex(i, j, k, t, l) == Grid::no_vertex)
                boundary_faces |= 1u << l;
          if(evaluator.is_trivially_empty(tet_negative, tet_positive, boundary_faces))
            continue;
          ++chunk.evaluated;
          const typename Grid::Tetrahedron tet = grid.tetrahedron(i, j, k, t);
          for(int l = 0; l < 4; ++l)
          {
            corner[l].id = tet[l];
            corner[l].values = values_at(tet[l]);
            corner[l].negative = tet_negative[l];
            corner[l].positive = tet_positive[l];
            corner[l].position = grid.position(tet[l]);
          }
          evaluator.evaluate_tetrahedron(
              corner,
              [&](int l) {
                Evaluator::Apex a{false, 0, 0};
                const std::size_t v = grid.neighbor_apex(i, j, k, t, l);
                if(v != Grid::no_vertex)
                {
                  a.exists = true;
                  field_sign_masks(values_at(v), expression_fields, a.negative, a.positive);
                }
                return a;
              },
              [&](int label, const Evaluator::Vertex* v, std::size_t count, int face) {
                chunk.add(label, v, count, evaluator,
                          label == Evaluator::domain_boundary_label ? grid_boundary_plane(grid, tet, face) : -1);
              });
        }
      }
  }
}

// A key can be shared with another slab only if its carrier lies in a vertex
// layer that bounds a slab (all its corners in that layer); returns that
// layer, or no_layer.
inline std::size_t shared_layer(const Tbiso_vertex_key& key, std::size_t layer_size, std::size_t slab)
{
  const std::size_t no_layer = (std::numeric_limits<std::size_t>::max)();
  const std::size_t z = key.corners[0] / layer_size;
  if(z % slab != 0)
    return no_layer;
  for(int c = 1; c < 4 && key.corners[c] != (std::numeric_limits<std::size_t>::max)(); ++c)
    if(key.corners[c] / layer_size != z)
      return no_layer;
  return z;
}

} // namespace internal

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_TBISO_GRID_SLAB_H
