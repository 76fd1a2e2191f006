// The display list (issue 32): every frame of a replay carries the marks its trace implies — one
// per visible vertex, one per visible active point, the span's box, the scanline — at the places
// the view's geometry puts them (computed here from the trace, not taken from the composer); and
// the composer's text metrics are OpenCV's own, so a layout measured without OpenCV is the one
// OpenCV draws.
#include <catch2/catch.hpp>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <opencv2/imgproc.hpp>

#include "trace/record.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/hershey.hpp"
#include "viz/trace_lookup.hpp"
#include "viz/typography.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

namespace {

struct Case {
  std::string name;
  trace::Trace trace;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  trace::TriangleInput course;
  course.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  course.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  course.width = course.height = 512;
  out.push_back({"course triangle", test::record(course)});
  out.push_back({"small", test::record(test::small_triangle())});
  out.push_back({"medium", test::record(test::medium_triangle(), Shading::flat)});
  trace::GeneralPolygonInput p;
  p.contours = {{{10, 1}, {15.5, 18.2}, {1.3, 7.3}, {18.7, 7.3}, {4.5, 18.2}}};
  p.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
  p.width = p.height = 20;
  FillOptions options;
  options.winding_rule = WindingRule::non_zero;
  out.push_back({"star", trace::record_polygon(p, options)});
  return out;
}

viz::Point rounded(viz::Point2d p) {
  return {int(std::lround(p.x)), int(std::lround(p.y))};
}

viz::Point2d centre(const viz::Rect& r) {
  return {r.x + r.width / 2.0, r.y + r.height / 2.0};
}

std::vector<viz::Mark> main_view(const std::vector<viz::Mark>& marks, viz::MarkKind kind) {
  std::vector<viz::Mark> out;
  for (const viz::Mark& m : marks)
    if (m.kind == kind && m.layer == 0) out.push_back(m);
  return out;
}

// One vertex mark per vertex the view shows, centred on it, named after it.
void check_vertex_marks(const std::vector<viz::Mark>& marks, const viz::ViewGeometry& g,
                        const std::vector<Vec2>& corners, const viz::Typography& type) {
  const viz::Rect& view = g.view();
  const std::vector<viz::Mark> vertices = main_view(marks, viz::MarkKind::vertex);
  std::size_t visible = 0;
  for (std::size_t v = 0; v < corners.size(); ++v) {
    const viz::Point q = rounded(g.to_frame(corners[v].x, corners[v].y));
    if (!view.contains(q)) continue;
    ++visible;
    const std::string name = fmt::format("v{}", v);
    INFO("vertex " << name << " at " << q.x << "," << q.y);
    const auto it = std::find_if(vertices.begin(), vertices.end(),
                                 [&](const viz::Mark& m) { return m.what == name; });
    REQUIRE(it != vertices.end());
    const int ring = type.px(7) + type.px(2);
    // The box is the marker's, clipped to the view: inside, its centre is the vertex.
    if ((viz::Rect(q.x - ring, q.y - ring, 2 * ring + 1, 2 * ring + 1) & view) ==
        viz::Rect(q.x - ring, q.y - ring, 2 * ring + 1, 2 * ring + 1)) {
      CHECK(std::abs(centre(it->box).x - (q.x + 0.5)) <= 0.5);
      CHECK(std::abs(centre(it->box).y - (q.y + 0.5)) <= 0.5);
    }
  }
  CHECK(vertices.size() == visible);
}

// One mark per visible active point of the row, named after its edge, on the point.
void check_active_point_marks(const std::vector<viz::Mark>& marks, const viz::ViewGeometry& g,
                              const trace::Scanline& row) {
  const std::vector<viz::Mark> points = main_view(marks, viz::MarkKind::active_point);
  std::size_t shown = 0;
  for (const trace::ActivePoint& p : row.active_points) {
    const viz::Point q = rounded(g.to_frame(p.x, double(row.y)));
    if (!g.view().contains(q)) continue;
    ++shown;
    INFO("active point of edge " << p.edge << " at x = " << p.x);
    const bool found = std::any_of(points.begin(), points.end(), [&](const viz::Mark& m) {
      return m.what == fmt::format("e{}", p.edge) && m.box.contains(q);
    });
    CHECK(found);
  }
  CHECK(points.size() == shown);
}

// The scanline, once, on the row; one box per span (or per inside interval), around its cells.
void check_row_marks(const std::vector<viz::Mark>& marks, const viz::ViewGeometry& g,
                     const trace::Scanline& row) {
  const std::vector<viz::Mark> lines = main_view(marks, viz::MarkKind::scanline);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].what == fmt::format("y = {}", row.y));
  const double y = g.to_frame(0, double(row.y)).y;
  CHECK(std::abs(centre(lines[0].box).y - y) <= 1.5);
  std::vector<trace::Span> spans;
  if (row.intervals)
    for (const trace::Interval& iv : *row.intervals) spans.push_back(iv.pixels);
  else if (row.span)
    spans.push_back(*row.span);
  std::erase_if(spans, [](const trace::Span& sp) { return sp.size() <= 0; });
  const std::vector<viz::Mark> boxes = main_view(marks, viz::MarkKind::span);
  CHECK(boxes.size() == spans.size());
  for (const trace::Span& sp : spans) {
    const std::string name = fmt::format("[{}, {})", sp.x_begin, sp.x_end);
    INFO("span " << name);
    const auto it = std::find_if(boxes.begin(), boxes.end(),
                                 [&](const viz::Mark& m) { return m.what == name; });
    REQUIRE(it != boxes.end());
    // The span's first and last cells' centres lie inside the box (where the view shows them).
    for (std::int64_t x : {sp.x_begin, sp.x_end - 1}) {
      const viz::Point q = rounded(g.to_frame(double(x), double(row.y)));
      if (g.view().contains(q)) CHECK(it->box.contains(q));
    }
  }
}

}  // namespace

