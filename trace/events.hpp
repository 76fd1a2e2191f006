#pragma once
// The events of trace format v1 (docs/design.md §5) as value types. One event is one line of a
// .jsonl trace; to_json/from_json live in event_json.hpp.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "src/tracer.hpp"
#include "src/vec2.hpp"

namespace scantrace::trace {

using i64 = std::int64_t;

inline constexpr const char* kFormatName = "scantrace-trace";
inline constexpr int kFormatVersion = 1;

struct CanvasSize {
  int width = 0, height = 0;
};

struct Header {
  std::string format = kFormatName;
  int version = kFormatVersion;
  CanvasSize canvas;
  // The options by value; their names (src/option_table.hpp) are what the JSON holds.
  Shading shading = Shading::gouraud;
  FillRule fill_rule = FillRule::top_left;
  int subpixel_bits = 8;
  TraceLevel level = TraceLevel::scanline;
  std::string generator;  // "scantrace X.Y.Z"
  // Present in traces of general polygons (docs/polygons.md).
  std::optional<WindingRule> winding_rule = std::nullopt;
  // Written only when they differ from the course's render (painter's order, no culling), so
  // that traces of course scenes keep their bytes.
  Visibility visibility = Visibility::painter;
  Cull cull = Cull::none;
  // The canvas colour the fill started from; written only when it is not white (the course's),
  // so that a replay can show the finished image as it was rendered.
  Color background{1, 1, 1};
};

struct TriangleBegin {
  int triangle = 0;
  std::vector<Vec2> vertices;  // as given
  std::vector<Vec2> snapped;   // on the subpixel grid: what coverage is decided on
  std::vector<Color> colors;
  std::optional<double> depth;
  std::optional<Color> flat_color;  // flat shading only
  // General polygons: the vertex indices of each contour, in order (`vertices` holds all the
  // contours' vertices one after another). Empty for a single contour.
  std::vector<std::vector<int>> contours = {};
  // Z-buffer traces: the depth of each vertex, from which the depth at every pixel centre follows
  // (src/depth_plane.hpp) — what a replay needs to redo the depth test. Empty otherwise.
  std::vector<double> vertex_depths = {};
};

struct EdgeEntry {
  int edge = 0;   // the edge from vertex `edge` to the next vertex of its contour
  Vec2 from, to;  // snapped endpoints, in that direction
  double y_min = 0, y_max = 0;
  double x_at_y_min = 0;            // x of the upper endpoint
  double dx_dy = 0;                 // the inverse slope: x moves by dx_dy per row
  i64 first_row = 0, last_row = 0;  // scanlines it is active on (first > last: none)
};

struct HorizontalEntry {
  int edge = 0;
  Vec2 from, to;
  double y = 0;
  std::string reason;
};

struct EdgeTableEvent {
  int triangle = 0;
  std::vector<EdgeEntry> edges;  // sorted by first row (y_min), then id
  std::vector<HorizontalEntry> horizontal;
};

// The record of an EdgeCrossing (src/tracer.hpp): where an active edge crosses the row.
struct EdgeCrossing {
  int edge = 0;
  double x = 0;  // the exact intersection with the row, rounded to double
  std::optional<int> winding = std::nullopt;  // general polygons: +1 going down, -1 up
  friend bool operator==(const EdgeCrossing&, const EdgeCrossing&) = default;
};

struct ActivePoint {
  double x = 0;
  int edge = 0;
  Color color;
};

struct Span {
  i64 x_begin = 0, x_end = 0;  // half-open, clipped to the canvas
  i64 size() const { return x_end - x_begin; }
  bool contains(i64 x) const { return x >= x_begin && x < x_end; }
};

struct SpanColors {
  Color begin;  // colour of pixel x_begin
  Color end;    // colour of pixel x_end - 1
};

// General polygons: one inside interval of a row, between the active edge where the winding rule
// turns inside and the one where it turns outside again.
struct Interval {
  int left_edge = 0, right_edge = 0;
  double x_left = 0, x_right = 0;    // the bounding edges' intersections with the row
  Span pixels;                       // half-open, clipped to the canvas, never empty
  std::optional<SpanColors> colors;  // Gouraud: colours of its first and last pixel
};

struct Scanline {
  int triangle = 0;
  i64 y = 0;
  std::vector<int> entered, retired;
  std::vector<EdgeCrossing> active_edges;
  std::vector<ActivePoint> active_points;  // sorted by x
  std::optional<Span> span;
  std::optional<SpanColors> span_colors;  // Gouraud
  // General polygons: every inside interval, left to right; `span` is then the first of them.
  std::optional<std::vector<Interval>> intervals = std::nullopt;
};

// The outcome of a pixel's depth test (z-buffer renders only).
struct PixelDepthTest {
  bool passed = true;
  double depth = 0;              // the triangle's depth at the pixel centre
  std::optional<double> stored;  // the buffer's depth before the test; none: empty (+inf)
};

struct Pixel {
  int triangle = 0;
  i64 x = 0, y = 0;
  Color color;
  double t = 0;  // weight along the span: 0 at the left active point, 1 at the right
  std::optional<PixelDepthTest> depth_test;
};

struct TriangleEnd {
  int triangle = 0;
  i64 rows = 0, pixels = 0;
};

struct TriangleSkipped {
  int triangle = 0;
  std::string reason;
};

struct Footer {
  i64 events = 0;  // events between header and footer
  bool truncated = false;
};

using Event = std::variant<Header, TriangleBegin, EdgeTableEvent, Scanline, Pixel, TriangleEnd,
                           TriangleSkipped, Footer>;

// The `type` of an event as it appears in the file.
const char* type_name(const Event& e);

}  // namespace scantrace::trace
