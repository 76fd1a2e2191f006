#pragma once
// The measurements of `scantrace bench` and their three outputs: a Markdown report (stdout), a
// CSV with one line per measurement, and a PNG plot of time against error drawn with OpenCV.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace scantrace::bench {

struct Measurement {
  std::string workload;  // "course scene", "small triangles (10 px²)", …
  std::string variant;   // "exact", "float", "double", "halfspace", "opencv", "memset", …
  std::string shading;   // "flat", "gouraud", or "" when it does not apply
  std::string image;     // "8-bit" or "float"
  double seconds = 0;    // median per render
  long long triangles = 0, pixels = 0;
  std::optional<double> wrong_per_million;  // coverage errors per million reference pixels
  std::optional<double> colour_max;         // largest Gouraud channel error
  std::optional<double> vs_opencv;          // seconds / OpenCV flat seconds on the same workload
};

std::string csv(const std::vector<Measurement>& rows);
// The runtime-vs-error plot: one point per (workload, variant, shading) with an error.
void write_plot(const std::vector<Measurement>& rows, const std::filesystem::path& png);

}  // namespace scantrace::bench
