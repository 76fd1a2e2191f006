#include "grade/image_input.hpp"

#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include "grade/captured_stderr.hpp"
#include "grade/jpeg_header.hpp"
#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/memory_budget.hpp"

namespace scantrace::grade {
namespace {

// An image file's pixels decoded by OpenCV (its header already checked), as RGB floats.
RgbImage opencv_decode(std::string_view bytes, const std::string& name, const std::string& format) {
  const std::vector<unsigned char> buffer(bytes.begin(), bytes.end());
  cv::Mat m;
  // What libpng, libjpeg or OpenCV print goes into this one message (captured_stderr.hpp).
  CapturedStderr messages;
  try {
    m = cv::imdecode(buffer, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    const std::string said = messages.text();
    throw InputError(name, "",
                     "cannot decode the image: " + std::string(e.what()) +
                         (said.empty() ? "" : " (the decoder said: " + said + ")"));
  }
  const std::string said = messages.text();
  if (m.empty() || m.type() != CV_8UC3)
    throw InputError(name, "",
                     "cannot decode the image (corrupt or unsupported " + format + " data)" +
                         (said.empty() ? std::string() : "; the decoder said: " + said));
  if (!said.empty()) spdlog::warn("warning: {}: the {} decoder said: {}", name, format, said);
  RgbImage pixels(m.cols, m.rows);
  for (int y = 0; y < m.rows; ++y) {
    const auto* row = m.ptr<cv::Vec3b>(y);
    for (int x = 0; x < m.cols; ++x)  // OpenCV holds BGR
      pixels(x, y) = {row[x][2] / 255.0f, row[x][1] / 255.0f, row[x][0] / 255.0f};
  }
  return pixels;
}

}  // namespace

bool declared_size(std::string_view b, const std::string& name, std::int64_t& width,
                   std::int64_t& height, std::string& format) {
  if (declared_png_or_bmp_size(b, name, width, height, format)) return true;
  if (b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0xFF &&
      static_cast<unsigned char>(b[1]) == 0xD8) {
    format = "jpeg";
    const JpegHeader header = read_jpeg_header(b);
    if (!header.ok)
      throw InputError(name, "JPEG header", "cannot be read (libjpeg: " + header.problem + ")");
    width = header.width, height = header.height;
    return true;
  }
  return false;
}

SubmittedImage decode_image(std::string_view bytes, const std::string& name) {
  if (is_npy(bytes)) return decode_npy(bytes, name);
  SubmittedImage out;
  out.name = name;
  std::int64_t w = 0, h = 0;
  if (!declared_size(bytes, name, w, h, out.format))
    throw InputError(name, "", "not a PNG, JPEG, BMP or .npy file");
  check_before_decoding(bytes, name, w, h, out.format);
  out.pixels = opencv_decode(bytes, name, out.format);
  return out;
}

SubmittedImage read_submitted_image(const std::filesystem::path& file) {
  return within_memory(file.string(), [&] {
    const std::string bytes = json_input::read_text_file(file);
    return decode_image(bytes, file.string());
  });
}

}  // namespace scantrace::grade
