// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The Python module `boolean_isosurfacing._core`, part 1: exceptions, the
// surveyor's volume, Marching Cubes CSG, contouring of point samples, and the
// readers and writers of meshes, point samples and .tris.  TBISO is in
// tbiso_bindings.cpp (a second translation unit, compiled in parallel).

#include "bindings.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tris.h>
#include <CGAL/Boolean_isosurfacing_3/Tangent_plane_signed_distance_3.h>
#include <CGAL/Boolean_isosurfacing_3/contour_point_set.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>

namespace biso_python {
namespace {

typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef std::array<double, 3> Coordinates;
typedef std::array<std::int64_t, 3> Int_triangle;

static_assert(sizeof(Coordinates) == 3 * sizeof(double), "std::array<double, 3> must be three doubles");
static_assert(sizeof(Int_triangle) == 3 * sizeof(std::int64_t), "std::array<int64_t, 3> must be three int64");

// Reads a row of three doubles of the caller's array as a Point_3: lets the
// library's soup overloads read numpy buffers in place.
struct Coordinates_point_map
{
  typedef Coordinates key_type;
  typedef Point_3 value_type;
  typedef Point_3 reference;
  typedef boost::readable_property_map_tag category;
  friend Point_3 get(const Coordinates_point_map&, const Coordinates& c) { return Point_3(c[0], c[1], c[2]); }
};

// The (n, 3) rows of a checked array, viewed as std::array's (no copy).
boost::iterator_range<const Coordinates*> point_rows(const Double_array& V)
{
  const Coordinates* first = reinterpret_cast<const Coordinates*>(V.data());
  return {first, first + V.shape(0)};
}

boost::iterator_range<const Int_triangle*> triangle_rows(const Index_array& F)
{
  const Int_triangle* first = reinterpret_cast<const Int_triangle*>(F.data());
  return {first, first + F.shape(0)};
}

// Rethrows the active package exception with `prefix` before its message,
// keeping its type (and so its Python exception class).
[[noreturn]] void rethrow_with_prefix(const std::string& prefix)
{
  try
  {
    throw;
  }
  catch(const BI::Parse_error& e) { throw BI::Parse_error(prefix + e.what(), e.position()); }
  catch(const BI::Empty_input_error& e) { throw BI::Empty_input_error(prefix + e.what()); }
  catch(const BI::Non_triangle_face_error& e) { throw BI::Non_triangle_face_error(prefix + e.what()); }
  catch(const BI::Open_mesh_error& e) { throw BI::Open_mesh_error(prefix + e.what()); }
  catch(const BI::Non_finite_value_error& e) { throw BI::Non_finite_value_error(prefix + e.what()); }
  catch(const BI::Inward_oriented_mesh_error& e) { throw BI::Inward_oriented_mesh_error(prefix + e.what()); }
  catch(const BI::Self_intersecting_mesh_error& e) { throw BI::Self_intersecting_mesh_error(prefix + e.what()); }
  catch(const BI::Lattice_too_large_error& e) { throw BI::Lattice_too_large_error(prefix + e.what()); }
  catch(const BI::Invalid_input_error& e) { throw BI::Invalid_input_error(prefix + e.what()); }
}

// ---------------------------------------------------------------- volume

double surveyor_volume_py(const py::handle& V_object, const py::handle& F_object, bool signed_volume)
{
  // NaN and out-of-range indices are the library's to report (its messages).
  const Double_array V = as_double_rows(V_object, 3, "V", false);
  const Index_array F = as_index_rows(F_object, 3, "F", std::size_t(-1));
  const auto points = point_rows(V);
  const auto triangles = triangle_rows(F);
  py::gil_scoped_release release;
  return BI::surveyor_volume(points, triangles,
                             BI::parameters::signed_volume(signed_volume, CGAL::parameters::point_map(
                                                                              Coordinates_point_map())));
}

// ---------------------------------------------------------------- CSG

// A closed, outward, manifold triangle mesh from (V, F), checked as
// IO::read_closed_triangle_mesh() checks a file: by the soup overload of
// surveyor_volume (faces, closedness, orientation, finiteness), then for
// manifold vertices.
Mesh closed_mesh_from(const Double_array& V, const Index_array& F)
{
  BI::surveyor_volume(point_rows(V), triangle_rows(F),
                      BI::parameters::signed_volume(false, CGAL::parameters::point_map(Coordinates_point_map())));
  std::vector<Point_3> points = copy_points(V);
  std::vector<std::array<std::size_t, 3>> triangles(std::size_t(F.shape(0)));
  std::memcpy(triangles.data(), F.data(), triangles.size() * sizeof(triangles[0]));
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles))
    throw BI::Invalid_input_error("it is closed but has a non-manifold vertex; split it first "
                                  "(PMP::duplicate_non_manifold_vertices)");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

BI::Boolean_expression csg_expression(const std::string& text, std::size_t number_of_meshes)
{
  if(text == "union")
    return BI::Boolean_expression::union_of(number_of_meshes);
  if(text == "intersection")
    return BI::Boolean_expression::intersection_of(number_of_meshes);
  if(text == "difference")
  {
    if(number_of_meshes != 2)
      throw BI::Invalid_input_error("'difference' needs exactly two meshes, got " + std::to_string(number_of_meshes) +
                                    " (write an expression such as \"A & !B & !C\")");
    return BI::Boolean_expression::difference();
  }
  const BI::Boolean_expression parsed = BI::Boolean_expression::parse(text);
  if(parsed.number_of_variables() > number_of_meshes)
    throw BI::Invalid_input_error("the expression names " + std::to_string(parsed.number_of_variables()) +
                                  " inputs but " + std::to_string(number_of_meshes) + " meshes were given");
  return BI::Boolean_expression(number_of_meshes, parsed.terms());
}

py::tuple csg_py(const py::sequence& meshes_in, const std::string& expr, std::optional<std::size_t> cells,
                 std::optional<double> spacing, bool shift, bool features, double feature_angle, int threads,
                 std::optional<std::size_t> max_memory_bytes)
{
  if(cells && spacing)
    throw BI::Invalid_input_error("give at most one of cells and spacing");
  if(spacing && !(std::isfinite(*spacing) && *spacing > 0))
    throw BI::Invalid_input_error("spacing must be positive and finite, got " + std::to_string(*spacing));
  if(cells && *cells == 0)
    throw BI::Invalid_input_error("cells must be positive");
  const std::size_t n = std::size_t(py::len(meshes_in));
  if(n == 0)
    throw BI::Empty_input_error("no input mesh");
  // The arrays are checked and kept alive (with the GIL) while the meshes
  // are built without it.
  std::vector<std::pair<Double_array, Index_array>> arrays;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::string prefix = "mesh " + std::to_string(i) + (i < 26 ? std::string(" (") + char('A' + i) + ")" : "");
    py::object item = meshes_in[i];
    if(!py::isinstance<py::sequence>(item) || py::len(item) != 2)
      throw BI::Invalid_input_error(prefix + ": expected a (V, F) pair");
    try
    {
      py::sequence pair = item.cast<py::sequence>();
      arrays.emplace_back(as_double_rows(pair[0], 3, "V", false), as_index_rows(pair[1], 3, "F", std::size_t(-1)));
    }
    catch(const BI::Invalid_input_error&)
    {
      rethrow_with_prefix(prefix + ": ");
    }
  }
  const BI::Boolean_expression expression = csg_expression(expr, n);

