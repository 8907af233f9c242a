// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_TANGENT_PLANE_SIGNED_DISTANCE_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_TANGENT_PLANE_SIGNED_DISTANCE_3_H

// The signed distance of Hoppe, DeRose, Duchamp, McDonald and Stuetzle,
// "Surface reconstruction from unorganized points" (SIGGRAPH 1992), as used by
// the contour-tracing assignment ([ContourTracing] in the manual's references):
//
//   f(p) = (p - o_i) . n_i,   i = the tangent plane whose centre o_i is nearest p,
//
// with o_i the centroid of the k nearest samples of x_i and n_i the direction
// of least variance of that neighbourhood (PCA), oriented consistently.  f is
// negative inside the sampled solid (normals point out).  f is *undefined*
// where the projection z = p - f(p) n_i of p onto the plane lies farther than
// rho + delta from every sample (rho: sampling density, delta: noise level),
// so that nothing is reconstructed far from the data.
//
// With input normals that face outward (stage 3 checks), f uses planes of
// the samples themselves instead: f(p) = (p - c_s) . n_s, with s the sample
// nearest p among the k neighbours of plane i's sample, n_s its input normal,
// and c_s the centroid of those of its k nearest samples whose input normals
// lie within 30 degrees of n_s (its own side of a sharp edge).  PCA blends the
// two sides of a sharp edge into one tilted plane whose centre is pulled
// inside, so Hoppe's zero set rounds every crease and corner off; the input
// normals do not, and the one-sided centroid still averages the noise along
// n_s.  The definition domain is Hoppe's; the winding number is asked as
// without normals, except next to sharp edges of clean samples (see
// all_input_normal_planes_agree()).
// Measured on 60K samples of four shared meshes (contouring.md), the
// Hausdorff distance to the source fell from 0.38-0.64 % to 0.31-0.44 % of
// the diagonal on clean samples, and from 0.64-0.80 % to 0.47-0.66 % with
// noise of half a spacing.
//
// Stages (each timed, see `timings()`):
//  1. k nearest neighbours of every sample (CGAL Spatial_searching, Kd_tree);
//  2. PCA of every neighbourhood (Eigen, closed-form 3x3 eigen solver);
//  3. orientation: flip each n_i towards the input normal of x_i when the
//     input has normals; otherwise Hoppe's propagation along a minimum
//     spanning forest (Kruskal, union-find) of the symmetric k-NN graph with
//     weights 1 - |n_i . n_j| + min(|n_i . e_ij|, |n_j . e_ij|) (e_ij the unit
//     edge direction: the second term keeps the tree from crossing thin
//     walls, see orient_by_minimum_spanning_forest), each tree rooted at its sample of largest z
//     whose normal is forced to +z (the top of a closed surface faces up);
//  4. the generalized winding number of the oriented samples (Barill et al.
//     2018, internal/Contouring/Winding_number.h), which decides the sign of
//     `consistent_value()` where Hoppe's nearest plane is contradicted.

#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Contouring/Winding_number.h>
#include <CGAL/Boolean_isosurfacing_3/internal/seconds_since.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>

