// Marching Cubes CSG against CGAL's exact Booleans: PMP corefinement (Epeck)
// on real meshes and Nef_polyhedron_3 on small ones.  For each pair and
// operation, at three lattice resolutions: the output is closed and
// 2-manifold, its volume converges to the exact result's, its one-sided
// Hausdorff distance to the exact result is at most sqrt(3) r, and the
// distance from the exact result to it shrinks with r.  All Nef-based checks
// live in this one binary (Nef compiles and runs slowly).

#include <CGAL/Boolean_isosurfacing_3/Boolean_expression.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/generators.h>
#include <CGAL/Boolean_isosurfacing_3/marching_cubes_csg.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace CGAL::Boolean_isosurfacing::test::kernels;

enum class Operation { UNION, INTERSECTION, DIFFERENCE };
const char* name(Operation op)
{
  return op == Operation::UNION ? "union" : op == Operation::INTERSECTION ? "intersection" : "difference";
}
BI::Boolean_expression expression(Operation op)
{
  return op == Operation::UNION ? BI::Boolean_expression::union_of(2)
         : op == Operation::INTERSECTION ? BI::Boolean_expression::intersection_of(2)
                                         : BI::Boolean_expression::difference();
}

Mesh read_shared(const std::string& relative)
{
  Mesh mesh;
  BI::IO::read_closed_triangle_mesh(std::string(BISO_SHARED_DATA_DIR) + "/" + relative, mesh);
  return mesh;
}

Mesh transformed(const Mesh& mesh, const Epick::Aff_transformation_3& t)
{
  Mesh copy = mesh;
  PMP::transform(t, copy);
  return copy;
}

// The exact Boolean result, by corefinement on Epeck, as an Epick mesh.
Mesh corefinement_result(const Mesh& a, const Mesh& b, Operation op)
{
  Exact_mesh ea, eb, result;
  CGAL::copy_face_graph(a, ea);
  CGAL::copy_face_graph(b, eb);
  bool ok = false;
  switch(op)
  {
    case Operation::UNION: ok = PMP::corefine_and_compute_union(ea, eb, result); break;
    case Operation::INTERSECTION: ok = PMP::corefine_and_compute_intersection(ea, eb, result); break;
    case Operation::DIFFERENCE: ok = PMP::corefine_and_compute_difference(ea, eb, result); break;
  }
  EXPECT_TRUE(ok) << "corefinement failed";
  Mesh out;
  CGAL::copy_face_graph(result, out);
  return out;
}

// Sampled one-sided Hausdorff distance from `a` to `b`
// (PMP::approximate_Hausdorff_distance: sample a, exact distance to b).
double one_sided_hausdorff(const Mesh& a, const Mesh& b)
{
  return PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
      a, b, CGAL::parameters::number_of_points_per_area_unit(20000.0 / PMP::area(a)));
}

struct Csg_run
{
  Mesh mesh;
  double spacing;
};

Csg_run mc_csg(const Mesh& a, const Mesh& b, Operation op, std::size_t cells)
{
  CGAL::Bbox_3 box = PMP::bbox(a) + PMP::bbox(b);
  // The round lattice (offset 0) these sequences were measured on: with the
  // default golden-section offset, bunny - moved bunny at 128 cells has an
  // exact -> output distance of 3.72 r (1.47 r at 64): a thin wedge sampled
  // differently, not a convergence failure (see features.md).
  const BI::Regular_lattice_3 lattice = BI::Regular_lattice_3::enclosing_with_cells(box, cells, 1, 0.0);
  Csg_run run{Mesh(), lattice.spacing()};
  const std::vector<Mesh> meshes = {a, b};
  // Plain Marching Cubes: the convergence claims below are the plain
  // method's (with sharp features, test_csg_features.cpp; the errors there
  // are smaller but do not always shrink monotonically, see features.md).
  BI::marching_cubes_csg(lattice, meshes, expression(op), run.mesh, BI::parameters::sharp_features(false));
  return run;
}

