// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_MESH_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_MESH_3_H

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/number_utils.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// An unstructured tetrahedral mesh: points and tetrahedra (four point
/// indices each).  The constructor validates the mesh and prepares what the
/// extraction needs:
///  - every tetrahedron is made positively oriented (an exact orientation
///    test; negatively oriented ones get two corners swapped);
///  - the neighbour across each face is found; a face shared by more than two
///    tetrahedra is a non-conforming mesh and is rejected.
///
/// \tparam GeomTraits a model of `Kernel`
///
/// \cgalModels{TetrahedralDomain_3}
template <typename GeomTraits>
class Tetrahedral_mesh_3
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef std::array<std::size_t, 4> Tetrahedron;

  /// No neighbour: the face is on the boundary of the mesh.
  static constexpr std::size_t no_vertex = (std::numeric_limits<std::size_t>::max)();

  Tetrahedral_mesh_3() = default;

  /// \throws Empty_input_error without tetrahedra;
  /// \throws Non_finite_value_error on a NaN or infinite coordinate;
  /// \throws Invalid_input_error on an out-of-range index, a tetrahedron with
  ///         a repeated or coplanar corners (zero volume), or a face shared by
  ///         more than two tetrahedra (non-conforming mesh).
  Tetrahedral_mesh_3(std::vector<Point_3> points, std::vector<Tetrahedron> tetrahedra)
    : m_points(std::move(points)), m_tetrahedra(std::move(tetrahedra))
  {
    validate();
  }

  const std::vector<Point_3>& points() const { return m_points; }
  const std::vector<Tetrahedron>& tetrahedra() const { return m_tetrahedra; }

  std::size_t number_of_vertices() const { return m_points.size(); }
  std::size_t number_of_tetrahedra() const { return m_tetrahedra.size(); }

  const Point_3& point(std::size_t v) const { return m_points[v]; }
  std::array<double, 3> position(std::size_t v) const
  {
    return {CGAL::to_double(m_points[v].x()), CGAL::to_double(m_points[v].y()), CGAL::to_double(m_points[v].z())};
  }

  /// Tetrahedron `t`, positively oriented.
  const Tetrahedron& tetrahedron(std::size_t t) const { return m_tetrahedra[t]; }

  /// The corner, opposite that face, of the tetrahedron sharing with `t` its
  /// face opposite local corner `l`; `no_vertex` on the boundary.
  std::size_t neighbor_apex(std::size_t t, int l) const { return m_neighbor_apex[t][l]; }

  /// Number of tetrahedron faces on the boundary of the mesh.
  std::size_t number_of_boundary_faces() const { return m_number_of_boundary_faces; }

  /// How many tetrahedra had to be reoriented.
  std::size_t number_of_reoriented_tetrahedra() const { return m_number_of_reoriented; }

private:
  void validate()
  {
    if(m_tetrahedra.empty())
      throw Empty_input_error("the tetrahedral mesh has no tetrahedron");
    for(std::size_t v = 0; v < m_points.size(); ++v)
    {
      const Point_3& p = m_points[v];
      if(!(std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
           std::isfinite(CGAL::to_double(p.z()))))
        throw Non_finite_value_error("vertex " + std::to_string(v) + " of the tetrahedral mesh has a non-finite coordinate");
    }
    typename GeomTraits::Orientation_3 orientation = GeomTraits().orientation_3_object();
    for(std::size_t t = 0; t < m_tetrahedra.size(); ++t)
    {
      Tetrahedron& tet = m_tetrahedra[t];
      for(int l = 0; l < 4; ++l)
        if(tet[l] >= m_points.size())
          throw Invalid_input_error("tetrahedron " + std::to_string(t) + " refers to vertex " +
                                    std::to_string(tet[l]) + " but the mesh has " +
                                    std::to_string(m_points.size()) + " vertices");
      const CGAL::Orientation o =
          orientation(m_points[tet[0]], m_points[tet[1]], m_points[tet[2]], m_points[tet[3]]);
      if(o == CGAL::COPLANAR)
        throw Invalid_input_error("tetrahedron " + std::to_string(t) +
                                  " is degenerate (repeated or coplanar corners, zero volume)");
      if(o == CGAL::NEGATIVE)
      {
        std::swap(tet[2], tet[3]);
        ++m_number_of_reoriented;
      }
    }

    // Faces as (sorted corners, tetrahedron, local corner opposite), sorted:
    // equal faces become adjacent.
    struct Face
    {
      std::array<std::size_t, 3> key;
      std::size_t tet;
      int opposite;
    };
    std::vector<Face> faces;
    faces.reserve(4 * m_tetrahedra.size());
    for(std::size_t t = 0; t < m_tetrahedra.size(); ++t)
      for(int l = 0; l < 4; ++l)
      {
        Face f;
        int n = 0;
        for(int m = 0; m < 4; ++m)
          if(m != l)
            f.key[n++] = m_tetrahedra[t][m];
        std::sort(f.key.begin(), f.key.end());
        f.tet = t;
        f.opposite = l;
        faces.push_back(f);
      }
    std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });

    m_neighbor_apex.assign(m_tetrahedra.size(), {no_vertex, no_vertex, no_vertex, no_vertex});
    m_number_of_boundary_faces = 0;
    for(std::size_t a = 0; a < faces.size();)
    {
      std::size_t b = a + 1;
      while(b < faces.size() && faces[b].key == faces[a].key)
        ++b;
      if(b - a > 2)
        throw Invalid_input_error("the tetrahedral mesh is not conforming: the face (" +
                                  std::to_string(faces[a].key[0]) + ", " + std::to_string(faces[a].key[1]) +
                                  ", " + std::to_string(faces[a].key[2]) + ") is shared by " +
                                  std::to_string(b - a) + " tetrahedra");
      if(b - a == 2)
      {
        const Face& f = faces[a];
        const Face& g = faces[a + 1];
        if(f.tet == g.tet)
          throw Invalid_input_error("tetrahedron " + std::to_string(f.tet) + " has a repeated face");
        m_neighbor_apex[f.tet][f.opposite] = m_tetrahedra[g.tet][g.opposite];
        m_neighbor_apex[g.tet][g.opposite] = m_tetrahedra[f.tet][f.opposite];
        // Two tetrahedra on the same side of their common face overlap.
        if(m_tetrahedra[g.tet][g.opposite] == m_tetrahedra[f.tet][f.opposite])
          throw Invalid_input_error("tetrahedra " + std::to_string(f.tet) + " and " + std::to_string(g.tet) +
                                    " are identical");
      }
      else
        ++m_number_of_boundary_faces;
      a = b;
    }
  }

  std::vector<Point_3> m_points;
  std::vector<Tetrahedron> m_tetrahedra;
  std::vector<std::array<std::size_t, 4>> m_neighbor_apex;
  std::size_t m_number_of_boundary_faces = 0;
  std::size_t m_number_of_reoriented = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_TETRAHEDRAL_MESH_3_H
