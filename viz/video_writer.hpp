#pragma once
// An MP4 video through cv::VideoWriter (FFmpeg backend): H.264 (fourcc avc1) when the encoder is
// available, MPEG-4 part 2 (mp4v) otherwise, with a warning.
#include <filesystem>
#include <span>

#include <opencv2/videoio.hpp>

#include "viz/frame_sink.hpp"

namespace scantrace::viz {

// A codec to try: OpenCV's fourcc and the name ffprobe gives its streams.
struct VideoCodec {
  const char* fourcc;
  const char* name;
};

// The codecs tried, in order: H.264, then MPEG-4 part 2.
inline constexpr VideoCodec kVideoCodecs[] = {{"avc1", "h264"}, {"mp4v", "mpeg4"}};

class VideoFile : public FrameSink {
 public:
  // Opens the writer (under a temporary name next to `path`); throws std::runtime_error naming
  // `path` when no codec can be opened. `size` must be even in both directions (4:2:0 video).
  // `codecs` are tried in order; a codec other than the first is written with a warning naming
  // the one that was missing (the tests pass a first codec that cannot exist, to see the
  // fallback where H.264 is installed).
  VideoFile(std::filesystem::path path, cv::Size size, double fps,
            std::span<const VideoCodec> codecs = kVideoCodecs);
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
