// Runs the command-line tools (`volume`, `csg`, `contour`) on good and bad
// files the tests write themselves (and on the shared point sets), and checks
// the exit status and what they print; and the conventions of the shared
// command line (--version, --help, exit codes, --json, --threads, the mesh
// formats) in all four tools, tbiso included.

#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <poll.h>
#include <regex>
#include <sstream>
#include <string>
#include <vector>
#include <sys/stat.h>
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
  // --quiet: these tests check the messages, not the progress lines (see
  // Tool.ProgressLinesNameTheStageAndAreSilencedByQuiet).
  Result run(const std::string& arguments) { return run_tool(BISO_VOLUME_TOOL, "--quiet " + arguments); }
};

class CsgTool : public Tool
{
protected:
  // --quiet: these tests check the messages, not the progress lines (see
  // Tool.ProgressLinesNameTheStageAndAreSilencedByQuiet).
  Result run(const std::string& arguments) { return run_tool(BISO_CSG_TOOL, "--quiet " + arguments); }
};

class ContourTool : public Tool
{
protected:
  // --quiet: these tests check the messages, not the progress lines (see
  // Tool.ProgressLinesNameTheStageAndAreSilencedByQuiet).
  Result run(const std::string& arguments) { return run_tool(BISO_CONTOUR_TOOL, "--quiet " + arguments); }
};

// Whether `s` prints on one terminal line: no control byte, no DEL, no byte
// of an invalid UTF-8 sequence (only ASCII is expected here).
bool is_printable_line(const std::string& s)
{
  for(char c : s)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if(u < 0x20 || u >= 0x7f)
      return false;
  }
  return true;
}

// stderr is one printable line followed by a newline.
::testing::AssertionResult is_one_clean_line(const std::string& err)
{
  if(err.empty() || err.back() != '\n' || err.find('\n') != err.size() - 1)
    return ::testing::AssertionFailure() << "not exactly one line: [" << err << "]";
  if(!is_printable_line(err.substr(0, err.size() - 1)))
    return ::testing::AssertionFailure() << "raw non-printable bytes: [" << err << "]";
  return ::testing::AssertionSuccess();
}

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


// The box [0,2]^3 with its faces reversed.
std::string inward_box_off(double x, double y, double z, double s)
{
  std::string text = box_off(x, y, z, s);
  std::istringstream in(text);
  std::ostringstream out;
  std::string line;
  int number = 0;
  while(std::getline(in, line))
  {
    int n, a, b, c;
    if(++number > 10 && std::sscanf(line.c_str(), "%d %d %d %d", &n, &a, &b, &c) == 4)
      out << "3 " << a << ' ' << c << ' ' << b << "\n";
    else
      out << line << "\n";
  }
  return out.str();
}

// --- B.2: complements, unbounded results, inward inputs --------------------

TEST_F(CsgTool, ComplementIsClippedByTheBoxAndClosed)
{
  // !A for A = [0,2]^3 at 40 cells (spacing 0.05): the box one cell beyond
  // A, [-0.05, 2.05]^3, minus A: 2.1^3 - 8 = 1.261.
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), out = m_dir + "/not_a.off";
  const Result r = run(a + " --expr \"!A\" --cells 40 -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("unbounded: clipped to the box"), std::string::npos) << r.out;
  EXPECT_NEAR(number_after(r.out, "volume "), 2.1 * 2.1 * 2.1 - 8, 0.04) << r.out;
  // The written shell is a valid, outward, closed solid for the volume tool.
  const Result v = run_tool(BISO_VOLUME_TOOL, out);
  EXPECT_EQ(v.status, 0) << v.err;
  EXPECT_NEAR(number_after(v.out, "volume "), 2.1 * 2.1 * 2.1 - 8, 0.04) << v.out;
}

TEST_F(CsgTool, ComplementOfAUnionAndTheWholeSpace)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  // Inputs' box [0,3]^3, 60 cells: clip box [-0.05, 3.05]^3, minus the union (15).
  const Result r = run(a + " " + b + " --expr \"!(A | B)\" --cells 60");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 3.1 * 3.1 * 3.1 - 15, 0.1) << r.out;
  // A | !A is everything: the clip box itself, not "empty".
  const Result all = run(a + " --expr \"A | !A\" --cells 40");
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_EQ(all.out.find("empty"), std::string::npos) << all.out;
  EXPECT_NEAR(number_after(all.out, "volume "), 2.1 * 2.1 * 2.1, 0.04) << all.out;
  // A & !A is empty, and says so.
  const Result none = run(a + " --expr \"A & !A\" --cells 40");
  ASSERT_EQ(none.status, 0) << none.err;
  EXPECT_NE(none.out.find("the result is empty"), std::string::npos) << none.out;
}

TEST_F(CsgTool, UnboundedSurfaceModeKeepsTheInwardSurface)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), out = m_dir + "/not_a.off";
  const Result r = run(a + " --expr \"!A\" --cells 40 --unbounded surface -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "the complement has volume "), 8, 0.1) << r.out;
  EXPECT_TRUE(std::ifstream(out).good());
  // Written inward: the volume tool refuses it unless --signed, which gives -8.
  EXPECT_NE(run_tool(BISO_VOLUME_TOOL, out).status, 0);
  const Result v = run_tool(BISO_VOLUME_TOOL, "--signed " + out);
  EXPECT_EQ(v.status, 0) << v.err;
  EXPECT_NEAR(number_after(v.out, "volume "), -8, 0.1) << v.out;
  const Result all = run(a + " --expr \"A | !A\" --cells 40 --unbounded surface");
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_NE(all.out.find("all of space"), std::string::npos) << all.out;
}

