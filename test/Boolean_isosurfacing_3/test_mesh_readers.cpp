// The package's mesh readers (IO::read_triangle_soup and the closed-mesh
// readers built on it) and writers: every format and variant against the
// same mesh written in code, hostile headers, truncated and corrupted files,
// non-finite coordinates, line numbers in errors, and CGAL's own reader as
// an independent oracle on the shared meshes.

#include "mesh_format_writers.h"

#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/IO/write_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/surveyor_volume.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
using BI::IO::Mesh_file_format;
using biso_test::Triangle_soup_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

Triangle_soup_3 read_bytes(const std::string& bytes, Mesh_file_format format)
{
  Triangle_soup_3 soup;
  BI::IO::read_triangle_soup(bytes.data(), bytes.size(), format, soup);
  return soup;
}

// The message of the Invalid_input_error that `f` throws ("" if none).
std::string error_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch(const BI::Invalid_input_error& e)
  {
    return e.what();
  }
  return "";
}

std::string read_error(const std::string& bytes, Mesh_file_format format)
{
  return error_of([&] { read_bytes(bytes, format); });
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// A cube of side 3 with integer corners, outward: volume 27.
Triangle_soup_3 integer_cube()
{
  Triangle_soup_3 s;
  for(int k = 0; k < 8; ++k) s.points.push_back({3.0 * (k & 1), 3.0 * ((k >> 1) & 1), 3.0 * ((k >> 2) & 1)});
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

void expect_same_soup(const Triangle_soup_3& expected, const Triangle_soup_3& actual, const std::string& what)
{
  ASSERT_EQ(actual.points.size(), expected.points.size()) << what;
  ASSERT_EQ(actual.triangles.size(), expected.triangles.size()) << what;
  EXPECT_TRUE(actual.points == expected.points) << what;
  EXPECT_TRUE(actual.triangles == expected.triangles) << what;
}

// STL renumbers points (in order of first use): compare the triangles'
// corner coordinates instead of indices.
void expect_same_geometry(const Triangle_soup_3& expected, const Triangle_soup_3& actual, const std::string& what)
{
  ASSERT_EQ(actual.points.size(), expected.points.size()) << what << ": welding must restore the shared points";
  ASSERT_EQ(actual.triangles.size(), expected.triangles.size()) << what;
  for(std::size_t t = 0; t < expected.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
      ASSERT_EQ(actual.points[actual.triangles[t][k]], expected.points[expected.triangles[t][k]])
          << what << ": triangle " << t << " corner " << k;
}

struct Encoded
{
  std::string name;
  std::string bytes;
  Mesh_file_format format;
  bool renumbers;
};

std::vector<Encoded> every_encoding(const Triangle_soup_3& s)
{
  using namespace biso_test;
  return {
      {"OFF (package writer)", BI::IO::triangle_soup_to_OFF(s), Mesh_file_format::OFF, false},
      {"OBJ", to_OBJ(s), Mesh_file_format::OBJ, false},
      {"OBJ with i//n corners", to_OBJ(s, true), Mesh_file_format::OBJ, false},
      {"ASCII PLY", to_ASCII_PLY(s), Mesh_file_format::PLY, false},
      {"binary PLY (package writer)", BI::IO::triangle_soup_to_binary_PLY(s), Mesh_file_format::PLY, false},
      {"binary PLY float/uchar/int LE", to_binary_PLY<float, std::uint8_t, std::int32_t>(s, false, "float", "uchar", "int"),
       Mesh_file_format::PLY, false},
      {"binary PLY float32/uint8/uint32 BE",
       to_binary_PLY<float, std::uint8_t, std::uint32_t>(s, true, "float32", "uint8", "uint32"), Mesh_file_format::PLY,
       false},
      {"binary PLY double/int/int BE", to_binary_PLY<double, std::int32_t, std::int32_t>(s, true, "double", "int", "int"),
       Mesh_file_format::PLY, false},
      {"binary PLY float64/ushort/ushort LE",
       to_binary_PLY<double, std::uint16_t, std::uint16_t>(s, false, "float64", "ushort", "ushort"),
       Mesh_file_format::PLY, false},
      {"ASCII STL", to_ASCII_STL(s), Mesh_file_format::STL, true},
      {"binary STL", to_binary_STL(s), Mesh_file_format::STL, true},
  };
}

TEST(MeshReaders, TheSameMeshFromEveryFormatAndVariant)
{
  const Triangle_soup_3 torus = biso_test::float_torus(40, 24);
  for(const Encoded& e : every_encoding(torus))
  {
    for(const Mesh_file_format format : {e.format, Mesh_file_format::from_content})
    {
      Triangle_soup_3 read;
      ASSERT_NO_THROW(read = read_bytes(e.bytes, format)) << e.name << ": " << read_error(e.bytes, format);
      if(e.renumbers)
        expect_same_geometry(torus, read, e.name);
      else
        expect_same_soup(torus, read, e.name);
      EXPECT_EQ(read.triangulated_polygons, 0u);
    }
  }
  EXPECT_NEAR(BI::surveyor_volume(torus), 2 * 3.14159265358979 * 3.14159265358979 * 0.4 * 0.4, 0.08);
}

TEST(MeshReaders, IntegerAndDoubleCoordinateTypesInBinaryPly)
{
  using biso_test::to_binary_PLY;
  const Triangle_soup_3 cube = integer_cube();
  const std::vector<std::pair<std::string, std::string>> files = {
      {"char", to_binary_PLY<std::int8_t, std::uint8_t, std::int8_t>(cube, false, "char", "uchar", "char")},
      {"uchar", to_binary_PLY<std::uint8_t, std::int8_t, std::uint8_t>(cube, true, "uchar", "char", "uchar")},
      {"short", to_binary_PLY<std::int16_t, std::int16_t, std::int16_t>(cube, false, "short", "short", "short")},
      {"ushort", to_binary_PLY<std::uint16_t, std::uint8_t, std::uint32_t>(cube, true, "ushort", "uchar", "uint")},
      {"int", to_binary_PLY<std::int32_t, std::uint8_t, std::int32_t>(cube, false, "int", "uchar", "int")},
      {"int32 BE", to_binary_PLY<std::int32_t, std::uint32_t, std::int32_t>(cube, true, "int32", "uint32", "int32")},
      {"uint", to_binary_PLY<std::uint32_t, std::uint8_t, std::int32_t>(cube, false, "uint", "uchar", "int")},
      {"float", to_binary_PLY<float, std::uint8_t, std::int32_t>(cube, false, "float", "uchar", "int")},
      {"double", to_binary_PLY<double, std::uint8_t, std::int32_t>(cube, true, "double", "uchar", "int")},
  };
  for(const auto& [type, bytes] : files)
  {
    Triangle_soup_3 read;
    ASSERT_NO_THROW(read = read_bytes(bytes, Mesh_file_format::PLY)) << type << ": "
                                                                      << read_error(bytes, Mesh_file_format::PLY);
    expect_same_soup(cube, read, type);
    EXPECT_DOUBLE_EQ(BI::surveyor_volume(read), 27.0) << type;
  }
  // ASCII PLY with int x, y, z (legal; CGAL 5.5's reader dereferences null on it).
  const Triangle_soup_3 ascii = read_bytes(biso_test::to_ASCII_PLY(cube, "int"), Mesh_file_format::PLY);
  expect_same_soup(cube, ascii, "ASCII PLY with int coordinates");
}

TEST(MeshReaders, TheClosedMeshReaderBuildsASurfaceMeshFromIntegerPly)
{
  char dir[] = "/tmp/biso_readers_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string path = std::string(dir) + "/cube_int.ply";
  std::ofstream(path, std::ios::binary)
      << biso_test::to_binary_PLY<std::int32_t, std::uint8_t, std::int32_t>(integer_cube(), false, "int", "uchar",
                                                                             "int");
  CGAL::Surface_mesh<K::Point_3> mesh;
  EXPECT_EQ(BI::IO::read_closed_triangle_mesh(path, mesh), 0u);
  EXPECT_EQ(mesh.number_of_vertices(), 8u);
  EXPECT_EQ(mesh.number_of_faces(), 12u);
  EXPECT_DOUBLE_EQ(BI::surveyor_volume(mesh), 27.0);
  // A directory and a missing file.
  EXPECT_TRUE(contains(error_of([&] { BI::IO::read_triangle_soup(dir); }), "directory"));
  EXPECT_TRUE(contains(error_of([&] { BI::IO::read_triangle_soup(std::string(dir) + "/none.off"); }), "cannot open"));
  std::system(("rm -rf '" + std::string(dir) + "'").c_str());
}

TEST(MeshReaders, PolygonsAreTriangulatedAndCounted)
{
  const std::string quads = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                            "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  const Triangle_soup_3 soup = read_bytes(quads, Mesh_file_format::OFF);
  EXPECT_EQ(soup.triangles.size(), 12u);
  EXPECT_EQ(soup.triangulated_polygons, 6u);
  EXPECT_DOUBLE_EQ(BI::surveyor_volume(soup), 1.0);
  // OBJ: negative (relative) indices, a pentagon, comments and other statements.
  const std::string obj = "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 1.5 0\nv 0 1 0\ng pent\n"
                          "f -5/1/1 -4/2/1 -3/3/1 -2/4/1 -1/5/1 # comment\nl 1 2\n";
  const Triangle_soup_3 pentagon = read_bytes(obj, Mesh_file_format::OBJ);
  ASSERT_EQ(pentagon.triangles.size(), 3u);
  EXPECT_EQ(pentagon.triangulated_polygons, 1u);
  EXPECT_EQ(pentagon.triangles[2], (Triangle_soup_3::Triangle{0, 3, 4}));
}

TEST(MeshReaders, StlWeldsByExactEqualityOnly)
{
  // -0 and +0 are one point; 1 and the next double are two.
  const std::string stl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                          "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -0 0 0\nvertex 0 1 0\n"
                          "vertex 1.0000000000000002 0 0\nendloop\nendfacet\nendsolid s\n";
  const Triangle_soup_3 soup = read_bytes(stl, Mesh_file_format::STL);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.unwelded_corners, 6u);
  EXPECT_EQ(soup.triangles[1][0], 0u);
  EXPECT_EQ(soup.triangles[1][1], 2u);
  EXPECT_EQ(soup.triangles[1][2], 3u);
}

TEST(MeshReaders, HugeHeaderCountsFailFastWithoutAllocating)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::pair<std::string, Mesh_file_format>> files = {
      {"OFF\n1000000000 1 0\n", Mesh_file_format::OFF}, // 18 bytes
      {"OFF\n4 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", Mesh_file_format::OFF},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n",
       Mesh_file_format::PLY},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 4000000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
       Mesh_file_format::PLY},
      {std::string(80, 's') + std::string("\xff\xff\xff\x0f", 4) + std::string(50, '\0'), Mesh_file_format::STL},
  };
  for(const auto& [bytes, format] : files)
  {
    const std::string e = read_error(bytes, format);
    EXPECT_FALSE(e.empty()) << bytes;
    EXPECT_TRUE(contains(e, "declares") || contains(e, "claims")) << e;
  }
  // A list claiming 2^31 items.
  const std::string list = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
                                       "property float y\nproperty float z\nelement face 1\n"
                                       "property list int int vertex_indices\nend_header\n") +
                           std::string("\xff\xff\xff\x7f", 4) + std::string(12, '\0');
  EXPECT_TRUE(contains(read_error(list, Mesh_file_format::PLY), "claims")) << read_error(list, Mesh_file_format::PLY);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  EXPECT_LT(usage.ru_maxrss, 1024 * 1024) << "kB peak: something allocated from a header count";
}

