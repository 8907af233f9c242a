// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of IO::read_closed_triangle_mesh(): the first byte
// chooses the extension (.off, .obj, .ply, .stl), the rest is the file.

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return 0;
  static const char* const extensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string path = biso_fuzz::write_temporary(data + 1, size - 1, extensions[data[0] % 4]);
  CGAL::Surface_mesh<K::Point_3> mesh;
  try
  {
    CGAL::Boolean_isosurfacing::IO::read_closed_triangle_mesh(path, mesh, (data[0] & 4) != 0);
    biso_fuzz::require(num_faces(mesh) >= 4, "a closed triangle mesh has at least 4 faces");
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
  }
  return 0;
}
