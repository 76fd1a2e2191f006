// The SVG and canvas backends of the display list (issue 32): an SVG frame is a valid,
// self-contained SVG 1.1 document (xmllint, against the elements and attributes of SVG 1.1 the
// backend writes: tests/viz/svg11_subset.dtd); rasterised by headless Chromium it agrees with the
// OpenCV frame of the same display list — same size, every marker and label at the same place
// (the shift that best matches its box is at most 1 px) and the same colours (histograms) — so a
// backend cannot silently drop or move a mark; the canvas JSON holds every operation and mark.
#include <catch2/catch.hpp>

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
    // Self-contained: the only URLs are the namespaces; images are data URIs.
    const std::regex url(R"((href|src)\s*=\s*"(?!data:)[^"]*")");
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
