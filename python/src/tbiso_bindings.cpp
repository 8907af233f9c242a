// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The Python module, part 2: TBISO (Boolean isosurfaces of scalar fields on
// tetrahedral grids and meshes), its crease network, the crease-preserving
// smoothing, and the readers and writers of tetrahedral meshes, scalar fields,
// labelled PLY surfaces, crease polylines and corners.

#include "bindings.h"

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_mesh_3.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/crease_preserving_smoothing.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <optional>

namespace biso_python {
namespace {

typedef BI::Tetrahedral_grid_3<K> Grid;
typedef BI::Tetrahedral_mesh_3<K> Tet_mesh;
typedef BI::Boolean_isosurface_soup<Point_3> Soup;
typedef CGAL::Surface_mesh<Point_3> Mesh;

Grid grid_from(const std::array<std::size_t, 3>& counts, const std::array<double, 6>& box)
{
  for(double b : box)
    if(!std::isfinite(b))
      throw BI::Invalid_input_error("the box must be finite");
  for(int a = 0; a < 3; ++a)
    if(!(box[a] < box[a + 3]))
      throw BI::Invalid_input_error("the box must have x0 < x1, y0 < y1, z0 < z1");
  return Grid::spanning(Point_3(box[0], box[1], box[2]), Point_3(box[3], box[4], box[5]), counts);
}

Tet_mesh tet_mesh_from(const py::handle& mesh)
{
  if(!py::isinstance<py::sequence>(mesh) || py::len(mesh) != 2)
    throw BI::Invalid_input_error("mesh must be a pair (X, T) of vertex and tetrahedron arrays");
  const py::sequence pair = py::reinterpret_borrow<py::sequence>(mesh);
  const Double_array X = as_double_rows(pair[0], 3, "X", false);
  // Negative indices are refused here (they would wrap); the upper bound and
  // everything else are the library's to check.
  const Index_array T = as_index_rows(pair[1], 4, "T", std::size_t(-1));
  for(py::ssize_t i = 0; i < T.size(); ++i)
    if(T.data()[i] < 0)
      throw BI::Invalid_input_error("T row " + std::to_string(i / 4) + " has a negative index " +
                                    std::to_string(T.data()[i]));
  py::gil_scoped_release release;
  std::vector<std::array<std::size_t, 4>> tetrahedra(std::size_t(T.shape(0)));
  std::memcpy(tetrahedra.data(), T.data(), tetrahedra.size() * sizeof(tetrahedra[0]));
  return Tet_mesh(copy_points(X), std::move(tetrahedra));
}

// One row per vertex, one column per field (a 1-D array is one field).  The
// library's Scalar_fields owns its values, so this is the one copy.
BI::Scalar_fields fields_from(const py::handle& object)
{
  if(object.is_none())
    throw BI::Invalid_input_error("fields is None");
  Double_array array;
  try
  {
    array = py::cast<Double_array>(object);
  }
  catch(const py::cast_error&)
  {
    throw BI::Invalid_input_error("fields is not an array of numbers");
  }
  if(array.ndim() != 1 && array.ndim() != 2)
    throw BI::Invalid_input_error("fields must have shape (number_of_vertices, number_of_fields), got " +
                                  std::to_string(array.ndim()) + " dimensions");
  const std::size_t n = array.ndim() == 2 ? std::size_t(array.shape(1)) : 1;
  if(array.size() == 0)
    throw BI::Empty_input_error("fields is empty");
  // NaN and infinity are the library's to report (it names the vertex and the field).
  return BI::Scalar_fields(n, std::vector<double>(array.data(), array.data() + array.size()));
}

// Closed and volume of a welded polygon soup: its fan triangles go through
// the soup overload of the surveyor's volume, which checks that every
// directed edge is matched by a reverse one (closed, consistently oriented).
std::optional<double> closed_volume(const Soup& soup)
{
  std::vector<std::array<std::size_t, 3>> fan;
  for(const std::vector<std::size_t>& poly : soup.polygons)
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      fan.push_back({poly[0], poly[k], poly[k + 1]});
  if(fan.empty())
    return std::nullopt;
  try
  {
    return BI::surveyor_volume(soup.points, fan, BI::parameters::signed_volume(true));
  }
  catch(const BI::Open_mesh_error&)
  {
    return std::nullopt;
  }
}

void smooth_soup(Soup& soup, const BI::Crease_network& creases, long long iterations, double lambda, double mu,
                 bool keep_creases)
{
  Mesh mesh;
  BI::Boolean_isosurface_mesh_maps<Point_3> maps;
  try
  {
    maps = BI::boolean_isosurface_to_mesh(soup, creases, mesh);
  }
  catch(const BI::Invalid_input_error& e)
  {
    throw BI::Invalid_input_error(std::string("smoothing: ") + e.what());
  }
  if(keep_creases)
    BI::smooth_with_creases(mesh, lambda, mu,
                            CGAL::parameters::number_of_iterations(iterations)
                                .edge_is_constrained_map(maps.edge_is_crease)
                                .vertex_is_constrained_map(maps.vertex_is_corner));
  else
    BI::plain_lambda_mu_smoothing(mesh, lambda, mu, CGAL::parameters::number_of_iterations(iterations));
  // Vertex i of the mesh is point i of the soup.
  for(const Mesh::Vertex_index v : mesh.vertices())
    soup.points[std::size_t(v)] = mesh.point(v);
}

py::list polylines_to_list(const BI::Crease_network& creases)
{
  return polygons_to_list(creases.polylines);
}

py::tuple boolean_isosurface_py(const py::handle& fields_object, const std::string& expr,
                                std::optional<std::array<std::size_t, 3>> grid, std::array<double, 6> box,
                                const py::handle& mesh_object, bool close, long long smooth, double lambda, double mu,
                                std::size_t slab_layers, int threads)
{
  if(grid.has_value() == !mesh_object.is_none())
    throw BI::Invalid_input_error("give exactly one domain: grid=(nx, ny, nz) or mesh=(X, T)");
  if(smooth < 0)
    throw BI::Invalid_input_error("smooth must be >= 0 (lambda|mu iterations), got " + std::to_string(smooth));
  const BI::Boolean_expression expression = BI::Boolean_expression::parse(expr);
  std::optional<Grid> grid_domain;
  std::optional<Tet_mesh> mesh_domain;
  if(grid)
    grid_domain.emplace(grid_from(*grid, box));
  else
    mesh_domain.emplace(tet_mesh_from(mesh_object));
  BI::Scalar_fields fields = fields_from(fields_object);

  Soup soup;
  BI::Crease_network creases;
  BI::Boolean_isosurface_statistics stats;
  double crease_seconds = 0, smoothing_seconds = 0;
  std::optional<double> volume;
  {
    py::gil_scoped_release release;
    const auto np = BI::parameters::close_at_domain_boundary(close, BI::parameters::slab_layers(slab_layers))
                        .callback(python_signals_callback());
    stats = with_threads(threads, [&] {
      return grid_domain ? BI::extract_boolean_isosurface<CGAL::Parallel_if_available_tag>(*grid_domain, fields,
                                                                                             expression, soup, np)
                         : BI::extract_boolean_isosurface<CGAL::Parallel_if_available_tag>(*mesh_domain, fields,
                                                                                             expression, soup, np);
    });
    BI::Scalar_fields().data().swap(fields.data()); // release early
    auto start = std::chrono::steady_clock::now();
    creases = BI::extract_crease_network(soup);
    crease_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(smooth > 0)
    {
      start = std::chrono::steady_clock::now();
      smooth_soup(soup, creases, smooth, lambda, mu, true);
      smoothing_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    volume = closed_volume(soup);
  }
  py::dict info;
  info["expression"] = expression.to_string();
  info["number_of_tetrahedra"] = stats.number_of_tetrahedra;
  info["number_of_evaluated_tetrahedra"] = stats.number_of_evaluated_tetrahedra;
  info["number_of_crease_edges"] = creases.number_of_crease_edges;
  info["closed"] = volume.has_value();
  info["volume"] = volume;
  info["seconds_table"] = stats.seconds_tables;
  info["seconds_extraction"] = stats.seconds_extraction;
  info["seconds_welding"] = stats.seconds_welding;
  info["seconds_creases"] = crease_seconds;
  info["seconds_smoothing"] = smoothing_seconds;
  py::array_t<int> labels(py::ssize_t(soup.face_fields.size()));
  std::memcpy(labels.mutable_data(), soup.face_fields.data(), soup.face_fields.size() * sizeof(int));
  py::list polygons = polygons_to_list(soup.polygons);
  py::list polylines = polylines_to_list(creases);
  py::array_t<std::int64_t> corners = index_array(std::move(creases.corners));
  return py::make_tuple(points_array(std::move(soup.points)), polygons, labels, polylines, corners, info);
}

py::array_t<double> grid_points_py(std::array<std::size_t, 3> counts, std::array<double, 6> box)
{
  const Grid grid = grid_from(counts, box);
  std::vector<std::array<double, 3>> points(grid.number_of_vertices());
  {
    py::gil_scoped_release release;
    for(std::size_t v = 0; v < points.size(); ++v)
      points[v] = grid.position(v);
  }
  return points_array(std::move(points));
}

// A soup from (V, polygons, labels), checked.
Soup soup_from(const py::handle& V_object, const py::handle& polygons_object, const py::handle& labels_object)
{
  const Double_array V = as_double_rows(V_object, 3, "V");
  Soup soup;
  soup.points = copy_points(V);
  soup.polygons = polygons_from(polygons_object, soup.points.size());
  if(labels_object.is_none())
    soup.face_fields.assign(soup.polygons.size(), 0);
  else
  {
    const py::array a = py::array::ensure(labels_object);
    if(!a || a.ndim() != 1 || (a.size() != 0 && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
      throw BI::Invalid_input_error("labels must be a 1-D array of integers");
    const auto labels = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if(std::size_t(labels.size()) != soup.polygons.size())
      throw BI::Invalid_input_error("labels has " + std::to_string(labels.size()) + " entries but there are " +
                                    std::to_string(soup.polygons.size()) + " polygons");
    for(py::ssize_t p = 0; p < labels.size(); ++p)
    {
      const std::int64_t l = labels.data()[p];
      if(l < -1 || l > std::numeric_limits<int>::max())
        throw BI::Invalid_input_error("labels[" + std::to_string(p) + "] is " + std::to_string(l) +
                                      "; a label is a field index or -1 (the domain boundary)");
      soup.face_fields.push_back(int(l));
    }
  }
  return soup;
}

py::array_t<double> smooth_py(const py::handle& V, const py::handle& polygons, const py::handle& labels,
                              long long iterations, double lambda, double mu, bool keep_creases)
{
  Soup soup = soup_from(V, polygons, labels);
  {
    py::gil_scoped_release release;
    const BI::Crease_network creases = BI::extract_crease_network(soup);
    smooth_soup(soup, creases, iterations, lambda, mu, keep_creases);
  }
  return points_array(std::move(soup.points));
}

py::tuple crease_network_py(const py::handle& V, const py::handle& polygons, const py::handle& labels)
{
  const Soup soup = soup_from(V, polygons, labels);
  BI::Crease_network creases;
  {
    py::gil_scoped_release release;
    creases = BI::extract_crease_network(soup);
  }
  py::list polylines = polylines_to_list(creases);
  return py::make_tuple(polylines, index_array(std::move(creases.corners)));
}

// ---------------------------------------------------------------- files

// The writers throw std::runtime_error when the file cannot be written:
// OSError, not RuntimeError.
template <typename F>
void write_file(const std::string& path, F&& write)
{
  check_writable(path);
  try
  {
    py::gil_scoped_release release;
    write();
  }
  catch(const BI::Invalid_input_error&)
  {
    throw;
  }
  catch(const std::runtime_error& e)
  {
    throw File_error(EIO, e.what(), path);
  }
}

py::tuple read_tetrahedral_mesh_py(const std::string& path)
{
  check_readable(path);
  std::optional<Tet_mesh> mesh;
  {
    py::gil_scoped_release release;
    mesh.emplace(BI::IO::read_tetrahedral_mesh<K>(path));
  }
  std::vector<Point_3> points = mesh->points();
  std::vector<std::array<std::size_t, 4>> tetrahedra = mesh->tetrahedra();
  return py::make_tuple(points_array(std::move(points)), index_array(std::move(tetrahedra)));
}

void write_tetrahedral_mesh_py(const std::string& path, const py::handle& X, const py::handle& T)
{
  const Tet_mesh mesh = tet_mesh_from(py::make_tuple(X, T));
  write_file(path, [&] { BI::IO::write_MEDIT(path, mesh); });
}

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

py::array_t<double> read_fields_py(const std::string& path, std::size_t number_of_vertices,
                                   std::size_t number_of_fields)
{
  check_readable(path);
  BI::Scalar_fields fields;
  {
    py::gil_scoped_release release;
    fields = BI::IO::read_scalar_fields(path, number_of_vertices, number_of_fields);
  }
  const py::ssize_t n = py::ssize_t(fields.number_of_vertices()), N = py::ssize_t(fields.number_of_fields());
  return owning_array<double>(std::move(fields.data()), {n, N});
}

void write_fields_py(const std::string& path, const py::handle& fields_object)
{
  const BI::Scalar_fields fields = fields_from(fields_object);
  const std::string e = extension_of(path);
  if(e == "raw" || e == "f64" || e == "f32")
    write_file(path, [&] {
      BI::IO::write_raw_scalar_fields(path, fields,
                                      e == "f32" ? BI::IO::Raw_scalar_type::FLOAT32 : BI::IO::Raw_scalar_type::FLOAT64);
    });
  else
    write_file(path, [&] { BI::IO::write_text_scalar_fields(path, fields); });
}

py::tuple read_isosurface_ply_py(const std::string& path)
{
  check_readable(path);
  Soup soup;
  {
    py::gil_scoped_release release;
    BI::IO::read_PLY_with_fields(path, soup);
  }
  py::array_t<int> labels(py::ssize_t(soup.face_fields.size()));
  std::memcpy(labels.mutable_data(), soup.face_fields.data(), soup.face_fields.size() * sizeof(int));
  py::list polygons = polygons_to_list(soup.polygons);
  return py::make_tuple(points_array(std::move(soup.points)), polygons, labels);
}

void write_isosurface_ply_py(const std::string& path, const py::handle& V, const py::handle& polygons,
                             const py::handle& labels, bool binary)
{
  const Soup soup = soup_from(V, polygons, labels);
  write_file(path, [&] { BI::IO::write_PLY_with_fields(path, soup, binary); });
}

BI::Crease_network network_from(const py::handle& polylines, const py::handle& corners, std::size_t n)
{
  BI::Crease_network creases;
  if(!polylines.is_none())
  {
    if(!py::isinstance<py::sequence>(polylines))
      throw BI::Invalid_input_error("creases must be a list of index sequences");
    for(const py::handle item : polylines)
    {
      const py::array a = py::array::ensure(item);
      if(!a || a.ndim() != 1 || (a.size() != 0 && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
        throw BI::Invalid_input_error("a crease polyline is not a 1-D sequence of integers");
      const auto line = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
      std::vector<std::size_t> chain;
      for(py::ssize_t i = 0; i < line.size(); ++i)
      {
        if(line.data()[i] < 0 || std::uint64_t(line.data()[i]) >= n)
          throw BI::Invalid_input_error("crease polyline " + std::to_string(creases.polylines.size()) +
                                        " refers to V row " + std::to_string(line.data()[i]) + ", but there are " +
                                        std::to_string(n));
        chain.push_back(std::size_t(line.data()[i]));
      }
      creases.polylines.push_back(std::move(chain));
    }
  }
  if(!corners.is_none())
  {
    const py::array a = py::array::ensure(corners);
    if(!a || a.ndim() != 1 || (a.size() != 0 && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
      throw BI::Invalid_input_error("corners must be a 1-D array of integers");
    const auto c = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for(py::ssize_t i = 0; i < c.size(); ++i)
    {
      if(c.data()[i] < 0 || std::uint64_t(c.data()[i]) >= n)
        throw BI::Invalid_input_error("corners[" + std::to_string(i) + "] refers to V row " +
                                      std::to_string(c.data()[i]) + ", but there are " + std::to_string(n));
      creases.corners.push_back(std::size_t(c.data()[i]));
    }
  }
  return creases;
}

void write_creases_py(const std::string& path, const py::handle& V_object, const py::handle& polylines)
{
  const std::vector<Point_3> points = copy_points(as_double_rows(V_object, 3, "V"));
  const BI::Crease_network creases = network_from(polylines, py::none(), points.size());
  write_file(path, [&] { BI::IO::write_polylines(path, points, creases); });
}

void write_corners_py(const std::string& path, const py::handle& V_object, const py::handle& corners)
{
  const std::vector<Point_3> points = copy_points(as_double_rows(V_object, 3, "V"));
  const BI::Crease_network creases = network_from(py::none(), corners, points.size());
  write_file(path, [&] { BI::IO::write_corners(path, points, creases); });
}

} // namespace

void bind_tbiso(py::module_& m)
{
  using namespace pybind11::literals;
  m.attr("taubin_default_lambda") = BI::taubin_default_lambda;
  m.attr("taubin_default_mu") = BI::taubin_default_mu;
  m.attr("taubin_default_number_of_iterations") = BI::taubin_default_number_of_iterations;

  m.def("boolean_isosurface", &boolean_isosurface_py, "fields"_a, "expr"_a, "grid"_a = py::none(),
        "box"_a = std::array<double, 6>{{-1, -1, -1, 1, 1, 1}}, "mesh"_a = py::none(), "close"_a = false,
        "smooth"_a = 0, "lambda_"_a = BI::taubin_default_lambda, "mu"_a = BI::taubin_default_mu,
        "slab_layers"_a = 0, "threads"_a = 0,
        R"doc(TBISO: the boundary of the Boolean set expr(f0, ..., f{N-1}), literal fi meaning f_i < 0.

Domain: grid=(nx, ny, nz) vertices spanning box=(x0, y0, z0, x1, y1, z1)
(6 Kuhn tetrahedra per cube; vertex (i, j, k) is row i + nx * (j + ny * k),
x fastest, see grid_points), or mesh=(X, T), X (n, 3) vertices and T (m, 4)
tetrahedra.  fields: (number_of_vertices, N) float64, one column per field
(a 1-D array is one field); copied once into the library's storage.
close=True closes the set where it reaches the boundary of the domain.
smooth=k runs k lambda|mu iterations of crease-preserving smoothing
(creases and corners stay put).  slab_layers: cube layers per parallel
task (0: the default); threads: TBB threads (0: all); the output does not
depend on either.  Ctrl-C (KeyboardInterrupt) stops the extraction between
batches of slabs.  Every combinatorial decision is exact.

Returns (V, polygons, labels, creases, corners, info): V (k, 3) float64;
polygons a list of int64 index arrays (convex, planar, outward); labels
(len(polygons),) the field each polygon lies on, -1 on the domain
boundary; creases a list of index polylines; corners an int64 index
array; info a dict with the counts, the time of each stage, "closed"
(every edge in two consistently oriented polygons) and "volume" (None
when not closed).)doc");

  m.def("grid_points", &grid_points_py, "grid"_a, "box"_a = std::array<double, 6>{{-1, -1, -1, 1, 1, 1}},
        "The (nx * ny * nz, 3) vertex positions of a TBISO grid, in the row order of its fields (x fastest).");

  m.def("crease_network", &crease_network_py, "V"_a, "polygons"_a, "labels"_a,
        "The crease polylines and corners of a labelled polygon soup: returns (creases, corners).");

  m.def("smooth_with_creases", &smooth_py, "V"_a, "polygons"_a, "labels"_a = py::none(),
        "iterations"_a = BI::taubin_default_number_of_iterations, "lambda_"_a = BI::taubin_default_lambda,
        "mu"_a = BI::taubin_default_mu, "keep_creases"_a = true,
        R"doc(Taubin lambda|mu smoothing of a polygon surface, keeping its creases and corners.

The creases are the edges between polygons of different labels (and the
border); crease vertices move along their crease only, corners (where
three labels meet, or creases end or branch) stay put.  With
keep_creases=False every vertex moves (plain lambda|mu).  The surface must
be a polygon mesh (manifold).  Returns the new V; the polygons are unchanged.)doc");

  m.def("read_tetrahedral_mesh", &read_tetrahedral_mesh_py, "path"_a,
        "Reads a Medit .mesh or TetGen .node/.ele mesh as (X, T); checked (conforming, no flat tetrahedron).");
  m.def("write_tetrahedral_mesh", &write_tetrahedral_mesh_py, "path"_a, "X"_a, "T"_a,
        "Writes (X, T) as a Medit .mesh file (17 significant digits).");
  m.def("read_fields", &read_fields_py, "path"_a, "number_of_vertices"_a = 0, "number_of_fields"_a = 0,
        R"doc(Reads scalar fields as a (number_of_vertices, N) array.

.raw / .f64: raw little-endian float64, .f32: raw float32 (both need
number_of_vertices and number_of_fields); anything else: the text layout,
which states N itself.)doc");
  m.def("write_fields", &write_fields_py, "path"_a, "fields"_a,
        "Writes scalar fields: raw float64 (.raw, .f64), raw float32 (.f32) or text (any other extension).");
  m.def("read_isosurface_ply", &read_isosurface_ply_py, "path"_a,
        "Reads a PLY surface with a face 'field' label: returns (V, polygons, labels).");
  m.def("write_isosurface_ply", &write_isosurface_ply_py, "path"_a, "V"_a, "polygons"_a, "labels"_a,
        "binary"_a = false, "Writes a labelled polygon surface as PLY with a 'field' and a colour per face.");
  m.def("write_creases", &write_creases_py, "path"_a, "V"_a, "creases"_a,
        "Writes crease polylines in CGAL's polylines text format ('n x1 y1 z1 ... xn yn zn' per line).");
  m.def("write_corners", &write_corners_py, "path"_a, "V"_a, "corners"_a,
        "Writes corners as 'x y z' lines.");
}

} // namespace biso_python
