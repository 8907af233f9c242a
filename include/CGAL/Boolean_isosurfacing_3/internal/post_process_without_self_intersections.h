// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_POST_PROCESS_WITHOUT_SELF_INTERSECTIONS_H
#define CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_POST_PROCESS_WITHOUT_SELF_INTERSECTIONS_H

#include <CGAL/Boolean_isosurfacing_3/Post_processing_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/internal/clear_output_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <chrono>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {
namespace internal {

// The (point boxes of the) vertices of `input` farther than `max_deviation`
// from `result`, none if `max_deviation` is 0: where a result lost a part of
// the input, as a remeshing does with a wall thinner than its edges.
template <typename TriangleMesh>
std::vector<CGAL::Bbox_3> far_input_points(const TriangleMesh& input, const TriangleMesh& result, double max_deviation)
{
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type
      Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef typename Kernel::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Iterator>>> Tree;
  std::vector<CGAL::Bbox_3> far;
  if(!(max_deviation > 0))
    return far;
  const auto vpm = get(CGAL::vertex_point, result);
  std::vector<Triangle> triangles;
  for(const auto f : faces(result))
  {
    const auto h = halfedge(f, result);
    triangles.emplace_back(get(vpm, source(h, result)), get(vpm, target(h, result)),
                           get(vpm, target(next(h, result), result)));
  }
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  const double squared = max_deviation * max_deviation;
  const auto input_vpm = get(CGAL::vertex_point, input);
  for(const auto v : vertices(input))
  {
    const Point& p = get(input_vpm, v);
    if(CGAL::to_double(tree.squared_distance(p)) > squared)
      far.push_back(p.bbox());
  }
  return far;
}

/*
 * Runs `process(work, crease, corner, is_frozen)` on a copy `work` of
 * `mesh`, with `crease` and `corner` the copies of `ecm` and `vcm` on it and
 * `is_frozen` a face property map of `work`, true for the faces the process
 * must leave as they are, and
 * checks the result: no self-intersection (`PMP::self_intersections()`,
 * exact predicates) and, if `max_deviation` > 0, no input vertex farther
 * than `max_deviation` from it.
 *
 * Why: remeshing and simplification move vertices by up to an edge length,
 * while a CSG result has walls and gaps thinner than a cell (where two
 * copies graze, a tray's wall): a vertex projected or collapsed there can
 * land through the other sheet, or flatten the wall.  Such places are few
 * and small (3-70 intersecting pairs on 10^5 triangles), so instead of
 * testing every move the whole result is tested once; where it fails, the
 * run is repeated from the input with the input's faces within `margin`
 * (times the run's number) of the intersecting faces and of the far input
 * vertices frozen.  After `max_runs` failed runs, `mesh` is left as it was
 * if the last result still self-intersects, and replaced by it with a
 * warning if it only left input vertices far.  `mesh` is replaced by the
 * result otherwise, with `ecm` and `vcm` written for its edges and vertices.
 *
 * An input that already self-intersects cannot pass the first check: then
 * only the second one is made, with a warning.
 */
template <typename TriangleMesh, typename EdgeIsConstrainedMap, typename VertexIsConstrainedMap, typename Process>
Post_processing_statistics post_process_without_self_intersections(TriangleMesh& mesh, EdgeIsConstrainedMap ecm,
                                                                   VertexIsConstrainedMap vcm, double margin,
                                                                   double max_deviation, const std::string& name,
                                                                   const Process& process, std::size_t max_runs = 4)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor, CGAL::Box_intersection_d::ID_EXPLICIT>
      Box;

  const auto start = std::chrono::steady_clock::now();
  Post_processing_statistics statistics;
  auto input_frozen = get(CGAL::dynamic_face_property_t<bool>(), mesh);
  for(const face_descriptor f : faces(mesh))
    put(input_frozen, f, false);
  std::vector<Box> input_boxes;
  bool input_checked = false, input_self_intersects = false;

  const auto intersecting_faces = [&](const TriangleMesh& m) {
    const auto check_start = std::chrono::steady_clock::now();
    std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
    PMP::self_intersections<CGAL::Parallel_if_available_tag>(faces(m), m, std::back_inserter(pairs));
    statistics.seconds_checks += seconds_since(check_start);
    return pairs;
  };

