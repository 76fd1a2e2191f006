#include "trace.hpp"

#include <algorithm>
#include <fstream>
#include <istream>
#include <nlohmann/json.hpp>

#include "event_json.hpp"
#include "io/input_file.hpp"
#include "io/json_input.hpp"
#include "io/memory_budget.hpp"
#include "trace_check.hpp"

namespace scantrace::trace {
namespace {

// What a loaded trace costs in memory per byte of its file: the events, their index and the
// vector's growth: 2.7 and 3.0 measured on the course scene's scanline- and pixel-level traces (see
// docs/robustness.md). A file is refused when its size times this exceeds the memory available.
constexpr std::uint64_t kMemoryPerTraceByte = 4;

// Lines longer than this are not a trace line but damage (or another file). The longest real
// lines are edge tables and scanlines of many-sided polygons, far below it.
constexpr std::size_t kMaxLineBytes = std::size_t{16} << 20;

enum class LineRead { line, last_line_unterminated, too_long, end };

// std::getline would read a 10 GB line into memory before its length could be checked; this
// stops at kMaxLineBytes.
LineRead read_line(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      return line.empty() ? LineRead::end : LineRead::last_line_unterminated;
    }
    if (c == '\n') return LineRead::line;
    if (line.size() == kMaxLineBytes) return LineRead::too_long;
    line.push_back(static_cast<char>(c));
  }
}

std::uint64_t pixel_key(i64 x, i64 y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
         static_cast<std::uint32_t>(y);
}

}  // namespace

std::string progress_of(const std::vector<Event>& events) {
  std::size_t n = events.size();
  std::string s = "it holds the header and " + std::to_string(n == 0 ? 0 : n - 1) + " events";
  // The last triangle and row reached, from the end: what a user needs to resume or re-trace.
  for (auto it = events.rbegin(); it != events.rend(); ++it) {
    if (const Pixel* p = std::get_if<Pixel>(&*it))
      return s + ", the last at triangle " + std::to_string(p->triangle) + ", pixel (" +
             std::to_string(p->x) + ", " + std::to_string(p->y) + ")";
    if (const Scanline* row = std::get_if<Scanline>(&*it))
      return s + ", the last at triangle " + std::to_string(row->triangle) + ", row " +
             std::to_string(row->y);
    const int tri = std::visit(
        [](const auto& v) -> int {
          if constexpr (requires { v.triangle; })
            return v.triangle;
          else
            return -1;
        },
        *it);
    if (tri >= 0) return s + ", the last for triangle " + std::to_string(tri);
  }
  return s;
}

std::string Trace::progress() const {
  return progress_of(events_);
}

const PixelWrite& PixelHistory::final() const {
  if (writes.empty()) throw std::out_of_range("no triangle wrote this pixel");
  return writes.back();
}

