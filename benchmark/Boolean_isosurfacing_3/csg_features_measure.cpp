// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Measures Marching Cubes CSG (plain and with sharp features) against the
// exact result (corefinement on Epeck) and against OpenVDB at the same voxel
// size (meshToLevelSet -> csg -> volumeToMesh), on the cases of issue 17:
//   - exact answers: a box minus a box moved by a non-lattice offset, a box
//     intersected with a rotated box, a cylinder united with a box;
//   - the shared pairs (shared/data/boolean_pairs);
//   - CAD meshes against a moved and rotated copy of themselves (fandisk,
//     mechpart_hoppe, rocker-arm, xyz-cube-20mm, tray_bottom), difference
//     and union;
//   - organic ones (bunny_hoppe, armadillo), difference and union.
// Measures, per case and method (all distances in units of the spacing r):
//   - the distance from the exact result's sharp edges (dihedral angle
//     above 30 degrees, sampled every r/8) to the output surface: p95 and
//     max over all of them; over the "resolvable" ones (not on or near a
//     knife edge: a knife edge has an interior angle below 2 atan(1/2) =
//     53.13 degrees, so that the solid is thinner than r at distance r from
//     it, and the samples closer than r / (2 tan(theta / 2)) to a knife edge
//     of interior angle theta are in its thin wedge); over the straight ones
//     (resolvable, on an exact edge at least 2r long, at least r from its
//     ends);
//   - the two-sided Hausdorff distance (area-weighted random samples of both
//     surfaces, plus the exact result's vertices and sharp-edge samples): all,
//     and away from thin wedges (samples farther than r / (2 tan(theta / 2))
//     from every knife edge of interior angle theta);
//   - the mean angle between the output's face normal and the exact face
//     normal at the nearest exact point (all samples, and samples at least
//     r away from every sharp edge);
//   - the volume's relative error;
//   - triangle quality: zero-area triangles (exact collinearity), the share
//     with a smallest angle below 5 and below 20 degrees, the smallest angle;
//   - closed 2-manifold and self-intersection (PMP::does_self_intersect);
//   - time: best of 3 sequential runs (OpenVDB limited to one thread); the
//     features' row also relative to plain MC with the sliver pass the
//     features run (sliver_edge_length 0.15), timed the same way.
//
// usage: csg_features_measure [--cells N] [--dump DIR] [--post-processing] [CASE ...]
// Without CASE, every case; `csg_features_measure --list` lists them.
// --post-processing adds the feature output simplified within 0.1 r
// (simplify_keeping_creases()) and remeshed to edges of r
// (remesh_keeping_creases()), their creases and corners kept.
// --dump DIR writes, per case, the exact result, the outputs, their crease
// polylines and the sharp-edge samples farther than 0.2 r from the output.

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/remesh_keeping_creases.h>
#include <CGAL/Boolean_isosurfacing_3/simplify_keeping_creases.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include "test_util.h"

#ifdef BISO_WITH_OPENVDB
#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>
#endif
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Segment_3 Segment;
typedef K::Triangle_3 Triangle;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
typedef std::vector<Triangle>::const_iterator Triangle_iterator;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangle_iterator>>> Triangle_tree;
typedef std::vector<Segment>::const_iterator Segment_iterator;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segment_iterator>>> Segment_tree;
typedef std::array<std::size_t, 3> Index_triangle;

const double pi = 3.14159265358979323846;
// Interior angle below which a sharp edge is a knife edge: the solid is
// thinner than r at distance r from it.
const double knife_angle = 2 * std::atan(0.5);

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ------------------------------------------------------------------ inputs

Mesh make_box(const Point& low, const Point& high) { return BI::test::make_box<Mesh>(low, high); }

Mesh make_cylinder(const Point& base, double radius, double height, int segments)
{
  return BI::test::make_cylinder<Mesh>(base, radius, height, segments);
}

Mesh read_mesh(const std::string& path)
{
  Mesh m;
  BI::IO::read_closed_triangle_mesh(path, m);
  return m;
}

struct Case
{
  std::string name;
  std::function<std::vector<Mesh>()> inputs;
  char op; // '|', '&', '-'
};

