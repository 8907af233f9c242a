// Tests of smooth_with_creases() (hierarchical lambda|mu smoothing, Taubin &
// Sibley) against plain_lambda_mu_smoothing() and Laplacian smoothing:
// on a noisy cube, the hierarchy keeps corners exact, creases straight and
// dihedral angles at 90 degrees where plain lambda|mu rounds them; on a noisy
// sphere, lambda|mu removes noise without the shrinkage of Laplacian
// smoothing.  Every measured number is printed so that it can be quoted.

#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Edge_index Edge;
typedef Mesh::Face_index Face;

const double pi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// The noisy cube [-1, 1]^3, each face an n x n grid of quads (or of triangles,
// each quad split along one diagonal).  A vertex is a lattice point
// (i, j, k) in [0, n]^3 with at least one coordinate 0 or n; the number of
// such "extreme" coordinates says what it is: 3 a cube corner, 2 a point of
// a cube edge (a crease vertex), 1 a point inside a cube face.
//
// Noise, uniform, amplitude a = 0.2 h (h = 2 / n, the grid spacing), from a
// std::mt19937 with a fixed seed:
//   - corners: none (they stay exact);
//   - crease vertices: +-a along their cube edge, and +-a/4 along each of the
//     two other axes (small noise off the edge line, so that its decrease
//     can be measured);
//   - face vertices: +-a along each of the three axes (normal and in-plane).
// Crease edges are flagged by construction: both endpoints lie on the same
// cube edge (they share two extreme coordinates).
// The flags are named properties of the mesh, so a copy of the mesh carries
// its own.
Mesh::Property_map<Edge, bool> crease_flags(const Mesh& mesh)
{
  return mesh.property_map<Edge, bool>("e:is_crease").first;
}

Mesh::Property_map<Vertex, bool> corner_flags(const Mesh& mesh)
{
  return mesh.property_map<Vertex, bool>("v:is_corner").first;
}

struct Noisy_cube
{
  Mesh mesh;
  int n = 0;
  double h = 0;
  std::vector<std::array<int, 3>> lattice; // by vertex index

  // Axis -> 0 (at -1), 1 (at +1) or -1 (not extreme).
  std::array<int, 3> extremes(Vertex v) const
  {
    std::array<int, 3> e;
    for(int a = 0; a < 3; ++a)
      e[a] = lattice[v][a] == 0 ? 0 : (lattice[v][a] == n ? 1 : -1);
    return e;
  }

  int number_of_extremes(Vertex v) const
  {
    const std::array<int, 3> e = extremes(v);
    return int(e[0] >= 0) + int(e[1] >= 0) + int(e[2] >= 0);
  }
};

