#include "cli/trace_flags.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/canvas_size.hpp"
#include "cli/option_choice.hpp"
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

std::vector<std::vector<Vec2>> parse_polygon(const std::string& text) {
  std::vector<std::vector<Vec2>> out;
  std::stringstream contours(text);
  for (std::string contour; std::getline(contours, contour, '|');) {
    std::stringstream in(contour);
    std::vector<Vec2>& c = out.emplace_back();
    for (std::string g; in >> g;) {
      const std::vector<double> v = numbers(g, "--polygon");
      if (v.size() != 2) throw std::invalid_argument("--polygon: \"" + g + "\" is not a point x,y");
      c.push_back({v[0], v[1]});
    }
    if (c.size() < 3)
      throw std::invalid_argument("--polygon: contour " + std::to_string(out.size()) +
                                  " needs at least three points x,y, got " +
                                  std::to_string(c.size()));
  }
  if (out.empty()) throw std::invalid_argument("--polygon needs at least one contour");
  return out;
}

std::vector<Color> parse_color_list(const std::string& text) {
  std::stringstream in(text);
  std::vector<Color> out;
  for (std::string g; in >> g;) {
    const std::vector<double> v = numbers(g, "--colors");
    if (v.size() != 3) throw std::invalid_argument("--colors: \"" + g + "\" is not a colour r,g,b");
    for (double c : v)
      if (c < 0 || c > 1)
        throw std::invalid_argument("--colors: components must be in [0, 1], got " +
                                    std::to_string(c));
    out.push_back({v[0], v[1], v[2]});
  }
  if (out.empty()) throw std::invalid_argument("--colors needs at least one colour r,g,b");
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

WindingRule TraceFlags::winding_rule() const {
  return chosen<WindingRule>(winding);
}

void TraceFlags::check(const std::string& fill_rule, const std::string& method) const {
  if (scene.empty() && triangle.empty() && polygon.empty())
    throw CLI::RequiredError("a SCENE file, --triangle or --polygon");
  if (!polygon.empty()) {
    if (chosen<FillRule>(fill_rule) == FillRule::closed)
      throw CLI::ValidationError("--fill-rule",
                                 "closed is not defined for general polygons (where edges cross "
                                 "or contours touch); use " +
                                     std::string(option_name(FillRule::top_left)));
    // A usage error like the one above, before the fill refuses it as bad input.
    if (chosen<Method>(method) == Method::halfspace)
      throw CLI::ValidationError("--method",
                                 "halfspace tests convex half-planes, which a general polygon "
                                 "is not; use exact, double or float");
    std::size_t vertices = 0;
    for (const auto& c : parse_polygon(polygon)) vertices += c.size();
    if (parse_color_list(colors).size() > vertices)
      throw CLI::ValidationError(
          "--colors", "more colours than the polygon's " + std::to_string(vertices) + " vertices");
  } else if (!triangle.empty()) {
    parse_colors(colors);
  }
}

std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput> TraceFlags::input(
    bool clamp_colors) const {
  if (!scene.empty()) {
    Scene s = load_scene_file(scene, clamp_colors);
    apply_canvas_size(s, size);
    return s;
  }
  if (!polygon.empty()) {
    trace::GeneralPolygonInput p;
    p.contours = parse_polygon(polygon);
    // Fewer colours than vertices are repeated in turn (the default: red, green, blue, …).
    const std::vector<Color> given = parse_color_list(colors);
    for (const auto& c : p.contours)
      for (std::size_t i = 0; i < c.size(); ++i)
        p.colors.push_back(given[p.colors.size() % given.size()]);
    std::tie(p.width, p.height) = canvas_size_or(size, kDefaultCanvasSize, kDefaultCanvasSize);
    check_canvas_memory(p.width, p.height, "--size", size);
    return p;
  }
  trace::TriangleInput t;
  t.vertices = parse_triangle(triangle);
  t.colors = parse_colors(colors);
  std::tie(t.width, t.height) = canvas_size_or(size, kDefaultCanvasSize, kDefaultCanvasSize);
  check_canvas_memory(t.width, t.height, "--size", size);
  return t;
}

trace::TraceFilter TraceFlags::filter() const {
  trace::TraceFilter f;
  f.level = chosen<TraceLevel>(level);
  if (!triangles.empty()) f.triangles = trace::IndexSet::parse(triangles);
  if (!rows.empty()) f.rows = trace::RowRange::parse(rows);
  if (max_events) f.max_events = *max_events;
  return f;
}

std::string TraceFlags::input_name() const {
  if (!scene.empty()) return scene;
  if (!polygon.empty()) return "the polygon " + polygon;
  return "the triangle " + triangle;
}

void add_trace_flags(CLI::App& command, TraceFlags& flags) {
  auto* scene =
      command.add_option("SCENE", flags.scene,
                         "scene file (JSON or MATLAB .mat) or OBJ model to trace,\nas for render");
  auto* triangle = command
                       .add_option("--triangle", flags.triangle,
                                   "trace one triangle instead of a scene, e.g.\n"
                                   "\"20,20 250,80 300,400\" (x = column, y = row down)")
                       ->check(parsed_by(parse_triangle));
  scene->excludes(triangle);
  auto* polygon = command
                      .add_option("--polygon", flags.polygon,
                                  "trace one general polygon (concave, self-intersecting,\n"
                                  "with holes): contours separated by '|', e.g.\n"
                                  "\"0,0 40,0 40,40 0,40 | 10,10 10,30 30,30 30,10\"")
                      ->check(parsed_by(parse_polygon));
  polygon->excludes(scene)->excludes(triangle);
  auto* colors =
      command
          .add_option("--colors", flags.colors,
                      "vertex colours, \"r,g,b r,g,b r,g,b\": three for --triangle; for\n"
                      "--polygon one per vertex, or fewer, repeated in turn")
          ->check(parsed_by([](const std::string& v) {
            // The one mix-up worth a hint: a model's base colour given to the vertex colours.
            if (v == "file" || v == "random" || v == "white")
              throw std::invalid_argument("\"" + v +
                                          "\" is a model's base colour: use --model-colors " + v +
                                          " (--colors are the vertex colours of --triangle or "
                                          "--polygon, \"r,g,b r,g,b r,g,b\")");
            parse_color_list(v);
          }))
          ->capture_default_str();
  add_canvas_size_option(command, flags.size);
  colors->excludes(scene);
  add_choice<WindingRule>(command, "--winding", flags.winding)
      ->needs(polygon)
      ->capture_default_str();
  add_choice<TraceLevel>(command, "--level", flags.level)->capture_default_str();
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
