/*!
\ingroup PkgBooleanIsosurfacing3Concepts
\cgalConcept

The concept `BooleanIsosurfaceSink` receives the surface that the slab-by-slab
TBISO driver streams out: points, numbered from 0 in the order they are added,
then polygons on them, each labelled by the field whose zero set it lies on.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Boolean_isosurfacing::Boolean_isosurface_soup_sink}
\cgalHasModels{CGAL::Boolean_isosurfacing::IO::Boolean_isosurface_PLY_stream}
\cgalHasModelsEnd

\sa `CGAL::Boolean_isosurfacing::extract_boolean_isosurface_by_slabs()`
*/
class BooleanIsosurfaceSink
{
public:
  /// Adds the next point.
  void add_point(const std::array<double, 3>& p);
  /// Adds a polygon of `n` vertices (indices of added points, in
  /// counter-clockwise order seen from outside) lying on the zero set of field
  /// `field` (-1 for a face that closes the set on the domain boundary).
  void add_polygon(const std::size_t* vertices, std::size_t n, int field);
};