Noisy_cube make_noisy_cube(int n, bool triangles, unsigned seed = 20260417u)
{
  Noisy_cube cube;
  cube.n = n;
  cube.h = 2.0 / n;
  const double amplitude = 0.2 * cube.h;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);

  std::map<std::array<int, 3>, Vertex> vertex_of;
  auto vertex_at = [&](std::array<int, 3> ijk) {
    const auto found = vertex_of.find(ijk);
    if(found != vertex_of.end())
      return found->second;
    std::array<double, 3> p;
    int extreme_count = 0;
    for(int a = 0; a < 3; ++a)
    {
      p[a] = -1.0 + cube.h * ijk[a];
      extreme_count += (ijk[a] == 0 || ijk[a] == n) ? 1 : 0;
    }
    for(int a = 0; a < 3; ++a)
    {
      const bool extreme = ijk[a] == 0 || ijk[a] == n;
      if(extreme_count == 2)
        p[a] += uniform(random) * (extreme ? amplitude / 4 : amplitude);
      else if(extreme_count == 1)
        p[a] += uniform(random) * amplitude;
    }
    const Vertex v = cube.mesh.add_vertex(Point(p[0], p[1], p[2]));
    vertex_of.emplace(ijk, v);
    if(cube.lattice.size() <= std::size_t(v))
      cube.lattice.resize(std::size_t(v) + 1);
    cube.lattice[v] = ijk;
    return v;
  };

  for(int a = 0; a < 3; ++a)
    for(int side = 0; side <= n; side += n)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for(int u = 0; u < n; ++u)
        for(int w = 0; w < n; ++w)
        {
          std::array<Vertex, 4> quad;
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for(int k = 0; k < 4; ++k)
          {
            std::array<int, 3> ijk;
            ijk[a] = side;
            ijk[b] = u + du[k];
            ijk[c] = w + dw[k];
            quad[k] = vertex_at(ijk);
          }
          // Counterclockwise in (b, c) has normal e_b x e_c = +e_a: outward
          // on the side at +1, reversed on the side at -1.
          if(side == 0)
            std::reverse(quad.begin(), quad.end());
          if(triangles)
          {
            cube.mesh.add_face(quad[0], quad[1], quad[2]);
            cube.mesh.add_face(quad[0], quad[2], quad[3]);
          }
          else
            cube.mesh.add_face(quad);
        }
    }

  auto is_crease = cube.mesh.add_property_map<Edge, bool>("e:is_crease", false).first;
  auto is_corner = cube.mesh.add_property_map<Vertex, bool>("v:is_corner", false).first;
  for(const Vertex v : cube.mesh.vertices())
    is_corner[v] = cube.number_of_extremes(v) == 3;
  for(const Edge e : cube.mesh.edges())
  {
    const auto p = cube.extremes(cube.mesh.vertex(e, 0)), q = cube.extremes(cube.mesh.vertex(e, 1));
    int shared = 0;
    for(int a = 0; a < 3; ++a)
      shared += (p[a] >= 0 && p[a] == q[a]) ? 1 : 0;
    is_crease[e] = shared >= 2;
  }
  return cube;
}

struct Statistics
{
  double mean = 0, max = 0;
};

struct Cube_measures
{
  Statistics crease_distance; // of crease vertices to their cube edge line
  Statistics plane_distance;  // of face vertices to their cube face plane
  Statistics dihedral;        // interior dihedral angle across crease edges, degrees (max = largest)
  double min_dihedral = 0;
  double volume = 0;
};

double volume_of(const Mesh& mesh)
{
  Mesh triangulated = mesh;
  PMP::triangulate_faces(triangulated);
  return PMP::volume(triangulated);
}

// `mesh` is `cube.mesh` or a smoothed copy of it (same indices).
Cube_measures measure(const Noisy_cube& cube, const Mesh& mesh)
{
  const auto is_crease = crease_flags(mesh);
  Cube_measures m;
  std::size_t crease_count = 0, face_count = 0;
  for(const Vertex v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    const double c[3] = {p.x(), p.y(), p.z()};
    const std::array<int, 3> e = cube.extremes(v);
    const int extreme_count = cube.number_of_extremes(v);
    if(extreme_count == 2)
    {
      double sq = 0;
      for(int a = 0; a < 3; ++a)
        if(e[a] >= 0)
          sq += CGAL::square(c[a] - (e[a] == 0 ? -1.0 : 1.0));
      const double d = std::sqrt(sq);
      m.crease_distance.mean += d;
      m.crease_distance.max = std::max(m.crease_distance.max, d);
      ++crease_count;
    }
    else if(extreme_count == 1)
    {
      for(int a = 0; a < 3; ++a)
        if(e[a] >= 0)
        {
          const double d = std::abs(c[a] - (e[a] == 0 ? -1.0 : 1.0));
          m.plane_distance.mean += d;
          m.plane_distance.max = std::max(m.plane_distance.max, d);
        }
      ++face_count;
    }
  }
  m.crease_distance.mean /= double(crease_count);
  m.plane_distance.mean /= double(face_count);

  std::size_t edge_count = 0;
  m.min_dihedral = 180;
  for(const Edge e : mesh.edges())
  {
    if(!is_crease[e])
      continue;
    const Vector n0 = PMP::compute_face_normal(mesh.face(mesh.halfedge(e, 0)), mesh);
    const Vector n1 = PMP::compute_face_normal(mesh.face(mesh.halfedge(e, 1)), mesh);
    const double cosine = std::max(-1.0, std::min(1.0, n0 * n1));
    const double dihedral = 180.0 - std::acos(cosine) * 180.0 / pi;
    m.dihedral.mean += dihedral;
    m.dihedral.max = std::max(m.dihedral.max, dihedral);
    m.min_dihedral = std::min(m.min_dihedral, dihedral);
    ++edge_count;
  }
  m.dihedral.mean /= double(edge_count);
  m.volume = volume_of(mesh);
  return m;
}