TEST_F(CsgTool, InwardInputIsUsedWithANote)
{
  const std::string a = write("inward.off", inward_box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  const Result r = run(a + " " + b + " --op union --cells 61");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(is_one_clean_line(r.err));
  EXPECT_NE(r.err.find("note:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("inward"), std::string::npos) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 15, 0.06 * 15) << r.out;
  // The same result as with the outward box.
  const Result outward = run(write("a.off", box_off(0, 0, 0, 2)) + " " + b + " --op union --cells 61");
  EXPECT_EQ(number_after(r.out, "volume "), number_after(outward.out, "volume ")) << r.out << outward.out;
}

// --- B.4: help and usage -----------------------------------------------------

TEST_F(CsgTool, HelpGoesToStdoutWithExitZero)
{
  for(const char* flag : {"--help", "-h"})
  {
    const Result r = run(flag);
    EXPECT_EQ(r.status, 0) << flag;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_NE(r.out.find("usage: csg"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--unbounded"), std::string::npos) << r.out;
    for(const char* option : {"--no-features", "--feature-angle", "--creases", "--corners", "--strict"})
      EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

TEST_F(ContourTool, HelpGoesToStdoutWithExitZero)
{
  const Result r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("usage: contour"), std::string::npos) << r.out;
}

// Runs the contour tool with a terminal (a pseudo-terminal) as stdin and no
// argument: it must not wait for input, but print a usage error and exit 2.
TEST_F(ContourTool, NoArgumentWithATerminalOnStdinIsAUsageError)
{
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  const std::string slave_name = ptsname(master);
  const std::string err_path = m_dir + "/stderr.txt";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if(pid == 0)
  {
    const int slave = open(slave_name.c_str(), O_RDWR);
    const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_WRONLY);
    if(slave < 0 || err < 0 || null < 0) _exit(100);
    dup2(slave, 0);
    dup2(null, 1);
    dup2(err, 2);
    execl(BISO_CONTOUR_TOOL, BISO_CONTOUR_TOOL, static_cast<char*>(nullptr));
    _exit(101);
  }
  int status = 0;
  bool exited = false;
  for(int i = 0; i < 200 && !exited; ++i) // 10 s at most
  {
    exited = waitpid(pid, &status, WNOHANG) == pid;
    if(!exited) usleep(50000);
  }
  if(!exited)
  {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  close(master);
  ASSERT_TRUE(exited) << "contour waited on the terminal";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = slurp(err_path);
  EXPECT_TRUE(is_one_clean_line(err));
  EXPECT_NE(err.find("terminal"), std::string::npos) << err;
}

// --- B.5 and C: every bad command line is one line, with the right code -----

struct Bad_arguments { std::string arguments; int status; const char* expected; };

TEST_F(CsgTool, BadCommandLinesGetOneLineAndExitTwo)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), two = a + " " + a + " --op union ";
  const Bad_arguments cases[] = {
      {two + "--cells 12.5", 2, "not a whole number"},
      {two + "--cells nan", 2, "NaN"},
      {two + "--cells inf", 2, "infinite"},
      {two + "--cells ''", 2, "empty"},
      {two + "--cells 0", 2, "at least 1"},
      {two + "--cells -3", 2, "at least 1"},
      {two + "--cells 10x", 2, "not a number"},
      {two + "--cells 3000000000", 2, "above the limit of"},
      {two + "--spacing -1", 2, "positive"},
      {two + "--spacing 1e999", 2, "too large"},
      {two + "--spacing", 2, "needs"},
      {two + "--cells 10 --cells 20", 2, "more than once"},
      {two + "--cells 10 --spacing 0.1", 2, "only one"},
      {two + "--cells 10 --frobnicate", 2, "unknown option"},
      {two + "--cells 10 --unbounded maybe", 2, "neither box nor surface"},
      {two + "--cells 10 -o out.xyz", 2, "extension"},
      {two + "--cells 10 --max-memory -2", 2, "positive"},
      {two + "--cells 10 --expr A", 2, "exactly one of --op and --expr"},
      {two + "--cells 10 --feature-angle 0", 2, "positive"},
      {two + "--cells 10 --feature-angle 180", 2, "(0, 180)"},
      {two + "--cells 10 --feature-angle", 2, "needs"},
      {two + "--cells 10 --no-features --creases c.txt", 2, "need sharp features"},
      {two + "--cells 10 --no-features --no-features", 2, "more than once"},
      {a + " " + a + " --expr \"A & (B\" --cells 10", 2, "column"},
      {a + " " + a + " --expr \"A | C\" --cells 10", 2, "2 files"},
      {a + " " + a + " --op xor --cells 10", 2, "unknown operation"},
      {a + " --op union --cells 10", 2, "exactly two"},
      {"--demo " + m_dir + "/d " + a, 2, "--demo"},
      // Raw control and invalid UTF-8 bytes are shown escaped.
      {two + "--cells 10 '--\x01\x1b[31m\xff'", 2, "\\x01\\x1b[31m\\xff"},
  };
  for(const Bad_arguments& c : cases)
  {
    const Result r = run(c.arguments);
    EXPECT_EQ(r.status, c.status) << c.arguments << ": " << r.err;
    EXPECT_TRUE(is_one_clean_line(r.err)) << c.arguments;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.arguments << ": " << r.out;
  }
}

TEST_F(CsgTool, TooManyCellsIsRefusedWithTheEstimateAndTheLimit)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2));
  const Result r = run(a + " " + a + " --op union --cells 2000000");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(is_one_clean_line(r.err));
  EXPECT_EQ(r.err.find("not a whole number"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--cells 2000000"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("would have 8e+18 points"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2^62"), std::string::npos) << r.err;
  // Below the point limit but above a small memory limit: the estimate in GiB
  // (the lattice is sparse: what grows is the crossings of the box's faces).
  const Result m = run(a + " " + a + " --op union --cells 4000 --max-memory 0.5");
  EXPECT_EQ(m.status, 1) << m.err;
  EXPECT_TRUE(is_one_clean_line(m.err));
  EXPECT_NE(m.err.find("GiB, more than the limit of 0.5 GiB (--max-memory)"), std::string::npos) << m.err;
}

// The inputs are read side by side on a parallel run; when several are bad
// the error is still the first bad one in order, as in a sequential run.
TEST_F(CsgTool, TheFirstBadInputInOrderIsTheError)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2));
  const std::string open = write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  const std::string missing = m_dir + "/missing.off";
  for(const char* threads : {"", "--sequential "})
  {
    Result r = run(std::string(threads) + open + " " + missing + " " + a + " --expr \"A | B | C\" --cells 10");
    EXPECT_EQ(r.status, 1) << threads;
    EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("open.off"), std::string::npos) << threads << r.err;
    EXPECT_NE(r.err.find("not closed"), std::string::npos) << threads << r.err;
    r = run(std::string(threads) + a + " " + missing + " " + open + " --expr \"A | B | C\" --cells 10");
    EXPECT_EQ(r.status, 1) << threads;
    EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("missing.off: cannot open"), std::string::npos) << threads << r.err;
  }
}