void expect_closed_2_manifold_outward(const Mesh& m, const std::string& what)
{
  EXPECT_TRUE(CGAL::is_closed(m)) << what;
  EXPECT_TRUE(CGAL::is_triangle_mesh(m)) << what;
  // polygon_soup_to_polygon_mesh would have duplicated non-manifold
  // vertices; none may share a position with another vertex.
  std::vector<Point> positions;
  for(auto v : vertices(m)) positions.push_back(m.point(v));
  std::sort(positions.begin(), positions.end());
  EXPECT_EQ(std::adjacent_find(positions.begin(), positions.end()), positions.end())
      << what << ": duplicated (non-manifold) vertex";
  EXPECT_GT(BI::surveyor_volume(m, BI::parameters::signed_volume(true)), 0) << what;
}

// One pair, all three operations, three resolutions.
void check_pair(const std::string& label, const Mesh& a, const Mesh& b, const std::vector<std::size_t>& cells)
{
  for(Operation op : {Operation::UNION, Operation::INTERSECTION, Operation::DIFFERENCE})
  {
    const Mesh exact = corefinement_result(a, b, op);
    const double exact_volume = BI::test::exact_volume(exact);
    ASSERT_GT(exact_volume, 0) << label << " " << name(op);
    std::vector<double> errors, distances_from_exact;
    for(std::size_t n : cells)
    {
      const Csg_run run = mc_csg(a, b, op, n);
      const std::string what = label + " " + name(op) + " cells " + std::to_string(n);
      expect_closed_2_manifold_outward(run.mesh, what);
      const double error = std::abs(BI::surveyor_volume(run.mesh) - exact_volume) / exact_volume;
      errors.push_back(error);
      const double to_exact = one_sided_hausdorff(run.mesh, exact);
      const double from_exact = one_sided_hausdorff(exact, run.mesh);
      std::printf("%-24s %-12s cells %4zu  r %.4g  volume rel. error %.3e  Hausdorff out->exact %.2f r, "
                  "exact->out %.2f r\n",
                  label.c_str(), name(op), n, run.spacing, error, to_exact / run.spacing, from_exact / run.spacing);
      // Guaranteed: every output triangle lies in one lattice cube and its
      // vertices are exact crossings, i.e. points of the exact surface.
      EXPECT_LE(to_exact, std::sqrt(3.0) * run.spacing) << what;
      // Not guaranteed the other way: where the two surfaces meet at a
      // shallow angle, or where the result is a slab thinner than r, the
      // exact result has parts that no lattice point samples (measured: up
      // to 4.6 r, fandisk minus a copy moved by 5% of its height).
      // Asserted: it shrinks with r (below).
      distances_from_exact.push_back(from_exact);
    }
    // Converges: every refinement (halving r) reduces the error by a clear
    // factor (linear convergence would give 2), unless it is already at the
    // level where the polyhedral inputs' own facets dominate (1e-4).
    for(std::size_t i = 1; i < errors.size(); ++i)
      EXPECT_TRUE(errors[i] < errors[i - 1] / 1.5 || errors[i] < 1e-4)
          << label << " " << name(op) << ": error " << errors[i - 1] << " -> " << errors[i];
    for(std::size_t i = 1; i < distances_from_exact.size(); ++i)
      EXPECT_LT(distances_from_exact[i], distances_from_exact[i - 1])
          << label << " " << name(op) << ": Hausdorff distance from the exact result does not shrink";
  }
}

TEST(CsgReference, SharedBallsAgainstCorefinement)
{
  check_pair("ballA/ballB", read_shared("boolean_pairs/ballA.off"), read_shared("boolean_pairs/ballB.off"),
             {24, 48, 96});
}

