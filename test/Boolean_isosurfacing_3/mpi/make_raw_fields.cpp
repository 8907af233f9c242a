// make_raw_fields NX NY NZ OUT.f64|OUT.f32: four scalar fields on the grid
// spanning [-1, 1]^3, vertex-major little-endian raw (the --fields layout).
// f0, f1: spheres; f2 = k - NZ/2 and f3 = i + j - (NX + NY) / 2 are integers,
// exactly zero on whole vertex layers and lines: welding across a rank
// boundary then meets faces lying in the shared layer and vertices with
// several vanishing fields (the exact keys' hard cases).
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
  if(argc != 5 && !nan_at_end)
  {
    std::fprintf(stderr, "usage: make_raw_fields NX NY NZ OUT.f64|OUT.f32 [nan-at-end]\n");
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
