/*!
\ingroup PkgBooleanIsosurfacing3Concepts
\cgalConcept

The concept `ScalarFieldSource` describes where the out-of-core and
distributed TBISO drivers read the values of N scalar fields at the vertices
of a grid, one range of vertices (a slab) at a time, so that the fields never
need to be in memory at once.

\cgalHasModelsBegin
\cgalHasModels{CGAL::Boolean_isosurfacing::Scalar_fields_source}
\cgalHasModels{CGAL::Boolean_isosurfacing::IO::Raw_scalar_field_reader}
\cgalHasModels{CGAL::Boolean_isosurfacing::Mpi_raw_scalar_field_reader}
\cgalHasModelsEnd

\sa `CGAL::Boolean_isosurfacing::extract_boolean_isosurface_by_slabs()`
*/
class ScalarFieldSource
{
public:
  /// The number N of fields.
  std::size_t number_of_fields() const;
  /// Writes to `values` (resized to `count * number_of_fields()`) the values of
  /// vertices `[first_vertex, first_vertex + count)`, vertex-major: the N values
  /// of vertex `first_vertex`, then those of the next vertex, and so on.
  void read(std::size_t first_vertex, std::size_t count, std::vector<double>& values);
};