std::vector<Case> all_cases(const std::string& data)
{
  std::vector<Case> cases;
  cases.push_back({"box-box",
                   [] {
                     return std::vector<Mesh>{make_box(Point(0, 0, 0), Point(1, 1, 1)),
                                              make_box(Point(0.5137, 0.4419, 0.6271), Point(1.7, 1.6, 1.8))};
                   },
                   '-'});
  cases.push_back({"box&rotbox",
                   [] {
                     return std::vector<Mesh>{make_box(Point(0, 0, 0), Point(1, 1, 1)),
                                              BI::test::moved(make_box(Point(0.2, 0.25, 0.15), Point(1.3, 1.2, 1.25)),
                                                    Point(0.5, 0.5, 0.5), Vector(1, 2, 3), 0.45, Vector(0, 0, 0))};
                   },
                   '&'});
  cases.push_back({"cylinder|box",
                   [] {
                     return std::vector<Mesh>{make_cylinder(Point(0.5, 0.5, -0.3), 0.37, 1.6, 64),
                                              make_box(Point(0, 0, 0), Point(1, 1, 1))};
                   },
                   '|'});
  const std::string pairs = data + "/boolean_pairs/";
  for(char op : {'|', '&', '-'})
    cases.push_back({std::string("balls") + op,
                     [pairs] { return std::vector<Mesh>{read_mesh(pairs + "ballA.off"), read_mesh(pairs + "ballB.off")}; },
                     op});
  cases.push_back({"generic-twin|",
                   [pairs] {
                     return std::vector<Mesh>{read_mesh(pairs + "Generic_Twin_7081.1.t0_left.obj"),
                                              read_mesh(pairs + "Generic_Twin_7081.1.t0_right.obj")};
                   },
                   '|'});
  cases.push_back({"hull-",
                   [pairs] {
                     return std::vector<Mesh>{read_mesh(pairs + "hull-body.obj"), read_mesh(pairs + "hull-mask.obj")};
                   },
                   '-'});
  const std::pair<const char*, const char*> moved_pairs[] = {
      {"fandisk", "fandisk.off"},   {"mechpart", "mechpart_hoppe.off"},   {"rocker-arm", "rocker-arm.obj"},
      {"xyz-cube", "xyz-cube-20mm.off"}, {"tray", "tray_bottom.off"}, {"bunny", "bunny_hoppe.off"},
      {"armadillo", "armadillo.obj"}};
  for(const auto& [name, file] : moved_pairs)
    for(char op : {'-', '|'})
    {
      const std::string path = data + "/meshes/" + file;
      cases.push_back({std::string(name) + op,
                       [path] {
                         const Mesh a = read_mesh(path);
                         return std::vector<Mesh>{a, BI::test::moved_copy(a)};
                       },
                       op});
    }
  return cases;
}

BI::Boolean_expression expression_of(char op)
{
  return op == '|' ? BI::Boolean_expression::union_of(2)
                   : (op == '&' ? BI::Boolean_expression::intersection_of(2) : BI::Boolean_expression::difference());
}

// ------------------------------------------------------------------ the exact reference

struct Sharp_sample
{
  Point p;
  bool knife, straight;
};

struct Reference
{
  bool available = false;
  std::string why_not;
  Mesh mesh;
  double volume = 0;
  std::vector<Triangle> triangles;
  std::unique_ptr<Triangle_tree> tree;
  std::vector<Segment> sharp, knives;
  std::vector<double> knife_zone; // per knife edge: r / (2 tan(theta / 2))
  std::unique_ptr<Segment_tree> sharp_tree, knife_tree;
  std::vector<Sharp_sample> sharp_samples;
  std::vector<Point> surface_samples; // with the vertices and the sharp samples

  // Whether p lies in the thin zone of a knife edge.
  bool in_thin_zone(const Point& p) const
  {
    if(!knife_tree)
      return false;
    const auto hit = knife_tree->closest_point_and_primitive(p);
    const std::size_t e = std::size_t(hit.second - knives.begin());
    return CGAL::squared_distance(p, hit.first) < knife_zone[e] * knife_zone[e];
  }
  double distance_to_sharp(const Point& p) const
  {
    return sharp_tree ? std::sqrt(sharp_tree->squared_distance(p)) : std::numeric_limits<double>::infinity();
  }
};

