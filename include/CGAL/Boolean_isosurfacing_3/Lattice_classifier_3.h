// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_BOOLEAN_ISOSURFACING_3_LATTICE_CLASSIFIER_3_H
#define CGAL_BOOLEAN_ISOSURFACING_3_LATTICE_CLASSIFIER_3_H

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/Regular_lattice_3.h>
#include <CGAL/Boolean_isosurfacing_3/exceptions.h>
#include <CGAL/Boolean_isosurfacing_3/named_parameters.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Concurrent_for.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Default_init_allocator.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Huge_pages.h>
#include <CGAL/Boolean_isosurfacing_3/internal/callback_parameter.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Mesh_triangles_3.h>
#include <CGAL/Boolean_isosurfacing_3/internal/Marching_cubes_csg/Perturbed_line_predicates_3.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Boolean_isosurfacing {

/// \ingroup PkgBooleanIsosurfacing3Ref
/// A crossing of an input mesh with a lattice line: it lies on the lattice
/// edge from point `index - 1` to point `index` of its line (indices along
/// the line's axis).  `position` is the coordinate along the axis, computed
/// in double and clamped to the edge; it is *not* used for any
/// combinatorial decision (those are exact).  `triangle` is the crossed
/// triangle: its number among the triangles of all meshes, mesh 0 first, each
/// mesh's faces in `faces()` order (it gives `marching_cubes_csg()` the exact
/// tangent plane of the crossing).  16 bytes: the index and the mesh share
/// one word (a lattice has fewer than 2^26 points along an axis, and there
/// are at most 64 meshes), because the crossings are most of the memory of
/// a fine lattice.
struct Lattice_crossing
{
  double position;
  std::uint32_t index : 26;
  std::uint32_t mesh : 6;
  std::uint32_t triangle = 0;
};

/*!
 * \ingroup PkgBooleanIsosurfacing3Ref
 *
 * Exact inside/outside classification of every point of a `Regular_lattice_3`
 * with respect to up to 64 closed triangle meshes, and the crossings of the
 * meshes with every lattice edge.
 *
 * All decisions are made for the *symbolically perturbed* lattice: every
 * lattice point p is moved to p + (d1, d2, d3), d1 >> d2 >> d3 > 0
 * infinitesimal.  No perturbed lattice point lies on a mesh and no perturbed
 * lattice line meets a mesh edge or vertex, so every question has a yes/no
 * answer, obtained from exact predicates on the unperturbed doubles plus the
 * sign of the leading perturbation term.  Consequences:
 *
 * - a lattice point that is not on any mesh is classified as it is (the
 *   parity of the number of crossings of a ray, like
 *   `CGAL::Side_of_triangle_mesh`); a point on a mesh is classified as the
 *   point moved by +d1 in x (then +d2 in y, +d3 in z);
 * - for every lattice edge and every mesh, the number of crossings on the
 *   edge has the parity of the change of classification between its ends,
 *   *exactly* (`number_of_inconsistent_edges()` checks it).
 *
 * Algorithm: one pass per axis over the lattice lines parallel to it.  Each
 * triangle is binned to the lines that pass through its projected bounding
 * box; a line crosses it iff the perturbed line point is inside its
 * projection (3 exact orient2d); the crossing's index along the line is a
 * double estimate corrected by exact orient3d tests.  The x lines give the
 * classification (toggle the mesh bit at each crossing index, then a prefix
 * XOR along the line): O(lines + crossings + triangles), no sorting of
 * lattice points, no ray shooting.
 *
 * The classification is stored *sparsely*: a point's mask is the mask of the
 * first point of its x line (`start_mask()`) toggled by the crossings of the
 * line before it, so no per-point array exists, and only the lines that hold
 * crossings (or, along x, start inside a mesh) are stored.  Memory: 16 bytes
 * per crossing, 8 per stored line (16 along x) and 8 per row of lines, so it
 * grows with the surface, not with the lattice's volume nor its
 * cross-sections.  `mask()` and `crossings_on_line()` find their line by a
 * binary search in its row; algorithms walk the stored lines of a row
 * (`stored_lines()`).
 */
class Lattice_classifier_3
{
public:
  typedef Lattice_crossing Crossing;

  /// A contiguous read-only range of crossings.
  class Crossing_range
  {
  public:
    Crossing_range() = default;
    Crossing_range(const Crossing* first, const Crossing* last) : m_first(first), m_last(last) {}
    const Crossing* begin() const { return m_first; }
    const Crossing* end() const { return m_last; }
    std::size_t size() const { return std::size_t(m_last - m_first); }
    bool empty() const { return m_first == m_last; }
    const Crossing& operator[](std::size_t i) const { return m_first[i]; }

  private:
    const Crossing* m_first = nullptr;
    const Crossing* m_last = nullptr;
  };

  static constexpr std::size_t max_number_of_meshes = 64;
  /// Points along an axis must be fewer than this (2^26): the width of
  /// `Lattice_crossing::index`.
  static constexpr std::size_t max_points_per_axis = std::size_t(1) << 26;
  /// Default of the named parameter `max_memory_bytes`: 8 GiB.
  static constexpr std::size_t default_max_memory_bytes = std::size_t(8) << 30;

