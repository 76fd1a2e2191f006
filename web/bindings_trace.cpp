// trace and frames (bindings.hpp): the JSON Lines `scantrace trace` writes, and the display lists
// of a trace's steps as the canvas backend draws them (viz/frame_json.hpp).
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "demo/demo_scene.hpp"
#include "io/obj_loader.hpp"
#include "io/scene_json.hpp"
#include "trace/event_json.hpp"
#include "trace/record.hpp"
#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/frame_text.hpp"
#include "web/bindings.hpp"
#include "web/step_json.hpp"
#include "web/traced_image.hpp"

namespace scantrace::web {
namespace {

constexpr const char* kTraceFile = "/tmp/scantrace-web-trace.jsonl";

Vec2 point(const nlohmann::json& p, const char* what) {
  if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
    throw std::invalid_argument(std::string(what) + ": a vertex is [x, y]");
  return {p[0].get<double>(), p[1].get<double>()};
}

Color colour(const nlohmann::json& c) {
  if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() ||
      !c[2].is_number())
    throw std::invalid_argument("input.colors: a colour is [r, g, b] in [0, 1]");
  return {c[0].get<double>(), c[1].get<double>(), c[2].get<double>()};
}

// The colours given, or the CLI's default (--colors "1,0,0 0,1,0 0,0,1", repeated for a polygon).
std::vector<Color> colours(const nlohmann::json& in, std::size_t n) {
  std::vector<Color> out;
  if (in.contains("colors")) {
    for (const auto& c : in["colors"]) out.push_back(colour(c));
    if (out.size() != n) throw std::invalid_argument("input.colors: one colour per vertex");
    return out;
  }
  const Color cycle[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (std::size_t i = 0; i < n; ++i) out.push_back(cycle[i % 3]);
  return out;
}

trace::TraceFilter filter_of(const nlohmann::json& o) {
  trace::TraceFilter f;
  if (o.contains("level")) f.level = trace::parse_level(o["level"].get<std::string>());
  if (o.contains("triangles")) f.triangles = trace::IndexSet::of(o["triangles"].get<std::vector<int>>());
  if (o.contains("max_events")) f.max_events = o["max_events"].get<std::int64_t>();
  return f;
}

trace::TriangleInput triangle_input(const nlohmann::json& in) {
  trace::TriangleInput t;
  if (!in["triangle"].is_array() || in["triangle"].size() != 3)
    throw std::invalid_argument("input.triangle: three vertices [x, y]");
  const std::vector<Color> c = colours(in, 3);
  for (int i = 0; i < 3; ++i) {
    t.vertices[i] = point(in["triangle"][i], "input.triangle");
    t.colors[i] = c[i];
  }
  t.width = in.value("width", kDefaultCanvasSize);
  t.height = in.value("height", kDefaultCanvasSize);
  return t;
}

trace::GeneralPolygonInput polygon_input(const nlohmann::json& in) {
  trace::GeneralPolygonInput p;
  std::size_t n = 0;
  for (const auto& contour : in["polygon"]) {
    p.contours.emplace_back();
    for (const auto& v : contour) p.contours.back().push_back(point(v, "input.polygon"));
    n += p.contours.back().size();
  }
  p.colors = colours(in, n);
  p.width = in.value("width", kDefaultCanvasSize);
  p.height = in.value("height", kDefaultCanvasSize);
  return p;
}

void require_input(const nlohmann::json& in) {
  if (!in.contains("scene") && !in.contains("triangle") && !in.contains("polygon"))
    throw std::invalid_argument("input: give scene (a file), triangle or polygon");
}

// The command's byte cap of a trace (`scantrace trace --max-bytes`: 1 GiB by default, 1024 to
// 2^50), which the module applies to a trace's text and to frames' result: options.max_bytes,
// lowered to the longest string a JavaScript engine makes (V8: 2^29 - 24 characters; the text is
// ASCII), with room for the footer line the cap leaves on top. Without it a pixel-level trace of
// 2048^2 was 493 MiB of text, and at 2600^2 V8 refused to make the string.
constexpr std::int64_t kCommandMaxBytes = std::int64_t{1} << 30;
constexpr std::int64_t kLongestText = (std::int64_t{1} << 29) - 24 - 128;

std::int64_t max_bytes_option(const nlohmann::json& o) {
  if (!o.contains("max_bytes")) return std::min(kCommandMaxBytes, kLongestText);
  const nlohmann::json& v = o["max_bytes"];
  // --max-bytes' check, CLI::Range(1024LL, 1LL << 50), and its words.
  if (!v.is_number_integer() || v.get<std::int64_t>() < 1024 ||
      v.get<std::int64_t>() > (std::int64_t{1} << 50))
    throw std::invalid_argument("max_bytes: Value " + v.dump() +
                                " not in range 1024 to 1125899906842624");
  return std::min(v.get<std::int64_t>(), kLongestText);
}

// The command's warning for a trace its budget cut (cli/trace_command.cpp), the budget named by
// the option that set it.
std::string truncated_warning(const trace::Footer& footer, const trace::TraceFilter& filter) {
  const bool by_events = filter.max_events && footer.events >= *filter.max_events;
  const std::string budget = by_events ? "max_events " + std::to_string(*filter.max_events)
                                       : "max_bytes " + std::to_string(*filter.max_bytes);
  return "warning: trace: the trace was truncated after " + std::to_string(footer.events) +
         " events by its budget " + budget + "; its footer says \"truncated\": true";
}

trace::Footer trace_to_file(const nlohmann::json& in, const nlohmann::json& o) {
  require_input(in);
  trace::TraceFilter filter = filter_of(o);
  filter.max_bytes = max_bytes_option(o);
  trace::Footer footer;
  if (in.contains("scene")) {
    const std::string path = in["scene"].get<std::string>();
    const Scene scene = load_scene(path, o);
    footer = trace::write_scene_trace(kTraceFile, scene, fill_options(o, is_obj_file(path)), filter);
  } else if (in.contains("triangle")) {
    footer = trace::write_triangle_trace(kTraceFile, triangle_input(in), fill_options(o, false), filter);
  } else {
    footer = trace::write_polygon_trace(kTraceFile, polygon_input(in), fill_options(o, false), filter);
  }
  if (footer.truncated) result().warning = truncated_warning(footer, filter);
  return footer;
}

// The JSON Lines of `events` as the file writer writes them under the byte cap `max_bytes`: the
// header and the event lines within it, then, where the next line would pass it, a footer saying
// truncated (trace/jsonl_writer.hpp's write_within), and the command's warning.
std::string capped_text(const std::vector<trace::Event>& events, const trace::TraceFilter& filter) {
  std::string text;
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string line = trace::event_to_json(events[i]).dump() + "\n";
    if (i > 0 && !std::holds_alternative<trace::Footer>(events[i]) &&
        static_cast<std::int64_t>(text.size() + line.size()) > *filter.max_bytes) {
      const trace::Footer cut{static_cast<i64>(i) - 1, true};
      result().warning = truncated_warning(cut, filter);
      return text + trace::event_to_json(trace::Event{cut}).dump() + "\n";
    }
    text += line;
  }
  return text;
}

// The trace kept in memory by the last st_trace with options.keep, for st_frames without a file:
// the explorer traces and composes on every mouse move, and writing the trace's JSON Lines to a
// file for the composer to parse back was a third of that (docs/performance.md).
std::optional<trace::Trace>& kept_trace() {
  static std::optional<trace::Trace> t;
  return t;
}

// The image of the kept trace of a triangle or polygon, kept from call to call with its bytes.
TracedImage& traced_image() {
  static TracedImage image;
  return image;
}

// The same events as trace_to_file writes, recorded in memory and kept; their JSON Lines text
// (each line as the file writer writes it: event_to_json(e).dump()); the fill's image, RGBA, as
// the result's bytes (a scene's in result().bytes, a triangle's or polygon's those traced_image()
// keeps).
std::string trace_in_memory(const nlohmann::json& in, const nlohmann::json& o) {
  require_input(in);
  const trace::TraceFilter filter = filter_of(o);
  if (in.contains("scene")) {
    traced_image().forget();
    kept_trace().reset();
    RgbImage image;
    const std::string path = in["scene"].get<std::string>();
    kept_trace() = trace::record_scene(load_scene(path, o), fill_options(o, is_obj_file(path)), filter, &image);
    put_rgba(image, result().bytes);
  } else {
    // The last trace says which pixels its fill wrote onto the kept canvas (canvas_for), so it
    // goes only once the new canvas is ready.
    FillOptions options;
    const auto fill = [&](const auto& input, auto record) {
      options = fill_options(o, false);
      RgbImage& canvas = traced_image().canvas_for(input.width, input.height, input.background,
                                                   kept_trace() ? &*kept_trace() : nullptr);
      kept_trace().reset();
      kept_trace() = record(canvas, input, options, filter);
    };
    try {
      if (in.contains("triangle"))
        fill(triangle_input(in), trace::record_triangle_onto);
      else
        fill(polygon_input(in), trace::record_polygon_onto);
    } catch (...) {
      // Bad input keeps no trace (st_frames then says so), and leaves the canvas half drawn.
      kept_trace().reset();
      traced_image().forget();
      throw;
    }
    // The image the traced fill drew, for a page to show (a polygon has no render of its own):
    // from the trace's spans when they are all of its pixels (no filter, none cut off), where the
    // fill writes exactly those pixels onto a canvas of its background (the trace's checks hold
    // each row's pixel events to its span); a drag's traced fill was a tenth of its mouse move in
    // Chromium converting 512 x 512 pixels, most of them background in the triangle's rows.
    // Not the halfspace method: it fills pixel by pixel and its trace has no scanline events.
    const trace::Trace& t = *kept_trace();
    const bool whole = options.method != Method::halfspace && !filter.triangles && !filter.rows &&
                       !filter.max_events && filter.level >= TraceLevel::scanline && t.footer() &&
                       !t.footer()->truncated;
    if (whole)
      traced_image().set_from_spans(t);
    else
      traced_image().set_from_every_pixel();
    result().kept_bytes = &traced_image().rgba();
  }
  // Without the text (options.text false: a drag's mouse move, which reads the step's events
  // with st_kept_step): the events' JSON was half of the call's time.
  if (!o.value("text", true)) return {};
  trace::TraceFilter capped = filter;
  capped.max_bytes = max_bytes_option(o);
  return capped_text(kept_trace()->events(), capped);
}

// A pixel block as the runs of equal rows and of equal columns it is made of, and one texel per
// run pair: the magnified canvas cells repeat each canvas pixel over a cell of frame pixels, so a
// step frame's 1280 × 600 block is some 40 × 40 texels. Lossless: rows are merged only when equal,
// columns only when equal in every row kept. The texels' RGBA bytes are appended to `bytes` from
// `at`. Writing and copying the 2.3 MB of RGBA bytes of the whole block was a quarter of a drag's
// mouse move (docs/performance.md).
struct BlockRuns {
  std::size_t at = 0;
  std::vector<std::size_t> cols, rows;  // run widths, run heights
};
BlockRuns block_runs(const viz::PixelsOp& p, std::vector<std::uint8_t>& bytes) {
  const std::size_t w = static_cast<std::size_t>(p.area.width), h = static_cast<std::size_t>(p.area.height);
  const viz::Vec3b* px = p.bgr->data();
  BlockRuns runs;
  // Rows: the first of each run of equal rows.
  std::vector<std::size_t> row_starts;
  for (std::size_t r = 0; r < h; ++r) {
    if (r > 0 && web::same_bytes(px + r * w, px + (r - 1) * w, w * sizeof(viz::Vec3b))) {
      ++runs.rows.back();
      continue;
    }
    row_starts.push_back(r);
    runs.rows.push_back(1);
  }
  // Columns: a new run where any kept row changes from the column before.
  std::vector<std::size_t> col_starts;
  for (std::size_t u = 0; u < w; ++u) {
    bool same = u > 0;
    for (std::size_t k = 0; same && k < row_starts.size(); ++k)
      same = px[row_starts[k] * w + u] == px[row_starts[k] * w + u - 1];
    if (same) {
      ++runs.cols.back();
      continue;
    }
    col_starts.push_back(u);
    runs.cols.push_back(1);
  }
  std::size_t at = runs.at = bytes.size();
  bytes.resize(at + row_starts.size() * col_starts.size() * 4);
  for (const std::size_t r : row_starts)
    for (const std::size_t u : col_starts) {
      const viz::Vec3b& c = px[r * w + u];
      bytes[at++] = c[2];
      bytes[at++] = c[1];
      bytes[at++] = c[0];
      bytes[at++] = 255;
    }
  return runs;
}

// The runs as the JSON frame's block (the op's last element; web/scantrace.mjs expands it):
//   {"at": offset of the texels' RGBA bytes, "cols": [run widths], "rows": [run heights]}
std::string block_runs_json(const viz::PixelsOp& p, std::vector<std::uint8_t>& bytes) {
  const BlockRuns runs = block_runs(p, bytes);
  std::string json = "{\"at\":" + std::to_string(runs.at) + ",\"cols\":[";
  const auto list = [&](const std::vector<std::size_t>& v) {
    for (std::size_t i = 0; i < v.size(); ++i) json += (i ? "," : "") + std::to_string(v[i]);
  };
  list(runs.cols);
  json += "],\"rows\":[";
  list(runs.rows);
  return json + "]}";
}

// The runs as a frame's numbers (viz::to_numbers' block): at, the column count and widths, the
// row count and heights.
void block_runs_numbers(const viz::PixelsOp& p, std::vector<std::uint8_t>& bytes, std::vector<double>& out) {
  const BlockRuns runs = block_runs(p, bytes);
  out.push_back(static_cast<double>(runs.at));
  for (const auto* v : {&runs.cols, &runs.rows}) {
    out.push_back(static_cast<double>(v->size()));
    out.insert(out.end(), v->begin(), v->end());
  }
}

// A frame's display list as viz::to_json writes it, its text as glyphs placed from the frame's
// glyph table (each glyph's strokes once: they were most of the JSON the page parsed on every
// mouse move, docs/performance.md), and its pixel blocks, when `raw`, as their runs and texels
// (block_runs) appended to `bytes` instead of PNG data URIs. The page puts the expanded bytes on
// its canvas at once (putImageData); the PNG and its base64 were most of a frame's time in the
// module and in the browser.
std::string frame_json(const viz::Frame& frame, bool raw, std::vector<std::uint8_t>& bytes) {
  if (!raw) return viz::to_json(frame, viz::TextForm::glyph_table);
  return viz::to_json(frame, viz::TextForm::glyph_table,
                      [&](const viz::PixelsOp& p) { return block_runs_json(p, bytes); });
}

// The same frame as numbers (viz::to_numbers), its blocks as runs: the numbers appended to
// `bytes` (from a multiple of 8, for a Float64Array), the rest as JSON,
//   {"w", "h", "bg", "at": the numbers' offset, "n": their count, "strings": [...], "marks": [...]}
// Writing the frame's numbers as text and parsing them back in the page was a fifth of a drag's
// mouse move (docs/performance.md).
std::string frame_numbers(const viz::Frame& frame, std::vector<std::uint8_t>& bytes) {
  viz::NumberFrame f = viz::to_numbers(frame, [&](const viz::PixelsOp& p, std::vector<double>& out) {
    block_runs_numbers(p, bytes, out);
  });
  const std::size_t at = (bytes.size() + 7) / 8 * 8;
  bytes.resize(at + f.numbers.size() * sizeof(double));
  std::memcpy(bytes.data() + at, f.numbers.data(), f.numbers.size() * sizeof(double));
  return "{\"w\":" + std::to_string(frame.size().width) + ",\"h\":" + std::to_string(frame.size().height) +
         ",\"bg\":\"" + viz::frame_text::hex_colour(frame.background()) + "\",\"at\":" + std::to_string(at) +
         ",\"n\":" + std::to_string(f.numbers.size()) + ",\"strings\":" + f.strings +
         ",\"marks\":" + f.marks + "}";
}

std::string read_file(const char* path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace
}  // namespace scantrace::web

using namespace scantrace;

extern "C" {

// The trace `scantrace trace` writes for `input_json` ({"scene": path} | {"triangle": [[x, y] ×3],
// "colors"?, "width"?, "height"?} | {"polygon": [[[x, y], …], …], "colors"?, …}) under the
// options (fill options, "level", "triangles", "max_events"; "keep": record in memory and keep the
// trace for st_frames and st_kept_step, and with "text": false write no text): JSON Lines in the
// result's text.
EMSCRIPTEN_KEEPALIVE int st_trace(const char* input_json, const char* options_json) {
  return web::run([&] {
    const nlohmann::json in = web::parse_options(input_json);
    const nlohmann::json o = web::parse_options(options_json);
    if (o.value("keep", false)) {
      std::string text = web::trace_in_memory(in, o);
      web::result().text = std::move(text);
      return;
    }
    web::trace_to_file(in, o);
    web::result().text = web::read_file(web::kTraceFile);
    // The file's bytes (up to the cap) stay out of the module's memory between calls.
    std::remove(web::kTraceFile);
  });
}

// The display lists of the trace file at `path` (empty: the trace kept by st_trace's "keep"), steps [first, first + count) (all by default):
// {"steps": [{"kind", "triangle", "first_row", "last_row"}, …], "frames": [frame JSON, …]}
// at options.width × options.height (1280 × 720), planned as `replay` plans them. With
// options.encoding "binary" each frame is its numbers in the result's bytes and the rest
// (frame_numbers), its blocks as runs.
EMSCRIPTEN_KEEPALIVE int st_frames(const char* path, const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    // An empty path: the trace the last st_trace with options.keep kept.
    if (!*path && !web::kept_trace()) throw std::invalid_argument("frames: no trace kept (trace with keep: true first)");
    std::optional<trace::Trace> loaded;
    if (*path) loaded = trace::Trace::load(path);
    const trace::Trace& t = *path ? *loaded : *web::kept_trace();
    viz::StepOptions steps;
    steps.rows_per_step = o.value("rows_per_step", 0);
    steps.mode = viz::parse_replay_mode(o.value("mode", std::string("auto")));
    viz::FrameSequence s(t, steps, {o.value("width", 1280), o.value("height", 720)},
                         o.value("source", std::string(path)));
    if (o.contains("marked_pixel"))
      s.mark_on_every_frame(viz::CanvasPixel{o["marked_pixel"][0].get<std::int64_t>(),
                                             o["marked_pixel"][1].get<std::int64_t>()});
    const std::size_t n = s.steps().size();
    const std::size_t first = std::min<std::size_t>(o.value("first", std::size_t{0}), n);
    const std::size_t last = std::min<std::size_t>(first + o.value("count", n), n);
    std::string out = "{\"steps\":" + web::StepsJson()(s) + ",\"frames\":[";
    const bool raw = o.value("blocks", std::string("png")) == "rgba";
    const bool numbers = o.value("encoding", std::string("json")) == "binary";
    // The trace's byte cap on the result too: a scene's every step asked for at once is
    // hundreds of megabytes of frames.
    const std::int64_t max_bytes = web::max_bytes_option(o);
    for (std::size_t i = first; i < last; ++i) {
      out += (i > first ? "," : "") + (numbers ? web::frame_numbers(s.frame(i), web::result().bytes)
                                               : web::frame_json(s.frame(i), raw, web::result().bytes));
      if (static_cast<std::int64_t>(out.size() + web::result().bytes.size()) > max_bytes)
        throw std::runtime_error("frames: the " + std::to_string(last - first) +
                                 " frames asked for pass the budget max_bytes " +
                                 std::to_string(max_bytes) + " at frame " + std::to_string(i - first + 1) +
                                 "; ask for fewer (first, count)");
    }
    out += "]}";
    web::result().text = std::move(out);
  });
}

