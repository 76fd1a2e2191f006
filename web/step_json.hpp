#pragma once
// A step of a replay as the pages list it (the full module's st_frames, web/bindings_trace.cpp,
// and the trace page's module, web/player/player_module.cpp, which must list the same steps):
// {"kind", "triangle", "first_row", "last_row"} and, on a step that shows the canvas, where it
// appears on the frame: canvas pixel (x, y) is centred at frame point origin + cell·(x, y),
// inside `view` (a page maps a click back to the pixel).
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "viz/frame_sequence.hpp"

namespace scantrace::web {

inline nlohmann::json step_json(const viz::FrameSequence& s, std::size_t i) {
  const viz::Step& st = s.steps()[i];
  nlohmann::json step{{"kind", viz::to_string(st.kind)},
                      {"triangle", st.triangle},
                      {"first_row", st.first_row},
                      {"last_row", st.last_row}};
  if (const auto g = s.geometry(i)) {
    const viz::Point2d o = g->to_frame(0, 0);
    step["view"] = {g->view().x, g->view().y, g->view().width, g->view().height};
    step["origin"] = {o.x, o.y};
    step["cell"] = g->cell();
  }
  return step;
}

// The list of all steps, [step_json(s, 0).dump(), …], written directly: nlohmann building and
// dumping an object per step, for the 47 steps of the course triangle on each of a drag's mouse
// moves, was a tenth of its st_frames call (docs/performance.md, "Ninth round"). The same text:
// the keys in nlohmann's order (sorted), integers in decimal, and the numbers of a step's
// geometry, which most steps share, formatted by nlohmann once for each geometry in a row.
class StepsJson {
 public:
  std::string operator()(const viz::FrameSequence& s) {
    std::string out = "[";
    for (std::size_t i = 0; i < s.steps().size(); ++i) {
      const viz::Step& st = s.steps()[i];
      const std::optional<viz::ViewGeometry> g = s.geometry(i);
      if (g) geometry(*g);
      out += i ? ",{" : "{";
      if (g) out += cell_;
      out += "\"first_row\":" + std::to_string(st.first_row) + ",\"kind\":" + kind(st.kind) +
             ",\"last_row\":" + std::to_string(st.last_row);
      if (g) out += origin_;
      out += ",\"triangle\":" + std::to_string(st.triangle);
      if (g) out += view_;
      out += '}';
    }
    return out + "]";
  }

 private:
  // nlohmann's text of a number: the shortest that reads back as it, "2.0" for an integral one.
  static std::string number(double v) { return nlohmann::json(v).dump(); }
  // Equal as nlohmann would print them: the same value and sign (0.0 and -0.0 print apart).
  static bool same(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

  void geometry(const viz::ViewGeometry& g) {
    const viz::Rect& v = g.view();
    const viz::Point2d o = g.to_frame(0, 0);
    if (have_ && v.x == view_rect_.x && v.y == view_rect_.y && v.width == view_rect_.width &&
        v.height == view_rect_.height && same(o.x, origin_point_.x) && same(o.y, origin_point_.y) &&
        same(g.cell(), cell_value_))
      return;
    have_ = true;
    view_rect_ = v;
    origin_point_ = o;
    cell_value_ = g.cell();
    cell_ = "\"cell\":" + number(g.cell()) + ",";
    origin_ = ",\"origin\":[" + number(o.x) + "," + number(o.y) + "]";
    view_ = ",\"view\":[" + std::to_string(v.x) + "," + std::to_string(v.y) + "," +
            std::to_string(v.width) + "," + std::to_string(v.height) + "]";
  }

  const std::string& kind(viz::StepKind k) {
    for (const auto& [kind, text] : kinds_)
      if (kind == k) return text;
    return kinds_.emplace_back(k, nlohmann::json(viz::to_string(k)).dump()).second;
  }

  bool have_ = false;
  viz::Rect view_rect_;
  viz::Point2d origin_point_;
  double cell_value_ = 0;
  std::string cell_, origin_, view_;
  std::vector<std::pair<viz::StepKind, std::string>> kinds_;
};

}  // namespace scantrace::web
