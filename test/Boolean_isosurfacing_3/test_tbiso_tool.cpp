// Runs the `tbiso` command-line tool on analytic fields, field files and the
// shared tetrahedral meshes, and checks what it prints and writes: the files
// are read back with the package's readers and checked independently
// (closedness, volume against exact values or a PMP clip of the input mesh).
// Also tests boolean_isosurface_to_mesh(), which the tool's --smooth uses.

#include <CGAL/Boolean_isosurfacing_3/IO/boolean_isosurface_files.h>
#include <CGAL/Boolean_isosurfacing_3/IO/read_closed_triangle_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface.h>
#include <CGAL/Boolean_isosurfacing_3/boolean_isosurface_to_mesh.h>
#include <CGAL/Boolean_isosurfacing_3/extract_crease_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef BI::Boolean_isosurface_soup<Point> Soup;
typedef CGAL::Surface_mesh<Point> Mesh;

const std::string data_dir = BISO_SHARED_DATA_DIR;
const double pi = 3.14159265358979323846;

struct Result
{
  int status;
  std::string out;
  std::string err;
};

std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

// The number printed after `key`, or NaN when `key` is not printed.
double number_after(const std::string& text, const std::string& key)
{
  const auto at = text.find(key);
  return at == std::string::npos ? std::nan("") : std::atof(text.c_str() + at + key.size());
}

// Every undirected edge in exactly two polygons, traversed in opposite
// directions: the surface bounds a solid.
::testing::AssertionResult is_closed_surface(const Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, std::pair<int, int>> edges; // (forward, backward) uses
  for(const auto& poly : s.polygons)
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
      auto& e = edges[{std::min(a, b), std::max(a, b)}];
      (a < b ? e.first : e.second) += 1;
    }
  for(const auto& [edge, uses] : edges)
    if(uses.first != 1 || uses.second != 1)
      return ::testing::AssertionFailure() << "edge (" << edge.first << ", " << edge.second << ") has "
                                           << uses.first << " + " << uses.second << " polygons";
  return ::testing::AssertionSuccess();
}

// The divergence theorem over the fan triangles, as an independent check of
// the volume the tool prints.
double volume(const Soup& s)
{
  double v = 0;
  for(const auto& poly : s.polygons)
    for(std::size_t k = 1; k + 1 < poly.size(); ++k)
      v += CGAL::determinant(s.points[poly[0]] - CGAL::ORIGIN, s.points[poly[k]] - CGAL::ORIGIN,
                             s.points[poly[k + 1]] - CGAL::ORIGIN) / 6;
  return v;
}

// Lines of numbers; every line must parse completely.
std::vector<std::vector<double>> read_number_lines(const std::string& path)
{
  std::vector<std::vector<double>> lines;
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    std::vector<double> values;
    double x;
    while(words >> x)
      values.push_back(x);
    EXPECT_TRUE(words.eof()) << path << ": cannot parse '" << line << "'";
    lines.push_back(values);
  }
  return lines;
}

class TbisoTool : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "biso_tbiso_tool_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    m_dir = pattern;
  }
  void TearDown() override
  {
    std::error_code ec;
    std::filesystem::remove_all(m_dir, ec);
  }

  std::string file(const std::string& name) const { return m_dir + "/" + name; }
  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream(file(name), std::ios::binary) << content;
    return file(name);
  }

  Result run(const std::string& arguments) const
  {
    const std::string out = file("stdout.txt"), err = file("stderr.txt");
    const std::string command = std::string(BISO_TBISO_TOOL) + " " + arguments + " >" + out + " 2>" + err + " </dev/null";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  }

  Soup read_ply(const std::string& path) const
  {
    Soup soup;
    EXPECT_NO_THROW(BI::IO::read_PLY_with_fields(path, soup)) << path;
    return soup;
  }

  std::string m_dir;
};