TEST_F(CsgTool, FileProblemsAreNamedBeforeComputing)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), two = a + " " + a + " --op union --cells 10 ";
  // A directory as an input, as an output.
  Result r = run(m_dir + " " + a + " --op union --cells 10");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(is_one_clean_line(r.err));
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  r = run(two + "-o " + m_dir);
  EXPECT_EQ(r.status, 2); // no extension: a usage error
  r = run(two + "-o " + m_dir + "/sub.off");
  EXPECT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(mkdir((m_dir + "/dir.off").c_str(), 0755), 0);
  r = run(two + "-o " + m_dir + "/dir.off");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  // An unwritable output is found before any computation (nothing on stdout).
  r = run(two + "-o " + m_dir + "/no/such/dir/out.off");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(is_one_clean_line(r.err));
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  // The probe of a new output file does not leave it behind when a later
  // step fails, and does not touch an existing one.
  const std::string fresh = m_dir + "/fresh.off";
  r = run(a + " " + m_dir + "/missing.off --op union --cells 10 -o " + fresh);
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(std::ifstream(fresh).good());
  const std::string existing = write("existing.off", "keep me\n");
  r = run(a + " " + m_dir + "/missing.off --op union --cells 10 -o " + existing);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(slurp(existing), "keep me\n");
  // Garbage bytes in a file are not echoed.
  const std::string garbage = write("garbage.off", "OFF\n\x01\x02\xff\xfe\x1b[2J 1 2\n");
  r = run(a + " " + garbage + " --op union --cells 10");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(is_one_clean_line(r.err));
}

TEST_F(ContourTool, ContoursASampledSphere)
{
  const std::string out = m_dir + "/sphere.off";
  const Result r = run(std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(number_after(r.out, "triangles: "), 100) << r.out;
  EXPECT_TRUE(std::ifstream(out).good());
  const Result plain = run(std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn --max-jump inf");
  EXPECT_EQ(plain.status, 0) << plain.err;
}

TEST_F(ContourTool, BadCommandLinesGetOneLineAndTheRightExit)
{
  const std::string sphere = std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn ";
  const std::string garbage = write("garbage.pts", "\x01\x02\xff\xfe\x1b[2J 1 2\n");
  const Bad_arguments cases[] = {
      {sphere + "--k 2", 2, "at least 3"},
      {sphere + "--k 1e9", 2, "above the limit of 1024"},
      {sphere + "--k 7.5", 2, "not a whole number"},
      {sphere + "--spacing 0", 2, "positive"},
      {sphere + "--spacing nan", 2, "NaN"},
      {sphere + "--spacing inf", 2, "infinite"},
      {sphere + "--spacing ''", 2, "empty"},
      {sphere + "--rho -1", 2, "positive"},
      {sphere + "--delta -0.1", 2, "negative"},
      {sphere + "--delta nan", 2, "NaN"},
      {sphere + "--max-jump -1", 2, "negative"},
      {sphere + "--max-jump 3x", 2, "not a number"},
      {sphere + "--cells", 2, "needs a value"},
      {sphere + "--cells 2000000", 2, "above the limit of 1048576"},
      {sphere + "--cells 10 --cell 0.1", 2, "exclusive"},
      {sphere + "--k 5 --k 6", 2, "more than once"},
      {sphere + sphere, 2, "more than one input file"},
      {sphere + "--bogus", 2, "unknown option"},
      {sphere + "-o out.xyz", 2, "extension"},
      {sphere + "-o", 2, "needs a value"},
      {sphere + "'--\x01\xff'", 2, "\\x01\\xff"},
      // Runtime problems: exit 1.
      {m_dir, 1, "is a directory"},
      {m_dir + "/missing.pts", 1, "cannot open"},
      {sphere + "-o " + m_dir + "/no/such/dir/x.off", 1, "cannot write"},
      {sphere + "--cells 100000", 1, "above the limit"},
      {sphere + "--spacing 1e-6", 1, "surface cubes"},
  };
  for(const Bad_arguments& c : cases)
  {
    const Result r = run(c.arguments);
    EXPECT_EQ(r.status, c.status) << c.arguments << ": " << r.err;
    EXPECT_TRUE(is_one_clean_line(r.err)) << c.arguments;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << ": " << r.err;
  }
  // Checked before reading: nothing on stdout.
  EXPECT_TRUE(run(sphere + "-o " + m_dir + "/no/such/dir/x.off").out.empty());
  // Garbage bytes from a file are escaped, never echoed raw.
  const Result g = run(garbage);
  EXPECT_EQ(g.status, 1);
  EXPECT_TRUE(is_one_clean_line(g.err));
}

// --- Sharp features and the resolution check (issue 17) --------------------

std::vector<std::array<double, 3>> read_points(const std::string& text, bool polylines)
{
  std::vector<std::array<double, 3>> points;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream l(line);
    std::size_t n = 1;
    if(polylines && !(l >> n))
      continue;
    for(std::size_t i = 0; i < n; ++i)
    {
      std::array<double, 3> p;
      if(l >> p[0] >> p[1] >> p[2])
        points.push_back(p);
    }
  }
  return points;
}

// Issue 17: --simplify keeps the (exact) result in a few hundred triangles,
// --remesh keeps it too; the two exclude each other.
TEST_F(CsgTool, SimplifyAndRemeshKeepTheResult)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1.137, 1.091, 1.063, 2));
  const double exact = 8 - 0.863 * 0.909 * 0.937;
  const Result plain = run(a + " " + b + " --op difference --cells 32");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const Result simplified = run(a + " " + b + " --op difference --cells 32 --simplify");
  ASSERT_EQ(simplified.status, 0) << simplified.err;
  EXPECT_NEAR(number_after(simplified.out, "volume "), exact, 1e-9 * exact) << simplified.out;
  EXPECT_LE(number_after(simplified.out, "vertices, "), 300) << simplified.out;
  EXPECT_GT(number_after(plain.out, "vertices, "), 5 * number_after(simplified.out, "vertices, ")) << plain.out;
  const Result remeshed = run(a + " " + b + " --op difference --cells 32 --remesh 0.1");
  ASSERT_EQ(remeshed.status, 0) << remeshed.err;
  EXPECT_NEAR(number_after(remeshed.out, "volume "), exact, 1e-9 * exact) << remeshed.out;
  const Result both = run(a + " " + b + " --op difference --cells 32 --remesh --simplify");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("at most one of --simplify and --remesh"), std::string::npos) << both.err;
  EXPECT_EQ(run(a + " " + b + " --op difference --cells 32 --simplify -1").status, 2);
}