TEST_CASE("every frame of a replay has the marks its trace implies", "[viz][display-list]") {
  for (const Case& c : cases()) {
    viz::StepOptions every_row;
    every_row.rows_per_step = 1;
    every_row.max_scanline_steps = 1 << 20;
    viz::FrameSequence s(c.trace, every_row, {1280, 720}, "test");
    const viz::Typography type(s.frame_size());
    const trace::TriangleBegin& b = c.trace.triangle_begin(0);
    const std::vector<Vec2>& corners = b.snapped.empty() ? b.vertices : b.snapped;
    std::size_t scanline_frames = 0;
    for (std::size_t i = 0; i < s.steps().size(); ++i) {
      const viz::Step& step = s.steps()[i];
      INFO(c.name << ", step " << i);
      const viz::Frame f = s.frame(i);
      CHECK(f.size() == viz::Size(1280, 720));
      const std::vector<viz::Mark> marks = f.marks();
      const std::optional<viz::ViewGeometry> g = s.geometry(i);
      if (!g) continue;
      check_vertex_marks(marks, *g, corners, type);
      const trace::Scanline* row = step.kind == viz::StepKind::scanlines
                                       ? viz::find_scanline(c.trace, step.triangle, step.last_row)
                                       : nullptr;
      if (!row) {
        CHECK(main_view(marks, viz::MarkKind::active_point).empty());
        CHECK(main_view(marks, viz::MarkKind::span).empty());
        continue;
      }
      ++scanline_frames;
      check_active_point_marks(marks, *g, *row);
      check_row_marks(marks, *g, *row);
    }
    CHECK(scanline_frames > 0);
  }
}

TEST_CASE("the composer's text metrics are cv::getTextSize's", "[viz][display-list][text]") {
  std::string printable;
  for (char ch = ' '; ch <= '~'; ++ch) printable += ch;
  std::vector<std::string> texts{"", "A", "Ag", "x = 12.34", "v0 (20, 20)", printable};
  for (char ch = ' '; ch <= '~'; ++ch) texts.emplace_back(1, ch);
  for (const auto& [font, cv_font] :
       {std::pair{viz::HersheyFont::simplex, cv::FONT_HERSHEY_SIMPLEX},
        std::pair{viz::HersheyFont::duplex, cv::FONT_HERSHEY_DUPLEX}})
    for (const double scale : {0.42 * 0.5, 0.42, 0.48, 0.6, 0.9, 1.3, 1.3 * 1.5, 0.48 * 2.7})
      for (const int thickness : {1, 2, 3})
        for (const std::string& text : texts) {
          INFO("font " << int(font) << " scale " << scale << " thickness " << thickness << " \""
                       << text << "\"");
          int cv_base = 0, our_base = 0;
          const cv::Size want = cv::getTextSize(text, cv_font, scale, thickness, &cv_base);
          const viz::Size got = viz::hershey_text_size(text, font, scale, thickness, &our_base);
          CHECK(got.width == want.width);
          CHECK(got.height == want.height);
          CHECK(our_base == cv_base);
        }
}

