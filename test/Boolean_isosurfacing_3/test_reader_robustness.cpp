// Copyright (c) 2026 Boolean Isosurfacing for CGAL contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

// Hostile inputs of the readers, most found by the fuzz harnesses of
// test/fuzz (see doc/Boolean_isosurfacing_3/fuzzing.md): each must give one
// clear error, quickly and without a large allocation.  The bytes are made
// here, not read from files.

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/pts.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_point_samples.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef BI::Boolean_isosurface_soup<K::Point_3> Soup;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The message of the Invalid_input_error that reading `bytes` as a PLY with fields throws ("" if none).
std::string ply_error(const std::string& bytes)
{
  std::istringstream in(bytes, std::ios::binary);
  Soup soup;
  try
  {
    BI::IO::read_PLY_with_fields(in, soup, "t.ply");
  }
  catch(const BI::Invalid_input_error& e)
  {
    return e.what();
  }
  return "";
}

bool one_printable_line(const std::string& message)
{
  for(char c : message)
    if(static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
      return false;
  return !message.empty();
}

const std::string ply_tetra_header =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
    "element face 4\nproperty list uchar int vertex_indices\nproperty int field\nend_header\n";
const std::string ply_tetra_body = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 0\n3 0 1 3 0\n3 0 3 2 1\n3 1 2 3 -1\n";

TEST(Reader_robustness, Ply_valid_still_reads)
{
  std::istringstream in(ply_tetra_header + ply_tetra_body + "\n\n");
  Soup soup;
  BI::IO::read_PLY_with_fields(in, soup);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.polygons.size(), 4u);
  EXPECT_EQ(soup.face_fields[3], -1);
}

// The fuzzer's 219-byte input: a binary PLY whose property-less element has
// a count near 2^64 made the reader loop over empty records.
TEST(Reader_robustness, Ply_property_less_element_with_huge_count)
{
  const std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                            "property float y\nproperty float z\nelement nothing 18446744073709551615\n"
                            "element face 0\nproperty list uchar int vertex_indices\nproperty int field\n"
                            "end_header\n" + std::string(12, '\0');
  const auto start = std::chrono::steady_clock::now();
  const std::string message = ply_error(bytes);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_TRUE(contains(message, "element 'nothing' has 18446744073709551615 records but no property")) << message;
  EXPECT_TRUE(one_printable_line(message)) << message;
}

TEST(Reader_robustness, Ply_count_overflow)
{
  std::string header = ply_tetra_header;
  header.replace(header.find("vertex 4"), 8, "vertex 99999999999999999999999");
  const std::string message = ply_error(header + ply_tetra_body);
  EXPECT_TRUE(contains(message, "count of element 'vertex' is out of range")) << message;
  EXPECT_TRUE(contains(message, "line 3")) << message;
}

TEST(Reader_robustness, Ply_count_larger_than_the_file)
{
  std::string header = ply_tetra_header;
  header.replace(header.find("face 4"), 6, "face 4000000000");
  const std::string message = ply_error(header + ply_tetra_body);
  EXPECT_TRUE(contains(message, "announces 4000000000 'face' records")) << message;
  // Binary: 3 doubles a vertex, 24 bytes each.
  const std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty double x\n"
                             "property double y\nproperty double z\nelement face 0\n"
                             "property list uchar int vertex_indices\nproperty int field\nend_header\n" +
                             std::string(48, '\0');
  const std::string m2 = ply_error(binary);
  EXPECT_TRUE(contains(m2, "100000000 'vertex' records of at least 24 bytes, but only 48 bytes")) << m2;
}

TEST(Reader_robustness, Ply_trailing_bytes)
{
  std::string message = ply_error(ply_tetra_header + ply_tetra_body + "0 0 0\n");
  EXPECT_TRUE(contains(message, "line 19: text after the last element")) << message;
  const std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty double x\n"
                             "property double y\nproperty double z\nelement face 0\n"
                             "property list uchar int vertex_indices\nproperty int field\nend_header\n" +
                             std::string("xyz");
  message = ply_error(binary);
  EXPECT_TRUE(contains(message, "3 trailing bytes after the last element")) << message;
}

TEST(Reader_robustness, Ply_version_word)
{
  std::string header = ply_tetra_header;
  header.replace(header.find("1.0"), 3, "\x1b[31m");
  const std::string message = ply_error(header + ply_tetra_body);
  EXPECT_TRUE(contains(message, "unsupported PLY version '\\x1b[31m' (only 1.0 is read)")) << message;
  EXPECT_TRUE(one_printable_line(message)) << message;
}

