#pragma once
// Where replayed frames go: a video file or a directory of PNG files. Both appear complete or not
// at all: they are written under a temporary name and renamed into place by commit(); a sink
// destroyed without commit (an error, an exception) removes what it wrote.
#include <cstddef>
#include <string>

#include <opencv2/core.hpp>

namespace scantrace::viz {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Adds `frame` (CV_8UC3, BGR, exactly the sink's size: anything else throws std::logic_error —
  // OpenCV's writer would drop it silently) shown for `repeat` frames.
  virtual void write(const cv::Mat& frame, int repeat) = 0;
  virtual void commit() = 0;
  virtual std::size_t frames() const = 0;  // written so far
  virtual std::string format() const = 0;  // "h264", "mpeg4" or "png"
};

// Throws std::logic_error unless `frame` is CV_8UC3 of exactly `size` — the guard every sink
// applies before handing a frame on.
void check_frame(const cv::Mat& frame, cv::Size size, const std::string& sink);

}  // namespace scantrace::viz
