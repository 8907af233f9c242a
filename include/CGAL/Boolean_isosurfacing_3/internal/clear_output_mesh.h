// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CLEAR_OUTPUT_MESH_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CLEAR_OUTPUT_MESH_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The package's rule: a mesh output is cleared first.  The caller's property
// maps on it (e.g. those passed as `edge_is_constrained_map`) must survive:
// `Surface_mesh::clear()` removes them, so a Surface_mesh is cleared without.
template <typename PolygonMesh>
void clear_output_mesh(PolygonMesh& mesh)
{
  CGAL::clear(mesh);
}

template <typename Point>
void clear_output_mesh(CGAL::Surface_mesh<Point>& mesh)
{
  mesh.clear_without_removing_property_maps();
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_CLEAR_OUTPUT_MESH_H
