// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Point samples made in code from closed meshes, for the contouring tests and
// benchmark (issue 18), and the measures of a reconstruction:
//  - sample_mesh: area-uniform random samples with the exact face normals,
//    optionally with Gaussian noise of deviation sigma (in sample spacings);
//  - simulate_range_scans: orthographic range scans from several directions,
//    merged, without normals: each scan keeps the first hit of every ray of a
//    regular grid whose incidence is below 75 degrees (occlusion and grazing
//    leave gaps), drops a random band of rows (a scanner drop-out), and adds
//    Gaussian noise along the ray;
//  - measure: closed, non-manifold vertices, components, Euler
//    characteristic, border cycles, and the symmetric Hausdorff distance to
//    the source mesh in percent of its bounding-box diagonal.

#ifndef BISO_TEST_POINT_SAMPLES_H
#define BISO_TEST_POINT_SAMPLES_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/bounding_box.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace biso_samples {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;

struct Samples
{
  std::vector<Point_3> points;
  std::vector<Vector_3> normals; // empty for scans
  double spacing = 0;            // nominal: sqrt(area / n), or the scan grid step
};

inline double gaussian(CGAL::Random& random)
{
  const double u1 = random.get_double(1e-300, 1), u2 = random.get_double();
  return std::sqrt(-2 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

inline double bounding_diagonal(const Mesh& mesh)
{
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

/// n area-uniform random samples of `mesh`, with its face normals; noise of
/// deviation `sigma` sample spacings in a random direction.
inline Samples sample_mesh(const Mesh& mesh, std::size_t n, unsigned seed, double sigma = 0)
{
  std::vector<std::array<Point_3, 3>> faces;
  std::vector<double> cumulative;
  double total = 0;
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    std::array<Point_3, 3> t{{mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                              mesh.point(mesh.target(mesh.next(h)))}};
    total += std::sqrt(CGAL::squared_area(t[0], t[1], t[2]));
    faces.push_back(t);
    cumulative.push_back(total);
  }
  CGAL::Random random(seed);
  Samples s;
  s.spacing = std::sqrt(total / double(n));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double u = random.get_double(0, total);
    const std::size_t f = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    const auto& t = faces[(std::min)(f, faces.size() - 1)];
    double a = random.get_double(), b = random.get_double();
    if(a + b > 1)
    {
      a = 1 - a;
      b = 1 - b;
    }
    Point_3 p = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
    if(sigma > 0)
    {
      const double gx = gaussian(random), gy = gaussian(random), gz = gaussian(random);
      p = p + sigma * s.spacing * Vector_3(gx, gy, gz);
    }
    const Vector_3 normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    s.points.push_back(p);
    s.normals.push_back(normal / std::sqrt(normal.squared_length()));
  }
  return s;
}

/// `views` orthographic scans of `mesh` from directions spread over the
/// sphere (a Fibonacci lattice, turned by `seed`), each a grid of
/// `rays` x `rays` rays over the bounding sphere; noise of deviation `sigma`
/// grid steps along the ray.  No normals.
inline Samples simulate_range_scans(const Mesh& mesh, int views, int rays, double sigma, unsigned seed)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  const Point_3 centre = CGAL::midpoint(box.min(), box.max());
  const double radius = 0.5 * std::sqrt(CGAL::squared_distance(box.min(), box.max()));
  const double step = 2 * radius / rays;
  CGAL::Random random(seed);
  const double turn = random.get_double(0, 6.283185307179586);
  Samples s;
  s.spacing = step;
  for(int v = 0; v < views; ++v)
  {
    // Fibonacci direction v of `views`.
    const double z = 1 - (2 * v + 1) / double(views);
    const double phi = turn + v * 2.399963229728653;
    const Vector_3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    const Vector_3 helper = std::abs(d.z()) < 0.9 ? Vector_3(0, 0, 1) : Vector_3(1, 0, 0);
    Vector_3 e1 = CGAL::cross_product(d, helper);
    e1 = e1 / std::sqrt(e1.squared_length());
    const Vector_3 e2 = CGAL::cross_product(d, e1);
    // A drop-out band of 4 % of the rows.
    const int band = int(random.get_double(0, 0.96) * rays), band_width = (std::max)(1, rays / 25);
    for(int i = 0; i < rays; ++i)
    {
      if(i >= band && i < band + band_width)
        continue;
      for(int j = 0; j < rays; ++j)
      {
        const double a = -radius + (i + 0.5) * step, b = -radius + (j + 0.5) * step;
        const Point_3 origin = centre + 3 * radius * d + a * e1 + b * e2;
        const auto hit = tree.first_intersection(K::Ray_3(origin, -d));
        if(!hit)
          continue;
        const Point_3* p = boost::get<Point_3>(&hit->first);
        if(p == nullptr)
          continue;
        const auto h = mesh.halfedge(hit->second);
        Vector_3 n = CGAL::cross_product(mesh.point(mesh.target(h)) - mesh.point(mesh.source(h)),
                                         mesh.point(mesh.target(mesh.next(h))) - mesh.point(mesh.source(h)));
        n = n / std::sqrt(n.squared_length());
        if(std::abs(n * d) < 0.2588190451) // incidence above 75 degrees
          continue;
        s.points.push_back(*p + sigma * step * gaussian(random) * d);
      }
    }
  }
  return s;
}

struct Measure
{
  bool closed = false;
  std::size_t non_manifold_vertices = 0; // duplicated by orient_polygon_soup
  std::size_t components = 0, border_cycles = 0, faces = 0;
  long euler = 0;
  double hausdorff_percent = -1; // of the source's bounding-box diagonal
  double out_to_source_percent = -1, source_to_out_percent = -1;
  Mesh mesh;
  // Genus of a closed surface with `components` pieces: (2 c - chi) / 2.
  long genus() const { return (2 * long(components) - euler - long(border_cycles)) / 2; }
};

/// The soup as a mesh and its measures; `source` (may be null) for the Hausdorff distance.
inline Measure measure(std::vector<Point_3> points, std::vector<std::array<std::size_t, 3>> triangles,
                       const Mesh* source)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Measure m;
  const std::size_t before = points.size();
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    PMP::orient_polygon_soup(points, triangles);
  m.non_manifold_vertices = points.size() - before;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, m.mesh);
  m.faces = m.mesh.number_of_faces();
  m.closed = CGAL::is_closed(m.mesh);
  Mesh copy = m.mesh;
  auto component = copy.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  m.components = PMP::connected_components(copy, component);
  m.euler = long(m.mesh.number_of_vertices()) - long(m.mesh.number_of_edges()) + long(m.mesh.number_of_faces());
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(m.mesh, std::back_inserter(cycles));
  m.border_cycles = cycles.size();
  if(source != nullptr && !m.mesh.is_empty())
  {
    const double diagonal = bounding_diagonal(*source);
    m.out_to_source_percent =
      100 / diagonal * PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(m.mesh, *source, 1e-4 * diagonal);
    m.source_to_out_percent =
      100 / diagonal * PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(*source, m.mesh, 1e-4 * diagonal);
    m.hausdorff_percent = (std::max)(m.out_to_source_percent, m.source_to_out_percent);
  }
  return m;
}

} // namespace biso_samples

#endif // BISO_TEST_POINT_SAMPLES_H
