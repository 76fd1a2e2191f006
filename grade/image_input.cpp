#include "grade/image_input.hpp"

#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/memory_budget.hpp"
#include "io/npy_reader.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {
namespace {

std::uint32_t be32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) << 24 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 8 |
         static_cast<unsigned char>(b[at + 3]);
}
std::uint32_t be16(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) << 8 |
         static_cast<unsigned char>(b[at + 1]);
}
std::int32_t le32(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(b[at + k]);
  return static_cast<std::int32_t>(v);
}

}  // namespace

bool declared_size(std::string_view b, const std::string& name, std::int64_t& width,
                   std::int64_t& height, std::string& format) {
  if (b.size() >= 8 && b.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) {
    format = "png";
    if (b.size() < 24 || b.substr(12, 4) != "IHDR")
      throw InputError(name, "PNG header", "truncated or missing IHDR chunk");
    width = be32(b, 16), height = be32(b, 20);
    // A complete PNG ends with the IEND chunk; a truncated file would otherwise decode partly.
    if (b.size() < 45 || b.substr(b.size() - 8, 4) != "IEND")
      throw InputError(name, "PNG data", "the file is truncated (no IEND chunk at its end)");
    return true;
  }
  if (b.size() >= 2 && b[0] == 'B' && b[1] == 'M') {
    format = "bmp";
    if (b.size() < 26) throw InputError(name, "BMP header", "truncated header");
    width = le32(b, 18), height = le32(b, 22);
    if (height < 0) height = -static_cast<std::int64_t>(height);
    return true;
  }
  if (b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0xFF &&
      static_cast<unsigned char>(b[1]) == 0xD8) {
    format = "jpeg";
    // Walk the marker segments to the first start-of-frame.
    for (std::size_t i = 2; i + 4 <= b.size();) {
      if (static_cast<unsigned char>(b[i]) != 0xFF) break;
      const unsigned marker = static_cast<unsigned char>(b[i + 1]);
      if (marker == 0xFF) {
        ++i;
        continue;
      }
      const std::size_t len = be16(b, i + 2);
      const bool sof =
          marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
      if (sof) {
        if (i + 9 > b.size()) break;
        height = be16(b, i + 5), width = be16(b, i + 7);
        return true;
      }
      if (len < 2) break;
      i += 2 + len;
    }
    throw InputError(name, "JPEG header", "no frame header (truncated or not a JPEG)");
  }
  return false;
}

SubmittedImage decode_image(std::string_view bytes, const std::string& name) {
  SubmittedImage out;
  out.name = name;
  if (bytes.size() >= 6 && bytes.substr(0, 6) == "\x93NUMPY") {
    const NpyImage npy = parse_npy(bytes, name, 4 * static_cast<std::uint64_t>(kMaxCanvasPixels));
    out.format = "npy";
    out.eight_bit = npy.integer;
    out.pixels = RgbImage(npy.width, npy.height);
    const float scale = npy.integer ? 1.0f / 255.0f : 1.0f;
    for (int y = 0; y < npy.height; ++y)
      for (int x = 0; x < npy.width; ++x) {
        const float* v = &npy.values[(static_cast<std::size_t>(y) * npy.width + x) * 3];
        out.pixels(x, y) = {v[0] * scale, v[1] * scale, v[2] * scale};
      }
    return out;
  }
  std::int64_t w = 0, h = 0;
  if (!declared_size(bytes, name, w, h, out.format))
    throw InputError(name, "", "not a PNG, JPEG, BMP or .npy file");
  // Each side first: two 32-bit sides can multiply past 2^63.
  if (w <= 0 || h <= 0 || w > kMaxCanvasPixels || h > kMaxCanvasPixels || w * h > kMaxCanvasPixels)
    throw InputError(name, out.format + " header",
                     "declares " + std::to_string(w) + "x" + std::to_string(h) +
                         " pixels, outside what can be compared (at most 2^28 pixels)");
  // Decoded bytes plus the float copy.
  check_memory(static_cast<std::uint64_t>(w * h) * (3 + 12), "decoding the image", name,
               out.format + " header");
  const std::vector<unsigned char> buffer(bytes.begin(), bytes.end());
  cv::Mat m;
  try {
    m = cv::imdecode(buffer, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    throw InputError(name, "", "cannot decode the image: " + std::string(e.what()));
  }
  if (m.empty() || m.type() != CV_8UC3)
    throw InputError(name, "",
                     "cannot decode the image (corrupt or unsupported " + out.format + " data)");
  out.pixels = RgbImage(m.cols, m.rows);
  for (int y = 0; y < m.rows; ++y) {
    const auto* row = m.ptr<cv::Vec3b>(y);
    for (int x = 0; x < m.cols; ++x)  // OpenCV holds BGR
      out.pixels(x, y) = {row[x][2] / 255.0f, row[x][1] / 255.0f, row[x][0] / 255.0f};
  }
  return out;
}

SubmittedImage read_submitted_image(const std::filesystem::path& file) {
  const std::string bytes = json_input::read_text_file(file);
  return decode_image(bytes, file.string());
}

}  // namespace scantrace::grade