void print(const char* name, const Cube_measures& m, double h, double reference_volume)
{
  std::cout << "  " << name << ": crease distance mean " << m.crease_distance.mean / h << " h, max "
            << m.crease_distance.max / h << " h; face-plane distance mean " << m.plane_distance.mean / h
            << " h, max " << m.plane_distance.max / h << " h; dihedral mean " << m.dihedral.mean << " deg (range "
            << m.min_dihedral << " .. " << m.dihedral.max << "); volume " << m.volume << " (change "
            << 100.0 * (m.volume - reference_volume) / reference_volume << " %)" << std::endl;
}

std::vector<Point> points_of(const Mesh& mesh)
{
  std::vector<Point> points;
  for(const Vertex v : mesh.vertices())
    points.push_back(mesh.point(v));
  return points;
}

// ---------------------------------------------------------------------------
// The cube: the hierarchy against plain lambda|mu.

void check_cube(bool triangles)
{
  const int n = 16;
  const Noisy_cube noisy = make_noisy_cube(n, triangles);
  const double h = noisy.h;
  const Cube_measures before = measure(noisy, noisy.mesh);

  Mesh hierarchical = noisy.mesh;
  const auto start = std::chrono::steady_clock::now();
  BI::smooth_with_creases(hierarchical, CGAL::parameters::edge_is_constrained_map(crease_flags(hierarchical))
                                            .vertex_is_constrained_map(corner_flags(hierarchical)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Cube_measures after = measure(noisy, hierarchical);

  Mesh plain = noisy.mesh;
  BI::plain_lambda_mu_smoothing(plain);
  const Cube_measures rounded = measure(noisy, plain);

  std::cout << "cube [-1,1]^3, " << n << "x" << n << (triangles ? " triangle pairs" : " quads") << " per face, "
            << noisy.mesh.number_of_vertices() << " vertices, h = " << h
            << ", lambda|mu defaults (10 iterations); hierarchical smoothing took " << seconds * 1e3 << " ms"
            << std::endl;
  print("noisy input ", before, h, before.volume);
  print("hierarchical", after, h, before.volume);
  print("plain       ", rounded, h, before.volume);

  // Corners do not move at all.
  std::size_t corners = 0;
  for(const Vertex v : hierarchical.vertices())
    if(noisy.number_of_extremes(v) == 3)
    {
      EXPECT_EQ(hierarchical.point(v), noisy.mesh.point(v));
      ++corners;
    }
  EXPECT_EQ(corners, 8u);

  // Crease vertices stay near (and come closer to) their cube edge.
  EXPECT_LT(after.crease_distance.mean, 0.6 * before.crease_distance.mean);
  EXPECT_LT(after.crease_distance.max, before.crease_distance.max);
  EXPECT_LT(after.crease_distance.max, 0.05 * h);
  // Face vertices come closer to their face plane.
  EXPECT_LT(after.plane_distance.mean, 0.5 * before.plane_distance.mean);
  EXPECT_LT(after.plane_distance.max, before.plane_distance.max);
  // The volume is kept.
  EXPECT_LT(std::abs(after.volume - before.volume) / before.volume, 0.005);
  // The creases stay sharp.
  EXPECT_NEAR(after.dihedral.mean, 90.0, 3.0);

  // Plain lambda|mu rounds the creases: crease vertices leave the edge
  // lines, and the dihedral angles open up.
  EXPECT_GT(rounded.crease_distance.mean, 5.0 * after.crease_distance.mean);
  EXPECT_GT(rounded.crease_distance.mean, before.crease_distance.mean);
  EXPECT_GT(rounded.dihedral.mean, after.dihedral.mean + 10.0);
}

TEST(CreasePreservingSmoothing, CubeQuadsKeepsCreasesWherePlainLambdaMuRoundsThem) { check_cube(false); }

TEST(CreasePreservingSmoothing, CubeTrianglesKeepsCreasesWherePlainLambdaMuRoundsThem) { check_cube(true); }

// The crease network found by CGAL's detect_sharp_edges, and the corners
// found from it (crease degree 3), give the same result as the flags set by
// construction: the cube is smoothed without any user-supplied flag.
TEST(CreasePreservingSmoothing, DetectedCreasesAndDefaultCornersMatchConstruction)
{
  Noisy_cube cube = make_noisy_cube(16, false);
  auto detected = cube.mesh.add_property_map<Edge, bool>("e:detected", false).first;
  PMP::detect_sharp_edges(cube.mesh, 60.0, detected);
  std::size_t count = 0, mismatches = 0;
  for(const Edge e : cube.mesh.edges())
  {
    count += detected[e] ? 1 : 0;
    mismatches += detected[e] != crease_flags(cube.mesh)[e] ? 1 : 0;
  }
  std::cout << "detect_sharp_edges(60 deg) on the noisy cube: " << count << " edges (12 x 16 = 192 expected), "
            << mismatches << " differ from the construction" << std::endl;
  ASSERT_EQ(mismatches, 0u);

  Mesh by_construction = cube.mesh;
  BI::smooth_with_creases(by_construction, CGAL::parameters::edge_is_constrained_map(crease_flags(by_construction))
                                               .vertex_is_constrained_map(corner_flags(by_construction)));
  BI::smooth_with_creases(cube.mesh, BI::taubin_default_lambda, BI::taubin_default_mu,
                          CGAL::parameters::edge_is_constrained_map(detected));
  EXPECT_EQ(points_of(cube.mesh), points_of(by_construction));
}

// Any FaceGraph: a Polyhedron_3 (no internal indices, edge descriptors of
// another kind) with dynamic property maps gives the Surface_mesh result.
TEST(CreasePreservingSmoothing, PolyhedronGivesTheSurfaceMeshResult)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor Polyhedron_vertex;
  Noisy_cube cube = make_noisy_cube(8, false);
  Polyhedron polyhedron;
  std::vector<std::pair<Vertex, Polyhedron_vertex>> vertex_to_vertex;
  CGAL::copy_face_graph(cube.mesh, polyhedron,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(vertex_to_vertex)));
  auto original = get(CGAL::dynamic_vertex_property_t<Vertex>(), polyhedron);
  for(const auto& pair : vertex_to_vertex)
    put(original, pair.second, pair.first);

  auto is_crease = get(CGAL::dynamic_edge_property_t<bool>(), polyhedron);
  for(const auto e : edges(polyhedron))
  {
    const auto h = cube.mesh.halfedge(get(original, source(e, polyhedron)), get(original, target(e, polyhedron)));
    ASSERT_TRUE(h.is_valid());
    put(is_crease, e, bool(crease_flags(cube.mesh)[cube.mesh.edge(h)]));
  }
  BI::smooth_with_creases(polyhedron, CGAL::parameters::edge_is_constrained_map(is_crease).number_of_iterations(5));
  BI::smooth_with_creases(cube.mesh,
                          CGAL::parameters::edge_is_constrained_map(crease_flags(cube.mesh)).number_of_iterations(5));

  // The neighbours are summed in another order: equal up to rounding.
  double difference = 0;
  for(const auto& pair : vertex_to_vertex)
    difference = std::max(difference, std::sqrt(CGAL::squared_distance(cube.mesh.point(pair.first), pair.second->point())));
  std::cout << "Polyhedron_3 vs Surface_mesh: max position difference " << difference << std::endl;
  EXPECT_LT(difference, 1e-12);
}

