#include "viz/step_page.hpp"

#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>

#include "io/atomic_write.hpp"
#include "io/gzip.hpp"
#include "io/interrupt.hpp"
#include "viz/frame_text.hpp"
#include "viz/html_player_page.hpp"
#include "viz/step_label.hpp"
#include "viz/svg_frame.hpp"

namespace scantrace::viz {
namespace {

void replace_once(std::string& text, const std::string& what, const std::string& with) {
  const std::size_t at = text.find(what);
  if (at == std::string::npos) throw std::logic_error("html player page: no " + what);
  text.replace(at, what.size(), with);
}

// Inside the inline script, "</script" would end the element early and "<!--" switch the parser
// into its escaped state (a directory named "c<!--<script>" in the trace's path: 0 steps shown).
// In JSON, <, > and & occur only inside strings, where \u003c is the same character: written so,
// no HTML-significant sequence is left in the data. Bytes that are not UTF-8 (a file name's) are
// replaced rather than thrown on.
std::string script_safe_json(const nlohmann::json& data) {
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
  return json;
}

// The extension a saved frame gets: the MIME subtype without its suffix ("image/svg+xml": svg).
std::string file_extension(const std::string& mime) {
  const std::size_t slash = mime.find('/'), plus = mime.find('+');
  return mime.substr(slash + 1, plus == std::string::npos ? std::string::npos : plus - slash - 1);
}

}  // namespace

std::string base64(const std::vector<unsigned char>& bytes) {
  return frame_text::base64(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

HtmlPlayerResult write_step_page(const StepPlan& plan, Size frame, std::size_t first,
                                 std::size_t last, const EncodeStep& encode,
                                 const std::filesystem::path& out,
                                 const HtmlPlayerOptions& options, Progress* progress) {
  if (first > last || last >= plan.steps.size())
    throw std::invalid_argument(fmt::format("{}: no steps to write", out.string()));
  nlohmann::json frames = nlohmann::json::array(), labels = nlohmann::json::array(),
                 rows = nlohmann::json::array();
  EncodedFrame e;
  const std::size_t count = last - first + 1;
  for (std::size_t i = first; i <= last; ++i) {
    check_interrupt();
    try {
      e = encode(i);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(fmt::format("{}: step {}: {}", out.string(), i + 1, error.what()));
    }
    // A gzipped frame is its bytes alone (the page inflates them, then types them as `mime`).
    frames.push_back(e.gzipped ? base64(e.bytes) : "data:" + e.mime + ";base64," + base64(e.bytes));
    const Step& s = plan.steps[i];
    labels.push_back(step_label(plan, s));
    rows.push_back(s.kind == StepKind::scanlines ? nlohmann::json::array({s.first_row, s.last_row})
                                                 : nlohmann::json());
    if (progress) progress->update(i - first + 1, count);
  }
  const std::string extension = file_extension(e.mime);
  nlohmann::json data;
  data["title"] = "scantrace: " + options.source;
  data["source"] = options.source;
  data["first"] = first + 1;
  data["total"] = plan.steps.size();
  data["width"] = frame.width;
  data["height"] = frame.height;
  data["fps"] = options.fps;
  data["mime"] = e.mime;
  data["gzip"] = e.gzipped;
  data["extension"] = extension;
  data["labels"] = std::move(labels);
  data["rows"] = std::move(rows);
  data["frames"] = std::move(frames);
  std::string page(html_player_page());
  // The data first: the title placeholder comes before it in the page, so a source named
  // "@DATA@" cannot catch the data.
  replace_once(page, "@DATA@", script_safe_json(data));
  replace_once(page, "@TITLE@", frame_text::xml_escape("scantrace: " + options.source));
  write_file_atomically(out, page);
  if (progress) progress->finish();
  return {count, page.size(), extension};
}

HtmlPlayerResult write_svg_step_page(FrameSequence& sequence, std::size_t first, std::size_t last,
                                     const std::filesystem::path& out,
                                     const HtmlPlayerOptions& options, Progress* progress) {
  // Why gzipped: the SVG frames' text is Hershey strokes (viz/svg_frame.hpp), about 400 KB a
  // frame of the course triangle, which gzip brings to about 110 KB. Why level 6: level 12 made
  // the course triangle's page 9% smaller (6.2 MB against 6.8) in 12 s more, which the demo's
  // first run would wait for.
  constexpr int kLevel = 6;
  const EncodeStep encode = [&](std::size_t i) {
    return EncodedFrame{gzip(to_svg(sequence.frame(i)), kLevel), "image/svg+xml", true};
  };
  return write_step_page(sequence.plan(), sequence.frame_size(), first, last, encode, out, options,
                         progress);
}

}  // namespace scantrace::viz
