// IO::read_triangle_soup throughput (MB/s of file) for every format, on a
// closed float torus written in code (1.2M triangles by default), and on the
// largest shared meshes.  The file is in the page cache after the first
// read, so this measures parsing, not the disk; `read_whole_file` alone (one
// read() into a fresh buffer) is printed beside it as the copy limit.
//
//   benchmark_mesh_readers [--data=DIR] [--tmp=DIR] [--triangles=N] [--only=FORMAT] [--keep] [google-benchmark flags]
//
// --only=FORMAT writes and reads only the generated files whose name
// contains FORMAT (e.g. binary_STL): for profiling.  --keep leaves the
// generated files in --tmp (for timing the tools on them).

#include "../../test/Boolean_isosurfacing_3/mesh_format_writers.h"

#include <CGAL/Boolean_isosurfacing_3/IO/read_triangle_soup.h>
#include <CGAL/Boolean_isosurfacing_3/IO/write_triangle_soup.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace {

namespace BI = CGAL::Boolean_isosurfacing;

std::size_t file_size(const std::string& path)
{
  struct stat s;
  return ::stat(path.c_str(), &s) == 0 ? std::size_t(s.st_size) : 0;
}

void write_file(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if(!out)
  {
    std::cerr << "benchmark_mesh_readers: cannot write " << path << "\n";
    std::exit(1);
  }
}

void register_file(const std::string& name, const std::string& path)
{
  const std::size_t bytes = file_size(path);
  if(bytes == 0)
    return;
  benchmark::RegisterBenchmark(("read_triangle_soup/" + name).c_str(), [path, bytes](benchmark::State& state) {
    std::size_t triangles = 0;
    for(auto _ : state)
    {
      BI::Triangle_soup_3 soup = BI::IO::read_triangle_soup(path);
      triangles = soup.triangles.size();
      benchmark::DoNotOptimize(soup.points.data());
    }
    state.counters["triangles"] = double(triangles);
    state.counters["MB"] = double(bytes) / 1e6;
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes));
  })->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = BISO_SHARED_DATA_DIR, tmp = "/tmp", only;
  std::uint32_t triangles = 1200000;
  bool keep = false;
  std::vector<char*> rest;
  for(int i = 0; i < argc; ++i)
  {
    if(std::strncmp(argv[i], "--data=", 7) == 0) data = argv[i] + 7;
    else if(std::strncmp(argv[i], "--tmp=", 6) == 0) tmp = argv[i] + 6;
    else if(std::strncmp(argv[i], "--only=", 7) == 0) only = argv[i] + 7;
    else if(std::strcmp(argv[i], "--keep") == 0) keep = true;
    else if(std::strncmp(argv[i], "--triangles=", 12) == 0) triangles = std::uint32_t(std::stoul(argv[i] + 12));
    else rest.push_back(argv[i]);
  }
  int rest_count = int(rest.size());
  benchmark::Initialize(&rest_count, rest.data());

  // n * m * 2 triangles with m = n / 2.
  const std::uint32_t n = std::uint32_t(std::sqrt(double(triangles))), m = std::max<std::uint32_t>(3, n / 2);
  const BI::Triangle_soup_3 torus = biso_test::float_torus(n, m);
  const std::string base = tmp + "/biso_bench_torus_" + std::to_string(torus.triangles.size());
  struct File
  {
    std::string name, path;
    std::function<std::string()> bytes;
  };
  const std::vector<File> all_files = {
      {"binary_STL", base + ".stl", [&] { return biso_test::to_binary_STL(torus); }},
      {"binary_PLY_double", base + "_double.ply", [&] { return BI::IO::triangle_soup_to_binary_PLY(torus); }},
      {"binary_PLY_float_extra", base + "_float_extra.ply",
       [&] { return biso_test::to_binary_PLY<float, std::uint8_t, std::int32_t>(torus, false, "float", "uchar", "int"); }},
      {"ASCII_OFF", base + ".off", [&] { return BI::IO::triangle_soup_to_OFF(torus); }},
      {"OBJ", base + ".obj", [&] { return biso_test::to_OBJ(torus); }},
      {"ASCII_PLY", base + "_ascii.ply", [&] { return biso_test::to_ASCII_PLY(torus); }},
      {"ASCII_STL", base + "_ascii.stl", [&] { return biso_test::to_ASCII_STL(torus); }},
  };
  std::vector<File> files;
  for(const File& f : all_files)
    if(f.name.find(only) != std::string::npos)
    {
      write_file(f.path, f.bytes());
      register_file(f.name + "/torus_" + std::to_string(torus.triangles.size() / 1000) + "K", f.path);
      files.push_back(f);
    }
  // The copy limit: one read() of the first file into a fresh buffer.
  const std::string first = files.empty() ? std::string() : files.front().path;
  const std::size_t first_bytes = file_size(first);
  if(first_bytes != 0)
  benchmark::RegisterBenchmark(("read_whole_file_only/" + files.front().name).c_str(), [first, first_bytes](benchmark::State& state) {
    for(auto _ : state)
    {
      auto buffer = BI::internal::read_whole_file(first);
      benchmark::DoNotOptimize(buffer.data());
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(first_bytes));
  })->Unit(benchmark::kMillisecond)->UseRealTime();
  for(const char* file : {"meshes/armadillo.obj", "meshes/bunny_hoppe.off"})
    if(only.empty())
      register_file(file, data + "/" + file);

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for(const File& f : files)
    if(!keep)
      std::remove(f.path.c_str());
  return 0;
}
