// The frame composer and its SVG and canvas backends without OpenCV (issue 32): this program links
// scantrace_viz_export and scantrace_viz_composer only (tests/CMakeLists.txt), so it builds where
// OpenCV is not; it composes every step of the course triangle's replay, writes it as SVG and
// JSON, and checks that no OpenCV library is even loaded into the process.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "composer/course_triangle.hpp"
#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/svg_frame.hpp"

using namespace scantrace;

TEST_CASE("frames compose and export without OpenCV", "[composer]") {
  const trace::Trace trace = test::course_triangle_trace();
  viz::FrameSequence s(trace, {}, {1280, 720}, "the course triangle");
  REQUIRE(s.steps().size() == 47);
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < s.steps().size(); ++i) {
    const viz::Frame f = s.frame(i);
    vertices += f.marks(viz::MarkKind::vertex).size();
    const std::string svg = viz::to_svg(f);
    CHECK(svg.rfind("<?xml", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(viz::to_json(f).find("\"ops\":[") != std::string::npos);
  }
  CHECK(vertices > 3 * 40);  // the three vertices on (almost) every frame

  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  INFO("mapped: " << text.str().substr(0, 2000));
  CHECK(text.str().find("libopencv") == std::string::npos);
}
