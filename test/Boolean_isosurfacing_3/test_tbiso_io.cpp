// Tests of the TBISO file formats: tetrahedral meshes (Medit, TetGen),
// scalar fields (raw float64/float32, text), and the output writers (PLY with
// fields, polylines, corners, OFF).  Real meshes from the shared data are
// checked against the counts and volumes of /work/shared/data/README.md;
// everything else is generated here, in a scratch directory.

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/scalar_fields.h>
#include <CGAL/Boolean_isosurfacing_3/IO/tetrahedral_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/Tetrahedral_grid_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

namespace BI = CGAL::Boolean_isosurfacing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef BI::Tetrahedral_mesh_3<K> Mesh;
typedef BI::IO::Raw_scalar_type Raw;

namespace {

const std::string data_dir = BISO_SHARED_DATA_DIR;

// A scratch directory, removed with its content at the end of the test.
class Scratch
{
public:
  Scratch()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "biso_tbiso_io_XXXXXX").string();
    if(mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("mkdtemp failed");
    m_dir = pattern;
  }
  ~Scratch()
  {
    std::error_code ec;
    std::filesystem::remove_all(m_dir, ec);
  }
  std::string file(const std::string& name) const { return m_dir + "/" + name; }
  std::string write(const std::string& name, const std::string& content) const
  {
    const std::string path = file(name);
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
  }

private:
  std::string m_dir;
};

// The message of the exception `f` throws, which must be exactly of type E.
template <typename E, typename F>
std::string message_of(F&& f)
{
  try
  {
    f();
  }
  catch(const std::exception& e)
  {
    EXPECT_EQ(typeid(e), typeid(E)) << "thrown: " << typeid(e).name() << ": " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "nothing thrown";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

double total_volume(const Mesh& mesh)
{
  double v = 0;
  for(const auto& t : mesh.tetrahedra())
    v += CGAL::volume(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]));
  return v;
}

bool same_mesh(const Mesh& a, const Mesh& b)
{
  return a.points() == b.points() && a.tetrahedra() == b.tetrahedra();
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

#define SKIP_WITHOUT(path)                                                                          \
  if(!std::filesystem::is_regular_file(path))                                                       \
  GTEST_SKIP() << "shared data not found: " << (path)

// Two tetrahedra sharing the face (1, 2, 3): the unit corner tetrahedron and
// the one over its slanted face.  Volume 1/6 + 1/3.
const char* two_tets_medit = "# two tetrahedra\r\n"
                             "meshversionformatted 1\r\n"
                             "DIMENSION\r\n"
                             "3\r\n"
                             "Vertices 5   # the count on the keyword's line\r\n"
                             "0 0 0 1\r\n"
                             "1 0 0 1\r\n"
                             "0 1 0 1\r\n"
                             "0 0 1 2\r\n"
                             "\r\n"
                             "1 1 1 2\r\n"
                             "Corners\r\n"
                             "2\r\n"
                             "1\r\n"
                             "2\r\n"
                             "Triangles\r\n"
                             "1\r\n"
                             "1 2 3 0\r\n"
                             "Tetrahedra\r\n"
                             "2\r\n"
                             "1 2 3 4 7\r\n"
                             "2 3 4 5 -7\r\n"
                             "Edges\r\n"
                             "1\r\n"
                             "1 2 0\r\n"
                             "End\r\n"
                             "anything after End is ignored\r\n";

// A jittered 3x3x3 Kuhn grid as an unstructured mesh: irrational-looking coordinates.
Mesh jittered_grid_mesh()
{
  const BI::Tetrahedral_grid_3<K> grid(Point_3(0.1, -0.2, 1. / 3.), {0.7, 1.1, 0.3}, {3, 3, 3});
  std::mt19937_64 random(20260101);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  std::vector<Point_3> points;
  for(std::size_t v = 0; v < grid.number_of_vertices(); ++v)
  {
    const std::array<double, 3> p = grid.position(v);
    points.emplace_back(p[0] + jitter(random) * 0.7, p[1] + jitter(random) * 1.1, p[2] + jitter(random) * 0.3);
  }
  std::vector<Mesh::Tetrahedron> tets;
  for(std::size_t k = 0; k < 2; ++k)
    for(std::size_t j = 0; j < 2; ++j)
      for(std::size_t i = 0; i < 2; ++i)
        for(int t = 0; t < 6; ++t)
          tets.push_back(grid.tetrahedron(i, j, k, t));
  return Mesh(points, tets);
}

std::vector<double> random_values(std::size_t n, unsigned seed, double scale)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<double> values(n);
  for(double& v : values)
    v = u(random);
  return values;
}

// ===========================================================================
// Tetrahedral meshes: shared data

struct Shared_mesh
{
  const char* file;
  std::size_t vertices, tetrahedra, boundary_faces;
  double volume;
};