  std::vector<Coordinates> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  BI::Marching_cubes_csg_statistics statistics;
  std::optional<BI::Regular_lattice_3> lattice;
  double total_seconds = 0;
  {
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    std::vector<Mesh> meshes;
    meshes.reserve(n);
    CGAL::Bbox_3 box;
    for(std::size_t i = 0; i < n; ++i)
    {
      try
      {
        meshes.push_back(closed_mesh_from(arrays[i].first, arrays[i].second));
      }
      catch(const BI::Invalid_input_error&)
      {
        rethrow_with_prefix("mesh " + std::to_string(i) +
                            (i < 26 ? std::string(" (") + char('A' + i) + ")" : "") + ": ");
      }
      for(const auto v : meshes.back().vertices())
        box += meshes.back().point(v).bbox();
    }
    const std::size_t default_cells = 128;
    // The library's default offset keeps axis-aligned faces on the bounding
    // box off the lattice planes; shift=False asks for the round lattice.
    const double offset = shift ? BI::Regular_lattice_3::default_offset_cells : 0.0;
    lattice.emplace(spacing ? BI::Regular_lattice_3::enclosing(box, *spacing, 1, offset)
                            : BI::Regular_lattice_3::enclosing_with_cells(box, cells ? *cells : default_cells, 1,
                                                                          offset));
    const std::size_t memory = max_memory_bytes ? *max_memory_bytes : BI::Lattice_classifier_3::default_max_memory_bytes;
    statistics = with_threads(threads, [&] {
      return BI::marching_cubes_csg<CGAL::Parallel_if_available_tag>(
          *lattice, meshes, expression, points, triangles,
          BI::parameters::max_memory_bytes(
              memory, BI::parameters::sharp_features(features, BI::parameters::feature_angle(feature_angle)))
              .callback(python_signals_callback()));
    });
    total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  py::dict info;
  info["expression"] = expression.to_string();
  info["lattice_points"] = lattice->number_of_points();
  info["lattice_origin"] = lattice->origin();
  info["spacing"] = lattice->spacing();
  info["crossings"] = statistics.crossings;
  info["boundary_points_inside"] = statistics.boundary_points_inside;
  info["closed"] = statistics.boundary_points_inside == 0;
  info["feature_vertices"] = statistics.feature_vertices;
  info["corner_vertices"] = statistics.corner_vertices;
  info["crease_edges"] = statistics.crease_edges;
  // Input components the lattice does not resolve (may be missing from V, F).
  py::list unresolved;
  for(const BI::Marching_cubes_csg_component_report& c : statistics.under_resolved_components)
  {
    py::dict d;
    d["mesh"] = c.mesh;
    d["component"] = c.component;
    d["triangles"] = c.triangles;
    d["crossings"] = c.crossings;
    d["volume"] = c.volume;
    d["lattice_volume"] = c.lattice_volume;
    d["suggested_spacing"] = c.suggested_spacing;
    unresolved.append(d);
  }
  info["checked_components"] = statistics.checked_components;
  info["under_resolved_components"] = unresolved;
  // The result's own walls or gaps thinner than a cell (see the C++ statistics).
  info["result_intervals"] = statistics.result_intervals;
  info["thin_result_intervals"] = statistics.thin_result_intervals;
  info["thin_result_fraction"] = statistics.thin_result_fraction();
  info["thin_result_suggested_spacing"] = statistics.thin_result_suggested_spacing;
  info["sparse_result_fraction"] = statistics.sparse_result_fraction;
  info["sparse_result_suggested_spacing"] = statistics.sparse_result_suggested_spacing;
  info["warnings"] = statistics.warnings;
  info["seconds_classification"] = statistics.seconds_classification;
  info["seconds_edges"] = statistics.seconds_edges;
  info["seconds_triangulation"] = statistics.seconds_triangulation;
  info["seconds_total"] = total_seconds;
  return py::make_tuple(points_array(std::move(points)), index_array(std::move(triangles)), info);
}

// ---------------------------------------------------------------- contouring

py::tuple contour_py(const py::handle& points_object, const py::handle& normals_object, std::optional<double> cell_size,
                     std::optional<double> cells, std::size_t k, std::optional<double> rho,
                     std::optional<double> delta, std::optional<double> max_jump,
                     std::optional<double> min_component_size, std::optional<double> margin, int threads)
{
  typedef BI::Tangent_plane_signed_distance_3<K, CGAL::Parallel_if_available_tag> Field;
  if(cell_size && cells)
    throw BI::Invalid_input_error("give at most one of cell_size and cells");
  const Double_array P = as_double_rows(points_object, 3, "points", false);
  std::optional<Double_array> N;
  if(!normals_object.is_none())
  {
    N = as_double_rows(normals_object, 3, "normals");
    if(N->shape(0) != P.shape(0))
      throw BI::Invalid_input_error("normals has " + std::to_string(N->shape(0)) + " rows but points has " +
                                    std::to_string(P.shape(0)));
  }
  std::vector<Point_3> out_points;
  std::vector<std::array<std::size_t, 3>> triangles;
  BI::Contouring_statistics report;
  std::optional<Field> field;
  {
    py::gil_scoped_release release;
    // The field copies the points; the library reports NaN by index.
    const std::vector<Point_3> points = copy_points(P);
    std::vector<Vector_3> normals;
    if(N)
    {
      const double* d = N->data();
      for(py::ssize_t i = 0; i < N->shape(0); ++i)
        normals.emplace_back(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
    }
    std::vector<std::size_t> indices(points.size());
    for(std::size_t i = 0; i < indices.size(); ++i)
      indices[i] = i;
    const auto point_map = CGAL::make_property_map(points);
    const auto normal_map = CGAL::make_property_map(normals);
    // rho and delta are estimated unless given: the class refuses a negative
    // value passed explicitly, so they are passed only when set.
    const auto base = BI::parameters::number_of_neighbors(k).point_map(point_map);
    auto build = [&](const auto& np) {
      if(rho && delta)
        field.emplace(indices, BI::parameters::sampling_density(*rho, BI::parameters::noise_level(*delta, np)));
      else if(rho)
        field.emplace(indices, BI::parameters::sampling_density(*rho, np));
      else if(delta)
        field.emplace(indices, BI::parameters::noise_level(*delta, np));
      else
        field.emplace(indices, np);
    };
    with_threads(threads, [&] {
      if(N)
        build(base.normal_map(normal_map));
      else
        build(base);
    });

    // The library's documented defaults, computed here so that one
    // instantiation of contour_signed_distance serves every call.
    double r = field->default_cell_size();
    if(cell_size)
      r = *cell_size;
    else if(cells)
    {
      if(!(std::isfinite(*cells) && *cells > 0))
        throw BI::Invalid_input_error("cells must be positive and finite");
      std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
      for(const Point_3& p : points)
        for(int a = 0; a < 3; ++a)
        {
          lo[a] = std::min(lo[a], p[a]);
          hi[a] = std::max(hi[a], p[a]);
        }
      r = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / *cells;
    }
    if(!(std::isfinite(r) && r > 0))
      throw BI::Invalid_input_error("the cell size must be positive and finite, got " + std::to_string(r));
    const double jump = max_jump ? *max_jump : 3 * r + 2 * field->noise_level();
    const double bubble = min_component_size ? *min_component_size : field->sampling_density();
    const double lattice_margin =
        margin ? *margin : std::ceil((field->sampling_density() + field->noise_level()) / r) + 2;
    if(!(jump > 0))
      throw BI::Invalid_input_error("max_jump must be positive (inf: Hoppe's plain rule)");
    if(!(std::isfinite(lattice_margin) && lattice_margin >= 0))
      throw BI::Invalid_input_error("margin must be >= 0 and finite");
    const BI::Regular_lattice_3 lattice =
        BI::contouring_lattice(*field, BI::parameters::cell_size(r, BI::parameters::lattice_margin(lattice_margin)));
    report = with_threads(threads, [&] {
      return BI::contour_signed_distance<CGAL::Parallel_if_available_tag>(
          lattice, *field, out_points, triangles,
          BI::parameters::maximum_jump(jump, BI::parameters::minimum_closed_component_size(bubble))
              .callback(python_signals_callback()));
    });
  }
  py::dict info;
  const auto& t = field->timings();
  info["k"] = field->number_of_neighbors();
  info["rho"] = field->sampling_density();
  info["delta"] = field->noise_level();
  info["cell_size"] = report.cell_size;
  info["lattice_origin"] = report.origin;
  info["number_of_cells"] = report.number_of_cells;
  info["input_normals_rejected"] = field->input_normals_rejected();
  info["input_normal_votes"] = field->input_normal_votes();
  info["orientation_trees"] = field->number_of_orientation_trees();
  info["field_evaluations"] = report.field_evaluations;
  info["undefined_points"] = report.undefined_points;
  info["visited_cubes"] = report.visited_cubes;
  info["surface_cubes"] = report.surface_cubes;
  info["skipped_cubes"] = report.skipped_cubes;
  info["border_exits"] = report.border_exits;
  info["discontinuous_cubes"] = report.discontinuous_cubes;
  info["removed_closed_components"] = report.removed_closed_components;
  info["seconds_neighbors"] = t.neighbors;
  info["seconds_planes"] = t.planes;
  info["seconds_orientation"] = t.orientation;
  info["seconds_field"] = report.seconds_field;
  info["seconds_contouring"] = report.seconds_contouring;
  return py::make_tuple(points_array(std::move(out_points)), index_array(std::move(triangles)), info);
}

// ---------------------------------------------------------------- files

std::string extension_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = path.substr(dot + 1);
  for(char& c : e)
    c = char(std::tolower((unsigned char)c));
  return e;
}

// A mesh built from scratch (dense indices) as points and triangles.
void mesh_to_arrays(const Mesh& mesh, std::vector<Point_3>& points, std::vector<std::array<std::size_t, 3>>& triangles)
{
  for(const auto v : mesh.vertices())
    points.push_back(mesh.point(v));
  for(const auto f : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    int c = 0;
    for(const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[c++] = std::size_t(v);
    triangles.push_back(t);
  }
}

py::tuple mesh_tuple(const Mesh& mesh)
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  mesh_to_arrays(mesh, points, triangles);
  return py::make_tuple(points_array(std::move(points)), index_array(std::move(triangles)));
}

py::tuple icosphere_py(std::array<double, 3> center, double radius, unsigned subdivisions)
{
  if(!(std::isfinite(radius) && radius > 0))
    throw BI::Invalid_input_error("radius must be positive and finite");
  if(subdivisions > 10)
    throw BI::Invalid_input_error("at most 10 subdivisions (20 * 4^10 triangles), got " + std::to_string(subdivisions));
  Mesh mesh;
  BI::make_icosphere(mesh, Point_3(center[0], center[1], center[2]), radius, subdivisions);
  return mesh_tuple(mesh);
}

py::tuple torus_py(std::array<double, 3> center, double major_radius, double minor_radius, unsigned major_segments,
                   unsigned minor_segments)
{
  if(!(std::isfinite(major_radius) && major_radius > minor_radius && minor_radius > 0))
    throw BI::Invalid_input_error("a torus needs major_radius > minor_radius > 0");
  if(major_segments < 3 || minor_segments < 3 || double(major_segments) * minor_segments > 1e8)
    throw BI::Invalid_input_error("a torus needs 3 or more segments each way (and fewer than 1e8 in all)");
  Mesh mesh;
  BI::make_torus(mesh, Point_3(center[0], center[1], center[2]), major_radius, minor_radius, major_segments,
                 minor_segments);
  return mesh_tuple(mesh);
}

py::tuple read_mesh_py(const std::string& path, bool closed)
{
  check_readable(path);
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  {
    py::gil_scoped_release release;
    if(closed)
    {
      Mesh mesh;
      BI::IO::read_closed_triangle_mesh(path, mesh);
      mesh_to_arrays(mesh, points, triangles);
    }
    else
    {
      std::vector<std::vector<std::size_t>> polygons;
      if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
        throw BI::Invalid_input_error("cannot parse '" + path + "' as OFF, OBJ, PLY or STL (malformed or unsupported)");
      for(std::size_t p = 0; p < polygons.size(); ++p)
      {
        if(polygons[p].size() != 3)
          throw BI::Non_triangle_face_error("polygon #" + std::to_string(p) + " has " +
                                            std::to_string(polygons[p].size()) + " vertices, not 3");
        triangles.push_back({polygons[p][0], polygons[p][1], polygons[p][2]});
      }
    }
  }
  return py::make_tuple(points_array(std::move(points)), index_array(std::move(triangles)));
}

void write_mesh_py(const std::string& path, const py::handle& V_object, const py::handle& F_object)
{
  const Double_array V = as_double_rows(V_object, 3, "V");
  const Index_array F = as_index_rows(F_object, 3, "F", std::size_t(V.shape(0)));
  const std::string e = extension_of(path);
  if(e != "off" && e != "obj" && e != "ply" && e != "stl")
    throw BI::Invalid_input_error("cannot tell the mesh format of '" + path + "': use .off, .obj, .ply or .stl");
  check_writable(path);
  py::gil_scoped_release release;
  const std::vector<Point_3> points = copy_points(V);
  std::vector<std::array<std::size_t, 3>> triangles(std::size_t(F.shape(0)));
  std::memcpy(triangles.data(), F.data(), triangles.size() * sizeof(triangles[0]));
  if(!CGAL::IO::write_polygon_soup(path, points, triangles, CGAL::parameters::stream_precision(17)))
    throw File_error(EIO, "cannot write the mesh", path);
}

py::tuple read_points_py(const std::string& path)
{
  check_readable(path);
  std::vector<Point_3> points;
  std::vector<Vector_3> normals;
  bool has_normals;
  {
    py::gil_scoped_release release;
    has_normals = BI::IO::read_point_samples(path, points, normals);
  }
  static_assert(sizeof(Vector_3) == 3 * sizeof(double), "Epick::Vector_3 must be three doubles");
  py::object N = py::none();
  if(has_normals)
  {
    const py::ssize_t n = py::ssize_t(normals.size());
    N = owning_array<double>(std::move(normals), {n, 3});
  }
  return py::make_tuple(points_array(std::move(points)), N);
}

void write_points_py(const std::string& path, const py::handle& P_object, const py::handle& N_object)
{
  const Double_array P = as_double_rows(P_object, 3, "points");
  std::optional<Double_array> N;
  if(!N_object.is_none())
  {
    N = as_double_rows(N_object, 3, "normals");
    if(N->shape(0) != P.shape(0))
      throw BI::Invalid_input_error("normals has " + std::to_string(N->shape(0)) + " rows but points has " +
                                    std::to_string(P.shape(0)));
  }
  const std::string e = extension_of(path);
  if(e != "pts" && e != "xyz" && e != "pwn")
    throw BI::Invalid_input_error("write_points writes text point files: use .pts, .xyz or .pwn, not '" + path + "'");
  check_writable(path);
  py::gil_scoped_release release;
  // The seed's .pts: `x y z [nx ny nz]` per line, which .xyz and .pwn share;
  // 17 significant digits read back the same doubles.
  std::FILE* out = std::fopen(path.c_str(), "w");
  if(!out)
    throw File_error(errno, "cannot open the file for writing", path);
  const double* p = P.data();
  const double* n = N ? N->data() : nullptr;
  bool ok = true;
  for(py::ssize_t i = 0; i < P.shape(0) && ok; ++i)
    ok = (n ? std::fprintf(out, "%.17g %.17g %.17g %.17g %.17g %.17g\n", p[3 * i], p[3 * i + 1], p[3 * i + 2],
                           n[3 * i], n[3 * i + 1], n[3 * i + 2])
            : std::fprintf(out, "%.17g %.17g %.17g\n", p[3 * i], p[3 * i + 1], p[3 * i + 2])) > 0;
  ok = (std::fclose(out) == 0) && ok;
  if(!ok)
    throw File_error(EIO, "cannot write the point file", path);
}

py::tuple read_tris_py(const std::string& path)
{
  check_readable(path);
  std::vector<BI::IO::Tris_triangle> triangles;
  {
    py::gil_scoped_release release;
    triangles = BI::IO::read_tris(path);
  }
  const py::ssize_t m = py::ssize_t(triangles.size());
  py::array_t<double> T({m, py::ssize_t(3), py::ssize_t(3)}), N({m, py::ssize_t(3)});
  auto t = T.mutable_unchecked<3>();
  auto n = N.mutable_unchecked<2>();
  for(py::ssize_t i = 0; i < m; ++i)
    for(int a = 0; a < 3; ++a)
    {
      n(i, a) = triangles[std::size_t(i)].n[a];
      t(i, 0, a) = triangles[std::size_t(i)].p0[a];
      t(i, 1, a) = triangles[std::size_t(i)].p1[a];
      t(i, 2, a) = triangles[std::size_t(i)].p2[a];
    }
  return py::make_tuple(T, N);
}

void write_tris_py(const std::string& path, const py::handle& V_object, const py::handle& F_object)
{
  const Double_array V = as_double_rows(V_object, 3, "V");
  const Index_array F = as_index_rows(F_object, 3, "F", std::size_t(V.shape(0)));
  check_writable(path);
  py::gil_scoped_release release;
  const std::vector<Point_3> points = copy_points(V);
  if(!BI::IO::write_tris(path, points, triangle_rows(F)))
    throw File_error(EIO, "cannot write the .tris file", path);
}

void register_exceptions(py::module_& m)
{
  // Invalid_input_error derives from std::invalid_argument, so every library
  // input error is a ValueError; its subclasses can be caught one by one.
  auto& invalid = py::register_exception<BI::Invalid_input_error>(m, "InvalidInputError", PyExc_ValueError);
  py::register_exception<BI::Empty_input_error>(m, "EmptyInputError", invalid.ptr());
  py::register_exception<BI::Non_triangle_face_error>(m, "NonTriangleFaceError", invalid.ptr());
  py::register_exception<BI::Open_mesh_error>(m, "OpenMeshError", invalid.ptr());
  py::register_exception<BI::Non_finite_value_error>(m, "NonFiniteValueError", invalid.ptr());
  py::register_exception<BI::Inward_oriented_mesh_error>(m, "InwardOrientedMeshError", invalid.ptr());
  py::register_exception<BI::Self_intersecting_mesh_error>(m, "SelfIntersectingMeshError", invalid.ptr());
  py::register_exception<BI::Lattice_too_large_error>(m, "LatticeTooLargeError", invalid.ptr());
  py::register_exception<BI::Parse_error>(m, "ParseError", invalid.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const File_error& e)
    {
      py::object error = py::reinterpret_steal<py::object>(
          PyObject_CallFunction(PyExc_OSError, "iss", e.error_number, e.what(), e.path.c_str()));
      if(error)
        PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
    }
  });
}

} // namespace

