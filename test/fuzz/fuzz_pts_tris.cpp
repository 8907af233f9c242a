// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of the `.pts` reader (BISO_FUZZ_TRIS undefined) or of the
// `.tris` reader (BISO_FUZZ_TRIS defined): the input is the file's bytes.

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tris.h>

#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Boolean_isosurfacing::IO;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try
  {
#ifdef BISO_FUZZ_TRIS
    const std::vector<IO::Tris_triangle> triangles = IO::read_tris(in);
    // Round trip: writing the triangles' vertices and reading them back gives the same vertices.
    std::vector<biso_fuzz::Point> points;
    std::vector<std::array<std::size_t, 3>> faces;
    for(const IO::Tris_triangle& t : triangles)
    {
      for(const auto& p : {t.p0, t.p1, t.p2})
        points.emplace_back(p[0], p[1], p[2]);
      faces.push_back({points.size() - 3, points.size() - 2, points.size() - 1});
    }
    std::ostringstream out;
    biso_fuzz::require(IO::write_tris(out, points, faces), "write_tris");
    std::istringstream again(out.str());
    const std::vector<IO::Tris_triangle> reread = IO::read_tris(again);
    biso_fuzz::require(reread.size() == triangles.size(), "tris round trip: triangle count");
    for(std::size_t i = 0; i < triangles.size(); ++i)
      biso_fuzz::require(reread[i].p0 == triangles[i].p0 && reread[i].p1 == triangles[i].p1 &&
                           reread[i].p2 == triangles[i].p2,
                         "tris round trip: vertices");
#else
    std::vector<biso_fuzz::Point> points;
    std::vector<biso_fuzz::Point> normals;
    const bool with_normals = IO::read_pts(in, points, normals);
    biso_fuzz::require(!points.empty(), "read_pts returned no point");
    biso_fuzz::require(with_normals ? normals.size() == points.size() : normals.empty(), "pts normal count");
#endif
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
  }
  return 0;
}
