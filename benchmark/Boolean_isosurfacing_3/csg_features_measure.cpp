// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Measures the sharp features of marching_cubes_csg() against the exact
// result (corefinement on Epeck), with and without features:
//   - distance from the exact result's sharp edges (dihedral > 30 degrees)
//     to the output surface, in units of the spacing r (max, p95);
//   - the share of triangles with a minimum angle below 5 degrees;
//   - the extraction time (best of 3).
// usage: csg_features_measure box|fandisk CELLS [OUTPUT_PREFIX]
// Writes PREFIX_features.off and PREFIX_plain.off when a prefix is given.

#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_exact_constructions_kernel::Point_3> Exact_mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

static const double pi = 3.14159265358979323846;

static Mesh make_box(const Point& l, const Point& h)
{
  Mesh m;
  CGAL::make_hexahedron(Point(l.x(), l.y(), l.z()), Point(h.x(), l.y(), l.z()), Point(h.x(), h.y(), l.z()),
                        Point(l.x(), h.y(), l.z()), Point(l.x(), h.y(), h.z()), Point(l.x(), l.y(), h.z()),
                        Point(h.x(), l.y(), h.z()), Point(h.x(), h.y(), h.z()), m);
  PMP::triangulate_faces(m);
  return m;
}

static Mesh moved(const Mesh& mesh, const Point& c, const Vector& axis, double angle, const Vector& t)
{
  const Vector u = axis / std::sqrt(axis.squared_length());
  const double co = std::cos(angle), s = std::sin(angle);
  Mesh copy = mesh;
  for(auto v : vertices(copy))
  {
    const Vector p = copy.point(v) - c;
    copy.point(v) = c + p * co + CGAL::cross_product(u, p) * s + u * (u * p) * (1 - co) + t;
  }
  return copy;
}

struct Measure
{
  double max = 0, p95 = 0, seconds = 0, small_angles = 0, min_angle = 180;
  std::size_t triangles = 0, features = 0, creases = 0, corners = 0, plain = 0, folded = 0, collapsed = 0;
  bool closed = false, self_intersecting = true;
  double volume = 0;
};

static double min_angle_degrees(const Point& a, const Point& b, const Point& c)
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

