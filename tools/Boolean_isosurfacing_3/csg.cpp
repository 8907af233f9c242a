// csg: Boolean operations on closed triangle meshes by Marching Cubes.
//
//   csg A B --op union|intersection|difference (--cells N | --spacing r) [-o out.off]
//   csg A B C ... --expr "A & !B | C" (--cells N | --spacing r) [-o out.off]
//   csg --demo DIR
//   [--no-features] [--feature-angle DEG] [--creases F] [--corners F] [--strict]
//   and the common options of cli.h (--threads, --sequential, --json, --quiet, --version)
//
// Reads OFF/OBJ/PLY/STL; the i-th input is the variable A, B, C, ... of the
// expression (also f0, f1, ...).  Prints the lattice size, the time of each
// stage, the output size and the output's Surveyor volume.  `csg --help`
// lists the options.  Sharp creases and corners are on by default
// (doc/Boolean_isosurfacing_3/features.md).  Input components the lattice
// does not resolve (and empty results) get a warning naming them and the
// --cells that would resolve them; --strict makes that an error.  Exit
// status: 0, 1 for a bad file, a failed computation or (--strict) an
// unresolved input, 2 for a bad command line; every error is one line on
// stderr (doc/Boolean_isosurfacing_3/tools.md).

#include "cli.h"
#include "process_start.h"
#include "csg_options.h"
#include "self_intersection.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/IO/write_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/Marching_cubes_table.h>
#include <CGAL/Boolean_isosurfacing_3/Post_processing_statistics.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/overlapping_shells.h>
#include <CGAL/Boolean_isosurfacing_3/remesh_keeping_creases.h>
#include <CGAL/Boolean_isosurfacing_3/result_bounding_box.h>
#include <CGAL/Boolean_isosurfacing_3/simplify_keeping_creases.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

using namespace csg_tool;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
// Inputs and output stay in flat arrays from file to file: no halfedge
// structure is built on the way (it was most of the process's time).
typedef BI::Triangle_soup_3 Soup;

// `expression & X`, X a new last variable: the result clipped to the solid X.
BI::Boolean_expression and_with_new_variable(const BI::Boolean_expression& expression)
{
  const std::size_t n = expression.number_of_variables();
  if(n + 1 > BI::Boolean_expression::max_variables)
    throw BI::Invalid_input_error("the result is unbounded and " + std::to_string(n) +
                                  " inputs leave no variable for the clipping box: use --unbounded surface");
  std::vector<BI::Boolean_term> terms = expression.terms();
  for(BI::Boolean_term& t : terms)
    t.pos |= std::uint64_t(1) << n;
  return BI::Boolean_expression(n + 1, std::move(terms));
}

// The closed, outward triangulated box [lo, hi].
Soup box_soup(const std::array<double, 3>& lo, const std::array<double, 3>& hi)
{
  Soup box;
  // Corner k at (k & 1, (k >> 1) & 1, (k >> 2) & 1).
  for(int k = 0; k < 8; ++k)
    box.points.push_back({{(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]}});
  box.triangles = {{{0, 2, 3}}, {{0, 3, 1}}, {{4, 5, 7}}, {{4, 7, 6}}, {{0, 1, 5}}, {{0, 5, 4}},
                   {{2, 6, 7}}, {{2, 7, 3}}, {{0, 4, 6}}, {{0, 6, 2}}, {{1, 3, 7}}, {{1, 7, 5}}};
  return box;
}

