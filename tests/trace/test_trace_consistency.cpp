// A trace that contradicts itself is refused with the file, the line and the contradiction; every
// trace the real fill writes passes even the thorough checks (exact arithmetic on the snapped
// vertices, trace/trace_check.hpp). The corrupt traces are real traces with one value edited, the
// way a user edits a file.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/scene_json.hpp"
#include "trace/event_json.hpp"
#include "trace/record.hpp"
#include "trace/trace_check.hpp"

using namespace scantrace;
using namespace scantrace::trace;
using ojson = nlohmann::ordered_json;

namespace {

// A Gouraud triangle with fractional vertices on a 64×48 canvas, one edge leaving the canvas on
// the right (so spans are clipped).
TriangleInput triangle() {
  TriangleInput t;
  t.vertices = {Vec2{3.3, 2.6}, Vec2{70.25, 20.5}, Vec2{11.7, 40.1}};
  t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  t.width = 64, t.height = 48;
  return t;
}

std::vector<ojson> lines_of(const Trace& t) {
  std::vector<ojson> lines;
  for (const Event& e : t.events()) lines.push_back(event_to_json(e));
  return lines;
}

std::vector<ojson> traced(TraceLevel level, FillOptions options = {}) {
  return lines_of(record_triangle(triangle(), options, TraceFilter{.level = level}));
}

std::string text_of(const std::vector<ojson>& lines) {
  std::string s;
  for (const ojson& j : lines) s += j.dump() + "\n";
  return s;
}

Trace parse(const std::vector<ojson>& lines) {
  std::istringstream in(text_of(lines));
  return Trace::parse(in, "t.jsonl");
}

void check_thoroughly(const std::vector<ojson>& lines) {
  check_consistency(parse(lines).events(), "t.jsonl", CheckDepth::thorough);
}

// Index of the n-th line (0-based count) of `type`; the line number in the file is index + 1.
std::size_t find(const std::vector<ojson>& lines, const std::string& type, int nth = 0,
                 const std::function<bool(const ojson&)>& also = nullptr) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i]["type"] == type && (!also || also(lines[i])) && nth-- == 0) return i;
  FAIL("no line of type " << type);
  return 0;
}

// The message names line index + 1 and contains `what`. (A matcher of its own: Catch2 v2's
// `a && b` keeps references to its operands, which must not be temporaries of a helper.)
class AtLine : public Catch::MatcherBase<std::string> {
 public:
  AtLine(std::size_t index, std::string what)
      : line_("t.jsonl:" + std::to_string(index + 1) + ": "), what_(std::move(what)) {}
  bool match(const std::string& s) const override {
    return s.find(line_) != std::string::npos && s.find(what_) != std::string::npos;
  }
  std::string describe() const override {
    return "names \"" + line_ + "\" and contains \"" + what_ + "\"";
  }

 private:
  std::string line_, what_;
};

AtLine at_line(std::size_t index, const std::string& what) {
  return AtLine(index, what);
}

bool has_span(const ojson& j) {
  return j.contains("span");
}

}  // namespace