std::vector<std::vector<std::size_t>> polygons_from(const py::handle& object, std::size_t number_of_points,
                                                    const char* name)
{
  std::vector<std::vector<std::size_t>> polygons;
  if(py::isinstance<py::array>(object) && py::reinterpret_borrow<py::array>(object).ndim() == 2)
  {
    const py::array a = py::reinterpret_borrow<py::array>(object);
    const Index_array rows = as_index_rows(object, std::size_t(a.shape(1)), name, number_of_points);
    const std::size_t k = std::size_t(rows.shape(1));
    polygons.resize(std::size_t(rows.shape(0)));
    for(std::size_t p = 0; p < polygons.size(); ++p)
      polygons[p].assign(rows.data() + p * k, rows.data() + (p + 1) * k);
  }
  else
  {
    if(!py::isinstance<py::sequence>(object))
      throw BI::Invalid_input_error(std::string(name) + " must be a list of index sequences or an (m, k) array");
    const py::sequence list = py::reinterpret_borrow<py::sequence>(object);
    polygons.resize(py::len(list));
    for(std::size_t p = 0; p < polygons.size(); ++p)
    {
      py::array a = py::array::ensure(list[p]);
      if(!a || a.ndim() != 1 || (a.size() != 0 && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
        throw BI::Invalid_input_error(std::string(name) + "[" + std::to_string(p) +
                                      "] is not a 1-D sequence of integers");
      const auto indices = Index_array::ensure(a);
      for(py::ssize_t i = 0; i < indices.size(); ++i)
      {
        const std::int64_t v = indices.data()[i];
        if(v < 0 || std::uint64_t(v) >= number_of_points)
          throw BI::Invalid_input_error(std::string(name) + "[" + std::to_string(p) + "] refers to V row " +
                                        std::to_string(v) + ", but there are " + std::to_string(number_of_points));
        polygons[p].push_back(std::size_t(v));
      }
    }
  }
  for(std::size_t p = 0; p < polygons.size(); ++p)
    if(polygons[p].size() < 3)
      throw BI::Invalid_input_error(std::string(name) + "[" + std::to_string(p) + "] has " +
                                    std::to_string(polygons[p].size()) + " vertices; a polygon needs at least 3");
  return polygons;
}

py::list polygons_to_list(const std::vector<std::vector<std::size_t>>& polygons)
{
  py::list list(polygons.size());
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    py::array_t<std::int64_t> a(py::ssize_t(polygons[p].size()));
    std::memcpy(a.mutable_data(), polygons[p].data(), polygons[p].size() * sizeof(std::size_t));
    list[p] = std::move(a);
  }
  return list;
}

} // namespace biso_python

