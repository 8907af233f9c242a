// Runs the command-line tools (`volume`, `csg`) on good and bad files the
// tests write themselves, and checks the exit status and what they print.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct Result
{
  int status;
  std::string out;
  std::string err;
};

std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Tool : public ::testing::Test
{
protected:
  void SetUp() override
  {
    char pattern[] = "/tmp/biso_volume_tool_XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    m_dir = pattern;
  }
  void TearDown() override { std::system(("rm -rf '" + m_dir + "'").c_str()); }

  std::string write(const std::string& name, const std::string& content)
  {
    const std::string path = m_dir + "/" + name;
    std::ofstream(path) << content;
    return path;
  }

  Result run_tool(const char* tool, const std::string& arguments)
  {
    const std::string out = m_dir + "/stdout.txt", err = m_dir + "/stderr.txt";
    const std::string command = std::string(tool) + " " + arguments + " >" + out + " 2>" + err + " </dev/null";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  }

  std::string m_dir;
};

class VolumeTool : public Tool
{
protected:
  Result run(const std::string& arguments) { return run_tool(BISO_VOLUME_TOOL, arguments); }
};

class CsgTool : public Tool
{
protected:
  Result run(const std::string& arguments) { return run_tool(BISO_CSG_TOOL, arguments); }
};

const char* tetrahedron_off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

int count_lines(const std::string& s)
{
  int n = 0;
  for(char c : s) n += (c == '\n');
  return n;
}

