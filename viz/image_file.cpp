#include "viz/image_file.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "io/atomic_write.hpp"
#include "io/image_size.hpp"
#include "io/input_error.hpp"
#include "viz/opencv_image.hpp"

namespace scantrace {

void write_png(const RgbImage& image, const std::filesystem::path& file) {
  if (image.width() <= 0 || image.height() <= 0)
    throw std::runtime_error(file.string() + ": cannot write an empty image");
  // Encode in memory rather than cv::imwrite: imwrite picks the format from the file name, which
  // the temporary name does not end in, and it cannot say why a write failed.
  std::vector<unsigned char> png;
  bool encoded = false;
  try {
    encoded = cv::imencode(".png", to_bgr8(image), png);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(file.string() + ": cannot encode PNG: " + e.what());
  }
  if (!encoded) throw std::runtime_error(file.string() + ": cannot encode PNG");
  write_file_atomically(file,
                        std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

RgbImage read_png(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(file.string(), "", "cannot read image: no such file");
  // The declared size is checked before OpenCV allocates for it: 8-bit BGR for the decoder, then
  // the float RGB image (12 bytes a pixel).
  if (const auto size = read_png_declared_size(file))
    check_image_size(*size, 3 + 12, file.string());
  const cv::Mat bgr = cv::imread(file.string(), cv::IMREAD_COLOR);
  if (bgr.empty()) throw InputError(file.string(), "", "cannot read image: not a decodable image");
  return from_bgr8(bgr);
}

}  // namespace scantrace
