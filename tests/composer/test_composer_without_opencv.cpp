// The frame composer and its SVG and canvas backends without OpenCV (issue 32): this program links
// scantrace_viz_export and scantrace_viz_composer only (tests/CMakeLists.txt), so it builds where
// OpenCV is not; it composes every step of the course triangle's replay, writes it as SVG and
// JSON, and checks that no OpenCV library is even loaded into the process.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "composer/course_triangle.hpp"
#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/hershey.hpp"
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

// The canvas JSON's "G" ops place glyphs from the frame's "glyphs" table, whose strokes the writer
// keeps from one frame to the next (viz/frame_json.cpp): placed, they must be the text's strokes
// as hershey_strokes draws them (the "T" form, computed without the table), in every frame, for
// each font and scale; and each op keeps its kind, clip and mark in place.
TEST_CASE("a frame's glyph table gives each text's own strokes, frame after frame", "[composer]") {
  struct Text {
    std::string s;
    viz::HersheyFont font;
    double scale;
    viz::Point origin;
  };
  const std::vector<Text> texts{{"Ab 12", viz::HersheyFont::simplex, 0.5, {10, 30}},
                                {"Ab", viz::HersheyFont::simplex, 0.75, {10, 60}},
                                {"bA", viz::HersheyFont::duplex, 0.5, {10, 90}}};
  for (int round = 0; round < 2; ++round) {  // the second frame finds the glyphs already written
    viz::Frame f({200, 120}, viz::Scalar(255, 255, 255));
    viz::FrameView whole(f);
    viz::FrameView area = whole(viz::Rect(5, 6, 150, 100));
    for (const Text& t : texts)
      area.text(t.s, t.origin, t.font, t.scale, viz::Scalar(0, 0, 0), 1, viz::LineType::aa,
                viz::Mark{viz::MarkKind::label, t.s, viz::Rect(1, 2, 3, 4), 0});
    const nlohmann::json j = nlohmann::json::parse(viz::to_json(f, viz::TextForm::glyph_table));
    REQUIRE(j["ops"].size() == texts.size());
    std::size_t points = 0;
    for (std::size_t k = 0; k < texts.size(); ++k) {
      const Text& t = texts[k];
      const nlohmann::json& op = j["ops"][k];
      CHECK(op[0] == "G");
      CHECK(op[1] == nlohmann::json::array({5, 6, 150, 100}));
      CHECK(op[2]["what"] == t.s);
      CHECK(op[3] == t.s);
      // The op's strokes: each placed glyph's table strokes moved to its origin, in order.
      std::vector<viz::Point2d> got;
      const nlohmann::json& placed = op[6];
      for (std::size_t g = 0; g < placed.size(); g += 3)
        for (const nlohmann::json& stroke : j["glyphs"][placed[g].get<std::size_t>()])
          for (std::size_t i = 0; i < stroke.size(); i += 2)
            got.push_back({placed[g + 1].get<double>() + stroke[i].get<double>(),
                           placed[g + 2].get<double>() + stroke[i + 1].get<double>()});
      std::vector<viz::Point2d> want;
      for (const auto& stroke : viz::hershey_strokes(t.s, t.font, t.scale, t.origin))
        want.insert(want.end(), stroke.begin(), stroke.end());
      REQUIRE(got.size() == want.size());
      for (std::size_t i = 0; i < want.size(); ++i) {
        // Two decimals each for the origin and the relative point.
        CHECK(std::abs(got[i].x - want[i].x) <= 0.0101);
        CHECK(std::abs(got[i].y - want[i].y) <= 0.0101);
      }
      points += want.size();
    }
    CHECK(points > 50);
    // "A" and "b" at two scales of simplex and once in duplex, the digits, and the space.
    CHECK(j["glyphs"].size() == 9);
  }
}

// Checkpoints of the canvas state are taken only once a sequence has gone back
// (viz/frame_sequence.cpp): going back before any exists restarts from an empty state. Every
// frame asked for in any order must be the frame asked for in order.
TEST_CASE("a frame sequence gives the same frame in any order", "[composer]") {
  const trace::Trace trace = test::course_triangle_trace();
  viz::StepOptions one_row;
  one_row.rows_per_step = 1;
  viz::FrameSequence in_order(trace, one_row, {640, 360}, "t");
  std::vector<std::string> frames;
  for (std::size_t i = 0; i < in_order.steps().size(); ++i)
    frames.push_back(viz::to_json(in_order.frame(i)));
  REQUIRE(frames.size() > 40);
  viz::FrameSequence any_order(trace, one_row, {640, 360}, "t");
  // Forward, back before the first checkpoint, forward past several, back by one, far back, to
  // the end, to the start.
  for (std::size_t i : std::vector<std::size_t>{20, 3, 33, 32, 31, 9, 17, frames.size() - 1, 0, 16, 15}) {
    INFO("step " << i + 1);
    CHECK(viz::to_json(any_order.frame(i)) == frames[i]);
  }
}