TEST(TetrahedralMeshIO, SharedMeshesHaveTheReadmeCountsAndVolumes)
{
  const Shared_mesh meshes[] = {{"octopus-low.mesh", 452, 1140, 898, 0.009135547848},
                                {"octopus-low.node", 452, 1140, 898, 0.009135547848},
                                {"octopus-low.ele", 452, 1140, 898, 0.009135547848},
                                {"bunny.mesh", 5433, 34055, 670, 0.001249414818},
                                {"hand.mesh", 7234, 29998, 9556, 0.160465576}};
  for(const Shared_mesh& m : meshes)
  {
    const std::string path = data_dir + "/tet/" + m.file;
    SKIP_WITHOUT(path);
    const Mesh mesh = BI::IO::read_tetrahedral_mesh<K>(path);
    EXPECT_EQ(mesh.number_of_vertices(), m.vertices) << m.file;
    EXPECT_EQ(mesh.number_of_tetrahedra(), m.tetrahedra) << m.file;
    EXPECT_EQ(mesh.number_of_boundary_faces(), m.boundary_faces) << m.file;
    // The README: all tetrahedra positively oriented (no reorientation needed).
    EXPECT_EQ(mesh.number_of_reoriented_tetrahedra(), 0u) << m.file;
    EXPECT_NEAR(total_volume(mesh), m.volume, 1e-9 * m.volume) << m.file;
  }
}

TEST(TetrahedralMeshIO, OctopusMeditAndTetGenTwinAreIdentical)
{
  const std::string base = data_dir + "/tet/octopus-low";
  SKIP_WITHOUT(base + ".mesh");
  SKIP_WITHOUT(base + ".node");
  const Mesh medit = BI::IO::read_MEDIT<K>(base + ".mesh");
  const Mesh tetgen = BI::IO::read_TetGen<K>(base); // the basename form
  EXPECT_TRUE(same_mesh(medit, tetgen));
  EXPECT_TRUE(same_mesh(tetgen, BI::IO::read_TetGen<K>(base + ".ele")));
}

// ===========================================================================
// Tetrahedral meshes: generated inputs

TEST(TetrahedralMeshIO, MeditWithCommentsSkippedBlocksCrlfAndLowercaseKeywords)
{
  Scratch scratch;
  const Mesh mesh = BI::IO::read_MEDIT<K>(scratch.write("two.MESH", two_tets_medit));
  ASSERT_EQ(mesh.number_of_vertices(), 5u);
  ASSERT_EQ(mesh.number_of_tetrahedra(), 2u);
  EXPECT_EQ(mesh.point(4), Point_3(1, 1, 1));
  EXPECT_EQ(mesh.number_of_boundary_faces(), 6u);
  EXPECT_NEAR(total_volume(mesh), 0.5, 1e-15);
  // Dispatch by extension is case-insensitive.
  EXPECT_TRUE(same_mesh(mesh, BI::IO::read_tetrahedral_mesh<K>(scratch.file("two.MESH"))));
}

TEST(TetrahedralMeshIO, TetGenZeroBasedWithAttributesAndMarkersEqualsMedit)
{
  Scratch scratch;
  scratch.write("two.node", "# 0-based, one attribute, a boundary marker\n"
                            "5 3 1 1\n"
                            "0 0 0 0 3.5 1\n"
                            "1 1 0 0 3.5 1\n"
                            "2 0 1 0 3.5 1   # trailing comment\n"
                            "3 0 0 1 3.5 0\n"
                            "4 1 1 1 3.5 0\n");
  scratch.write("two.ele", "2 4 1\n"
                           "\n"
                           "1 0 1 2 3 9\n" // elements numbered from 1, corners from 0
                           "2 1 2 3 4 9\n"
                           "# Generated by hand\n");
  const Mesh tetgen = BI::IO::read_tetrahedral_mesh<K>(scratch.file("two.node"));
  Scratch other;
  const Mesh medit = BI::IO::read_MEDIT<K>(other.write("two.mesh", two_tets_medit));
  EXPECT_TRUE(same_mesh(tetgen, medit));
}

TEST(TetrahedralMeshIO, MeditRoundTripIsExact)
{
  Scratch scratch;
  const Mesh mesh = jittered_grid_mesh();
  ASSERT_EQ(mesh.number_of_tetrahedra(), 48u);
  BI::IO::write_MEDIT(scratch.file("grid.mesh"), mesh);
  const Mesh back = BI::IO::read_MEDIT<K>(scratch.file("grid.mesh"));
  EXPECT_TRUE(same_mesh(mesh, back));
  EXPECT_EQ(back.number_of_reoriented_tetrahedra(), 0u); // written positively oriented
  EXPECT_EQ(total_volume(back), total_volume(mesh));
}

// ===========================================================================
// Tetrahedral meshes: errors

TEST(TetrahedralMeshIO, MissingFileNamesIt)
{
  Scratch scratch;
  const std::string path = scratch.file("absent.mesh");
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_MEDIT<K>(path); }), path));
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_tetrahedral_mesh<K>(path); }), path));
  // A .node without its .ele.
  scratch.write("lonely.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_TetGen<K>(scratch.file("lonely")); }),
                       "lonely.ele"));
  // A directory is not a file.
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_MEDIT<K>(scratch.file("")); }),
                       "cannot open"));
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_tetrahedral_mesh<K>("x.vtk"); }),
                       "unknown tetrahedral mesh format"));
}