static Measure measure(const std::vector<Mesh>& meshes, const std::string& expression, const BI::Regular_lattice_3& lattice,
                       const std::vector<Point>& sharp_samples, bool features, const std::string& output)
{
  Measure m;
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  BI::Marching_cubes_csg_statistics s;
  m.seconds = 1e30;
  for(int run = 0; run < 3; ++run)
  {
    points.clear();
    triangles.clear();
    const auto start = std::chrono::steady_clock::now();
    s = BI::marching_cubes_csg(lattice, meshes, BI::Boolean_expression::parse(expression), points, triangles,
                               BI::parameters::sharp_features(features));
    m.seconds = (std::min)(m.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  m.features = s.feature_vertices;
  m.creases = s.crease_edges;
  m.corners = s.corner_vertices;
  m.plain = s.plain_feature_polygons;
  m.folded = s.folded_feature_polygons;
  m.collapsed = s.collapsed_edges;
  Mesh out;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, out);
  m.closed = CGAL::is_closed(out);
  m.self_intersecting = PMP::does_self_intersect(out);
  m.volume = PMP::volume(out);
  m.triangles = triangles.size();
  std::size_t small = 0;
  for(const auto& t : triangles)
  {
    const double a = min_angle_degrees(points[t[0]], points[t[1]], points[t[2]]);
    m.min_angle = (std::min)(m.min_angle, a);
    small += a < 5 ? 1 : 0;
  }
  m.small_angles = 100.0 * double(small) / double(triangles.size());
  Tree tree(faces(out).first, faces(out).second, out);
  tree.accelerate_distance_queries();
  std::vector<double> d;
  for(const Point& p : sharp_samples)
    d.push_back(std::sqrt(tree.squared_distance(p)) / lattice.spacing());
  std::sort(d.begin(), d.end());
  m.max = d.back();
  m.p95 = d[std::size_t(0.95 * double(d.size() - 1))];
  if(!output.empty())
    CGAL::IO::write_polygon_mesh(output, out, CGAL::parameters::stream_precision(17));
  return m;
}

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: csg_features_measure box|fandisk CELLS [OUTPUT_PREFIX]\n";
    return 2;
  }
  const std::string which = argv[1];
  const std::size_t cells = std::size_t(std::stoul(argv[2]));
  const std::string prefix = argc > 3 ? argv[3] : "";
  std::vector<Mesh> meshes;
  if(which == "box")
  {
    meshes.push_back(make_box(Point(0, 0, 0), Point(1, 1, 1)));
    meshes.push_back(make_box(Point(0.5137, 0.4419, 0.6271), Point(1.7, 1.6, 1.8)));
  }
  else
  {
    Mesh f;
    if(!CGAL::IO::read_polygon_mesh(std::string(BISO_SHARED_DATA_DIR) + "/meshes/fandisk.off", f))
    {
      std::cerr << "cannot read fandisk.off\n";
      return 1;
    }
    const CGAL::Bbox_3 b = PMP::bbox(f);
    const double size = (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
    const Point c((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2, (b.zmin() + b.zmax()) / 2);
    meshes.push_back(f);
    meshes.push_back(moved(f, c, Vector(1, 2, 3), 10 * pi / 180, Vector(0.137 * size, 0.091 * size, 0.063 * size)));
  }
  // The exact result and its sharp edges.
  Exact_mesh ea, eb, eo;
  CGAL::copy_face_graph(meshes[0], ea);
  CGAL::copy_face_graph(meshes[1], eb);
  if(!PMP::corefine_and_compute_difference(ea, eb, eo))
  {
    std::cerr << "corefinement failed\n";
    return 1;
  }
  Mesh exact;
  CGAL::copy_face_graph(eo, exact);
  const BI::Regular_lattice_3 lattice =
      BI::Regular_lattice_3::enclosing_with_cells(PMP::bbox(meshes[0]) + PMP::bbox(meshes[1]), cells);
  const double r = lattice.spacing();
  std::vector<Point> samples;
  std::size_t sharp = 0;
  for(auto e : edges(exact))
  {
    const auto h = halfedge(e, exact);
    const Vector n1 = PMP::compute_face_normal(face(h, exact), exact);
    const Vector n2 = PMP::compute_face_normal(face(opposite(h, exact), exact), exact);
    if(!(n1 * n2 < std::cos(30 * pi / 180)))
      continue;
    ++sharp;
    const Point a = exact.point(source(h, exact)), b = exact.point(target(h, exact));
    const int n = (std::max)(1, int(std::ceil(std::sqrt(CGAL::squared_distance(a, b)) / (r / 8))));
    for(int i = 0; i <= n; ++i)
      samples.push_back(a + (b - a) * (double(i) / n));
  }
  std::cout << which << " minus moved copy, " << cells << " cells, r = " << r << ", exact volume "
            << PMP::volume(exact) << ", " << sharp << " sharp edges, " << samples.size() << " samples\n";
  for(bool features : {false, true})
  {
    const Measure m = measure(meshes, "A & !B", lattice, samples, features,
                              prefix.empty() ? "" : prefix + (features ? "_features.off" : "_plain.off"));
    std::cout << (features ? "features" : "plain   ") << ": sharp edges to output max " << m.max << " r, p95 " << m.p95
              << " r; triangles " << m.triangles << ", min angle < 5 deg " << m.small_angles << " %, min angle "
              << m.min_angle << " deg; time " << m.seconds << " s; volume " << m.volume << "; closed " << m.closed
              << ", self-intersecting " << m.self_intersecting << "; feature vertices " << m.features << ", creases "
              << m.creases << ", corners " << m.corners << ", plain feature polygons " << m.plain << " (folded " << m.folded << "), collapsed edges " << m.collapsed << "\n";
  }
  return 0;
}
