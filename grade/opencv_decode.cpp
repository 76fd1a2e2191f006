#include "grade/opencv_decode.hpp"

#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include "grade/captured_stderr.hpp"
#include "io/input_error.hpp"

namespace scantrace::grade {

void decode_with_opencv(std::string_view bytes, SubmittedImage& out) {
  const std::string& name = out.name;
  const std::vector<unsigned char> buffer(bytes.begin(), bytes.end());
  cv::Mat m;
  // What libjpeg or OpenCV print goes into this one message (captured_stderr.hpp).
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
                     "cannot decode the image (corrupt or unsupported " + out.format + " data)" +
                         (said.empty() ? std::string() : "; the decoder said: " + said));
  if (!said.empty())
    spdlog::warn("warning: {}: the {} decoder said: {}", name, out.format, said);
  out.pixels = RgbImage(m.cols, m.rows);
  for (int y = 0; y < m.rows; ++y) {
    const auto* row = m.ptr<cv::Vec3b>(y);
    for (int x = 0; x < m.cols; ++x)  // OpenCV holds BGR
      out.pixels(x, y) = {row[x][2] / 255.0f, row[x][1] / 255.0f, row[x][0] / 255.0f};
  }
}

}  // namespace scantrace::grade