// Area-weighted random points of the triangles, about `per_r2` per r^2,
// between 2e4 and 4e5.
std::vector<std::pair<Point, std::size_t>> sample_triangles(const std::vector<Triangle>& triangles, double r,
                                                            double per_r2, unsigned seed)
{
  std::vector<double> cumulative;
  double area = 0;
  for(const Triangle& t : triangles)
  {
    area += std::sqrt(t.squared_area());
    cumulative.push_back(area);
  }
  std::vector<std::pair<Point, std::size_t>> result;
  if(!(area > 0))
    return result;
  const std::size_t n = std::size_t((std::min)(4e5, (std::max)(2e4, per_r2 * area / (r * r))));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t t =
        std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), u(random) * area) - cumulative.begin());
    const std::size_t tt = (std::min)(t, triangles.size() - 1);
    double a = u(random), b = u(random);
    if(a + b > 1)
    {
      a = 1 - a;
      b = 1 - b;
    }
    const Triangle& tr = triangles[tt];
    result.emplace_back(tr[0] + (tr[1] - tr[0]) * a + (tr[2] - tr[0]) * b, tt);
  }
  return result;
}

void build_reference(Reference& ref, const std::vector<Mesh>& meshes, char op, double r)
{
  for(std::size_t m = 0; m < meshes.size(); ++m)
    if(PMP::does_self_intersect(meshes[m]))
    {
      ref.why_not = "input " + std::to_string(m) + " self-intersects";
      return;
    }
  Exact_mesh ea, eb, eo;
  CGAL::copy_face_graph(meshes[0], ea);
  CGAL::copy_face_graph(meshes[1], eb);
  bool ok = false;
  try
  {
    ok = op == '|' ? PMP::corefine_and_compute_union(ea, eb, eo)
                   : (op == '&' ? PMP::corefine_and_compute_intersection(ea, eb, eo)
                                : PMP::corefine_and_compute_difference(ea, eb, eo));
  }
  catch(const std::exception& e)
  {
    ref.why_not = std::string("corefinement threw: ") + e.what();
    return;
  }
  if(!ok)
  {
    ref.why_not = "corefinement refused";
    return;
  }
  CGAL::copy_face_graph(eo, ref.mesh);
  ref.available = true;
  ref.volume = CGAL::to_double(PMP::volume(eo));
  for(auto f : faces(ref.mesh))
  {
    const auto h = halfedge(f, ref.mesh);
    ref.triangles.emplace_back(ref.mesh.point(source(h, ref.mesh)), ref.mesh.point(target(h, ref.mesh)),
                               ref.mesh.point(target(next(h, ref.mesh), ref.mesh)));
  }
  ref.tree = std::make_unique<Triangle_tree>(ref.triangles.begin(), ref.triangles.end());
  ref.tree->accelerate_distance_queries();
  // Sharp edges with their interior angle.
  std::vector<double> interior;
  for(auto e : edges(ref.mesh))
  {
    const auto h = halfedge(e, ref.mesh);
    const Vector n1 = PMP::compute_face_normal(face(h, ref.mesh), ref.mesh);
    const Vector n2 = PMP::compute_face_normal(face(opposite(h, ref.mesh), ref.mesh), ref.mesh);
    const double c = (std::max)(-1.0, (std::min)(1.0, n1 * n2));
    if(!(c < std::cos(30 * pi / 180)))
      continue;
    const Point a = ref.mesh.point(source(h, ref.mesh)), b = ref.mesh.point(target(h, ref.mesh));
    // Convex iff the far vertex of the opposite face is below the plane of the first.
    const Point far = ref.mesh.point(target(next(opposite(h, ref.mesh), ref.mesh), ref.mesh));
    const bool convex = (far - a) * n1 < 0;
    const double bend = std::acos(c);
    const double theta = convex ? pi - bend : pi + bend;
    ref.sharp.emplace_back(a, b);
    interior.push_back(theta);
    if(theta < knife_angle)
    {
      ref.knives.emplace_back(a, b);
      ref.knife_zone.push_back(r / (2 * std::tan(theta / 2)));
    }
  }
  if(!ref.sharp.empty())
    ref.sharp_tree = std::make_unique<Segment_tree>(ref.sharp.begin(), ref.sharp.end());
  if(!ref.knives.empty())
  {
    ref.knife_tree = std::make_unique<Segment_tree>(ref.knives.begin(), ref.knives.end());
    ref.knife_tree->accelerate_distance_queries();
  }
  for(std::size_t e = 0; e < ref.sharp.size(); ++e)
  {
    const Segment& s = ref.sharp[e];
    const double length = std::sqrt(s.squared_length());
    const int n = (std::max)(1, int(std::ceil(length / (r / 8))));
    for(int i = 0; i <= n; ++i)
    {
      const double t = double(i) / n;
      const Point p = s.source() + (s.target() - s.source()) * t;
      const bool thin = interior[e] < knife_angle || ref.in_thin_zone(p);
      const bool straight = !thin && length >= 2 * r && t * length >= r && (1 - t) * length >= r;
      ref.sharp_samples.push_back({p, thin, straight});
    }
  }
  for(const auto& s : sample_triangles(ref.triangles, r, 16, 1))
    ref.surface_samples.push_back(s.first);
  for(auto v : vertices(ref.mesh))
    ref.surface_samples.push_back(ref.mesh.point(v));
  for(const Sharp_sample& s : ref.sharp_samples)
    ref.surface_samples.push_back(s.p);
}