// Medit file with `line` replacing line `at` (1-based) of a valid file.
std::string medit_with(std::size_t at, const std::string& line)
{
  std::vector<std::string> lines = {"MeshVersionFormatted 1", "Dimension 3", "Vertices", "5", "0 0 0 0",
                                    "1 0 0 0", "0 1 0 0", "0 0 1 0", "1 1 1 0", "Tetrahedra", "2",
                                    "1 2 3 4 0", "2 3 4 5 0", "End"};
  lines[at - 1] = line;
  std::string text;
  for(const std::string& l : lines)
    text += l + "\n";
  return text;
}

TEST(TetrahedralMeshIO, MeditErrorsNameFileAndLine)
{
  Scratch scratch;
  ASSERT_NO_THROW(BI::IO::read_MEDIT<K>(scratch.write("ok.mesh", medit_with(1, "MeshVersionFormatted 1"))));
  struct Case
  {
    std::size_t at;
    const char* line;
    const char* expected;
  };
  const Case parse_errors[] = {{7, "0 1 abc 0", "'abc' is not a number"},
                               {7, "0 1 0", "expected 'x y z ref'"},
                               {12, "1 2 3 9 0", "vertex index 9 out of range [1, 5]"},
                               {13, "0 3 4 5 0", "vertex index 0 out of range"},
                               {12, "1 2 -3 4 0", "not a non-negative integer"},
                               {2, "Dimension 2", "only 3D meshes"},
                               {4, "6", "expected 'x y z ref'"}, // one vertex too many announced
                               {14, "Bogus", "the file ends after the keyword 'Bogus'"}}; // unknown block without count
  for(const Case& c : parse_errors)
  {
    const std::string path = scratch.write("bad.mesh", medit_with(c.at, c.line));
    try
    {
      BI::IO::read_MEDIT<K>(path);
      ADD_FAILURE() << "no error for line " << c.at << " '" << c.line << "'";
    }
    catch(const BI::Parse_error& e)
    {
      const std::string m = e.what();
      EXPECT_TRUE(contains(m, c.expected)) << m;
      EXPECT_TRUE(contains(m, path)) << m;
      if(c.at != 4) // reported where the damage shows (below)
      {
        EXPECT_EQ(e.position(), c.at) << m;
        EXPECT_TRUE(contains(m, "line " + std::to_string(c.at) + ":")) << m;
      }
    }
  }
  // One vertex too many announced: reported at the Tetrahedra keyword, line 10.
  {
    const std::string path = scratch.write("bad.mesh", medit_with(4, "6"));
    EXPECT_TRUE(contains(message_of<BI::Parse_error>([&] { BI::IO::read_MEDIT<K>(path); }), "line 10:"));
  }
  // A NaN coordinate.
  {
    const std::string path = scratch.write("nan.mesh", medit_with(8, "0 nan 1 0"));
    const std::string m = message_of<BI::Non_finite_value_error>([&] { BI::IO::read_MEDIT<K>(path); });
    EXPECT_TRUE(contains(m, "line 8:")) << m;
    EXPECT_TRUE(contains(m, "nan")) << m;
  }
  // The file ends inside the Tetrahedra block.
  {
    const std::string path = scratch.write("short.mesh", medit_with(11, "3"));
    const std::string m = message_of<BI::Parse_error>([&] { BI::IO::read_MEDIT<K>(path); });
    EXPECT_TRUE(contains(m, "expected 'a b c d ref'")) << m; // the End line, 14
    EXPECT_TRUE(contains(m, "line 14:")) << m;
  }
  // No tetrahedra.
  {
    const std::string path = scratch.write("empty.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n1\n0 0 0 0\nEnd\n");
    EXPECT_TRUE(contains(message_of<BI::Empty_input_error>([&] { BI::IO::read_MEDIT<K>(path); }), "no Tetrahedra"));
  }
}

TEST(TetrahedralMeshIO, TetGenErrorsNameFileAndLine)
{
  Scratch scratch;
  const std::string node = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
  const std::string ele = "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n";
  scratch.write("t.node", node);
  scratch.write("t.ele", ele);
  ASSERT_NO_THROW(BI::IO::read_TetGen<K>(scratch.file("t.node")));

  auto expect = [&](const std::string& node_text, const std::string& ele_text, const char* file,
                    std::size_t line, const char* what) {
    scratch.write("t.node", node_text);
    scratch.write("t.ele", ele_text);
    try
    {
      BI::IO::read_TetGen<K>(scratch.file("t"));
      ADD_FAILURE() << "no error, expected " << what;
    }
    catch(const BI::Parse_error& e)
    {
      const std::string m = e.what();
      EXPECT_EQ(e.position(), line) << m;
      EXPECT_TRUE(contains(m, scratch.file(file) + "' line " + std::to_string(line) + ":")) << m;
      EXPECT_TRUE(contains(m, what)) << m;
    }
  };
  expect("5 3 0 0\n1 0 0 0\n2 1 0 0\n4 0 1 0\n4 0 0 1\n5 1 1 1\n", ele, "t.node", 4, "expected vertex number 3");
  expect("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1 7\n5 1 1 1\n", ele, "t.node", 5, "found 5 fields");
  expect(node + "6 2 2 2\n", ele, "t.node", 7, "more vertex lines");
  expect(node, "2 4 0\n1 1 2 3 4\n2 2 3 4 6\n", "t.ele", 3, "vertex index 6 out of range [1, 5]");
  expect(node, "2 4 0\n1 0 2 3 4\n2 2 3 4 5\n", "t.ele", 2, "vertex index 0 out of range");
  expect(node, "3 4 0\n1 1 2 3 4\n2 2 3 4 5\n", "t.ele", 3, "the file ends after 2 of the 3 tetrahedra");
  expect(node, "2 4 0\n1 1 2 3 4\n2 2 x 4 5\n", "t.ele", 3, "'x' is not a non-negative integer");

  scratch.write("t.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 inf 1\n");
  scratch.write("t.ele", ele);
  const std::string m = message_of<BI::Non_finite_value_error>([&] { BI::IO::read_TetGen<K>(scratch.file("t")); });
  EXPECT_TRUE(contains(m, "t.node' line 6:")) << m;
}