  for(std::size_t run = 1; run <= max_runs; ++run)
  {
    statistics.runs = run;
    TriangleMesh work;
    std::vector<std::pair<vertex_descriptor, vertex_descriptor>> vertex_pairs;
    std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> halfedge_pairs;
    std::vector<std::pair<face_descriptor, face_descriptor>> face_pairs;
    CGAL::copy_face_graph(mesh, work,
                          CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vertex_pairs))
                              .halfedge_to_halfedge_output_iterator(std::back_inserter(halfedge_pairs))
                              .face_to_face_output_iterator(std::back_inserter(face_pairs)));
    auto crease = get(CGAL::dynamic_edge_property_t<bool>(), work);
    auto corner = get(CGAL::dynamic_vertex_property_t<bool>(), work);
    for(const auto& p : vertex_pairs)
      put(corner, p.second, bool(get(vcm, p.first)));
    for(const auto& p : halfedge_pairs)
      put(crease, edge(p.second, work), bool(get(ecm, edge(p.first, mesh))));
    auto is_frozen = get(CGAL::dynamic_face_property_t<bool>(), work);
    statistics.frozen_faces = 0;
    for(const auto& p : face_pairs)
    {
      put(is_frozen, p.second, bool(get(input_frozen, p.first)));
      statistics.frozen_faces += get(input_frozen, p.first);
    }

    statistics.edges_collapsed = process(work, crease, corner, is_frozen);

    std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
    if(!input_self_intersects)
    {
      pairs = intersecting_faces(work);
      if(!pairs.empty() && !input_checked)
      {
        input_checked = true;
        if(!intersecting_faces(mesh).empty())
        {
          statistics.warnings.push_back(name + ": the input mesh self-intersects, the result is not checked for "
                                               "self-intersections");
          input_self_intersects = true;
          pairs.clear();
        }
      }
    }
    statistics.intersecting_pairs_found += pairs.size();
    const auto far_start = std::chrono::steady_clock::now();
    const auto far = far_input_points(mesh, work, max_deviation);
    statistics.seconds_checks += seconds_since(far_start);
    statistics.far_input_vertices_found += far.size();
    // The last run's result is kept without self-intersection even if it
    // left input vertices far: the caller is told where, not refused.
    if(pairs.empty() && (far.empty() || run == max_runs))
    {
      if(!far.empty())
        statistics.warnings.push_back(name + ": " + std::to_string(far.size()) +
                                      " input vertices are farther than " + std::to_string(max_deviation) +
                                      " from the result (a wall thinner than that flattened, or a sharp tip "
                                      "rounded off) after " + std::to_string(run) + " runs");
      vertex_pairs.clear();
      halfedge_pairs.clear();
      clear_output_mesh(mesh);
      CGAL::copy_face_graph(work, mesh,
                            CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vertex_pairs))
                                .halfedge_to_halfedge_output_iterator(std::back_inserter(halfedge_pairs)));
      for(const auto& p : vertex_pairs)
        put(vcm, p.second, bool(get(corner, p.first)));
      for(const auto& p : halfedge_pairs)
        put(ecm, edge(p.second, mesh), bool(get(crease, edge(p.first, work))));
      statistics.number_of_vertices = num_vertices(mesh);
      statistics.number_of_faces = num_faces(mesh);
      statistics.seconds = seconds_since(start);
      return statistics;
    }

    // Freeze the input's faces near the intersecting faces and the far input
    // vertices, farther each run.
    if(input_boxes.empty())
      for(const face_descriptor f : faces(mesh))
        input_boxes.emplace_back(PMP::face_bbox(f, mesh), f);
    std::vector<Box> near;
    const double d = margin * double(run);
    const auto grown = [&](const CGAL::Bbox_3& b) {
      near.emplace_back(
          CGAL::Bbox_3(b.xmin() - d, b.ymin() - d, b.zmin() - d, b.xmax() + d, b.ymax() + d, b.zmax() + d),
          face_descriptor());
    };
    for(const auto& p : pairs)
      for(const face_descriptor f : {p.first, p.second})
        grown(PMP::face_bbox(f, work));
    for(const CGAL::Bbox_3& b : far)
      grown(b);
    CGAL::box_intersection_d(input_boxes.begin(), input_boxes.end(), near.begin(), near.end(),
                             [&](const Box& a, const Box&) { put(input_frozen, a.info(), true); });
  }
  statistics.reverted = true;
  statistics.frozen_faces = 0;
  statistics.edges_collapsed = 0;
  statistics.warnings.push_back(name + ": every run (" + std::to_string(max_runs) + ") self-intersected" +
                                (max_deviation > 0 ? " or left an input vertex farther than " +
                                                         std::to_string(max_deviation) + " from the result"
                                                   : std::string()) +
                                "; the mesh is left as it was");
  statistics.number_of_vertices = num_vertices(mesh);
  statistics.number_of_faces = num_faces(mesh);
  statistics.seconds = seconds_since(start);
  return statistics;
}

} // namespace internal
} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_INTERNAL_POST_PROCESS_WITHOUT_SELF_INTERSECTIONS_H