// ------------------------------------------------------------------ measures

struct Soup
{
  std::vector<Point> points;
  std::vector<Index_triangle> triangles;
  std::vector<std::array<std::size_t, 2>> creases;
};

struct Quantiles
{
  double p95 = std::nan(""), max = std::nan("");
  std::size_t n = 0;
};

Quantiles quantiles(std::vector<double> d)
{
  Quantiles q;
  q.n = d.size();
  if(d.empty())
    return q;
  std::sort(d.begin(), d.end());
  q.max = d.back();
  q.p95 = d[std::size_t(0.95 * double(d.size() - 1))];
  return q;
}

struct Measure
{
  std::string method;
  double seconds = std::nan("");
  std::size_t triangles = 0, zero_area = 0;
  double under5 = 0, under20 = 0, min_angle = 180;
  bool manifold = false, closed = false, checked_self_intersection = false, self_intersecting = false;
  double volume = 0, volume_error = std::nan("");
  Quantiles sharp_all, sharp_resolvable, sharp_straight;
  double hausdorff_to_output = std::nan(""), hausdorff_to_exact = std::nan("");
  double hausdorff_to_output_thick = std::nan(""), hausdorff_to_exact_thick = std::nan("");
  double normal_error = std::nan(""), normal_error_smooth = std::nan("");
  std::string note;
};

double min_angle_degrees(const Point& a, const Point& b, const Point& c)
{
  const Point p[3] = {a, b, c};
  double best = 180;
  for(int i = 0; i < 3; ++i)
  {
    const Vector u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
    const double lu = std::sqrt(u.squared_length()), lv = std::sqrt(v.squared_length());
    if(lu == 0 || lv == 0)
      return 0;
    best = (std::min)(best, std::acos((std::max)(-1.0, (std::min)(1.0, (u * v) / (lu * lv)))) * 180 / pi);
  }
  return best;
}