// Issue 17: the lattice is sized on where the result can be.  A unit part
// intersected with an operand 10^30 wide comes out whole (on the inputs' box
// the lattice would have cells of 10^29).
TEST_F(CsgTool, ATinyPartInAHugeOperandIsSizedOnThePart)
{
  const std::string a = write("a.off", box_off(0.1, 0.2, 0.3, 1)), huge = write("huge.off", box_off(-1e30, -1e30, -1e30, 2e30));
  const Result r = run(a + " " + huge + " --op intersection --cells 16");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 1.0, 1e-9) << r.out;
  const Result d = run(a + " " + huge + " --op difference --cells 16");
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_NE(d.out.find("the result is empty"), std::string::npos) << d.out;
}

// Issue 17: an input whose own shells overlap is named (parity makes the
// doubly covered part a void).
TEST_F(CsgTool, OverlappingShellsOfOneInputAreNamed)
{
  // Two unit-ish boxes in one file, overlapping.
  std::ostringstream two;
  two.precision(17);
  two << "OFF\n16 24 0\n";
  for(double o : {0.0, 0.5})
    for(int k = 0; k < 8; ++k)
      two << o + (k & 1) << ' ' << o + ((k >> 1) & 1) << ' ' << o + ((k >> 2) & 1) << "\n";
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for(int shell = 0; shell < 2; ++shell)
    for(const auto& f : faces)
      two << "3 " << f[0] + 8 * shell << ' ' << f[1] + 8 * shell << ' ' << f[2] + 8 * shell << "\n";
  const std::string a = write("two_shells.off", two.str()), b = write("b.off", box_off(3, 3, 3, 1));
  const Result r = run(a + " " + b + " --op union --cells 16");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("two_shells.off (A) has overlapping shells"), std::string::npos) << r.err;
  const Result clean = run(b + " " + b + " --op union --cells 16 --check-inputs");
  EXPECT_EQ(clean.err.find("overlapping"), std::string::npos) << clean.err;
  EXPECT_EQ(clean.err.find("intersects itself"), std::string::npos) << clean.err;
  // One shell folded through itself: a box whose corner (1, 1, 1) is moved
  // beyond its face x = 0.  Only --check-inputs tests for that.
  std::ostringstream folded;
  folded << "OFF\n8 12 0\n";
  for(int k = 0; k < 7; ++k)
    folded << (k & 1) << ' ' << ((k >> 1) & 1) << ' ' << ((k >> 2) & 1) << "\n";
  folded << "-0.2 0.5 0.5\n";
  for(const auto& f : faces)
    folded << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << "\n";
  const std::string c = write("folded.off", folded.str());
  const Result unchecked = run(c + " " + b + " --op union --cells 16");
  ASSERT_EQ(unchecked.status, 0) << unchecked.err;
  EXPECT_EQ(unchecked.err.find("intersects itself"), std::string::npos) << unchecked.err;
  const Result checked = run(c + " " + b + " --op union --cells 16 --check-inputs");
  ASSERT_EQ(checked.status, 0) << checked.err;
  EXPECT_NE(checked.err.find("folded.off (A) intersects itself"), std::string::npos) << checked.err;
}

// A = [0,2]^3 minus B = A moved by a non-lattice offset: the exact result has
// 14 vertices (7 of A, B's lowest corner, 3 + 3 edge-face intersections), and
// its edges are on the planes x in {0, 2, bx}, y in {0, 2, by}, z in {0, 2, bz}.
TEST_F(CsgTool, SharpFeaturesPutCornersAndCreasesOnTheExactResult)
{
  const double b[3] = {0.5137, 0.4419, 0.6271};
  const std::string a = write("a.off", box_off(0, 0, 0, 2));
  // box_off() with a different offset per axis: its corner lines rewritten.
  std::ostringstream moved;
  moved.precision(17);
  moved << "OFF\n8 12 0\n";
  for(int k = 0; k < 8; ++k)
    moved << b[0] + 2 * (k & 1) << ' ' << b[1] + 2 * ((k >> 1) & 1) << ' ' << b[2] + 2 * ((k >> 2) & 1) << "\n";
  const std::string faces = box_off(0, 0, 0, 2);
  moved << faces.substr(faces.find("3 0 2 3"));
  const std::string bb = write("b.off", moved.str());
  const double exact = 8 - (2 - b[0]) * (2 - b[1]) * (2 - b[2]);
  const std::string creases = m_dir + "/creases.polylines.txt", corners = m_dir + "/corners.xyz";
  const Result r = run(a + " " + bb + " --op difference --cells 32 --creases " + creases + " --corners " + corners +
                       " -o " + m_dir + "/d.off");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("sharp features:"), std::string::npos) << r.out;
  // Exact up to rounding: the faces are flat and every edge and corner is a feature.
  EXPECT_NEAR(number_after(r.out, "volume "), exact, 1e-9 * exact) << r.out;
  const double spacing = number_after(r.out, "spacing ");
  ASSERT_GT(spacing, 0) << r.out;
  std::vector<std::array<double, 3>> vertices;
  for(int k = 0; k < 7; ++k)
    vertices.push_back({{2.0 * (k & 1), 2.0 * ((k >> 1) & 1), 2.0 * ((k >> 2) & 1)}});
  vertices.push_back({{b[0], b[1], b[2]}});
  for(int axis = 0; axis < 3; ++axis)
  {
    std::array<double, 3> p{{b[0], b[1], b[2]}}, q{{2, 2, 2}};
    p[axis] = 2; // B's edge from its lowest corner along `axis` leaves A at 2
    q[axis] = b[axis]; // A's edge into (2, 2, 2) enters B at b
    vertices.push_back(p);
    vertices.push_back(q);
  }
  const std::vector<std::array<double, 3>> found = read_points(slurp(corners), false);
  std::vector<bool> hit(vertices.size(), false);
  for(const auto& c : found)
  {
    double best = 1e300;
    std::size_t nearest = 0;
    for(std::size_t v = 0; v < vertices.size(); ++v)
    {
      const double d = std::hypot(c[0] - vertices[v][0], c[1] - vertices[v][1], c[2] - vertices[v][2]);
      if(d < best)
        best = d, nearest = v;
    }
    EXPECT_LT(best, 1e-9 * spacing) << c[0] << " " << c[1] << " " << c[2];
    hit[nearest] = true;
  }
  EXPECT_EQ(std::count(hit.begin(), hit.end(), true), 14) << slurp(corners);
  // Every crease point is on an exact edge: two of its coordinates on face planes.
  const std::vector<std::array<double, 3>> crease_points = read_points(slurp(creases), true);
  EXPECT_GT(crease_points.size(), 100u);
  for(const auto& p : crease_points)
  {
    int on_planes = 0;
    for(int axis = 0; axis < 3; ++axis)
      on_planes += std::min({std::abs(p[axis]), std::abs(p[axis] - 2), std::abs(p[axis] - b[axis])}) < 1e-9 * spacing;
    EXPECT_GE(on_planes, 2) << p[0] << " " << p[1] << " " << p[2];
  }
  // Plain Marching Cubes chamfers the edges: a larger error, and no features line.
  const Result plain = run(a + " " + bb + " --op difference --cells 32 --no-features");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.out.find("sharp features:"), std::string::npos) << plain.out;
  EXPECT_GT(std::abs(number_after(plain.out, "volume ") - exact), 1e-4 * exact) << plain.out;
  // A feature angle above the boxes' 90 degrees finds no feature.
  const Result blunt = run(a + " " + bb + " --op difference --cells 32 --feature-angle 95");
  ASSERT_EQ(blunt.status, 0) << blunt.err;
  EXPECT_EQ(blunt.out.find("sharp features:"), std::string::npos) << blunt.out;
}

