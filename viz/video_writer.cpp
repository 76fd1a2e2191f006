#include "viz/video_writer.hpp"

#include <stdexcept>
#include <system_error>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "io/atomic_write.hpp"
#include "io/interrupt.hpp"

namespace scantrace::viz {

void check_frame(const cv::Mat& frame, cv::Size size, const std::string& sink) {
  if (frame.type() != CV_8UC3 || frame.size() != size)
    throw std::logic_error(fmt::format(
        "{}: a frame of {}x{} (OpenCV type {}) was handed to a writer of {}x{} CV_8UC3 frames",
        sink, frame.cols, frame.rows, frame.type(), size.width, size.height));
}

VideoFile::VideoFile(std::filesystem::path path, cv::Size size, double fps)
    : path_(std::move(path)), temp_(temporary_name_keeping_extension(path_)), size_(size) {
  if (size.width % 2 || size.height % 2)
    throw std::invalid_argument(path_.string() + ": video frames must have even sizes, not " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  const std::filesystem::path parent = path_.parent_path();
  std::error_code ec;
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
    throw std::runtime_error(path_.string() + ": cannot write: no directory " + parent.string());
  // The FFmpeg backend only: it is the one that writes MP4 files, and asking the others
  // (GStreamer) first fills stderr with their failures.
  struct Codec {
    const char* fourcc;
    const char* name;
  };
  register_temporary(temp_);
  for (const Codec c : {Codec{"avc1", "h264"}, Codec{"mp4v", "mpeg4"}}) {
    try {
      writer_.open(temp_.string(), cv::CAP_FFMPEG,
                   cv::VideoWriter::fourcc(c.fourcc[0], c.fourcc[1], c.fourcc[2], c.fourcc[3]), fps,
                   size, true);
    } catch (const cv::Exception&) {
      writer_.release();
    }
    if (writer_.isOpened()) {
      codec_ = c.name;
      break;
    }
  }
  if (!writer_.isOpened()) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    unregister_temporary(temp_);
    throw std::runtime_error(path_.string() +
                             ": cannot open a video writer (neither H.264 'avc1' nor MPEG-4 "
                             "'mp4v' through OpenCV's FFmpeg backend; is the directory "
                             "writable?)");
  }
  if (codec_ != "h264")
    spdlog::warn(
        "warning: {}: the H.264 encoder (fourcc avc1) is not available; writing "
        "MPEG-4 part 2 (mp4v) instead",
        path_.string());
}

VideoFile::~VideoFile() {
  if (committed_) return;
  writer_.release();
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
  unregister_temporary(temp_);
}

void VideoFile::write(const cv::Mat& frame, int repeat) {
  check_frame(frame, size_, path_.string());
  for (int i = 0; i < repeat; ++i) writer_.write(frame);
  frames_ += static_cast<std::size_t>(std::max(repeat, 0));
}

void VideoFile::commit() {
  writer_.release();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(temp_, ec);
  if (ec || bytes == 0 || frames_ == 0) {
    std::filesystem::remove(temp_, ec);
    throw std::runtime_error(path_.string() + ": the video writer produced no data" +
                             (frames_ == 0 ? " (no frames)" : " (disk full?)"));
  }
  std::filesystem::rename(temp_, path_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw std::runtime_error(path_.string() + ": cannot write: " + ec.message());
  }
  committed_ = true;
  unregister_temporary(temp_);
}

}  // namespace scantrace::viz
