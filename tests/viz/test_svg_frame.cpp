// The SVG and canvas backends of the display list (issue 32): an SVG frame is a valid,
// self-contained SVG 1.1 document (xmllint, against the elements and attributes of SVG 1.1 the
// backend writes: tests/viz/svg11_subset.dtd); rasterised by headless Chromium it agrees with the
// OpenCV frame of the same display list — same size, every marker and label at the same place
// (the shift that best matches its box is at most 1 px) and the same colours (histograms) — so a
// backend cannot silently drop or move a mark; the canvas JSON holds every operation and mark.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/svg_frame.hpp"
#include "chromium_compare.hpp"

using namespace scantrace;
using namespace scantrace::test::chromium;
namespace fs = std::filesystem;

TEST_CASE("an SVG frame is valid, self-contained SVG 1.1", "[viz][svg]") {
  const trace::Trace t = course_triangle();
  viz::FrameSequence s(t, {}, {1280, 720}, "test");
  const fs::path dir = scratch("valid");
  const std::string dtd = std::string(SCANTRACE_SOURCE_DIR) + "/tests/viz/svg11_subset.dtd";
  for (std::size_t i :
       {std::size_t{0}, std::size_t{3}, s.steps().size() / 2, s.steps().size() - 1}) {
    INFO("step " << i);
    const std::string svg = viz::to_svg(s.frame(i));
    // Self-contained: the only URLs are the namespaces; images are data URIs, glyphs placed from
    // the document's own <defs> (#gN).
    const std::regex url(R"((href|src)\s*=\s*"(?!data:|#g[0-9]+")[^"]*")");
    CHECK_FALSE(std::regex_search(svg, url));
    CHECK(svg.find("http://", svg.find("xmlns:xlink") + 50) == std::string::npos);
    CHECK(svg.find("width=\"1280\" height=\"720\"") != std::string::npos);
    const fs::path file = dir / fmt::format("frame_{}.svg", i);
    write(file, svg);
    if (!have("xmllint")) {
      WARN("skipped: xmllint is not installed (scripts/deps.sh installs libxml2-utils)");
      continue;
    }
    CHECK(
        std::system(fmt::format("xmllint --noout --nonet --dtdvalid '{}' '{}'", dtd, file.string())
                        .c_str()) == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("the canvas JSON holds every operation and mark of the frame", "[viz][svg][json]") {
  const trace::Trace t = course_triangle();
  viz::FrameSequence s(t, {}, {1280, 720}, "test");
  for (std::size_t i = 0; i < s.steps().size(); i += 7) {
    INFO("step " << i);
    const viz::Frame f = s.frame(i);
    const nlohmann::json j = nlohmann::json::parse(viz::to_json(f));
    CHECK(j["w"] == 1280);
    CHECK(j["h"] == 720);
    REQUIRE(j["ops"].size() == f.ops().size());
    std::size_t marks = 0;
    for (std::size_t k = 0; k < f.ops().size(); ++k) {
      const nlohmann::json& op = j["ops"][k];
      const viz::DrawOp& d = f.ops()[k];
      const auto* block = std::get_if<viz::PixelsOp>(&d.body);
      const char kind = block && block->area.area() == 1 ? 'R' : "RLCTP"[d.body.index()];
      CHECK(op[0].get<std::string>() == std::string(1, kind));
      CHECK(op[1].is_null() == !d.clip.has_value());
      if (d.mark) {
        ++marks;
        CHECK(op[2]["kind"] == viz::to_string(d.mark->kind));
        CHECK(op[2]["what"] == d.mark->what);
        CHECK(op[2]["box"] == nlohmann::json::array({d.mark->box.x, d.mark->box.y,
                                                     d.mark->box.width, d.mark->box.height}));
      }
    }
    CHECK(marks == f.marks().size());
  }
  CHECK(std::string(viz::frame_canvas_script()).find("function drawScantraceFrame(ctx, frame)") !=
        std::string::npos);
}

TEST_CASE("the canvas JSON's glyph table places the strokes the text op holds",
          "[viz][svg][json]") {
  // The same frame with its text as strokes ("T") and as glyphs placed from the frame's table
  // ("G"): every "G" op, each glyph's strokes moved to its origin, gives the "T" op's strokes
  // (both written to 1/100 px: a sum of two such numbers is within 0.01), and the table holds each
  // glyph once, however often the text repeats it.
  const trace::Trace t = course_triangle();
  viz::FrameSequence s(t, {}, {1280, 720}, "test");
  const viz::Frame f = s.frame(s.steps().size() / 2);
  const nlohmann::json strokes = nlohmann::json::parse(viz::to_json(f));
  const nlohmann::json table = nlohmann::json::parse(viz::to_json(f, viz::TextForm::glyph_table));
  REQUIRE(table["ops"].size() == strokes["ops"].size());
  CHECK_FALSE(strokes.contains("glyphs"));
  std::size_t texts = 0, placed = 0, points = 0;
  double worst = 0;
  for (std::size_t k = 0; k < strokes["ops"].size(); ++k) {
    const nlohmann::json& a = strokes["ops"][k];
    const nlohmann::json& b = table["ops"][k];
    if (a[0] != "T") {
      CHECK(a == b);
      continue;
    }
    ++texts;
    REQUIRE(b[0] == "G");
    CHECK(b[3] == a[3]);  // the text, colour and thickness
    CHECK(b[4] == a[4]);
    CHECK(b[5] == a[5]);
    std::vector<double> expanded;
    for (std::size_t g = 0; g + 2 < b[6].size(); g += 3) {
      ++placed;
      const double x = b[6][g + 1], y = b[6][g + 2];
      for (const auto& stroke : table["glyphs"].at(b[6][g].get<std::size_t>()))
        for (std::size_t i = 0; i + 1 < stroke.size(); i += 2) {
          expanded.push_back(x + stroke[i].get<double>());
          expanded.push_back(y + stroke[i + 1].get<double>());
        }
    }
    std::vector<double> want;
    for (const auto& stroke : a[6])
      for (const auto& v : stroke) want.push_back(v.get<double>());
    REQUIRE(expanded.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) worst = std::max(worst, std::abs(expanded[i] - want[i]));
    points += want.size() / 2;
  }
  INFO(texts << " text ops, " << placed << " glyphs placed, " << points << " stroke points");
  CHECK(texts > 20);
  CHECK(worst <= 0.0100001);
  CHECK(table["glyphs"].size() < placed / 3);  // each glyph once: far fewer than placed
  CHECK(viz::to_json(f, viz::TextForm::glyph_table).size() * 3 < viz::to_json(f).size());
}

TEST_CASE("Chromium draws an SVG frame as OpenCV draws its raster", "[viz][svg][chromium]") {
  if (!have("chromium")) {
    WARN("skipped: chromium is not installed (scripts/deps.sh installs it)");
    return;
  }
  const trace::Trace t = course_triangle();
  viz::FrameSequence s(t, {}, {1280, 720}, "test");
  const fs::path dir = scratch("chromium");
  check_pages_against_raster(s, dir, [&](const viz::Frame& f, std::size_t i) {
    const fs::path page = dir / fmt::format("frame_{}.svg", i);
    write(page, viz::to_svg(f));
    return page;
  });
  fs::remove_all(dir);
}
