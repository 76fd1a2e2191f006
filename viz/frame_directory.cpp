#include "viz/frame_directory.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <opencv2/imgcodecs.hpp>

#include "io/atomic_write.hpp"

namespace scantrace::viz {
namespace {

bool is_frame_file(const std::filesystem::path& p) {
  const std::string name = p.filename().string();
  return name.size() == 15 && name.rfind("frame_", 0) == 0 &&
         (name.compare(11, 4, ".png") == 0 || name.compare(11, 4, ".svg") == 0) &&
         name.find_first_not_of("0123456789", 6) == 11;
}

// A directory may be replaced when it is a directory of frames from an earlier run, or empty.
void check_replaceable(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return;
  if (!std::filesystem::is_directory(dir, ec))
    throw std::runtime_error(dir.string() + ": exists and is not a directory");
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (!entry.is_regular_file() || !is_frame_file(entry.path()))
      throw std::runtime_error(fmt::format(
          "{}: the directory exists and holds other files than frame_NNNNN.png (e.g. {}); not "
          "replacing it",
          dir.string(), entry.path().filename().string()));
  if (ec) throw std::runtime_error(dir.string() + ": cannot read directory: " + ec.message());
}

}  // namespace

std::string FrameDirectory::file_name(std::size_t number, const std::string& extension) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%05zu.", number);
  return buf + extension;
}

FrameDirectory::FrameDirectory(std::filesystem::path dir, cv::Size size, std::size_t first_number,
                               std::string extension)
    : dir_(std::move(dir)),
      size_(size),
      first_number_(first_number),
      extension_(std::move(extension)) {
  // "out/" names the directory "out".
  if (!dir_.has_filename()) dir_ = dir_.parent_path();
  if (dir_.empty()) throw std::runtime_error("frame directory: empty path");
  check_replaceable(dir_);
  temp_ = temporary_name_for(dir_);
  std::error_code ec;
  std::filesystem::remove_all(temp_, ec);
  std::filesystem::create_directories(temp_, ec);
  if (ec) throw std::runtime_error(dir_.string() + ": cannot create directory: " + ec.message());
}

FrameDirectory::~FrameDirectory() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(temp_, ignored);
}

void FrameDirectory::write(const cv::Mat& frame, int /*repeat*/) {
  check_frame(frame, size_, dir_.string());
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", frame, png))
    throw std::runtime_error(dir_.string() + ": cannot encode frame " +
                             std::to_string(frames_ + 1) + " as PNG");
  write_document(std::string(png.begin(), png.end()));
}

void FrameDirectory::write_document(const std::string& bytes) {
  const std::filesystem::path file = temp_ / file_name(first_number_ + frames_, extension_);
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
    throw std::runtime_error(dir_.string() + ": cannot write " + file.filename().string() +
                             " (disk full?)");
  ++frames_;
}

void FrameDirectory::commit() {
  // An earlier replay's frames are moved aside first, so that the new directory replaces them in
  // one rename and no mixture of old and new frames is ever visible.
  check_replaceable(dir_);
  std::error_code ec;
  std::filesystem::path old;
  if (std::filesystem::exists(dir_, ec)) {
    old = temporary_name_for(dir_);
    old += ".old";
    std::filesystem::remove_all(old, ec);
    std::filesystem::rename(dir_, old, ec);
    if (ec) throw std::runtime_error(dir_.string() + ": cannot replace: " + ec.message());
  }
  std::filesystem::rename(temp_, dir_, ec);
  if (ec) {
    std::error_code ignored;
    if (!old.empty()) std::filesystem::rename(old, dir_, ignored);
    throw std::runtime_error(dir_.string() + ": cannot write: " + ec.message());
  }
  committed_ = true;
  if (!old.empty()) std::filesystem::remove_all(old, ec);
}

}  // namespace scantrace::viz