TEST_CASE("traces of the real fill pass the cheap and the thorough checks", "[trace][check]") {
  for (const TraceLevel level : {TraceLevel::triangle, TraceLevel::scanline, TraceLevel::pixel})
    for (const FillRule rule : {FillRule::top_left, FillRule::closed})
      for (const Shading shading : {Shading::flat, Shading::gouraud}) {
        const auto lines = traced(level, {.shading = shading, .fill_rule = rule});
        CHECK_NOTHROW(check_thoroughly(lines));
      }
  // Random triangles, a quarter with integer vertices (rows and crossings exactly on centres),
  // some far outside the canvas, on grids of 0, 4 and 8 bits.
  std::uint64_t seed = 12345;
  auto next = [&] {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < 300; ++i) {
    TriangleInput t;
    const bool integral = i % 4 == 0;
    for (auto& v : t.vertices) {
      v = {next() * 90 - 20, next() * 70 - 15};
      if (integral) v = {std::round(v.x), std::round(v.y)};
    }
    if (i % 50 == 7) t.vertices[0] = {-1e6, 30.5};
    for (auto& c : t.colors) c = {next(), next(), next()};
    t.width = 50, t.height = 40;
    const FillOptions options{.shading = i % 2 ? Shading::flat : Shading::gouraud,
                              .fill_rule = i % 3 ? FillRule::top_left : FillRule::closed,
                              .subpixel_bits = std::array{0, 4, 8}[i % 3]};
    const auto lines = lines_of(record_triangle(t, options, {.level = TraceLevel::pixel}));
    INFO("triangle " << i);
    CHECK_NOTHROW(check_thoroughly(lines));
  }
  // General polygons: intervals, windings, contours.
  GeneralPolygonInput star;
  star.contours = {{{10, 1}, {15.5, 18.2}, {1.3, 7.3}, {18.7, 7.3}, {4.5, 18.2}}};
  star.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}};
  star.width = star.height = 20;
  for (const WindingRule w : {WindingRule::even_odd, WindingRule::non_zero})
    CHECK_NOTHROW(check_thoroughly(
        lines_of(record_polygon(star, {.winding_rule = w}, {.level = TraceLevel::pixel}))));
}

// Hidden from discovery: tests/CMakeLists.txt runs it as its own test, reported SKIPPED (its
// output says "skipped:") when ../shared/data is absent.
TEST_CASE("the course scene's scanline trace passes the thorough checks", "[.][course-check]") {
  const std::filesystem::path scene =
      std::filesystem::path(SCANTRACE_SHARED_DATA) / "hw1_2024.json";
  if (!std::filesystem::exists(scene)) {
    WARN("skipped: " << scene << " is not present");
    return;
  }
  const Trace t = record_scene(load_scene(scene), {}, {.level = TraceLevel::scanline});
  const CheckSummary s = check_consistency(t.events(), "course.jsonl", CheckDepth::thorough);
  CHECK(s.events == static_cast<std::int64_t>(t.events().size()));
  CHECK(s.events - 2 == 111298);  // the count: the events between header and footer
}

// A trace whose events contradict each other is refused naming the line: its spans and rows, its
// values, its order and counts (the three cases below).
TEST_CASE("a trace whose spans or rows contradict the triangle is refused naming the line",
          "[trace][check]") {
  const auto good = traced(TraceLevel::scanline);
  REQUIRE_NOTHROW(parse(good));

  SECTION("a span that runs backwards") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 3, has_span);
    t[i]["span"] = {{"x_begin", 1000000000000000}, {"x_end", -1000000000000000}};
    CHECK_THROWS_WITH(parse(t), at_line(i, "runs backwards"));
  }
  SECTION("a span outside the canvas") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 3, has_span);
    t[i]["span"]["x_end"] = 65;
    CHECK_THROWS_WITH(parse(t), at_line(i, "is not inside the canvas [0, 64)"));
  }
  SECTION("a row outside the triangle's rows") {
    auto t = good;
    const std::size_t i = find(t, "triangle_end") - 1;  // the last scanline
    t[i]["y"] = 47;
    CHECK_THROWS_WITH(parse(t), at_line(i, "outside the rows 3…40"));
  }
  SECTION("the same row twice") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 5);
    t.insert(t.begin() + static_cast<std::ptrdiff_t>(i) + 1, t[i]);
    CHECK_THROWS_WITH(parse(t), at_line(i + 1, "rows of a triangle must increase"));
  }
}

