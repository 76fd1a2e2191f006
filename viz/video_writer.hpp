#pragma once
// An MP4 video through cv::VideoWriter (FFmpeg backend): H.264 (fourcc avc1) when the encoder is
// available, MPEG-4 part 2 (mp4v) otherwise, with a warning.
#include <filesystem>

#include <opencv2/videoio.hpp>

#include "viz/frame_sink.hpp"

namespace scantrace::viz {

class VideoFile : public FrameSink {
 public:
  // Opens the writer (under a temporary name next to `path`); throws std::runtime_error naming
  // `path` when no codec can be opened. `size` must be even in both directions (4:2:0 video).
  VideoFile(std::filesystem::path path, cv::Size size, double fps);
  ~VideoFile() override;

  void write(const cv::Mat& frame, int repeat) override;
  void commit() override;
  std::size_t frames() const override { return frames_; }
  std::string format() const override { return codec_; }

 private:
  std::filesystem::path path_, temp_;
  cv::Size size_;
  cv::VideoWriter writer_;
  std::string codec_;
  std::size_t frames_ = 0;
  bool committed_ = false;
};

}  // namespace scantrace::viz