// A generated mesh (the demo's inputs) as a soup.
Soup soup_of(const Mesh& mesh)
{
  Soup soup;
  std::vector<std::uint32_t> index(mesh.number_of_vertices());
  for(const Mesh::Vertex_index v : mesh.vertices())
  {
    index[v] = std::uint32_t(soup.points.size());
    const Point& p = mesh.point(v);
    soup.points.push_back({{p.x(), p.y(), p.z()}});
  }
  for(const Mesh::Face_index f : mesh.faces())
  {
    Soup::Triangle t;
    int i = 0;
    for(const Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      t[i++] = index[v];
    soup.triangles.push_back(t);
  }
  return soup;
}

struct Result
{
  Soup soup;
  BI::Marching_cubes_csg_statistics statistics;
  BI::Regular_lattice_3 lattice;
  BI::Crease_network creases; // vertex indices of `soup`
  std::optional<BI::Post_processing_statistics> post_processing; // --simplify or --remesh
};

std::size_t max_memory_bytes(const Options& options)
{
  if(options.max_memory_gib > 0)
    return std::size_t(options.max_memory_gib * double(std::size_t(1) << 30));
  // The library's default, unless this machine has less: refusing with an
  // estimate beats being killed half-way.
  std::size_t limit = BI::Lattice_classifier_3::default_max_memory_bytes;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if(pages > 0 && page_size > 0)
    limit = (std::min)(limit, std::size_t(double(pages) * double(page_size) * 0.75));
  return limit;
}

// `e`'s message, with the named parameter the library suggests replaced by
// this tool's flag, prefixed by the lattice flag that caused it.
std::string lattice_message(const Options& options, const BI::Lattice_too_large_error& e)
{
  std::string message = e.what();
  const std::string parameter = "(named parameter max_memory_bytes)";
  const std::size_t at = message.find(parameter);
  if(at != std::string::npos)
    message.replace(at, parameter.size(), "(--max-memory)");
  return options.lattice_flag.empty() ? message : options.lattice_flag + ": " + message;
}

CGAL::Bbox_3 bounding_box(const Soup& soup)
{
  CGAL::Bbox_3 box;
  for(const auto& p : soup.points)
    box += CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
  return box;
}

CGAL::Bbox_3 bounding_box(const std::vector<Soup>& soups)
{
  CGAL::Bbox_3 box;
  for(const Soup& s : soups)
    box += bounding_box(s);
  return box;
}

// The box the lattice is sized on: where the result can be
// (result_bounding_box()), or all the inputs' box when the result is
// unbounded (it is clipped to that box) or cannot be anywhere.
CGAL::Bbox_3 lattice_box(const BI::Boolean_expression& expression, const std::vector<Soup>& meshes)
{
  std::vector<CGAL::Bbox_3> boxes;
  for(const Soup& m : meshes) boxes.push_back(bounding_box(m));
  const BI::Result_bounding_box result = BI::result_bounding_box(expression, boxes);
  return result.bounded && !result.empty ? result.box : bounding_box(meshes);
}

// The crease edges (vertex pairs) chained into polylines between corners,
// branch points and ends; a closed crease repeats its first vertex.  Only
// the vertices on creases are indexed (an output has millions of others).
BI::Crease_network crease_polylines(const std::vector<std::array<std::size_t, 2>>& edges,
                                    const std::vector<std::size_t>& corners)
{
  BI::Crease_network network;
  network.corners = corners;
  network.number_of_crease_edges = edges.size();
  // The crease vertices, sorted; a vertex's slot is its rank among them.
  std::vector<std::size_t> vertices;
  for(const auto& e : edges)
    vertices.insert(vertices.end(), e.begin(), e.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  auto slot = [&](std::size_t v) {
    return std::size_t(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
  };
  std::vector<std::vector<std::size_t>> incident(vertices.size());
  for(std::size_t e = 0; e < edges.size(); ++e)
    for(std::size_t v : edges[e])
      incident[slot(v)].push_back(e);
  std::vector<bool> is_corner(vertices.size(), false), used(edges.size(), false);
  for(std::size_t v : corners)
  {
    const std::size_t s = slot(v);
    if(s < vertices.size() && vertices[s] == v)
      is_corner[s] = true;
  }
  auto is_end = [&](std::size_t s) { return is_corner[s] || incident[s].size() != 2; };
  auto walk = [&](std::size_t v, std::size_t e) {
    std::vector<std::size_t> line{v};
    while(!used[e])
    {
      used[e] = true;
      v = edges[e][0] == v ? edges[e][1] : edges[e][0];
      line.push_back(v);
      const std::size_t s = slot(v);
      if(is_end(s))
        break;
      e = incident[s][0] == e ? incident[s][1] : incident[s][0];
    }
    network.polylines.push_back(std::move(line));
  };
  for(std::size_t s = 0; s < vertices.size(); ++s)
    if(is_end(s))
      for(std::size_t e : incident[s])
        if(!used[e])
          walk(vertices[s], e);
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(!used[e])
      walk(edges[e][0], e); // a closed loop without corner
  return network;
}

// --simplify / --remesh on the result, its creases and corners kept.  They
// work on a halfedge mesh, built here only when asked for; the soup and the
// features are then replaced by the processed mesh's (compacted: vertex i is
// soup point i).
std::optional<BI::Post_processing_statistics> post_process(Soup& soup, BI::Marching_cubes_csg_features& features,
                                                          const Options& options, double spacing)
{
  if(soup.triangles.empty() || (!options.simplify && !options.remesh))
    return std::nullopt;
  Mesh output;
  {
    std::vector<Point> points;
    points.reserve(soup.points.size());
    for(const auto& p : soup.points)
      points.emplace_back(p[0], p[1], p[2]);
    PMP::polygon_soup_to_polygon_mesh(points, soup.triangles, output);
  }
  auto crease = output.add_property_map<Mesh::Edge_index, bool>("e:csg_crease", false).first;
  auto corner = output.add_property_map<Mesh::Vertex_index, bool>("v:csg_corner", false).first;
  // polygon_soup_to_polygon_mesh() keeps the points' order on a valid soup.
  for(const auto& e : features.crease_edges)
  {
    const auto h = halfedge(Mesh::Vertex_index(Mesh::size_type(e[0])), Mesh::Vertex_index(Mesh::size_type(e[1])), output);
    if(h.second)
      crease[edge(h.first, output)] = true;
  }
  for(std::size_t v : features.corner_vertices)
    corner[Mesh::Vertex_index(Mesh::size_type(v))] = true;
  const auto maps = CGAL::parameters::edge_is_constrained_map(crease).vertex_is_constrained_map(corner);
  const BI::Post_processing_statistics statistics =
      options.simplify
          ? BI::simplify_keeping_creases(output, options.simplify_cells * spacing, maps)
          : BI::remesh_keeping_creases(output, options.remesh_length > 0 ? options.remesh_length : spacing, maps);
  output.collect_garbage();
  soup = soup_of(output);
  features = BI::Marching_cubes_csg_features();
  for(const Mesh::Edge_index e : output.edges())
    if(crease[e])
    {
      const std::size_t a = std::size_t(output.vertex(e, 0)), b = std::size_t(output.vertex(e, 1));
      features.crease_edges.push_back({{(std::min)(a, b), (std::max)(a, b)}});
    }
  for(const Mesh::Vertex_index v : output.vertices())
    if(corner[v])
      features.corner_vertices.push_back(std::size_t(v));
  return statistics;
}

// The lattice encloses `box` (the inputs' bounding box) with `margin_cells`;
// the library's default lattice keeps the box's faces off the lattice planes.
Result run_csg(const std::vector<Soup>& meshes, const BI::Boolean_expression& expression, const Options& options,
               const CGAL::Bbox_3& box, std::size_t margin_cells = 1)
{
  Result r{Soup(), BI::Marching_cubes_csg_statistics(),
           options.cells > 0 ? BI::Regular_lattice_3::enclosing_with_cells(box, options.cells, margin_cells)
                             : BI::Regular_lattice_3::enclosing(box, options.spacing, margin_cells),
           BI::Crease_network()};
  BI::Marching_cubes_csg_features features;
  const auto np = BI::parameters::sharp_features(
      options.features,
      BI::parameters::feature_angle(
          options.feature_angle,
          BI::parameters::max_memory_bytes(max_memory_bytes(options), BI::parameters::sharp_feature_output(&features))))
      .callback(biso_tools::progress_callback("csg", "computing the CSG", options.quiet));
#ifdef CGAL_LINKED_WITH_TBB
  if(options.parallel)
    r.statistics = BI::marching_cubes_csg<CGAL::Parallel_tag>(r.lattice, meshes, expression, r.soup.points,
                                                              r.soup.triangles, np);
  else
#endif
    r.statistics = BI::marching_cubes_csg<CGAL::Sequential_tag>(r.lattice, meshes, expression, r.soup.points,
                                                                r.soup.triangles, np);
  r.post_processing = post_process(r.soup, features, options, r.lattice.spacing());
  r.creases = crease_polylines(features.crease_edges, features.corner_vertices);
  return r;
}

// The output's (signed) volume.  The output is closed by construction when
// no lattice boundary point is inside the result, and then skips the edge
// check (8 bytes per directed edge: more than the output itself).
double output_volume(const Result& r, bool signed_volume = false)
{
  return BI::surveyor_volume(
      r.soup, BI::parameters::signed_volume(signed_volume,
                                            BI::parameters::check_closedness(r.statistics.boundary_points_inside != 0)));
}

// The part of the result's volume in intervals of lattice lines that hold no
// lattice point (walls or gaps thinner than a cell), in percent.
double thin_result_percent(const BI::Marching_cubes_csg_statistics& s) { return 100 * s.thin_result_fraction(); }

void print_result(std::FILE* out, const Result& r)
{
  const auto& n = r.lattice.number_of_points();
  const auto& s = r.statistics;
  std::fprintf(out, "  lattice %zu x %zu x %zu points (%zu), spacing %.6g\n", n[0], n[1], n[2], s.lattice_points,
               r.lattice.spacing());
  std::fprintf(out, "  classification %.3f s, edge points %.3f s, triangulation %.3f s (%zu crossings)\n",
               s.seconds_classification, s.seconds_edges, s.seconds_triangulation, s.crossings);
  std::fprintf(out, "  output %zu vertices, %zu triangles\n", r.soup.points.size(), r.soup.triangles.size());
  if(s.feature_vertices > 0 || s.plain_feature_polygons > 0)
    std::fprintf(out,
                 "  sharp features: %zu feature vertices (%zu corners), %zu crease edges in %zu polylines, "
                 "%zu feature polygons kept plain, %zu short edges collapsed\n",
                 s.feature_vertices, s.corner_vertices, s.crease_edges, r.creases.polylines.size(),
                 s.plain_feature_polygons, s.collapsed_edges);
  if(s.weak_fans > 0 || s.extraction_runs > 1)
    std::fprintf(out,
                 "  fold tests: %zu fans passed only the weaker test; %zu cubes given the strict test after "
                 "a check, in %zu extraction runs\n",
                 s.weak_fans, s.strict_fold_cubes, s.extraction_runs);
  std::fprintf(out,
               "  resolution check: %zu input components, %zu not resolved by the lattice; %zu of %zu result "
               "intervals on lattice lines thinner than a cell (%.3g %% of the volume), %.3g %% in walls "
               "or gaps under two cells\n",
               s.checked_components, s.under_resolved_components.size(), s.thin_result_intervals,
               s.result_intervals, thin_result_percent(s), 100 * s.sparse_result_fraction);
}

// The stages the library timed, as progress lines, and the JSON members
// of the result.
void report_result(Tool& tool, const Result& r)
{
  const auto& s = r.statistics;
  const auto& n = r.lattice.number_of_points();
  tool.stage("classification", "classified " + std::to_string(s.lattice_points) + " lattice points",
             s.seconds_classification);
  tool.stage("edges", "placed " + std::to_string(s.crossings) + " edge crossings", s.seconds_edges);
  tool.stage("triangulation", "triangulated " + std::to_string(r.soup.triangles.size()) + " triangles",
             s.seconds_triangulation);
  if(r.post_processing)
  {
    const BI::Post_processing_statistics& p = *r.post_processing;
    tool.stage("post_processing",
               std::string(p.edges_collapsed > 0 ? "simplified" : "post-processed") + " in " +
                   std::to_string(p.runs) + (p.runs == 1 ? " run" : " runs") + " (" +
                   std::to_string(p.frozen_faces) + " faces kept where earlier runs self-intersected (" +
                   std::to_string(p.intersecting_pairs_found) + " pairs) or left the input (" +
                   std::to_string(p.far_input_vertices_found) + " vertices); checks " +
                   std::to_string(p.seconds_checks).substr(0, 5) + " s)",
               p.seconds);
    for(const std::string& w : p.warnings)
      tool.warning(w);
    biso_tools::Json_object post;
    post.set("runs", p.runs);
    post.set("frozen_faces", p.frozen_faces);
    post.set("intersecting_pairs_found", p.intersecting_pairs_found);
    post.set("far_input_vertices_found", p.far_input_vertices_found);
    post.set("reverted", p.reverted);
    post.set("seconds_checks", p.seconds_checks);
    tool.summary().set("post_processing", post);
  }
  biso_tools::Json_object lattice;
  lattice.set_raw("points", biso_tools::json_number_array({double(n[0]), double(n[1]), double(n[2])}));
  lattice.set("spacing", r.lattice.spacing());
  biso_tools::Json_object& j = tool.summary();
  j.set("lattice", lattice);
  j.set("vertices", r.soup.points.size());
  j.set("faces", r.soup.triangles.size());
  j.set("crossings", s.crossings);
  j.set("feature_vertices", s.feature_vertices);
  j.set("corners", s.corner_vertices);
  j.set("crease_edges", s.crease_edges);
  j.set("weak_fans", s.weak_fans);
  j.set("strict_fold_cubes", s.strict_fold_cubes);
  j.set("extraction_runs", s.extraction_runs);
  j.set("unresolved_components", s.under_resolved_components.size());
  j.set("thin_result_intervals", s.thin_result_intervals);
  j.set("thin_result_percent", thin_result_percent(s));
  j.set("sparse_result_percent", 100 * s.sparse_result_fraction);
}

// One warning (or, with --strict, error) line.
void resolution_problem(Tool& tool, const Options& options, const std::string& text)
{
  if(options.strict)
  {
    tool.summary().set("strict_failure", true);
    biso_tools::print_error("csg", "error: " + text);
  }
  else
    tool.warning(text);
}

// An empty result from non-empty inputs is the answer only if the
// expression is false wherever some inputs overlap; we cannot tell cheaply,
// so it is never a plain success unless the expression is false everywhere
// (A & !A).
bool suspicious_empty_result(const Result& r, const Options& options, const std::vector<Soup>& meshes,
                             const BI::Boolean_expression& requested)
{
  bool inputs_empty = true;
  for(std::size_t i = 0; i < options.files.size(); ++i)
    inputs_empty = inputs_empty && meshes[i].triangles.empty();
  if(!r.soup.triangles.empty() || requested.evaluate(0) || inputs_empty)
    return false;
  const std::size_t n = requested.number_of_variables();
  bool satisfiable = n > 20; // too many to enumerate: assume it can be true
  for(std::uint64_t m = 1; !satisfiable && m < (std::uint64_t(1) << n); ++m)
    satisfiable = requested.evaluate(m);
  return satisfiable;
}

// The warnings about what the lattice missed: one line each, at most
// `limit` lines.  Returns their number (all of them, not only printed).
std::size_t resolution_warnings(Tool& tool, const Result& r, const Options& options, const std::vector<Soup>& meshes,
                                const CGAL::Bbox_3& box, const BI::Boolean_expression& requested)
{
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  std::size_t count = 0, printed = 0;
  const std::size_t limit = 10;
  for(const BI::Marching_cubes_csg_component_report& c : r.statistics.under_resolved_components)
  {
    if(c.mesh >= options.files.size())
      continue; // the clipping box
    ++count;
    if(printed == limit)
      continue;
    ++printed;
    const double cells = std::ceil(longest / c.suggested_spacing);
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s (%s) component %zu (%zu triangles, volume %.6g) is not resolved by the lattice: %s, "
                  "lattice volume %.6g; --cells %.0f (spacing %.6g) would resolve it",
                  options.files[c.mesh].c_str(), c.mesh < 26 ? std::string(1, char('A' + c.mesh)).c_str() : "",
                  c.component, c.triangles, c.volume,
                  c.crossings == 0 ? "it crosses no lattice edge"
                                   : (std::to_string(c.inside_points) + " lattice points inside").c_str(),
                  c.lattice_volume, cells, c.suggested_spacing);
    resolution_problem(tool, options, text);
  }
  if(count > printed)
    resolution_problem(tool, options,
                       std::to_string(count - printed) + " more input components are not resolved by the lattice");
  if(suspicious_empty_result(r, options, meshes, requested))
  {
    ++count;
    resolution_problem(tool, options,
                       "the result is empty although the inputs are not: either the exact result "
                       "is empty or the lattice is too coarse to see it");
  }
  // Thin walls or gaps of the result itself (a difference of nearly
  // coincident solids), which the component check cannot see; the library
  // decides when they are worth a warning.  Not repeated when input
  // components were named already (their --cells suffices).
  const BI::Marching_cubes_csg_statistics& s = r.statistics;
  if(count == 0 && s.has_thin_result())
  {
    ++count;
    char text[512];
    std::snprintf(text, sizeof text,
                  "the result has walls or gaps thinner than a lattice cell: %zu of %zu intervals of lattice lines "
                  "through it hold no lattice point (at least %.3g %% of its volume is missing or filled in); "
                  "--cells %.0f (spacing %.6g) would see most of them",
                  s.thin_result_intervals, s.result_intervals, thin_result_percent(s),
                  std::ceil(longest / s.thin_result_suggested_spacing), s.thin_result_suggested_spacing);
    resolution_problem(tool, options, text);
  }
  else if(count == 0 && s.has_sparse_result())
  {
    ++count;
    char text[512];
    std::snprintf(text, sizeof text,
                  "%.3g %% of the result lies in walls or gaps that hold at most one lattice point across: "
                  "Marching Cubes may break them into pieces; --cells %.0f (spacing %.6g) would see most of them",
                  100 * s.sparse_result_fraction, std::ceil(longest / s.sparse_result_suggested_spacing),
                  s.sparse_result_suggested_spacing);
    resolution_problem(tool, options, text);
  }
  return count;
}

double exact_volume(const CGAL::Surface_mesh<Epeck::Point_3>& m)
{
  return CGAL::to_double(CGAL::exact(PMP::volume(m)));
}

void make_directory(const std::string& dir)
{
  struct stat info;
  if(mkdir(dir.c_str(), 0755) != 0 && (errno != EEXIST || stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)))
    throw biso_tools::File_error(dir + ": cannot create the directory (" +
                                 (errno == EEXIST ? std::string("a file of that name exists") : std::strerror(errno)) + ")");
}

// The volume of the exact Boolean result of `a` and `b` (PMP corefinement, Epeck).
double exact_result_volume(const Soup& a, const Soup& b, const std::string& op)
{
  typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
  auto exact_mesh = [](const Soup& s) {
    std::vector<Epeck::Point_3> points;
    for(const auto& p : s.points)
      points.emplace_back(p[0], p[1], p[2]);
    Exact_mesh m;
    PMP::polygon_soup_to_polygon_mesh(points, s.triangles, m);
    return m;
  };
  Exact_mesh a_copy = exact_mesh(a), b_copy = exact_mesh(b), exact_result;
  if(op == "union") PMP::corefine_and_compute_union(a_copy, b_copy, exact_result);
  else if(op == "intersection") PMP::corefine_and_compute_intersection(a_copy, b_copy, exact_result);
  else PMP::corefine_and_compute_difference(a_copy, b_copy, exact_result);
  return exact_volume(exact_result);
}

int run_demo(Tool& tool, Options options)
{
  const std::string& dir = options.demo_dir;
  make_directory(dir);
  biso_tools::check_output_file(dir + "/A_sphere.off");
  // The built-in pair: a sphere and a torus that cuts through it.
  std::vector<Soup> meshes(2);
  {
    Mesh sphere, torus;
    BI::make_icosphere(sphere, Point(0, 0, 0), 1.0, 4);
    BI::make_torus(torus, Point(0.9, 0, 0), 0.8, 0.35, 96, 48);
    meshes[0] = soup_of(sphere);
    meshes[1] = soup_of(torus);
  }
  for(const auto& [i, name] : {std::pair<int, const char*>{0, "/A_sphere.off"}, {1, "/B_torus.off"}})
  {
    BI::IO::write_triangle_soup(dir + name, meshes[i]);
    tool.output(dir + name);
  }
  std::FILE* out = tool.human();
  std::fprintf(out,
               "Marching Cubes CSG of a sphere (A, %zu triangles) and a torus through it (B, %zu triangles),\n"
               "written with the results to %s/.  'exact' is the volume of the exact Boolean result\n"
               "of the same polyhedra (PMP corefinement with Epeck).\n\n",
               meshes[0].triangles.size(), meshes[1].triangles.size(), dir.c_str());
  const std::pair<const char*, BI::Boolean_expression> operations[] = {
      {"union", BI::Boolean_expression::union_of(2)},
      {"intersection", BI::Boolean_expression::intersection_of(2)},
      {"difference", BI::Boolean_expression::difference()}};
  if(options.cells == 0 && options.spacing == 0) options.cells = 128;
  biso_tools::Json_object results;
  for(const auto& [name, expression] : operations)
  {
    const std::string op = name;
    const double exact = exact_result_volume(meshes[0], meshes[1], op);
    const Result r = run_csg(meshes, expression, options, bounding_box(meshes));
    const double ours = output_volume(r);
    std::fprintf(out, "%s (%s)\n", name, expression.to_string().c_str());
    print_result(out, r);
    std::fprintf(out, "  volume %.6f   exact %.6f   relative error %.2e\n\n", ours, exact,
                 std::abs(ours - exact) / exact);
    BI::IO::write_triangle_soup(dir + "/" + op + ".off", r.soup);
    tool.output(dir + "/" + op + ".off");
    biso_tools::Json_object j;
    j.set("faces", r.soup.triangles.size());
    j.set("volume", ours);
    j.set("exact_volume", exact);
    results.set(op, j);
  }
  tool.summary().set("demo", results);
  return 0;
}

std::string variable_name(std::size_t i)
{
  return i < 26 ? std::string(1, char('A' + i)) : "f" + std::to_string(i);
}

// Reads every input into flat arrays (checked closed and consistently
// oriented); an inward-oriented one is accepted with a note.  The files are
// read side by side on a parallel run; the first bad one (in order) is the
// error, as in a sequential run.
std::vector<Soup> read_inputs(Tool& tool, const std::vector<std::string>& files)
{
  const biso_tools::Stopwatch watch;
  std::vector<Soup> meshes(files.size());
  std::vector<double> signed_volumes(files.size(), 0);
  tool.for_each_index(files.size(), [&](std::size_t i) {
    biso_tools::check_input_file(files[i]);
    try
    {
      meshes[i] = BI::IO::read_closed_triangle_soup(files[i], /* allow_inward = */ true, &signed_volumes[i]);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw biso_tools::File_error(files[i] + ": " + e.what());
    }
  });
  std::size_t triangles = 0;
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    const double signed_volume = signed_volumes[i];
    triangles += meshes[i].triangles.size();
    tool.input(files[i]);
    if(meshes[i].triangulated_polygons > 0)
      tool.note(files[i] + " (" + variable_name(i) + "): " + std::to_string(meshes[i].triangulated_polygons) +
                " polygons with more than 3 vertices were split into triangles");
    if(signed_volume < 0)
      tool.note(files[i] + " (" + variable_name(i) +
                ") is oriented inward; the classification counts crossings, so it is used as the solid it bounds");
  }
  tool.stage("read", "read " + std::to_string(files.size()) + " meshes (" + std::to_string(triangles) + " triangles)",
             watch.seconds());
  return meshes;
}