// A slab thinner than a cell united with a box: no lattice point is inside
// the slab, so it would vanish silently.  The tool names it and the --cells
// that resolves it; at those cells it is there, with its exact volume.
TEST_F(CsgTool, ThinSlabIsReportedWithTheCellsThatResolveIt)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 1));
  // [1.5, 2] x [0, 1] x [0.1, 0.14]; at 16 cells (r = 0.125) the lattice
  // planes are at z = -0.17 + 0.125 k: none between 0.1 and 0.14.
  std::ostringstream o;
  o.precision(17);
  o << "OFF\n8 12 0\n";
  for(int k = 0; k < 8; ++k)
    o << 1.5 + 0.5 * (k & 1) << ' ' << 1.0 * ((k >> 1) & 1) << ' ' << 0.1 + 0.04 * ((k >> 2) & 1) << "\n";
  const std::string faces = box_off(0, 0, 0, 1);
  o << faces.substr(faces.find("3 0 2 3"));
  const std::string slab = write("slab.off", o.str());
  const std::string out = m_dir + "/u.off";
  const Result r = run(a + " " + slab + " --op union --cells 16 -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(slab + " (B) component 0"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("1 not resolved"), std::string::npos) << r.out;
  EXPECT_NEAR(number_after(r.out, "volume "), 1, 1e-7) << r.out; // the slab is missing
  EXPECT_TRUE(std::ifstream(out).good());
  const double cells = number_after(r.err, "--cells ");
  ASSERT_GT(cells, 16) << r.err;
  EXPECT_LT(cells, 400) << r.err;
  // --strict: an error, exit 1, nothing written.
  const std::string strict_out = m_dir + "/strict.off";
  const Result strict = run(a + " " + slab + " --op union --cells 16 --strict -o " + strict_out);
  EXPECT_EQ(strict.status, 1) << strict.err;
  EXPECT_NE(strict.err.find("error: "), std::string::npos) << strict.err;
  EXPECT_FALSE(std::ifstream(strict_out).good());
  // At the suggested cells the slab is there: 1 + 0.5 * 0.04.
  const Result fine = run(a + " " + slab + " --op union --strict --cells " + std::to_string(int(cells)));
  ASSERT_EQ(fine.status, 0) << fine.err;
  EXPECT_TRUE(fine.err.empty()) << fine.err;
  EXPECT_NEAR(number_after(fine.out, "volume "), 1.02, 1e-3) << fine.out;
}

// An intersection of disjoint boxes is empty for the right reason, but the
// tool cannot know: not a plain success (a warning; --strict: exit 1).
// A & !A is empty whatever the inputs: no warning.
TEST_F(CsgTool, EmptyResultFromNonEmptyInputsIsNotAPlainSuccess)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 1)), b = write("b.off", box_off(3, 0, 0, 1));
  const Result r = run(a + " " + b + " --op intersection --cells 16");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("the result is empty"), std::string::npos) << r.out;
  EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("warning: the result is empty although the inputs are not"), std::string::npos) << r.err;
  EXPECT_EQ(run(a + " " + b + " --op intersection --cells 16 --strict").status, 1);
  const Result none = run(a + " --expr \"A & !A\" --cells 16 --strict");
  EXPECT_EQ(none.status, 0) << none.err;
  EXPECT_TRUE(none.err.empty()) << none.err;
}

// Manifold's HullMask test: body - mask leaves shells 1-2 units thick.
// Every input component is resolved at 64 cells (spacing 5), but the result
// is not: the check on the result's own intervals says so, with the cells
// that see them; there the volume is within 0.1 % of the corefinement's
// (346492.2, the inputs' volume difference: the mask is inside the body).
TEST_F(CsgTool, HullBodyMinusMaskReportsTheThinShells)
{
  const std::string data = std::string(BISO_SHARED_DATA_DIR) + "/boolean_pairs/hull-";
  const Result r = run(data + "body.obj " + data + "mask.obj --op difference --cells 64");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("warning: the result has walls or gaps thinner than a lattice cell"), std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("0 not resolved"), std::string::npos) << r.out;
  EXPECT_LT(number_after(r.out, "volume "), 0.5 * 346492.2) << r.out; // most of the shells are missing
  EXPECT_EQ(run(data + "body.obj " + data + "mask.obj --op difference --cells 64 --strict").status, 1);
  const double cells = number_after(r.err, "--cells ");
  ASSERT_GT(cells, 64) << r.err;
  ASSERT_LT(cells, 1000) << r.err;
  const Result fine = run(data + "body.obj " + data + "mask.obj --op difference --strict --cells " +
                          std::to_string(int(cells)));
  ASSERT_EQ(fine.status, 0) << fine.err;
  EXPECT_TRUE(fine.err.empty()) << fine.err;
  EXPECT_NEAR(number_after(fine.out, "volume "), 346492.2, 0.001 * 346492.2) << fine.out;
}

