#include "grade/pixel_story.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>

#include "grade/face_geometry.hpp"
#include "grade/scene_around.hpp"
#include "src/painter.hpp"
#include "io/interrupt.hpp"
#include "trace/record.hpp"

namespace scantrace::grade {
namespace {

std::string rgb(Color c) {
  return fmt::format("({:.4f}, {:.4f}, {:.4f})", c.r, c.g, c.b);
}
std::string num(double v) {
  return fmt::format("{:.6g}", v);
}

nlohmann::json color_json(Color c) {
  return nlohmann::json::array({c.r, c.g, c.b});
}

// The face's sentence: what the fill did about pixel (x, y).
std::string face_sentence(const FaceStep& s, int x, int y, bool gouraud) {
  std::string out = fmt::format("face {} (depth {}): ", s.face, num(s.depth));
  switch (s.outcome) {
    case Outcome::skipped:
      return out + "skipped by the fill (" + s.skip_reason + ")";
    case Outcome::row_outside:
      return out + fmt::format(
                       "does not cover it: row {} is not among its scanlines {}..{} "
                       "(ceil(y_min) .. ceil(y_max) - 1)",
                       y, s.first_row, s.last_row);
    default:
      break;
  }
  std::string row;
  if (s.active_points.size() >= 2) {
    const auto& l = s.active_points.front();
    const auto& r = s.active_points.back();
    row = fmt::format("row {} has active points x_L = {} (edge {}) and x_R = {} (edge {})", y,
                      num(l.x), l.edge, num(r.x), r.edge);
  }
  const std::string span = s.span ? fmt::format("span {}..{}", s.span->x_begin, s.span->x_end - 1)
                                  : std::string("an empty span");
  switch (s.outcome) {
    case Outcome::left_of_span:
      return out + "does not cover it: " + row + ", " + span +
             fmt::format(" (ceil(x_L) .. ceil(x_R) - 1); x = {} is left of it", x);
    case Outcome::right_of_span:
      return out + "does not cover it: " + row + ", " + span +
             fmt::format(" (ceil(x_L) .. ceil(x_R) - 1); x = {} is right of it", x);
    case Outcome::written:
    case Outcome::depth_rejected: {
      out += "covers it: " + row + ", " + span + "; ";
      if (gouraud && s.active_points.size() >= 2)
        out += fmt::format("Gouraud: edge colours {} and {}, t = {} along the span gives {}",
                           rgb(s.active_points.front().color), rgb(s.active_points.back().color),
                           num(s.t), rgb(*s.color));
      else
        out += "flat colour (the mean of the vertex colours) " + rgb(*s.color);
      if (s.depth_test) {
        const auto& d = *s.depth_test;
        const std::string stored = d.stored ? num(*d.stored) : std::string("empty");
        out += fmt::format("; depth test: depth {} vs stored {}: {}", num(d.depth), stored,
                           d.passed ? "passes, written" : "fails, not written");
      } else {
        out += "; written";
      }
      return out;
    }
    default:
      return out;
  }
}

}  // namespace

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::skipped:
      return "skipped";
    case Outcome::row_outside:
      return "row_outside";
    case Outcome::left_of_span:
      return "left_of_span";
    case Outcome::right_of_span:
      return "right_of_span";
    case Outcome::written:
      return "written";
    case Outcome::depth_rejected:
      return "depth_rejected";
  }
  return "?";
}