Trace Trace::load(const std::filesystem::path& path, bool drop_unfinished_last_line) {
  // A FIFO or a device is refused before the stream opens it (a FIFO blocked that open for
  // good, /dev/zero was one endless line): io/input_file.hpp.
  if (const std::string problem = regular_file_problem(path); !problem.empty())
    throw TraceError(path.string() + ": cannot open trace: " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TraceError(path.string() + ": cannot open trace");
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (!ec)
    check_memory(static_cast<std::uint64_t>(bytes) * kMemoryPerTraceByte,
                 "loading this trace of " + format_bytes(bytes), path.string(), "");
  try {
    return parse(in, path.string(), drop_unfinished_last_line);
  } catch (const std::bad_alloc&) {
    throw TraceError(path.string() + ": " + out_of_memory_problem());
  }
}

Trace Trace::parse(std::istream& in, const std::string& name, bool drop_unfinished_last_line) {
  std::vector<Event> events;
  std::string line;
  std::size_t number = 0;
  bool dropped = false;
  for (LineRead r; (r = read_line(in, line)) != LineRead::end;) {
    ++number;
    if (r == LineRead::last_line_unterminated && drop_unfinished_last_line) {
      dropped = true;
      break;
    }
    const std::string where = name + ":" + std::to_string(number) + ": ";
    if (r == LineRead::too_long)
      throw TraceError(where + "line longer than " + std::to_string(kMaxLineBytes >> 20) +
                       " MiB: not a trace event (a damaged file, or not a trace)");
    if (line.empty()) throw TraceError(where + "empty line (one JSON object per line expected)");
    // Nesting is bounded before nlohmann sees the line (its recursive parts overflow the stack on
    // a few hundred thousand levels); the position is this line's and the bracket's column.
    if (const auto at = json_input::find_excess_nesting(line))
      throw TraceError(name + ":" + std::to_string(number) + ":" + std::to_string(*at + 1) + ": " +
                       json_input::nesting_problem());
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::parse_error& e) {
      // A last line without its newline is where a writer was cut off, not damage in the middle.
      if (r == LineRead::last_line_unterminated && !events.empty())
        throw TraceError(where +
                         "the file ends in the middle of this line: the trace is "
                         "incomplete (cut off while being written); " +
                         progress_of(events));
      throw TraceError(where + "not valid JSON (" + e.what() + ")");
    } catch (const nlohmann::json::out_of_range&) {
      // Thrown by parse for a number beyond a double ("1e999", found by fuzzing).
      throw TraceError(where + "a number is too large for a double");
    }
    // The format and version are checked before anything else is decoded: a later version may
    // change any other key, and "version 2 is not supported" is the message that helps then.
    if (number == 1) {
      auto text = [&](const char* key) {
        return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>()
                                                                      : std::string();
      };
      if (text("type") != "header") throw TraceError(where + "the first line must be the header");
      const std::string format = text("format");
      if (format != kFormatName)
        throw TraceError(where + "format is \"" + format + "\", not a scantrace trace");
      const std::int64_t version = j.contains("version") && j["version"].is_number_integer()
                                       ? j["version"].get<std::int64_t>()
                                       : 0;
      if (version != kFormatVersion)
        throw TraceError(where + "trace format version " + std::to_string(version) +
                         " is not supported (this build reads version " +
                         std::to_string(kFormatVersion) + ")");
    }
    try {
      events.push_back(event_from_json(j));
    } catch (const std::exception& e) {
      // A header option's unknown name says "header: …" itself (trace/event_json.cpp).
      const std::string what = e.what();
      throw TraceError(where + (what.rfind("header: ", 0) == 0 ? "" : "malformed event: ") + what);
    }
  }
  if (events.empty()) throw TraceError(name + ": empty file, not a trace");
  Trace t = from_events(std::move(events), name);
  t.dropped_last_line_ = dropped;
  return t;
}

