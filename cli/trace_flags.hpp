#pragma once
// What to trace and how much, shared by `trace` and `explain`:
//   (SCENE | --triangle "x0,y0 x1,y1 x2,y2" [--colors "r,g,b r,g,b r,g,b"] [--size WxH]
//          | --polygon "x,y x,y … | x,y …" [--colors "r,g,b …"] [--winding even-odd|non-zero])
//   [--level triangle|scanline|pixel] [--triangles 3,17,40-45] [--rows A:B] [--max-events N]
#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "src/option_table.hpp"
#include "src/scene.hpp"
#include "trace/record.hpp"
#include "trace/trace_filter.hpp"

namespace CLI {
class App;
}

namespace scantrace::cli {

struct TraceFlags {
  std::string scene;
  std::string triangle;
  std::string polygon;
  std::string winding = option_table<WindingRule>().default_name();
  std::string colors = "1,0,0 0,1,0 0,0,1";
  std::string size;  // --size, the canvas (cli/canvas_size.hpp); empty: by input
  std::string level = option_table<TraceLevel>().default_name();
  std::string triangles;
  std::string rows;
  std::optional<long long> max_events;

  // Throws InputError when the scene file is bad; `clamp_colors` as in cli/scene_input.hpp.
  std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput> input(
      bool clamp_colors) const;
  WindingRule winding_rule() const;
  // The checks that need several options at once (run from the subcommand's callback, so they
  // are usage errors): an input is given, --colors fits it, a polygon is not filled `closed` nor
  // by the halfspace method.
  void check(const std::string& fill_rule, const std::string& method) const;
  trace::TraceFilter filter() const;
  // "SCENE" or "the triangle (x0,y0) (x1,y1) (x2,y2)", for messages.
  std::string input_name() const;
};

// Adds the options above to `command`. Malformed values (a triangle that is not three points, a
// bad range) are usage errors, reported before anything runs.
void add_trace_flags(CLI::App& command, TraceFlags& flags);

// Parsers for the text forms (throw std::invalid_argument naming the problem).
std::array<Vec2, 3> parse_triangle(const std::string& text);
std::array<Color, 3> parse_colors(const std::string& text);
// "x,y x,y … | x,y …": contours separated by '|', at least three points each.
std::vector<std::vector<Vec2>> parse_polygon(const std::string& text);
// Any number (at least one) of colours "r,g,b r,g,b …".
std::vector<Color> parse_color_list(const std::string& text);
std::pair<int, int> parse_size(const std::string& text);

}  // namespace scantrace::cli
