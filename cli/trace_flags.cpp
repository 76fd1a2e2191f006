#include "cli/trace_flags.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/scene_input.hpp"
#include "cli/validators.hpp"

#include "io/scene_json.hpp"

namespace scantrace::cli {
namespace {

// "a,b,c" → numbers; `what` names the item in errors.
std::vector<double> numbers(const std::string& item, const std::string& what) {
  std::vector<double> out;
  std::stringstream in(item);
  std::string part;
  while (std::getline(in, part, ',')) {
    double v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || !std::isfinite(v))
      throw std::invalid_argument(what + ": \"" + part + "\" is not a finite number");
    out.push_back(v);
  }
  return out;
}

// Three whitespace-separated groups of `n` comma-separated numbers.
std::array<std::vector<double>, 3> three_groups(const std::string& text, std::size_t n,
                                                const std::string& what, const char* form) {
  std::stringstream in(text);
  std::vector<std::string> groups;
  for (std::string g; in >> g;) groups.push_back(g);
  if (groups.size() != 3)
    throw std::invalid_argument(what + " needs three " + form + " separated by spaces, got " +
                                std::to_string(groups.size()));
  std::array<std::vector<double>, 3> out;
  for (int i = 0; i < 3; ++i) {
    out[i] = numbers(groups[i], what);
    if (out[i].size() != n)
      throw std::invalid_argument(what + ": \"" + groups[i] + "\" is not " + form);
  }
  return out;
}

}  // namespace

std::array<Vec2, 3> parse_triangle(const std::string& text) {
  const auto g = three_groups(text, 2, "--triangle", "points x,y");
  return {Vec2{g[0][0], g[0][1]}, Vec2{g[1][0], g[1][1]}, Vec2{g[2][0], g[2][1]}};
}

std::array<Color, 3> parse_colors(const std::string& text) {
  const auto g = three_groups(text, 3, "--colors", "colours r,g,b");
  std::array<Color, 3> out;
  for (int i = 0; i < 3; ++i) {
    for (double v : g[i])
      if (v < 0 || v > 1)
        throw std::invalid_argument("--colors: components must be in [0, 1], got " +
                                    std::to_string(v));
    out[i] = {g[i][0], g[i][1], g[i][2]};
  }
  return out;
}

std::pair<int, int> parse_size(const std::string& text) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  const char* s = text.data();
  const auto r1 = std::from_chars(s, s + (x == std::string::npos ? 0 : x), w);
  const auto r2 = x == std::string::npos ? r1 : std::from_chars(s + x + 1, s + text.size(), h);
  if (x == std::string::npos || r1.ec != std::errc() || r1.ptr != s + x || r2.ec != std::errc() ||
      r2.ptr != s + text.size() || w <= 0 || h <= 0 ||
      static_cast<long long>(w) * h > kMaxCanvasPixels)
    throw std::invalid_argument("--size: \"" + text +
                                "\" is not WIDTHxHEIGHT with positive sizes (at most 2^28 pixels)");
  return {w, h};
}

std::variant<Scene, trace::TriangleInput> TraceFlags::input(bool clamp_colors) const {
  if (!scene.empty()) return load_scene_file(scene, clamp_colors);
  trace::TriangleInput t;
  t.vertices = parse_triangle(triangle);
  t.colors = parse_colors(colors);
  std::tie(t.width, t.height) = parse_size(size);
  check_canvas_memory(t.width, t.height, "--size", size);
  return t;
}

trace::TraceFilter TraceFlags::filter() const {
  trace::TraceFilter f;
  f.level = trace::parse_level(level);
  if (!triangles.empty()) f.triangles = trace::IndexSet::parse(triangles);
  if (!rows.empty()) f.rows = trace::RowRange::parse(rows);
  if (max_events) f.max_events = *max_events;
  return f;
}

std::string TraceFlags::input_name() const {
  if (!scene.empty()) return scene;
  return "the triangle " + triangle;
}

void add_trace_flags(CLI::App& command, TraceFlags& flags) {
  auto* scene =
      command.add_option("SCENE", flags.scene, "scene file to trace (JSON, as for render)");
  auto* triangle = command
                       .add_option("--triangle", flags.triangle,
                                   "trace one triangle instead of a scene, e.g.\n"
                                   "\"20,20 250,80 300,400\" (x = column, y = row down)")
                       ->check(parsed_by(parse_triangle));
  scene->excludes(triangle);
  command
      .add_option("--colors", flags.colors, "vertex colours of --triangle, \"r,g,b r,g,b r,g,b\"")
      ->check(parsed_by(parse_colors))
      ->needs(triangle)
      ->capture_default_str();
  command.add_option("--size", flags.size, "canvas of --triangle, WIDTHxHEIGHT")
      ->check(parsed_by(parse_size))
      ->needs(triangle)
      ->capture_default_str();
  command
      .add_option("--level", flags.level,
                  "triangle: setup, edge table and result per triangle\n"
                  "scanline: also every row's active edges, points, span\n"
                  "pixel: also every pixel written, with its colour")
      ->check(CLI::IsMember({"triangle", "scanline", "pixel"}))
      ->capture_default_str();
  command
      .add_option("--triangles", flags.triangles,
                  "trace only these faces, e.g. 3,17,40-45 (default: all)")
      ->check(parsed_by([](const std::string& v) { trace::IndexSet::parse(v); }));
  command
      .add_option("--rows", flags.rows, "trace only rows A…B, inclusive, e.g. 100:120, 100: or :50")
      ->check(parsed_by([](const std::string& v) { trace::RowRange::parse(v); }));
  command
      .add_option("--max-events", flags.max_events,
                  "stop after N events; the footer then says truncated")
      ->check(CLI::PositiveNumber);
}

}  // namespace scantrace::cli