// At 200 cells hardly any interval through the shells is empty (0.22 % of the
// volume: the thin-result check is silent), but a quarter of the result lies
// in walls one lattice point thick, which Marching Cubes breaks into pieces:
// 7 % of the volume is lost.  Measured: 21.5 % sparse (warned above 15 %).
// The cells it suggests see the shells.
TEST_F(CsgTool, HullBodyMinusMaskAt200CellsReportsWallsOnePointThick)
{
  const std::string data = std::string(BISO_SHARED_DATA_DIR) + "/boolean_pairs/hull-";
  const Result r = run(data + "body.obj " + data + "mask.obj --op difference --cells 200");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("walls or gaps that hold at most one lattice point across"), std::string::npos) << r.err;
  EXPECT_LT(number_after(r.out, "volume "), 0.97 * 346492.2) << r.out;
  EXPECT_EQ(run(data + "body.obj " + data + "mask.obj --op difference --cells 200 --strict").status, 1);
  const double cells = number_after(r.err, "--cells ");
  ASSERT_GT(cells, 256) << r.err;
  ASSERT_LT(cells, 2000) << r.err;
  const Result fine = run(data + "body.obj " + data + "mask.obj --op difference --strict --cells " +
                          std::to_string(int(cells)));
  ASSERT_EQ(fine.status, 0) << fine.err;
  EXPECT_TRUE(fine.err.empty()) << fine.err;
  EXPECT_NEAR(number_after(fine.out, "volume "), 346492.2, 0.001 * 346492.2) << fine.out;
}

// Manifold's GenericTwinBooleanTest7081 pair at 128 cells (an empty union
// before the check, exit 0): its main shell is a sheet about 1.2 units thick
// in a box 15000 units long (spacing 115), its 12 small pieces cross no
// lattice edge.  Now they are named, and the empty union is not a success
// under --strict.  (Under a second: no slow label needed.)
TEST_F(CsgTool, GenericTwinUnionNamesWhatTheLatticeMisses)
{
  const std::string data = std::string(BISO_SHARED_DATA_DIR) + "/boolean_pairs/Generic_Twin_7081.1.t0_";
  const Result r = run(data + "left.obj " + data + "right.obj --op union --cells 128");
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("is not resolved by the lattice"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("left.obj (A) component 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the result is empty although the inputs are not"), std::string::npos) << r.err;
  const Result strict = run(data + "left.obj " + data + "right.obj --op union --cells 128 --strict");
  EXPECT_EQ(strict.status, 1) << strict.out << strict.err;
}

} // namespace

// --- The shared command line (tools/Boolean_isosurfacing_3/cli.h) ---------

struct Tool_binary { const char* name; const char* path; };
const Tool_binary all_tools[] = {{"volume", BISO_VOLUME_TOOL},
                                 {"csg", BISO_CSG_TOOL},
                                 {"contour", BISO_CONTOUR_TOOL},
                                 {"tbiso", BISO_TBISO_TOOL}};

TEST_F(Tool, VersionPrintsTheToolAndTheProjectVersion)
{
  for(const Tool_binary& t : all_tools)
  {
    const Result r = run_tool(t.path, "--version");
    EXPECT_EQ(r.status, 0) << t.name << ": " << r.err;
    EXPECT_EQ(r.out, std::string(t.name) + " " + BISO_VERSION + "\n") << t.name;
    EXPECT_TRUE(r.err.empty()) << t.name << ": " << r.err;
  }
}

TEST_F(Tool, HelpGoesToStdoutWithTheCommonOptions)
{
  for(const Tool_binary& t : all_tools)
    for(const char* flag : {"--help", "-h"})
    {
      const Result r = run_tool(t.path, flag);
      EXPECT_EQ(r.status, 0) << t.name << " " << flag;
      EXPECT_TRUE(r.err.empty()) << t.name << ": " << r.err;
      EXPECT_NE(r.out.find(std::string("usage: ") + t.name), std::string::npos) << r.out;
      for(const char* option : {"--threads", "--sequential", "--json", "--quiet", "--version"})
        EXPECT_NE(r.out.find(option), std::string::npos) << t.name << ": " << option;
    }
}