TEST(TetrahedralMeshIO, NonConformingMeshIsRejected)
{
  // Three tetrahedra on the face (0, 1, 2): apexes above, below, and above again.
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0),
                                       Point_3(0, 0, 1), Point_3(0, 0, -1), Point_3(0.2, 0.2, 2)};
  const std::vector<Mesh::Tetrahedron> tets = {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}};
  const std::string m = message_of<BI::Invalid_input_error>([&] { Mesh mesh(points, tets); });
  EXPECT_TRUE(contains(m, "not conforming")) << m;
  EXPECT_TRUE(contains(m, "(0, 1, 2) is shared by 3")) << m;
  // The same through a file: the reader lets the mesh's own validation speak.
  EXPECT_NO_THROW({ Mesh two(points, {tets[0], tets[1]}); });
  std::ostringstream medit;
  BI::IO::write_MEDIT(medit, Mesh(points, {tets[0], tets[1]}));
  std::string text = medit.str();
  const std::string two = "Tetrahedra\n2\n";
  ASSERT_TRUE(contains(text, two));
  text.replace(text.find(two), two.size(), "Tetrahedra\n3\n1 2 3 6 0\n");
  std::istringstream in(text);
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::read_MEDIT<K>(in, "three"); }),
                       "not conforming"));
}

// ===========================================================================
// Scalar fields

TEST(ScalarFieldsIO, RawFloat64RoundTripIsBitExact)
{
  Scratch scratch;
  std::vector<double> values = random_values(3 * 101, 7, 1e3);
  values[0] = -0.0;
  values[1] = 5e-324; // the smallest subnormal
  values[2] = 1e300;
  values[3] = -std::numeric_limits<double>::max();
  values[4] = 1. / 3.;
  const BI::Scalar_fields fields(3, values);
  for(const char* name : {"f.raw", "f.f64", "f.F64"})
  {
    const std::string path = scratch.file(name);
    BI::IO::write_raw_scalar_fields(path, fields, Raw::FLOAT64);
    EXPECT_EQ(std::filesystem::file_size(path), 3u * 101u * 8u);
    const BI::Scalar_fields back = BI::IO::read_scalar_fields(path, 101, 3);
    EXPECT_EQ(back.number_of_vertices(), 101u);
    EXPECT_EQ(back.number_of_fields(), 3u);
    EXPECT_TRUE(bitwise_equal(back.data(), values)) << name;
  }
  // The first bytes are little-endian IEEE: -0.0 is 7 zero bytes then 0x80.
  std::ifstream in(scratch.file("f.raw"), std::ios::binary);
  unsigned char b[8];
  in.read(reinterpret_cast<char*>(b), 8);
  EXPECT_EQ(b[7], 0x80);
  EXPECT_EQ(b[0], 0x00);
}

TEST(ScalarFieldsIO, RawFloat32RoundTripRoundsToFloat)
{
  Scratch scratch;
  std::vector<double> values = random_values(2 * 50, 8, 10.);
  values[0] = 1e-50; // below the float range: becomes +0
  const BI::Scalar_fields fields(2, values);
  const std::string path = scratch.file("f.f32");
  BI::IO::write_raw_scalar_fields(path, fields, Raw::FLOAT32);
  EXPECT_EQ(std::filesystem::file_size(path), 2u * 50u * 4u);
  const BI::Scalar_fields back = BI::IO::read_scalar_fields(path, 50, 2);
  std::vector<double> expected(values.size());
  for(std::size_t k = 0; k < values.size(); ++k)
    expected[k] = double(static_cast<float>(values[k]));
  EXPECT_TRUE(bitwise_equal(back.data(), expected));
  EXPECT_EQ(back.value(0, 0), 0.);
  // A value beyond the float range cannot be written as float32.
  const BI::Scalar_fields huge(1, std::vector<double>{1., 1e300});
  const std::string m = message_of<BI::Invalid_input_error>(
      [&] { BI::IO::write_raw_scalar_fields(scratch.file("huge.f32"), huge, Raw::FLOAT32); });
  EXPECT_TRUE(contains(m, "vertex 1, field 0")) << m;
}

