// tbiso's summary: the domain, the fields and the expression, and the
// surface (its size, creases, closedness and volume), printed for people
// and set in the JSON summary.

#ifndef BISO_TOOLS_TBISO_SUMMARY_H
#define BISO_TOOLS_TBISO_SUMMARY_H

#include "tbiso_extract.h"
#include "tbiso_output.h"

#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace tbiso_tool {

// What the library says of the surface: closed when every directed edge is
// matched by a reverse one, so that it bounds a solid (the check of the soup
// overload of surveyor_volume(), on the polygons' fan triangles), with its
// volume (signed: winding-number weighted); a 2-manifold when CGAL's
// is_polygon_soup_a_polygon_mesh() says so (what --smooth needs), with the
// reason when it is not.
struct Surface_check
{
  std::optional<double> volume; // empty: not closed
  std::string open_reason;
  bool manifold = true;
  std::string non_manifold_reason;
};

inline Surface_check check_surface(const Soup& soup)
{
  Surface_check result;
  try
  {
    result.volume = BI::surveyor_volume(soup.points, fan_triangles(soup), BI::parameters::signed_volume(true));
  }
  catch(const BI::Open_mesh_error& e)
  {
    result.open_reason = e.what();
  }
  result.manifold = CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons);
  if(!result.manifold)
    result.non_manifold_reason = BI::internal::describe_non_manifold_soup(soup);
  return result;
}

inline void print_domain(Tool& tool, const Input& in, const Options& o, double seconds)
{
  biso_tools::Json_object domain;
  if(in.grid)
  {
    const auto& n = in.grid->vertex_counts();
    const std::array<double, 6> b = o.domain_box();
    std::fprintf(tool.human(),
                 "domain:     grid %zu x %zu x %zu vertices (%zu), %zu tetrahedra, box [%g, %g] x [%g, %g] x [%g, %g]\n",
                 n[0], n[1], n[2], in.grid->number_of_vertices(), in.grid->number_of_tetrahedra(), b[0], b[3], b[1],
                 b[4], b[2], b[5]);
    domain.set("kind", "grid");
    domain.set_raw("cells", biso_tools::json_number_array({double(n[0] - 1), double(n[1] - 1), double(n[2] - 1)}));
    domain.set_raw("box", biso_tools::json_number_array({b[0], b[1], b[2], b[3], b[4], b[5]}));
    domain.set("vertices", in.grid->number_of_vertices());
    domain.set("tetrahedra", in.grid->number_of_tetrahedra());
  }
  else
  {
    std::fprintf(tool.human(),
                 "domain:     tetrahedral mesh %s: %zu vertices, %zu tetrahedra (%zu boundary faces), read in %.3f s\n",
                 o.mesh_file.c_str(), in.mesh->number_of_vertices(), in.mesh->number_of_tetrahedra(),
                 in.mesh->number_of_boundary_faces(), seconds);
    tool.input(o.mesh_file);
    tool.stage("domain", "read " + std::to_string(in.mesh->number_of_tetrahedra()) + " tetrahedra", seconds);
    domain.set("kind", "mesh");
    domain.set("vertices", in.mesh->number_of_vertices());
    domain.set("tetrahedra", in.mesh->number_of_tetrahedra());
  }
  tool.summary().set("domain", domain);
}

inline void print_fields(Tool& tool, const Options& o, std::size_t number_of_fields, const std::string& how)
{
  std::FILE* out = tool.human();
  if(o.fields_file.empty())
  {
    std::fprintf(out, "fields:     %zu%s\n", number_of_fields, how.c_str());
    for(std::size_t i = 0; i < o.field_specs.size(); ++i)
      std::fprintf(out, "  f%zu = %s\n", i, o.field_specs[i].c_str());
  }
  else
  {
    std::fprintf(out, "fields:     %zu, read%s from %s\n", number_of_fields, how.c_str(), o.fields_file.c_str());
    tool.input(o.fields_file);
  }
  tool.summary().set("fields", number_of_fields);
  tool.summary().set_raw("field_specs", biso_tools::json_string_array(o.field_specs));
}

inline void print_expression(Tool& tool, const Options& o, const BI::Boolean_expression& e)
{
  std::fprintf(tool.human(), "expression: %s (%zu term%s)%s\n", e.to_string().c_str(), e.number_of_terms(),
               e.number_of_terms() == 1 ? "" : "s", o.close ? ", closed at the domain boundary" : "");
  std::fflush(tool.human());
  tool.summary().set("expression", e.to_string());
  tool.summary().set("close", o.close);
}

// The output, creases and surface lines.
inline void print_surface(Tool& tool, const Options& o, const Soup& soup, const BI::Crease_network& creases)
{
  std::FILE* out = tool.human();
  std::size_t triangles = 0;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    triangles += poly.size() - 2;
  std::fprintf(out, "output:     %zu vertices, %zu polygons (%zu triangles when fanned)\n", soup.points.size(),
               soup.polygons.size(), triangles);
  std::fprintf(out, "creases:    %zu edges, %zu polylines, %zu corners\n", creases.number_of_crease_edges,
               creases.polylines.size(), creases.corners.size());
  biso_tools::Json_object& j = tool.summary();
  j.set("vertices", soup.points.size());
  j.set("faces", soup.polygons.size());
  j.set("triangles", triangles);
  biso_tools::Json_object c;
  c.set("edges", creases.number_of_crease_edges);
  c.set("polylines", creases.polylines.size());
  c.set("corners", creases.corners.size());
  j.set("creases", c);
  if(soup.polygons.empty())
  {
    std::fprintf(out, "surface:    empty\n");
    j.set("closed", false);
    j.set("volume", 0.0);
    j.set_null("open_reason");
    j.set("manifold", false);
    j.set_null("non_manifold_reason");
    return;
  }
  const Surface_check check = check_surface(soup);
  const std::string non_manifold =
      check.manifold ? "" : ", with non-manifold edges or vertices (" + check.non_manifold_reason + ")";
  j.set("closed", check.volume.has_value());
  j.set("manifold", check.manifold);
  if(check.manifold)
    j.set_null("non_manifold_reason");
  else
    j.set("non_manifold_reason", check.non_manifold_reason);
  if(check.volume)
  {
    std::fprintf(out, "surface:    closed, volume %.15g%s%s\n", *check.volume,
                 o.smooth_iterations ? " (after smoothing)" : "", biso_tools::printable(non_manifold).c_str());
    j.set("volume", *check.volume);
    j.set_null("open_reason");
  }
  else
  {
    std::fprintf(out, "surface:    not closed (%s)%s%s\n", biso_tools::printable(check.open_reason).c_str(),
                 biso_tools::printable(non_manifold).c_str(),
                 o.close ? "" : "; --close closes it on the domain boundary");
    j.set_null("volume");
    j.set("open_reason", check.open_reason);
  }
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_SUMMARY_H