#include <CGAL/Euclidean_distance.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 * Hoppe's tangent-plane signed distance of a point sample, ready to be
 * evaluated anywhere: `field(p)` is an empty optional where f is undefined.
 *
 * \tparam GeomTraits a CGAL kernel (`Point_3`, `Vector_3`, `FT` convertible
 *         to double); default `CGAL::Epick`.
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` (default) or
 *         `CGAL::Parallel_tag`: with the latter the k-NN queries and the
 *         plane fits of the construction run on TBB's threads.  The field is
 *         the same bit for bit (each sample's neighbours and plane are its
 *         own); the orientation, a propagation, stays sequential.
 *
 * Named parameters of the constructor (its reference lists them; the
 * defaults are explained here):
 *  - `point_map`, `normal_map` (CGAL's): how to read a point and, when the
 *    map is given, its (roughly) outward normal, used only to orient n_i;
 *  - `Boolean_isosurfacing::parameters::number_of_neighbors(k)`: k, default 15
 *    (the neighbourhood includes the sample itself);
 *  - `sampling_density(rho)`: Hoppe's rho, the radius of the largest disk on
 *    the surface free of samples.  Default 1.5 sqrt(15 / k) median_i d_k(i),
 *    d_k(i) the distance from sample i to its k-th nearest neighbour (itself
 *    included).  For a sample of density lambda, median d_k ~ sqrt(k / (pi
 *    lambda)), so the default is 1.5 sqrt(15 / (pi lambda)) whatever k; the
 *    largest empty disk of a *uniform random* sample of n points has radius
 *    about sqrt((ln n + ln ln n) / (pi lambda)), which this exceeds for any
 *    n with ln n + ln ln n < 33 (n < 10^13).  Measured: without the factor
 *    1.5, a clean 200K-point random torus sample left 3 undefined lattice
 *    points near the surface (holes);
 *  - `noise_level(delta)`: default twice the median, over the samples, of the
 *    RMS distance of the neighbourhood to its PCA plane (sqrt of the least
 *    eigenvalue): about 2 sigma for Gaussian noise of deviation sigma, and a
 *    small curvature term for clean samples.
 *
 * \throws Empty_input_error no point;
 * \throws Non_finite_value_error a NaN or infinite coordinate (names the index);
 * \throws Invalid_input_error fewer than k points, all points on one line or
 *         one plane (exact predicates decide this), k < 3, rho or delta < 0.
 *
 * \cgalModels{ContouringField_3}
 */
template <typename GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel,
          typename ConcurrencyTag = CGAL::Sequential_tag>
class Tangent_plane_signed_distance_3
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename Geom_traits::Point_3 Point_3;
  typedef typename Geom_traits::Vector_3 Vector_3;

  /// Wall-clock seconds of each construction stage.
  struct Timings
  {
    double neighbors = 0;   ///< kd-tree build + k-NN queries
    double planes = 0;      ///< PCA of every neighbourhood + estimates of rho, delta
    double orientation = 0; ///< orientation of the normals
    double winding_number = 0; ///< sample areas + the winding number's tree
  };

private:
  typedef CGAL::Search_traits_3<Geom_traits> Base_search_traits;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Index_point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Index_point_map, Base_search_traits> Search_traits;
  typedef CGAL::Distance_adapter<std::size_t, Index_point_map, CGAL::Euclidean_distance<Base_search_traits>>
    Distance;
  typedef CGAL::Sliding_midpoint<Search_traits> Splitter;
  // Leaves of 30 points instead of CGAL's default 10: the k-NN of all samples
  // (k = 15) and the nearest-centre queries of the lattice are 25-30 % faster
  // (10K and 60K samples of a sphere; 20 and 40 are in between).
  static constexpr unsigned int leaf_size = 30;
  typedef CGAL::Kd_tree<Search_traits, Splitter, CGAL::Tag_true> Tree;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits, Distance, Splitter, Tree> Neighbor_search;

public:
  /*!
   * builds the tangent planes of `points` and orients them.
   *
   * \param points the samples
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{point_map}
   *     \cgalParamDescription{the point of each element of `points`}
   *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Point_3`} \cgalParamDefault{`CGAL::Identity_property_map`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{normal_map}
   *     \cgalParamDescription{the (roughly) outward normal of each sample, used only to orient the tangent planes}
   *     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Vector_3`} \cgalParamDefault{none: the planes are oriented along a minimum spanning tree}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{number_of_neighbors}
   *     \cgalParamDescription{k, the size of each neighbourhood (the sample itself included), from 3 to 1024}
   *     \cgalParamType{`std::size_t`} \cgalParamDefault{15}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{sampling_density}
   *     \cgalParamDescription{Hoppe's rho, the radius of the largest disk on the surface free of samples}
   *     \cgalParamType{`double`} \cgalParamDefault{1.5 sqrt(15 / k) times the median distance to the k-th nearest neighbour}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{noise_level}
   *     \cgalParamDescription{Hoppe's delta}
   *     \cgalParamType{`double`} \cgalParamDefault{twice the median RMS distance of a neighbourhood to its PCA plane}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   */
  template <typename PointRange, typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Tangent_plane_signed_distance_3(const PointRange& points,
                                           const NamedParameters& np = parameters::default_values())
  {
    typedef CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
    using parameters::choose_parameter;
    using parameters::get_parameter;

    const auto point_map = NP_helper::get_const_point_map(points, np);
    m_k = choose_parameter(get_parameter(np, internal_np::number_of_neighbors), std::size_t(15));
    if(m_k < 3)
      throw Invalid_input_error("number_of_neighbors must be at least 3 (got " + std::to_string(m_k) + ")");

    m_points.reserve(points.size());
    for(const auto& value : points)
      m_points.push_back(get(point_map, value));
    check_points();

    std::vector<Vector_3> input_normals;
    if constexpr(NP_helper::has_normal_map())
    {
      const auto normal_map = NP_helper::get_normal_map(points, np);
      input_normals.reserve(points.size());
      for(const auto& value : points)
        input_normals.push_back(get(normal_map, value));
      m_has_input_normals = true;
    }

    compute_neighbors();
    compute_planes();
    const double rho = choose_parameter(get_parameter(np, internal_np::sampling_density), -1.0);
    const double delta = choose_parameter(get_parameter(np, internal_np::noise_level), -1.0);
    if(rho >= 0)
      m_rho = rho;
    else if(!is_default(np, internal_np::sampling_density))
      throw Invalid_input_error("sampling_density must be >= 0");
    if(delta >= 0)
      m_delta = delta;
    else if(!is_default(np, internal_np::noise_level))
      throw Invalid_input_error("noise_level must be >= 0");
    if(m_has_input_normals)
    {
      orient_by_input_normals(input_normals);
      if(extreme_samples_face_outward())
      {
        const auto start = std::chrono::steady_clock::now();
        compute_input_normal_planes(input_normals);
        m_timings.orientation += internal::seconds_since(start);
      }
      else
      {
        // The input's normals are not outward (CGAL's cube.pwn: every face
        // normal along +axis, whichever side the face is on).  Their signs
        // are worthless; Hoppe's propagation does not need them.
        m_input_normals_rejected = true;
        const double input_seconds = m_timings.orientation;
        orient_by_minimum_spanning_forest();
        m_timings.orientation += input_seconds;
      }
    }
    else
      orient_by_minimum_spanning_forest();
    // Independent, and each sequential inside: side by side on two threads.
    internal::concurrent_invoke<ConcurrencyTag>([this] { build_centre_tree(); }, [this] { build_winding_number(); });
  }

  Tangent_plane_signed_distance_3(const Tangent_plane_signed_distance_3&) = delete;
  Tangent_plane_signed_distance_3& operator=(const Tangent_plane_signed_distance_3&) = delete;

  /// f(p), or an empty optional where f is undefined (see the class comment).
  std::optional<double> operator()(const Point_3& p) const
  {
    const std::size_t i = nearest_centre(p);
    const Vector_3& n = m_normals[i];
    const double f = CGAL::to_double((p - m_centres[i]) * n);
    const Point_3 z = p - f * n;
    // The sample of plane i bounds the distance from z to the samples: no
    // search when it is near enough (nearly always, near the surface).
    const double limit = m_rho + m_delta;
    if(CGAL::to_double(CGAL::squared_distance(z, m_points[i])) > limit * limit && distance_to_samples(z) > limit)
      return std::nullopt;
    return uses_input_normals() ? input_normal_plane_value(p, i) : f;
  }

  /// Whether f uses the planes of the input normals (given, and outward)
  /// rather than Hoppe's PCA planes; see the class comment.
  bool uses_input_normals() const { return !m_plane_points.empty(); }

  /// With input normals, the samples with a neighbour whose input normal is
  /// more than 30 degrees from their own: next to a sharp edge or on a
  /// curve sharper than the neighbourhood (0 on a smooth, well-sampled
  /// surface, where the contouring then looks for no sharp feature).
  std::size_t number_of_sharp_samples() const { return m_sharp_samples; }

  /// The plane f uses at `p` (a point on it and its unit outward normal):
  /// the nearest sample's input-normal plane when `uses_input_normals()`,
  /// else Hoppe's nearest tangent plane.  The Hermite data of the sharp
  /// features.
  std::pair<Point_3, Vector_3> nearest_plane(const Point_3& p) const
  {
    const std::size_t i = nearest_centre(p);
    if(uses_input_normals())
    {
      const std::size_t s = plane_sample(p, i);
      return {m_plane_points[s], m_input_normals[s]};
    }
    return {m_centres[i], m_normals[i]};
  }

  /// The generalized winding number of the oriented samples at `p`
  /// (regularized, see internal/Contouring/Winding_number.h): about 1 inside
  /// and 0 outside a closed sampled surface, 1/2 on it.
  double winding_number(const Point_3& p) const
  {
    return m_winding({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }

  /// The winding number as a length: L (1/2 - w(p)), negative inside, with
  /// L = twice the median regularization width, so that it is about the
  /// signed distance within a sample spacing of a flat sheet.
  double winding_number_distance(const Point_3& p) const { return m_winding_scale * (0.5 - winding_number(p)); }

  /// A value at every point, with one sign per point that both Hoppe's f and
  /// the winding number agree with where they are decisive: f(p) where f is
  /// defined and the winding number does not contradict its sign by more
  /// than `winding_number_tolerance()` (|w - 1/2| below it: near the surface,
  /// near an open border of the sample), else `winding_number_distance(p)`.
  /// Hoppe's f is the accurate position near a smooth, well-sampled surface;
  /// the winding number, a sum over all the samples, is the robust side where
  /// f takes the plane of the other side of a thin wall (phantom sheets),
  /// where noise flips a plane, and where f is undefined (gaps).
  ///
  /// The winding number costs most of the time, so it is not evaluated where
  /// it cannot be decisive against f: where the nearest plane's sample has a
  /// flat neighbourhood (its k neighbours' planes within 25 degrees of its
  /// own: no sharp edge, no other sheet), p is at least delta from the plane
  /// and within rho / 2 of the centre sideways (not diagonally past an edge),
  /// and the planes of the sample's 7 nearest neighbours give p the sign of f.
  /// Each condition was needed: without the flatness or the sideways bound
  /// mechpart's clean error grew from 0.64 to 0.75-0.80 % of the diagonal,
  /// with |f| >= delta / 2 fertility's noisy error from 0.80 to 1.15 %; with
  /// all of them the output matched the one with the winding number
  /// everywhere (Hausdorff distance and topology) on the 16 inputs of
  /// contouring.md.
  double consistent_value(const Point_3& p) const
  {
    Neighbor_search search(*m_centre_tree, p, 1, 0, true, Distance(m_centre_map));
    const std::size_t i = search.begin()->first;
    const double f = CGAL::to_double((p - m_centres[i]) * m_normals[i]);
    const Point_3 z = p - f * m_normals[i];
    const double limit = m_rho + m_delta;
    const bool defined =
      CGAL::to_double(CGAL::squared_distance(z, m_points[i])) <= limit * limit || distance_to_samples(z) <= limit;
    // The value, and the tests below, use the input normals' plane when
    // there is one; Hoppe's plane i still says where f is defined, and how
    // flat the neighbourhood is.
    const double value = uses_input_normals() ? input_normal_plane_value(p, i) : f;
    if(uses_input_normals() && defined && m_delta < 0.1 * m_rho && all_input_normal_planes_agree(p, i, value))
      return value;
    if(defined && m_flat[i] && std::abs(value) >= m_delta &&
       CGAL::to_double(search.begin()->second) - f * f <= 0.25 * m_rho * m_rho)
    {
      bool agree = true;
      const std::size_t* around = neighbors(i);
      for(std::size_t a = 1; a < (std::min)(m_k, std::size_t(8)) && agree; ++a)
        agree = (CGAL::to_double((p - m_centres[around[a]]) * m_normals[around[a]]) < 0) == (value < 0);
      if(agree)
        return value;
    }
    const double w = winding_number(p);
    const double v = m_winding_scale * (0.5 - w);
    if(defined && ((value < 0) == (v < 0) || std::abs(w - 0.5) < m_winding_tolerance))
      return value;
    return v;
  }

  /// |w - 1/2| below which `consistent_value()` keeps Hoppe's sign (0.1).
  double winding_number_tolerance() const { return m_winding_tolerance; }

  /// Index of the tangent plane whose centre is nearest to `p` (ties: the
  /// kd-tree's deterministic order).
  std::size_t nearest_centre(const Point_3& p) const
  {
    Neighbor_search search(*m_centre_tree, p, 1, 0, true, Distance(m_centre_map));
    return search.begin()->first;
  }

  /// Euclidean distance from `p` to the nearest sample.
  double distance_to_samples(const Point_3& p) const
  {
    Neighbor_search search(*m_point_tree, p, 1, 0, true, Distance(m_point_map));
    return std::sqrt(CGAL::to_double(search.begin()->second));
  }

  std::size_t number_of_points() const { return m_points.size(); }
  std::size_t number_of_neighbors() const { return m_k; }
  const std::vector<Point_3>& points() const { return m_points; }
  /// Centre o_i and unit normal n_i of tangent plane i (one per sample).
  const std::vector<Point_3>& centres() const { return m_centres; }
  const std::vector<Vector_3>& normals() const { return m_normals; }
  /// The k nearest samples of sample i (itself first), i in [0, n).
  const std::size_t* neighbors(std::size_t i) const { return m_neighbors.data() + i * m_k; }
  double sampling_density() const { return m_rho; }
  /// The lattice spacing `contour_signed_distance()` uses by default: a third
  /// of the *estimated* rho, even when `sampling_density` is given.  A larger
  /// rho bridges holes in the data (unsampled socket bottoms in distcap.pts),
  /// it does not make the sample coarser.
  double default_cell_size() const { return m_estimated_rho / 3; }
  double noise_level() const { return m_delta; }
  /// Median distance from a sample to its nearest other sample (the typical spacing).
  double median_spacing() const { return m_median_spacing; }
  bool has_input_normals() const { return m_has_input_normals; }
  /// Whether input normals were given but found not to point outward (see
  /// `extreme_samples_face_outward()`), so that the planes were oriented by
  /// Hoppe's propagation instead, as without normals.
  bool input_normals_rejected() const { return m_input_normals_rejected; }
  /// The test's directions that voted, and those that voted against the input normals.
  std::pair<std::size_t, std::size_t> input_normal_votes() const { return {m_outward_votes, m_inward_votes}; }
  /// Trees of the spanning forest used for orientation (0 with input normals).
  std::size_t number_of_orientation_trees() const { return m_orientation_trees; }
  /// Samples whose plane was fitted to part of their k neighbours (two sheets, see compute_planes).
  std::size_t number_of_trimmed_neighbourhoods() const { return m_trimmed_neighbourhoods; }
  const Timings& timings() const { return m_timings; }

private:
  template <typename NP, typename Tag>
  static bool is_default(const NP&, Tag)
  {
    return CGAL::parameters::is_default_parameter<NP, Tag>::value;
  }

  void check_points() const
  {
    if(m_points.empty())
      throw Empty_input_error("the point set is empty");
    for(std::size_t i = 0; i < m_points.size(); ++i)
      for(int c = 0; c < 3; ++c)
        if(!std::isfinite(CGAL::to_double(m_points[i][c])))
        {
          std::ostringstream out;
          out << "point " << i << " has a non-finite coordinate";
          throw Non_finite_value_error(out.str());
        }
    if(m_points.size() < m_k)
      throw Invalid_input_error("fewer points (" + std::to_string(m_points.size()) +
                                ") than neighbours per tangent plane (k = " + std::to_string(m_k) + ")");
    // Exact predicates: a solid needs 4 affinely independent samples.
    const typename Geom_traits::Collinear_3 collinear = Geom_traits().collinear_3_object();
    const typename Geom_traits::Orientation_3 orientation = Geom_traits().orientation_3_object();
    const Point_3& a = m_points[0];
    std::size_t b = 1;
    while(b < m_points.size() && m_points[b] == a)
      ++b;
    std::size_t c = b + 1;
    while(c < m_points.size() && collinear(a, m_points[b], m_points[c]))
      ++c;
    if(b >= m_points.size() || c >= m_points.size())
      throw Invalid_input_error("all points lie on one line: they do not sample a closed surface");
    std::size_t d = c + 1;
    while(d < m_points.size() && orientation(a, m_points[b], m_points[c], m_points[d]) == CGAL::COPLANAR)
      ++d;
    if(d >= m_points.size())
      throw Invalid_input_error("all points lie in one plane: they do not sample a closed surface");
  }

  void compute_neighbors()
  {
    const auto start = std::chrono::steady_clock::now();
    m_point_map = Index_point_map(m_points.data());
    m_point_tree = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                                          boost::counting_iterator<std::size_t>(m_points.size()), Splitter(leaf_size),
                                          Search_traits(m_point_map));
    m_point_tree->build(); // now, not lazily: queries are then read-only
    const std::size_t n = m_points.size();
    m_neighbors.assign(n * m_k, 0);
    m_kth_distance.assign(n, 0);
    m_nearest_distance.assign(n, 0);
    const Distance distance(m_point_map);
    // Blocks of samples: the queries only read the tree (built above), and
    // each writes its own sample's slots.
    internal::concurrent_for_blocks<ConcurrencyTag>(n, 256, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
      {
        Neighbor_search search(*m_point_tree, m_points[i], static_cast<unsigned int>(m_k), 0, true, distance);
        // The result is sorted by distance; put i itself first even among
        // duplicates so that neighbors(i)[0] == i always.
        m_neighbors[i * m_k] = i;
        std::size_t j = 1;
        double last = 0;
        for(auto it = search.begin(); it != search.end(); ++it)
        {
          last = CGAL::to_double(it->second);
          if(it->first == i || j == m_k)
            continue;
          if(j == 1)
            m_nearest_distance[i] = std::sqrt(last);
          m_neighbors[i * m_k + j++] = it->first;
        }
        m_kth_distance[i] = std::sqrt(last);
      }
    });
    m_timings.neighbors = internal::seconds_since(start);
  }

  static double median(std::vector<double> values)
  {
    const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
  }

  // PCA of the offsets d[j] = x_nb[j] - x, j in [0, count) with use(j)
  // (offsets from the sample x itself: no cancellation far from the origin).
  struct Plane_fit
  {
    Eigen::Vector3d mean;   ///< centroid - x
    Eigen::Vector3d normal; ///< unit, least variance
    double residual;        ///< RMS distance to the plane
  };

  template <typename Use>
  static Plane_fit fit_plane(const Eigen::Vector3d* d, std::size_t count, const Use& use)
  {
    std::size_t used = 0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(std::size_t j = 0; j < count; ++j)
      if(use(j))
      {
        mean += d[j];
        ++used;
      }
    mean /= double(used);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(std::size_t j = 0; j < count; ++j)
      if(use(j))
      {
        const Eigen::Vector3d e = d[j] - mean;
        covariance += e * e.transpose();
      }
    covariance /= double(used);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    return {mean, solver.eigenvectors().col(0).normalized(), std::sqrt(std::max(0.0, solver.eigenvalues()(0)))};
  }

  void gather_offsets(std::size_t i, std::vector<Eigen::Vector3d>& d) const
  {
    const std::size_t* nb = neighbors(i);
    for(std::size_t j = 0; j < m_k; ++j)
      d[j] = offset(nb[j], m_points[i]);
  }

  Eigen::Vector3d offset(std::size_t j, const Point_3& x) const
  {
    const Vector_3 d = m_points[j] - x;
    return Eigen::Vector3d(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z()));
  }

  // Tangent planes.  Hoppe fits a plane to the k nearest samples; where a
  // wall is thinner than the neighbourhood (the sockets of distcap.pts, walls
  // ~0.025 thick against a k = 15 radius of ~0.022) those samples lie on both
  // sides, and the plane, halfway between, is wrong on both.  So the k
  // neighbours are sorted by their offset along the normal of the plane of
  // the first k0 = min(k, 8) (nearer than the other side), and split where
  // two consecutive offsets differ by more than
  //   tau = max(0.3 d_k(i), 6 s),  s = median over samples of the k0-plane residual
  // (of the k0 plane: where most neighbourhoods straddle a wall, the k plane's
  // residual is the wall's thickness, not the noise);
  // the plane is refitted on the group that holds the sample itself, if the
  // rest (3 samples or more) lies on a parallel plane: a second sheet.  A
  // group split off across a crease is not parallel; there the split made
  // bubbles (bunny: 4 pieces instead of 1), so the k plane is kept.
  //  - 0.3 d_k(i): a surface of curvature radius R is within d_k^2 / (2R) of
  //    its tangent plane at distance d_k, below 0.3 d_k while R > 1.7 d_k
  //    (coarser samples of such curvature are not resolved anyway);
  //  - 6 s: with noise of deviation sigma, s is about 0.6 to 0.8 sigma (8
  //    samples, least-variance direction), so 6 s is about 4 sigma, while
  //    noise leaves gaps of about sigma between 15 sorted offsets.  Measured: a threshold on
  //    the offsets themselves (not their gaps) trimmed 19 % of a noisy torus'
  //    neighbourhoods and broke it into 18 components.
  // On one sheet nothing is split, and the plane is Hoppe's.
  void compute_planes()
  {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = m_points.size();
    const std::size_t k0 = (std::min)(m_k, std::size_t(8));
    const auto all = [](std::size_t) { return true; };
    std::vector<Eigen::Vector3d> d(m_k);
    // s from every 16th sample: a median needs no more, and this pass is then
    // 1/16 of a plane fit per sample.
    std::vector<double> residual;
    for(std::size_t i = 0; i < n; i += 16)
    {
      gather_offsets(i, d);
      residual.push_back(fit_plane(d.data(), k0, all).residual);
    }
    const double noise_gap = 6.0 * median(residual);
    residual.assign(n, 0);
    m_centres.resize(n);
    m_normals.resize(n);
    std::vector<char> trimmed(n, 0);
    // Blocks of samples, each with its own scratch and its samples' slots.
    internal::concurrent_for_blocks<ConcurrencyTag>(n, 256, [&](std::size_t first, std::size_t last) {
      std::vector<Eigen::Vector3d> d(m_k);
      std::vector<std::pair<double, std::size_t>> offsets(m_k);
      std::vector<char> keep(m_k);
      for(std::size_t i = first; i < last; ++i)
      {
        const Point_3& x = m_points[i];
        gather_offsets(i, d);
        Plane_fit fit = fit_plane(d.data(), m_k, all);
        const double tau = (std::max)(0.3 * m_kth_distance[i], noise_gap);
        // Where all k samples are within 0.05 tau (RMS) of one plane, a split
        // could move the plane by about that much only: not worth a test.
        if(k0 < m_k && fit.residual > 0.05 * tau)
        {
          const Plane_fit first = fit_plane(d.data(), k0, all);
          for(std::size_t j = 0; j < m_k; ++j)
            offsets[j] = {(d[j] - first.mean).dot(first.normal), j};
          std::sort(offsets.begin(), offsets.end());
          // The group of consecutive offsets, without a gap > tau, that holds j = 0.
          std::size_t self = 0;
          while(offsets[self].second != 0)
            ++self;
          std::size_t begin = self, end = self + 1;
          while(begin > 0 && offsets[begin].first - offsets[begin - 1].first <= tau)
            --begin;
          while(end < m_k && offsets[end].first - offsets[end - 1].first <= tau)
            ++end;
          if(end - begin < m_k && end - begin >= k0 / 2 && m_k - (end - begin) >= 3)
          {
            std::fill(keep.begin(), keep.end(), 0);
            for(std::size_t a = begin; a < end; ++a)
              keep[offsets[a].second] = 1;
            const Plane_fit own = fit_plane(d.data(), m_k, [&keep](std::size_t j) { return keep[j] != 0; });
            const Plane_fit other = fit_plane(d.data(), m_k, [&keep](std::size_t j) { return keep[j] == 0; });
            // A second sheet is parallel; a group split off across a crease is not.
            if(std::abs(own.normal.dot(other.normal)) >= 0.8)
            {
              trimmed[i] = 1;
              fit = own;
            }
          }
        }
        m_centres[i] = x + Vector_3(fit.mean.x(), fit.mean.y(), fit.mean.z());
        m_normals[i] = Vector_3(fit.normal.x(), fit.normal.y(), fit.normal.z());
        residual[i] = fit.residual;
      }
    });
    m_trimmed_neighbourhoods = std::size_t(std::count(trimmed.begin(), trimmed.end(), 1));
    // rho: see the class comment.  median(d_k) ~ sqrt(k / (pi lambda)) for a
    // sample of density lambda, so this is 1.5 sqrt(15 / (pi lambda)) for any k.
    m_rho = m_estimated_rho = 1.5 * std::sqrt(15.0 / double(m_k)) * median(m_kth_distance);
    m_delta = 2.0 * median(residual);
    m_median_spacing = median(m_nearest_distance);
    m_timings.planes = internal::seconds_since(start);
  }

  // The sample whose input-normal plane f uses at p, given Hoppe's nearest
  // centre i: the nearest to p of the k neighbours of sample i (one kd-tree
  // query fewer than the nearest sample, which it nearly always is).
  std::size_t plane_sample(const Point_3& p, std::size_t i) const
  {
    const std::size_t* around = neighbors(i);
    std::size_t best = around[0];
    double best_distance = CGAL::to_double(CGAL::squared_distance(p, m_points[best]));
    for(std::size_t a = 1; a < m_k; ++a)
    {
      const double d = CGAL::to_double(CGAL::squared_distance(p, m_points[around[a]]));
      if(d < best_distance)
      {
        best_distance = d;
        best = around[a];
      }
    }
    return best;
  }

  // Whether p lies within rho of the sample s whose plane f uses and on the
  // side `value` says of the input-normal planes of all of s's neighbours.
  // consistent_value() then does not ask the winding number, on clean
  // samples (delta below rho / 10): the winding number is below 1/2 just
  // inside a convex sharp edge or corner (1/4 at a right-angled edge, 1/8 at
  // a box corner), where p is inside every face plane, and would round them
  // off again (a box turned off the lattice axes: 224 lattice points within
  // 2 cells of the box with the wrong sign, 2 with this rule).  On noisy
  // samples (mechpart, noise of half a spacing) the rule let noisy planes
  // make bumps of 2 cells, so there the winding number decides as without
  // input normals.
  bool all_input_normal_planes_agree(const Point_3& p, std::size_t i, double value) const
  {
    const std::size_t s = plane_sample(p, i);
    if(CGAL::to_double(CGAL::squared_distance(p, m_points[s])) > m_rho * m_rho)
      return false;
    const std::size_t* around = neighbors(s);
    for(std::size_t a = 0; a < m_k; ++a)
      if((CGAL::to_double((p - m_plane_points[around[a]]) * m_input_normals[around[a]]) < 0) != (value < 0))
        return false;
    return true;
  }

  // f with the input normals at p, given Hoppe's nearest centre i.
  double input_normal_plane_value(const Point_3& p, std::size_t i) const
  {
    const std::size_t s = plane_sample(p, i);
    return CGAL::to_double((p - m_plane_points[s]) * m_input_normals[s]);
  }

  // The planes of the input normals (class comment): the unit input normal
  // of each sample, through the centroid of its neighbours on its own side
  // (input normals within 30 degrees; the sample itself always is).  A zero
  // or non-finite input normal takes the sample's oriented PCA plane.
  void compute_input_normal_planes(const std::vector<Vector_3>& input_normals)
  {
    const double cos_side = 0.8660254037844387;
    m_input_normals.resize(m_points.size());
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      const double length = std::sqrt(CGAL::to_double(input_normals[i].squared_length()));
      m_input_normals[i] = length > 0 && std::isfinite(length) ? input_normals[i] / length : m_normals[i];
    }
    m_plane_points.resize(m_points.size());
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      const std::size_t* around = neighbors(i);
      double sum[3] = {0, 0, 0};
      std::size_t count = 0;
      for(std::size_t a = 0; a < m_k; ++a)
        if(a == 0 || CGAL::to_double(m_input_normals[around[a]] * m_input_normals[i]) > cos_side)
        {
          for(int c = 0; c < 3; ++c)
            sum[c] += CGAL::to_double(m_points[around[a]][c]);
          ++count;
        }
      if(count < m_k)
        ++m_sharp_samples;
      m_plane_points[i] = Point_3(sum[0] / double(count), sum[1] / double(count), sum[2] / double(count));
    }
  }

  void orient_by_input_normals(const std::vector<Vector_3>& input_normals)
  {
    const auto start = std::chrono::steady_clock::now();
    for(std::size_t i = 0; i < m_normals.size(); ++i)
      if(CGAL::to_double(m_normals[i] * input_normals[i]) < 0)
        m_normals[i] = -m_normals[i];
    m_orientation_trees = 0;
    m_timings.orientation = internal::seconds_since(start);
  }

  // A cheap test of input normals that are supposed to point outward: the
  // sample extreme in a direction d lies on the convex hull of the sample, where
  // an outward normal has n . d > 0.  Over the 26 directions of the 3x3x3
  // stencil, those whose extreme sample has a decisive plane (|n . d| > 0.5)
  // vote; more than a quarter of them against means the signs are not
  // outward.  Clean outward samples (sphere, elephant, oni, tori made in code)
  // have no vote against; cube.pwn, whose normals all point along +axis, has
  // 12 of 25 against.  One pass over the points finds the extreme samples
  // of all 26 directions: 13 axes, each with its highest and lowest sample.
  bool extreme_samples_face_outward()
  {
    std::vector<Vector_3> axes; // one of d and -d for each direction d
    for(int dx = -1; dx <= 1; ++dx)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dz = -1; dz <= 1; ++dz)
          if(dx > 0 || (dx == 0 && (dy > 0 || (dy == 0 && dz > 0))))
            axes.emplace_back(dx, dy, dz);
    // The first sample with the largest (smallest) height along each axis.
    std::vector<std::size_t> highest(axes.size(), 0), lowest(axes.size(), 0);
    std::vector<double> high(axes.size(), -std::numeric_limits<double>::infinity());
    std::vector<double> low(axes.size(), std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      const Vector_3 p = m_points[i] - CGAL::ORIGIN;
      for(std::size_t a = 0; a < axes.size(); ++a)
      {
        const double h = CGAL::to_double(p * axes[a]);
        if(h > high[a])
        {
          high[a] = h;
          highest[a] = i;
        }
        if(h < low[a])
        {
          low[a] = h;
          lowest[a] = i;
        }
      }
    }
    std::size_t votes = 0, against = 0;
    auto vote = [&](std::size_t extreme, const Vector_3& d) {
      const double alignment = CGAL::to_double(m_normals[extreme] * d) / std::sqrt(CGAL::to_double(d * d));
      if(std::abs(alignment) > 0.5)
      {
        ++votes;
        if(alignment < 0)
          ++against;
      }
    };
    for(std::size_t a = 0; a < axes.size(); ++a)
    {
      vote(highest[a], axes[a]);
      vote(lowest[a], -axes[a]);
    }
    m_outward_votes = votes;
    m_inward_votes = against;
    return 4 * against <= votes;
  }

  // Hoppe 1992, section 3.3: propagate the orientation along a minimum
  // spanning forest of the neighbour graph weighted by 1 - |n_i . n_j|, so
  // that it crosses nearly parallel planes first.
  void orient_by_minimum_spanning_forest()
  {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = m_points.size();
    // The neighbour pairs (i < j), each once, in lexicographic order: each
    // pair is bucketed under its smaller sample, and only the small buckets
    // are sorted (one sort of all n (k - 1) pairs took most of this stage).
    std::vector<std::size_t> bucket_begin(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 1; j < m_k; ++j)
        if(neighbors(i)[j] != i)
          ++bucket_begin[(std::min)(i, neighbors(i)[j]) + 1];
    for(std::size_t i = 0; i < n; ++i)
      bucket_begin[i + 1] += bucket_begin[i];
    std::vector<std::size_t> larger(bucket_begin[n]);
    {
      std::vector<std::size_t> fill(bucket_begin.begin(), bucket_begin.end() - 1);
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 1; j < m_k; ++j)
        {
          const std::size_t other = neighbors(i)[j];
          if(other != i)
            larger[fill[(std::min)(i, other)]++] = (std::max)(i, other);
        }
    }
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    pairs.reserve(larger.size());
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto first = larger.begin() + std::ptrdiff_t(bucket_begin[i]);
      const auto last = larger.begin() + std::ptrdiff_t(bucket_begin[i + 1]);
      std::sort(first, last);
      for(auto it = first; it != last; ++it)
        if(it == first || *it != *(it - 1))
          pairs.emplace_back(i, *it);
    }
    // Weight 1 - |n_i . n_j| (Hoppe), plus min(|n_i . e|, |n_j . e|) for the
    // unit edge direction e: across a wall thinner than a neighbourhood (the
    // sockets of distcap.pts) the k-NN graph joins the two sides, whose planes
    // are parallel (Hoppe's weight ~0, so the tree prefers these edges) but
    // whose normals must be *opposite*; such an edge runs along both normals.
    // Along the surface, and across a sharp edge, at least one normal is
    // nearly orthogonal to the edge, so the term stays small there.  Measured
    // on distcap: chi -252 -> -15 with the default parameters, and 717 -> 664
    // neighbour pairs with n_i . n_j < -0.9 (the rest are the two sides of the
    // walls, correctly opposite).
    // (weight, edge index): sorted as pairs, the order by increasing (weight, index).
    std::vector<std::pair<double, std::size_t>> by_weight(pairs.size());
    internal::concurrent_for<ConcurrencyTag>(pairs.size(), [&](std::size_t e) {
      const Vector_3& ni = m_normals[pairs[e].first];
      const Vector_3& nj = m_normals[pairs[e].second];
      double w = 1.0 - std::abs(CGAL::to_double(ni * nj));
      const Vector_3 d = m_points[pairs[e].second] - m_points[pairs[e].first];
      const double length = std::sqrt(CGAL::to_double(d * d));
      if(length > 0)
        w += (std::min)(std::abs(CGAL::to_double(ni * d)), std::abs(CGAL::to_double(nj * d))) / length;
      by_weight[e] = {w, e};
    });
    // Kruskal: the edges by increasing (weight, index), joined by union-find.
    // (Boost's kruskal_minimum_spanning_tree keeps its edges in a binary heap
    // compared through property maps: 22 % of a noisy 60K-sample run.)  The
    // order is total, so a parallel sort gives the sequential one.
    internal::concurrent_sort<ConcurrencyTag>(by_weight.begin(), by_weight.end());
    std::vector<std::size_t> parent(n);
    for(std::size_t i = 0; i < n; ++i)
      parent[i] = i;
    auto find = [&parent](std::size_t v) {
      while(parent[v] != v)
        v = parent[v] = parent[parent[v]];
      return v;
    };
    std::vector<std::pair<std::size_t, std::size_t>> tree_edges;
    tree_edges.reserve(n);
    for(const auto& weighted : by_weight)
    {
      const std::size_t e = weighted.second;
      const std::size_t a = find(pairs[e].first), b = find(pairs[e].second);
      if(a == b)
        continue;
      parent[(std::max)(a, b)] = (std::min)(a, b);
      tree_edges.push_back(pairs[e]);
    }

    // Adjacency of the forest in CSR form (deterministic order).
    std::vector<std::size_t> degree(n + 1, 0);
    for(const auto& e : tree_edges)
    {
      ++degree[e.first + 1];
      ++degree[e.second + 1];
    }
    for(std::size_t i = 0; i < n; ++i)
      degree[i + 1] += degree[i];
    std::vector<std::size_t> adjacent(degree[n]);
    std::vector<std::size_t> fill(degree.begin(), degree.end() - 1);
    for(const auto& e : tree_edges)
    {
      adjacent[fill[e.first]++] = e.second;
      adjacent[fill[e.second]++] = e.first;
    }
    // Roots: per tree, the sample of largest z (smallest index among ties).
    std::vector<std::size_t> order(n);
    for(std::size_t i = 0; i < n; ++i)
      order[i] = i;
    std::stable_sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) {
      return CGAL::to_double(m_points[a].z()) > CGAL::to_double(m_points[b].z());
    });
    std::vector<char> visited(n, 0);
    std::vector<std::size_t> stack;
    m_orientation_trees = 0;
    for(std::size_t root : order)
    {
      if(visited[root])
        continue;
      ++m_orientation_trees;
      if(CGAL::to_double(m_normals[root].z()) < 0)
        m_normals[root] = -m_normals[root];
      visited[root] = 1;
      stack.push_back(root);
      while(!stack.empty())
      {
        const std::size_t i = stack.back();
        stack.pop_back();
        for(std::size_t a = degree[i]; a < degree[i + 1]; ++a)
        {
          const std::size_t j = adjacent[a];
          if(visited[j])
            continue;
          visited[j] = 1;
          if(CGAL::to_double(m_normals[i] * m_normals[j]) < 0)
            m_normals[j] = -m_normals[j];
          stack.push_back(j);
        }
      }
    }
    m_timings.orientation = internal::seconds_since(start);
  }

  // Sample areas a_i = pi d_i^2 / k, d_i the distance from x_i to its k-th
  // neighbour measured in its tangent plane (the k samples cover that disk);
  // regularization eps_i = 0.7 sqrt(a_i), about 0.7 of the local spacing.
  // 0.7: with 1.0 the winding number blurs walls 2 spacings thick
  // (distcap.pts' sockets: chi -13 instead of a disk), with 0.5 and less it
  // is rough between samples.
  void build_winding_number()
  {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = m_points.size();
    std::vector<std::array<double, 3>> x(n), normal(n);
    std::vector<double> area(n), eps(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Vector_3& ni = m_normals[i];
      const Vector_3 d = m_points[neighbors(i)[m_k - 1]] - m_points[i];
      const double along = CGAL::to_double(d * ni);
      const double tangential2 = (std::max)(0.0, CGAL::to_double(d * d) - along * along);
      area[i] = 3.14159265358979323846 * tangential2 / double(m_k);
      x[i] = {CGAL::to_double(m_points[i].x()), CGAL::to_double(m_points[i].y()), CGAL::to_double(m_points[i].z())};
      normal[i] = {CGAL::to_double(ni.x()), CGAL::to_double(ni.y()), CGAL::to_double(ni.z())};
    }
    const double typical_area = median(area);
    for(std::size_t i = 0; i < n; ++i)
      eps[i] = 0.7 * std::sqrt(area[i] > 0 ? area[i] : typical_area);
    m_winding_scale = 2 * median(eps);
    if(!(m_winding_scale > 0))
      m_winding_scale = m_median_spacing > 0 ? m_median_spacing : 1;
    m_winding = internal::Fast_winding_number(x, normal, area, eps);
    // Flat neighbourhoods: every neighbour's plane within 25 degrees of the
    // sample's (no sharp edge, no second sheet of the other orientation).
    m_flat.assign(n, 1);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t a = 1; a < m_k && m_flat[i]; ++a)
        m_flat[i] = CGAL::to_double(m_normals[i] * m_normals[neighbors(i)[a]]) >= 0.9;
    m_timings.winding_number = internal::seconds_since(start);
  }

  void build_centre_tree()
  {
    const auto start = std::chrono::steady_clock::now();
    m_centre_map = Index_point_map(m_centres.data());
    m_centre_tree = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                                           boost::counting_iterator<std::size_t>(m_centres.size()), Splitter(leaf_size),
                                           Search_traits(m_centre_map));
    m_centre_tree->build();
    m_timings.neighbors += internal::seconds_since(start);
  }

  std::vector<Point_3> m_points;
  std::vector<Point_3> m_centres;
  std::vector<Vector_3> m_normals;
  std::vector<std::size_t> m_neighbors;
  std::vector<double> m_kth_distance, m_nearest_distance;
  Index_point_map m_point_map, m_centre_map;
  std::unique_ptr<Tree> m_point_tree, m_centre_tree;
  std::size_t m_k = 15;
  double m_rho = 0, m_estimated_rho = 0, m_delta = 0, m_median_spacing = 0;
  bool m_has_input_normals = false;
  std::size_t m_orientation_trees = 0;
  std::size_t m_trimmed_neighbourhoods = 0;
  bool m_input_normals_rejected = false;
  // Empty unless f uses the input normals' planes (uses_input_normals()).
  std::vector<Vector_3> m_input_normals; // unit
  std::vector<Point_3> m_plane_points;
  std::size_t m_sharp_samples = 0;
  std::size_t m_outward_votes = 0, m_inward_votes = 0;
  internal::Fast_winding_number m_winding;
  std::vector<char> m_flat; // see build_winding_number
  double m_winding_scale = 1, m_winding_tolerance = 0.1;
  Timings m_timings;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_TANGENT_PLANE_SIGNED_DISTANCE_3_H