  /*!
   * classifies the points of `lattice` with respect to `meshes`.
   *
   * \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
   *         (needs TBB); the result is identical for both.
   * \tparam TriangleMeshRange a range of models of `FaceListGraph` (or of
   *         `std::reference_wrapper`s to them) with triangle faces; the
   *         points of their `vertex_point` maps have `x()`, `y()`, `z()`
   *         convertible to double by `CGAL::to_double()`.  Its elements may
   *         also be `Triangle_soup_3`s (flat arrays, as the package's readers
   *         give them: no mesh to build), checked to be closed by the
   *         linear-time edge test; a soup may have non-manifold vertices.
   *
   * \param meshes the closed triangle meshes; bit m of a point's mask is mesh m
   * \param lattice the lattice whose points are classified
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{callback}
   *     \cgalParamDescription{called with fractions in [0, 1], from the calling thread; returning
   *       `false` cancels (`Operation_cancelled_error`)}
   *     \cgalParamType{a callable `bool(double)`} \cgalParamDefault{none}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{max_memory_bytes}
   *     \cgalParamDescription{refuse to start when the estimated memory exceeds it (`Lattice_too_large_error`)}
   *     \cgalParamType{`std::size_t`} \cgalParamDefault{8 GiB}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * Coordinates are converted to double; the predicates are exact for those
   * doubles (so exact for `Epick` and `Simple_cartesian<double>` meshes).
   *
   * \throws Empty_input_error if `meshes` is empty or a mesh has no face.
   * \throws Invalid_input_error if there are more than 64 meshes.
   * \throws Non_triangle_face_error, Open_mesh_error, Non_finite_value_error
   *         for a mesh that is not a closed triangle mesh with finite coordinates.
   * \throws Lattice_too_large_error if the memory estimate exceeds the limit.
   */
  template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMeshRange,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  static Lattice_classifier_3 classify(const TriangleMeshRange& meshes, const Regular_lattice_3& lattice,
                                       const NamedParameters& np = parameters::default_values())
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const std::size_t max_memory =
        choose_parameter(get_parameter(np, internal_np::max_memory_bytes), default_max_memory_bytes);
    std::size_t number_of_meshes = 0;
    std::vector<internal::Lattice_triangle> triangles = read_meshes(meshes, number_of_meshes);
    return classify_triangles<ConcurrencyTag>(std::move(triangles), number_of_meshes, lattice, max_memory, 0,
                                              internal::progress_of(np));
  }

  /// \cond SKIP_IN_MANUAL
  // The building blocks of `classify()`, also used by marching_cubes_csg():
  // it validates the meshes before anything else and reserves memory for
  // its own arrays (`reserved_bytes`) in the estimate.
  template <typename TriangleMeshRange>
  static std::vector<internal::Lattice_triangle> read_meshes(const TriangleMeshRange& meshes,
                                                             std::size_t& number_of_meshes)
  {
    return read_meshes(meshes, number_of_meshes, [](const auto& mesh, std::uint32_t m, auto& out) {
      internal::append_lattice_triangles(mesh, m, out);
    });
  }

  // As above; `append(mesh, m, triangles)` appends the triangles of mesh m
  // (so that the caller chooses each mesh's vertex point map).
  template <typename TriangleMeshRange, typename Append>
  static std::vector<internal::Lattice_triangle> read_meshes(const TriangleMeshRange& meshes,
                                                             std::size_t& number_of_meshes, const Append& append)
  {
    number_of_meshes = std::size_t(std::distance(std::begin(meshes), std::end(meshes)));
    if(number_of_meshes == 0)
      throw Empty_input_error("no input mesh");
    if(number_of_meshes > max_number_of_meshes)
      throw Invalid_input_error(std::to_string(number_of_meshes) + " meshes given; at most " +
                                std::to_string(max_number_of_meshes) + " are supported");
    std::vector<internal::Lattice_triangle> triangles;
    std::size_t total_faces = 0;
    for(const auto& element : meshes)
      total_faces += internal::number_of_input_faces(internal::unwrap_mesh(element));
    // 2 MB pages: the array is written once, and a fresh 4 KB page costs a
    // fault (microseconds on virtual machines) for every 51 triangles.
    internal::reserve_in_huge_pages(triangles, total_faces);
    std::uint32_t m = 0;
    for(const auto& element : meshes)
      append(internal::unwrap_mesh(element), m++, triangles);
    if(triangles.size() >= (std::size_t(1) << 32))
      throw Invalid_input_error("the meshes have 2^32 triangles or more");
    return triangles;
  }

  template <typename ConcurrencyTag>
  static Lattice_classifier_3 classify_triangles(std::vector<internal::Lattice_triangle> triangles,
                                                 std::size_t number_of_meshes, const Regular_lattice_3& lattice,
                                                 std::size_t max_memory_bytes, std::size_t reserved_bytes,
                                                 const internal::Progress& progress)
  {
    Lattice_classifier_3 result(lattice, number_of_meshes);
    result.template run<ConcurrencyTag>(triangles, max_memory_bytes, reserved_bytes, progress);
    return result;
  }
  // Frees the crossings and the stored lines (marching_cubes_csg() needs
  // them no more once its vertices are placed): the classifier then holds
  // no line, and only lattice() and number_of_meshes() remain meaningful.
  void release_crossings()
  {
    for(int axis = 0; axis < 3; ++axis)
    {
      std::vector<Crossing>().swap(m_crossings[axis]);
      std::vector<Line_entry>(1, Line_entry{0, 0}).swap(m_lines[axis]);
      std::vector<std::size_t>(m_row_begin[axis].size(), 0).swap(m_row_begin[axis]);
    }
    std::vector<std::uint64_t>().swap(m_start_masks);
  }
  /// \endcond

  /// \name Access
  /// @{

  /// The classified lattice.
  const Regular_lattice_3& lattice() const { return m_lattice; }
  /// The number of meshes (bits of a mask).
  std::size_t number_of_meshes() const { return m_number_of_meshes; }

  /// Bit m set iff the first point (i = 0) of x line `x_line` (see
  /// `line_index()`) is inside mesh m.
  std::uint64_t start_mask(std::size_t x_line) const
  {
    CGAL_precondition(x_line < number_of_lines(0));
    const std::size_t e = find_line(0, x_line);
    return e == no_line ? 0 : m_start_masks[e];
  }

  /// A line along an axis that holds crossings (or, along x, whose first
  /// point is inside a mesh): its index `u` within its row, its crossings
  /// and (along x) its start mask.
  struct Stored_line
  {
    std::size_t u;
    Crossing_range crossings;
    std::uint64_t start_mask;
  };

  /// The stored lines of row `v` along `axis` (the lines whose v index is
  /// `v`, see `line_index()`), by increasing u: a random-access range of
  /// `Stored_line`.  Every other line of the row has no crossing and (along
  /// x) starts outside every mesh.
  class Stored_lines
  {
  public:
    Stored_lines(const Lattice_classifier_3& c, int axis, std::size_t v)
      : m_c(&c), m_axis(axis), m_first(c.m_row_begin[axis][v]), m_last(c.m_row_begin[axis][v + 1])
    {}
    std::size_t size() const { return m_last - m_first; }
    bool empty() const { return m_first == m_last; }
    Stored_line operator[](std::size_t k) const { return m_c->stored_line(m_axis, m_first + k); }
    /// The u index of the k-th line (what a search by u reads).
    std::size_t u(std::size_t k) const { return m_c->m_lines[m_axis][m_first + k].u; }
    /// The first k in [from, size()) whose line has u index `u` or more.
    std::size_t lower_bound(std::size_t u, std::size_t from = 0) const
    {
      const Line_entry* base = m_c->m_lines[m_axis].data() + m_first;
      return std::size_t(std::lower_bound(base + from, base + size(), u,
                                          [](const Line_entry& e, std::size_t value) { return e.u < value; }) -
                         base);
    }

  private:
    const Lattice_classifier_3* m_c;
    int m_axis;
    std::size_t m_first, m_last;
  };

  /// The stored lines of row `v` along `axis`.
  Stored_lines stored_lines(int axis, std::size_t v) const
  {
    CGAL_precondition(0 <= axis && axis < 3 && v + 1 < m_row_begin[axis].size());
    return Stored_lines(*this, axis, v);
  }

  /// The number of rows of lines along `axis` (the number of lattice points
  /// along its v axis).
  std::size_t number_of_rows(int axis) const { return m_row_begin[axis].size() - 1; }

  /// Bit m set iff lattice point (i, j, k) is inside mesh m: the line's
  /// start mask toggled by the crossings before the point (O(crossings on
  /// the x line)).
  std::uint64_t mask(std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(i < m_lattice.number_of_points(0) && j < m_lattice.number_of_points(1) &&
                      k < m_lattice.number_of_points(2));
    const std::size_t line = line_index(0, i, j, k);
    const std::size_t e = find_line(0, line);
    if(e == no_line)
      return 0;
    const Stored_line stored = stored_line(0, e);
    std::uint64_t mask = stored.start_mask;
    for(const Crossing& c : stored.crossings)
    {
      if(c.index > i)
        break;
      mask ^= std::uint64_t(1) << c.mesh;
    }
    return mask;
  }
  /// The mask of the lattice point of index `linear_index` (`Regular_lattice_3::linear_index()`).
  std::uint64_t mask(std::size_t linear_index) const
  {
    CGAL_precondition(linear_index < m_lattice.total_number_of_points());
    const std::size_t nx = m_lattice.number_of_points(0), ny = m_lattice.number_of_points(1);
    return mask(linear_index % nx, (linear_index / nx) % ny, linear_index / (nx * ny));
  }

  /// true iff lattice point (i, j, k) is inside mesh `mesh`.
  bool is_inside(std::size_t mesh, std::size_t i, std::size_t j, std::size_t k) const
  {
    return ((mask(i, j, k) >> mesh) & 1) != 0;
  }

  /// Number of lattice lines along `axis` (stored or not).
  std::size_t number_of_lines(int axis) const
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    return n[internal::line_u_axis(axis)] * n[internal::line_v_axis(axis)];
  }

  /// Number of stored lines along `axis` (see `stored_lines()`).
  std::size_t number_of_stored_lines(int axis) const { return m_row_begin[axis].back(); }

  /// Index of the line along `axis` through point (i, j, k): the two other
  /// indices, the smaller axis varying fastest.
  std::size_t line_index(int axis, std::size_t i, std::size_t j, std::size_t k) const
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    switch(axis)
    {
    case 0: return j + n[1] * k;
    case 1: return i + n[0] * k;
    default: return i + n[0] * j;
    }
  }

  /// The crossings on the lattice edges of a line along `axis`, sorted by
  /// (`index`, `position`, `mesh`).
  Crossing_range crossings_on_line(int axis, std::size_t line) const
  {
    CGAL_precondition(0 <= axis && axis < 3 && line < number_of_lines(axis));
    const std::size_t e = find_line(axis, line);
    return e == no_line ? Crossing_range() : stored_line(axis, e).crossings;
  }

  /// The crossings on the lattice edge from (i, j, k) to its neighbour along
  /// `axis`, sorted by (`position`, `mesh`).
  /// \pre the index of (i, j, k) along `axis` is below `number_of_points(axis) - 1`
  Crossing_range crossings_on_edge(int axis, std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(0 <= axis && axis < 3);
    CGAL_precondition((axis == 0 ? i : (axis == 1 ? j : k)) + 1 < m_lattice.number_of_points(axis));
    const Crossing_range line = crossings_on_line(axis, line_index(axis, i, j, k));
    const std::uint32_t index = std::uint32_t((axis == 0 ? i : (axis == 1 ? j : k)) + 1);
    const Crossing* first = std::lower_bound(line.begin(), line.end(), index,
                                             [](const Crossing& c, std::uint32_t x) { return c.index < x; });
    const Crossing* last = first;
    while(last != line.end() && last->index == index)
      ++last;
    return Crossing_range(first, last);
  }

  /// Number of crossings on lattice edges along `axis` (crossings outside
  /// the lattice are not stored).
  std::size_t number_of_crossings(int axis) const { return m_crossings[axis].size(); }
  /// The number of crossings of the meshes with lattice edges, all axes.
  std::size_t number_of_crossings() const
  {
    return m_crossings[0].size() + m_crossings[1].size() + m_crossings[2].size();
  }

  /// Wall-clock seconds spent on the lines along `axis` (for axis 0 this
  /// includes the classification).
  double seconds(int axis) const { return m_seconds[axis]; }

  /// The memory estimate that was checked against `max_memory_bytes`.
  std::size_t estimated_memory_bytes() const { return m_estimated_bytes; }

  /// @}

  /// The number of (lattice edge, mesh) pairs whose number of crossings has
  /// not the parity of the change of the mesh's classification along the
  /// edge.  Zero by construction for closed meshes; O(points + crossings).
  std::size_t number_of_inconsistent_edges() const
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    const std::size_t nx = n[0], ny = n[1], nz = n[2];
    std::size_t bad = 0;
    // Toggles of the crossings on one edge (index t) from `c` on; counts
    // crossings out of order or out of range as inconsistent.
    auto toggles_at = [](const Crossing*& c, const Crossing* end, std::size_t t) {
      std::uint64_t toggles = 0;
      for(; c != end && c->index == t; ++c)
        toggles ^= std::uint64_t(1) << c->mesh;
      return toggles;
    };
    // The masks of plane k, from the x lines (which define them).
    auto plane_masks = [&](std::size_t k, std::vector<std::uint64_t>& masks) {
      for(std::size_t j = 0; j < ny; ++j)
      {
        const Crossing_range line = crossings_on_line(0, j + ny * k);
        const Crossing* c = line.begin();
        std::uint64_t mask = start_mask(j + ny * k);
        for(std::size_t i = 0; i < nx; ++i)
        {
          mask ^= i == 0 ? 0 : toggles_at(c, line.end(), i);
          masks[i + nx * j] = mask;
        }
        if(c != line.end())
          bad += std::size_t(line.end() - c);
      }
    };
    std::vector<std::uint64_t> low(nx * ny), high(nx * ny);
    // Cursors of the z lines, advanced plane by plane.
    std::vector<const Crossing*> z_cursor(nx * ny);
    for(std::size_t l = 0; l < nx * ny; ++l)
      z_cursor[l] = crossings_on_line(2, l).begin();
    for(std::size_t k = 0; k < nz; ++k)
    {
      plane_masks(k, high);
      for(std::size_t i = 0; i < nx; ++i)
      {
        const Crossing_range line = crossings_on_line(1, i + nx * k);
        const Crossing* c = line.begin();
        for(std::size_t j = 1; j < ny; ++j)
        {
          const std::uint64_t change = high[i + nx * (j - 1)] ^ high[i + nx * j];
          bad += std::size_t(internal::popcount64(change ^ toggles_at(c, line.end(), j)));
        }
        if(c != line.end())
          bad += std::size_t(line.end() - c);
      }
      if(k > 0)
        for(std::size_t l = 0; l < nx * ny; ++l)
        {
          const std::uint64_t change = low[l] ^ high[l];
          bad += std::size_t(internal::popcount64(change ^ toggles_at(z_cursor[l], crossings_on_line(2, l).end(), k)));
        }
      std::swap(low, high);
    }
    for(std::size_t l = 0; l < nx * ny; ++l)
      bad += std::size_t(crossings_on_line(2, l).end() - z_cursor[l]);
    return bad;
  }

