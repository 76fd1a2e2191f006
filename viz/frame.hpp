#pragma once
// A frame as a display list (docs/design.md §6): the ordered drawing operations of one frame, in
// frame pixels, composed once and drawn by any backend — OpenCV's raster (viz/opencv/), SVG
// (viz/svg_frame.hpp), a browser canvas from its JSON (viz/frame_json.hpp). Like Skia's recorded
// pictures and matplotlib's artists, the frame decides what is drawn and where; a backend only
// decides how a line or a glyph becomes pixels.
//
// An operation's numbers are those of the OpenCV call that draws it (a line's end points in
// 1/2^shift pixels, a circle's integer centre and radius, text at its baseline origin with a
// Hershey font and scale), so the OpenCV backend repeats the call exactly and its frames are the
// pixels the composer drew before there was a display list. Every operation may be confined to an
// area of the frame (`clip`, what drawing into an OpenCV region of interest did): its coordinates
// are then relative to the area's top-left corner, and nothing outside the area is drawn.
//
// Operations that mark something the trace implies carry a Mark: what it is (a vertex, an active
// point, a label, ...), its name ("v0", "e2", the label's text) and the frame area it covers. The
// tests read the marks instead of guessing them from pixels.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "viz/geometry.hpp"
#include "viz/hershey.hpp"

namespace scantrace::viz {

enum class MarkKind {
  none,
  vertex,        // a vertex marker
  active_point,  // an active point's marker
  label,         // a boxed label on the magnified canvas
  inset,         // a zoom inset
  scanline,      // the current row's line
  span,          // the span's box (one op per side)
  cells,         // the canvas pixels of a view
};
const char* to_string(MarkKind kind);

struct Mark {
  MarkKind kind = MarkKind::none;
  std::string what;  // "v0", "e1", the label's text, "y = 12"
  Rect box;          // the frame area the mark keeps for itself (absolute frame coordinates)
  int layer = 0;     // 0: the main view, k: zoom inset k
};

struct RectOp {  // cv::rectangle
  Rect rect;
  Scalar colour;
  int thickness = 1;  // FILLED: filled
  LineType type = LineType::plain;
};
struct LineOp {  // cv::line; the end points are in 1/2^shift pixels
  Point a, b;
  Scalar colour;
  int thickness = 1;
  LineType type = LineType::plain;
  int shift = 0;
};
struct CircleOp {  // cv::circle
  Point centre;
  int radius = 0;
  Scalar colour;
  int thickness = 1;  // FILLED: a disc
  LineType type = LineType::plain;
};
struct TextOp {  // cv::putText, `origin` on the baseline
  std::string text;
  Point origin;
  HersheyFont font = HersheyFont::simplex;
  double scale = 1;
  Scalar colour;
  int thickness = 1;
  LineType type = LineType::aa;
};
struct PixelsOp {  // a block of pixels copied onto the frame (the magnified canvas cells)
  Rect area;
  // area.width * area.height, row by row; shared, so that a frame's ops copy cheaply and the
  // composer reads what it drew without a second copy.
  std::shared_ptr<const std::vector<Vec3b>> bgr;
};

using DrawOpBody = std::variant<RectOp, LineOp, CircleOp, TextOp, PixelsOp>;

struct DrawOp {
  DrawOpBody body;
  std::optional<Rect> clip;  // absolute; the op's coordinates are relative to clip->tl()
  std::optional<Mark> mark;
  // The op's offset: where its coordinates' origin lies on the frame.
  Point origin() const { return clip ? clip->tl() : Point{}; }
};

class Frame {
 public:
  Frame() = default;
  Frame(Size size, Scalar background) : size_(size), background_(background) {}

  Size size() const { return size_; }
  const Scalar& background() const { return background_; }
  const std::vector<DrawOp>& ops() const { return ops_; }
  void add(DrawOp op) { ops_.push_back(std::move(op)); }
  // Every operation's mark, in drawing order.
  std::vector<Mark> marks() const;
  std::vector<Mark> marks(MarkKind kind) const;

 private:
  Size size_;
  Scalar background_;
  std::vector<DrawOp> ops_;
};

// What composing code draws on: a frame, or an area of it with its own coordinates (the way an
// OpenCV region of interest was used). Drawing calls have OpenCV's names and arguments.
class FrameView {
 public:
  explicit FrameView(Frame& frame);

  // The area `r` (in this view's coordinates, clipped to it) as a view of its own.
  FrameView operator()(const Rect& r) const;
  int width() const { return area_.width; }
  int height() const { return area_.height; }
  Size size() const { return area_.size(); }
  // The view's area on the frame.
  const Rect& area() const { return area_; }
  Frame& frame() const { return *frame_; }

  void rectangle(const Rect& r, const Scalar& colour, int thickness = 1,
                 LineType type = LineType::plain, std::optional<Mark> mark = {});
  void line(Point a, Point b, const Scalar& colour, int thickness = 1,
            LineType type = LineType::plain, int shift = 0, std::optional<Mark> mark = {});
  void circle(Point centre, int radius, const Scalar& colour, int thickness = 1,
              LineType type = LineType::plain, std::optional<Mark> mark = {});
  void text(const std::string& text, Point origin, HersheyFont font, double scale,
            const Scalar& colour, int thickness, LineType type, std::optional<Mark> mark = {});
  void pixels(const Rect& area, std::shared_ptr<const std::vector<Vec3b>> bgr,
              std::optional<Mark> mark = {});
  void pixel(Point p, const Vec3b& colour) {
    pixels({p.x, p.y, 1, 1}, std::make_shared<const std::vector<Vec3b>>(1, colour));
  }

 private:
  FrameView(Frame& frame, Rect area) : frame_(&frame), area_(area), clipped_(true) {}
  void add(DrawOpBody body, std::optional<Mark> mark);

  Frame* frame_;
  Rect area_;             // absolute
  bool clipped_ = false;  // an area: its ops carry it as their clip (the whole frame: none)
};

}  // namespace scantrace::viz