// The demo's spheres: a = 0.45 / sqrt(3), radius 0.62.
std::string demo_fields()
{
  const double a = 0.45 / std::sqrt(3.0);
  const double c[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  std::string s;
  char spec[160];
  for(const auto& p : c)
  {
    std::snprintf(spec, sizeof spec, " --field sphere:%.17g,%.17g,%.17g,0.62", p[0], p[1], p[2]);
    s += spec;
  }
  return s + " --expr \"f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3\"";
}

TEST_F(TbisoTool, DemoWritesThreeReadableFiles)
{
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("--demo " + file("demo"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.status, 0) << r.err;
  std::cout << "[ INFO     ] tbiso --demo took " << seconds << " s\n" << r.out;
  EXPECT_LT(seconds, 20.0); // about 1 s alone; generous on a loaded machine
  for(const char* key : {"domain:     grid 128 x 128 x 128", "fields:     4", "(6 terms)", "time fields:",
                         "time extraction:", "welding", "time creases:", "time writing:", "output:", "creases:"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;

  const Soup soup = read_ply(file("demo/tbiso_demo.ply"));
  ASSERT_GT(soup.polygons.size(), 10000u);
  EXPECT_TRUE(is_closed_surface(soup));
  for(int label : soup.face_fields)
    EXPECT_TRUE(label >= 0 && label < 4) << label;
  const double v = volume(soup);
  EXPECT_NEAR(number_after(r.out, "volume "), v, 1e-9 * v) << r.out;
  EXPECT_EQ(number_after(r.out, "output:     "), double(soup.points.size()));

  const auto polylines = read_number_lines(file("demo/tbiso_demo_creases.polylines.txt"));
  EXPECT_GT(polylines.size(), 0u);
  EXPECT_EQ(double(polylines.size()), number_after(r.out, "edges, ")) << r.out;
  for(const auto& line : polylines)
  {
    ASSERT_FALSE(line.empty());
    EXPECT_GE(line[0], 2);
    EXPECT_EQ(line.size(), 1 + 3 * std::size_t(line[0]));
  }
  const auto corners = read_number_lines(file("demo/tbiso_demo_corners.xyz"));
  EXPECT_GT(corners.size(), 0u);
  EXPECT_EQ(double(corners.size()), number_after(r.out, "polylines, ")) << r.out;
  for(const auto& c : corners)
    EXPECT_EQ(c.size(), 3u);
}

// An unwritable output (-o, --creases, --corners) is found before any
// computation: one line on stderr, exit 1, nothing on stdout; a probe does
// not leave a file behind.
TEST_F(TbisoTool, UnwritableOutputIsRefusedBeforeComputing)
{
  const std::string nowhere = file("no/such/dir/x");
  for(const std::string flag : {"-o " + nowhere + ".ply", "--creases " + nowhere + ".txt",
                                "--corners " + nowhere + ".xyz", "-o " + m_dir + "/dir.ply"})
  {
    std::filesystem::create_directory(file("dir.ply"));
    const auto start = std::chrono::steady_clock::now();
    // A good -o besides an unwritable --creases or --corners (-o is given once).
    const std::string ok = flag.rfind("-o ", 0) == 0 ? "" : " -o " + file("ok.ply");
    const Result r = run("--cells 256 --field sphere:0,0,0,0.5 --smooth 50" + ok + " " + flag);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.status, 1) << flag;
    EXPECT_TRUE(r.out.empty()) << flag << "\n" << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.err.find("cannot write") != std::string::npos || r.err.find("is a directory") != std::string::npos)
        << r.err;
    EXPECT_LT(seconds, 5.0) << flag; // the 257^3 extraction itself takes longer than this
    EXPECT_FALSE(std::filesystem::exists(file("ok.ply"))) << flag;
  }
}

// The box [-0.5, 2] x [-0.25, 2] x [-0.75, 2] cut by the domain [-1, 1]^3:
// its faces inside the domain lie on grid planes (spacing 0.25), so sampling
// is exact and so is the volume, 1.5 * 1.25 * 1.75.
TEST_F(TbisoTool, BoxOnGridPlanesHasTheExactVolume)
{
  const Result r = run("--cells 8 --field box:-0.5,-0.25,-0.75,2,2,2 --close -o " + file("box.ply"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 1.5 * 1.25 * 1.75, 1e-9) << r.out;
  const Soup soup = read_ply(file("box.ply"));
  EXPECT_TRUE(is_closed_surface(soup));
  EXPECT_NEAR(volume(soup), 1.5 * 1.25 * 1.75, 1e-9);

  // A box wholly inside the domain is not exact, even with its faces on grid
  // planes: along its edges in the anti-diagonal directions of the Kuhn
  // triangulation some tetrahedra have their four corners on the box surface.
  // The field is identically zero on them, so the regularized set leaves
  // them out and the edges are chamfered (by less than a cell).
  const Result inner = run("--cells 8 --field box:-0.5,-0.25,-0.75,0.75,0.5,0.25");
  ASSERT_EQ(inner.status, 0) << inner.err;
  const double exact = 1.25 * 0.75 * 1;
  EXPECT_LT(number_after(inner.out, "volume "), exact) << inner.out;
  EXPECT_GT(number_after(inner.out, "volume "), 0.75 * exact) << inner.out;
}

TEST_F(TbisoTool, CylinderAndTorusFields)
{
  // A cylinder along y, centre (x, z) = (0.3, -0.2), radius 0.4, closed at y = +-1.
  const Result c = run("--cells 32 --field cylinder:y,0.3,-0.2,0.4 --close -o " + file("c.ply"));
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NEAR(number_after(c.out, "volume "), pi * 0.16 * 2, 0.02 * pi * 0.16 * 2) << c.out;
  const Soup soup = read_ply(file("c.ply"));
  CGAL::Bbox_3 box;
  for(const Point& p : soup.points)
    box += p.bbox();
  EXPECT_DOUBLE_EQ(box.ymin(), -1);
  EXPECT_DOUBLE_EQ(box.ymax(), 1);
  EXPECT_NEAR(box.xmin(), -0.1, 0.01);
  EXPECT_NEAR(box.xmax(), 0.7, 0.01);
  EXPECT_NEAR(box.zmin(), -0.6, 0.01);
  EXPECT_NEAR(box.zmax(), 0.2, 0.01);

  const Result t = run("--cells 40 --field torus:0.6,0.25");
  ASSERT_EQ(t.status, 0) << t.err;
  const double torus = 2 * pi * pi * 0.6 * 0.25 * 0.25;
  EXPECT_NEAR(number_after(t.out, "volume "), torus, 0.03 * torus) << t.out;
}

TEST_F(TbisoTool, FieldFilesTextAndRaw)
{
  // f0 = x - 0.25 on a 5^3 grid (spacing 0.5): linear, so exact.
  std::string text = "1\n";
  std::vector<double> values;
  for(int k = 0; k < 5; ++k)
    for(int j = 0; j < 5; ++j)
      for(int i = 0; i < 5; ++i)
        values.push_back(-1 + 0.5 * i - 0.25);
  for(double v : values)
    text += std::to_string(v) + "\n";
  const Result r = run("--cells 4 --close --fields " + write("f.txt", text));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "volume "), 1.25 * 4, 1e-12) << r.out;

  std::ofstream raw(file("f.f64"), std::ios::binary);
  raw.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(double)));
  raw.close();
  const Result b = run("--cells 4 --close --fields " + file("f.f64") + " --field-count 1");
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_NEAR(number_after(b.out, "volume "), 1.25 * 4, 1e-12) << b.out;
}