void measure_soup(Measure& m, const Soup& soup, const Reference& ref, double r, bool check_topology)
{
  m.triangles = soup.triangles.size();
  std::vector<Triangle> triangles;
  triangles.reserve(soup.triangles.size());
  std::size_t small5 = 0, small20 = 0;
  double volume = 0;
  for(const Index_triangle& t : soup.triangles)
  {
    const Point &a = soup.points[t[0]], &b = soup.points[t[1]], &c = soup.points[t[2]];
    triangles.emplace_back(a, b, c);
    if(CGAL::collinear(a, b, c))
      ++m.zero_area;
    const double angle = min_angle_degrees(a, b, c);
    m.min_angle = (std::min)(m.min_angle, angle);
    small5 += angle < 5 ? 1 : 0;
    small20 += angle < 20 ? 1 : 0;
    volume += CGAL::determinant(a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN) / 6;
  }
  m.volume = volume;
  if(!soup.triangles.empty())
  {
    m.under5 = 100.0 * double(small5) / double(soup.triangles.size());
    m.under20 = 100.0 * double(small20) / double(soup.triangles.size());
  }
  if(check_topology)
  {
    m.manifold = PMP::is_polygon_soup_a_polygon_mesh(soup.triangles);
    if(m.manifold)
    {
      Mesh mesh;
      PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
      m.closed = CGAL::is_closed(mesh);
      m.checked_self_intersection = true;
      m.self_intersecting = PMP::does_self_intersect(mesh);
    }
  }
  if(!ref.available || triangles.empty())
    return;
  m.volume_error = (volume - ref.volume) / ref.volume;
  Triangle_tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  // Sharp edges to the output.
  std::vector<double> all, resolvable, straight;
  for(const Sharp_sample& s : ref.sharp_samples)
  {
    const double d = std::sqrt(tree.squared_distance(s.p)) / r;
    all.push_back(d);
    if(!s.knife)
      resolvable.push_back(d);
    if(s.straight)
      straight.push_back(d);
  }
  m.sharp_all = quantiles(all);
  m.sharp_resolvable = quantiles(resolvable);
  m.sharp_straight = quantiles(straight);
  // Exact -> output.
  double h = 0, h_thick = 0;
  for(const Point& p : ref.surface_samples)
  {
    const double d = std::sqrt(tree.squared_distance(p)) / r;
    h = (std::max)(h, d);
    if(d > h_thick && !ref.in_thin_zone(p))
      h_thick = d;
  }
  m.hausdorff_to_output = h;
  m.hausdorff_to_output_thick = h_thick;
  // Output -> exact, and the normals.
  h = h_thick = 0;
  double normal_sum = 0, smooth_sum = 0;
  std::size_t normal_count = 0, smooth_count = 0;
  for(const auto& s : sample_triangles(triangles, r, 16, 2))
  {
    const auto hit = ref.tree->closest_point_and_primitive(s.first);
    const double d = std::sqrt(CGAL::squared_distance(s.first, hit.first)) / r;
    h = (std::max)(h, d);
    if(d > h_thick && !ref.in_thin_zone(s.first))
      h_thick = d;
    const Vector n_out = triangles[s.second].supporting_plane().orthogonal_vector();
    const Vector n_exact = hit.second->supporting_plane().orthogonal_vector();
    const double lo = std::sqrt(n_out.squared_length()), le = std::sqrt(n_exact.squared_length());
    if(!(lo > 0 && le > 0))
      continue;
    const double angle = std::acos((std::max)(-1.0, (std::min)(1.0, (n_out * n_exact) / (lo * le)))) * 180 / pi;
    normal_sum += angle;
    ++normal_count;
    if(ref.distance_to_sharp(hit.first) >= r)
    {
      smooth_sum += angle;
      ++smooth_count;
    }
  }
  m.hausdorff_to_exact = h;
  m.hausdorff_to_exact_thick = h_thick;
  m.normal_error = normal_count ? normal_sum / double(normal_count) : std::nan("");
  m.normal_error_smooth = smooth_count ? smooth_sum / double(smooth_count) : std::nan("");
}

// ------------------------------------------------------------------ the methods

// `sliver` >= 0: that sliver_edge_length (cells) instead of the default
// (0.15 with features, none without).
Soup run_ours(const std::vector<Mesh>& meshes, char op, const BI::Regular_lattice_3& lattice, bool features,
              double& seconds, BI::Marching_cubes_csg_statistics& statistics, double sliver = -1)
{
  Soup soup;
  seconds = 1e30;
  for(int run = 0; run < 3; ++run)
  {
    std::vector<std::array<double, 3>> points;
    std::vector<Index_triangle> triangles;
    BI::Marching_cubes_csg_features f;
    const auto start = std::chrono::steady_clock::now();
    if(sliver >= 0)
      statistics = BI::marching_cubes_csg<CGAL::Sequential_tag>(
          lattice, meshes, expression_of(op), points, triangles,
          BI::parameters::sharp_features(
              features, BI::parameters::sliver_edge_length(sliver, BI::parameters::sharp_feature_output(&f))));
    else
      statistics = BI::marching_cubes_csg<CGAL::Sequential_tag>(
          lattice, meshes, expression_of(op), points, triangles,
          BI::parameters::sharp_features(features, BI::parameters::sharp_feature_output(&f)));
    seconds = (std::min)(seconds, seconds_since(start));
    soup.points.clear();
    for(const auto& p : points)
      soup.points.emplace_back(p[0], p[1], p[2]);
    soup.triangles = std::move(triangles);
    soup.creases = f.crease_edges;
  }
  return soup;
}