TEST(ScalarFieldsIO, TextRoundTripIsBitExact)
{
  Scratch scratch;
  std::vector<double> values = random_values(4 * 77, 9, 1e-3);
  values[5] = 0.1;
  values[6] = -1e-310;
  values[7] = 123456789012345678.;
  const BI::Scalar_fields fields(4, values);
  const std::string path = scratch.file("f.txt");
  BI::IO::write_text_scalar_fields(path, fields);
  const BI::Scalar_fields back = BI::IO::read_scalar_fields(path, 77, 4);
  EXPECT_EQ(back.number_of_fields(), 4u);
  EXPECT_TRUE(bitwise_equal(back.data(), values));
  // Without any check (0, 0).
  EXPECT_TRUE(bitwise_equal(BI::IO::read_scalar_fields(path, 0).data(), values));
}

TEST(ScalarFieldsIO, TextWithCommentsAndBlankLines)
{
  std::istringstream in("# two fields\n\n  2   # N\n1 -2\n+3.5\t4e-1  # vertex 1\n\n-0 0.25\n");
  const BI::Scalar_fields f = BI::IO::read_text_scalar_fields(in);
  EXPECT_EQ(f.number_of_vertices(), 3u);
  EXPECT_EQ(f.data(), (std::vector<double>{1, -2, 3.5, 0.4, 0, 0.25}));
}

TEST(ScalarFieldsIO, RawReaderReadsAnyRange)
{
  Scratch scratch;
  const std::size_t V = 1000, N = 3;
  const std::vector<double> values = random_values(V * N, 10, 5.);
  const BI::Scalar_fields fields(N, values);
  BI::IO::write_raw_scalar_fields(scratch.file("f.f64"), fields, Raw::FLOAT64);
  BI::IO::write_raw_scalar_fields(scratch.file("f.f32"), fields, Raw::FLOAT32);

  BI::IO::Raw_scalar_field_reader r64(scratch.file("f.f64"), V, N, Raw::FLOAT64);
  BI::IO::Raw_scalar_field_reader r32(scratch.file("f.f32"), V, N, Raw::FLOAT32);
  std::vector<double> range;
  // Out of order, overlapping, to the very end, and empty ranges.
  const std::pair<std::size_t, std::size_t> ranges[] = {{317, 211}, {0, 1}, {999, 1}, {5, 0}, {1000, 0}, {0, 1000}, {300, 300}};
  for(const auto& fc : ranges)
  {
    const std::size_t first = fc.first, count = fc.second;
    const std::vector<double> slice(values.begin() + std::ptrdiff_t(first * N),
                                    values.begin() + std::ptrdiff_t((first + count) * N));
    r64.read(first, count, range);
    EXPECT_TRUE(bitwise_equal(range, slice)) << first << " " << count;
    r32.read(first, count, range);
    ASSERT_EQ(range.size(), slice.size());
    for(std::size_t k = 0; k < slice.size(); ++k)
      ASSERT_EQ(range[k], double(static_cast<float>(slice[k])));
  }
  EXPECT_THROW(r64.read(990, 11, range), std::out_of_range);
  EXPECT_THROW(r64.read(1001, 0, range), std::out_of_range);
  // Still usable after a rejected range.
  r64.read(998, 2, range);
  EXPECT_EQ(range[5], values[2999]);
}

TEST(ScalarFieldsIO, GridSlabIsOneContiguousRange)
{
  // The documented layout: grid vertex (i, j, k) is v = i + nx * (j + ny * k),
  // so layers k0 <= k < k1 are the vertices [nx*ny*k0, nx*ny*k1).
  Scratch scratch;
  const BI::Tetrahedral_grid_3<K> grid(Point_3(0, 0, 0), {1, 1, 1}, {5, 4, 6});
  const std::size_t N = 2;
  BI::Scalar_fields fields(grid.number_of_vertices(), N);
  for(std::size_t v = 0; v < grid.number_of_vertices(); ++v)
  {
    const std::array<std::size_t, 3> c = grid.vertex_coordinates(v);
    fields.value(v, 0) = double(c[0] + 10 * c[1] + 100 * c[2]);
    fields.value(v, 1) = -double(c[2]);
  }
  BI::IO::write_raw_scalar_fields(scratch.file("g.raw"), fields);
  BI::IO::Raw_scalar_field_reader reader(scratch.file("g.raw"), grid.number_of_vertices(), N);
  std::vector<double> slab;
  reader.read(5 * 4 * 2, 5 * 4 * 3, slab); // layers 2, 3, 4
  std::size_t at = 0;
  for(std::size_t k = 2; k < 5; ++k)
    for(std::size_t j = 0; j < 4; ++j)
      for(std::size_t i = 0; i < 5; ++i, at += N)
      {
        ASSERT_EQ(slab[at], double(i + 10 * j + 100 * k));
        ASSERT_EQ(slab[at + 1], -double(k));
      }
}

