// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_CREASE_PRESERVING_SMOOTHING_H
#define CGAL_BOOLEAN_ISOSURFACING_3_CREASE_PRESERVING_SMOOTHING_H

// Taubin's lambda|mu smoothing, plain and hierarchical.  The seed (Taubin &
// Sibley, "Extracting Boolean isosurfaces from tetrahedral meshes") extracts
// crease polylines and corners together with the surface precisely so that
// they survive smoothing: a crease vertex is smoothed as a point of its
// polyline, a corner not at all.
//
// CGAL 5.5 already finds creases from the geometry
// (`CGAL::Polygon_mesh_processing::detect_sharp_edges()`), so this header
// does not: its output is a valid `edge_is_constrained_map` here.

#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Taubin's default positive factor: with `taubin_default_mu` it gives the
/// pass-band frequency k_PB = 1/lambda + 1/mu ~= 0.1 ("A signal processing
/// approach to fair surface design", SIGGRAPH 1995), which keeps the shape
/// and removes the noise at the scale of a few edges.
constexpr double taubin_default_lambda = 0.6307;

/// \ingroup PkgBooleanIsosurfacing3Ref
/// Taubin's default negative factor; see `taubin_default_lambda`.
constexpr double taubin_default_mu = -0.6732;

/// \ingroup PkgBooleanIsosurfacing3Ref
/// The number of lambda|mu iterations (one lambda step followed by one mu
/// step) done when `CGAL::parameters::number_of_iterations` is not passed.
constexpr int taubin_default_number_of_iterations = 10;

namespace internal {

// The umbrella operator of a fixed neighbourhood structure, on positions
// copied to flat arrays.
//
// Why flat arrays (CSR: `m_first` / `m_neighbours`) rather than BGL
// circulators at every step: the neighbourhoods never change while
// smoothing, a step is memory bound, and a circulator plus a property-map
// lookup per neighbour costs several times a sequential array read.  Building
// the arrays once is O(V + E); every step is then O(V + E) with no allocation
// (the displacement buffer is reused), so the cost of many iterations is
// predictable.
class Umbrella_operator
{
public:
  typedef std::uint32_t Slot;

  explicit Umbrella_operator(std::size_t number_of_slots) : m_xyz(3 * number_of_slots, 0.0) {}

  void set_position(Slot s, double x, double y, double z)
  {
    m_xyz[3 * s] = x;
    m_xyz[3 * s + 1] = y;
    m_xyz[3 * s + 2] = z;
  }

  const double* position(Slot s) const { return &m_xyz[3 * s]; }

  // Appends a moving vertex; its neighbours follow with `add_neighbour`.
  void begin_moving_vertex(Slot s)
  {
    if(m_first.empty())
      m_first.push_back(0);
    m_moving.push_back(s);
    m_first.push_back(Slot(m_neighbours.size()));
  }

  void add_neighbour(Slot s)
  {
    m_neighbours.push_back(s);
    ++m_first.back();
  }

  std::size_t number_of_moving_vertices() const { return m_moving.size(); }
  Slot moving_vertex(std::size_t m) const { return m_moving[m]; }

  // One Jacobi step p <- p + factor * (mean of neighbours - p): all
  // displacements are computed from the current positions before any is
  // applied, so the result does not depend on the vertex order.
  void step(double factor)
  {
    const std::size_t n = m_moving.size();
    m_displacement.resize(3 * n); // allocates on the first step only
    for(std::size_t m = 0; m < n; ++m)
    {
      const Slot begin = m_first[m], end = m_first[m + 1];
      double sx = 0, sy = 0, sz = 0;
      for(Slot k = begin; k < end; ++k)
      {
        const double* q = &m_xyz[3 * std::size_t(m_neighbours[k])];
        sx += q[0];
        sy += q[1];
        sz += q[2];
      }
      const double inverse_count = 1.0 / double(end - begin);
      const double* p = &m_xyz[3 * std::size_t(m_moving[m])];
      m_displacement[3 * m] = factor * (sx * inverse_count - p[0]);
      m_displacement[3 * m + 1] = factor * (sy * inverse_count - p[1]);
      m_displacement[3 * m + 2] = factor * (sz * inverse_count - p[2]);
    }
    for(std::size_t m = 0; m < n; ++m)
    {
      double* p = &m_xyz[3 * std::size_t(m_moving[m])];
      p[0] += m_displacement[3 * m];
      p[1] += m_displacement[3 * m + 1];
      p[2] += m_displacement[3 * m + 2];
    }
  }