// The feature output as a Surface_mesh with its creases and corners, then
// simplified (max_distance > 0) or remeshed (edge_length > 0).
Soup run_post_processed(const std::vector<Mesh>& meshes, char op, const BI::Regular_lattice_3& lattice,
                        double max_distance, double edge_length, double& seconds)
{
  Mesh out;
  auto crease = out.add_property_map<Mesh::Edge_index, bool>("e:crease", false).first;
  auto corner = out.add_property_map<Mesh::Vertex_index, bool>("v:corner", false).first;
  BI::marching_cubes_csg(lattice, meshes, expression_of(op), out,
                         CGAL::parameters::edge_is_constrained_map(crease).vertex_is_constrained_map(corner));
  const auto start = std::chrono::steady_clock::now();
  const auto maps = CGAL::parameters::edge_is_constrained_map(crease).vertex_is_constrained_map(corner);
  if(max_distance > 0)
    BI::simplify_keeping_creases(out, max_distance, maps);
  else
    BI::remesh_keeping_creases(out, edge_length, maps);
  seconds = seconds_since(start);
  out.collect_garbage();
  Soup soup;
  soup.points.assign(out.points().begin(), out.points().end());
  for(auto f : faces(out))
  {
    const auto h = halfedge(f, out);
    soup.triangles.push_back({{std::size_t(source(h, out)), std::size_t(target(h, out)),
                               std::size_t(target(next(h, out), out))}});
  }
  for(auto e : edges(out))
    if(crease[e])
      soup.creases.push_back({{std::size_t(out.vertex(e, 0)), std::size_t(out.vertex(e, 1))}});
  return soup;
}

#ifdef BISO_WITH_OPENVDB
Soup run_openvdb(const std::vector<Mesh>& meshes, char op, double voxel, double& seconds)
{
  openvdb::initialize();
  const auto transform = openvdb::math::Transform::createLinearTransform(voxel);
  std::vector<std::vector<openvdb::Vec3s>> points(2);
  std::vector<std::vector<openvdb::Vec3I>> triangles(2);
  for(int m = 0; m < 2; ++m)
  {
    const Mesh& mesh = meshes[m];
    for(auto v : vertices(mesh))
      points[m].emplace_back(float(mesh.point(v).x()), float(mesh.point(v).y()), float(mesh.point(v).z()));
    for(auto f : faces(mesh))
    {
      const auto h = halfedge(f, mesh);
      triangles[m].emplace_back(std::uint32_t(source(h, mesh)), std::uint32_t(target(h, mesh)),
                                std::uint32_t(target(next(h, mesh), mesh)));
    }
  }
  Soup soup;
  seconds = 1e30;
  for(int run = 0; run < 3; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    auto a = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points[0], triangles[0], 3.0f);
    auto b = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points[1], triangles[1], 3.0f);
    if(op == '|')
      openvdb::tools::csgUnion(*a, *b);
    else if(op == '&')
      openvdb::tools::csgIntersection(*a, *b);
    else
      openvdb::tools::csgDifference(*a, *b);
    std::vector<openvdb::Vec3s> out_points;
    std::vector<openvdb::Vec3I> out_triangles;
    std::vector<openvdb::Vec4I> out_quads;
    openvdb::tools::volumeToMesh(*a, out_points, out_triangles, out_quads, 0.0);
    seconds = (std::min)(seconds, seconds_since(start));
    soup = Soup();
    for(const auto& p : out_points)
      soup.points.emplace_back(p[0], p[1], p[2]);
    // OpenVDB's polygons are inward-facing (clockwise seen from outside).
    for(const auto& t : out_triangles)
      soup.triangles.push_back({{t[2], t[1], t[0]}});
    for(const auto& q : out_quads)
    {
      soup.triangles.push_back({{q[2], q[1], q[0]}});
      soup.triangles.push_back({{q[3], q[2], q[0]}});
    }
  }
  return soup;
}
#endif

void write_soup(const std::string& path, const Soup& soup)
{
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << soup.points.size() << " " << soup.triangles.size() << " 0\n";
  for(const Point& p : soup.points)
    out << p << "\n";
  for(const Index_triangle& t : soup.triangles)
    out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

void write_creases(const std::string& path, const Soup& soup)
{
  std::ofstream out(path);
  out.precision(17);
  for(const auto& e : soup.creases)
    out << "2 " << soup.points[e[0]] << " " << soup.points[e[1]] << "\n";
}

// ------------------------------------------------------------------ report

std::string fixed(double x, int digits = 2)
{
  if(std::isnan(x))
    return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, x);
  return b;
}

