/*!
\ingroup PkgBooleanIsosurfacing3Concepts
\cgalConcept

The concept `ContouringField_3` describes the signed function whose zero set
`CGAL::Boolean_isosurfacing::contour_signed_distance()` contours on a regular
lattice: a function that may be undefined (far from the samples), together
with the samples it was built from, which seed the traversal of the lattice
\cgalCite{Hoppe1992}.  `f < 0` is inside.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Boolean_isosurfacing::Tangent_plane_signed_distance_3}
\cgalHasModelsEnd
*/
class ContouringField_3
{
public:
  /// A point type constructible from three doubles, whose coordinates are `p[0]`, `p[1]`, `p[2]`.
  typedef unspecified_type Point_3;

  /// The seeds of the traversal: a range of `Point_3` (the samples).
  const std::vector<Point_3>& points() const;
  /// The sampling density rho: sets the default cell size, the lattice margin
  /// and the size of the "bubbles" that are removed.
  double sampling_density() const;
  /// The noise level delta (used in the defaults of the contouring).
  double noise_level() const;
  /// Optional: the default lattice spacing; without it the spacing is `sampling_density() / 3`.
  double default_cell_size() const;
  /// The value at `p`, or an empty optional where the function is undefined.
  std::optional<double> operator()(const Point_3& p) const;
  /// Optional, with `distance_to_samples()`: a value defined everywhere, one
  /// consistent sign per point; when the field has both, the contouring uses
  /// it (named parameter `consistent_signs`, default `true`), skips no cube,
  /// and cuts away the pieces far from the samples that span wide openings.
  double consistent_value(const Point_3& p) const;
  /// Optional, with `consistent_value()`: the distance from `p` to the nearest sample.
  double distance_to_samples(const Point_3& p) const;
};