PYBIND11_MODULE(_core, m)
{
  using namespace biso_python;
  using namespace pybind11::literals;
  m.doc() = "Boolean Isosurfacing for CGAL: Marching Cubes CSG, the surveyor's volume, contouring of point "
            "samples and TBISO Boolean isosurfaces, on numpy arrays.";
  register_exceptions(m);
#ifdef CGAL_LINKED_WITH_TBB
  m.attr("parallel") = true;
#else
  m.attr("parallel") = false;
#endif

  m.def("surveyor_volume", &surveyor_volume_py, "V"_a, "F"_a, "signed"_a = false,
        R"doc(Volume enclosed by a closed triangle mesh (V, F), by the surveyor's formula.

V: (n, 3) float64 array of points; F: (m, 3) integer array of triangles
(read in place when C-contiguous float64 / int64).  The relative error is
below 4e-15 (a certified bound with an exact fallback), also far from the
origin.

With signed=False (the default), an inward-oriented mesh raises
InwardOrientedMeshError; with signed=True the winding-number-weighted
signed volume is returned.  Raises OpenMeshError (a border edge or
inconsistent orientation), NonFiniteValueError, EmptyInputError, or
InvalidInputError (an index out of range, a repeated vertex), all ValueError.)doc");

  m.def("csg", &csg_py, "meshes"_a, "expr"_a, "cells"_a = py::none(), "spacing"_a = py::none(), "shift"_a = true,
        "features"_a = true, "feature_angle"_a = 30.0, "threads"_a = 0, "max_memory_bytes"_a = py::none(),
        R"doc(Marching Cubes CSG: the boundary of expr(meshes) sampled on a regular lattice.

meshes: a list of (V, F) pairs, each a closed, outward-oriented triangle
mesh; mesh i is variable i of the expression (A, B, C, ... or f0, f1, ...).
expr: a Boolean expression ("A & !B | C", with &, |, !, -, parentheses) or
one of "union", "intersection", "difference" (A & !B, two meshes).
cells: lattice cells along the longest side of the bounding box (default
128), or spacing: the lattice spacing (give at most one).  shift=True (the
library's default lattice) puts the lattice planes 0.382 cell off the
bounding box, so that axis-aligned faces on it do not lie on lattice planes;
shift=False puts a plane on each box minimum.  features=True places sharp
creases and corners where the crossing normals of a cube differ by more than
feature_angle degrees (Extended Marching Cubes on the exact Hermite data);
False gives plain Marching Cubes.  threads: TBB worker
threads (0: all cores); the output does not depend on it.  Ctrl-C
(KeyboardInterrupt) stops it between batches of work.

Returns (V, F, info): V (k, 3) float64, F (t, 3) int64 outward triangles,
closed and 2-manifold when info["closed"]; info holds the lattice, the
crossings, the sharp-feature counts, info["under_resolved_components"] (input
components with no lattice point inside or a lattice volume off by more
than a factor 2: they may be missing from the output), the result's own
thin walls or gaps (info["thin_result_fraction"] of its line volume in
intervals of lattice lines that hold no lattice point, and a spacing that
would see them; info["sparse_result_fraction"] likewise for intervals that
hold fewer than two), info["warnings"] (one line per missing guarantee) and the
time of each stage.  The GIL is released while it runs.)doc");

  m.def("contour", &contour_py, "points"_a, "normals"_a = py::none(), "cell_size"_a = py::none(),
        "cells"_a = py::none(), "k"_a = 15, "rho"_a = py::none(), "delta"_a = py::none(), "max_jump"_a = py::none(),
        "min_component_size"_a = py::none(), "margin"_a = py::none(), "threads"_a = 0,
        R"doc(Contours oriented (or unoriented) point samples into a triangle mesh (Hoppe et al. 1992).

points: (n, 3) float64 samples; normals: optional (n, 3) roughly outward
normals (used only to orient the tangent planes; rejected with a note in
info when they do not point outward).  k: neighbours per tangent plane;
rho, delta: Hoppe's sampling density and noise level (estimated when
None); cell_size (length) or cells (along the longest side): the lattice
spacing, default a third of the estimated rho; max_jump: a length, the
largest change of f along a sign-changing edge (default 3 cell_size +
2 delta; inf gives Hoppe's plain rule); min_component_size: closed pieces
with a smaller bounding-box diagonal are removed (default rho);
margin: lattice cells around the samples' box.  threads: TBB worker
threads for the k-NN queries, the plane fits and the field at the lattice
points (0: all cores); the output does not depend on it.

Returns (V, F, info): outward-oriented triangles (f < 0 inside); info holds
rho, delta, the lattice and the counts and times of each stage.)doc");

  m.def("read_mesh", &read_mesh_py, "path"_a, "closed"_a = true,
        R"doc(Reads a triangle mesh (OFF, OBJ, PLY, STL) as (V, F).

With closed=True (the default) the file must bound a solid, checked as the
tools check it: a closed, consistently outward-oriented triangle mesh with
manifold vertices and finite coordinates (else a ValueError naming the
problem).  With closed=False any triangle soup is returned as it is.
A missing or unreadable file raises OSError (FileNotFoundError, ...).)doc");
  m.def("write_mesh", &write_mesh_py, "path"_a, "V"_a, "F"_a,
        "Writes (V, F) as OFF, OBJ, PLY or STL (by the extension), with 17 significant digits.");
  m.def("read_points", &read_points_py, "path"_a,
        R"doc(Reads point samples: .pts (the seed's 'x y z [nx ny nz]'), .xyz, .pwn, .ply.

Returns (P, N) with N None when the file has no normals.  A malformed line
raises ParseError (a ValueError) naming the line.)doc");
  m.def("write_points", &write_points_py, "path"_a, "points"_a, "normals"_a = py::none(),
        "Writes points (and normals) as text, one 'x y z [nx ny nz]' line per sample (.pts, .xyz, .pwn).");
  m.def("read_tris", &read_tris_py, "path"_a,
        "Reads a .tris file: returns (T, N), T (m, 3, 3) the corners of each triangle, N (m, 3) its stored normal.");
  m.def("write_tris", &write_tris_py, "path"_a, "V"_a, "F"_a,
        "Writes (V, F) as the seed's .tris (a unit normal and three corners per triangle).");

  m.def("icosphere", &icosphere_py, "center"_a = std::array<double, 3>{{0, 0, 0}}, "radius"_a = 1.0,
        "subdivisions"_a = 4,
        "A geodesic sphere (V, F): an icosahedron split 4 times per subdivision, 20 * 4^s outward triangles.");
  m.def("torus", &torus_py, "center"_a = std::array<double, 3>{{0, 0, 0}}, "major_radius"_a = 0.8,
        "minor_radius"_a = 0.35, "major_segments"_a = 96, "minor_segments"_a = 48,
        "A torus (V, F) around the axis through center parallel to z: 2 * major * minor outward triangles.");

  bind_tbiso(m);
}
