// The fields of `tbiso --field SPEC`, shared by tbiso.cpp (in core and
// --out-of-core) and tbiso_distributed.cpp (--distributed): the parsing of
// the specs, the functions, and `Analytic_field_source`, which evaluates them
// at the grid vertices a slab (or an MPI rank's range) asks for, so that no
// process ever holds more than the values it reads.

#ifndef BISO_TOOLS_TBISO_FIELDS_H
#define BISO_TOOLS_TBISO_FIELDS_H

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tbiso_fields {

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef std::function<double(const Point&)> Field;

// Every error the user can cause: reported on one line, exit status 1.
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

inline double parse_double(const std::string& text, const std::string& what)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    throw Error(what + ": '" + text + "' is not a finite number");
  return v;
}

inline std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts(1);
  for(char c : text)
    if(c == separator)
      parts.emplace_back();
    else
      parts.back() += c;
  return parts;
}

inline std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& what)
{
  const std::vector<std::string> parts = split(text, ',');
  if(parts.size() != count)
    throw Error(what + ": expected " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
  std::vector<double> values;
  for(const std::string& p : parts)
    values.push_back(parse_double(p, what));
  return values;
}

// Signed distance to a closed triangle mesh: an AABB tree for the distance,
// ray parity (exact predicates) for the sign, so that points on the surface
// get exactly 0.  The tree is built before any query, so concurrent queries
// are safe.
class Signed_distance_to_mesh
{
  typedef CGAL::Side_of_triangle_mesh<Surface_mesh, K> Side;
  typedef Side::AABB_tree Tree;

public:
  explicit Signed_distance_to_mesh(const std::string& path)
  {
    try
    {
      BI::IO::read_closed_triangle_mesh(path, m_mesh);
    }
    catch(const BI::Invalid_input_error& e)
    {
      throw Error("--field distance:" + path + ": " + e.what());
    }
    m_tree = std::make_unique<Tree>(faces(m_mesh).first, faces(m_mesh).second, m_mesh);
    m_tree->build();
    m_tree->accelerate_distance_queries();
    m_side = std::make_unique<Side>(*m_tree);
  }

  double operator()(const Point& p) const
  {
    const CGAL::Bounded_side side = (*m_side)(p);
    if(side == CGAL::ON_BOUNDARY)
      return 0;
    const double d = std::sqrt(CGAL::to_double(m_tree->squared_distance(p)));
    return side == CGAL::ON_BOUNDED_SIDE ? -d : d;
  }

  std::size_t number_of_faces() const { return m_mesh.number_of_faces(); }

private:
  Surface_mesh m_mesh;
  std::unique_ptr<Tree> m_tree;
  std::unique_ptr<Side> m_side;
};

inline Field make_field(const std::string& spec)
{
  const std::size_t colon = spec.find(':');
  if(colon == std::string::npos)
    throw Error("--field '" + spec + "': expected KIND:PARAMETERS (see tbiso --help)");
  const std::string kind = spec.substr(0, colon), rest = spec.substr(colon + 1);
  const std::string what = "--field " + spec;
  if(kind == "sphere")
  {
    const std::vector<double> v = parse_numbers(rest, 4, what);
    if(!(v[3] > 0))
      throw Error(what + ": the radius must be positive");
    const double cx = v[0], cy = v[1], cz = v[2], r = v[3];
    return [=](const Point& p) {
      const double x = p.x() - cx, y = p.y() - cy, z = p.z() - cz;
      return std::sqrt(x * x + y * y + z * z) - r;
    };
  }
  if(kind == "plane")
  {
    const std::vector<double> v = parse_numbers(rest, 4, what);
    if(v[0] == 0 && v[1] == 0 && v[2] == 0)
      throw Error(what + ": the normal (A,B,C) is zero");
    const double a = v[0], b = v[1], c = v[2], d = v[3];
    return [=](const Point& p) { return a * p.x() + b * p.y() + c * p.z() + d; };
  }
  if(kind == "box")
  {
    const std::vector<double> v = parse_numbers(rest, 6, what);
    for(int a = 0; a < 3; ++a)
      if(!(v[a] < v[a + 3]))
        throw Error(what + ": the minimum must be below the maximum on every axis");
    const std::array<double, 3> lo{v[0], v[1], v[2]}, hi{v[3], v[4], v[5]};
    // Exact distance: Euclidean outside, to the nearest face inside.  Each
    // coordinate offset is a difference with a box bound, so a point on a
    // face plane gets exactly 0 there.
    return [=](const Point& p) {
      const double x[3] = {p.x(), p.y(), p.z()};
      double outside = 0, inside = -std::numeric_limits<double>::infinity();
      for(int a = 0; a < 3; ++a)
      {
        const double q = std::max(lo[a] - x[a], x[a] - hi[a]);
        inside = std::max(inside, q);
        if(q > 0)
          outside += q * q;
      }
      return outside > 0 ? std::sqrt(outside) : inside;
    };
  }
  if(kind == "cylinder")
  {
    const std::vector<std::string> parts = split(rest, ',');
    if(parts.size() != 4 || parts[0].size() != 1 || std::string("xyz").find(parts[0][0]) == std::string::npos)
      throw Error(what + ": expected cylinder:AXIS,C1,C2,R with AXIS x, y or z");
    const int axis = int(parts[0][0] - 'x');
    const double c1 = parse_double(parts[1], what), c2 = parse_double(parts[2], what), r = parse_double(parts[3], what);
    if(!(r > 0))
      throw Error(what + ": the radius must be positive");
    return [=](const Point& p) {
      const double x[3] = {p.x(), p.y(), p.z()};
      // The other two axes in increasing order: x -> (y, z), y -> (x, z), z -> (x, y).
      const double u = x[axis == 0 ? 1 : 0] - c1, w = x[axis == 2 ? 1 : 2] - c2;
      return std::sqrt(u * u + w * w) - r;
    };
  }
  if(kind == "torus")
  {
    const std::vector<double> v = parse_numbers(rest, 2, what);
    if(!(v[1] > 0) || !(v[0] >= 0))
      throw Error(what + ": expected R >= 0 and r > 0");
    const double R = v[0], r = v[1];
    return [=](const Point& p) {
      const double q = std::sqrt(p.x() * p.x() + p.y() * p.y()) - R;
      return std::sqrt(q * q + p.z() * p.z()) - r;
    };
  }
  if(kind == "distance")
  {
    if(rest.empty())
      throw Error(what + ": expected distance:MESHFILE");
    const std::shared_ptr<const Signed_distance_to_mesh> distance = std::make_shared<Signed_distance_to_mesh>(rest);
    return [distance](const Point& p) { return (*distance)(p); };
  }
  throw Error("--field '" + spec + "': unknown kind '" + kind + "' (sphere, plane, box, cylinder, torus, distance)");
}

// A ScalarFieldSource evaluating the functions at the grid's vertices:
// vertex v has the values functions[i](grid.point(v)), the doubles the
// in-core sampling gives.
class Analytic_field_source
{
public:
  Analytic_field_source(const CGAL::Boolean_isosurfacing::Tetrahedral_grid_3<K>& grid, std::vector<Field> functions)
    : m_grid(grid), m_functions(std::move(functions))
  {}
  std::size_t number_of_fields() const { return m_functions.size(); }
  void read(std::size_t first, std::size_t count, std::vector<double>& values)
  {
    if(first > m_grid.number_of_vertices() || count > m_grid.number_of_vertices() - first)
      throw std::out_of_range("vertices [" + std::to_string(first) + ", " + std::to_string(first + count) +
                              ") are not within the grid");
    const std::size_t n = m_functions.size();
    values.resize(count * n);
    for(std::size_t v = 0; v < count; ++v)
    {
      const Point p = m_grid.point(first + v);
      for(std::size_t i = 0; i < n; ++i)
        values[v * n + i] = m_functions[i](p);
    }
    m_evaluated += count;
  }
  // Vertices evaluated so far (the ghost layers counted again).
  std::size_t evaluated_vertices() const { return m_evaluated; }

private:
  const CGAL::Boolean_isosurfacing::Tetrahedral_grid_3<K>& m_grid;
  std::vector<Field> m_functions;
  std::size_t m_evaluated = 0;
};

} // namespace tbiso_fields

#endif // BISO_TOOLS_TBISO_FIELDS_H