  // Factors outside the stable range make the high frequencies grow without
  // bound; checking once at the end (before anything is written back to the
  // mesh) costs O(V) and leaves the mesh untouched on that error.
  bool moving_positions_are_finite() const
  {
    for(const Slot s : m_moving)
      for(int i = 0; i < 3; ++i)
        if(!std::isfinite(m_xyz[3 * std::size_t(s) + i]))
          return false;
    return true;
  }

private:
  std::vector<double> m_xyz;         // 3 coordinates per vertex slot
  std::vector<Slot> m_moving;        // slots of the vertices that move
  std::vector<Slot> m_first;         // CSR offsets into m_neighbours, size |m_moving| + 1
  std::vector<Slot> m_neighbours;    // slots of the neighbours, vertex after vertex
  std::vector<double> m_displacement; // 3 per moving vertex, reused by every step
};

// How a vertex is smoothed: the hierarchy of the seed (corners over creases
// over surface).
enum class Vertex_role : unsigned char { fixed, crease, surface };

template <typename FT>
void check_lambda_mu(const FT& lambda_value, const FT& mu_value)
{
  const double lambda = CGAL::to_double(lambda_value), mu = CGAL::to_double(mu_value);
  // Written so that NaN fails every test.
  if(!(lambda > 0) || !std::isfinite(lambda))
  {
    std::ostringstream out;
    out << "lambda|mu smoothing: lambda must be a finite number > 0, got " << lambda;
    throw Invalid_input_error(out.str());
  }
  if(!(mu < -lambda) || !std::isfinite(mu))
  {
    std::ostringstream out;
    out << "lambda|mu smoothing: mu must be finite and < -lambda (so that the surface does not shrink), got lambda = "
        << lambda << ", mu = " << mu;
    throw Invalid_input_error(out.str());
  }
}

template <typename NamedParameters>
long long number_of_lambda_mu_iterations(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                           taubin_default_number_of_iterations);
  static_assert(std::is_integral<std::decay_t<decltype(iterations)>>::value,
                "number_of_iterations must be an integer");
  if constexpr(std::is_signed<std::decay_t<decltype(iterations)>>::value)
    if(iterations < 0)
      throw Invalid_input_error("lambda|mu smoothing: number_of_iterations must be >= 0, got " +
                                std::to_string(iterations));
  return static_cast<long long>(iterations);
}

// Copies the positions into an Umbrella_operator, lists the moving vertices
// with the neighbours `role_of` asks for, runs the iterations and writes the
// moved vertices back.  `role_of(v)` returns the role of v;
// `is_crease(e)` tells whether e is a crease edge (consulted for crease
// vertices only).  Fixed vertices are never written, so their points stay
// exactly as they were, also with exact number types.
template <typename PolygonMesh, typename VertexIndexMap>
std::size_t number_of_vertex_slots(const PolygonMesh& mesh, const VertexIndexMap& vim)
{
  // Slots are the vertex indices; a Surface_mesh with removed vertices has
  // gaps in them, which only cost unused slots.
  std::size_t number_of_slots = 0;
  for(const auto v : vertices(mesh))
    number_of_slots = (std::max)(number_of_slots, std::size_t(get(vim, v)) + 1);
  if(number_of_slots > std::size_t((std::numeric_limits<Umbrella_operator::Slot>::max)()))
    throw Invalid_input_error("lambda|mu smoothing: more than 2^32 - 1 vertices");
  return number_of_slots;
}

template <typename PolygonMesh, typename NamedParameters, typename VertexIndexMap, typename RoleOf,
          typename IsCrease>
