// The canvas backend of the display list (issue 32): a self-contained HTML page holding a frame's
// JSON (to_json) and frame_canvas_script(), drawing into a <canvas> of the frame's size, is
// screenshot by headless Chromium and compared with the OpenCV raster of the same display list
// with the SVG backend's criteria (tests/viz/chromium_compare.hpp) — so the JavaScript, which
// nothing else executes, cannot silently drop, move or recolour a mark.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include <spdlog/fmt/fmt.h>
#include <opencv2/core.hpp>

#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "chromium_compare.hpp"

using namespace scantrace;
using namespace scantrace::test::chromium;
namespace fs = std::filesystem;

namespace {

// The page: no margin and no scrollbars, so the canvas's pixel (0, 0) is the screenshot's. The
// JSON is embedded as a JavaScript literal (JSON is one); "</" is escaped so a label holding
// "</script>" cannot end the script element.
std::string canvas_page(const viz::Frame& f, viz::TextForm text) {
  std::string json = viz::to_json(f, text);
  for (std::size_t at = 0; (at = json.find("</", at)) != std::string::npos; at += 3)
    json.replace(at, 2, "<\\/");
  return fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><style>html, body {{ margin: 0; "
      "padding: 0; overflow: hidden; background: #000; }} canvas {{ display: block; }}</style>"
      "</head><body><canvas id=\"c\" width=\"{}\" height=\"{}\"></canvas>\n<script>\n{}\n"
      "const frame = {};\ndrawScantraceFrame(document.getElementById('c').getContext('2d'), "
      "frame);\n</script></body></html>\n",
      f.size().width, f.size().height, viz::frame_canvas_script(), json);
}

}  // namespace

TEST_CASE("Chromium draws a canvas frame as OpenCV draws its raster", "[viz][canvas][chromium]") {
  if (!have("chromium")) {
    WARN("skipped: chromium is not installed (scripts/deps.sh installs it)");
    return;
  }
  const trace::Trace t = course_triangle();
  viz::FrameSequence s(t, {}, {1280, 720}, "test");
  const fs::path dir = scratch("canvas");
  check_pages_against_raster(s, dir, [&](const viz::Frame& f, std::size_t i) {
    const fs::path page = dir / fmt::format("frame_{}.html", i);
    // Text as its glyphs from the frame's table (what the pages draw), and on step 4 (the
    // first step's card) as its strokes ("T", what the Jupyter player's deck expands into).
    write(page, canvas_page(f, i == 3 ? viz::TextForm::strokes : viz::TextForm::glyph_table));
    return page;
  });
  fs::remove_all(dir);
}
