// The tools' self-intersection test of an input soup: PMP's answer, from the
// arrays when the triangles suit the grid of does_triangle_soup_self_intersect()
// (4x faster than PMP::does_self_intersect() on a Surface_mesh, in a third of
// the memory), else PMP on the mesh of the soup.

#ifndef BISO_TOOLS_SELF_INTERSECTION_H
#define BISO_TOOLS_SELF_INTERSECTION_H

#include "kernels.h"

#include <CGAL/Boolean_isosurfacing_3/IO/Triangle_soup_3.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/internal/does_triangle_soup_self_intersect.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <optional>

namespace biso_tools {

/// Whether the 2-manifold soup intersects itself (see
/// does_triangle_soup_self_intersect()); `mesh`, if given, is the mesh of the
/// soup, else one is built when PMP must answer.
inline bool soup_self_intersects(const CGAL::Boolean_isosurfacing::Triangle_soup_3& soup, bool parallel,
                                 const Mesh* mesh = nullptr)
{
  namespace BI = CGAL::Boolean_isosurfacing;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::optional<bool> answer;
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
    answer = BI::internal::does_triangle_soup_self_intersect<CGAL::Parallel_tag>(soup.points, soup.triangles);
  else
#endif
    answer = BI::internal::does_triangle_soup_self_intersect<CGAL::Sequential_tag>(soup.points, soup.triangles);
  if(answer)
    return *answer;
  Mesh built;
  if(mesh == nullptr)
  {
    BI::IO::triangle_soup_to_mesh(soup, built);
    mesh = &built;
  }
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
    return PMP::does_self_intersect<CGAL::Parallel_tag>(*mesh);
#endif
  return PMP::does_self_intersect<CGAL::Sequential_tag>(*mesh);
}

} // namespace biso_tools

#endif // BISO_TOOLS_SELF_INTERSECTION_H
