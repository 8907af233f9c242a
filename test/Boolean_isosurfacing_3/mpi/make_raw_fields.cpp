// make_raw_fields NX NY NZ OUT.f64|OUT.f32: four scalar fields on the grid
// spanning [-1, 1]^3, vertex-major little-endian raw (the --fields layout).
// f0, f1: spheres; f2 = k - NZ/2 and f3 = i + j - (NX + NY) / 2 are integers,
// exactly zero on whole vertex layers and lines: welding across a rank
// boundary then meets faces lying in the shared layer and vertices with
// several vanishing fields (the exact keys' hard cases).
//
// make_raw_fields NX NY NZ OUT demo-spheres: instead, the four spheres of
// `tbiso --demo` (centres on a regular tetrahedron, mirrored into each other
// by coordinate swaps).  Where the exact fields of two of them are equal, the
// sampled values differ by a few units in the last place (the squares are
// summed in another order), and rounding the vertices to double leaves
// polygons of zero area that the welding must remove (internal::weld_chunk).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  // nan-at-end: the last vertex's f0 is NaN (an error only the last rank sees).
  const bool nan_at_end = argc == 6 && std::strcmp(argv[5], "nan-at-end") == 0;
  const bool demo_spheres = argc == 6 && std::strcmp(argv[5], "demo-spheres") == 0;
  if(argc != 5 && !nan_at_end && !demo_spheres)
  {
    std::fprintf(stderr, "usage: make_raw_fields NX NY NZ OUT.f64|OUT.f32 [nan-at-end|demo-spheres]\n");
    return 2;
  }
  const long nx = std::atol(argv[1]), ny = std::atol(argv[2]), nz = std::atol(argv[3]);
  const std::string out = argv[4];
  const bool f32 = out.size() > 4 && out.substr(out.size() - 4) == ".f32";
  if(nx < 2 || ny < 2 || nz < 2)
  {
    std::fprintf(stderr, "make_raw_fields: at least 2 vertices per axis\n");
    return 2;
  }
  std::FILE* file = std::fopen(out.c_str(), "wb");
  if(!file)
  {
    std::fprintf(stderr, "make_raw_fields: cannot write %s\n", out.c_str());
    return 1;
  }
  std::vector<double> row(std::size_t(nx) * 4);
  std::vector<float> row32(row.size());
  for(long k = 0; k < nz; ++k)
    for(long j = 0; j < ny; ++j)
    {
      for(long i = 0; i < nx; ++i)
      {
        const double x = -1 + 2.0 * double(i) / double(nx - 1), y = -1 + 2.0 * double(j) / double(ny - 1),
                     z = -1 + 2.0 * double(k) / double(nz - 1);
        double* v = row.data() + 4 * i;
        if(demo_spheres)
        {
          const double a = 0.45 / std::sqrt(3.0);
          const double c[4][3] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
          for(int f = 0; f < 4; ++f)
            v[f] = std::sqrt((x - c[f][0]) * (x - c[f][0]) + (y - c[f][1]) * (y - c[f][1]) +
                             (z - c[f][2]) * (z - c[f][2])) - 0.62;
          continue;
        }
        v[0] = std::sqrt((x - 0.1) * (x - 0.1) + y * y + (z + 0.05) * (z + 0.05)) - 0.7;
        v[1] = std::sqrt((x + 0.3) * (x + 0.3) + (y - 0.2) * (y - 0.2) + (z - 0.3) * (z - 0.3)) - 0.45;
        v[2] = double(k - nz / 2);
        v[3] = double(i + j - (nx + ny) / 2);
        if(nan_at_end && k == nz - 1 && j == ny - 1 && i == nx - 1)
          v[0] = std::nan("");
      }
      if(f32)
      {
        for(std::size_t t = 0; t < row.size(); ++t)
          row32[t] = float(row[t]);
        std::fwrite(row32.data(), sizeof(float), row32.size(), file); // little-endian hosts only (x86, arm)
      }
      else
        std::fwrite(row.data(), sizeof(double), row.size(), file);
    }
  return std::fclose(file) == 0 ? 0 : 1;
}