TEST(ScalarFieldsIO, WrongRawSizeGivesBothSizes)
{
  Scratch scratch;
  const std::string path = scratch.file("f.raw");
  BI::IO::write_raw_scalar_fields(path, BI::Scalar_fields(2, random_values(10, 11, 1.)));
  std::string m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_raw_scalar_fields(path, 4, 3); });
  EXPECT_TRUE(contains(m, "has 80 bytes, expected 96")) << m;
  EXPECT_TRUE(contains(m, path)) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::Raw_scalar_field_reader reader(path, 5, 2, Raw::FLOAT32); });
  EXPECT_TRUE(contains(m, "has 80 bytes, expected 40")) << m;
  // Dispatch: N is required for raw files; the message gives the N that fits.
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_scalar_fields(path, 5, 0); });
  EXPECT_TRUE(contains(m, "give its number of fields N")) << m;
  EXPECT_TRUE(contains(m, "N = 2")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_scalar_fields(path, 3, 0); });
  EXPECT_TRUE(contains(m, "80 bytes, not a positive multiple of 24")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_scalar_fields(path, 0, 2); });
  EXPECT_TRUE(contains(m, "number of vertices")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_raw_scalar_fields(path, 5, 65); });
  EXPECT_TRUE(contains(m, "between 1 and 64")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_raw_scalar_fields(scratch.file("no.raw"), 5, 2); });
  EXPECT_TRUE(contains(m, "no.raw")) << m;
}

TEST(ScalarFieldsIO, NonFiniteValuesNameVertexAndField)
{
  Scratch scratch;
  // Raw: a NaN written by other software.
  std::vector<double> values = random_values(12, 12, 1.);
  values[7] = std::numeric_limits<double>::quiet_NaN(); // vertex 2, field 1 (N = 3)
  {
    std::ofstream out(scratch.file("nan.raw"), std::ios::binary);
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * 8));
  }
  std::string m = message_of<BI::Non_finite_value_error>(
      [&] { BI::IO::read_raw_scalar_fields(scratch.file("nan.raw"), 4, 3); });
  EXPECT_TRUE(contains(m, "vertex 2, field 1")) << m;
  // ... but a range without it reads fine.
  BI::IO::Raw_scalar_field_reader reader(scratch.file("nan.raw"), 4, 3);
  std::vector<double> range;
  EXPECT_NO_THROW(reader.read(3, 1, range));
  // Writers refuse to write what cannot be read.
  m = message_of<BI::Non_finite_value_error>([&] {
    BI::IO::write_raw_scalar_fields(scratch.file("w.raw"), BI::Scalar_fields(3, values));
  });
  EXPECT_TRUE(contains(m, "vertex 2, field 1")) << m;
  m = message_of<BI::Non_finite_value_error>([&] {
    BI::IO::write_text_scalar_fields(scratch.file("w.txt"), BI::Scalar_fields(3, values));
  });
  EXPECT_TRUE(contains(m, "w.txt': vertex 2, field 1")) << m;
  EXPECT_FALSE(std::filesystem::exists(scratch.file("w.txt"))); // refused before creating the file
  EXPECT_FALSE(std::filesystem::exists(scratch.file("w.raw")));
  // Text.
  const std::string path = scratch.write("nan.txt", "3\n0 0 0\n1 2 -inf\n");
  m = message_of<BI::Non_finite_value_error>([&] { BI::IO::read_text_scalar_fields(path); });
  EXPECT_TRUE(contains(m, "line 3: vertex 1, field 2")) << m;
  const std::string huge = scratch.write("huge.txt", "1\n0\n1e400\n");
  m = message_of<BI::Non_finite_value_error>([&] { BI::IO::read_text_scalar_fields(huge); });
  EXPECT_TRUE(contains(m, "line 3: vertex 1, field 0")) << m;
}

TEST(ScalarFieldsIO, TextErrorsNameTheLine)
{
  Scratch scratch;
  struct Case
  {
    const char* text;
    std::size_t line;
    const char* expected;
  };
  const Case cases[] = {{"2\n1 2\n3\n", 3, "expected 2 values (one per field) for vertex 1, found 1"},
                        {"# c\n2\n1 2\n3 x\n", 4, "'x' is not a number"},
                        {"2 3\n1 2\n", 1, "expected the number of fields N"},
                        {"65\n", 1, "1 to 64"},
                        {"2\n1 2 3\n", 2, "found 3"}};
  for(const Case& c : cases)
  {
    const std::string path = scratch.write("bad.txt", c.text);
    try
    {
      BI::IO::read_text_scalar_fields(path);
      ADD_FAILURE() << "no error for " << c.text;
    }
    catch(const BI::Parse_error& e)
    {
      const std::string m = e.what();
      EXPECT_EQ(e.position(), c.line) << m;
      EXPECT_TRUE(contains(m, path + "' line " + std::to_string(c.line) + ":")) << m;
      EXPECT_TRUE(contains(m, c.expected)) << m;
    }
  }
  const std::string empty = scratch.write("empty.txt", "# nothing\n3\n");
  message_of<BI::Empty_input_error>([&] { BI::IO::read_text_scalar_fields(empty); });
  // Count checks of the dispatcher.
  const std::string ok = scratch.write("ok.txt", "2\n1 2\n3 4\n");
  std::string m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_scalar_fields(ok, 3); });
  EXPECT_TRUE(contains(m, "has values for 2 vertices, the domain has 3")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_scalar_fields(ok, 2, 3); });
  EXPECT_TRUE(contains(m, "has 2 fields, expected 3")) << m;
}