std::string general(double x)
{
  if(std::isnan(x))
    return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, "%.2g", x);
  return b;
}

std::string pair_of(const Quantiles& q)
{
  return q.n == 0 ? "-" : fixed(q.p95) + " / " + fixed(q.max);
}

struct Row
{
  std::string case_name;
  std::size_t cells;
  double r;
  std::string exact_note;
  double thin_percent;
  Measure m;
};

void print_tables(const std::vector<Row>& rows)
{
  std::cout << "\n### Accuracy against the exact result (distances in r; sharp edges p95 / max)\n\n"
            << "| case | method | sharp edges, all | resolvable | straight | Hausdorff exact→out / out→exact | "
               "away from thin wedges | mean normal error (°), all / away from creases | volume rel. error |\n"
            << "|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& row : rows)
  {
    const Measure& m = row.m;
    std::cout << "| " << row.case_name << " | " << m.method << " | ";
    if(!row.exact_note.empty())
    {
      std::cout << "no exact result (" << row.exact_note << ") | | | | | | |\n";
      continue;
    }
    std::cout << pair_of(m.sharp_all) << " | " << pair_of(m.sharp_resolvable) << " | " << pair_of(m.sharp_straight)
              << " | " << fixed(m.hausdorff_to_output) << " / " << fixed(m.hausdorff_to_exact) << " | "
              << fixed(m.hausdorff_to_output_thick) << " / " << fixed(m.hausdorff_to_exact_thick) << " | "
              << fixed(m.normal_error, 1) << " / " << fixed(m.normal_error_smooth, 1) << " | "
              << general(m.volume_error) << " |\n";
  }
  std::cout << "\n### Triangles and time\n\n"
            << "| case | cells (r) | method | triangles | zero-area | < 5° | < 20° | smallest angle | closed 2-manifold, "
               "self-intersecting | time (s) | thin result % |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& row : rows)
  {
    const Measure& m = row.m;
    std::string topology = !m.manifold ? "not a 2-manifold" : (m.closed ? "closed" : "open");
    if(m.checked_self_intersection)
      topology += m.self_intersecting ? ", **self-intersecting**" : ", no self-intersection";
    std::cout << "| " << row.case_name << " | " << row.cells << " (" << general(row.r) << ") | " << m.method << " | "
              << m.triangles << " | " << m.zero_area << " | " << fixed(m.under5) << " % | " << fixed(m.under20)
              << " % | " << fixed(m.min_angle, 3) << "° | " << topology << " | " << fixed(m.seconds, 3) << " | "
              << fixed(row.thin_percent, 2) << (m.note.empty() ? "" : " (" + m.note + ")") << " |\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t cells = 128;
  std::string dump;
  std::vector<std::string> wanted;
  bool list = false, post_processing = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--cells" && i + 1 < argc)
      cells = std::size_t(std::stoul(argv[++i]));
    else if(a == "--dump" && i + 1 < argc)
      dump = argv[++i];
    else if(a == "--list")
      list = true;
    else if(a == "--post-processing")
      post_processing = true;
    else if(!a.empty() && a[0] == '-' && a.size() > 1 && a[1] == '-')
    {
      std::cerr << "usage: csg_features_measure [--cells N] [--dump DIR] [--post-processing] [--list] [CASE ...]\n";
      return 2;
    }
    else
      wanted.push_back(a);
  }
  const std::vector<Case> cases = all_cases(BISO_SHARED_DATA_DIR);
  if(list)
  {
    for(const Case& c : cases)
      std::cout << c.name << "\n";
    return 0;
  }
#ifdef CGAL_LINKED_WITH_TBB
  // OpenVDB runs on TBB: one thread, as ours (Sequential_tag).
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
  std::vector<Row> rows;
  for(const Case& c : cases)
  {
    if(!wanted.empty() && std::find(wanted.begin(), wanted.end(), c.name) == wanted.end())
      continue;
    std::vector<Mesh> meshes;
    try
    {
      meshes = c.inputs();
    }
    catch(const std::exception& e)
    {
      std::cerr << c.name << ": cannot read the inputs: " << e.what() << "\n";
      return 1;
    }
    const BI::Regular_lattice_3 lattice =
        BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(meshes[0]) + PMP::bbox(meshes[1]), cells);
    const double r = lattice.spacing();
    const auto start = std::chrono::steady_clock::now();
    Reference ref;
    build_reference(ref, meshes, c.op, r);
    std::cerr << c.name << ": exact result " << (ref.available ? "" : "not available (" + ref.why_not + ") ")
              << "in " << seconds_since(start) << " s, " << ref.sharp.size() << " sharp edges (" << ref.knives.size()
              << " knife edges), " << ref.sharp_samples.size() << " sharp samples\n";
    const auto add = [&](Measure m, const Soup& soup, double thin_percent, bool topology) {
      const auto t0 = std::chrono::steady_clock::now();
      measure_soup(m, soup, ref, r, topology);
      std::cerr << "  " << m.method << ": " << m.triangles << " triangles, measured in " << seconds_since(t0) << " s\n";
      rows.push_back({c.name, cells, r, ref.available ? "" : ref.why_not, thin_percent, m});
      if(!dump.empty())
      {
        std::string file = c.name + "_" + m.method;
        for(char& ch : file)
          if(ch == '|' || ch == '&' || ch == ' ' || ch == '+')
            ch = ch == '|' ? 'U' : (ch == '&' ? 'I' : '_');
        write_soup(dump + "/" + file + ".off", soup);
        if(!soup.creases.empty())
          write_creases(dump + "/" + file + ".polylines.txt", soup);
        if(ref.available)
        {
          std::vector<Triangle> triangles;
          for(const auto& t : soup.triangles)
            triangles.emplace_back(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
          const Triangle_tree tree(triangles.begin(), triangles.end());
          std::ofstream bad(dump + "/" + file + ".far_sharp.xyz");
          for(const Sharp_sample& s : ref.sharp_samples)
          {
            const double d = std::sqrt(tree.squared_distance(s.p)) / r;
            if(d > 0.2)
              bad << s.p << " " << d << " " << (s.knife ? "knife" : (s.straight ? "straight" : "resolvable")) << "\n";
          }
        }
      }
    };
    if(!dump.empty() && ref.available)
    {
      std::string file = c.name;
      for(char& ch : file)
        if(ch == '|' || ch == '&')
          ch = ch == '|' ? 'U' : 'I';
      CGAL::IO::write_polygon_mesh(dump + "/" + file + "_exact.off", ref.mesh, CGAL::parameters::stream_precision(17));
    }
    double plain_seconds = 0;
    for(bool features : {false, true})
    {
      Measure m;
      m.method = features ? "features" : "plain MC";
      BI::Marching_cubes_csg_statistics s;
      const Soup soup = run_ours(meshes, c.op, lattice, features, m.seconds, s);
      const double thin = 100 * s.thin_result_fraction();
      if(features)
      {
        // The features' own cost: against plain MC with the same sliver
        // pass (collapses and flips), which plain MC skips by default.
        double cleaned_seconds = 0;
        BI::Marching_cubes_csg_statistics cleaned_statistics;
        run_ours(meshes, c.op, lattice, false, cleaned_seconds, cleaned_statistics, 0.15);
        char note[160];
        std::snprintf(note, sizeof note, "%.2fx plain, %.2fx plain with the sliver pass", m.seconds / plain_seconds,
                      m.seconds / cleaned_seconds);
        m.note = note;
      }
      else
        plain_seconds = m.seconds;
      add(m, soup, thin, true);
    }
    if(post_processing)
      for(int which = 0; which < 2; ++which)
      {
        Measure m;
        m.method = which == 0 ? "features + simplify 0.1 r" : "features + remesh r";
        try
        {
          const Soup soup = run_post_processed(meshes, c.op, lattice, which == 0 ? 0.1 * r : 0, which == 0 ? 0 : r,
                                               m.seconds);
          m.note = "time: post-processing only";
          add(m, soup, std::nan(""), true);
        }
        catch(const std::exception& e)
        {
          std::cerr << "  " << m.method << " failed: " << e.what() << "\n";
        }
      }
#ifdef BISO_WITH_OPENVDB
    {
      Measure m;
      m.method = "OpenVDB";
      const Soup soup = run_openvdb(meshes, c.op, r, m.seconds);
      add(m, soup, std::nan(""), true);
    }
#endif
  }
  print_tables(rows);
  return 0;
}