// --out-of-core reads a raw file slab by slab and streams a binary PLY: the
// same surface as the in-core run, whatever the slab size.
TEST_F(TbisoTool, OutOfCoreGivesTheInCoreSurface)
{
  const Result in_core = run("--cells 20" + demo_fields() + " --close -o " + file("in_core.ply"));
  ASSERT_EQ(in_core.status, 0) << in_core.err;
  // The same fields as a raw float64 file (the tool samples in double).
  const double a = 0.45 / std::sqrt(3.0);
  const double c[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  std::vector<double> values;
  for(int k = 0; k < 21; ++k)
    for(int j = 0; j < 21; ++j)
      for(int i = 0; i < 21; ++i)
      {
        const double p[3] = {-1 + 0.1 * i, -1 + 0.1 * j, -1 + 0.1 * k};
        for(const auto& q : c)
          values.push_back(std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                     (p[2] - q[2]) * (p[2] - q[2])) - 0.62);
      }
  std::ofstream raw(file("f.f64"), std::ios::binary);
  raw.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(double)));
  raw.close();
  const std::string expression = " --expr \"f0&f1 | f0&f2 | f0&f3 | f1&f2 | f1&f3 | f2&f3\" --close";
  const Result from_file = run("--cells 20 --fields " + file("f.f64") + " --field-count 4" + expression +
                               " -o " + file("from_file.ply"));
  ASSERT_EQ(from_file.status, 0) << from_file.err;
  const Soup reference = read_ply(file("from_file.ply"));
  EXPECT_GT(reference.polygons.size(), 100u);
  for(const char* slab : {"1", "3", "8"})
  {
    const Result r = run("--cells 20 --fields " + file("f.f64") + " --field-count 4" + expression +
                         " --out-of-core --slab-size " + slab + " -o " + file("ooc.ply"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("peak resident"), std::string::npos) << r.out;
    const Soup streamed = read_ply(file("ooc.ply"));
    EXPECT_EQ(streamed.polygons.size(), reference.polygons.size()) << slab;
    EXPECT_EQ(streamed.points.size(), reference.points.size()) << slab;
    // Same points and polygons up to the numbering, which depends on the slab size.
    std::multiset<std::vector<Point>> a, b;
    for(const auto& poly : reference.polygons)
    {
      std::vector<Point> q;
      for(std::size_t v : poly)
        q.push_back(reference.points[v]);
      std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
      a.insert(q);
    }
    for(const auto& poly : streamed.polygons)
    {
      std::vector<Point> q;
      for(std::size_t v : poly)
        q.push_back(streamed.points[v]);
      std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
      b.insert(q);
    }
    EXPECT_TRUE(a == b) << "slab size " << slab;
  }
  // Analytic fields out of core: evaluated slab by slab, the in-core surface.
  {
    // demo_fields() has the expression: only --close added (an option is given once).
    const Result r = run("--cells 20" + demo_fields() + " --close --out-of-core -o " + file("ooc_analytic.ply"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("evaluated slab by slab"), std::string::npos) << r.out;
    const Soup streamed = read_ply(file("ooc_analytic.ply"));
    const Soup in_core_soup = read_ply(file("in_core.ply"));
    ASSERT_GT(in_core_soup.polygons.size(), 100u);
    auto shapes = [](const Soup& soup) {
      std::multiset<std::vector<Point>> set;
      for(const auto& poly : soup.polygons)
      {
        std::vector<Point> q;
        for(std::size_t v : poly)
          q.push_back(soup.points[v]);
        std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
        set.insert(q);
      }
      return set;
    };
    EXPECT_EQ(streamed.points.size(), in_core_soup.points.size());
    EXPECT_TRUE(shapes(streamed) == shapes(in_core_soup));
  }
  // Its own errors: command lines it cannot run, usage errors (exit 2).
  const std::pair<std::string, const char*> errors[] = {
      {"--cells 20 --fields " + file("f.f64") + " --field-count 4" + expression + " --out-of-core -o x.off", "OUT.ply"},
      {"--cells 20 --fields " + file("f.f64") + expression + " --out-of-core -o x.ply", "--field-count"},
      {"--cells 20 --fields " + file("f.f64") + " --field-count 4" + expression + " --out-of-core -o " +
           file("x.ply") + " --creases c.txt", "whole surface"},
      {"--cells 20 --fields " + file("f.f64") + " --field-count 4" + demo_fields() + " --close --out-of-core -o " +
           file("x.ply"), "not both"},
      {"--cells 20" + demo_fields() + " --field-count 4 --close --out-of-core -o " + file("x.ply"),
       "--field-count is for"},
      {"--cells 20 --fields " + file("f.f64") + " --field-count 4 --slab-size 0" + expression, "at least 1"}};
  for(const auto& e : errors)
  {
    const Result r = run(e.first);
    EXPECT_EQ(r.status, 2) << e.first;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(e.second), std::string::npos) << e.first << "\n" << r.err;
  }
}

