#include "event_json.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/option_table.hpp"

namespace scantrace {

void to_json(nlohmann::ordered_json& j, const Vec2& p) {
  j = nlohmann::ordered_json::array({p.x, p.y});
}
void to_json(nlohmann::ordered_json& j, const Color& c) {
  j = nlohmann::ordered_json::array({c.r, c.g, c.b});
}

void from_json(const nlohmann::json& j, Vec2& p) {
  if (!j.is_array() || j.size() != 2) throw std::invalid_argument("expected a point [x, y]");
  p = {j[0].get<double>(), j[1].get<double>()};
}
void from_json(const nlohmann::json& j, Color& c) {
  if (!j.is_array() || j.size() != 3) throw std::invalid_argument("expected a colour [r, g, b]");
  c = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

}  // namespace scantrace

namespace scantrace::trace {
namespace {

using ojson = nlohmann::ordered_json;
using json = nlohmann::json;

// nlohmann's get<int>() converts a float or an out-of-range integer by a plain cast, which is
// undefined behaviour for 5e33 (found by fuzzing the reader): integers are checked here.
template <class T>
T integer(const json& v) {
  if (v.is_number_integer() && !v.is_number_unsigned()) {
    const std::int64_t i = v.get<std::int64_t>();
    if (i >= std::numeric_limits<T>::min() && i <= std::numeric_limits<T>::max())
      return static_cast<T>(i);
  } else if (v.is_number_unsigned()) {
    const std::uint64_t u = v.get<std::uint64_t>();
    if (u <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return static_cast<T>(u);
  }
  throw std::invalid_argument("expected an integer in range, got " + v.dump());
}

// A triangle_skipped event's reason, one of trace_schema.json's list (the SkipReason names a skip
// is traced with; "hidden" is a z-buffer count, never a skip event). Anything else ("bogus", an
// HTML tag) was accepted and shown as is by the player and the messages.
std::string skip_reason(const json& v) {
  static constexpr const char* kReasons[] = {"too_few_vertices", "out_of_range",  "degenerate",
                                             "no_pixel_centre",  "offscreen",     "culled"};
  const std::string reason = v.get<std::string>();
  for (const char* known : kReasons)
    if (reason == known) return reason;
  std::string list;
  for (const char* known : kReasons) list += (list.empty() ? "" : ", ") + std::string(known);
  throw std::invalid_argument("triangle_skipped reason " +
                              v.dump(-1, ' ', true, json::error_handler_t::replace) +
                              " is not one of " + list);
}

// A header option's value by its name in the option's table (src/option_table.hpp). The name
// is quoted as it is: the message's printer escapes what a terminal would obey.
template <class E>
E named(const json& v) {
  const OptionTable<E>& table = option_table<E>();
  const std::string name = v.get<std::string>();
  if (const std::optional<E> e = table.parse(name)) return *e;
  const bool two = table.names().size() == 2;
  std::string message = std::string("header: ") + table.key + " \"" + name + "\" is ";
  message += two ? "neither " : "not ";
  message += table.listed(two ? " nor " : " or ");
  throw std::invalid_argument(message);
}

std::vector<int> integers(const json& v) {
  if (!v.is_array()) throw std::invalid_argument("expected an array of integers");
  std::vector<int> out;
  for (const json& item : v) out.push_back(integer<int>(item));
  return out;
}

template <class T>
ojson list(const std::vector<T>& items) {
  ojson a = ojson::array();
  for (const T& item : items) a.push_back(item);
  return a;
}

ojson encode(const Header& h) {
  ojson j = {{"type", "header"},
             {"format", h.format},
             {"version", h.version},
             {"canvas", {{"width", h.canvas.width}, {"height", h.canvas.height}}},
             {"shading", option_name(h.shading)},
             {"fill_rule", option_name(h.fill_rule)},
             {"subpixel_bits", h.subpixel_bits},
             {"level", option_name(h.level)},
             {"generator", h.generator}};
  if (h.winding_rule) j["winding_rule"] = option_name(*h.winding_rule);
  if (h.visibility != Visibility::painter) j["visibility"] = option_name(h.visibility);
  if (h.cull != Cull::none) j["cull"] = option_name(h.cull);
  if (!(h.background == Color{1, 1, 1})) j["background"] = h.background;
  return j;
}

ojson encode(const TriangleBegin& e) {
  ojson j = {{"type", "triangle_begin"},
             {"triangle", e.triangle},
             {"vertices", list(e.vertices)},
             {"snapped", list(e.snapped)},
             {"colors", list(e.colors)}};
  if (e.depth) j["depth"] = *e.depth;
  if (e.flat_color) j["flat_color"] = *e.flat_color;
  if (!e.contours.empty()) j["contours"] = e.contours;
  if (!e.vertex_depths.empty()) j["vertex_depths"] = e.vertex_depths;
  return j;
}

ojson encode(const EdgeTableEvent& e) {
  ojson edges = ojson::array(), horizontal = ojson::array();
  for (const EdgeEntry& x : e.edges)
    edges.push_back({{"edge", x.edge},
                     {"from", x.from},
                     {"to", x.to},
                     {"y_min", x.y_min},
                     {"y_max", x.y_max},
                     {"x_at_y_min", x.x_at_y_min},
                     {"dx_dy", x.dx_dy},
                     {"first_row", x.first_row},
                     {"last_row", x.last_row}});
  for (const HorizontalEntry& h : e.horizontal)
    horizontal.push_back(
        {{"edge", h.edge}, {"from", h.from}, {"to", h.to}, {"y", h.y}, {"reason", h.reason}});
  return {{"type", "edge_table"},
          {"triangle", e.triangle},
          {"edges", edges},
          {"horizontal", horizontal}};
}

ojson encode(const Scanline& s) {
  ojson active = ojson::array(), points = ojson::array();
  for (const EdgeCrossing& a : s.active_edges) {
    ojson e = {{"edge", a.edge}, {"x", a.x}};
    if (a.winding) e["winding"] = *a.winding;
    active.push_back(e);
  }
  for (const ActivePoint& p : s.active_points)
    points.push_back({{"x", p.x}, {"edge", p.edge}, {"color", p.color}});
  ojson j = {{"type", "scanline"},     {"triangle", s.triangle}, {"y", s.y},
             {"entered", s.entered},   {"retired", s.retired},   {"active_edges", active},
             {"active_points", points}};
  if (s.span) j["span"] = {{"x_begin", s.span->x_begin}, {"x_end", s.span->x_end}};
  if (s.span_colors)
    j["span_colors"] = {{"begin", s.span_colors->begin}, {"end", s.span_colors->end}};
  if (s.intervals) {
    ojson list = ojson::array();
    for (const Interval& i : *s.intervals) {
      ojson x = {{"x_begin", i.pixels.x_begin}, {"x_end", i.pixels.x_end},
                 {"left_edge", i.left_edge},    {"right_edge", i.right_edge},
                 {"x_left", i.x_left},          {"x_right", i.x_right}};
      if (i.colors) x["colors"] = {{"begin", i.colors->begin}, {"end", i.colors->end}};
      list.push_back(x);
    }
    j["intervals"] = list;
  }
  return j;
}

ojson encode(const Pixel& p) {
  ojson j = {{"type", "pixel"}, {"triangle", p.triangle}, {"x", p.x},
             {"y", p.y},        {"color", p.color},       {"t", p.t}};
  if (p.depth_test) {
    j["depth_test"] = p.depth_test->passed ? "passed" : "rejected";
    j["depth"] = p.depth_test->depth;
    if (p.depth_test->stored) j["stored_depth"] = *p.depth_test->stored;
  }
  return j;
}
ojson encode(const TriangleEnd& e) {
  return {
      {"type", "triangle_end"}, {"triangle", e.triangle}, {"rows", e.rows}, {"pixels", e.pixels}};
}
ojson encode(const TriangleSkipped& e) {
  return {{"type", "triangle_skipped"}, {"triangle", e.triangle}, {"reason", e.reason}};
}
ojson encode(const Footer& f) {
  return {{"type", "footer"}, {"events", f.events}, {"truncated", f.truncated}};
}

template <class T>
std::vector<T> list_of(const json& j, const char* key) {
  std::vector<T> out;
  for (const json& item : j.at(key)) out.push_back(item.get<T>());
  return out;
}

Header decode_header(const json& j) {
  Header h;
  h.format = j.at("format").get<std::string>();
  h.version = integer<int>(j.at("version"));
  h.canvas = {integer<int>(j.at("canvas").at("width")), integer<int>(j.at("canvas").at("height"))};
  h.shading = named<Shading>(j.at("shading"));
  h.fill_rule = named<FillRule>(j.at("fill_rule"));
  h.subpixel_bits = integer<int>(j.at("subpixel_bits"));
  h.level = named<TraceLevel>(j.at("level"));
  h.generator = j.at("generator").get<std::string>();
  if (j.contains("winding_rule")) h.winding_rule = named<WindingRule>(j["winding_rule"]);
  if (j.contains("visibility")) h.visibility = named<Visibility>(j["visibility"]);
  if (j.contains("cull")) h.cull = named<Cull>(j["cull"]);
  if (j.contains("background")) h.background = j["background"].get<Color>();
  return h;
}

TriangleBegin decode_begin(const json& j) {
  TriangleBegin e;
  e.triangle = integer<int>(j.at("triangle"));
  e.vertices = list_of<Vec2>(j, "vertices");
  e.snapped = list_of<Vec2>(j, "snapped");
  e.colors = list_of<Color>(j, "colors");
  if (j.contains("depth")) e.depth = j["depth"].get<double>();
  if (j.contains("flat_color")) e.flat_color = j["flat_color"].get<Color>();
  if (j.contains("contours")) e.contours = j["contours"].get<std::vector<std::vector<int>>>();
  if (j.contains("vertex_depths")) e.vertex_depths = j["vertex_depths"].get<std::vector<double>>();
  return e;
}

EdgeTableEvent decode_edge_table(const json& j) {
  EdgeTableEvent e;
  e.triangle = integer<int>(j.at("triangle"));
  for (const json& x : j.at("edges"))
    e.edges.push_back({integer<int>(x.at("edge")), x.at("from").get<Vec2>(), x.at("to").get<Vec2>(),
                       x.at("y_min").get<double>(), x.at("y_max").get<double>(),
                       x.at("x_at_y_min").get<double>(), x.at("dx_dy").get<double>(),
                       integer<i64>(x.at("first_row")), integer<i64>(x.at("last_row"))});
  for (const json& h : j.at("horizontal"))
    e.horizontal.push_back({integer<int>(h.at("edge")), h.at("from").get<Vec2>(),
                            h.at("to").get<Vec2>(), h.at("y").get<double>(),
                            h.at("reason").get<std::string>()});
  return e;
}

Scanline decode_scanline(const json& j) {
  Scanline s;
  s.triangle = integer<int>(j.at("triangle"));
  s.y = integer<i64>(j.at("y"));
  s.entered = integers(j.at("entered"));
  s.retired = integers(j.at("retired"));
  for (const json& a : j.at("active_edges")) {
    EdgeCrossing e{integer<int>(a.at("edge")), a.at("x").get<double>()};
    if (a.contains("winding")) e.winding = integer<int>(a["winding"]);
    s.active_edges.push_back(e);
  }
  for (const json& p : j.at("active_points"))
    s.active_points.push_back(
        {p.at("x").get<double>(), integer<int>(p.at("edge")), p.at("color").get<Color>()});
  if (j.contains("span"))
    s.span = Span{integer<i64>(j["span"].at("x_begin")), integer<i64>(j["span"].at("x_end"))};
  if (j.contains("span_colors"))
    s.span_colors = SpanColors{j["span_colors"].at("begin").get<Color>(),
                               j["span_colors"].at("end").get<Color>()};
  if (j.contains("intervals")) {
    s.intervals.emplace();
    for (const json& i : j["intervals"]) {
      Interval x;
      x.pixels = {i.at("x_begin").get<i64>(), i.at("x_end").get<i64>()};
      x.left_edge = i.at("left_edge").get<int>();
      x.right_edge = i.at("right_edge").get<int>();
      x.x_left = i.at("x_left").get<double>();
      x.x_right = i.at("x_right").get<double>();
      if (i.contains("colors"))
        x.colors =
            SpanColors{i["colors"].at("begin").get<Color>(), i["colors"].at("end").get<Color>()};
      s.intervals->push_back(x);
    }
  }
  return s;
}

}  // namespace

const char* type_name(const Event& e) {
  static constexpr const char* kNames[] = {"header",           "triangle_begin", "edge_table",
                                           "scanline",         "pixel",          "triangle_end",
                                           "triangle_skipped", "footer"};
  return kNames[e.index()];
}

ojson event_to_json(const Event& e) {
  return std::visit([](const auto& v) { return encode(v); }, e);
}

Event event_from_json(const json& j) {
  if (!j.is_object()) throw std::invalid_argument("an event must be a JSON object");
  const std::string type = j.at("type").get<std::string>();
  if (type == "header") return decode_header(j);
  if (type == "triangle_begin") return decode_begin(j);
  if (type == "edge_table") return decode_edge_table(j);
  if (type == "scanline") return decode_scanline(j);
  if (type == "pixel") {
    Pixel p{integer<int>(j.at("triangle")), integer<i64>(j.at("x")), integer<i64>(j.at("y")),
            j.at("color").get<Color>(),     j.at("t").get<double>(), {}};
    if (j.contains("depth_test")) {
      PixelDepthTest d;
      d.passed = j.at("depth_test").get<std::string>() == "passed";
      d.depth = j.at("depth").get<double>();
      if (j.contains("stored_depth")) d.stored = j.at("stored_depth").get<double>();
      p.depth_test = d;
    }
    return p;
  }
  if (type == "triangle_end")
    return TriangleEnd{integer<int>(j.at("triangle")), integer<i64>(j.at("rows")),
                       integer<i64>(j.at("pixels"))};
  if (type == "triangle_skipped")
    return TriangleSkipped{integer<int>(j.at("triangle")), skip_reason(j.at("reason"))};
  if (type == "footer") return Footer{integer<i64>(j.at("events")), j.at("truncated").get<bool>()};
  throw std::invalid_argument("unknown event type \"" + type + "\"");
}

}  // namespace scantrace::trace