// ===========================================================================
// Output files

BI::Boolean_isosurface_soup<Point_3> sample_soup()
{
  BI::Boolean_isosurface_soup<Point_3> soup;
  const std::vector<double> c = random_values(3 * 9, 13, 2.);
  for(std::size_t v = 0; v < 9; ++v)
    soup.points.emplace_back(c[3 * v], c[3 * v + 1], c[3 * v + 2]);
  soup.points[0] = Point_3(0.1, 1. / 3., -0.0);
  soup.polygons = {{0, 1, 2}, {2, 1, 3, 4}, {4, 5, 6, 7, 8}, {8, 7, 0}, {3, 5, 6}};
  soup.face_fields = {0, 1, BI::Boolean_isosurface_soup<Point_3>::domain_boundary, 5, 13};
  return soup;
}

TEST(OutputFiles, PlyWithFieldsRoundTrip)
{
  Scratch scratch;
  const BI::Boolean_isosurface_soup<Point_3> soup = sample_soup();
  for(bool binary : {false, true})
  {
    const std::string path = scratch.file(binary ? "b.ply" : "a.ply");
    BI::IO::write_PLY_with_fields(path, soup, binary);
    BI::Boolean_isosurface_soup<Point_3> back;
    back.points.emplace_back(9, 9, 9); // cleared by the reader
    BI::IO::read_PLY_with_fields(path, back);
    EXPECT_EQ(back.points, soup.points) << binary;
    EXPECT_EQ(back.polygons, soup.polygons) << binary;
    EXPECT_EQ(back.face_fields, soup.face_fields) << binary;

    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string header = text.substr(0, text.find("end_header\n") + 11);
    EXPECT_TRUE(contains(header, "element vertex 9\nproperty double x\nproperty double y\nproperty double z\n"));
    EXPECT_TRUE(contains(header, "element face 5\nproperty list uchar int vertex_indices\nproperty int field\n"
                                 "property uchar red\nproperty uchar green\nproperty uchar blue\n"));
    if(binary)
    {
      std::size_t faces = 0;
      for(const auto& p : soup.polygons)
        faces += 1 + 4 * p.size() + 4 + 3;
      EXPECT_EQ(text.size(), header.size() + 9 * 24 + faces);
    }
    else
    {
      EXPECT_TRUE(contains(text, "\n5 4 5 6 7 8 -1 160 160 160\n")); // boundary: grey
      EXPECT_TRUE(contains(text, "\n3 0 1 2 0 228 26 28\n"));
      EXPECT_TRUE(contains(text, "\n3 3 5 6 13 55 126 184\n")); // palette cycles: 13 % 12 = 1
    }
  }
  // Distinct labels get distinct colours within a palette cycle; boundary grey is none of them.
  for(int a = -1; a < 12; ++a)
    for(int b = a + 1; b < 12; ++b)
      EXPECT_NE(BI::IO::field_color(a), BI::IO::field_color(b)) << a << " " << b;
}

TEST(OutputFiles, PlyReaderErrorsAndForeignLayouts)
{
  Scratch scratch;
  BI::Boolean_isosurface_soup<Point_3> soup;
  // Float coordinates, extra properties and elements, int8 list counts: still read.
  const std::string foreign = scratch.write("f.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                                     "property float y\nproperty float z\nproperty uchar alpha\n"
                                                     "element face 1\nproperty int field\nproperty list char uint vertex_index\n"
                                                     "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                                                     "end_header\n0 0 0 1\n1 0 0 1\n0 1 0 1\n-1 3 0 1 2\n0 1\n");
  BI::IO::read_PLY_with_fields(foreign, soup);
  EXPECT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<std::size_t>>{{0, 1, 2}}));
  EXPECT_EQ(soup.face_fields, std::vector<int>{-1});

  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                           "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                           "property int field\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  std::string m = message_of<BI::Parse_error>(
      [&] { BI::IO::read_PLY_with_fields(scratch.write("e.ply", head + "3 0 1 2\n"), soup); });
  EXPECT_TRUE(contains(m, "line 14: too few values")) << m;
  m = message_of<BI::Invalid_input_error>(
      [&] { BI::IO::read_PLY_with_fields(scratch.write("e.ply", head + "3 0 1 3 0\n"), soup); });
  EXPECT_TRUE(contains(m, "face 0 refers to vertex 3")) << m;
  m = message_of<BI::Parse_error>(
      [&] { BI::IO::read_PLY_with_fields(scratch.write("e.ply", head + "3 0 1 2 -2\n"), soup); });
  EXPECT_TRUE(contains(m, "line 14: the field -2")) << m;
  m = message_of<BI::Invalid_input_error>([&] {
    std::string no_field = head;
    no_field.replace(no_field.find("property int field\n"), 19, "");
    BI::IO::read_PLY_with_fields(scratch.write("e.ply", no_field + "3 0 1 2\n"), soup);
  });
  EXPECT_TRUE(contains(m, "no scalar property 'field'")) << m;
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_PLY_with_fields(scratch.file("none.ply"), soup); });
  EXPECT_TRUE(contains(m, "none.ply")) << m;
  // A truncated binary body.
  BI::IO::write_PLY_with_fields(scratch.file("b.ply"), sample_soup(), true);
  std::filesystem::resize_file(scratch.file("b.ply"), std::filesystem::file_size(scratch.file("b.ply")) - 5);
  m = message_of<BI::Invalid_input_error>([&] { BI::IO::read_PLY_with_fields(scratch.file("b.ply"), soup); });
  EXPECT_TRUE(contains(m, "ends early")) << m;
}

