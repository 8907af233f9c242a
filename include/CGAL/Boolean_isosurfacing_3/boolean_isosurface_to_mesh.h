// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_TO_MESH_H
#define CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_TO_MESH_H

#include <CGAL/Boolean_isosurfacing_3/internal/clear_output_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Boolean_isosurface_soup.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

namespace internal {

// Why a soup is not a polygon mesh, for the error message: the check of
// PMP only answers yes or no.  Only called on failure.
template <typename Point_3>
std::string describe_non_manifold_soup(const Boolean_isosurface_soup<Point_3>& soup)
{
  std::vector<std::pair<std::size_t, std::size_t>> directed;
  for(std::size_t p = 0; p < soup.polygons.size(); ++p)
  {
    const std::vector<std::size_t>& poly = soup.polygons[p];
    if(poly.size() < 3)
      return "polygon " + std::to_string(p) + " has fewer than 3 vertices";
    std::vector<std::size_t> sorted(poly);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return "polygon " + std::to_string(p) + " repeats a vertex";
    for(std::size_t k = 0; k < poly.size(); ++k)
      directed.emplace_back(poly[k], poly[(k + 1) % poly.size()]);
  }
  auto at = [&](std::size_t v) {
    std::ostringstream out;
    out.precision(6);
    out << "(" << CGAL::to_double(soup.points[v].x()) << ", " << CGAL::to_double(soup.points[v].y()) << ", "
        << CGAL::to_double(soup.points[v].z()) << ")";
    return out.str();
  };
  // Undirected edge uses: more than two polygons on an edge is a
  // non-manifold edge (XOR-like expressions produce them where four
  // regions meet along a curve).
  std::vector<std::pair<std::size_t, std::size_t>> undirected(directed);
  for(auto& e : undirected)
    if(e.second < e.first)
      std::swap(e.first, e.second);
  std::sort(undirected.begin(), undirected.end());
  std::size_t bad_edges = 0, example = 0;
  for(std::size_t i = 0; i < undirected.size();)
  {
    std::size_t j = i + 1;
    while(j < undirected.size() && undirected[j] == undirected[i])
      ++j;
    if(j - i > 2 && bad_edges++ == 0)
      example = undirected[i].first;
    i = j;
  }
  if(bad_edges > 0)
    return "the surface has " + std::to_string(bad_edges) + " non-manifold edge(s) (more than two polygons on an edge, e.g. at " +
           at(example) + ")";
  std::sort(directed.begin(), directed.end());
  const auto twice = std::adjacent_find(directed.begin(), directed.end());
  if(twice != directed.end())
    return "two polygons around the edge at " + at(twice->first) + " are not consistently oriented";
  return "the surface has a non-manifold vertex (surface sheets touching at a point)";
}

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * converts the output of `extract_boolean_isosurface()` into a polygon mesh,
 * for processing that needs connectivity (smoothing, remeshing...).  The mesh
 * is cleared first; then vertex `i` is point `i` of the soup and face `p`
 * (in insertion order) is polygon `p`, so per-point and per-polygon data of
 * the soup keep their indices.
 *
 * The polygons are taken as they are: the soup is already oriented and
 * welded, so nothing is reoriented or repaired (which could silently change
 * the surface).
 *
 * \tparam PolygonMesh a model of `MutableFaceGraph` with an internal vertex
 *         point property map (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
 *
 * \throws Invalid_input_error if the soup is not a valid polygon mesh
 * (`CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`): a
 * Boolean isosurface has non-manifold edges or vertices where regions of
 * the set touch along a curve or at a point (for example `f0 & !f1 | !f0 & f1`
 * where the two zero sets cross).  Such a surface can only be written as a
 * polygon soup.  `mesh` is left empty then.
 */
template <typename Point_3, typename PolygonMesh>
void boolean_isosurface_to_mesh(const Boolean_isosurface_soup<Point_3>& soup, PolygonMesh& mesh)
{
  if(soup.face_fields.size() != soup.polygons.size())
    throw Invalid_input_error("the soup has " + std::to_string(soup.polygons.size()) + " polygons but " +
                              std::to_string(soup.face_fields.size()) + " face labels");
  for(std::size_t p = 0; p < soup.polygons.size(); ++p)
    for(std::size_t v : soup.polygons[p])
      if(v >= soup.points.size())
        throw Invalid_input_error("polygon " + std::to_string(p) + " refers to point " + std::to_string(v) +
                                  " but the soup has " + std::to_string(soup.points.size()) + " points");
  internal::clear_output_mesh(mesh);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw Invalid_input_error("cannot make a polygon mesh of the Boolean isosurface: " +
                              internal::describe_non_manifold_soup(soup) +
                              "; it can only be written as a polygon soup");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The property maps `boolean_isosurface_to_mesh()` adds to a `Surface_mesh`.
/// They live in the mesh (as named properties) and stay valid as long as it
/// does and the properties are not removed.
template <typename Point_3>
struct Boolean_isosurface_mesh_maps
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  /// `"f:field"`: the soup's `face_fields` label of every face.
  typename Mesh::template Property_map<typename Mesh::Face_index, int> face_field;
  /// `"e:crease"`: the edges of the polylines of `extract_crease_network()`
  /// (faces of different labels, or closing faces of different planes of the
  /// domain boundary); border edges are false.
  typename Mesh::template Property_map<typename Mesh::Edge_index, bool> edge_is_crease;
  /// `"v:corner"`: true for the corners of the crease network.
  typename Mesh::template Property_map<typename Mesh::Vertex_index, bool> vertex_is_corner;
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * As the generic overload, for a `Surface_mesh`, and also adds the labels,
 * creases and corners as property maps (see `Boolean_isosurface_mesh_maps`),
 * ready for `smooth_with_creases()`:
 * \code
 * const auto maps = boolean_isosurface_to_mesh(soup, creases, mesh);
 * smooth_with_creases(mesh, CGAL::parameters::edge_is_constrained_map(maps.edge_is_crease)
 *                               .vertex_is_constrained_map(maps.vertex_is_corner));
 * \endcode
 * `creases` must be `extract_crease_network(soup)` (its corners are marked).
 * Cost: O(V + E + F) after the conversion.
 */
template <typename Point_3>
Boolean_isosurface_mesh_maps<Point_3>
boolean_isosurface_to_mesh(const Boolean_isosurface_soup<Point_3>& soup, const Crease_network& creases,
                           CGAL::Surface_mesh<Point_3>& mesh)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::Edge_index Edge_index;

  for(std::size_t c : creases.corners)
    if(c >= soup.points.size())
      throw Invalid_input_error("corner " + std::to_string(c) + " is not a point of the soup");
  boolean_isosurface_to_mesh<Point_3, Mesh>(soup, mesh);

  Boolean_isosurface_mesh_maps<Point_3> maps;
  maps.face_field = mesh.template add_property_map<Face_index, int>("f:field", Boolean_isosurface_soup<Point_3>::domain_boundary).first;
  maps.edge_is_crease = mesh.template add_property_map<Edge_index, bool>("e:crease", false).first;
  maps.vertex_is_corner = mesh.template add_property_map<Vertex_index, bool>("v:corner", false).first;
  // The mesh was built from scratch: face p is polygon p, vertex i is point i.
  for(std::size_t p = 0; p < soup.polygons.size(); ++p)
    maps.face_field[Face_index(typename Mesh::size_type(p))] = soup.face_fields[p];
  // The edges of the crease polylines: faces of different labels, and
  // closing faces of different planes of the domain boundary.
  for(const std::vector<std::size_t>& line : creases.polylines)
    for(std::size_t k = 0; k + 1 < line.size(); ++k)
    {
      const auto h = mesh.halfedge(Vertex_index(typename Mesh::size_type(line[k])),
                                   Vertex_index(typename Mesh::size_type(line[k + 1])));
      if(h == Mesh::null_halfedge())
        throw Invalid_input_error("crease edge (" + std::to_string(line[k]) + ", " + std::to_string(line[k + 1]) +
                                  ") is not an edge of the soup");
      if(!mesh.is_border(mesh.edge(h)))
        maps.edge_is_crease[mesh.edge(h)] = true;
    }
  for(std::size_t c : creases.corners)
    maps.vertex_is_corner[Vertex_index(typename Mesh::size_type(c))] = true;
  return maps;
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// As above, computing `extract_crease_network(soup)` itself.
template <typename Point_3>
Boolean_isosurface_mesh_maps<Point_3> boolean_isosurface_to_mesh(const Boolean_isosurface_soup<Point_3>& soup,
                                                                  CGAL::Surface_mesh<Point_3>& mesh)
{
  return boolean_isosurface_to_mesh(soup, extract_crease_network(soup), mesh);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * TBISO into a `Surface_mesh`: `extract_boolean_isosurface()` on `domain`
 * (a `Tetrahedral_grid_3` or a `Tetrahedral_mesh_3`), then
 * `boolean_isosurface_to_mesh()`.  `mesh` is cleared first (the package's
 * rule for every output).  The side outputs go to CGAL's named parameters:
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{face_patch_map}
 *     \cgalParamDescription{receives the field label of every face (`Boolean_isosurface_soup::face_fields`;
 *       -1 for a closing face on the domain boundary)}
 *     \cgalParamType{a `WritablePropertyMap` from `face_descriptor` to `int`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{receives `true` for the edges of the crease network
 *       (`extract_crease_network()`), `false` for the others}
 *     \cgalParamType{a `WritablePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{receives `true` for the corners of the crease network, `false` for the others}
 *     \cgalParamType{a `WritablePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{as for `extract_boolean_isosurface()`; its other named parameters apply too}
 *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws Invalid_input_error as `extract_boolean_isosurface()`, and when the
 * surface is not a 2-manifold (see `boolean_isosurface_to_mesh()`).
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TetrahedralDomain_3, typename Point_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boolean_isosurface_statistics extract_boolean_isosurface(const TetrahedralDomain_3& domain, const Scalar_fields& fields,
                                                         const Boolean_expression& expression,
                                                         CGAL::Surface_mesh<Point_3>& mesh,
                                                         const NamedParameters& np = parameters::default_values())
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  Boolean_isosurface_soup<Point_3> soup;
  Boolean_isosurface_statistics statistics = extract_boolean_isosurface<ConcurrencyTag>(domain, fields, expression, soup, np);
  const auto start = std::chrono::steady_clock::now();
  const Crease_network creases = extract_crease_network(soup);
  boolean_isosurface_to_mesh<Point_3, Mesh>(soup, mesh);
  // The mesh was built from scratch: face p is polygon p, vertex i is point i.
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value)
  {
    auto fpm = parameters::get_parameter(np, CGAL::internal_np::face_patch);
    for(std::size_t p = 0; p < soup.polygons.size(); ++p)
      put(fpm, typename Mesh::Face_index(typename Mesh::size_type(p)), soup.face_fields[p]);
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
  {
    auto ecm = parameters::get_parameter(np, CGAL::internal_np::edge_is_constrained);
    for(const auto e : mesh.edges())
      put(ecm, e, false);
    for(const std::vector<std::size_t>& line : creases.polylines)
      for(std::size_t k = 0; k + 1 < line.size(); ++k)
      {
        const auto h = mesh.halfedge(typename Mesh::Vertex_index(typename Mesh::size_type(line[k])),
                                     typename Mesh::Vertex_index(typename Mesh::size_type(line[k + 1])));
        if(h != Mesh::null_halfedge() && !mesh.is_border(mesh.edge(h)))
          put(ecm, mesh.edge(h), true);
      }
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_is_constrained_t>::value)
  {
    auto vcm = parameters::get_parameter(np, CGAL::internal_np::vertex_is_constrained);
    for(const auto v : mesh.vertices())
      put(vcm, v, false);
    for(std::size_t c : creases.corners)
      put(vcm, typename Mesh::Vertex_index(typename Mesh::size_type(c)), true);
  }
  statistics.seconds += internal::seconds_since(start);
  return statistics;
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_BOOLEAN_ISOSURFACE_TO_MESH_H