namespace {

// Step 1: row y of the faces around (x, y), traced as the whole scene draws them. Of each face's
// pixels only the one asked about: the work and the memory are linear in the faces around the
// pixel, not in their spans' pixels (docs/robustness.md).
trace::Trace trace_row_around(const Scene& scene, const FillOptions& options, int x, int y,
                              double extra_margin, std::vector<int>& faces) {
  const Scene around = scene_around(scene, x, y, snap_margin(options) + extra_margin, &faces);
  trace::TraceFilter filter;
  filter.level = TraceLevel::pixel;
  filter.rows = trace::RowRange{y, y};
  filter.columns = trace::RowRange{x, x};
  return trace::record_scene(around, options, filter);
}

// Step 2: the story's header: the pixel, the canvas and the options; the background until a face
// writes the pixel.
PixelStory empty_story(const Scene& scene, const FillOptions& options, int x, int y) {
  PixelStory story;
  story.x = x, story.y = y;
  story.width = scene.width, story.height = scene.height;
  story.shading = to_string(options.shading);
  story.fill_rule = to_string(options.fill_rule);
  story.visibility = to_string(options.visibility);
  story.background = scene.background;
  story.final_color = scene.background;
  return story;
}

// Step 3a: the face as the scene gives it: vertices, colours, mean depth, and whether the centre
// lies exactly on its outline.
FaceStep describe_face(const Scene& scene, const FillOptions& options, int face, int x, int y) {
  FaceStep s;
  s.face = face;
  for (int k = 0; k < 3; ++k) {
    s.vertices.push_back(scene.vertices[scene.faces[face][k]]);
    s.colors.push_back(scene.vcolors[scene.faces[face][k]]);
    s.depth += scene.depth[scene.faces[face][k]];
  }
  s.depth /= 3;
  int e = -1;
  const OnOutline on = FaceGeometry(scene, face, options.subpixel_bits).on_outline(x, y, &e);
  if (on != OnOutline::no) s.outline = on == OnOutline::edge ? "edge" : "vertex", s.outline_edge = e;
  return s;
}

// Step 3b: the face's scanlines, from its edge table (none: 0..-1).
void find_scanlines(const trace::EdgeTableEvent& table, FaceStep& s) {
  s.first_row = INT64_MAX, s.last_row = INT64_MIN;
  for (const auto& edge : table.edges)
    if (edge.first_row <= edge.last_row)
      s.first_row = std::min(s.first_row, edge.first_row),
      s.last_row = std::max(s.last_row, edge.last_row);
  if (s.first_row > s.last_row) s.first_row = 0, s.last_row = -1;
}

// Step 3c: row y's active points and span, and where x falls: left or right of the span, or
// inside it (written, or rejected by the depth test).
void place_on_row(const trace::Trace& t, int local, int x, int y, FaceStep& s) {
  const trace::Scanline& row = t.scanline(local, y);
  s.active_points = row.active_points;
  s.span = row.span;
  s.span_colors = row.span_colors;
  if (!row.span || x < row.span->x_begin) {
    s.outcome = row.span && x >= row.span->x_end ? Outcome::right_of_span : Outcome::left_of_span;
    return;
  }
  if (x >= row.span->x_end) {
    s.outcome = Outcome::right_of_span;
    return;
  }
  for (const trace::Pixel* p : t.pixels(local))
    if (p->x == x && p->y == y) {
      s.color = p->color, s.t = p->t, s.depth_test = p->depth_test;
      s.outcome =
          p->depth_test && !p->depth_test->passed ? Outcome::depth_rejected : Outcome::written;
    }
}

// Step 3: what the fill did about the pixel in one face.
FaceStep face_step(const Scene& scene, const FillOptions& options, const trace::Trace& t,
                   int local, int face, int x, int y) {
  FaceStep s = describe_face(scene, options, face, x, y);
  if (const auto skipped = t.skipped(local)) {
    s.outcome = Outcome::skipped;
    s.skip_reason = skipped->reason;
    return s;
  }
  find_scanlines(t.edge_table(local), s);
  if (!t.has_scanline(local, y)) {
    s.outcome = Outcome::row_outside;
    return s;
  }
  place_on_row(t, local, x, y, s);
  return s;
}

// Step 4: a centre exactly on an outline: who owns it, and who does not. The faces named beside
// each are the first four on the outline (three of them other than it), found once: comparing
// every pair was quadratic in the faces around the pixel.
void add_outline_notes(const FillOptions& options, PixelStory& story) {
  std::vector<const FaceStep*> on_outline;
  for (const FaceStep& o : story.faces)
    if (!o.outline.empty() && o.outcome != Outcome::skipped && on_outline.size() < 4)
      on_outline.push_back(&o);
  const auto gets = [](const FaceStep& f) {
    return f.outcome == Outcome::written || f.outcome == Outcome::depth_rejected;
  };
  for (const FaceStep& s : story.faces) {
    if (s.outline.empty() || s.outcome == Outcome::skipped) continue;
    std::string others;
    int listed = 0;
    for (const FaceStep* op : on_outline)
      if (const FaceStep& o = *op; o.face != s.face && ++listed <= 3)
        others += fmt::format("{}face {} on the other side {} it", others.empty() ? "" : "; ",
                              o.face, gets(o) ? "gets" : "does not get");
    std::string rule =
        options.fill_rule == FillRule::closed
            ? "the closed rule gives every face a centre on its outline (shared edges are painted "
              "twice)"
        : gets(s) ? "the top-left rule gives it to this face (a top or left edge of it)"
                  : "the top-left rule does not give it to this face (a right or bottom edge of it)";
    story.notes.push_back(fmt::format("the centre lies exactly on {} {} of face {}: {}{}",
                                      s.outline, s.outline_edge, s.face, rule,
                                      others.empty() ? "" : "; " + others));
  }
}

}  // namespace