TEST_CASE("a trace with a colour or a vertex out of range is refused naming the line",
          "[trace][check]") {
  const auto good = traced(TraceLevel::scanline);
  REQUIRE_NOTHROW(parse(good));

  SECTION("a colour outside [0, 1]") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 2);
    t[i]["active_points"][0]["color"] = {0.5, 1.25, 0};
    // The whole message, which the checker builds only when a check fails (a callable per row).
    const std::string row = "triangle " + std::to_string(t[i]["triangle"].get<int>()) + ", row " +
                            std::to_string(t[i]["y"].get<std::int64_t>());
    CHECK_THROWS_WITH(parse(t), at_line(i, row + ": active point 0: colour [0.5, 1.25, 0] is not a "
                                             "colour in [0, 1]"));
    REQUIRE(t[i].contains("span_colors"));  // Gouraud
    auto u = good;
    u[i]["span_colors"]["end"] = {0, 0, -0.5};
    CHECK_THROWS_WITH(parse(u), at_line(i, row + ": span colour end [0, 0, -0.5] is not a colour"));
    auto v = good;
    const std::size_t b = find(v, "triangle_begin");
    v[b]["colors"][1] = {-0.5, 0, 0};
    CHECK_THROWS_WITH(parse(v), at_line(b, "vertex 1: colour"));
  }
  SECTION("a vertex beyond the fill's coordinate range") {
    // Found by fuzz_trace_reader (fuzz/regressions/trace_reader/vertex-beyond-range): the
    // thorough check snapped 9.2e19 to the grid, a float-to-integer overflow (UBSan).
    auto t = good;
    const std::size_t b = find(t, "triangle_begin");
    t[b]["vertices"][0][0] = 92233720368547758084.5;
    CHECK_THROWS_WITH(parse(t),
                      at_line(b, "vertex 0 x 9.2233720368547758e+19 is beyond the fill's range"));
    auto u = good;
    u[b]["snapped"][2][1] = -2147483648.0;
    CHECK_THROWS_WITH(parse(u), at_line(b, "vertex 2 snapped y"));
  }
}

TEST_CASE("a trace whose events are out of order or miscounted is refused naming the line",
          "[trace][check]") {
  const auto good = traced(TraceLevel::scanline);
  REQUIRE_NOTHROW(parse(good));

  SECTION("a scanline of a triangle that was never begun") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 4);
    t[i]["triangle"] = 7;
    CHECK_THROWS_WITH(parse(t), at_line(i, "scanline of triangle 7, which was never begun"));
  }
  SECTION("a scanline after its triangle ended") {
    auto t = good;
    const std::size_t end = find(t, "triangle_end");
    auto row = t[end - 1];
    row["y"] = 41;
    t.insert(t.begin() + static_cast<std::ptrdiff_t>(end) + 1, row);
    CHECK_THROWS_WITH(parse(t), at_line(end + 1, "after its triangle_end"));
  }
  SECTION("active points out of order") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 6);
    std::swap(t[i]["active_points"][0], t[i]["active_points"][1]);
    CHECK_THROWS_WITH(parse(t), at_line(i, "active points are not sorted by x"));
  }
  SECTION("entered and retired that disagree with the active set") {
    auto t = good;
    const std::size_t first = find(t, "scanline");
    t[first]["entered"] = ojson::array();
    CHECK_THROWS_WITH(parse(t), at_line(first, "entered [] disagrees with the active set"));
    auto u = good;
    const std::size_t mid = find(u, "scanline", 10);
    u[mid]["retired"] = {0};
    CHECK_THROWS_WITH(parse(u), at_line(mid, "retired [0] disagrees with the active set"));
    auto v = good;
    v[mid]["active_edges"][0]["edge"] = 9;
    CHECK_THROWS_WITH(parse(v), at_line(mid, "but the edge table makes"));
  }
  SECTION("counts of triangle_end and the footer that disagree with the trace") {
    auto t = good;
    const std::size_t end = find(t, "triangle_end");
    t[end]["rows"] = t[end]["rows"].get<int>() + 1;
    CHECK_THROWS_WITH(parse(t), at_line(end, "rows 39, but its edge table covers 38 rows"));
    auto u = good;
    u[end]["pixels"] = u[end]["pixels"].get<int>() - 1;
    CHECK_THROWS_WITH(parse(u), at_line(end, "but its spans hold"));
    auto v = good;
    v.back()["events"] = 3;
    CHECK_THROWS_WITH(parse(v), at_line(v.size() - 1, "footer: events 3, but the trace holds"));
  }
  SECTION("a trace cut short is checked as far as it goes (--partial keeps working)") {
    auto t = good;
    t.resize(find(t, "scanline", 12) + 1);
    const Trace cut = parse(t);
    CHECK_FALSE(cut.complete());
    CHECK_NOTHROW(check_consistency(cut.events(), "t.jsonl", CheckDepth::thorough));
  }
}

