#include "viz/video_writer.hpp"

#include <stdexcept>
#include <system_error>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "io/atomic_write.hpp"
#include "io/interrupt.hpp"

namespace scantrace::viz {
namespace {

// "H.264", "MPEG-4 part 2": the names the warning gives the codecs.
std::string codec_label(const std::string& name) {
  if (name == "h264") return "H.264";
  if (name == "mpeg4") return "MPEG-4 part 2";
  return name;
}

std::string fourcc_of(std::span<const VideoCodec> codecs, const std::string& name) {
  for (const VideoCodec& c : codecs)
    if (name == c.name) return c.fourcc;
  return "?";
}

}  // namespace

void check_frame(const cv::Mat& frame, cv::Size size, const std::string& sink) {
  if (frame.type() != CV_8UC3 || frame.size() != size)
    throw std::logic_error(fmt::format(
        "{}: a frame of {}x{} (OpenCV type {}) was handed to a writer of {}x{} CV_8UC3 frames",
        sink, frame.cols, frame.rows, frame.type(), size.width, size.height));
}

VideoFile::VideoFile(std::filesystem::path path, cv::Size size, double fps,
                     std::span<const VideoCodec> codecs)
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
  register_temporary(temp_);
  for (const VideoCodec& c : codecs) {
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
  if (codec_ != codecs.front().name)
    spdlog::warn(
        "warning: {}: the {} encoder (fourcc {}) is not available; writing {} ({}) instead",
        path_.string(), codec_label(codecs.front().name), codecs.front().fourcc,
        codec_label(codec_), fourcc_of(codecs, codec_));
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
