#pragma once
// A step of a replay as the pages list it (the full module's st_frames, web/bindings_trace.cpp,
// and the trace page's module, web/player/player_module.cpp, which must list the same steps):
// {"kind", "triangle", "first_row", "last_row"} and, on a step that shows the canvas, where it
// appears on the frame: canvas pixel (x, y) is centred at frame point origin + cell·(x, y),
// inside `view` (a page maps a click back to the pixel).
#include <cstddef>

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

}  // namespace scantrace::web