Trace Trace::from_events(std::vector<Event> events, const std::string& name,
                         const std::optional<RowRange>& pixel_columns) {
  Trace t;
  t.name_ = name;
  if (events.empty() || !std::holds_alternative<Header>(events.front()))
    throw TraceError(name + ": a trace starts with its header");
  // Replay allocates from the canvas size: refuse what no writer could have produced.
  const CanvasSize canvas = std::get<Header>(events.front()).canvas;
  if (canvas.width <= 0 || canvas.height <= 0 ||
      static_cast<long long>(canvas.width) * canvas.height > kMaxCanvasPixels)
    throw TraceError(name + ":1: header: canvas " + std::to_string(canvas.width) + "x" +
                     std::to_string(canvas.height) +
                     " is not a positive size of at most 2^28 pixels");
  for (std::size_t i = 1; i < events.size(); ++i) {
    const Event& e = events[i];
    auto fail = [&](const std::string& what) {
      throw TraceError(name + ":" + std::to_string(i + 1) + ": " + what);
    };
    if (t.footer_) fail("event after the footer");
    if (std::holds_alternative<Header>(e)) fail("a second header");
    if (const Footer* f = std::get_if<Footer>(&e)) {
      t.footer_ = *f;
      continue;
    }
    const int tri = std::visit(
        [](const auto& v) -> int {
          if constexpr (requires { v.triangle; })
            return v.triangle;
          else
            return -1;
        },
        e);
    if (!t.index_.count(tri)) t.order_.push_back(tri);
    TriangleIndex& ix = t.index_[tri];
    if (std::holds_alternative<TriangleBegin>(e))
      ix.begin = i;
    else if (std::holds_alternative<EdgeTableEvent>(e))
      ix.edge_table = i;
    else if (std::holds_alternative<TriangleEnd>(e))
      ix.end = i;
    else if (std::holds_alternative<TriangleSkipped>(e))
      ix.skipped = i;
    else if (const Scanline* s = std::get_if<Scanline>(&e)) {
      ix.scanlines[s->y] = i;
      t.rows_[s->y].push_back(i);
    } else if (const Pixel* p = std::get_if<Pixel>(&e)) {
      if (!ix.pixels.empty() && std::get<Pixel>(events[ix.pixels.back()]).y > p->y)
        ix.pixels_by_row = false;
      ix.pixels.push_back(i);
      t.pixel_events_[pixel_key(p->x, p->y)].push_back(i);
    }
  }
  // The cheap consistency checks run on every trace before anyone replays, steps or queries it:
  // a record that contradicts itself must not be narrated (trace_check.hpp; the thorough ones
  // are `scantrace check`).
  check_consistency(events, name, CheckDepth::cheap, pixel_columns);
  t.events_ = std::move(events);
  return t;
}

const Header& Trace::header() const {
  return std::get<Header>(events_.front());
}

std::vector<int> Trace::triangles() const {
  return order_;
}

const Trace::TriangleIndex& Trace::at(int t) const {
  auto it = index_.find(t);
  if (it == index_.end())
    throw std::out_of_range(name_ + ": triangle " + std::to_string(t) + " is not in the trace");
  return it->second;
}

const TriangleBegin* Trace::find_triangle_begin(int t) const {
  auto it = index_.find(t);
  if (it == index_.end() || !it->second.begin) return nullptr;
  return &std::get<TriangleBegin>(events_[*it->second.begin]);
}

const EdgeTableEvent* Trace::find_edge_table(int t) const {
  auto it = index_.find(t);
  if (it == index_.end() || !it->second.edge_table) return nullptr;
  return &std::get<EdgeTableEvent>(events_[*it->second.edge_table]);
}

const Scanline* Trace::find_scanline(int t, i64 y) const {
  auto it = index_.find(t);
  if (it == index_.end()) return nullptr;
  auto row = it->second.scanlines.find(y);
  return row == it->second.scanlines.end() ? nullptr : &std::get<Scanline>(events_[row->second]);
}

const TriangleBegin& Trace::triangle_begin(int t) const {
  at(t);  // names a triangle that is not in the trace at all
  if (const TriangleBegin* b = find_triangle_begin(t)) return *b;
  throw std::out_of_range(name_ + ": triangle " + std::to_string(t) + " has no triangle_begin");
}

const EdgeTableEvent& Trace::edge_table(int t) const {
  at(t);
  if (const EdgeTableEvent* e = find_edge_table(t)) return *e;
  throw std::out_of_range(name_ + ": triangle " + std::to_string(t) + " has no edge table");
}

bool Trace::has_scanline(int t, i64 y) const {
  return find_scanline(t, y) != nullptr;
}

const Scanline& Trace::scanline(int t, i64 y) const {
  at(t);
  if (const Scanline* s = find_scanline(t, y)) return *s;
  throw std::out_of_range(name_ + ": triangle " + std::to_string(t) + " has no scanline " +
                          std::to_string(y) + " in the trace");
}

std::vector<const Scanline*> Trace::scanlines(int t) const {
  std::vector<const Scanline*> out;
  for (const auto& [y, i] : at(t).scanlines) out.push_back(&std::get<Scanline>(events_[i]));
  return out;
}

