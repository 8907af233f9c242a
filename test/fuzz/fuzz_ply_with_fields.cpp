// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of IO::read_PLY_with_fields(): the input is the file
// (ASCII or binary).  What it reads must survive a write/read round trip.

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>

#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Boolean_isosurfacing::IO;
  typedef CGAL::Boolean_isosurfacing::Boolean_isosurface_soup<biso_fuzz::Point> Soup;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size), std::ios::binary);
  Soup soup;
  try
  {
    IO::read_PLY_with_fields(in, soup);
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
    return 0;
  }
  // Polygons the writer cannot store (fewer than 3 or more than 255
  // vertices) are legal to read but not to write back.
  for(const auto& polygon : soup.polygons)
    if(polygon.size() < 3 || polygon.size() > 255)
      return 0;
  for(bool binary : {false, true})
  {
    std::ostringstream out(std::ios::binary);
    IO::write_PLY_with_fields(out, soup, binary);
    std::istringstream again(out.str(), std::ios::binary);
    Soup reread;
    IO::read_PLY_with_fields(again, reread);
    biso_fuzz::require(reread.polygons == soup.polygons && reread.face_fields == soup.face_fields &&
                         reread.points.size() == soup.points.size(),
                       "PLY round trip");
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      for(int c = 0; c < 3; ++c)
        biso_fuzz::require(reread.points[i].c[c] == soup.points[i].c[c], "PLY round trip: coordinates");
  }
  return 0;
}