// Jacobi steps: the result does not depend on the order of the vertices.
// The same cube rebuilt with its vertices inserted in a shuffled order gives
// the same points (a Gauss-Seidel sweep, updating in place, would differ by
// a fraction of the noise).
TEST(CreasePreservingSmoothing, ResultDoesNotDependOnVertexOrder)
{
  const Noisy_cube cube = make_noisy_cube(8, true);
  const std::size_t count = cube.mesh.number_of_vertices();
  std::vector<std::size_t> order(count);
  for(std::size_t i = 0; i < count; ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(3u));

  Mesh shuffled;
  std::vector<Vertex> new_vertex(count);
  for(const std::size_t old_index : order)
    new_vertex[old_index] = shuffled.add_vertex(cube.mesh.point(Vertex(Mesh::size_type(old_index))));
  for(const Face f : cube.mesh.faces())
  {
    std::vector<Vertex> polygon;
    for(const Vertex v : CGAL::vertices_around_face(cube.mesh.halfedge(f), cube.mesh))
      polygon.push_back(new_vertex[v]);
    shuffled.add_face(polygon);
  }
  Mesh original = cube.mesh;
  BI::smooth_with_creases(original);
  BI::smooth_with_creases(shuffled);

  double difference = 0;
  for(std::size_t i = 0; i < count; ++i)
    difference = std::max(difference, std::sqrt(CGAL::squared_distance(original.point(Vertex(Mesh::size_type(i))),
                                                                       shuffled.point(new_vertex[i]))));
  std::cout << "shuffled vertex order: max position difference " << difference << std::endl;
  EXPECT_LT(difference, 1e-12);
}

