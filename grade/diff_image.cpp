#include "grade/diff_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "grade/diff_picture.hpp"
#include "io/atomic_write.hpp"
#include "io/png_writer.hpp"
#include "viz/hershey.hpp"

// diff.png is drawn here without OpenCV (it was cv::putText, cv::rectangle and cv::resize, which
// made `scantrace-diff` load imgcodecs and its ~140 libraries at every start): the legend's text
// is the Hershey font OpenCV uses (viz/hershey.hpp: the same strokes and metrics), drawn as
// antialiased lines one pixel wide; the PNG is io/png_writer's.
namespace scantrace::grade {
namespace {

constexpr int kWindow = 32, kZoom = 8, kPanel = 300;
using Rgb8 = std::array<std::uint8_t, 3>;
constexpr Rgb8 kText{35, 35, 35}, kBlack{0, 0, 0}, kWhite{255, 255, 255};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

// An RGB byte canvas, clipped writes.
struct Canvas {
  int width, height;
  std::vector<Rgb8> px;
  Canvas(int w, int h) : width(w), height(h), px(static_cast<std::size_t>(w) * h, kWhite) {}
  Rgb8& at(int x, int y) { return px[static_cast<std::size_t>(y) * width + x]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  void blend(int x, int y, Rgb8 c, double a) {
    if (!inside(x, y) || a <= 0) return;
    Rgb8& p = at(x, y);
    for (int k = 0; k < 3; ++k)
      p[k] = static_cast<std::uint8_t>(std::lround(p[k] * (1 - a) + c[k] * a));
  }
  void fill(Rect r, Rgb8 c) {
    for (int y = std::max(0, r.y); y < std::min(height, r.y + r.height); ++y)
      for (int x = std::max(0, r.x); x < std::min(width, r.x + r.width); ++x) at(x, y) = c;
  }
  void outline(Rect r, Rgb8 c) {  // one pixel wide, on the rectangle's outermost pixels
    fill({r.x, r.y, r.width, 1}, c);
    fill({r.x, r.y + r.height - 1, r.width, 1}, c);
    fill({r.x, r.y, 1, r.height}, c);
    fill({r.x + r.width - 1, r.y, 1, r.height}, c);
  }
};

double segment_distance(viz::Point2d a, viz::Point2d b, double x, double y) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = std::clamp(len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0.0, 0.0, 1.0);
  return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

// `text` with its baseline starting at (x, y): each pixel takes the text colour with the coverage
// of the nearest stroke (1 on it, 0 a pixel away), so joints are not darkened twice.
void put_text(Canvas& c, const std::string& text, int x, int y, double scale) {
  const auto strokes = viz::hershey_strokes(text, viz::HersheyFont::simplex, scale, {x, y});
  int baseline = 0;
  const viz::Size size = viz::hershey_text_size(text, viz::HersheyFont::simplex, scale, 1, &baseline);
  const Rect box{x - 2, y - size.height - 2, size.width + 4, size.height + baseline + 4};
  std::vector<double> cover(static_cast<std::size_t>(box.width) * box.height, 0.0);
  for (const auto& line : strokes)
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const auto [x0, x1] = std::minmax(line[i].x, line[i + 1].x);
      const auto [y0, y1] = std::minmax(line[i].y, line[i + 1].y);
      for (int py = std::max(box.y, static_cast<int>(std::floor(y0)) - 1);
           py <= std::min(box.y + box.height - 1, static_cast<int>(std::ceil(y1)) + 1); ++py)
        for (int px = std::max(box.x, static_cast<int>(std::floor(x0)) - 1);
             px <= std::min(box.x + box.width - 1, static_cast<int>(std::ceil(x1)) + 1); ++px) {
          double& a = cover[static_cast<std::size_t>(py - box.y) * box.width + (px - box.x)];
          a = std::max(a, 1.0 - segment_distance(line[i], line[i + 1], px, py));
        }
    }
  for (int py = 0; py < box.height; ++py)
    for (int px = 0; px < box.width; ++px)
      c.blend(box.x + px, box.y + py, kText, cover[static_cast<std::size_t>(py) * box.width + px]);
}

// The 32×32 window holding the most differing pixels, on a grid of half-window steps.
Rect worst_window(const DiffReport& r) {
  const int W = r.width, H = r.height;
  int best_x = 0, best_y = 0, best_n = -1;
  for (int y0 = 0; y0 < std::max(1, H - kWindow + 1); y0 += kWindow / 2)
    for (int x0 = 0; x0 < std::max(1, W - kWindow + 1); x0 += kWindow / 2) {
      int n = 0;
      for (int y = y0; y < std::min(H, y0 + kWindow); ++y)
        for (int x = x0; x < std::min(W, x0 + kWindow); ++x)
          n += r.category_map[static_cast<std::size_t>(y) * W + x] != 0;
      if (n > best_n) best_n = n, best_x = x0, best_y = y0;
    }
  return {best_x, best_y, std::min(kWindow, W - best_x), std::min(kWindow, H - best_y)};
}

// The legend (a swatch and the count of each category) and the worst window magnified, in the
// panel right of the picture.
void draw_panel(Canvas& c, const DiffReport& r, Rect window) {
  const int px0 = r.width + 12;
  put_text(c, fmt::format("{} of {} pixels differ", r.differing_pixels, r.compared_pixels), px0,
           22, 0.5);
  int y = 46;
  for (std::size_t k = 0; k < kCategories.size(); ++k, y += 22) {
    c.fill({px0, y - 12, 14, 14}, kCategoryColours[k]);
    put_text(c, fmt::format("{}  {}", kCategories[k], r.categories.at(kCategories[k])), px0 + 22,
             y, 0.45);
  }
  y += 10;
  put_text(c,
           fmt::format("worst region x {}..{}, y {}..{}", window.x, window.x + window.width - 1,
                       window.y, window.y + window.height - 1),
           px0, y, 0.45);
  // Nearest-neighbour magnification, taken before the window's frame is drawn over the picture.
  const Rect inset{px0, y + 8, window.width * kZoom, window.height * kZoom};
  const bool fits = inset.x + inset.width <= c.width && inset.y + inset.height <= c.height;
  if (fits)
    for (int v = 0; v < inset.height; ++v)
      for (int u = 0; u < inset.width; ++u)
        c.at(inset.x + u, inset.y + v) = c.at(window.x + u / kZoom, window.y + v / kZoom);
  c.outline(window, kBlack);
  if (fits) c.outline(inset, kBlack);
}

}  // namespace

std::string diff_image_png(const DiffReport& r, const std::filesystem::path&) {
  const int W = r.width, H = r.height;
  const int height =
      std::max(H, 40 + 22 * static_cast<int>(kCategories.size()) + 30 + kWindow * kZoom + 40);
  Canvas c(W + kPanel, height);
  const std::vector<std::uint8_t> picture = diff_picture(r);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::uint8_t* p = &picture[3 * (static_cast<std::size_t>(y) * W + x)];
      c.at(x, y) = {p[0], p[1], p[2]};
    }
  draw_panel(c, r, worst_window(r));
  RgbImage out(c.width, c.height);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const Rgb8 p = c.at(x, y);
      out(x, y) = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
    }
  return png::encode(out);
}

void write_diff_image(const DiffReport& r, const std::filesystem::path& file) {
  write_file_atomically(file, diff_image_png(r, file));
}

}  // namespace scantrace::grade