TEST_F(TbisoTool, OctopusMeshSphereAndPlane)
{
  const Result r = run("--mesh " + data_dir + "/tet/octopus-low.mesh --field sphere:0.05,0,0.1,0.3 "
                       "--field plane:1,0.2,0,-0.02 --expr \"f0 & f1\" --close -o " + file("o.ply") +
                       " --creases " + file("o.txt"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1140 tetrahedra"), std::string::npos) << r.out;
  const Soup soup = read_ply(file("o.ply"));
  ASSERT_GT(soup.polygons.size(), 0u);
  EXPECT_TRUE(is_closed_surface(soup));
  const double v = volume(soup);
  EXPECT_GT(v, 0);
  EXPECT_LT(v, 0.009135547848); // the whole octopus (README)
  EXPECT_NEAR(number_after(r.out, "volume "), v, 1e-9 * v);
  // Faces on the sphere, on the plane and on the mesh boundary.
  std::vector<int> labels(soup.face_fields);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  EXPECT_EQ(labels, (std::vector<int>{-1, 0, 1}));
  EXPECT_GT(read_number_lines(file("o.txt")).size(), 0u);
}

// tet/bunny.mesh tetrahedralizes the bunny's convex hull with the surface of
// meshes/bunny.off as internal faces; the signed distance to that surface
// and a plane y = 0.11 give the part of the bunny below the plane (the
// README's example).  Where the bunny touches its hull, its faces are on the
// domain boundary and f0 vanishes on them: they are f0's faces, not closing
// faces (they were 97 closing faces, and the cut loop was broken into 35
// polylines with 13 corners), so the crease is the one cut loop.
TEST_F(TbisoTool, BunnyBelowAPlaneMatchesAClip)
{
  const std::string bunny = data_dir + "/meshes/bunny.off";
  const Result r = run("--mesh " + data_dir + "/tet/bunny.mesh --field distance:" + bunny +
                       " --field plane:0,1,0,-0.11 --expr \"f0 & f1\" --close -o " + file("b.ply"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Soup soup = read_ply(file("b.ply"));
  EXPECT_TRUE(is_closed_surface(soup));
  EXPECT_NE(r.out.find("1 polylines, 0 corners"), std::string::npos) << r.out;
  EXPECT_EQ(std::set<int>(soup.face_fields.begin(), soup.face_fields.end()), (std::set<int>{0, 1}))
      << "no closing face";
  const double v = volume(soup);
  EXPECT_NEAR(number_after(r.out, "volume "), v, 1e-9 * v);
  EXPECT_GT(v, 0);
  EXPECT_LT(v, 0.000754); // the whole bunny (README)

  // Reference: the closed bunny clipped by the same plane (negative side kept).
  Mesh mesh;
  BI::IO::read_closed_triangle_mesh(bunny, mesh);
  ASSERT_TRUE(PMP::clip(mesh, K::Plane_3(0, 1, 0, -0.11), CGAL::parameters::clip_volume(true)));
  const double reference = CGAL::to_double(PMP::volume(mesh));
  ASSERT_GT(reference, 0.0001);
  std::cout << "[ INFO     ] bunny below y = 0.11: tbiso " << v << ", PMP::clip " << reference << " (relative difference "
            << std::abs(v - reference) / reference << ")\n";
  EXPECT_NEAR(v, reference, 0.05 * reference) << "reference (PMP::clip) " << reference;
}

// The README's bunny example: the bunny below the plane y = 0.11, on a grid
// around the bunny.  The set stays inside the domain, so there is no closing
// face, and its crease is the one loop where the plane cuts the bunny.  (On
// the bunny's own tetrahedral mesh the set is ill-posed: f0 is the distance
// to the domain's boundary, of either sign there within rounding, and the set
// reaches the boundary in scattered patches; see the test above.)
TEST_F(TbisoTool, BunnyOnAGridHasOneCutLoop)
{
  const std::string bunny = data_dir + "/meshes/bunny.off";
  const Result r = run("--cells 63,63,63 --box -0.1,0.025,-0.07,0.07,0.195,0.07 --field distance:" + bunny +
                       " --field plane:0,1,0,-0.11 --expr \"f0 & f1\" --close -o " + file("b.ply") + " --creases " +
                       file("b.txt") + " --corners " + file("b.xyz"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 polylines, 0 corners"), std::string::npos) << r.out;
  const Soup soup = read_ply(file("b.ply"));
  EXPECT_TRUE(is_closed_surface(soup));
  std::set<int> labels(soup.face_fields.begin(), soup.face_fields.end());
  EXPECT_EQ(labels, (std::set<int>{0, 1})) << "no closing face";
  const auto polylines = read_number_lines(file("b.txt"));
  ASSERT_EQ(polylines.size(), 1u);
  const std::vector<double>& loop = polylines[0];
  ASSERT_GE(loop.size(), 1 + 3 * 20u);
  for(std::size_t k = 1; k < loop.size(); k += 3)
    EXPECT_NEAR(loop[k + 1], 0.11, 1e-12) << "the loop lies on the cut plane";
  EXPECT_EQ(std::vector<double>(loop.begin() + 1, loop.begin() + 4), std::vector<double>(loop.end() - 3, loop.end()))
      << "closed";
  Mesh mesh;
  BI::IO::read_closed_triangle_mesh(bunny, mesh);
  ASSERT_TRUE(PMP::clip(mesh, K::Plane_3(0, 1, 0, -0.11), CGAL::parameters::clip_volume(true)));
  const double reference = CGAL::to_double(PMP::volume(mesh)), v = volume(soup);
  std::cout << "[ INFO     ] bunny below y = 0.11 on a 64^3 grid: tbiso " << v << ", PMP::clip " << reference << "\n";
  EXPECT_NEAR(v, reference, 0.03 * reference);
}

// With --close, the domain's own edges and corners are creases and corners:
// the whole box (a sphere containing it) has 8 corners and 12 polylines.  A
// sphere of radius 1.5 clipped by [-1, 1]^3 keeps 12 pieces of box edges; after
// smoothing, the corners have not moved and the closing faces are still flat
// on their box faces, so they still meet at 90 degrees.
TEST_F(TbisoTool, ClosedBoxKeepsItsEdgesAndCornersWhenSmoothed)
{
  const Result box = run("--cells 8 --field sphere:0,0,0,10 --close");
  ASSERT_EQ(box.status, 0) << box.err;
  EXPECT_NE(box.out.find("creases:    96 edges, 12 polylines, 8 corners"), std::string::npos) << box.out;

  const std::string common = "--cells 32 --field sphere:0,0,0,1.5 --close";
  const Result plain = run(common + " -o " + file("p.ply") + " --corners " + file("p.xyz"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  const Result smooth = run(common + " --smooth 10 -o " + file("s.ply") + " --corners " + file("s.xyz"));
  ASSERT_EQ(smooth.status, 0) << smooth.err;
  // Where the sphere crosses the 12 box edges: 24 corners.
  EXPECT_EQ(count_lines(slurp(file("p.xyz"))), 24) << plain.out;
  EXPECT_EQ(slurp(file("s.xyz")), slurp(file("p.xyz")));
  const Soup a = read_ply(file("p.ply")), b = read_ply(file("s.ply"));
  ASSERT_EQ(a.polygons, b.polygons);
  std::size_t closing = 0, moved = 0;
  for(std::size_t p = 0; p < b.polygons.size(); ++p)
  {
    if(b.face_fields[p] != Soup::domain_boundary)
      continue;
    ++closing;
    const auto& poly = b.polygons[p];
    K::Vector_3 n = CGAL::cross_product(b.points[poly[1]] - b.points[poly[0]], b.points[poly[2]] - b.points[poly[0]]);
    n = n / std::sqrt(n.squared_length());
    const double largest = std::max({std::abs(n.x()), std::abs(n.y()), std::abs(n.z())});
    EXPECT_GT(largest, 1 - 1e-9) << "closing face " << p << " is no longer on a box face: normal " << n;
    for(std::size_t v : poly)
      moved += a.points[v] != b.points[v];
  }
  EXPECT_GT(closing, 100u);
  EXPECT_GT(moved, 0u) << "the closing faces' inner vertices are smoothed within their plane";
  EXPECT_TRUE(is_closed_surface(b));
}

TEST_F(TbisoTool, SmoothingKeepsCornersFixed)
{
  const std::string common = "--cells 32" + demo_fields();
  const Result plain = run(common + " -o " + file("p.ply") + " --corners " + file("p.xyz"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  const Result smooth = run(common + " --smooth 5 -o " + file("s.ply") + " --corners " + file("s.xyz"));
  ASSERT_EQ(smooth.status, 0) << smooth.err;
  EXPECT_NE(smooth.out.find("time smoothing:"), std::string::npos) << smooth.out;

  const std::string corners = slurp(file("p.xyz"));
  EXPECT_GT(count_lines(corners), 0);
  EXPECT_EQ(slurp(file("s.xyz")), corners); // the same doubles, digit for digit

  // Same polygons and labels; vertices moved.
  const Soup a = read_ply(file("p.ply")), b = read_ply(file("s.ply"));
  EXPECT_EQ(a.polygons, b.polygons);
  EXPECT_EQ(a.face_fields, b.face_fields);
  ASSERT_EQ(a.points.size(), b.points.size());
  std::size_t moved = 0;
  for(std::size_t i = 0; i < a.points.size(); ++i)
    moved += a.points[i] != b.points[i];
  EXPECT_GT(moved, a.points.size() / 2);
  EXPECT_TRUE(is_closed_surface(b));
}

TEST_F(TbisoTool, SmoothingANonManifoldSurfaceFails)
{
  // XOR of two overlapping balls: four sheets meet along the circle where
  // the spheres cross.
  const Result r = run("--cells 16 --field sphere:0.2,0,0,0.5 --field sphere:-0.2,0,0,0.5 "
                       "--expr \"f0 & !f1 | !f0 & f1\" --smooth --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("non-manifold"), std::string::npos) << r.err;
  // Without smoothing it is written as a soup.
  const Result soup = run("--cells 16 --field sphere:0.2,0,0,0.5 --field sphere:-0.2,0,0,0.5 "
                          "--expr \"f0 & !f1 | !f0 & f1\" -o " + file("x.ply"));
  EXPECT_EQ(soup.status, 0) << soup.err;
  EXPECT_NE(soup.out.find("non-manifold edges"), std::string::npos) << soup.out;
}

TEST_F(TbisoTool, ParallelSequentialAndThreadLimitGiveTheSameFile)
{
  const std::string common = "--cells 24" + demo_fields() + " --close";
  ASSERT_EQ(run(common + " -o " + file("par.ply")).status, 0);
  ASSERT_EQ(run(common + " --sequential -o " + file("seq.ply")).status, 0);
  ASSERT_EQ(run(common + " --threads 1 -o " + file("one.ply")).status, 0);
  const std::string par = slurp(file("par.ply"));
  EXPECT_GT(par.size(), 1000u);
  EXPECT_EQ(slurp(file("seq.ply")), par);
  EXPECT_EQ(slurp(file("one.ply")), par);
}

// A grid too large for memory is refused before anything is allocated, with
// the estimate: 5000^3 vertices x 4 fields x 8 bytes = 4000 GB.
TEST_F(TbisoTool, GridTooLargeForMemoryIsRefusedWithTheEstimate)
{
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("--cells 4999" + demo_fields());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("tbiso: error: --cells: 5000 x 5000 x 5000 vertices x 4 fields need at least 4000.0 GB", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("available"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 5.0) << "refused before sampling";
  // Anisotropic grids and out of core: the slabs in flight are what counts.
  const Result flat = run("--cells 99999,99999,1" + demo_fields());
  EXPECT_EQ(flat.status, 1);
  EXPECT_NE(flat.err.find("need at least 640.0 GB"), std::string::npos) << flat.err;
  const Result ooc = run("--cells 399999,399999,39 --fields " + file("f.f64") + " --field-count 1 --out-of-core -o " +
                         file("o.ply"));
  EXPECT_EQ(ooc.status, 1);
  EXPECT_NE(ooc.err.find("out of core"), std::string::npos) << ooc.err;
}

TEST_F(TbisoTool, HelpAndOffOutput)
{
  const Result help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("usage: tbiso"), std::string::npos) << help.out;
  EXPECT_EQ(help.err, "");
  EXPECT_EQ(run("-h").out, help.out);
  const Result off = run("--cells 8 --field sphere:0,0,0,0.5 -o " + file("s.OFF"));
  EXPECT_EQ(off.status, 0) << off.err;
  EXPECT_EQ(slurp(file("s.OFF")).substr(0, 4), "OFF\n");
}

// Every error: one line "tbiso: error: ..." naming the problem; exit status 2
// for a bad command line, 1 for a bad file or a failed computation.
TEST_F(TbisoTool, ErrorsGiveOneLineAndTheRightExitCode)
{
  const std::string sphere = " --field sphere:0,0,0,0.5";
  const std::string nan_fields = write("nan.txt", "1\n0\n1\nnan\n-1\n0\n1\n2\n3\n");
  const std::string short_fields = write("short.txt", "1\n0\n1\n");
  const std::string non_conforming =
      write("nc.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n6\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                       "0 0 -1 0\n0.2 0.2 1 0\nTetrahedra\n3\n1 2 3 4 0\n1 2 3 5 0\n1 2 3 6 0\nEnd\n");
  const std::string open_mesh = write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  struct Case { std::string arguments; int status; const char* expected; };
  const Case cases[] = {
      {"", 2, "nothing to do"},
      {"--cells 8 --frobnicate" + sphere, 2, "unknown option"},
      {"--cells 8" + sphere + " --expr", 2, "needs a value"},
      {"--cells 8x" + sphere, 2, "not a number"},
      {"--cells 8.5" + sphere, 2, "not a whole number"},
      {"--cells 8 --cells 9" + sphere, 2, "more than once"},
      {"--cells 8 --spacing 0.1" + sphere, 2, "only one"},
      {"--cells 8,8" + sphere, 2, "NX,NY,NZ"},
      {"--cells 0" + sphere, 2, "at least 1"},
      {"--cells 8 --field sphere:0,0,0,abc", 2, "not a finite number"},
      {"--cells 8 --field sphere:0,0,0", 2, "expected 4"},
      {"--cells 8 --box 1,1,1,0,0,0" + sphere, 2, "minimum"},
      {"--cells 8 --field cone:1,2", 2, "unknown kind"},
      {"--cells 8", 2, "no fields"},
      {"--field-count 1" + sphere, 2, "no domain"},
      {"--cells 8 --mesh x.mesh" + sphere, 2, "not both"},
      {"--cells 8 --fields " + short_fields + sphere, 2, "not both"},
      {"--cells 1 --fields " + short_fields, 1, "2 vertices"},
      {"--cells 1 --fields " + nan_fields, 1, "non-finite"},
      {"--cells 1 --fields " + file("missing.txt"), 1, "cannot open"},
      {"--cells 1 --fields " + file("missing.f64") + " --field-count 1", 1, "cannot open"},
      {"--cells 8" + sphere + " --field plane:1,0,0,0", 2, "--expr is required"},
      {"--cells 8" + sphere + " --field plane:1,0,0,0 --expr \"f0 & f3\"", 2, "f3"},
      {"--cells 8" + sphere + " --expr \"f0 & (f1\"", 2, "column"},
      {"--cells 8" + sphere + " --expr \"f0 + f1\"", 2, "column"},
      {"--mesh " + non_conforming + sphere, 1, "not conforming"},
      {"--mesh " + file("missing.mesh") + sphere, 1, "cannot open"},
      {"--mesh " + file("x.vtk") + sphere, 1, "unknown tetrahedral mesh format"},
      {"--cells 8 --field distance:" + file("missing.off"), 1, "cannot open"},
      {"--cells 8 --field distance:" + open_mesh, 1, "not closed"},
      {"--cells 8" + sphere + " -o " + file("out.xyz"), 2, "extension"},
      {"--cells 8" + sphere + " --threads 0", 2, "threads"},
      {"--cells 8" + sphere + " --smooth 2 --lambda 0.5 --mu 0.5", 1, "mu"},
      {"--cells 8" + sphere + " --lambda 0.5", 2, "--smooth"},
      {"--cells 8" + sphere + " -o " + file("no/such/dir/out.ply"), 1, "cannot write"},
      {"--demo " + file("d") + " --cells 8", 2, "--demo"},
  };
  for(const auto& [arguments, status, expected] : cases)
  {
    // --quiet: no progress line of the stages before a run-time error.
    const Result r = run(arguments + (status == 1 ? " --quiet" : ""));
    EXPECT_EQ(r.status, status) << arguments << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << arguments << ": " << r.err;
    EXPECT_EQ(r.err.rfind("tbiso: error: ", 0), 0u) << arguments << ": " << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << arguments << ": " << r.err;
  }
}

// ---- boolean_isosurface_to_mesh() ----------------------------------------

typedef std::function<double(const Point&)> Field;

Soup extract(std::size_t n, const std::vector<Field>& fields, const std::string& expression)
{
  const BI::Tetrahedral_grid_3<K> grid = BI::Tetrahedral_grid_3<K>::spanning(Point(-1, -1, -1), Point(1, 1, 1), {n, n, n});
  Soup soup;
  BI::extract_boolean_isosurface(grid, BI::sample_fields(grid, fields), BI::Boolean_expression::parse(expression), soup,
                                 BI::parameters::close_at_domain_boundary(true));
  return soup;
}

Field sphere(double cx, double cy, double cz, double r)
{
  return [=](const Point& p) {
    return std::sqrt(CGAL::square(p.x() - cx) + CGAL::square(p.y() - cy) + CGAL::square(p.z() - cz)) - r;
  };
}

TEST(BooleanIsosurfaceToMesh, KeepsOrderAndMarksLabelsCreasesCorners)
{
  const Soup soup = extract(17, {sphere(0.2, 0.1, 0, 0.6), sphere(-0.2, 0, 0.1, 0.6), sphere(0, -0.3, 0, 0.5)},
                            "f0 & f1 & f2");
  ASSERT_GT(soup.polygons.size(), 0u);
  const BI::Crease_network creases = BI::extract_crease_network(soup);
  ASSERT_GT(creases.corners.size(), 0u);

  Mesh mesh;
  mesh.add_vertex(Point(5, 5, 5)); // cleared first
  const BI::Boolean_isosurface_mesh_maps<Point> maps = BI::boolean_isosurface_to_mesh(soup, mesh);
  ASSERT_EQ(mesh.number_of_vertices(), soup.points.size());
  ASSERT_EQ(mesh.number_of_faces(), soup.polygons.size());
  EXPECT_TRUE(CGAL::is_closed(mesh));
  for(const Mesh::Vertex_index v : mesh.vertices())
    EXPECT_EQ(mesh.point(v), soup.points[std::size_t(v)]);
  for(const Mesh::Face_index f : mesh.faces())
  {
    std::vector<std::size_t> polygon;
    for(const Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(std::size_t(v));
    const std::vector<std::size_t>& expected = soup.polygons[std::size_t(f)];
    ASSERT_EQ(polygon.size(), expected.size());
    std::rotate(polygon.begin(), std::find(polygon.begin(), polygon.end(), expected[0]), polygon.end());
    EXPECT_EQ(polygon, expected);
    EXPECT_EQ(maps.face_field[f], soup.face_fields[std::size_t(f)]);
  }
  std::size_t crease_edges = 0, corners = 0;
  for(const Mesh::Edge_index e : mesh.edges())
    crease_edges += maps.edge_is_crease[e];
  for(const Mesh::Vertex_index v : mesh.vertices())
    corners += maps.vertex_is_corner[v];
  EXPECT_EQ(crease_edges, creases.number_of_crease_edges);
  EXPECT_EQ(corners, creases.corners.size());
  // The maps are named properties of the mesh.
  const bool has_field = mesh.property_map<Mesh::Face_index, int>("f:field").second;
  const bool has_crease = mesh.property_map<Mesh::Edge_index, bool>("e:crease").second;
  const bool has_corner = mesh.property_map<Mesh::Vertex_index, bool>("v:corner").second;
  EXPECT_TRUE(has_field && has_crease && has_corner);

  // The generic overload (any MutableFaceGraph) builds the same mesh.
  Mesh generic;
  BI::boolean_isosurface_to_mesh<Point, Mesh>(soup, generic);
  EXPECT_EQ(generic.number_of_faces(), mesh.number_of_faces());
  const bool generic_has_field = generic.property_map<Mesh::Face_index, int>("f:field").second;
  EXPECT_FALSE(generic_has_field);
}

TEST(BooleanIsosurfaceToMesh, NonManifoldSurfaceIsRefused)
{
  const Soup soup = extract(17, {sphere(0.2, 0, 0, 0.5), sphere(-0.2, 0, 0, 0.5)}, "f0 & !f1 | !f0 & f1");
  Mesh mesh;
  try
  {
    BI::boolean_isosurface_to_mesh(soup, mesh);
    ADD_FAILURE() << "no exception";
  }
  catch(const BI::Invalid_input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("non-manifold edge"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("soup"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mesh.number_of_faces(), 0u);
}

} // namespace

namespace {

class TbisoLattice : public TbisoTool
{};

// --cells N (cells), --spacing h and the old --grid N+1 (vertices) name the
// same grid on the default box; on a flat box --cells N is along the
// longest side, the other axes in proportion.
TEST_F(TbisoLattice, CellsSpacingAndTheOldGridFlagAgree)
{
  const std::string fields = " --field sphere:0.1,0,0,0.6 --field plane:0,1,1,0.2 --expr \"f0 & !f1\" --quiet";
  ASSERT_EQ(run("--cells 16" + fields + " -o " + file("cells.ply")).status, 0);
  ASSERT_EQ(run("--spacing 0.125" + fields + " -o " + file("spacing.ply")).status, 0);
  ASSERT_EQ(run("--grid 17" + fields + " -o " + file("grid.ply")).status, 0);
  ASSERT_EQ(run("--cells 16,16,16" + fields + " -o " + file("axes.ply")).status, 0);
  const std::string cells = slurp(file("cells.ply"));
  EXPECT_GT(cells.size(), 1000u);
  EXPECT_TRUE(slurp(file("spacing.ply")) == cells);
  EXPECT_TRUE(slurp(file("grid.ply")) == cells);
  EXPECT_TRUE(slurp(file("axes.ply")) == cells);
  const Result flat = run("--cells 20 --box -1,-1,-0.25,1,1,0.25 --field sphere:0,0,0,0.6");
  ASSERT_EQ(flat.status, 0) << flat.err;
  EXPECT_NE(flat.out.find("grid 21 x 21 x 6 vertices"), std::string::npos) << flat.out;
  const Result fine = run("--spacing 0.3 --box -1,-1,-0.25,1,1,0.25 --field sphere:0,0,0,0.6");
  EXPECT_NE(fine.out.find("grid 8 x 8 x 3 vertices"), std::string::npos) << fine.out; // ceil(2/0.3) = 7 cells
  EXPECT_EQ(run("--help").out.find("--grid"), std::string::npos) << "the old flag is hidden";
}

} // namespace