TEST(MeshReaders, APropertylessElementWithAHugeCountIsSkippedAtOnce)
{
  // Zero bytes per instance: legal, and must not loop 10^18 times.
  const Triangle_soup_3 cube = integer_cube();
  std::string ply = biso_test::to_binary_PLY<float, std::uint8_t, std::int32_t>(cube, false, "float", "uchar", "int");
  const std::string marker = "element vertex";
  ply.insert(ply.find(marker), "element nothing 1000000000000000000\n");
  const auto start = std::chrono::steady_clock::now();
  expect_same_soup(cube, read_bytes(ply, Mesh_file_format::PLY), "with an empty element");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
}

TEST(MeshReaders, MalformedPlyHeaders)
{
  const std::string body = "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const struct { std::string text; const char* expected; } cases[] = {
      {"ply\nformat ascii 1.0\nproperty float x\n" + vertex + face + body, "line 3: 'property' before any 'element'"},
      {"ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n" + face + body, "line 3:"},
      {"ply\nformat ascii 2.0\n" + vertex + face + body, "line 2:"},
      {"ply\nformat ascii 1.0\n" + vertex + "element face 1\nproperty list float int vertex_indices\n" + body,
       "line 8:"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" + face + body,
       "no scalar property 'z'"},
      {"ply\nformat ascii 1.0\n" + vertex + body, "no 'face' element"},
      {"ply\nformat ascii 1.0\n" + vertex + face, "no 'end_header'"},
      {"ply\nformat ascii 1.0\n" + vertex + "element face 1\nproperty list uchar float vertex_indices\n" + body,
       "integer type"},
      {"ply\nformat ascii 1.0\n" + vertex + face + body + "3 0 1 2\n", "unexpected content"},
      {"ply\nformat ascii 1.0\n" + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       "line 13: face 0 refers to vertex 3, but there are 3 vertices"},
  };
  for(const auto& c : cases)
  {
    const std::string e = read_error(c.text, Mesh_file_format::PLY);
    EXPECT_TRUE(contains(e, c.expected)) << "expected '" << c.expected << "', got '" << e << "'";
  }
}

