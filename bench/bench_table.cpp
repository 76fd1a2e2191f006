#include "bench/bench_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/atomic_write.hpp"
#include "src/fill_options.hpp"

namespace scantrace::bench {
namespace {

std::string number(std::optional<double> v, const char* format = "%.6g") {
  if (!v) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

}  // namespace

std::string csv(const std::vector<Measurement>& rows) {
  std::string out =
      "workload,variant,shading,image,median_ms,triangles_per_s,pixels_per_s,"
      "wrong_pixels_per_million,colour_error_max,time_vs_opencv_flat\n";
  for (const Measurement& m : rows) {
    out += quoted(m.workload) + "," + m.variant + "," + m.shading + "," + m.image + "," +
           number(m.seconds * 1e3) + "," + number(m.triangles / m.seconds) + "," +
           number(m.pixels / m.seconds) + "," + number(m.wrong_per_million) + "," +
           number(m.colour_max) + "," + number(m.vs_opencv) + "\n";
  }
  return out;
}

void write_plot(const std::vector<Measurement>& rows, const std::filesystem::path& png) {
  // Two panels, time per triangle (log) across: coverage errors per million reference pixels and
  // the largest Gouraud colour error, both on log scales, with "0" (exact) drawn as its own lane
  // below the scale since a log axis has no zero.
  const int W = 1480, H = 640, panel_w = 640, top = 70, plot_h = 460, lane = 40;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto text = [&](const std::string& s, cv::Point at, double scale = 0.5,
                        cv::Scalar c = cv::Scalar(40, 40, 40)) {
    cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, c, 1, cv::LINE_AA);
  };
  text("scantrace bench: run time against error (medians, same run)", {20, 32}, 0.8);

  double t_min = 1e30, t_max = 0;
  for (const Measurement& m : rows)
    if (m.wrong_per_million && m.triangles > 0) {
      const double ns = 1e9 * m.seconds / m.triangles;
      t_min = std::min(t_min, ns), t_max = std::max(t_max, ns);
    }
  if (t_max == 0) return;
  const double lx0 = std::floor(std::log10(t_min)), lx1 = std::ceil(std::log10(t_max)) + 0.01;
  const std::map<std::string, cv::Scalar> colour{{"exact", {40, 160, 40}},
                                                 {"float", {30, 30, 220}},
                                                 {"double", {220, 120, 30}},
                                                 {"halfspace", {160, 40, 160}},
                                                 {"opencv", {20, 20, 20}}};

  for (int p = 0; p < 2; ++p) {
    const int x0 = 80 + p * (panel_w + 80), y0 = top, y1 = top + plot_h;
    const double ly0 = p == 0 ? -2 : -16, ly1 = p == 0 ? 6 : 0;  // decades of the error axis
    cv::rectangle(img, {x0, y0}, {x0 + panel_w, y1}, cv::Scalar(120, 120, 120));
    cv::rectangle(img, {x0, y1 + 8}, {x0 + panel_w, y1 + 8 + lane}, cv::Scalar(200, 200, 200));
    text(p == 0 ? "coverage errors per million pixels" : "largest Gouraud colour error",
         {x0, y0 - 10}, 0.55);
    text("0 (exact)", {x0 - 75, y1 + 8 + lane / 2 + 5}, 0.4);
    text("time per triangle (ns, log)", {x0 + panel_w / 2 - 100, y1 + lane + 45}, 0.5);
    for (double d = lx0; d <= lx1; d += 1) {
      const int x = x0 + static_cast<int>((d - lx0) / (lx1 - lx0) * panel_w);
      cv::line(img, {x, y0}, {x, y1}, cv::Scalar(230, 230, 230));
      text("1e" + std::to_string(static_cast<int>(d)), {x - 12, y1 + lane + 25}, 0.4);
    }
    for (double d = ly0; d <= ly1; d += (p == 0 ? 1 : 2)) {
      const int y = y1 - static_cast<int>((d - ly0) / (ly1 - ly0) * plot_h);
      cv::line(img, {x0, y}, {x0 + panel_w, y}, cv::Scalar(230, 230, 230));
      text("1e" + std::to_string(static_cast<int>(d)), {x0 - 50, y + 4}, 0.4);
    }
    int slot = 0;
    for (const Measurement& m : rows) {
      const std::optional<double> err = p == 0 ? m.wrong_per_million : m.colour_max;
      if (!err || m.triangles == 0 || (p == 1 && m.shading != to_string(Shading::gouraud)))
        continue;
      const double lx = std::log10(1e9 * m.seconds / m.triangles);
      const int x = x0 + static_cast<int>((lx - lx0) / (lx1 - lx0) * panel_w);
      int y;
      if (*err <= 0) {
        y = y1 + 8 + 8 + (slot++ % 3) * 10;  // the "exact" lane, staggered
      } else {
        const double ly = std::clamp(std::log10(*err), ly0, ly1);
        y = y1 - static_cast<int>((ly - ly0) / (ly1 - ly0) * plot_h);
      }
      const auto c = colour.count(m.variant) ? colour.at(m.variant) : cv::Scalar(128, 128, 128);
      if (m.shading == to_string(Shading::gouraud))
        cv::circle(img, {x, y}, 5, c, cv::FILLED, cv::LINE_AA);
      else
        cv::rectangle(img, {x - 4, y - 4}, {x + 4, y + 4}, c, cv::FILLED);
    }
  }
  int lx = 80;
  for (const auto& [name, c] : colour) {
    cv::circle(img, {lx, H - 18}, 5, c, cv::FILLED, cv::LINE_AA);
    text(name, {lx + 10, H - 13}, 0.5);
    lx += 130;
  }
  text("square: flat, disc: Gouraud; one mark per workload", {lx + 20, H - 13}, 0.5);
  std::vector<unsigned char> bytes;
  cv::imencode(".png", img, bytes);
  write_file_atomically(
      png, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace scantrace::bench
