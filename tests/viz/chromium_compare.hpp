#pragma once
// Helpers of the tests that draw a frame in headless Chromium (its SVG, its canvas page) and
// compare the screenshot with the OpenCV raster of the same display list: same size, every marker
// and label at the same place (the shift that best matches its box is at most 1 px, the mean
// difference there small) and the same colours (histograms).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <spdlog/fmt/fmt.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "trace/trace.hpp"
#include "viz/frame.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/opencv/frame_raster.hpp"
#include "viz_test_support.hpp"

namespace scantrace::test::chromium {

// A triangle of a 512x512 image: big enough for edge tables, scanlines and zoom insets.
inline trace::Trace course_triangle() {
  trace::TriangleInput t;
  t.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  t.width = t.height = 512;
  return test::record(t);
}

// The steps whose frames are compared: the title card, an edge-table step, a scanline step with
// zoom insets, the end card.
inline std::vector<std::size_t> compared_steps(const viz::FrameSequence& s) {
  std::vector<std::size_t> steps{0, 3, 0, s.steps().size() - 1};
  for (std::size_t i = 0; i < s.steps().size(); ++i)
    if (s.steps()[i].kind == viz::StepKind::scanlines) {
      steps[2] = i + 4;
      break;
    }
  return steps;
}

inline bool have(const char* tool) {
  return std::system(fmt::format("command -v {} >/dev/null 2>&1", tool).c_str()) == 0;
}

inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / fmt::format("scantrace-svg-{}-{}", name, getpid());
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

inline void write(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

// Headless Chromium's screenshot of `page` in a window of `size`; empty when it failed. The
// virtual time budget lets a page's asynchronous drawing (the canvas backend loads its pixel
// blocks as images) finish before the shot; it does not slow a static SVG.
inline cv::Mat screenshot(const std::filesystem::path& page, const std::filesystem::path& png,
                          viz::Size size, const std::filesystem::path& profile) {
  const std::string command = fmt::format(
      "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
      "--force-device-scale-factor=1 --virtual-time-budget=10000 --user-data-dir='{}' "
      "--screenshot='{}' --window-size={},{} 'file://{}' >/dev/null 2>&1",
      profile.string(), png.string(), size.width, size.height, page.string());
  if (std::system(command.c_str()) != 0) return {};
  return cv::imread(png.string(), cv::IMREAD_COLOR);
}

// The shift (dx, dy) in [-3, 3]^2 that best matches `box` of `a` in `b`, and the mean absolute
// difference per channel there.
struct Match {
  int dx = 0, dy = 0;
  double mean = 1e9;
};
inline Match best_shift(const cv::Mat& a, const cv::Mat& b, const viz::Rect& box) {
  Match best;
  const cv::Rect r = cv::Rect(box) & cv::Rect(3, 3, a.cols - 6, a.rows - 6);
  if (r.empty()) return {0, 0, 0};
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      cv::Mat diff;
      cv::absdiff(a(r), b(r + cv::Point(dx, dy)), diff);
      const cv::Scalar m = cv::mean(diff);
      const double mean = (m[0] + m[1] + m[2]) / 3;
      if (mean < best.mean - 1e-9 ||
          (std::abs(mean - best.mean) <= 1e-9 &&
           std::abs(dx) + std::abs(dy) < std::abs(best.dx) + std::abs(best.dy)))
        best = {dx, dy, mean};
    }
  return best;
}

// Half the L1 distance of the two images' normalised 16-bin histograms, the worst channel: the
// share of pixels whose channel value moved to another bin.
inline double histogram_distance(const cv::Mat& a, const cv::Mat& b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> ha(16), hb(16);
    for (int y = 0; y < a.rows; ++y)
      for (int x = 0; x < a.cols; ++x) {
        ha[a.at<cv::Vec3b>(y, x)[c] / 16] += 1;
        hb[b.at<cv::Vec3b>(y, x)[c] / 16] += 1;
      }
    double d = 0;
    for (int i = 0; i < 16; ++i) d += std::abs(ha[i] - hb[i]);
    worst = std::max(worst, d / 2 / (double(a.rows) * a.cols));
  }
  return worst;
}

// The checks both backends must pass against OpenCV's raster of frame `f`.
inline void check_same_as_raster(const viz::Frame& f, const cv::Mat& raster, const cv::Mat& shot) {
  CHECK(shot.cols == raster.cols);
  CHECK(shot.rows == raster.rows);
  if (shot.size() != raster.size()) return;
  // Every marker and label of the main view is where OpenCV drew it, within a pixel.
  std::size_t checked = 0;
  for (const viz::Mark& m : f.marks()) {
    if (m.kind != viz::MarkKind::vertex && m.kind != viz::MarkKind::active_point &&
        m.kind != viz::MarkKind::label)
      continue;
    const Match match = best_shift(raster, shot, m.box);
    INFO(viz::to_string(m.kind) << " " << m.what << " at [" << m.box.x << ", " << m.box.y << " "
                                << m.box.width << "x" << m.box.height << "]: shift " << match.dx
                                << "," << match.dy << ", mean difference " << match.mean);
    CHECK(std::abs(match.dx) <= 1);
    CHECK(std::abs(match.dy) <= 1);
    CHECK(match.mean < 24);
    ++checked;
  }
  CHECK(checked >= 3);
  const double h = histogram_distance(raster, shot);
  INFO("histogram distance " << h);
  // Anti-aliasing differs (Skia against OpenCV) along every line and glyph: measured 0.004-0.03
  // on these frames; a dropped block of cells or a missing panel moves far more.
  CHECK(h < 0.05);
}

// Every compared step of `s`: `page` writes the backend's page of the frame into `dir` and
// returns its path; its screenshot must pass check_same_as_raster.
inline void check_pages_against_raster(
    viz::FrameSequence& s, const std::filesystem::path& dir,
    const std::function<std::filesystem::path(const viz::Frame&, std::size_t)>& page) {
  for (const std::size_t i : compared_steps(s)) {
    INFO("step " << i + 1);
    const viz::Frame f = s.frame(i);
    const cv::Mat shot =
        screenshot(page(f, i), dir / fmt::format("shot_{}.png", i), f.size(), dir / "profile");
    REQUIRE(!shot.empty());
    check_same_as_raster(f, viz::rasterize(f), shot);
  }
}

}  // namespace scantrace::test::chromium