TEST_F(VolumeTool, PrintsTheVolumeOfAGoodFile)
{
  const Result r = run(write("tet.off", tetrahedron_off));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("volume 0.16666666666666"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(VolumeTool, CheckPrintsPmpAndExactValues)
{
  const Result r = run("--check " + write("tet.off", tetrahedron_off));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("PMP::volume (Epick)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("exact (Epeck)        0.16666666666666"), std::string::npos) << r.out;
}

TEST_F(VolumeTool, ReadsObjPlyAndStl)
{
  const std::string obj = write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::string ply = write("tet.ply",
                                "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                "property double z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string stl = write("tet.stl",
                                "solid t\n"
                                "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
                                "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
                                "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
                                "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n"
                                "endsolid t\n");
  for(const std::string& path : {obj, ply, stl})
  {
    const Result r = run(path);
    EXPECT_EQ(r.status, 0) << path << ": " << r.err;
    EXPECT_NE(r.out.find("volume 0.16666666666666"), std::string::npos) << path << ": " << r.out;
  }
}

// Every bad input: a non-zero exit, exactly one line on stderr naming the
// file and the problem, nothing on stdout.
struct Bad_case { const char* name; const char* content; const char* expected; };

TEST_F(VolumeTool, BadInputGetsOneClearLineAndNonZeroExit)
{
  const Bad_case cases[] = {
      {"open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n", "not closed"},
      {"garbage.off", "OFF\n4 4 0\n0 0 zero\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
       "line 3: cannot parse coordinate 3 of vertex 0"},
      {"short.off", "OFF\n4 4 0\n0 0 zero\n", "line 2: the header declares 4 vertices"},
      {"huge.off", "OFF\n1000000000 1 0\n", "line 2: the header declares 1000000000 vertices"},
      {"nan.off", "OFF\n4 4 0\n0 0 0\nnan 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
       "line 4: vertex 1 has a non-finite coordinate (nan 0 0)"},
      {"int.ply", "ply\nformat ascii 1.0\nproperty int x\nend_header\n", "line 3: 'property' before any 'element'"},
      {"binary.stl", "\x01\x02\x03 not an STL file", "cannot parse it as STL"},
      {"empty.off", "OFF\n0 0 0\n", "no face"},
      {"inward.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n", "oriented inward"},
      {"not_a_mesh.txt", "hello\n", "cannot parse"},
  };
  for(const Bad_case& c : cases)
  {
    const std::string path = write(c.name, c.content);
    const Result r = run(path);
    EXPECT_NE(r.status, 0) << c.name;
    EXPECT_EQ(count_lines(r.err), 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name << ": " << r.out;
  }
  const Result missing = run(m_dir + "/does_not_exist.off");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("cannot open"), std::string::npos) << missing.err;
  EXPECT_EQ(count_lines(missing.err), 1) << missing.err;
}

TEST_F(VolumeTool, QuadsAreTriangulatedAndTheToolSaysSo)
{
  const Result r = run(write("quad.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                         "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("volume 1 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("12 triangles, 6 polygons split into triangles"), std::string::npos) << r.out;
}

TEST_F(VolumeTool, IntegerCoordinatesInPlyAreLegal)
{
  // CGAL 5.5's PLY reader dereferences null on this file (the tool used to exit 139).
  const Result r = run(write("int.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty int x\nproperty int y\n"
                                        "property int z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0 0 0\n6 0 0\n0 6 0\n0 0 6\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("volume 36 "), std::string::npos) << r.out;
}

TEST_F(VolumeTool, HelpGoesToStdoutAndADirectoryIsAClearError)
{
  const Result help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("usage: volume"), std::string::npos) << help.out;
  EXPECT_TRUE(help.err.empty()) << help.err;
  const Result dir = run(m_dir);
  EXPECT_EQ(dir.status, 1);
  EXPECT_NE(dir.err.find("is a directory"), std::string::npos) << dir.err;
  EXPECT_EQ(count_lines(dir.err), 1) << dir.err;
}

TEST_F(VolumeTool, SignedOptionAcceptsAnInwardMesh)
{
  const Result r = run("--signed " + write("inward.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                        "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("volume -0.16666666666666"), std::string::npos) << r.out;
}

TEST_F(VolumeTool, SelfIntersectingMeshIsRefusedUnlessSigned)
{
  // Two interpenetrating tetrahedra in one file.
  const std::string path = write("two.off", "OFF\n8 8 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n"
                                            "0.3 0.3 0.3\n2.3 0.3 0.3\n0.3 2.3 0.3\n0.3 0.3 2.3\n"
                                            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                                            "3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n");
  const Result refused = run(path);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("intersects itself"), std::string::npos) << refused.err;
  const Result accepted = run("--signed " + path);
  EXPECT_EQ(accepted.status, 0) << accepted.err;
  EXPECT_NE(accepted.out.find("volume 2.666666666666"), std::string::npos) << accepted.out;
}

TEST_F(VolumeTool, ManyFilesOneBadStillReportsTheGoodOnes)
{
  const Result r = run(write("a.off", tetrahedron_off) + " " + m_dir + "/missing.off");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("volume 0.1666"), std::string::npos) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

TEST_F(VolumeTool, UsageErrors)
{
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("--frobnicate x.off").status, 2);
}

TEST_F(VolumeTool, DemoWritesMeshesAndPrintsAccurateVolumes)
{
  const Result r = run("--demo " + m_dir + "/demo");
  EXPECT_EQ(r.status, 0) << r.err;
  for(const char* file : {"sphere.off", "sphere_at_1e7.off", "cube_at_1e6.off", "torus.off"})
    EXPECT_TRUE(std::ifstream(m_dir + "/demo/" + file).good()) << file;
  EXPECT_NE(r.out.find("exact (Epeck)        1 "), std::string::npos) << r.out; // the unit cube, exactly 1
}

// Two overlapping axis-aligned boxes as OFF text (corner, size), outward.
std::string box_off(double x, double y, double z, double s)
{
  std::ostringstream o;
  o.precision(17);
  o << "OFF\n8 12 0\n";
  for(int k = 0; k < 8; ++k)
    o << x + s * (k & 1) << ' ' << y + s * ((k >> 1) & 1) << ' ' << z + s * ((k >> 2) & 1) << "\n";
  // Corner k at offset (k&1, (k>>1)&1, (k>>2)&1); two triangles per face.
  o << "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n"
       "3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n";
  return o.str();
}

double number_after(const std::string& text, const std::string& key)
{
  const auto at = text.find(key);
  return at == std::string::npos ? -1 : std::atof(text.c_str() + at + key.size());
}

TEST_F(CsgTool, UnionIntersectionDifferenceOfTwoBoxes)
{
  // Boxes [0,2]^3 and [1,3]^3: union 15, intersection 1, difference 7.  The
  // box faces lie between lattice planes, so MC reproduces them except near
  // edges and corners, where it cuts by less than a cell: compare loosely.
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  const std::pair<const char*, double> cases[] = {{"union", 15}, {"intersection", 1}, {"difference", 7}};
  for(const auto& [op, expected] : cases)
  {
    const std::string out = m_dir + "/" + op + ".off";
    const Result r = run(a + " " + b + " --op " + op + " --cells 61 -o " + out);
    EXPECT_EQ(r.status, 0) << op << ": " << r.err;
    EXPECT_NE(r.out.find("lattice"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("classification"), std::string::npos) << r.out;
    EXPECT_NEAR(number_after(r.out, "volume "), expected, 0.06 * expected) << op << ": " << r.out;
    EXPECT_TRUE(std::ifstream(out).good()) << op;
    // The written mesh is a valid solid for the volume tool, including its
    // self-intersection check: the tool shifts its lattice off the box
    // faces, so no two vertices coincide.
    const Result v = run_tool(BISO_VOLUME_TOOL, out);
    EXPECT_EQ(v.status, 0) << op << ": " << v.err;
  }
}

TEST_F(CsgTool, ExpressionOverThreeInputs)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2)),
                    c = write("c.off", box_off(5, 5, 5, 1));
  const Result r = run(a + " " + b + " " + c + " --expr \"A & !B | C\" --spacing 0.05");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 7 + 1, 0.06 * 8) << r.out;
}

TEST_F(CsgTool, BadInputGetsOneClearLineAndNonZeroExit)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2));
  const std::string open = write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  const std::string empty = write("empty.off", "OFF\n0 0 0\n");
  const std::pair<std::string, const char*> cases[] = {
      {a + " " + m_dir + "/missing.off --op union --cells 10", "cannot open"},
      {a + " " + open + " --op union --cells 10", "not closed"},
      {a + " " + empty + " --op union --cells 10", "no face"},
      {a + " " + a + " --expr \"A & (B\" --cells 10", "column"},
      {a + " " + a + " --expr \"A | C\" --cells 10", "2 files"},
      {a + " " + a + " --op xor --cells 10", "unknown operation"},
      {a + " " + a + " --op union --spacing 1e-7", "lattice"},
  };
  for(const auto& [arguments, expected] : cases)
  {
    const Result r = run(arguments);
    EXPECT_NE(r.status, 0) << arguments;
    EXPECT_EQ(count_lines(r.err), 1) << arguments << ": " << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << arguments << ": " << r.err;
  }
  EXPECT_EQ(run(a + " " + a + " --op union").status, 2); // neither --cells nor --spacing
  EXPECT_EQ(run(a + " " + a + " --op union --cells -3").status, 2);
}

TEST_F(CsgTool, DemoPrintsTheThreeOperationsAgainstExactVolumes)
{
  const Result r = run("--demo " + m_dir + "/demo --cells 64");
  EXPECT_EQ(r.status, 0) << r.err;
  for(const char* op : {"union", "intersection", "difference"})
  {
    EXPECT_NE(r.out.find(std::string(op) + " ("), std::string::npos) << r.out;
    EXPECT_TRUE(std::ifstream(m_dir + "/demo/" + op + ".off").good()) << op;
  }
  // Every operation's relative volume error is printed and small at 64 cells.
  std::size_t at = 0, count = 0;
  while((at = r.out.find("relative error ", at)) != std::string::npos)
  {
    EXPECT_LT(std::atof(r.out.c_str() + at + 15), 1e-2) << r.out;
    ++at;
    ++count;
  }
  EXPECT_EQ(count, 3u) << r.out;
}

} // namespace
