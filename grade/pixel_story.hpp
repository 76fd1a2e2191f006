#pragma once
// `why`: the history of one pixel in the algorithm's own terms. Every face whose bounding box
// holds the pixel centre, in drawing order, with what the fill did about the pixel — skipped (and
// why), row Y not among its rows, the centre left or right of the row's span (with the active
// points that decided it), or written (with the colour, the span weight t and, under a z-buffer,
// the depth test) — what the fill rule did with a centre exactly on an edge or a vertex, and the
// final colour with the write it came from.
//
// Only the faces around the pixel are traced, and only row Y: the cost is that of the faces whose
// bounding box holds the pixel, not that of the scene.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "src/scene.hpp"
#include "trace/events.hpp"

namespace scantrace::grade {

// What happened to the pixel in one face's fill.
enum class Outcome {
  skipped,         // the fill did not draw the face at all (`skip_reason`)
  row_outside,     // row Y is not among the face's scanlines
  left_of_span,    // X < the span's first pixel
  right_of_span,   // X >= the span's end
  written,         // the face wrote the pixel
  depth_rejected,  // z-buffer: the face covers the pixel but the depth test kept the old value
};
const char* to_string(Outcome o);

struct FaceStep {
  int face = 0;
  double depth = 0;  // mean of the vertex depths (the painter's key)
  std::vector<Vec2> vertices;
  std::vector<Color> colors;
  Outcome outcome = Outcome::skipped;
  std::string skip_reason;                        // skipped
  trace::i64 first_row = 0, last_row = -1;        // the face's scanlines (rows of its edge table)
  std::vector<trace::ActivePoint> active_points;  // on row Y, sorted by x
  std::optional<trace::Span> span;                // on row Y, half-open
  std::optional<trace::SpanColors> span_colors;   // Gouraud
  std::optional<Color> color;                     // written / depth_rejected: the colour computed
  double t = 0;                                   // weight along the span
  std::optional<trace::PixelDepthTest> depth_test;
  std::string outline;    // "" or "edge" / "vertex": the centre lies exactly on the face's outline
  int outline_edge = -1;  // the edge (from vertex i to i + 1) or the vertex i
};

struct PixelStory {
  int x = 0, y = 0;
  int width = 0, height = 0;
  std::string shading, fill_rule, visibility;
  Color background;
  std::vector<FaceStep> faces;  // in drawing order
  Color final_color;
  std::optional<int> final_face;   // none: the background
  std::vector<std::string> notes;  // the boundary rule, in words

  nlohmann::json to_json() const;
  // The whole story, several lines.
  std::string to_text() const;
  // One paragraph (the diff report's examples): the faces that wrote the pixel, and those of
  // `also` (whichever way the fill placed the pixel: its row's span and where x falls).
  std::string summary(const std::vector<int>& also = {}) const;
};

// Throws std::out_of_range when (x, y) is not on the canvas. The scene must be valid. The work
// and the memory are linear in the faces around the pixel (one row and one pixel event of each);
// a long run stops on SIGINT/SIGTERM (io/interrupt.hpp).
// `extra_margin` widens the faces' bounding boxes (by default only by the snapping margin): the
// diff's examples also trace faces that end a pixel short of (x, y).
PixelStory why(const Scene& scene, const FillOptions& options, int x, int y,
               double extra_margin = 0);

// What one face around the pixel costs why() at most: its five events (the begin event's
// vertices, the edge table, row y's active points and span), its FaceStep and its sentence,
// rounded up; the caller checks faces × this against the memory budget first.
inline constexpr std::uint64_t kWhyBytesPerFace = 4096;

// The faces whose bounding box (widened by `margin` px) holds the centre (x, y), in scene order.
std::vector<int> faces_around(const Scene& scene, int x, int y, double margin = 0);

}  // namespace scantrace::grade
