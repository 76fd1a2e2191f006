#include "grade/diff_image.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "grade/diff_picture.hpp"
#include "io/atomic_write.hpp"

namespace scantrace::grade {
namespace {

constexpr int kWindow = 32, kZoom = 8, kPanel = 300;

}  // namespace

std::string diff_image_png(const DiffReport& r, const std::filesystem::path& file) {
  const int W = r.width, H = r.height;
  const int height =
      std::max(H, 40 + 22 * static_cast<int>(kCategories.size()) + 30 + kWindow * kZoom + 40);
  cv::Mat out(height, W + kPanel, CV_8UC3, cv::Scalar(255, 255, 255));
  const std::vector<std::uint8_t> picture = diff_picture(r);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::uint8_t* p = &picture[3 * (static_cast<std::size_t>(y) * W + x)];
      out.at<cv::Vec3b>(y, x) = {p[2], p[1], p[0]};  // OpenCV holds BGR
    }
  // The worst window: the most differing pixels, on a grid of half-window steps.
  int best_x = 0, best_y = 0, best_n = -1;
  for (int y0 = 0; y0 < std::max(1, H - kWindow + 1); y0 += kWindow / 2)
    for (int x0 = 0; x0 < std::max(1, W - kWindow + 1); x0 += kWindow / 2) {
      int n = 0;
      for (int y = y0; y < std::min(H, y0 + kWindow); ++y)
        for (int x = x0; x < std::min(W, x0 + kWindow); ++x)
          n += r.category_map[static_cast<std::size_t>(y) * W + x] != 0;
      if (n > best_n) best_n = n, best_x = x0, best_y = y0;
    }
  const cv::Rect window(best_x, best_y, std::min(kWindow, W - best_x),
                        std::min(kWindow, H - best_y));
  const cv::Scalar text(35, 35, 35);
  const auto put = [&](const std::string& s, int x, int y, double scale = 0.45) {
    cv::putText(out, s, {x, y}, cv::FONT_HERSHEY_SIMPLEX, scale, text, 1, cv::LINE_AA);
  };
  const int px0 = W + 12;
  put(fmt::format("{} of {} pixels differ", r.differing_pixels, r.compared_pixels), px0, 22, 0.5);
  int y = 46;
  for (std::size_t c = 0; c < kCategories.size(); ++c, y += 22) {
    cv::rectangle(
        out, {px0, y - 12, 14, 14},
        cv::Scalar(kCategoryColours[c][2], kCategoryColours[c][1], kCategoryColours[c][0]),
        cv::FILLED);
    put(fmt::format("{}  {}", kCategories[c], r.categories.at(kCategories[c])), px0 + 22, y);
  }
  y += 10;
  put(fmt::format("worst region x {}..{}, y {}..{}", window.x, window.x + window.width - 1,
                  window.y, window.y + window.height - 1),
      px0, y);
  cv::Mat zoom;
  cv::resize(out(window).clone(), zoom, {}, kZoom, kZoom, cv::INTER_NEAREST);
  cv::rectangle(out, window, cv::Scalar(0, 0, 0), 1);
  const cv::Rect inset(px0, y + 8, zoom.cols, zoom.rows);
  if (inset.x + inset.width <= out.cols && inset.y + inset.height <= out.rows) {
    zoom.copyTo(out(inset));
    cv::rectangle(out, inset, cv::Scalar(0, 0, 0), 1);
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", out, png))
    throw std::runtime_error(file.string() + ": cannot encode PNG");
  return std::string(reinterpret_cast<const char*>(png.data()), png.size());
}

void write_diff_image(const DiffReport& r, const std::filesystem::path& file) {
  write_file_atomically(file, diff_image_png(r, file));
}

}  // namespace scantrace::grade