TEST(CsgReference, TorusAndRotatedCopyInterlinked)
{
  // The shared torus (R = 1, r = 0.5, axis z) and a copy rotated 90 degrees
  // about x and shifted by (0.8, 0, 0): the tubes interlink and overlap.
  const Mesh torus = read_shared("meshes/torus.off");
  const Epick::Aff_transformation_3 rotate_x(1, 0, 0, 0, 0, -1, 0, 1, 0);
  const Epick::Aff_transformation_3 shift(CGAL::TRANSLATION, Epick::Vector_3(0.8, 0, 0));
  check_pair("torus/rotated torus", torus, transformed(torus, shift * rotate_x), {24, 48, 96});
}

TEST(CsgReference, BunnyAndMovedCopy)
{
  const Mesh bunny = read_shared("meshes/bunny.off");
  const CGAL::Bbox_3 box = PMP::bbox(bunny);
  const Epick::Aff_transformation_3 shift(CGAL::TRANSLATION,
                                          Epick::Vector_3(0.3 * (box.xmax() - box.xmin()), 0.1 * (box.ymax() - box.ymin()), 0));
  check_pair("bunny/moved bunny", bunny, transformed(bunny, shift), {32, 64, 128});
}

TEST(CsgReference, FandiskAndMovedCopy)
{
  // Sharp features.  (Against a copy rotated by 0.3 rad about z,
  // corefine_and_compute_difference itself reports failure, so the exact
  // reference is a translated copy.)
  const Mesh fandisk = read_shared("meshes/fandisk.off");
  const CGAL::Bbox_3 box = PMP::bbox(fandisk);
  const Epick::Aff_transformation_3 shift(
      CGAL::TRANSLATION, Epick::Vector_3(0.25 * (box.xmax() - box.xmin()), 0.1 * (box.ymax() - box.ymin()),
                                         0.05 * (box.zmax() - box.zmin())));
  check_pair("fandisk/moved fandisk", fandisk, transformed(fandisk, shift), {32, 64, 128});
}

// Nef_polyhedron_3 as a second, independent exact reference on small inputs:
// it must agree with corefinement, and MC must converge to both.
TEST(CsgReference, NefPolyhedronAgreesWithCorefinementAndMarchingCubesConverges)
{
  Mesh a, b;
  BI::make_icosphere(a, Point(0, 0, 0), 1.0, 2);
  BI::make_icosphere(b, Point(0.7, 0.2, 0.1), 0.8, 2);
  Exact_mesh ea, eb;
  CGAL::copy_face_graph(a, ea);
  CGAL::copy_face_graph(b, eb);
  typedef CGAL::Nef_polyhedron_3<Epeck> Nef;
  const Nef na(ea), nb(eb);
  for(Operation op : {Operation::UNION, Operation::INTERSECTION, Operation::DIFFERENCE})
  {
    const Nef result = op == Operation::UNION ? na + nb : op == Operation::INTERSECTION ? na * nb : na - nb;
    ASSERT_TRUE(result.is_simple()) << name(op);
    Exact_mesh nef_mesh;
    CGAL::convert_nef_polyhedron_to_polygon_mesh(result, nef_mesh, /* triangulate_all_faces */ true);
    const Epeck::FT nef_volume = PMP::volume(nef_mesh);
    const Mesh core = corefinement_result(a, b, op);
    Exact_mesh core_exact;
    CGAL::copy_face_graph(core, core_exact);
    // Corefinement output was rounded to double by the copy to Epick: compare
    // to double precision.
    const double nef_v = CGAL::to_double(CGAL::exact(nef_volume));
    EXPECT_NEAR(BI::test::exact_volume(core), nef_v, 1e-12 * nef_v) << name(op);
    double previous = 1;
    for(std::size_t n : {16, 32, 64})
    {
      const Csg_run run = mc_csg(a, b, op, n);
      expect_closed_2_manifold_outward(run.mesh, std::string("Nef spheres ") + name(op));
      const double error = std::abs(BI::surveyor_volume(run.mesh) - nef_v) / nef_v;
      std::printf("Nef spheres %-13s cells %3zu  volume rel. error vs Nef %.3e\n", name(op), n, error);
      EXPECT_LT(error, previous) << name(op);
      previous = error;
    }
  }
}

} // namespace