TEST_CASE("typographic characters are drawn as their ASCII look-alikes, the rest as '?'",
          "[viz][display-list][text]") {
  // The explorer's footer read "the explorer?s triangle": the fonts are ASCII only.
  CHECK(viz::hershey_ascii("the explorer\u2019s triangle") == "the explorer's triangle");
  CHECK(viz::hershey_ascii("\u201Cfar\u201D \u2013 near\u2026") == "\"far\" - near...");
  CHECK(viz::hershey_ascii("x \u2264 y \u2192 3\u00D74 \u2212 1") == "x <= y -> 3x4 - 1");
  // Not folded: a letter outside ASCII, a control character, a cut sequence: one '?' each, as
  // OpenCV's putText draws them.
  CHECK(viz::hershey_ascii("caf\u00E9") == "caf?");
  CHECK(viz::hershey_ascii("a\x1b[2Jb") == "a?[2Jb");
  CHECK(viz::hershey_ascii(std::string("ab\xE2\x80", 4)) == "ab?");
  CHECK(viz::hershey_ascii(std::string("\xE2\x80\x99\xE2", 4)) == "'?");
  // Measured as it is drawn: the width of the look-alike, which is OpenCV's for the ASCII text.
  int cv_base = 0;
  const cv::Size want = cv::getTextSize("explorer's", cv::FONT_HERSHEY_SIMPLEX, 0.6, 1, &cv_base);
  CHECK(viz::hershey_text_size("explorer\u2019s", viz::HersheyFont::simplex, 0.6, 1).width ==
        want.width);
  // A text op holds the ASCII form, so every backend (OpenCV's putText too) draws the same.
  viz::Frame frame({200, 40}, {255, 255, 255});
  viz::FrameView view(frame);
  view.text("it\u2019s", {2, 30}, viz::HersheyFont::simplex, 0.6, {0, 0, 0}, 1, viz::LineType::aa);
  REQUIRE(frame.ops().size() == 1);
  CHECK(std::get<viz::TextOp>(frame.ops()[0].body).text == "it's");
}

TEST_CASE("the Hershey strokes lie where OpenCV draws the text", "[viz][display-list][text]") {
  // Each stroke point of the composer's glyphs is on (or next to) a pixel putText inked.
  for (const viz::HersheyFont font : {viz::HersheyFont::simplex, viz::HersheyFont::duplex}) {
    cv::Mat m(80, 900, CV_8UC1, cv::Scalar(0));
    // Characters whose glyph is OpenCV's own (viz/hershey/glyphs.inc marks the few that are not).
    const std::string text = "scantrace: x = 12.34, v0 (20, 20) |&$!?+-/";
    cv::putText(m, text, {5, 50}, int(font), 1.1, cv::Scalar(255), 1, cv::LINE_8);
    std::size_t points = 0, near = 0;
    for (const auto& stroke : viz::hershey_strokes(text, font, 1.1, {5, 50}))
      for (const viz::Point2d& p : stroke) {
        ++points;
        const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
        bool inked = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) inked |= m.at<std::uint8_t>(y + dy, x + dx) != 0;
        near += inked;
      }
    INFO("font " << int(font));
    CHECK(points > 200);
    CHECK(near == points);
  }
}

TEST_CASE("the side panel's worked x += dx/dy never reads '+ -'", "[viz][display-list][formula]") {
  // Issue 36: "e2: 208.733 + -0.3902 = 208.343" is written "e2: 208.733 - 0.3902 = 208.343". Every
  // such line of every frame of two triangles whose edges slope either way is read back from the
  // display list's text and checked as arithmetic: the operator is + or -, the operand is not
  // negative, and x + dx/dy is the result to the shown digits. The triangles: the course
  // triangle, and mirrored (its edges slope the other way).
  std::vector<trace::Trace> traces;
  for (const double mirror : {0.0, 512.0}) {
    trace::TriangleInput t;
    t.vertices = {Vec2{std::abs(mirror - 20), 20}, Vec2{std::abs(mirror - 250), 80},
                  Vec2{std::abs(mirror - 300), 400}};
    t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
    t.width = t.height = 512;
    traces.push_back(test::record(t));
  }
  viz::StepOptions every_row;
  every_row.rows_per_step = 1;
  every_row.max_scanline_steps = 1 << 20;
  const std::regex line(R"(^\s*e(\d+): (-?[0-9.]+) ([+-]) (\S+) = (-?[0-9.]+)$)");
  std::size_t minus = 0, plus = 0;
  for (const trace::Trace& t : traces) {
    viz::FrameSequence s(t, every_row, {1280, 720}, "test");
    for (std::size_t i = 0; i < s.steps().size(); ++i) {
      const viz::Frame frame = s.frame(i);
      for (const viz::DrawOp& op : frame.ops()) {
        const auto* text = std::get_if<viz::TextOp>(&op.body);
        if (!text || text->text.find(" = ") == std::string::npos) continue;
        INFO("step " << i + 1 << ": \"" << text->text << "\"");
        CHECK(text->text.find("+ -") == std::string::npos);
        CHECK(text->text.find("- -") == std::string::npos);
        std::smatch m;
        if (!std::regex_match(text->text, m, line)) continue;
        const double x = std::stod(m[2]), step = std::stod(m[4]), result = std::stod(m[5]);
        CHECK(step >= 0);
        CHECK(std::abs((m[3] == "+" ? x + step : x - step) - result) < 0.0015);
        (m[3] == "+" ? plus : minus) += 1;
      }
    }
  }
  CHECK(minus > 0);  // the triangle has edges of negative dx/dy on its rows...
  CHECK(plus > 0);   // ...and of positive
}
