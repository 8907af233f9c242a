// tbiso's summary: the domain, the fields and the expression, and the
// surface (its size, creases, closedness and volume), printed for people
// and set in the JSON summary.

#ifndef BISO_TOOLS_TBISO_SUMMARY_H
#define BISO_TOOLS_TBISO_SUMMARY_H

#include "tbiso_extract.h"

#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace tbiso_tool {

// Closed: every directed edge is matched by exactly one reverse edge (so
// each undirected edge is in exactly two consistently oriented polygons).
struct Edge_report
{
  std::size_t border = 0, non_manifold = 0, inconsistent = 0;
  bool closed() const { return border == 0 && non_manifold == 0 && inconsistent == 0; }
};

inline Edge_report check_edges(const Soup& soup)
{
  struct Use
  {
    std::size_t a, b;
    bool forward;
    bool operator<(const Use& u) const { return a != u.a ? a < u.a : (b != u.b ? b < u.b : forward < u.forward); }
  };
  std::vector<Use> uses;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
      uses.push_back(a < b ? Use{a, b, true} : Use{b, a, false});
    }
  std::sort(uses.begin(), uses.end());
  Edge_report report;
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while(j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b)
      ++j;
    if(j - i == 1)
      ++report.border;
    else if(j - i > 2)
      ++report.non_manifold;
    else if(uses[i].forward == uses[i + 1].forward)
      ++report.inconsistent;
    i = j;
  }
  return report;
}

// Divergence theorem over the fan triangles of the polygons, relative to the
// centre of the bounding box (fewer lost digits than the origin far away).
inline double enclosed_volume(const Soup& soup)
{
  if(soup.points.empty())
    return 0;
  CGAL::Bbox_3 box;
  for(const Point& p : soup.points)
    box += p.bbox();
  const K::Vector_3 centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  double volume = 0;
  for(const std::vector<std::size_t>& poly : soup.polygons)
  {
    const K::Vector_3 a = soup.points[poly[0]] - CGAL::ORIGIN - centre;
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      volume += CGAL::determinant(a, soup.points[poly[k]] - CGAL::ORIGIN - centre,
                                  soup.points[poly[k + 1]] - CGAL::ORIGIN - centre);
  }
  return volume / 6;
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
  const Edge_report edges = check_edges(soup);
  j.set("closed", !soup.polygons.empty() && edges.closed());
  j.set("border_edges", edges.border);
  j.set("non_manifold_edges", edges.non_manifold);
  if(soup.polygons.empty())
  {
    std::fprintf(out, "surface:    empty\n");
    j.set("volume", 0.0);
  }
  else if(edges.closed())
  {
    const double volume = enclosed_volume(soup);
    std::fprintf(out, "surface:    closed, volume %.15g%s\n", volume, o.smooth_iterations ? " (after smoothing)" : "");
    j.set("volume", volume);
  }
  else
  {
    std::fprintf(out, "surface:    not closed (%zu border edges, %zu non-manifold edges, %zu inconsistent edges)%s\n",
                 edges.border, edges.non_manifold, edges.inconsistent,
                 o.close ? "" : "; --close closes it on the domain boundary");
    j.set_null("volume");
  }
}

} // namespace tbiso_tool

#endif // BISO_TOOLS_TBISO_SUMMARY_H
