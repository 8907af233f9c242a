// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// libFuzzer harness of the scalar field readers.
//  - BISO_FUZZ_RAW undefined: the text layout; the input is the file.
//  - BISO_FUZZ_RAW defined: the raw layout; the first 4 bytes choose the
//    number of vertices (2 bytes), the number of fields N (0 to 65, so that
//    the invalid 0 and 65 are reached) and the extension (.raw, .f64, .f32),
//    the rest is the file.  Also reads sub-ranges as the out-of-core reader does.

#include "fuzz_common.h"

#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace IO = CGAL::Boolean_isosurfacing::IO;
  try
  {
#ifdef BISO_FUZZ_RAW
    if(size < 4)
      return 0;
    const std::size_t vertices = std::size_t(data[0]) | (std::size_t(data[1]) << 8);
    const std::size_t fields = data[2] % 66;
    static const char* const extensions[] = {".raw", ".f64", ".f32"};
    const char* extension = extensions[data[3] % 3];
    const std::string path = biso_fuzz::write_temporary(data + 4, size - 4, extension);
    // Hint 0 exercises the "give N" message; the hint itself the reader.
    const CGAL::Boolean_isosurfacing::Scalar_fields all = IO::read_scalar_fields(path, vertices, fields);
    biso_fuzz::require(all.number_of_vertices() == vertices && all.number_of_fields() == fields,
                       "raw: counts");
    const IO::Raw_scalar_type type =
        (data[3] % 3 == 2) ? IO::Raw_scalar_type::FLOAT32 : IO::Raw_scalar_type::FLOAT64;
    IO::Raw_scalar_field_reader reader(path, vertices, fields, type);
    std::vector<double> values;
    const std::size_t first = vertices / 3, count = vertices - first;
    reader.read(first, count, values);
    for(std::size_t k = 0; k < values.size(); ++k)
      biso_fuzz::require(values[k] == all.data()[first * fields + k], "raw: sub-range differs from the whole");
    try
    {
      reader.read(first, vertices, values); // out of range unless first == 0
      biso_fuzz::require(first == 0, "raw: out-of-range read accepted");
    }
    catch(const std::out_of_range&)
    {
    }
#else
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    const CGAL::Boolean_isosurfacing::Scalar_fields fields = IO::read_text_scalar_fields(in);
    std::ostringstream out;
    IO::write_text_scalar_fields(out, fields);
    std::istringstream again(out.str());
    const CGAL::Boolean_isosurfacing::Scalar_fields reread = IO::read_text_scalar_fields(again);
    biso_fuzz::require(reread.number_of_fields() == fields.number_of_fields() && reread.data() == fields.data(),
                       "text scalar fields round trip");
#endif
  }
  catch(const CGAL::Boolean_isosurfacing::Invalid_input_error&)
  {
  }
  return 0;
}
