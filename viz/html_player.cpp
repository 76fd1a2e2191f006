#include "viz/html_player.hpp"

#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/atomic_write.hpp"
#include "io/interrupt.hpp"
#include "viz/frame_text.hpp"
#include "viz/html_player_page.hpp"
#include "viz/step_label.hpp"

namespace scantrace::viz {
namespace {

// Why lossless WebP: the frames are flat colours, thin lines and small text, which lossless
// WebP stores in about a third of PNG's bytes (the course triangle: ~45 KB a frame at 1280x720)
// while every digit of the side panel stays exactly as drawn — JPEG's ringing blurs it, and a
// test can compare the page's pixels with the replayer's exactly. Every browser since 2020 shows
// WebP.
constexpr int kWebpLossless = 101;  // OpenCV: IMWRITE_WEBP_QUALITY above 100 selects lossless

void replace_once(std::string& text, const std::string& what, const std::string& with) {
  const std::size_t at = text.find(what);
  if (at == std::string::npos) throw std::logic_error("html player page: no " + what);
  text.replace(at, what.size(), with);
}

}  // namespace

std::string base64(const std::vector<unsigned char>& bytes) {
  return frame_text::base64(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

EncodedFrame encode_page_frame(const cv::Mat& frame) {
  EncodedFrame e;
  e.mime = "image/webp";
  if (!cv::imencode(".webp", frame, e.bytes, {cv::IMWRITE_WEBP_QUALITY, kWebpLossless}))
    throw std::runtime_error("cannot encode a frame as WebP");
  return e;
}

HtmlPlayerResult write_html_player(Replayer& replayer, std::size_t first, std::size_t last,
                                   const std::filesystem::path& out,
                                   const HtmlPlayerOptions& options, Progress* progress) {
  const StepPlan& plan = replayer.plan();
  if (first > last || last >= plan.steps.size())
    throw std::invalid_argument(fmt::format("{}: no steps to write", out.string()));
  nlohmann::json frames = nlohmann::json::array(), labels = nlohmann::json::array(),
                 rows = nlohmann::json::array();
  HtmlPlayerResult result;
  std::string mime;
  const std::size_t count = last - first + 1;
  for (std::size_t i = first; i <= last; ++i) {
    check_interrupt();
    EncodedFrame e;
    try {
      e = encode_page_frame(replayer.frame(i));
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(fmt::format("{}: step {}: {}", out.string(), i + 1, error.what()));
    }
    mime = e.mime;
    frames.push_back("data:" + e.mime + ";base64," + base64(e.bytes));
    const Step& s = plan.steps[i];
    labels.push_back(step_label(plan, s));
    rows.push_back(s.kind == StepKind::scanlines ? nlohmann::json::array({s.first_row, s.last_row})
                                                 : nlohmann::json());
    if (progress) progress->update(i - first + 1, count);
  }
  nlohmann::json data;
  data["title"] = "scantrace: " + options.source;
  data["source"] = options.source;
  data["first"] = first + 1;
  data["total"] = plan.steps.size();
  data["width"] = replayer.frame_size().width;
  data["height"] = replayer.frame_size().height;
  data["fps"] = options.fps;
  data["extension"] = mime.substr(mime.find('/') + 1);
  data["labels"] = std::move(labels);
  data["rows"] = std::move(rows);
  data["frames"] = std::move(frames);
  // Inside the inline script, "</script" would end the element early and "<!--" switch the
  // parser into its escaped state (a directory named "c<!--<script>" in the trace's path: 0 steps
  // shown). In JSON, <, > and & occur only inside strings, where \u003c is the same character:
  // written so, no HTML-significant sequence is left in the data. Bytes that are not UTF-8 (a
  // file name's) are replaced rather than thrown on.
  const std::string dumped = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string json;
  json.reserve(dumped.size());
  for (const char c : dumped) {
    if (c == '<')
      json += "\\u003c";
    else if (c == '>')
      json += "\\u003e";
    else if (c == '&')
      json += "\\u0026";
    else
      json += c;
  }
  std::string page(html_player_page());
  // The data first: the title placeholder comes before it in the page, so a source named
  // "@DATA@" cannot catch the data.
  replace_once(page, "@DATA@", json);
  replace_once(page, "@TITLE@", frame_text::xml_escape("scantrace: " + options.source));
  write_file_atomically(out, page);
  if (progress) progress->finish();
  result.steps = count;
  result.bytes = page.size();
  result.format = data["extension"];
  return result;
}

}  // namespace scantrace::viz
