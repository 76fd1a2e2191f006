#include "fill_options.hpp"

#include "option_table.hpp"
#include "tracer.hpp"

namespace scantrace {

// The defaults are FillOptions' own (and TraceFilter's level), so they are written once.
template <>
const OptionTable<Shading>& option_table<Shading>() {
  static const OptionTable<Shading> t{"shading",
                                      FillOptions{}.shading,
                                      {{Shading::flat, "flat"}, {Shading::gouraud, "gouraud"}},
                                      "flat: each triangle in the mean of its vertex colours\n"
                                      "gouraud: vertex colours interpolated along the edges,\n"
                                      "then along each scanline"};
  return t;
}

template <>
const OptionTable<FillRule>& option_table<FillRule>() {
  static const OptionTable<FillRule> t{
      "fill_rule",
      FillOptions{}.fill_rule,
      {{FillRule::top_left, "top-left"}, {FillRule::closed, "closed"}},
      "top-left: a pixel on an edge shared by two triangles\n"
      "belongs to exactly one of them (no overlap, no gaps)\n"
      "closed: every centre inside or on the boundary is\n"
      "filled, so shared edges are painted twice (the\n"
      "course's and OpenCV's rule)"};
  return t;
}

template <>
const OptionTable<Method>& option_table<Method>() {
  static const OptionTable<Method> t{"method",
                                     FillOptions{}.method,
                                     {{Method::exact, "exact"},
                                      {Method::float32, "float"},
                                      {Method::double64, "double"},
                                      {Method::halfspace, "halfspace"}},
                                     "exact: fixed-point edge table, exact decisions\n"
                                     "float: the textbook loop, x += 1/m in float32\n"
                                     "double: x recomputed per row in double\n"
                                     "halfspace: bounding box + exact edge functions\n"
                                     "(docs/accuracy.md: what each gets wrong)"};
  return t;
}

template <>
const OptionTable<WindingRule>& option_table<WindingRule>() {
  static const OptionTable<WindingRule> t{
      "winding_rule",
      FillOptions{}.winding_rule,
      {{WindingRule::even_odd, "even-odd"}, {WindingRule::non_zero, "non-zero"}},
      "which pixels of --polygon are inside: even-odd (an odd\n"
      "number of edges to the left) or non-zero (edges going\n"
      "down minus edges going up is not zero)"};
  return t;
}

template <>
const OptionTable<Cull>& option_table<Cull>() {
  static const OptionTable<Cull> t{
      "cull",
      FillOptions{}.cull,
      {{Cull::none, "none"}, {Cull::back, "back"}, {Cull::front, "front"}},
      "skip faces turned away (back) or towards the viewer\n"
      "(front); default: back for a model, none for a scene"};
  return t;
}

template <>
const OptionTable<Visibility>& option_table<Visibility>() {
  static const OptionTable<Visibility> t{
      "visibility",
      FillOptions{}.visibility,
      {{Visibility::painter, "painter"}, {Visibility::zbuffer, "zbuffer"}},
      "painter: farthest mean depth first (the course's);\n"
      "zbuffer: per-pixel depth test; default: zbuffer for a\n"
      "model, painter for a scene"};
  return t;
}

template <>
const OptionTable<Occlusion>& option_table<Occlusion>() {
  static const OptionTable<Occlusion> t{"occlusion",
                                        FillOptions{}.occlusion,
                                        {{Occlusion::near_to_far, "near-to-far"},
                                         {Occlusion::far_to_near, "far-to-near"},
                                         {Occlusion::automatic, "auto"}},
                                        "near-to-far: each pixel written once, hidden faces "
                                        "rejected\nfar-to-near: the painter's order as taught\n"
                                        "auto: one of the two, chosen from the scene"};
  return t;
}

template <>
const OptionTable<TraceLevel>& option_table<TraceLevel>() {
  static const OptionTable<TraceLevel> t{"level",
                                         TraceLevel::scanline,
                                         {{TraceLevel::triangle, "triangle"},
                                          {TraceLevel::scanline, "scanline"},
                                          {TraceLevel::pixel, "pixel"}},
                                         "triangle: setup, edge table and result per triangle\n"
                                         "scanline: also every row's active edges, points, span\n"
                                         "pixel: also every pixel written, with its colour"};
  return t;
}

const char* to_string(Shading s) {
  return option_name(s);
}
const char* to_string(FillRule r) {
  return option_name(r);
}
const char* to_string(Method m) {
  return option_name(m);
}
const char* to_string(Cull c) {
  return option_name(c);
}
const char* to_string(Visibility v) {
  return option_name(v);
}
const char* to_string(Occlusion o) {
  return option_name(o);
}
const char* to_string(WindingRule w) {
  return option_name(w);
}

bool parse_method(const char* name, Method& out) {
  const std::optional<Method> m = parse_option<Method>(name);
  if (m) out = *m;
  return m.has_value();
}

bool parse_winding_rule(const char* name, WindingRule& out) {
  const std::optional<WindingRule> w = parse_option<WindingRule>(name);
  if (w) out = *w;
  return w.has_value();
}

}  // namespace scantrace
