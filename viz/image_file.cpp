#include "viz/image_file.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "io/image_size.hpp"
#include "io/input_error.hpp"
#include "io/png_writer.hpp"
#include "viz/opencv_image.hpp"

namespace scantrace {

// One encoder for every PNG scantrace writes, the command's and the libraries' (io/png_writer.hpp):
// the same image gives the same bytes whichever wrote it.
void write_png(const RgbImage& image, const std::filesystem::path& file) {
  png::write(image, file);
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
