/*!
\ingroup PkgBooleanIsosurfacing3Concepts
\cgalConcept

The concept `SurveyorVolumeTraits_3` describes the geometric types and
functors that `CGAL::Boolean_isosurfacing::surveyor_volume()` needs.

When `FT` is `double`, the volume is computed from the Cartesian coordinates
given by `Compute_x_3`, `Compute_y_3`, `Compute_z_3` (with a certified error
bound and an exact fallback); for other number types, `Compute_volume_3` is
summed.  The test `SurveyorVolume.ConceptArchetypeIsEnough` compiles the
function with a traits class that has exactly the members below.

When the named parameter `check_self_intersections` is passed, the traits must
also meet the requirements of `CGAL::Polygon_mesh_processing::does_self_intersect()`.

\cgalHasModelsBegin
\cgalHasModels{All models of `Kernel`: `CGAL::Exact_predicates_inexact_constructions_kernel`\, `CGAL::Exact_predicates_exact_constructions_kernel`\, `CGAL::Simple_cartesian<double>`\, ...}
\cgalHasModelsEnd
*/
class SurveyorVolumeTraits_3
{
public:
  /// A number type: `double`, or a model of `FieldNumberType`.
  typedef unspecified_type FT;
  /// The point type of the mesh (the value type of its vertex point map).
  typedef unspecified_type Point_3;

  /// `FT operator()(const Point_3& p) const`: the x coordinate of `p`.
  typedef unspecified_type Compute_x_3;
  /// The same for the y coordinate.
  typedef unspecified_type Compute_y_3;
  /// The same for the z coordinate.
  typedef unspecified_type Compute_z_3;
  /// `Point_3 operator()(const FT& x, const FT& y, const FT& z) const`.
  typedef unspecified_type Construct_point_3;
  /// `FT operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) const`:
  /// the signed volume of the tetrahedron (p, q, r, s), positive when (p, q, r, s) is positively oriented.
  typedef unspecified_type Compute_volume_3;

  /// \name Function objects
  /// @{

  /// returns a `Compute_x_3`.
  Compute_x_3 compute_x_3_object() const;
  /// returns a `Compute_y_3`.
  Compute_y_3 compute_y_3_object() const;
  /// returns a `Compute_z_3`.
  Compute_z_3 compute_z_3_object() const;
  /// returns a `Construct_point_3`.
  Construct_point_3 construct_point_3_object() const;
  /// returns a `Compute_volume_3`.
  Compute_volume_3 compute_volume_3_object() const;
  /// @}
};
