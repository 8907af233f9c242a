// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of the Medit `.mesh` reader (BISO_FUZZ_TETGEN undefined:
// the input is the file) or of the TetGen reader (BISO_FUZZ_TETGEN defined:
// the input is the `.node` file, a NUL byte, then the `.ele` file).

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sstream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Boolean_isosurfacing::IO;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try
  {
#ifdef BISO_FUZZ_TETGEN
    const std::size_t split = bytes.find('\0');
    std::istringstream node(bytes.substr(0, split));
    std::istringstream ele(split == std::string::npos ? std::string() : bytes.substr(split + 1));
    const CGAL::Boolean_isosurfacing::Tetrahedral_mesh_3<K> mesh = IO::read_TetGen<K>(node, ele);
#else
    std::istringstream in(bytes);
    const CGAL::Boolean_isosurfacing::Tetrahedral_mesh_3<K> mesh = IO::read_MEDIT<K>(in);
#endif
    // Round trip through the Medit writer.
    std::ostringstream out;
    IO::write_MEDIT(out, mesh);
    std::istringstream again(out.str());
    const CGAL::Boolean_isosurfacing::Tetrahedral_mesh_3<K> reread = IO::read_MEDIT<K>(again);
    biso_fuzz::require(reread.points() == mesh.points() && reread.tetrahedra() == mesh.tetrahedra(),
                       "Medit round trip");
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
  }
  return 0;
}
