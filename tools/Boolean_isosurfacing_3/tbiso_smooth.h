// tbiso --smooth: hierarchical lambda|mu smoothing of the soup's points,
// keeping its creases and corners.

#ifndef BISO_TOOLS_TBISO_SMOOTH_H
#define BISO_TOOLS_TBISO_SMOOTH_H

#include "tbiso_extract.h"

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Surface_mesh.h>

#include <string>

namespace tbiso_tool {

// Through a Surface_mesh: vertex i of the mesh is point i of the soup, so the
// polygons and their labels are kept as they are.
inline void smooth(Soup& soup, const BI::Crease_network& creases, const Options& o)
{
  typedef CGAL::Surface_mesh<Point> Surface_mesh;
  Surface_mesh mesh;
  BI::Boolean_isosurface_mesh_maps<Point> maps;
  try
  {
    maps = BI::boolean_isosurface_to_mesh(soup, creases, mesh);
  }
  catch(const BI::Invalid_input_error& e)
  {
    throw Error(std::string("--smooth: ") + e.what());
  }
  BI::smooth_with_creases(mesh, o.lambda ? *o.lambda : BI::taubin_default_lambda,
                          o.mu ? *o.mu : BI::taubin_default_mu,
                          CGAL::parameters::number_of_iterations(*o.smooth_iterations)
                              .edge_is_constrained_map(maps.edge_is_crease)
                              .vertex_is_constrained_map(maps.vertex_is_corner));
  for(const Surface_mesh::Vertex_index v : mesh.vertices())
    soup.points[std::size_t(v)] = mesh.point(v);
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_SMOOTH_H
