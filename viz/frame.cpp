#include "viz/frame.hpp"

namespace scantrace::viz {

const char* to_string(MarkKind kind) {
  switch (kind) {
    case MarkKind::none:
      return "none";
    case MarkKind::vertex:
      return "vertex";
    case MarkKind::active_point:
      return "active_point";
    case MarkKind::label:
      return "label";
    case MarkKind::inset:
      return "inset";
    case MarkKind::scanline:
      return "scanline";
    case MarkKind::span:
      return "span";
    case MarkKind::cells:
      return "cells";
  }
  return "none";
}

std::vector<Mark> Frame::marks() const {
  std::vector<Mark> out;
  for (const DrawOp& op : ops_)
    if (op.mark) out.push_back(*op.mark);
  return out;
}

std::vector<Mark> Frame::marks(MarkKind kind) const {
  std::vector<Mark> out;
  for (const DrawOp& op : ops_)
    if (op.mark && op.mark->kind == kind) out.push_back(*op.mark);
  return out;
}

FrameView::FrameView(Frame& frame) : frame_(&frame), area_({0, 0}, frame.size()) {}

FrameView FrameView::operator()(const Rect& r) const {
  // As an OpenCV region of interest of a region: relative to this area, never outside it.
  return FrameView(*frame_, (r + area_.tl()) & area_);
}

void FrameView::add(DrawOpBody body, std::optional<Mark> mark) {
  DrawOp op{std::move(body), std::nullopt, std::move(mark)};
  if (clipped_) op.clip = area_;
  frame_->add(std::move(op));
}

void FrameView::rectangle(const Rect& r, const Scalar& colour, int thickness, LineType type,
                          std::optional<Mark> mark) {
  add(RectOp{r, colour, thickness, type}, std::move(mark));
}

void FrameView::line(Point a, Point b, const Scalar& colour, int thickness, LineType type,
                     int shift, std::optional<Mark> mark) {
  add(LineOp{a, b, colour, thickness, type, shift}, std::move(mark));
}

void FrameView::circle(Point centre, int radius, const Scalar& colour, int thickness, LineType type,
                       std::optional<Mark> mark) {
  add(CircleOp{centre, radius, colour, thickness, type}, std::move(mark));
}

void FrameView::text(const std::string& text, Point origin, HersheyFont font, double scale,
                     const Scalar& colour, int thickness, LineType type, std::optional<Mark> mark) {
  add(TextOp{hershey_ascii(text), origin, font, scale, colour, thickness, type}, std::move(mark));
}

void FrameView::pixels(const Rect& area, std::shared_ptr<const std::vector<Vec3b>> bgr,
                       std::optional<Mark> mark) {
  add(PixelsOp{area, std::move(bgr)}, std::move(mark));
}

}  // namespace scantrace::viz
