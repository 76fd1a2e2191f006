// Use case: fill general polygons under both winding rules (docs/polygons.md) and save them side by
// side: a self-intersecting pentagram and a square with a square hole whose contours run the same
// way round. Even-odd leaves both centres empty; non-zero fills them (winding number 2 there).
// This is the program that makes docs/polygon_winding.png.
//
//   polygon_winding [OUT.png]
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "src/winding_fill.hpp"
#include "viz/image_file.hpp"
#include "viz/opencv_image.hpp"

namespace {

using namespace scantrace;
using Contours = std::vector<std::vector<Vec2>>;

constexpr int kCell = 240, kLabel = 28;

Contours shifted(const Contours& c, double dx, double dy) {
  Contours out = c;
  for (auto& contour : out)
    for (Vec2& p : contour) p = {p.x + dx, p.y + dy};
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "polygon_winding.png";

  // A pentagram: every second vertex of a regular pentagon, so its edges cross and the centre
  // is wound twice.
  Contours star(1);
  for (int k = 0; k < 5; ++k) {
    const double a = -std::numbers::pi / 2 + k * 4 * std::numbers::pi / 5;
    star[0].push_back({120 + 105 * std::cos(a), 128 + 105 * std::sin(a)});
  }
  const std::vector<Color> star_colours{
      {1, 0, 0}, {0, 0.8, 0}, {0, 0, 1}, {1, 0.8, 0}, {0.8, 0, 0.8}};
  // A square with a square hole, both contours clockwise (on screen, y down).
  const Contours holed{{{25, 25}, {215, 25}, {215, 215}, {25, 215}},
                       {{75, 75}, {165, 75}, {165, 165}, {75, 165}}};
  const std::vector<Color> holed_colours{{1, 0, 0},     {0, 0.8, 0},   {0, 0, 1},   {1, 0.8, 0},
                                         {0, 0.8, 0.8}, {0.8, 0, 0.8}, {1, 0.5, 0}, {0.3, 0.3, 1}};

  RgbImage canvas(2 * kCell, 2 * (kCell + kLabel), Rgb32f{1, 1, 1});
  long long pixels[2][2] = {};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col) {
      FillOptions opt;
      opt.winding_rule = col == 0 ? WindingRule::even_odd : WindingRule::non_zero;
      const Contours c =
          shifted(row == 0 ? star : holed, col * kCell, row * (kCell + kLabel) + kLabel);
      const std::vector<Color>& colours = row == 0 ? star_colours : holed_colours;
      pixels[row][col] =
          fill_polygon_contours(canvas, std::span(c), std::span(colours), opt).pixels;
    }

  cv::Mat bgr = to_bgr8(canvas);
  const char* rows[] = {"pentagram", "square with a hole"};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col) {
      const std::string label = std::string(col == 0 ? "even-odd" : "non-zero") + ": " + rows[row];
      cv::putText(bgr, label, {col * kCell + 8, row * (kCell + kLabel) + 19},
                  cv::FONT_HERSHEY_SIMPLEX, 0.45, {30, 30, 30}, 1, cv::LINE_AA);
    }
  cv::line(bgr, {kCell, 0}, {kCell, bgr.rows}, {180, 180, 180}, 1);
  cv::line(bgr, {0, kCell + kLabel}, {bgr.cols, kCell + kLabel}, {180, 180, 180}, 1);
  write_png(from_bgr8(bgr), out);
  std::printf(
      "pentagram: even-odd %lld pixels, non-zero %lld; square with hole: even-odd %lld, "
      "non-zero %lld -> %s\n",
      pixels[0][0], pixels[0][1], pixels[1][0], pixels[1][1], out);
  // Non-zero fills the centres even-odd leaves empty: strictly more pixels in both rows.
  return pixels[0][1] > pixels[0][0] && pixels[1][1] > pixels[1][0] ? 0 : 1;
}