TEST(MeshReaders, NonFiniteCoordinatesAreNamed)
{
  const struct { std::string text; Mesh_file_format format; const char* expected; } cases[] = {
      {"OFF\n3 1 0\n0 0 0\nnan 1 0\n0 1 0\n3 0 1 2\n", Mesh_file_format::OFF,
       "line 4: vertex 1 has a non-finite coordinate (nan 1 0)"},
      {"OFF\n3 1 0\n0 0 0\n1 1 0\n0 -inf 0\n3 0 1 2\n", Mesh_file_format::OFF,
       "line 5: vertex 2 has a non-finite coordinate (0 -inf 0)"},
      {"OFF\n3 1 0\n0 0 0\n1 1 0\n0 1e999 0\n3 0 1 2\n", Mesh_file_format::OFF, "(0 inf 0)"},
      {"# c\nv 0 0 0\nv 1 0 Infinity\nv 0 1 0\nf 1 2 3\n", Mesh_file_format::OBJ,
       "line 3: vertex 2 has a non-finite coordinate (1 0 inf)"},
      {"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex NaN 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
       "endsolid s\n",
       Mesh_file_format::STL, "line 5: facet 0 has a vertex with a non-finite coordinate (nan 0 0)"},
  };
  for(const auto& c : cases)
  {
    std::string e;
    try
    {
      read_bytes(c.text, c.format);
    }
    catch(const BI::Non_finite_value_error& x)
    {
      e = x.what();
    }
    catch(const BI::Invalid_input_error& x)
    {
      e = std::string("wrong type: ") + x.what();
    }
    EXPECT_TRUE(contains(e, c.expected)) << "expected '" << c.expected << "', got '" << e << "'";
  }
  Triangle_soup_3 bad = integer_cube();
  bad.points[5][1] = std::numeric_limits<double>::quiet_NaN();
  const std::string ply =
      biso_test::to_binary_PLY<float, std::uint8_t, std::int32_t>(bad, true, "float", "uchar", "int");
  const std::string e = read_error(ply, Mesh_file_format::PLY);
  EXPECT_TRUE(contains(e, "vertex 5 has a non-finite coordinate (3 nan 3)")) << e;
}

