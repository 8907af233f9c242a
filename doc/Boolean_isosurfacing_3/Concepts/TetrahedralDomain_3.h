/*!
\ingroup PkgBooleanIsosurfacing3Concepts
\cgalConcept

The concept `TetrahedralDomain_3` describes a conforming tetrahedral mesh whose
vertices carry the samples of the scalar fields of a Boolean isosurface (TBISO,
\cgalCite{TaubinSibley2009}).  Vertices are numbered `0 ... number_of_vertices() - 1`;
the fields of a domain are a `CGAL::Boolean_isosurfacing::Scalar_fields` in
that vertex order.

`CGAL::Boolean_isosurfacing::sample_fields()` accepts any model;
`CGAL::Boolean_isosurfacing::extract_boolean_isosurface()` has one overload per
model below: the regular grid enumerates its tetrahedra on the fly (6 Kuhn
tetrahedra per cube) and is never stored, the unstructured mesh stores them
with their face neighbours.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Boolean_isosurfacing::Tetrahedral_grid_3}
\cgalHasModels{CGAL::Boolean_isosurfacing::Tetrahedral_mesh_3}
\cgalHasModelsEnd
*/
class TetrahedralDomain_3
{
public:
  /// The geometric traits, a model of `Kernel`.
  typedef unspecified_type Geom_traits;
  /// `Geom_traits::Point_3`.
  typedef unspecified_type Point_3;
  /// `std::array<std::size_t, 4>`: four vertex indices, positively oriented.
  typedef unspecified_type Tetrahedron;

  /// The number of vertices.
  std::size_t number_of_vertices() const;
  /// The number of tetrahedra.
  std::size_t number_of_tetrahedra() const;
  /// The position of vertex `v`, as a point.
  Point_3 point(std::size_t v) const;
  /// The position of vertex `v`, as three doubles (what the fields are sampled at).
  std::array<double, 3> position(std::size_t v) const;
};