TEST(Reader_robustness, Ply_garbage_is_escaped)
{
  const std::string message = ply_error("ply\nformat ascii 1.0\n\x01\x02garbage\xff\xfe\nend_header\n");
  EXPECT_TRUE(contains(message, "unknown PLY header line '\\x01\\x02garbage\\xff\\xfe'")) << message;
  EXPECT_TRUE(one_printable_line(message)) << message;
}

TEST(Reader_robustness, Medit_count_larger_than_the_file)
{
  std::istringstream in("MeshVersionFormatted 2\nDimension 3\nVertices\n1000000000000\n0 0 0 0\n");
  try
  {
    BI::IO::read_MEDIT<K>(in, "m.mesh");
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Parse_error& e)
  {
    EXPECT_TRUE(contains(e.what(), "'m.mesh' line 4: the header announces 1000000000000 vertices")) << e.what();
  }
  std::istringstream tets("Vertices 0\nTetrahedra 99999999999\n");
  EXPECT_THROW(BI::IO::read_MEDIT<K>(tets, "m.mesh"), BI::Parse_error);
}

TEST(Reader_robustness, TetGen_count_larger_than_the_file)
{
  std::istringstream node("4000000000 3 0 0\n0 0 0 0\n"), ele("1 4 0\n0 0 1 2 3\n");
  try
  {
    BI::IO::read_TetGen<K>(node, ele, "t.node", "t.ele");
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Parse_error& e)
  {
    EXPECT_TRUE(contains(e.what(), "'t.node' line 1: the header announces 4000000000 vertices")) << e.what();
  }
}

TEST(Reader_robustness, Binary_bytes_are_escaped)
{
  std::istringstream mesh("Vertices 1\n\x1b]0;owned\x07 0 0 0\n");
  try
  {
    BI::IO::read_MEDIT<K>(mesh, "m.mesh");
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Invalid_input_error& e)
  {
    EXPECT_TRUE(one_printable_line(e.what())) << e.what();
    EXPECT_TRUE(contains(e.what(), "\\x1b]0;owned\\x07")) << e.what();
  }
  std::vector<K::Point_3> p;
  std::vector<K::Vector_3> n;
  std::istringstream pts("0 0 0\n1 \x9b" "2J 3\n");
  try
  {
    BI::IO::read_pts(pts, p, n);
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Parse_error& e)
  {
    EXPECT_TRUE(one_printable_line(e.what())) << e.what();
    EXPECT_EQ(e.position(), 2u);
  }
  std::istringstream fields("1\n0.5\x1b[2J\n");
  try
  {
    BI::IO::read_text_scalar_fields(fields, "f.txt");
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Parse_error& e)
  {
    EXPECT_TRUE(one_printable_line(e.what())) << e.what();
  }
}

std::string write_temporary(const std::string& name, const std::string& bytes)
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(Reader_robustness, Xyz_error_is_one_line_naming_the_file_and_line)
{
  const std::string path = write_temporary("robustness_bad.xyz", "3\n0 0 0\n1 2 3\n1 2 x\n");
  std::vector<K::Point_3> p;
  std::vector<K::Vector_3> n;
  try
  {
    BI::IO::read_point_samples(path, p, n);
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Parse_error& e)
  {
    EXPECT_TRUE(contains(e.what(), "'" + path + "' line 4: 'x' is not a number")) << e.what();
    EXPECT_TRUE(one_printable_line(e.what())) << e.what();
    EXPECT_EQ(e.position(), 4u);
  }
  // A valid .xyz with its optional count line, and a .pwn with normals.
  p.clear();
  EXPECT_FALSE(BI::IO::read_point_samples(write_temporary("robustness_ok.xyz", "2\n0 0 0\n1 2 3\n"), p, n));
  EXPECT_EQ(p.size(), 2u);
  p.clear();
  EXPECT_TRUE(BI::IO::read_point_samples(write_temporary("robustness_ok.pwn", "0 0 0 0 0 1\n1 2 3 1 0 0\n"), p, n));
  EXPECT_EQ(n.size(), 2u);
  // Incomplete normals, and a directory.
  EXPECT_THROW(BI::IO::read_point_samples(write_temporary("robustness_bad.pwn", "0 0 0 0 0\n"), p, n),
               BI::Parse_error);
  try
  {
    BI::IO::read_point_samples(::testing::TempDir() + ".", p, n);
    ADD_FAILURE() << "accepted";
  }
  catch(const BI::Invalid_input_error& e)
  {
    EXPECT_TRUE(contains(e.what(), "it is a directory")) << e.what();
  }
}

} // namespace
