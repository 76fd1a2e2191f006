#include "viz/html_player.hpp"

#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace scantrace::viz {
namespace {

// Why lossless WebP: the frames are flat colours, thin lines and small text, which lossless
// WebP stores in about a third of PNG's bytes (the course triangle: ~45 KB a frame at 1280x720)
// while every digit of the side panel stays exactly as drawn — JPEG's ringing blurs it, and a
// test can compare the page's pixels with the replayer's exactly. Every browser since 2020 shows
// WebP.
constexpr int kWebpLossless = 101;  // OpenCV: IMWRITE_WEBP_QUALITY above 100 selects lossless

}  // namespace

EncodedFrame encode_page_frame(const cv::Mat& frame) {
  EncodedFrame e;
  e.mime = "image/webp";
  if (!cv::imencode(".webp", frame, e.bytes, {cv::IMWRITE_WEBP_QUALITY, kWebpLossless}))
    throw std::runtime_error("cannot encode a frame as WebP");
  return e;
}

HtmlPlayerResult write_html_player(Replayer& replayer, std::size_t first, std::size_t last,
                                   const std::filesystem::path& out,
                                   const HtmlPlayerOptions& options, Progress* progress) {
  const cv::Size size = replayer.frame_size();
  return write_step_page(
      replayer.plan(), {size.width, size.height}, first, last,
      [&](std::size_t i) { return encode_page_frame(replayer.frame(i)); }, out, options, progress);
}

}  // namespace scantrace::viz