// Inputs whose own shells overlap (or, with --check-inputs, intersect):
// parity, which the classification uses, makes a doubly covered part a void
// where Manifold and OpenSCAD take the union.  One warning per mesh.
// The number of connected components of a soup (triangles joined by their
// vertex indices): a union-find, cheap next to reading the file.
std::size_t soup_components(const Soup& soup)
{
  std::vector<std::uint32_t> parent(soup.points.size());
  for(std::uint32_t v = 0; v < parent.size(); ++v)
    parent[v] = v;
  auto find = [&](std::uint32_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const Soup::Triangle& t : soup.triangles)
    for(int k = 1; k < 3; ++k)
    {
      const std::uint32_t a = find(t[0]), b = find(t[k]);
      if(a != b)
        parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  std::vector<bool> used(soup.points.size(), false);
  for(const Soup::Triangle& t : soup.triangles)
    used[t[0]] = true;
  std::size_t components = 0;
  for(std::uint32_t v = 0; v < parent.size(); ++v)
    components += used[v] && find(v) == v ? 1 : 0;
  return components;
}

void overlap_warnings(Tool& tool, const Options& options, const std::vector<Soup>& meshes)
{
  for(std::size_t i = 0; i < options.files.size(); ++i)
  {
    // A halfedge mesh is built only where there is something to check.
    if(!options.check_inputs && soup_components(meshes[i]) < 2)
      continue;
    Mesh mesh;
    try
    {
      BI::IO::triangle_soup_to_mesh(meshes[i], mesh);
    }
    catch(const BI::Invalid_input_error&)
    {
      continue; // non-manifold vertices: not checked (the classification counts crossings anyway)
    }
    // The self-intersection test on the soup (biso_tools::soup_self_intersects()), not PMP's
    // on the mesh that find_overlapping_shells() would run: 3-4x faster.
    BI::Overlapping_shells_report report = BI::find_overlapping_shells(mesh, false);
    if(options.check_inputs)
    {
      report.checked_self_intersection = true;
      report.self_intersecting = biso_tools::soup_self_intersects(meshes[i], options.parallel, &mesh);
    }
    if(!report.overlaps())
      continue;
    std::string text = options.files[i] + " (" + variable_name(i) + ")";
    if(!report.overlapping_pairs.empty())
    {
      const auto& pair = report.overlapping_pairs.front();
      text += " has overlapping shells (" + std::to_string(report.overlapping_pairs.size()) +
              " pair(s) of its " + std::to_string(report.components) + " components, e.g. " +
              std::to_string(pair.first) + " and " + std::to_string(pair.second) + ")";
    }
    else
      text += " intersects itself";
    tool.warning(text + ": inside is decided by parity, so a part covered twice is outside the solid "
                        "(Manifold and OpenSCAD take the union there)");
  }
}

// An unbounded result clipped to a box one cell beyond the inputs.
struct Clip
{
  bool clip = false;
  std::array<double, 3> lo{}, hi{};
  std::size_t margin_cells = 1;
};

// Adds the clipping box to `meshes` and `expression` when the result is
// unbounded and --unbounded box.
Clip clip_unbounded(const Options& options, const CGAL::Bbox_3& box, std::vector<Soup>& meshes,
                    BI::Boolean_expression& expression)
{
  Clip c;
  // Outside every input all masks are 0, so the result is unbounded iff
  // the expression is true there.
  c.clip = expression.evaluate(0) && options.unbounded == Unbounded_mode::BOX;
  if(!c.clip)
    return c;
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const double spacing = options.cells > 0 ? longest / double(options.cells) : options.spacing;
  // The box one cell beyond the inputs, inside a lattice of two cells'
  // margin: its faces lie between lattice planes (the library's lattice is offset
  // by a fraction of a cell), so they come out flat.
  for(int a = 0; a < 3; ++a)
  {
    c.lo[a] = box.min(a) - spacing;
    c.hi[a] = box.max(a) + spacing;
  }
  meshes.push_back(box_soup(c.lo, c.hi));
  expression = and_with_new_variable(expression);
  c.margin_cells = 2;
  return c;
}

// The human summary and the volume of the JSON summary.
void print_summary(Tool& tool, const Options& options, const Result& r, const BI::Boolean_expression& requested,
                   const Clip& clip, double seconds)
{
  std::FILE* out = tool.human();
  const bool unbounded = requested.evaluate(0);
  std::fprintf(out, "csg %s over %zu meshes\n", requested.to_string().c_str(), options.files.size());
  if(clip.clip)
    std::fprintf(out, "  the result is unbounded: clipped to the box [%.9g, %.9g, %.9g] - [%.9g, %.9g, %.9g]\n",
                 clip.lo[0], clip.lo[1], clip.lo[2], clip.hi[0], clip.hi[1], clip.hi[2]);
  print_result(out, r);
  std::fprintf(out, "  total %.3f s\n", seconds);
  biso_tools::Json_object& j = tool.summary();
  j.set("unbounded", unbounded);
  j.set("clipped", clip.clip);
  if(r.soup.triangles.empty())
  {
    std::fprintf(out, unbounded && !clip.clip ? "  the result is all of space (no surface)\n" : "  the result is empty\n");
    if(unbounded && !clip.clip) j.set_null("volume");
    else j.set("volume", 0.0);
  }
  else if(unbounded && !clip.clip)
  {
    const double complement = -output_volume(r, true);
    std::fprintf(out, "  the result is unbounded: its surface is inward-oriented; the complement has volume %.9g\n",
                 complement);
    j.set_null("volume");
    j.set("complement_volume", complement);
  }
  else
  {
    const double volume = output_volume(r);
    std::fprintf(out, "  volume %.9g\n", volume);
    j.set("volume", volume);
  }
}

void write_outputs(Tool& tool, const Options& options, const Result& r)
{
  const biso_tools::Stopwatch watch;
  if(!options.output.empty())
  {
    try
    {
      BI::IO::write_triangle_soup(options.output, r.soup);
    }
    catch(const std::runtime_error& e)
    {
      throw biso_tools::File_error(e.what());
    }
    tool.output(options.output);
  }
  if(!options.creases_file.empty() || !options.corners_file.empty())
  {
    try
    {
      if(!options.creases_file.empty())
        BI::IO::write_polylines(options.creases_file, r.soup.points, r.creases);
      if(!options.corners_file.empty())
        BI::IO::write_corners(options.corners_file, r.soup.points, r.creases);
    }
    catch(const std::runtime_error& e)
    {
      throw biso_tools::File_error(e.what());
    }
    for(const std::string* f : {&options.creases_file, &options.corners_file})
      if(!f->empty()) tool.output(*f);
  }
  if(!options.output.empty() || !options.creases_file.empty() || !options.corners_file.empty())
    tool.stage("write", "wrote the outputs", watch.seconds());
}

int run(Tool& tool, const Options& options)
{
  if(options.files.empty()) throw Usage_error("no input file (csg --help for usage)");
  if(options.have_op == options.have_expression) throw Usage_error("give exactly one of --op and --expr");
  if((options.cells > 0) == (options.spacing > 0)) throw Usage_error("give exactly one of --cells N and --spacing h");
  const BI::Boolean_expression requested = expression_from(options, options.files.size());
  BI::Boolean_expression expression = requested;
  for(const std::string* f : {&options.output, &options.creases_file, &options.corners_file})
    if(!f->empty()) biso_tools::check_output_file(*f);

  const std::future<void> table = biso_tools::build_meanwhile<BI::Marching_cubes_table>(tool.parallel());
  std::vector<Soup> meshes = read_inputs(tool, options.files);
  overlap_warnings(tool, options, meshes);
  const CGAL::Bbox_3 box = lattice_box(requested, meshes);
  const Clip clip = clip_unbounded(options, box, meshes, expression);

  const biso_tools::Stopwatch watch;
  std::optional<Result> result;
  try
  {
    result.emplace(run_csg(meshes, expression, options, box, clip.margin_cells));
  }
  catch(const BI::Lattice_too_large_error& e)
  {
    throw BI::Invalid_input_error(lattice_message(options, e));
  }
  const Result& r = *result;
  const double seconds = watch.seconds();
  report_result(tool, r);
  tool.time("total", seconds);
  tool.summary().set("expression", requested.to_string());
  const std::size_t unresolved = resolution_warnings(tool, r, options, meshes, box, requested);
  print_summary(tool, options, r, requested, clip, seconds);
  if(unresolved > 0 && options.strict)
    return 1; // nothing written: the result is not trusted
  write_outputs(tool, options, r);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  // The MPI driver first: it is started with the huge-page heap directly.
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--distributed")
    {
#ifdef BISO_WITH_MPI
      return biso_tools::run_distributed_driver("csg", "csg_distributed", argv);
#else
      std::cerr << "csg: error: --distributed: this csg was built without MPI\n";
      return 1;
#endif
    }
  biso_tools::restart_with_huge_page_heap(argv);
  Tool tool("csg", description);
  Options options;
  Option_text text;
  add_options(tool, options, text);
  return tool.run(
      argc, argv, [&] { check_options(tool, options, text); },
      [&] { return options.demo_dir.empty() ? run(tool, options) : run_demo(tool, options); });
}