// An open surface: its border is a crease.  A noisy square patch whose border
// vertices lie exactly on the square's sides (noise along the side only):
// with the 4 patch corners marked, the border stays exactly on the sides,
// where plain lambda|mu pulls it inward.
TEST(CreasePreservingSmoothing, OpenPatchBorderIsACrease)
{
  const int n = 12;
  const double h = 1.0 / n, amplitude = 0.2 * h;
  std::mt19937 random(7u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Mesh mesh;
  std::vector<Vertex> grid;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const bool border_i = i == 0 || i == n, border_j = j == 0 || j == n;
      double x = i * h, y = j * h, z = 0;
      if(!border_i && !border_j)
      {
        x += uniform(random) * amplitude;
        y += uniform(random) * amplitude;
        z += uniform(random) * amplitude;
      }
      else if(!border_i)
        x += uniform(random) * amplitude; // along a side y = 0 or y = 1
      else if(!border_j)
        y += uniform(random) * amplitude; // along a side x = 0 or x = 1
      grid.push_back(mesh.add_vertex(Point(x, y, z)));
    }
  auto at = [&](int i, int j) { return grid[std::size_t(j * (n + 1) + i)]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  auto is_corner = mesh.add_property_map<Vertex, bool>("v:is_corner", false).first;
  for(const Vertex v : {at(0, 0), at(n, 0), at(n, n), at(0, n)})
    is_corner[v] = true;

  auto border_offset = [&](const Mesh& m) { // largest distance of a border vertex to its side, and mean |z|
    double offset = 0, z = 0;
    for(int k = 0; k <= n; ++k)
      for(const Vertex v : {at(k, 0), at(k, n), at(0, k), at(n, k)})
      {
        const Point& p = m.point(v);
        const double side = (v == at(k, 0)) ? std::abs(p.y()) : (v == at(k, n)) ? std::abs(p.y() - 1)
                                                              : (v == at(0, k)) ? std::abs(p.x())
                                                                                : std::abs(p.x() - 1);
        offset = std::max(offset, side);
      }
    for(const Vertex v : m.vertices())
      z += std::abs(m.point(v).z());
    return std::make_pair(offset, z / double(m.number_of_vertices()));
  };

  Mesh hierarchical = mesh, plain = mesh;
  BI::smooth_with_creases(hierarchical, CGAL::parameters::vertex_is_constrained_map(corner_flags(hierarchical)));
  BI::plain_lambda_mu_smoothing(plain);
  const auto before = border_offset(mesh), after = border_offset(hierarchical), rounded = border_offset(plain);
  std::cout << "open " << n << "x" << n << " patch: border offset from its side (in h) hierarchical "
            << after.first / h << ", plain " << rounded.first / h << "; mean |z| (in h) noisy " << before.second / h
            << ", hierarchical " << after.second / h << std::endl;
  EXPECT_EQ(after.first, 0.0);
  EXPECT_GT(rounded.first, 0.1 * h);
  EXPECT_LT(after.second, 0.5 * before.second);
  for(const Vertex v : {at(0, 0), at(n, 0), at(n, n), at(0, n)})
    EXPECT_EQ(hierarchical.point(v), mesh.point(v));
}

// ---------------------------------------------------------------------------
// The sphere: no creases; lambda|mu against Laplacian smoothing.

struct Sphere_measures
{
  double rms_radial_error = 0, volume = 0;
};

Sphere_measures measure_sphere(const Mesh& mesh)
{
  Sphere_measures m;
  for(const Vertex v : mesh.vertices())
    m.rms_radial_error += CGAL::square(std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length()) - 1.0);
  m.rms_radial_error = std::sqrt(m.rms_radial_error / double(mesh.number_of_vertices()));
  m.volume = PMP::volume(mesh);
  return m;
}

