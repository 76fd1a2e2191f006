// The trace page's own WebAssembly module (docs/web.md, "The trace page"): only what the player
// calls, so that a page of `replay -o OUT.html` weighs kilobytes. It reads the trace from memory
// (no file system), plans its steps once and composes one step's frame at a time, with the same
// viz::FrameSequence and canvas JSON as the full module's st_frames (web/bindings_trace.cpp): no
// scene readers, no rasterizer entry points, no why or diff. A separate file, not the full
// module's bindings: EMSCRIPTEN_KEEPALIVE exports every st_* function of a linked object, and the
// linker keeps whatever an export reaches.
//
// Each st_page_* function returns 0 (done), 1 (bad input: st_page_error() is the message) or 2
// (a bad argument from the page); its result text stays until the next call.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "trace/trace.hpp"
#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "web/call_status.hpp"
#include "web/step_json.hpp"

namespace scantrace::web {
namespace {

struct Page {
  std::string text;   // the last call's result
  std::string error;  // its message when it failed
  // The trace and its steps, from st_page_open on; the sequence refers to the trace.
  std::optional<trace::Trace> trace;
  std::unique_ptr<viz::FrameSequence> frames;
};

Page& page() {
  static Page p;
  return p;
}

template <class Work>
int run(Work&& work) {
  Page& p = page();
  p.text.clear();
  p.error.clear();
  return call_status(work, p.error);
}

}  // namespace
}  // namespace scantrace::web

using namespace scantrace;

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* st_page_text() { return web::page().text.c_str(); }
EMSCRIPTEN_KEEPALIVE std::size_t st_page_text_size() { return web::page().text.size(); }
EMSCRIPTEN_KEEPALIVE const char* st_page_error() { return web::page().error.c_str(); }

// The trace's JSON Lines `trace_text`, planned under `options_json` ({"width", "height" (1280 ×
// 720), "rows_per_step", "mode", "source", "marked_pixel"}, as the full module's st_frames takes
// them): {"steps": [step, …]}. The trace and its plan are kept for st_page_frame.
EMSCRIPTEN_KEEPALIVE int st_page_open(const char* trace_text, const char* options_json) {
  return web::run([&] {
    web::Page& p = web::page();
    p.frames.reset();
    p.trace.reset();
    const nlohmann::json o = nlohmann::json::parse(options_json ? options_json : "{}", nullptr, false);
    if (!o.is_object()) throw std::invalid_argument("options: not a JSON object");
    std::istringstream in(trace_text ? trace_text : "");
    p.trace = trace::Trace::parse(in, o.value("source", std::string("the trace")));
    viz::StepOptions steps;
    steps.rows_per_step = o.value("rows_per_step", 0);
    steps.mode = viz::parse_replay_mode(o.value("mode", std::string("auto")));
    p.frames = std::make_unique<viz::FrameSequence>(
        *p.trace, steps, viz::Size{o.value("width", 1280), o.value("height", 720)},
        o.value("source", std::string()));
    if (o.contains("marked_pixel"))
      p.frames->mark_on_every_frame(viz::CanvasPixel{o["marked_pixel"][0].get<std::int64_t>(),
                                                     o["marked_pixel"][1].get<std::int64_t>()});
    std::string out = "{\"steps\":[";
    for (std::size_t i = 0; i < p.frames->steps().size(); ++i)
      out += (i ? "," : "") + web::step_json(*p.frames, i).dump();
    p.text = out + "]}";
  });
}

// Step `index`'s frame as the canvas backend draws it (viz::to_json with the glyph table, pixel
// blocks as PNG data URIs): what the full module's st_frames writes for that step.
EMSCRIPTEN_KEEPALIVE int st_page_frame(int index) {
  return web::run([&] {
    web::Page& p = web::page();
    if (!p.frames) throw std::invalid_argument("frame: no trace opened");
    if (index < 0 || static_cast<std::size_t>(index) >= p.frames->steps().size())
      throw std::invalid_argument("frame: step " + std::to_string(index) + " out of range");
    p.text = viz::to_json(p.frames->frame(static_cast<std::size_t>(index)), viz::TextForm::glyph_table);
  });
}

}  // extern "C"