private:
  // Offsets of the lines into the crossings of their axis (checked to fit).
  typedef std::uint32_t Line_offset;

  // A stored line: its u index and its first crossing (the next entry's
  // `first` ends its crossings; a last entry per axis closes the array).
  struct Line_entry
  {
    std::uint32_t u;
    Line_offset first;
  };
  static constexpr std::size_t no_line = std::size_t(-1);

  // The entry of a line (u + nu * v), or no_line: a binary search in its row.
  std::size_t find_line(int axis, std::size_t line) const
  {
    const std::size_t nu = m_lattice.number_of_points(internal::line_u_axis(axis));
    const std::size_t u = line % nu, v = line / nu;
    const Line_entry* first = m_lines[axis].data() + m_row_begin[axis][v];
    const Line_entry* last = m_lines[axis].data() + m_row_begin[axis][v + 1];
    const Line_entry* e =
        std::lower_bound(first, last, u, [](const Line_entry& x, std::size_t value) { return x.u < value; });
    return e != last && e->u == u ? std::size_t(e - m_lines[axis].data()) : no_line;
  }

  Stored_line stored_line(int axis, std::size_t e) const
  {
    const Crossing* base = m_crossings[axis].data();
    const Line_entry* entry = m_lines[axis].data() + e;
    return Stored_line{entry->u, Crossing_range(base + entry[0].first, base + entry[1].first),
                       axis == 0 ? m_start_masks[e] : 0};
  }

  // One crossing of a row of lines (the lines along an axis with a common v index).
  struct Row_crossing
  {
    double position;
    std::uint32_t u;
    std::uint32_t index;
    std::uint32_t mesh;
    std::uint32_t triangle;

    friend bool operator<(const Row_crossing& a, const Row_crossing& b)
    {
      if(a.u != b.u)
        return a.u < b.u;
      if(a.index != b.index)
        return a.index < b.index;
      if(a.position != b.position)
        return a.position < b.position;
      if(a.mesh != b.mesh)
        return a.mesh < b.mesh;
      return a.triangle < b.triangle;
    }
  };

  // The lines along an axis that may cross a triangle: u0 <= u < u1, v0 <= v < v1.
  // Trivial (no member initializers): the array of a block per triangle is
  // not zero-filled before line_block() writes every element.
  struct Line_block
  {
    std::uint32_t u0, u1, v0, v1;
    bool empty() const { return u0 >= u1 || v0 >= v1; }
    std::size_t size() const { return empty() ? 0 : std::size_t(u1 - u0) * std::size_t(v1 - v0); }
  };
  typedef std::vector<Line_block, internal::Default_init_allocator<Line_block>> Line_blocks;

  Lattice_classifier_3(const Regular_lattice_3& lattice, std::size_t number_of_meshes)
    : m_lattice(lattice), m_number_of_meshes(number_of_meshes)
  {}

  // A perturbed line through (u + du, v + dv) can only cross a triangle if
  // umin <= u < umax and vmin <= v < vmax (the perturbation is positive).
  Line_block line_block(const internal::Lattice_triangle& t, int axis,
                        const std::array<std::vector<double>, 3>& coordinates) const
  {
    Line_block b{0, 0, 0, 0};
    if(t.projected_orientation(axis) == 0)
      return b;
    const int u = internal::line_u_axis(axis), v = internal::line_v_axis(axis);
    const double umin = (std::min)({t.p[0][u], t.p[1][u], t.p[2][u]});
    const double umax = (std::max)({t.p[0][u], t.p[1][u], t.p[2][u]});
    const double vmin = (std::min)({t.p[0][v], t.p[1][v], t.p[2][v]});
    const double vmax = (std::max)({t.p[0][v], t.p[1][v], t.p[2][v]});
    auto first_not_below = [&](int a, double value) {
      return std::uint32_t(internal::first_index_not_below(coordinates[a].data(), coordinates[a].size(),
                                                           m_lattice.spacing(), value));
    };
    b.u0 = first_not_below(u, umin);
    b.u1 = first_not_below(u, umax);
    b.v0 = first_not_below(v, vmin);
    b.v1 = first_not_below(v, vmax);
    return b;
  }

  template <typename ConcurrencyTag>
  void run(const std::vector<internal::Lattice_triangle>& triangles, std::size_t max_memory_bytes,
           std::size_t reserved_bytes, const internal::Progress& progress)
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    for(int a = 0; a < 3; ++a)
      if(n[a] >= max_points_per_axis)
        throw Lattice_too_large_error("the lattice has " + std::to_string(n[a]) + " points along " +
                                      std::string(1, char('x' + a)) + "; at most " +
                                      std::to_string(max_points_per_axis - 1) +
                                      " are supported: use a larger spacing");
    const std::size_t T = triangles.size();
    // The lattice coordinates, computed once by the one formula.
    std::array<std::vector<double>, 3> coordinates;
    for(int a = 0; a < 3; ++a)
    {
      coordinates[a].resize(n[a]);
      for(std::size_t i = 0; i < n[a]; ++i)
        coordinates[a][i] = m_lattice.coordinate(a, i);
    }

    // Line blocks of every triangle for the three axes, and the memory
    // estimate, before the big allocations.
    std::array<Line_blocks, 3> blocks;
    std::array<std::size_t, 3> candidates{{0, 0, 0}}, binned{{0, 0, 0}};
    for(int axis = 0; axis < 3; ++axis)
    {
      internal::reserve_in_huge_pages(blocks[axis], T); // fewer fresh-page faults, as above
      blocks[axis].resize(T);
      internal::concurrent_for<ConcurrencyTag>(
          T, [&](std::size_t t) { blocks[axis][t] = line_block(triangles[t], axis, coordinates); });
      const int u = internal::line_u_axis(axis), v = internal::line_v_axis(axis);
      const double cell_area = m_lattice.spacing() * m_lattice.spacing();
      for(std::size_t t = 0; t < T; ++t)
      {
        const Line_block& b = blocks[axis][t];
        if(b.empty())
          continue;
        // The lines through a triangle's projection are lattice points of a
        // convex region: at most area / r^2 + perimeter / (2 r) + 1 of them
        // (Nosarzewska's bound), and at most its block.
        const auto& q = triangles[t].p;
        const double area = 0.5 * std::abs((q[1][u] - q[0][u]) * (q[2][v] - q[0][v]) -
                                           (q[2][u] - q[0][u]) * (q[1][v] - q[0][v]));
        double perimeter = 0;
        for(int e = 0; e < 3; ++e)
        {
          const double du = q[(e + 1) % 3][u] - q[e][u], dv = q[(e + 1) % 3][v] - q[e][v];
          perimeter += std::sqrt(du * du + dv * dv);
        }
        const double bound = area / cell_area + perimeter / (2 * m_lattice.spacing()) + 1;
        candidates[axis] += std::size_t((std::min)(double(b.size()), bound));
        binned[axis] += b.v1 - b.v0;
      }
    }
    check_memory(triangles.size(), candidates, binned, max_memory_bytes, reserved_bytes);

    const double weights[4] = {0, 0.5, 0.75, 1.0};
    for(int axis = 0; axis < 3; ++axis)
    {
      const auto start = std::chrono::steady_clock::now();
      process_axis<ConcurrencyTag>(axis, triangles, blocks[axis], coordinates,
                                   progress.part(weights[axis], weights[axis + 1]));
      Line_blocks().swap(blocks[axis]);
      m_seconds[axis] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }

  void check_memory(std::size_t number_of_triangles, const std::array<std::size_t, 3>& candidates,
                    const std::array<std::size_t, 3>& binned, std::size_t max_memory_bytes, std::size_t reserved_bytes)
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    // Doubles: the sum must not wrap around.
    double bytes = double(reserved_bytes) +
                   double(number_of_triangles) * double(sizeof(internal::Lattice_triangle) + 3 * sizeof(Line_block));
    double largest_axis = 0;
    for(int axis = 0; axis < 3; ++axis)
    {
      const double lines = double(n[internal::line_u_axis(axis)]) * double(n[internal::line_v_axis(axis)]);
      (void)lines;
      // The rows, and at most one stored line (and, along x, start mask) per candidate crossing.
      bytes += 8.0 * double(n[internal::line_v_axis(axis)] + 1) +
               double(candidates[axis]) * double(sizeof(Line_entry) + (axis == 0 ? 8 : 0));
      // The offsets are 32-bit: an upper bound of the crossings must fit.
      if(double(candidates[axis]) >= double(std::numeric_limits<Line_offset>::max()))
        throw Lattice_too_large_error("the lattice would hold more than 2^32 crossings along " +
                                      std::string(1, char('x' + axis)) + ": use a larger spacing");
      bytes += double(candidates[axis]) * double(sizeof(Crossing)); // at most that many crossings stay
      // Transient, one axis at a time: row buffers and bins.
      largest_axis = (std::max)(largest_axis, double(candidates[axis]) * double(sizeof(Row_crossing)) +
                                                  double(binned[axis]) * 4.0 + 8.0 * double(n[internal::line_v_axis(axis)]));
    }
    bytes += largest_axis;
    m_estimated_bytes = bytes < 1.8e19 ? std::size_t(bytes) : std::size_t(-1);
    if(bytes > double(max_memory_bytes))
    {
      std::ostringstream out;
      out.precision(3);
      out << "the lattice " << n[0] << " x " << n[1] << " x " << n[2] << " with " << m_number_of_meshes
          << " mesh(es) needs about " << bytes / double(1 << 30) << " GiB, more than the limit of "
          << double(max_memory_bytes) / double(1 << 30)
          << " GiB (named parameter max_memory_bytes): use a larger spacing or raise the limit";
      throw Lattice_too_large_error(out.str());
    }
  }

  // An interval [lo, hi] along u that contains the projection of `t` on the
  // row of lines at v = `pv`: the extent computed in double, widened by a
  // bound of its rounding error (a few ulps of the triangle's coordinates);
  // false if the row misses the triangle.
  static bool scan_extent(const internal::Lattice_triangle& t, int u, int v, double pv, double& lo, double& hi)
  {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    double magnitude = std::abs(pv);
    for(int e = 0; e < 3; ++e)
      magnitude = (std::max)({magnitude, std::abs(t.p[e][u]), std::abs(t.p[e][v])});
    // x = a_u + (pv - a_v) (b_u - a_u) / (b_v - a_v): each operation is off by
    // at most half an ulp of a value bounded by 2 * magnitude.
    const double error = 64 * std::numeric_limits<double>::epsilon() * magnitude +
                         std::numeric_limits<double>::denorm_min();
    for(int e = 0; e < 3; ++e)
    {
      const std::array<double, 3>& a = t.p[e];
      const std::array<double, 3>& b = t.p[(e + 1) % 3];
      if((a[v] - pv) * (b[v] - pv) > 0)
        continue; // the edge is on one side of the row
      if(a[v] == b[v])
      {
        lo = (std::min)({lo, a[u], b[u]});
        hi = (std::max)({hi, a[u], b[u]});
        continue;
      }
      const double x = a[u] + (pv - a[v]) * (b[u] - a[u]) / (b[v] - a[v]);
      lo = (std::min)(lo, x);
      hi = (std::max)(hi, x);
    }
    lo -= error;
    hi += error;
    if(!(std::isfinite(lo) && std::isfinite(hi)))
    {
      // Overflow far from the lattice: scan the whole block.
      lo = -std::numeric_limits<double>::infinity();
      hi = std::numeric_limits<double>::infinity();
    }
    return lo <= hi;
  }

  // Sorts the crossings of a row by (u, index, position, mesh): a counting
  // sort on u (there are few crossings per line), then an insertion sort of
  // each line.
  static void sort_row(std::vector<Row_crossing>& row, std::size_t nu)
  {
    if(row.size() < 2)
      return;
    // The counting sort costs O(nu): only where the row is dense in u (a
    // sparse row of a fine lattice would pay for the whole cross-section).
    if(row.size() < 32 || 4 * row.size() < nu)
    {
      std::sort(row.begin(), row.end());
      return;
    }
    std::vector<std::uint32_t> first(nu + 1, 0);
    for(const Row_crossing& c : row)
      ++first[c.u + 1];
    for(std::size_t j = 0; j < nu; ++j)
      first[j + 1] += first[j];
    std::vector<Row_crossing> sorted(row.size());
    for(const Row_crossing& c : row)
      sorted[first[c.u]++] = c;
    // first[j] is now the end of line j.
    std::size_t begin = 0;
    for(std::size_t j = 0; j < nu && begin < sorted.size(); ++j)
    {
      const std::size_t end = first[j];
      for(std::size_t a = begin + 1; a < end; ++a)
        for(std::size_t b = a; b > begin && sorted[b] < sorted[b - 1]; --b)
          std::swap(sorted[b], sorted[b - 1]);
      begin = end;
    }
    row.swap(sorted);
  }

  template <typename ConcurrencyTag>
  void process_axis(int axis, const std::vector<internal::Lattice_triangle>& triangles,
                    const Line_blocks& blocks, const std::array<std::vector<double>, 3>& coordinates,
                    const internal::Progress& progress)
  {
    const std::array<std::size_t, 3>& n = m_lattice.number_of_points();
    const int u = internal::line_u_axis(axis), v = internal::line_v_axis(axis);
    const std::size_t nu = n[u], nv = n[v], na = n[axis];

    // Bin the triangles to the rows (v indices) of lines they may cross, in
    // increasing triangle order (a counting sort).
    std::vector<std::size_t> row_begin(nv + 1, 0);
    for(const Line_block& b : blocks)
      if(!b.empty())
        for(std::uint32_t r = b.v0; r < b.v1; ++r)
          ++row_begin[r + 1];
    for(std::size_t r = 0; r < nv; ++r)
      row_begin[r + 1] += row_begin[r];
    std::vector<std::uint32_t> row_triangles(row_begin[nv]);
    {
      std::vector<std::size_t> fill(row_begin.begin(), row_begin.end() - 1);
      for(std::size_t t = 0; t < blocks.size(); ++t)
        if(!blocks[t].empty())
          for(std::uint32_t r = blocks[t].v0; r < blocks[t].v1; ++r)
            row_triangles[fill[r]++] = std::uint32_t(t);
    }

    std::vector<std::vector<Row_crossing>> rows(nv);
    // Per row, along x: the start masks of its lines, (u, mask), increasing u, non-zero.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint64_t>>> starts(axis == 0 ? nv : 0);
    internal::concurrent_for<ConcurrencyTag>(
        nv,
        [&](std::size_t r) {
          std::vector<Row_crossing>& out = rows[r];
          std::array<double, 3> p;
          p[v] = coordinates[v][r];
          for(std::size_t e = row_begin[r]; e < row_begin[r + 1]; ++e)
          {
            const internal::Lattice_triangle& t = triangles[row_triangles[e]];
            const Line_block& b = blocks[row_triangles[e]];
            // Only the lines within the triangle's extent on this row (up to
            // the rounding of that extent) can cross it; the exact test below
            // decides.  For a sliver across many cells: its area, not its box.
            double lo, hi;
            if(!scan_extent(t, u, v, p[v], lo, hi))
              continue;
            auto first_not_below = [&](double value) {
              return std::uint32_t(internal::first_index_not_below(coordinates[u].data(), nu, m_lattice.spacing(), value));
            };
            const std::uint32_t first = (std::max)(b.u0, first_not_below(lo));
            const std::uint32_t last = (std::min)(b.u1, first_not_below(hi) + 1);
            for(std::uint32_t ju = first; ju < last; ++ju)
            {
              p[u] = coordinates[u][ju];
              if(!internal::line_crosses_triangle(t, axis, p[u], p[v]))
                continue;
              const double position = internal::crossing_coordinate(t, axis, p[u], p[v]);
              const std::size_t guess =
                  internal::first_index_not_below(coordinates[axis].data(), na, m_lattice.spacing(), position);
              const std::size_t index = internal::crossing_index(t, axis, coordinates[axis].data(), na, p, guess);
              if(index >= na || (index == 0 && axis != 0))
                continue; // not on a lattice edge, and no effect on the classification
              out.push_back(Row_crossing{position, ju, std::uint32_t(index), t.mesh, row_triangles[e]});
            }
          }
          sort_row(out, nu);

          if(axis == 0)
          {
            // Classification: the parity of the crossings before each point.
            // The crossings before the first point give the line's start
            // mask; the others stay and define the rest of the line.
            for(const Row_crossing& c : out)
              if(c.index == 0)
              {
                if(starts[r].empty() || starts[r].back().first != c.u)
                  starts[r].emplace_back(c.u, 0);
                starts[r].back().second ^= std::uint64_t(1) << c.mesh;
              }
            starts[r].erase(std::remove_if(starts[r].begin(), starts[r].end(),
                                           [](const std::pair<std::uint32_t, std::uint64_t>& s) { return s.second == 0; }),
                            starts[r].end());
            out.erase(std::remove_if(out.begin(), out.end(), [](const Row_crossing& c) { return c.index == 0; }),
                      out.end());
          }
          for(Row_crossing& c : out)
          {
            const double low = coordinates[axis][c.index - 1], high = coordinates[axis][c.index];
            if(!(c.position >= low))
              c.position = low;
            if(!(c.position <= high))
              c.position = high;
          }
        },
        progress.part(0, 0.95));

    // Gather the rows into one array, line by line: the stored lines of a
    // row are the distinct u of its crossings (and, along x, of its start
    // masks), already sorted.
    auto for_each_line = [&](std::size_t r, const auto& f) { // f(u, first crossing, end, start mask)
      const std::vector<Row_crossing>& row = rows[r];
      const std::pair<std::uint32_t, std::uint64_t>* s = axis == 0 ? starts[r].data() : nullptr;
      const std::pair<std::uint32_t, std::uint64_t>* s_end = axis == 0 ? s + starts[r].size() : nullptr;
      std::size_t c = 0;
      while(c < row.size() || s != s_end)
      {
        std::uint32_t line_u = std::numeric_limits<std::uint32_t>::max();
        if(c < row.size()) line_u = row[c].u;
        if(s != s_end) line_u = (std::min)(line_u, s->first);
        std::uint64_t mask = 0;
        if(s != s_end && s->first == line_u)
          mask = (s++)->second;
        const std::size_t first = c;
        while(c < row.size() && row[c].u == line_u)
          ++c;
        f(line_u, first, c, mask);
      }
    };
    std::vector<std::size_t> row_offset(nv + 1, 0), line_offset(nv + 1, 0);
    internal::concurrent_for<ConcurrencyTag>(nv, [&](std::size_t r) {
      std::size_t lines = 0;
      for_each_line(r, [&](std::uint32_t, std::size_t, std::size_t, std::uint64_t) { ++lines; });
      line_offset[r + 1] = lines;
      row_offset[r + 1] = rows[r].size();
    });
    for(std::size_t r = 0; r < nv; ++r)
    {
      row_offset[r + 1] += row_offset[r];
      line_offset[r + 1] += line_offset[r];
    }
    std::vector<Crossing>& crossings = m_crossings[axis];
    crossings.resize(row_offset[nv]);
    std::vector<Line_entry>& lines = m_lines[axis];
    lines.resize(line_offset[nv] + 1);
    lines.back() = Line_entry{0, Line_offset(crossings.size())};
    if(axis == 0)
      m_start_masks.resize(line_offset[nv]);
    m_row_begin[axis] = line_offset;
    internal::concurrent_for<ConcurrencyTag>(nv, [&](std::size_t r) {
      std::size_t out = row_offset[r], entry = line_offset[r];
      for_each_line(r, [&](std::uint32_t line_u, std::size_t first, std::size_t last, std::uint64_t mask) {
        lines[entry] = Line_entry{line_u, Line_offset(row_offset[r] + first)};
        if(axis == 0)
          m_start_masks[entry] = mask;
        ++entry;
        (void)last;
      });
      for(const Row_crossing& c : rows[r])
      {
        Crossing& stored = crossings[out++];
        stored.position = c.position;
        stored.index = c.index;
        stored.mesh = c.mesh;
        stored.triangle = c.triangle;
      }
      std::vector<Row_crossing>().swap(rows[r]);
    });
    progress.report(1.0);
  }

  Regular_lattice_3 m_lattice;
  std::size_t m_number_of_meshes = 0;
  // Per axis: the stored lines of row v are m_lines[m_row_begin[v] .. m_row_begin[v + 1]).
  std::array<std::vector<std::size_t>, 3> m_row_begin;
  std::array<std::vector<Line_entry>, 3> m_lines;
  std::vector<std::uint64_t> m_start_masks; // per stored x line
  std::array<std::vector<Crossing>, 3> m_crossings;
  std::array<double, 3> m_seconds{{0, 0, 0}};
  std::size_t m_estimated_bytes = 0;
};

} // namespace Boolean_isosurfacing
} // namespace CGAL

#endif // CGAL_BOOLEAN_ISOSURFACING_3_LATTICE_CLASSIFIER_3_H