// What a page shows of one step of the kept trace: {"events": the trace's event count,
// "edge_table": face `triangle`'s edge_table event, "scanline": its scanline event of row `y`}
// (null where the trace has none), each as its line of the JSON Lines.
EMSCRIPTEN_KEEPALIVE int st_kept_step(int triangle, double y) {
  return web::run([&] {
    if (!web::kept_trace())
      throw std::invalid_argument("keptStep: no trace kept (trace with keep: true first)");
    const trace::Trace& t = *web::kept_trace();
    const auto line = [](const auto* e) {
      return e ? trace::event_to_json(trace::Event{*e}).dump() : std::string("null");
    };
    const trace::Scanline* row = t.find_scanline(triangle, static_cast<i64>(y));
    web::result().text = "{\"events\":" + std::to_string(t.events().size()) +
                         ",\"edge_table\":" + line(t.find_edge_table(triangle)) +
                         ",\"scanline\":" + line(row) + "}";
  });
}

// drawScantraceFrame's source (viz/frame_json.hpp), for a page to compile once.
EMSCRIPTEN_KEEPALIVE const char* st_canvas_script() { return viz::frame_canvas_script(); }

// The built-in demo scene (`scantrace demo`'s demo_scene.json) as scene JSON.
EMSCRIPTEN_KEEPALIVE int st_demo_scene() {
  return web::run([] { web::result().text = scene_to_json(demo_scene()); });
}

}  // extern "C"