TEST_F(Tool, UsageErrorsAreOneLineWithExitTwo)
{
  for(const Tool_binary& t : all_tools)
    for(const char* arguments : {"--frobnicate", "--threads 0", "--threads two", "--threads 2 --sequential",
                                 "--json --json", "--threads"})
    {
      const Result r = run_tool(t.path, arguments);
      EXPECT_EQ(r.status, 2) << t.name << " " << arguments << ": " << r.err;
      EXPECT_TRUE(is_one_clean_line(r.err)) << t.name << " " << arguments;
      EXPECT_EQ(r.err.rfind(std::string(t.name) + ": error: ", 0), 0u) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

// The JSON summary, parsed by Python's json module; prints "key=value" for
// the scalar members and "key=[n]" for the arrays' lengths, one per line.
std::string json_members(const std::string& path)
{
  const std::string script =
      "import json,sys\n"
      "d = json.load(open(sys.argv[1]))\n"
      "for k, v in d.items():\n"
      "    print(k + '=' + (('[%d]' % len(v)) if isinstance(v, list) else ('{}' if isinstance(v, dict) else "
      "json.dumps(v))))\n"
      "    if isinstance(v, dict):\n"
      "        for k2, v2 in v.items():\n"
      "            print(k + '.' + k2 + '=' + json.dumps(v2))\n";
  const std::string command = "/usr/bin/python3 -c \"$(cat <<'PYEOF'\n" + script + "PYEOF\n)\" '" + path + "' 2>&1";
  std::string out;
  if(FILE* pipe = popen(command.c_str(), "r"))
  {
    char buffer[4096];
    std::size_t n;
    while((n = fread(buffer, 1, sizeof buffer, pipe)) > 0)
      out.append(buffer, n);
    if(pclose(pipe) != 0)
      return "python failed: " + out;
  }
  return out;
}

// The value of `key=` in json_members' output (NaN if absent).
double member(const std::string& members, const std::string& key)
{
  const std::string lines = "\n" + members, line = "\n" + key + "=";
  const std::size_t at = lines.find(line);
  return at == std::string::npos ? std::nan("") : std::atof(lines.c_str() + at + line.size());
}

TEST_F(Tool, JsonSummariesParseAndHoldTheDocumentedKeys)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  const std::string tet = write("tet.off", tetrahedron_off);
  const std::string points = std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn";
  struct Case { const char* tool; std::string arguments; std::vector<std::string> keys; };
  const Case cases[] = {
      {BISO_VOLUME_TOOL, tet + " " + tet, {"results=[2]"}},
      {BISO_CSG_TOOL, a + " " + b + " --op union --cells 16 -o " + m_dir + "/u.off",
       {"vertices=", "faces=", "volume=", "lattice=", "expression=", "times.classification=", "times.read="}},
      {BISO_CONTOUR_TOOL, points + " -o " + m_dir + "/c.off", {"vertices=", "faces=", "points=", "times.contouring="}},
      {BISO_TBISO_TOOL, "--cells 8 --field sphere:0,0,0,0.5 -o " + m_dir + "/t.ply",
       {"vertices=", "faces=", "volume=", "closed=true", "creases=", "times.extraction=", "times.fields="}},
  };
  for(const Case& c : cases)
  {
    const Result r = run_tool(c.tool, c.arguments + " --json");
    ASSERT_EQ(r.status, 0) << c.tool << ": " << r.err;
    std::ofstream(m_dir + "/summary.json") << r.out;
    const std::string members = json_members(m_dir + "/summary.json");
    for(const std::string key : {"tool=", "version=\"" BISO_VERSION "\"", "inputs=", "outputs=", "times=",
                                 "warnings=[0]"})
      EXPECT_NE(members.find(key), std::string::npos) << c.tool << ": " << key << "\n" << members << r.out;
    for(const std::string& key : c.keys)
      EXPECT_NE(members.find(key), std::string::npos) << c.tool << ": " << key << "\n" << members;
    EXPECT_EQ(r.out.find("time "), std::string::npos) << "no human summary with --json: " << r.out;
  }
  // The values are the ones of the human summary.
  const Result human = run_tool(BISO_CSG_TOOL, a + " " + b + " --op union --cells 16");
  const Result json = run_tool(BISO_CSG_TOOL, a + " " + b + " --op union --cells 16 --json");
  std::ofstream(m_dir + "/csg.json") << json.out;
  const std::string members = json_members(m_dir + "/csg.json");
  EXPECT_NEAR(member(members, "volume"), number_after(human.out, "volume "), 1e-6) << members;
  EXPECT_EQ(member(members, "faces"), number_after(human.out, "vertices, ")) << members << human.out;
}

TEST_F(Tool, JsonHasTheWarnings)
{
  // A thin slab the lattice misses: a warning, in the JSON too.
  const std::string a = write("a.off", box_off(0, 0, 0, 2));
  std::ostringstream slab;
  slab << "OFF\n8 12 0\n";
  for(int k = 0; k < 8; ++k)
    slab << ((k & 1) ? 2.0 : 0.0) << " " << ((k & 2) ? 2.0 : 0.0) << " " << ((k & 4) ? 1.0005 : 1.0) << "\n";
  slab << "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n";
  const std::string thin = write("thin.off", slab.str());
  const Result r = run_tool(BISO_CSG_TOOL, a + " " + thin + " --op difference --cells 8 --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ofstream(m_dir + "/w.json") << r.out;
  const std::string members = json_members(m_dir + "/w.json");
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_EQ(members.find("warnings=[0]"), std::string::npos) << members;
  EXPECT_NE(members.find("warnings=["), std::string::npos) << members;
}

TEST_F(Tool, ProgressLinesNameTheStageAndAreSilencedByQuiet)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  const Result r = run_tool(BISO_CSG_TOOL, a + " " + b + " --op union --cells 16");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("csg: classified "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" lattice points in "), std::string::npos) << r.err;
  const Result quiet = run_tool(BISO_CSG_TOOL, a + " " + b + " --op union --cells 16 --quiet");
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
  const Result t = run_tool(BISO_TBISO_TOOL, "--cells 8 --field sphere:0,0,0,0.5");
  EXPECT_NE(t.err.find("tbiso: extracted "), std::string::npos) << t.err;
  EXPECT_TRUE(run_tool(BISO_TBISO_TOOL, "--cells 8 --field sphere:0,0,0,0.5 --quiet").err.empty());
  const Result c = run_tool(BISO_CONTOUR_TOOL, std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn");
  EXPECT_NE(c.err.find("contour: contoured "), std::string::npos) << c.err;
}

// Runs `tool arguments...` with stderr on a pseudo-terminal (stdin and stdout
// on /dev/null) and the progress delay at 0, and returns what it printed on
// the terminal.
std::string run_on_a_terminal(const char* tool, const std::vector<std::string>& arguments)
{
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if(master < 0 || grantpt(master) != 0 || unlockpt(master) != 0)
    return "no pseudo-terminal";
  const std::string slave_name = ptsname(master);
  std::vector<char*> argv{const_cast<char*>(tool)};
  for(const std::string& a : arguments)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if(pid == 0)
  {
    const int slave = open(slave_name.c_str(), O_RDWR);
    const int null = open("/dev/null", O_RDWR);
    if(slave < 0 || null < 0) _exit(100);
    dup2(null, 0);
    dup2(null, 1);
    dup2(slave, 2);
    setenv("BISO_PROGRESS_DELAY", "0", 1);
    execv(tool, argv.data());
    _exit(101);
  }
  // Read while it runs (a pseudo-terminal holds a few kB), until it exits.
  std::string text;
  char buffer[4096];
  int status = 0;
  bool exited = false;
  for(int i = 0; i < 1200; ++i) // 60 s at most
  {
    pollfd p{master, POLLIN, 0};
    while(poll(&p, 1, 0) > 0 && (p.revents & POLLIN))
    {
      const ssize_t n = read(master, buffer, sizeof buffer);
      if(n <= 0)
        break;
      text.append(buffer, std::size_t(n));
    }
    if(exited)
      break;
    exited = waitpid(pid, &status, WNOHANG) == pid;
    if(!exited)
      usleep(50000);
  }
  if(!exited)
  {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  close(master);
  return text;
}

// On a terminal, the CSG's progress comes live through the library's
// `callback`: a line "csg: computing the CSG [###   ]  N%" redrawn in place
// (\r), erased (\r, spaces, \r) before the stage lines; --quiet silences it.
TEST_F(Tool, ProgressLineIsLiveOnATerminalAndErasedBeforeTheStageLines)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(1, 1, 1, 2));
  const std::string text = run_on_a_terminal(BISO_CSG_TOOL, {a, b, "--op", "union", "--cells", "40"});
  const std::size_t first = text.find("csg: computing the CSG [");
  ASSERT_NE(first, std::string::npos) << text;
  const std::size_t stage = text.find("csg: classified ");
  ASSERT_NE(stage, std::string::npos) << text;
  EXPECT_LT(first, stage) << text;
  // More than one fraction drawn, in place, each with its percentage.
  const std::string progress = text.substr(first, stage - first);
  const std::regex drawn("\r?csg: computing the CSG \\[#* *\\] +[0-9]+%");
  const auto lines = std::distance(std::sregex_iterator(progress.begin(), progress.end(), drawn), std::sregex_iterator());
  EXPECT_GE(lines, 2) << progress;
  // Erased before the stage line: "\r", spaces, "\r" just before it.
  EXPECT_TRUE(std::regex_search(progress, std::regex("\r +\r$"))) << progress;
  // Nothing of it under --quiet.
  const std::string quiet = run_on_a_terminal(BISO_CSG_TOOL, {a, b, "--op", "union", "--cells", "40", "--quiet"});
  EXPECT_EQ(quiet.find('%'), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("csg: "), std::string::npos) << quiet;
  // The contouring and TBISO show theirs too.
  const std::string c =
      run_on_a_terminal(BISO_CONTOUR_TOOL, {std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn"});
  EXPECT_NE(c.find("contour: contouring ["), std::string::npos) << c;
  const std::string t = run_on_a_terminal(BISO_TBISO_TOOL, {"--cells", "24", "--field", "sphere:0,0,0,0.5"});
  EXPECT_NE(t.find("tbiso: extracting the surface ["), std::string::npos) << t;
}

TEST_F(Tool, SequentialAndThreadLimitGiveByteIdenticalFiles)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(0.73, 0.61, 0.52, 2));
  const std::string points = std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn";
  struct Case { const char* tool; std::string arguments; };
  const Case cases[] = {{BISO_CSG_TOOL, a + " " + b + " --op difference --cells 40"},
                        {BISO_CONTOUR_TOOL, points + " --cells 40"},
                        {BISO_TBISO_TOOL, "--cells 24 --field sphere:0,0,0,0.6 --field plane:1,1,0,0.1 --expr "
                                          "\"f0 & !f1\" --close"}};
  for(const Case& c : cases)
  {
    std::vector<std::string> files;
    for(const char* mode : {"", "--sequential", "--threads 2", "--threads 1"})
    {
      const std::string out = m_dir + "/out" + std::to_string(files.size()) + ".off";
      const Result r = run_tool(c.tool, c.arguments + " " + mode + " --quiet -o " + out);
      ASSERT_EQ(r.status, 0) << c.tool << " " << mode << ": " << r.err;
      files.push_back(slurp(out));
    }
    EXPECT_GT(files[0].size(), 1000u) << c.tool;
    for(std::size_t i = 1; i < files.size(); ++i)
      EXPECT_TRUE(files[i] == files[0]) << c.tool << ": run " << i << " differs";
  }
}