PixelStory why(const Scene& scene, const FillOptions& options, int x, int y,
               double extra_margin) {
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
    throw std::out_of_range(
        fmt::format("pixel ({}, {}) is outside the {}x{} canvas", x, y, scene.width, scene.height));
  std::vector<int> faces;
  const trace::Trace t = trace_row_around(scene, options, x, y, extra_margin, faces);
  PixelStory story = empty_story(scene, options, x, y);
  std::size_t done = 0;
  for (int local : t.triangles()) {
    if ((++done & 1023) == 0) check_interrupt();
    FaceStep s = face_step(scene, options, t, local, faces[local], x, y);
    if (s.outcome == Outcome::written) story.final_color = *s.color, story.final_face = s.face;
    story.faces.push_back(std::move(s));
  }
  add_outline_notes(options, story);
  return story;
}

std::string PixelStory::to_text() const {
  std::string out = fmt::format("pixel ({}, {}) of the {}x{} canvas ({}, {} rule, {}):\n", x, y,
                                width, height, shading, fill_rule, visibility);
  if (faces.empty()) out += "  no face's bounding box holds its centre\n";
  const bool gouraud = shading == to_string(Shading::gouraud);
  for (std::size_t i = 0; i < faces.size(); ++i)
    out += fmt::format("  {}. {}\n", i + 1, face_sentence(faces[i], x, y, gouraud));
  for (const auto& n : notes) out += "  note: " + n + "\n";
  out += "  final colour " + rgb(final_color) +
         (final_face ? fmt::format(", written by face {}", *final_face)
                     : std::string(", the background (no face wrote it)")) +
         "\n";
  return out;
}

std::string PixelStory::summary(const std::vector<int>& also) const {
  std::string out = fmt::format("Pixel ({}, {}): ", x, y);
  int n = 0;
  for (const auto& f : faces)
    if (f.outcome != Outcome::skipped) ++n;
  if (faces.empty()) out += "no face's bounding box holds its centre. ";
  for (const auto& f : faces)
    if (f.outcome == Outcome::written || f.outcome == Outcome::depth_rejected ||
        std::find(also.begin(), also.end(), f.face) != also.end())
      out += face_sentence(f, x, y, shading == to_string(Shading::gouraud)) + ". ";
  out += fmt::format("{} face(s) around it. ", n);
  // One paragraph: the first two boundary notes at most.
  for (std::size_t i = 0; i < notes.size() && i < 2; ++i) out += notes[i] + ". ";
  out += "Final colour " + rgb(final_color) +
         (final_face ? fmt::format(" from face {}.", *final_face) : std::string(" (background)."));
  return out;
}

nlohmann::json PixelStory::to_json() const {
  nlohmann::json faces_json = nlohmann::json::array();
  for (const auto& f : faces) {
    nlohmann::json j{{"face", f.face}, {"depth", f.depth}, {"outcome", to_string(f.outcome)}};
    nlohmann::json v = nlohmann::json::array(), c = nlohmann::json::array();
    for (const auto& p : f.vertices) v.push_back({p.x, p.y});
    for (const auto& col : f.colors) c.push_back(color_json(col));
    j["vertices"] = v;
    j["colors"] = c;
    if (f.outcome == Outcome::skipped) j["reason"] = f.skip_reason;
    if (f.first_row <= f.last_row) j["rows"] = {f.first_row, f.last_row};
    if (!f.active_points.empty()) {
      nlohmann::json pts = nlohmann::json::array();
      for (const auto& p : f.active_points)
        pts.push_back({{"x", p.x}, {"edge", p.edge}, {"color", color_json(p.color)}});
      j["active_points"] = pts;
    }
    if (f.span) j["span"] = {{"x_begin", f.span->x_begin}, {"x_end", f.span->x_end}};
    if (f.color) {
      j["color"] = color_json(*f.color);
      j["t"] = f.t;
    }
    if (f.depth_test) {
      j["depth_test"] = {{"passed", f.depth_test->passed}, {"depth", f.depth_test->depth}};
      if (f.depth_test->stored) j["depth_test"]["stored"] = *f.depth_test->stored;
    }
    if (!f.outline.empty()) j["on_outline"] = {{"kind", f.outline}, {"index", f.outline_edge}};
    faces_json.push_back(std::move(j));
  }
  nlohmann::json j{{"format", "scantrace-why"},
                   {"version", 1},
                   {"pixel", {x, y}},
                   {"canvas", {{"width", width}, {"height", height}}},
                   {"shading", shading},
                   {"fill_rule", fill_rule},
                   {"visibility", visibility},
                   {"background", color_json(background)},
                   {"faces", faces_json},
                   {"notes", notes},
                   {"final", {{"color", color_json(final_color)}}}};
  j["final"]["face"] = final_face ? nlohmann::json(*final_face) : nlohmann::json(nullptr);
  return j;
}

}  // namespace scantrace::grade