TEST(MeshReaders, TextErrorsGiveTheLineNumber)
{
  const struct { std::string text; Mesh_file_format format; std::size_t line; const char* expected; } cases[] = {
      {"OFF\n# comment\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", Mesh_file_format::OFF, 5,
       "cannot parse coordinate 3 of vertex 1: expected a number, found 'zero'"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n\n3 0 1 7\n", Mesh_file_format::OFF, 7, "refers to vertex 7"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Mesh_file_format::OFF, 2, "declares 2 faces"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n      ", Mesh_file_format::OFF, 7, "truncated"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", Mesh_file_format::OFF, 6, "face 0 has 2 vertices"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", Mesh_file_format::OBJ, 5, "refers to vertex 4"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\x01\x02garbage\n", Mesh_file_format::OBJ, 5, "'\\x01\\x02garbage'"},
      {"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n",
       Mesh_file_format::STL, 6, "facet 0 has 2 vertices"},
  };
  for(const auto& c : cases)
  {
    std::string message;
    std::size_t line = 0;
    try
    {
      read_bytes(c.text, c.format);
    }
    catch(const BI::Parse_error& e)
    {
      message = e.what();
      line = e.position();
    }
    EXPECT_EQ(line, c.line) << message;
    EXPECT_TRUE(contains(message, "line " + std::to_string(c.line) + ": ")) << message;
    EXPECT_TRUE(contains(message, c.expected)) << "expected '" << c.expected << "', got '" << message << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Every prefix of every encoding, and single corrupted bytes: the reader
// either reads a soup with indices in range or throws Invalid_input_error;
// it never crashes, hangs or reads outside the buffer (the ASan run of the
// suite checks the last).
TEST(MeshReaders, TruncatedAndCorruptedFilesNeverCrash)
{
  Triangle_soup_3 small = integer_cube();
  std::size_t rejected = 0;
  for(const Encoded& e : every_encoding(small))
  {
    std::size_t accepted_prefixes = 0;
    for(std::size_t n = 0; n < e.bytes.size(); ++n)
    {
      const std::string prefix = e.bytes.substr(0, n);
      try
      {
        const Triangle_soup_3 s = read_bytes(prefix, e.format);
        for(const auto& t : s.triangles)
          for(std::uint32_t v : t) ASSERT_LT(v, s.points.size()) << e.name << " prefix " << n;
        // (A binary STL's 80-byte text header alone is a valid, empty ASCII STL.)
        accepted_prefixes += !s.triangles.empty();
      }
      catch(const BI::Invalid_input_error& x)
      {
        ++rejected;
        EXPECT_EQ(std::string(x.what()).find('\n'), std::string::npos) << x.what();
      }
    }
    // Formats with counts accept no non-empty prefix but the one without the final
    // newline; OBJ and ASCII STL have no counts, so a prefix that ends at a
    // statement is a smaller valid file.
    if(e.format != Mesh_file_format::OBJ && e.name != "ASCII STL")
      EXPECT_LE(accepted_prefixes, 1u) << e.name;
    for(std::size_t n = 0; n < e.bytes.size(); ++n)
      for(const char c : {'\0', '9', '-', '\xff', ' ', '\n'})
      {
        std::string corrupt = e.bytes;
        corrupt[n] = c;
        try
        {
          const Triangle_soup_3 s = read_bytes(corrupt, e.format);
          for(const auto& t : s.triangles)
            for(std::uint32_t v : t) ASSERT_LT(v, s.points.size()) << e.name << " byte " << n;
        }
        catch(const BI::Invalid_input_error&)
        {
          ++rejected;
        }
      }
  }
  EXPECT_GT(rejected, 1000u);
}

TEST(MeshReaders, WritersRoundTripExactly)
{
  Triangle_soup_3 s = biso_test::float_torus(12, 8);
  s.points[0] = {0.1, -1e-300, 1e300};
  s.points[1] = {-0.0, 3.0000000000000004, 123456789.123456789};
  char dir[] = "/tmp/biso_writers_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  for(const char* name : {"/s.ply", "/s.off", "/S.PLY", "/s.obj"})
  {
    const std::string path = std::string(dir) + name;
    BI::IO::write_triangle_soup(path, s);
    const Triangle_soup_3 back = BI::IO::read_triangle_soup(path);
    expect_same_soup(s, back, name);
    EXPECT_TRUE(std::signbit(back.points[1][0])) << name;
  }
  // Binary STL stores floats and no shared points: every corner of every
  // facet reads back as the float of the written corner, and welding by
  // coordinates gives back the same number of points.
  {
    const Triangle_soup_3 torus = biso_test::float_torus(12, 8);
    const std::string path = std::string(dir) + "/s.stl";
    BI::IO::write_triangle_soup(path, torus);
    const Triangle_soup_3 back = BI::IO::read_triangle_soup(path);
    ASSERT_EQ(back.triangles.size(), torus.triangles.size());
    EXPECT_EQ(back.points.size(), torus.points.size());
    for(std::size_t t = 0; t < torus.triangles.size(); ++t)
      for(int v = 0; v < 3; ++v)
        for(int a = 0; a < 3; ++a)
          ASSERT_EQ(back.points[back.triangles[t][v]][a], double(float(torus.points[torus.triangles[t][v]][a])));
  }
  EXPECT_THROW(BI::IO::write_triangle_soup(std::string(dir) + "/s.xyz", s), std::invalid_argument);
  EXPECT_THROW(BI::IO::write_triangle_soup(std::string(dir) + "/no/such/dir/s.ply", s), std::runtime_error);
  std::system(("rm -rf '" + std::string(dir) + "'").c_str());
}

TEST(MeshReaders, ClosedSoupAndMeshValidation)
{
  char dir[] = "/tmp/biso_closed_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = std::string(dir) + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  };
  const std::string tet = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_NEAR(BI::surveyor_volume(BI::IO::read_closed_triangle_soup(write("tet.off", tet))), 1.0 / 6, 1e-16);
  const std::string open = "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n";
  EXPECT_THROW(BI::IO::read_closed_triangle_soup(write("open.off", open)), BI::Open_mesh_error);
  const std::string inward = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
  EXPECT_THROW(BI::IO::read_closed_triangle_soup(write("inward.off", inward)), BI::Inward_oriented_mesh_error);
  EXPECT_NO_THROW(BI::IO::read_closed_triangle_soup(write("inward2.off", inward), true));
  // Two tetrahedra sharing one vertex: a closed soup, not a 2-manifold.
  const std::string bowtie = "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 4 5\n3 0 6 4\n3 0 5 6\n3 4 6 5\n";
  const std::string path = write("bowtie.off", bowtie);
  EXPECT_NEAR(BI::surveyor_volume(BI::IO::read_closed_triangle_soup(path)), 2.0 / 6, 1e-15);
  CGAL::Surface_mesh<K::Point_3> mesh;
  EXPECT_TRUE(contains(error_of([&] { BI::IO::read_closed_triangle_mesh(path, mesh); }), "non-manifold vertex"));
  CGAL::Surface_mesh<K::Point_3> cube;
  const std::string quads = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                            "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  EXPECT_EQ(BI::IO::read_closed_triangle_mesh(write("quads.off", quads), cube), 6u);
  EXPECT_EQ(cube.number_of_faces(), 12u);
  EXPECT_TRUE(CGAL::is_closed(cube));
  // Found by fuzz_closed_triangle_mesh: a triangle and its reverse pass the
  // edge check but bound nothing; so does a flat closed surface (two
  // tetrahedra's worth of faces folded into a plane), and an empty one.
  const std::string pillow = "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 3\nf* 1 4 3int82\xba 43\n";
  for(bool allow_inward : {false, true})
    EXPECT_TRUE(contains(error_of([&] { BI::IO::read_closed_triangle_soup(write("pillow.obj", pillow), allow_inward); }),
                         "doubly covered triangle"));
  const std::string flat = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_TRUE(contains(error_of([&] { BI::IO::read_closed_triangle_soup(write("flat.off", flat)); }),
                       "encloses no volume"));
  // With allow_inward (the parity reading) a signed volume of 0 is not an
  // error: an outward cube and an inward copy elsewhere is a parity solid.
  EXPECT_NO_THROW(BI::IO::read_closed_triangle_soup(write("flat2.off", flat), true));
  std::system(("rm -rf '" + std::string(dir) + "'").c_str());
}

// CGAL's own reader as an oracle: the same points (exactly) and polygons on
// every shared mesh.
TEST(MeshReaders, AgreeWithCgalOnTheSharedMeshes)
{
  const std::string data = BISO_SHARED_DATA_DIR;
  std::size_t files = 0;
  for(const char* file :
      {"meshes/3holes.off", "meshes/armadillo.obj", "meshes/bumpy-cube.obj", "meshes/bunny.off", "meshes/cube.obj",
       "meshes/elephant.obj", "meshes/fandisk.off", "meshes/quadknot_tri.off", "meshes/xyz-cube-20mm.off",
       "boolean_pairs/Generic_Twin_7081.1.t0_left.obj", "boolean_pairs/hull-body.obj"})
  {
    const std::string path = data + "/" + file;
    if(!std::ifstream(path).good())
      continue;
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, points, polygons)) << file;
    const Triangle_soup_3 soup = BI::IO::read_triangle_soup(path);
    ASSERT_EQ(soup.points.size(), points.size()) << file;
    ASSERT_EQ(soup.triangles.size(), polygons.size()) << file;
    for(std::size_t i = 0; i < points.size(); ++i)
      ASSERT_TRUE(soup.points[i][0] == points[i].x() && soup.points[i][1] == points[i].y() &&
                  soup.points[i][2] == points[i].z())
          << file << " point " << i;
    for(std::size_t f = 0; f < polygons.size(); ++f)
    {
      ASSERT_EQ(polygons[f].size(), 3u) << file;
      for(int k = 0; k < 3; ++k) ASSERT_EQ(soup.triangles[f][k], polygons[f][k]) << file << " face " << f;
    }
    EXPECT_GT(BI::surveyor_volume(soup), 0) << file;
    ++files;
  }
  if(files == 0)
    GTEST_SKIP() << "no shared data at " << data;
  EXPECT_EQ(files, 11u);
}

} // namespace
