// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of IO::read_closed_triangle_mesh(): the first byte
// chooses the extension (.off, .obj, .ply, .stl), the rest is the file.
// A mesh read is then checked for self-intersections twice, on its soup
// (internal::does_triangle_soup_self_intersect(), the volume tool's check)
// and by PMP::does_self_intersect(): the answers must agree.

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/internal/does_triangle_soup_self_intersect.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

void check_self_intersection_answers(const Mesh& mesh)
{
  // The mesh comes from a soup without garbage: its indices are the soup's.
  std::vector<std::array<double, 3>> points;
  for(const Mesh::Vertex_index v : vertices(mesh))
    points.push_back({{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}});
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for(const Mesh::Face_index f : faces(mesh))
  {
    std::array<std::uint32_t, 3> t;
    int i = 0;
    for(const Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh))
      t[std::size_t(i++)] = std::uint32_t(v);
    triangles.push_back(t);
  }
  const std::optional<bool> ours =
      CGAL::Boolean_isosurfacing::internal::does_triangle_soup_self_intersect<CGAL::Sequential_tag>(points, triangles);
  if(ours)
    biso_fuzz::require(*ours == CGAL::Polygon_mesh_processing::does_self_intersect(mesh),
                       "the soup's self-intersection answer is PMP's");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return 0;
  static const char* const extensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string path = biso_fuzz::write_temporary(data + 1, size - 1, extensions[data[0] % 4]);
  Mesh mesh;
  try
  {
    CGAL::Boolean_isosurfacing::IO::read_closed_triangle_mesh(path, mesh, (data[0] & 4) != 0);
    biso_fuzz::require(num_faces(mesh) >= 4, "a closed triangle mesh has at least 4 faces");
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
    return 0;
  }
  check_self_intersection_answers(mesh);
  return 0;
}