TEST(CreasePreservingSmoothing, SphereLambdaMuDenoisesWithoutTheShrinkageOfLaplacian)
{
  Mesh noisy;
  BI::make_icosphere(noisy, Point(0, 0, 0), 1.0, 4);
  double mean_edge = 0;
  for(const Edge e : noisy.edges())
    mean_edge += std::sqrt(CGAL::squared_distance(noisy.point(noisy.vertex(e, 0)), noisy.point(noisy.vertex(e, 1))));
  mean_edge /= double(noisy.number_of_edges());
  std::mt19937 random(11u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for(const Vertex v : noisy.vertices())
  {
    const Vector radial = noisy.point(v) - CGAL::ORIGIN;
    noisy.point(v) = CGAL::ORIGIN + radial * (1.0 + 0.2 * mean_edge * uniform(random));
  }
  const Sphere_measures before = measure_sphere(noisy);

  Mesh lambda_mu = noisy;
  BI::smooth_with_creases(lambda_mu);
  const Sphere_measures after = measure_sphere(lambda_mu);

  // Without creases, on a closed surface, the hierarchy has one level.
  Mesh plain = noisy;
  BI::plain_lambda_mu_smoothing(plain);
  EXPECT_EQ(points_of(plain), points_of(lambda_mu));

  // Laplacian smoothing: the same 10 lambda steps, without the mu steps
  // (mu = 0 makes a mu step the identity; the public functions refuse it).
  Mesh laplacian = noisy;
  BI::internal::run_lambda_mu(
      laplacian, BI::taubin_default_lambda, 0.0, BI::taubin_default_number_of_iterations,
      CGAL::parameters::default_values(), get(CGAL::vertex_index, laplacian),
      [](Vertex) { return BI::internal::Vertex_role::surface; }, [](Edge) { return false; });
  const Sphere_measures shrunk = measure_sphere(laplacian);

  const double sphere_volume = 4.0 / 3.0 * pi;
  auto change = [&](double v) { return (v - before.volume) / before.volume; };
  std::cout << "icosphere (" << noisy.number_of_vertices() << " vertices, mean edge " << mean_edge
            << "), radial noise +-0.2 edge: RMS radial error noisy " << before.rms_radial_error << ", lambda|mu "
            << after.rms_radial_error << ", Laplacian " << shrunk.rms_radial_error << "; volume noisy "
            << before.volume << " (exact sphere " << sphere_volume << "), change lambda|mu "
            << 100.0 * change(after.volume) << " %, Laplacian " << 100.0 * change(shrunk.volume) << " %"
            << std::endl;

  EXPECT_LT(after.rms_radial_error, 0.5 * before.rms_radial_error);
  EXPECT_LT(std::abs(change(after.volume)), 0.005);
  EXPECT_LT(change(shrunk.volume), -0.01);
  EXPECT_GT(std::abs(change(shrunk.volume)), 5.0 * std::abs(change(after.volume)));
  EXPECT_GT(shrunk.rms_radial_error, after.rms_radial_error);
}

// ---------------------------------------------------------------------------
// Bad input.

TEST(CreasePreservingSmoothing, InvalidParametersThrowAndLeaveTheMeshUnchanged)
{
  Mesh mesh;
  BI::make_icosphere(mesh, Point(0, 0, 0), 1.0, 1);
  const std::vector<Point> original = points_of(mesh);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();

  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.0, -0.7), BI::Invalid_input_error);   // lambda = 0
  EXPECT_THROW(BI::smooth_with_creases(mesh, -0.5, -0.7), BI::Invalid_input_error);  // lambda < 0
  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.6, -0.6), BI::Invalid_input_error);   // mu = -lambda
  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.6, -0.3), BI::Invalid_input_error);   // mu > -lambda
  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.6, 0.7), BI::Invalid_input_error);    // mu > 0
  EXPECT_THROW(BI::smooth_with_creases(mesh, nan, -0.7), BI::Invalid_input_error);
  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.6, nan), BI::Invalid_input_error);
  EXPECT_THROW(BI::smooth_with_creases(mesh, 0.6, -infinity), BI::Invalid_input_error);
  EXPECT_THROW(BI::smooth_with_creases(mesh, CGAL::parameters::number_of_iterations(-1)), BI::Invalid_input_error);
  EXPECT_THROW(BI::plain_lambda_mu_smoothing(mesh, 0.6, -0.5), BI::Invalid_input_error);
  EXPECT_THROW(BI::plain_lambda_mu_smoothing(mesh, 0.0, -0.5), BI::Invalid_input_error);
  // Far outside the stable range the iteration overflows: reported, and the
  // mesh is not overwritten with infinities.
  EXPECT_THROW(BI::smooth_with_creases(mesh, 1e150, -1e151, CGAL::parameters::number_of_iterations(3)),
               BI::Non_finite_value_error);
  EXPECT_EQ(points_of(mesh), original);

  Mesh with_nan = mesh;
  with_nan.point(*with_nan.vertices().begin()) = Point(nan, 0, 0);
  EXPECT_THROW(BI::smooth_with_creases(with_nan), BI::Non_finite_value_error);
  EXPECT_THROW(BI::plain_lambda_mu_smoothing(with_nan), BI::Non_finite_value_error);
  // Zero iterations still validate the input, and otherwise do nothing.
  EXPECT_THROW(BI::smooth_with_creases(with_nan, CGAL::parameters::number_of_iterations(0)),
               BI::Non_finite_value_error);
  BI::smooth_with_creases(mesh, CGAL::parameters::number_of_iterations(0));
  EXPECT_EQ(points_of(mesh), original);

  // An empty mesh is a no-op, not an error.
  Mesh empty;
  EXPECT_NO_THROW(BI::smooth_with_creases(empty));
}

} // namespace