void run_lambda_mu(PolygonMesh& mesh, double lambda, double mu, long long iterations, const NamedParameters& np,
                   const VertexIndexMap& vim, const RoleOf& role_of, const IsCrease& is_crease)
{
  typedef boost::graph_traits<PolygonMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename CGAL::GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef Umbrella_operator::Slot Slot;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, mesh));
  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));

  const auto x = gt.compute_x_3_object();
  const auto y = gt.compute_y_3_object();
  const auto z = gt.compute_z_3_object();
  Umbrella_operator umbrella(number_of_vertex_slots(mesh, vim));
  for(const vertex_descriptor v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    const double px = CGAL::to_double(x(p)), py = CGAL::to_double(y(p)), pz = CGAL::to_double(z(p));
    if(!(std::isfinite(px) && std::isfinite(py) && std::isfinite(pz)))
    {
      std::ostringstream out;
      out << "lambda|mu smoothing: vertex #" << get(vim, v) << " has a non-finite coordinate (" << px << ' ' << py
          << ' ' << pz << ")";
      throw Non_finite_value_error(out.str());
    }
    umbrella.set_position(Slot(get(vim, v)), px, py, pz);
  }
  if(iterations == 0)
    return;

  std::vector<vertex_descriptor> moving;
  for(const vertex_descriptor v : vertices(mesh))
  {
    const Vertex_role role = role_of(v);
    // An isolated vertex has no neighbours to average.
    if(role == Vertex_role::fixed || halfedge(v, mesh) == Graph_traits::null_halfedge())
      continue;
    umbrella.begin_moving_vertex(Slot(get(vim, v)));
    moving.push_back(v);
    for(const halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh))
      if(role == Vertex_role::surface || is_crease(edge(h, mesh)))
        umbrella.add_neighbour(Slot(get(vim, source(h, mesh))));
  }

  for(long long i = 0; i < iterations; ++i)
  {
    umbrella.step(lambda); // shrinks (a Gaussian-like low-pass step) ...
    umbrella.step(mu);     // ... and this larger negative step expands back
  }
  if(!umbrella.moving_positions_are_finite())
  {
    std::ostringstream out;
    out << "lambda|mu smoothing diverged (lambda = " << lambda << ", mu = " << mu
        << "): |(1 - 2 lambda)(1 - 2 mu)| must not exceed 1 for the iteration to be stable";
    throw Non_finite_value_error(out.str());
  }

  const auto construct_point = gt.construct_point_3_object();
  for(std::size_t m = 0; m < moving.size(); ++m)
  {
    const double* p = umbrella.position(umbrella.moving_vertex(m));
    put(vpm, moving[m], construct_point(FT(p[0]), FT(p[1]), FT(p[2])));
  }
}

} // namespace internal

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * smooths `mesh` with Taubin's lambda|mu algorithm applied *hierarchically*,
 * as Taubin & Sibley do with the crease polylines and corners of a Boolean
 * isosurface, so that creases stay sharp and corners stay put:
 *
 * - a *corner* does not move;
 * - a *crease vertex* (exactly two incident crease edges) moves only along
 *   its crease polyline: the 1-D umbrella operator over its two crease
 *   neighbours;
 * - every other vertex uses the umbrella operator over all its neighbours
 *   (the vertices joined to it by an edge, crease vertices and corners
 *   included).
 *
 * Each iteration is one step p <- p + lambda L(p) followed by one step
 * p <- p + mu L(p), where L(p) is the mean of the neighbours of p minus p.
 * A step computes all displacements from the current positions, then applies
 * them (Jacobi), so the result does not depend on the vertex order.  The
 * weights are uniform, as in Taubin's original; they ignore edge lengths, so
 * in-surface noise is smoothed as well as normal noise.  The positive step
 * shrinks, the larger negative one expands back: low frequencies (below
 * k_PB = 1/lambda + 1/mu) pass, high frequencies (noise) are attenuated, and
 * the surface does not shrink as with Laplacian smoothing.  (In the pass band
 * the gain is slightly above 1, about 1 - (lambda + mu) k for a small
 * frequency k, so a smooth closed surface grows a little: with the defaults,
 * +0.35 % in volume for a unit icosphere of 2562 vertices after 10
 * iterations, where 10 Laplacian steps shrink it by 5.3 %.)
 *
 * Creases: the edges marked by `edge_is_constrained_map` and, for a surface
 * with border, the border edges (the border is a crease of the surface: a
 * border vertex then slides along the border instead of pulling it inward).
 * Corners: the vertices marked by `vertex_is_constrained_map` and, always,
 * the vertices with a number of incident crease edges other than 0 and 2
 * (endpoints and branch points of the crease network, where the 1-D operator
 * is undefined).  So the cube's 8 corners are found from its 12 crease
 * polylines, but the 4 corners of a square patch, where two border edges
 * meet, must be marked (they are crease vertices of a closed border loop).
 *
 * Works for polygon meshes, not only triangle meshes: only the edges are
 * used.  Cost: O(V + E) to set up, then O(V + E) per step.  The coordinates
 * are processed as doubles; fixed vertices are never written back.
 *
 * \tparam TriangleOrPolygonMesh a model of `FaceGraph` and `VertexListGraph`
 *         (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
 * \tparam NamedParameters a sequence of named parameters
 *
 * \param mesh the surface; its vertex points are replaced
 * \param lambda the positive factor, default `taubin_default_lambda` (0.6307)
 * \param mu the negative factor, default `taubin_default_mu` (-0.6732)
 * \param np an optional sequence of CGAL's named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{lambda|mu iterations (2 steps each), an integer >= 0}
 *     \cgalParamType{an integer} \cgalParamDefault{`taubin_default_number_of_iterations` (10)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{the crease edges, for example filled by `CGAL::Polygon_mesh_processing::detect_sharp_edges()` or by the extraction of a Boolean isosurface}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{no crease (only the border)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{vertices that must not move, in addition to the corners found from the crease degree}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the positions of the vertices, replaced by the smoothed ones}
 *     \cgalParamType{a model of `ReadWritePropertyMap` from `vertex_descriptor` to the point type} \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{indices in [0, n) for the vertices}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `std::size_t`} \cgalParamDefault{the mesh's own, or a dynamic map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel (`Compute_x_3`...`Compute_z_3`, `Construct_point_3`)} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \pre the smoothing is stable for uniform weights when
 *      |(1 - 2 lambda)(1 - 2 mu)| <= 1 (true for the defaults).
 *
 * \throws Invalid_input_error if `lambda` <= 0, `mu` >= -`lambda`, either is
 *         not finite, or `number_of_iterations` < 0.
 * \throws Non_finite_value_error if a vertex has a NaN or infinite
 *         coordinate, or if the iteration diverged (factors far outside the
 *         stable range).  On any exception `mesh` is left unchanged.
 */
template <typename TriangleOrPolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void smooth_with_creases(TriangleOrPolygonMesh& mesh, double lambda, double mu,
                         const CGAL_NP_CLASS& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleOrPolygonMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::edge_descriptor edge_descriptor;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
      CGAL::internal_np::edge_is_constrained_t, CGAL_NP_CLASS,
      CGAL::Static_boolean_property_map<edge_descriptor, false>>::type Edge_is_crease_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
      CGAL::internal_np::vertex_is_constrained_t, CGAL_NP_CLASS,
      CGAL::Static_boolean_property_map<vertex_descriptor, false>>::type Vertex_is_corner_map;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  internal::check_lambda_mu(lambda, mu);
  const long long iterations = internal::number_of_lambda_mu_iterations(np);
  const Edge_is_crease_map ecm = choose_parameter<Edge_is_crease_map>(
      get_parameter(np, CGAL::internal_np::edge_is_constrained));
  const Vertex_is_corner_map vcm = choose_parameter<Vertex_is_corner_map>(
      get_parameter(np, CGAL::internal_np::vertex_is_constrained));

  const auto is_crease = [&](const edge_descriptor e) {
    return CGAL::is_border(e, mesh) || bool(get(ecm, e));
  };

  // Crease degree of every vertex: one pass over the edges.
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<std::uint32_t> crease_degree(internal::number_of_vertex_slots(mesh, vim), 0);
  for(const edge_descriptor e : edges(mesh))
    if(is_crease(e))
    {
      ++crease_degree[get(vim, source(e, mesh))];
      ++crease_degree[get(vim, target(e, mesh))];
    }

  const auto role_of = [&](const vertex_descriptor v) {
    const std::uint32_t degree = crease_degree[get(vim, v)];
    if(bool(get(vcm, v)) || (degree != 0 && degree != 2))
      return internal::Vertex_role::fixed;
    return degree == 2 ? internal::Vertex_role::crease : internal::Vertex_role::surface;
  };
  internal::run_lambda_mu(mesh, lambda, mu, iterations, np, vim, role_of, is_crease);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * `smooth_with_creases()` with Taubin's default factors
 * (`taubin_default_lambda`, `taubin_default_mu`): for example
 * `smooth_with_creases(mesh, CGAL::parameters::edge_is_constrained_map(ecm))`.
 *
 * \param mesh the surface; its vertex points are replaced
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{lambda|mu iterations (2 steps each), an integer >= 0}
 *     \cgalParamType{an integer} \cgalParamDefault{`taubin_default_number_of_iterations` (10)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{the crease edges}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `edge_descriptor` to `bool`} \cgalParamDefault{no crease (only the border)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{vertices that must not move, in addition to the corners found from the crease degree}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `bool`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the positions of the vertices, replaced by the smoothed ones}
 *     \cgalParamType{a model of `ReadWritePropertyMap` from `vertex_descriptor` to the point type} \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{indices in [0, n) for the vertices}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `std::size_t`} \cgalParamDefault{the mesh's own, or a dynamic map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 */
template <typename TriangleOrPolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void smooth_with_creases(TriangleOrPolygonMesh& mesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  smooth_with_creases(mesh, taubin_default_lambda, taubin_default_mu, np);
}

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * smooths `mesh` with Taubin's lambda|mu algorithm *without* hierarchy: every
 * vertex, on a crease, a corner or the border included, moves by the umbrella
 * operator over all its neighbours, and nothing is fixed.  On a closed mesh
 * without creases it gives the same result as `smooth_with_creases()`; on a
 * piecewise smooth surface it rounds the creases and corners (it is the
 * baseline the hierarchical version is measured against).
 *
 * Same parameters, defaults, cost and exceptions as `smooth_with_creases()`,
 * but `edge_is_constrained_map` and `vertex_is_constrained_map` are ignored.
 *
 * \param mesh the surface; its vertex points are replaced
 * \param lambda, mu the factors, as for `smooth_with_creases()`
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{lambda|mu iterations (2 steps each), an integer >= 0}
 *     \cgalParamType{an integer} \cgalParamDefault{`taubin_default_number_of_iterations` (10)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the positions of the vertices, replaced by the smoothed ones}
 *     \cgalParamType{a model of `ReadWritePropertyMap` from `vertex_descriptor` to the point type} \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{indices in [0, n) for the vertices}
 *     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `std::size_t`} \cgalParamDefault{the mesh's own, or a dynamic map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 */
template <typename TriangleOrPolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void plain_lambda_mu_smoothing(TriangleOrPolygonMesh& mesh, double lambda, double mu,
                               const CGAL_NP_CLASS& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleOrPolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleOrPolygonMesh>::edge_descriptor edge_descriptor;
  internal::check_lambda_mu(lambda, mu);
  const long long iterations = internal::number_of_lambda_mu_iterations(np);
  internal::run_lambda_mu(
      mesh, lambda, mu, iterations, np, CGAL::get_initialized_vertex_index_map(mesh, np),
      [](vertex_descriptor) { return internal::Vertex_role::surface; }, [](edge_descriptor) { return false; });
}

/// \ingroup PkgBooleanIsosurfacing3Ref
/// `plain_lambda_mu_smoothing()` with Taubin's default factors.
///
/// \param mesh the surface; its vertex points are replaced
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{lambda|mu iterations (2 steps each), an integer >= 0}
///     \cgalParamType{an integer} \cgalParamDefault{`taubin_default_number_of_iterations` (10)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices, replaced by the smoothed ones}
///     \cgalParamType{a model of `ReadWritePropertyMap` from `vertex_descriptor` to the point type} \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{indices in [0, n) for the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to `std::size_t`} \cgalParamDefault{the mesh's own, or a dynamic map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a CGAL kernel} \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleOrPolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void plain_lambda_mu_smoothing(TriangleOrPolygonMesh& mesh, const CGAL_NP_CLASS& np = parameters::default_values())
{
  plain_lambda_mu_smoothing(mesh, taubin_default_lambda, taubin_default_mu, np);
}

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_CREASE_PRESERVING_SMOOTHING_H
