#pragma once
// A directory of numbered PNG frames, frame_00001.png, frame_00002.png, … — one file per step
// (a still image needs no repeats; `repeat` is ignored). With the extension "svg" it holds the
// SVG documents of the frames instead (write_document), frame_00001.svg, ….
#include <filesystem>
#include <string>

#include "viz/frame_sink.hpp"

namespace scantrace::viz {

class FrameDirectory : public FrameSink {
 public:
  // Writes into a temporary sibling directory of `dir`. Throws std::runtime_error naming `dir`
  // when it exists and holds anything but frames of an earlier replay (which it replaces).
  // Frames are numbered from `first_number`: the step number, so that `--steps 5:12` writes
  // frame_00005.png … frame_00012.png, as the steps are numbered on the frames themselves.
  FrameDirectory(std::filesystem::path dir, cv::Size size, std::size_t first_number = 1,
                 std::string extension = "png");
  ~FrameDirectory() override;

  void write(const cv::Mat& frame, int repeat) override;
  // The next frame's file, already encoded (an SVG document).
  void write_document(const std::string& bytes);
  void commit() override;
  std::size_t frames() const override { return frames_; }
  std::string format() const override { return extension_; }

  // "frame_00042.png" for frame 42 (1-based).
  static std::string file_name(std::size_t number, const std::string& extension = "png");

 private:
  std::filesystem::path dir_, temp_;
  cv::Size size_;
  std::size_t first_number_ = 1;
  std::string extension_;
  std::size_t frames_ = 0;
  bool committed_ = false;
};

}  // namespace scantrace::viz