TEST(OutputFiles, PolylinesCornersAndOffRoundTrip)
{
  const BI::Boolean_isosurface_soup<Point_3> soup = sample_soup();
  BI::Crease_network creases;
  creases.polylines = {{0, 1, 2}, {3, 4, 5, 3}};
  creases.corners = {0, 2, 8};

  std::ostringstream polylines;
  BI::IO::write_polylines(polylines, soup.points, creases);
  std::istringstream pin(polylines.str());
  std::string line;
  for(const auto& polyline : creases.polylines)
  {
    ASSERT_TRUE(std::getline(pin, line));
    std::istringstream l(line);
    std::size_t n = 0;
    l >> n;
    ASSERT_EQ(n, polyline.size());
    for(std::size_t v : polyline)
    {
      double x, y, z;
      l >> x >> y >> z;
      EXPECT_EQ(Point_3(x, y, z), soup.points[v]);
    }
    EXPECT_TRUE(l.eof() || (l >> std::ws).eof());
  }
  EXPECT_FALSE(std::getline(pin, line));

  std::ostringstream corners;
  BI::IO::write_corners(corners, soup.points, creases);
  std::istringstream cstream(corners.str());
  for(std::size_t v : creases.corners)
  {
    double x, y, z;
    ASSERT_TRUE(cstream >> x >> y >> z);
    EXPECT_EQ(Point_3(x, y, z), soup.points[v]);
  }
  EXPECT_FALSE(cstream >> line);

  Scratch scratch;
  BI::IO::write_OFF_polygons(scratch.file("s.off"), soup);
  std::ifstream off(scratch.file("s.off"));
  std::size_t V, F, E;
  ASSERT_TRUE(off >> line >> V >> F >> E);
  EXPECT_EQ(line, "OFF");
  ASSERT_EQ(V, soup.points.size());
  ASSERT_EQ(F, soup.polygons.size());
  for(const Point_3& p : soup.points)
  {
    double x, y, z;
    off >> x >> y >> z;
    EXPECT_EQ(Point_3(x, y, z), p);
  }
  for(const auto& polygon : soup.polygons)
  {
    std::size_t n;
    off >> n;
    ASSERT_EQ(n, polygon.size());
    for(std::size_t v : polygon)
    {
      std::size_t w;
      off >> w;
      EXPECT_EQ(w, v);
    }
  }
  // The file variants write the same text.
  BI::IO::write_polylines(scratch.file("p.polylines.txt"), soup.points, creases);
  std::ifstream pf(scratch.file("p.polylines.txt"));
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(pf)), std::istreambuf_iterator<char>()), polylines.str());
}

TEST(OutputFiles, WriterErrors)
{
  const BI::Boolean_isosurface_soup<Point_3> soup = sample_soup();
  BI::Crease_network creases;
  creases.corners = {9};
  const std::string nowhere = "/nonexistent-biso-dir/x";
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] { BI::IO::write_PLY_with_fields(nowhere, soup); }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] { BI::IO::write_OFF_polygons(nowhere, soup); }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] { BI::IO::write_polylines(nowhere, soup.points, {}); }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] { BI::IO::write_corners(nowhere, soup.points, {}); }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] { BI::IO::write_MEDIT(nowhere, jittered_grid_mesh()); }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] {
                         BI::IO::write_text_scalar_fields(nowhere, BI::Scalar_fields(1, std::vector<double>{1.}));
                       }), nowhere));
  EXPECT_TRUE(contains(message_of<std::runtime_error>([&] {
                         BI::IO::write_raw_scalar_fields(nowhere, BI::Scalar_fields(1, std::vector<double>{1.}));
                       }), nowhere));
  std::ostringstream sink;
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::write_corners(sink, soup.points, creases); }),
                       "corner 0 refers to point 9"));
  BI::Boolean_isosurface_soup<Point_3> bad = soup;
  bad.face_fields.pop_back();
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::write_PLY_with_fields(sink, bad); }),
                       "4 face fields for 5 polygons"));
  bad = soup;
  bad.polygons[0].assign(256, 0);
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::write_PLY_with_fields(sink, bad); }),
                       "polygon 0 has 256 vertices"));
  bad = soup;
  bad.face_fields[1] = -2;
  EXPECT_TRUE(contains(message_of<BI::Invalid_input_error>([&] { BI::IO::write_PLY_with_fields(sink, bad); }),
                       "field label -2"));
}

} // namespace