// Every mesh-writing tool writes OFF, OBJ, PLY and STL by the extension;
// each reads back (the package's reader) with the faces the tool reports.
TEST_F(Tool, EveryMeshFormatReadsBackWithTheReportedFaces)
{
  const std::string a = write("a.off", box_off(0, 0, 0, 2)), b = write("b.off", box_off(0.73, 0.61, 0.52, 2));
  const std::string points = std::string(BISO_SHARED_DATA_DIR) + "/points/sphere.pwn";
  struct Case { const char* tool; std::string arguments; const char* faces_key; };
  const Case cases[] = {{BISO_CSG_TOOL, a + " " + b + " --op union --cells 20", "faces"},
                        {BISO_CONTOUR_TOOL, points + " --cells 30", "faces"},
                        {BISO_TBISO_TOOL, "--cells 12 --field sphere:0,0,0,0.6 --field box:-0.3,-0.3,-0.3,0.3,0.3,1 "
                                          "--expr \"f0 & !f1\"", "triangles"}};
  for(const Case& c : cases)
    for(const char* format : {"off", "obj", "ply", "stl", "OFF"})
    {
      const std::string out = m_dir + "/out." + format;
      const Result r = run_tool(c.tool, c.arguments + " --json --quiet -o " + out);
      ASSERT_EQ(r.status, 0) << c.tool << " " << format << ": " << r.err;
      std::ofstream(m_dir + "/f.json") << r.out;
      const double faces = member(json_members(m_dir + "/f.json"), c.faces_key);
      ASSERT_GT(faces, 10) << c.tool << " " << format << ": " << r.out;
      CGAL::Boolean_isosurfacing::Triangle_soup_3 soup;
      ASSERT_NO_THROW(soup = CGAL::Boolean_isosurfacing::IO::read_triangle_soup(out)) << c.tool << " " << format;
      EXPECT_EQ(double(soup.triangles.size()), faces) << c.tool << " " << format;
    }
  for(const Case& c : cases)
  {
    const Result r = run_tool(c.tool, c.arguments + " -o " + m_dir + "/out.xyz");
    EXPECT_EQ(r.status, 2) << c.tool << ": " << r.err;
    EXPECT_TRUE(is_one_clean_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("extension"), std::string::npos) << r.err;
  }
}

// File names with quotes, backslashes and control bytes still give valid
// JSON (escaped, and the control bytes shown as \xNN as on stderr).
TEST_F(Tool, JsonEscapesStrangeFileNames)
{
  const std::string name = write("q\"uo\\te\x01.off", tetrahedron_off);
  const Result r = run_tool(BISO_VOLUME_TOOL, "'" + name + "' --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ofstream(m_dir + "/s.json") << r.out;
  const std::string members = json_members(m_dir + "/s.json");
  EXPECT_NE(members.find("inputs=[1]"), std::string::npos) << members << r.out;
  EXPECT_NE(r.out.find("q\\\"uo\\\\te\\\\x01.off"), std::string::npos) << r.out;
}