std::vector<const Pixel*> Trace::pixels(int t) const {
  std::vector<const Pixel*> out;
  for (std::size_t i : at(t).pixels) out.push_back(&std::get<Pixel>(events_[i]));
  return out;
}

std::vector<const Scanline*> Trace::scanlines(int t, i64 first_row, i64 last_row) const {
  std::vector<const Scanline*> out;
  const auto& rows = at(t).scanlines;
  for (auto it = rows.lower_bound(first_row); it != rows.end() && it->first <= last_row; ++it)
    out.push_back(&std::get<Scanline>(events_[it->second]));
  return out;
}

std::vector<const Pixel*> Trace::pixels(int t, i64 first_row, i64 last_row) const {
  const TriangleIndex& ix = at(t);
  const auto y_of = [&](std::size_t i) { return std::get<Pixel>(events_[i]).y; };
  auto begin = ix.pixels.begin(), end = ix.pixels.end();
  if (ix.pixels_by_row) {
    // Rows in order (as the fill writes them): the rows asked for are found by bisection, so a
    // replay's frame costs its own rows, not every pixel of the triangle.
    begin = std::partition_point(begin, end, [&](std::size_t i) { return y_of(i) < first_row; });
    end = std::partition_point(begin, end, [&](std::size_t i) { return y_of(i) <= last_row; });
  }
  std::vector<const Pixel*> out;
  for (auto it = begin; it != end; ++it)
    if (const i64 y = y_of(*it); y >= first_row && y <= last_row)
      out.push_back(&std::get<Pixel>(events_[*it]));
  return out;
}

std::optional<TriangleEnd> Trace::triangle_end(int t) const {
  const auto& ix = at(t);
  if (!ix.end) return std::nullopt;
  return std::get<TriangleEnd>(events_[*ix.end]);
}

std::optional<TriangleSkipped> Trace::skipped(int t) const {
  const auto& ix = at(t);
  if (!ix.skipped) return std::nullopt;
  return std::get<TriangleSkipped>(events_[*ix.skipped]);
}

PixelHistory Trace::pixel_history(i64 x, i64 y) const {
  PixelHistory h;
  // Pixel events (level pixel) are the record itself; without them the write is reconstructed
  // from the scanline: the pixel is in the span, and its colour is the flat colour or the linear
  // interpolation of the span's end colours (Gouraud colour is linear along a row).
  std::map<std::size_t, PixelWrite> by_event;
  if (auto it = pixel_events_.find(pixel_key(x, y)); it != pixel_events_.end())
    for (std::size_t i : it->second) {
      const Pixel& p = std::get<Pixel>(events_[i]);
      if (p.x == x && p.y == y) by_event[i] = {p.triangle, p.color, true};
    }
  if (auto it = rows_.find(y); it != rows_.end())
    for (std::size_t i : it->second) {
      const Scanline& s = std::get<Scanline>(events_[i]);
      if (!s.span || !at(s.triangle).pixels.empty()) continue;
      // A general polygon's row has one span per inside interval.
      std::optional<Span> span;
      std::optional<SpanColors> colors;
      if (s.intervals) {
        for (const Interval& iv : *s.intervals)
          if (iv.pixels.contains(x)) span = iv.pixels, colors = iv.colors;
      } else if (s.span->contains(x)) {
        span = s.span, colors = s.span_colors;
      }
      if (!span) continue;
      Color c;
      if (colors) {
        const i64 last = span->x_end - 1 - span->x_begin;
        const double w = last > 0 ? static_cast<double>(x - span->x_begin) / last : 0.0;
        c = colors->begin + (colors->end - colors->begin) * w;
      } else if (const auto& ix = at(s.triangle); ix.begin) {
        const TriangleBegin& b = std::get<TriangleBegin>(events_[*ix.begin]);
        if (b.flat_color) c = *b.flat_color;
      }
      by_event[i] = {s.triangle, c, false};
    }
  for (auto& [i, w] : by_event) h.writes.push_back(w);
  return h;
}

}  // namespace scantrace::trace
