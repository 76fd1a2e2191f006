#pragma once
// The step page (viz/step_page.hpp) of raster frames: each step drawn by the OpenCV backend
// (viz/replayer.hpp) and embedded as lossless WebP.
//
//   viz::Replayer r(trace, {}, {1280, 720}, "triangle.jsonl");
//   viz::write_html_player(r, 0, r.steps().size() - 1, "triangle.html", {});
#include <cstddef>
#include <filesystem>

#include <opencv2/core.hpp>

#include "viz/progress.hpp"
#include "viz/replayer.hpp"
#include "viz/step_page.hpp"

namespace scantrace::viz {

// Writes steps first..last (0-based, inclusive) of `replayer` to `out`, atomically. Throws
// std::runtime_error naming the file when a frame cannot be encoded or the file written.
HtmlPlayerResult write_html_player(Replayer& replayer, std::size_t first, std::size_t last,
                                   const std::filesystem::path& out,
                                   const HtmlPlayerOptions& options, Progress* progress = nullptr);

EncodedFrame encode_page_frame(const cv::Mat& frame);

}  // namespace scantrace::viz
