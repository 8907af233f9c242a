// tbiso's output files: the surface by its extension (.ply with the field
// labels and colours, .off and .obj polygons, .stl fan triangles), the
// crease polylines and the corners.

#ifndef BISO_TOOLS_TBISO_OUTPUT_H
#define BISO_TOOLS_TBISO_OUTPUT_H

#include "tbiso_extract.h"

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/IO/polygon_soup_io.h>

#include <array>
#include <string>
#include <vector>

namespace tbiso_tool {

// The polygons as fans of triangles (they are convex: pieces of a plane
// clipped by a tetrahedron and other planes).
inline std::vector<std::array<std::size_t, 3>> fan_triangles(const Soup& soup)
{
  std::vector<std::array<std::size_t, 3>> triangles;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      triangles.push_back({{poly[0], poly[k], poly[k + 1]}});
  return triangles;
}

inline void write_surface(const std::string& path, const Soup& soup)
{
  const std::string e = biso_tools::extension(path);
  if(e == "ply")
    BI::IO::write_PLY_with_fields(path, soup);
  else if(e == "off")
    BI::IO::write_OFF_polygons(path, soup);
  else
  {
    const bool ok = e == "stl" ? CGAL::IO::write_polygon_soup(path, soup.points, fan_triangles(soup),
                                                              CGAL::parameters::stream_precision(17))
                               : CGAL::IO::write_polygon_soup(path, soup.points, soup.polygons,
                                                              CGAL::parameters::stream_precision(17));
    if(!ok)
      throw Error(path + ": cannot write");
  }
}

inline void write_outputs(Tool& tool, const Options& o, const Soup& soup, const BI::Crease_network& creases)
{
  const biso_tools::Stopwatch watch;
  if(!o.output.empty())
  {
    write_surface(o.output, soup);
    tool.output(o.output);
  }
  if(!o.creases_file.empty())
  {
    BI::IO::write_polylines(o.creases_file, soup.points, creases);
    tool.output(o.creases_file);
  }
  if(!o.corners_file.empty())
  {
    BI::IO::write_corners(o.corners_file, soup.points, creases);
    tool.output(o.corners_file);
  }
  if(!o.output.empty() || !o.creases_file.empty() || !o.corners_file.empty())
  {
    tool.stage("writing", "wrote the outputs", watch.seconds());
    std::fprintf(tool.human(), "time writing:    %.3f s\n", watch.seconds());
  }
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_OUTPUT_H