TEST_CASE("pixel events must be the pixels of their row's span", "[trace][check]") {
  const auto good = traced(TraceLevel::pixel);
  REQUIRE_NOTHROW(parse(good));
  SECTION("a pixel outside the span") {
    auto t = good;
    const std::size_t row = find(t, "scanline", 8, has_span);
    t[row - 1]["x"] = t[row]["span"]["x_end"].get<int>() + 2;  // the row's last pixel
    CHECK_THROWS_WITH(parse(t), at_line(row, "is outside the span"));
  }
  SECTION("a pixel missing") {
    auto t = good;
    const std::size_t row = find(t, "scanline", 8, has_span);
    t.erase(t.begin() + static_cast<std::ptrdiff_t>(row) - 1);
    CHECK_THROWS_WITH(parse(t), at_line(row - 1, "pixel events for a span of"));
  }
  SECTION("a pixel of a triangle never begun") {
    auto t = good;
    const std::size_t p = find(t, "pixel", 3);
    t[p]["triangle"] = 2;
    CHECK_THROWS_WITH(parse(t), at_line(p, "pixel of triangle 2, which was never begun"));
  }
}

TEST_CASE("the thorough checks recompute the edge table, the crossings and the spans exactly",
          "[trace][check]") {
  const auto good = traced(TraceLevel::scanline);
  auto thorough_failure = [](const std::vector<ojson>& t) {
    // The cheap checks (every load) accept these: only exact arithmetic sees them.
    REQUIRE_NOTHROW(parse(t));
    return [t] { check_thoroughly(t); };
  };
  SECTION("an edge table entry that disagrees with the snapped vertices") {
    auto t = good;
    const std::size_t i = find(t, "edge_table");
    t[i]["edges"][1]["dx_dy"] = t[i]["edges"][1]["dx_dy"].get<double>() * (1 + 1e-12);
    CHECK_THROWS_WITH(thorough_failure(t)(), at_line(i, "dx_dy is"));
  }
  SECTION("a snapped vertex that is not the vertex on the grid") {
    auto t = good;
    const std::size_t i = find(t, "triangle_begin");
    t[i]["snapped"][0][0] = 3.25;  // 3.3 snaps to 845/256 = 3.30078125
    CHECK_THROWS_WITH(thorough_failure(t)(), at_line(i, "is not the vertex on the 1/256 grid"));
  }
  SECTION("an active point off its edge's exact crossing") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 9);
    const double x = t[i]["active_points"][0]["x"].get<double>();
    t[i]["active_points"][0]["x"] = std::nextafter(x, -1e9);
    CHECK_THROWS_WITH(thorough_failure(t)(), at_line(i, "but the edge crosses the row at"));
  }
  SECTION("a span that is not ceil(x_L) .. ceil(x_R) - 1") {
    auto t = good;
    const std::size_t i = find(t, "scanline", 9, has_span);
    t[i]["span"]["x_end"] = t[i]["span"]["x_end"].get<int>() - 1;
    const std::size_t end = find(t, "triangle_end");
    t[end]["pixels"] = t[end]["pixels"].get<int>() - 1;  // keep the counts agreeing
    CHECK_THROWS_WITH(thorough_failure(t)(), at_line(i, "but ceil(x_L) … ceil(x_R) − 1"));
  }
}
