#pragma once
// Text on frames. Every size is given for a 1280x720 frame and scaled with the frame, so a
// 1920x1080 video reads like the 720p one, only sharper. The Hershey fonts (viz/hershey.hpp) are
// ASCII only: texts use "x", "-" and "..." rather than typographic signs.
#include <optional>
#include <string>
#include <vector>

#include "viz/frame.hpp"
#include "viz/hershey.hpp"

namespace scantrace::viz {

enum class TextStyle { small, body, strong, heading, title, huge };

class Typography {
 public:
  explicit Typography(Size frame);

  // Frame pixels per pixel of the 720p design.
  double unit() const { return unit_; }
  int px(double design_pixels) const;

  Size measure(const std::string& text, TextStyle style) const;  // width, ascent
  // Height of a line of text from its top to the bottom of its descenders.
  int box_height(TextStyle style) const;
  int width(const std::string& text, TextStyle style) const { return measure(text, style).width; }
  // Distance between the tops of two consecutive lines.
  int line_height(TextStyle style) const;

  // Draws `text` with its top-left corner at `top_left`; returns the x just after it.
  int draw(FrameView& image, const std::string& text, Point top_left, TextStyle style,
           const Scalar& colour) const;
  // Draws `text` on a filled box with a margin, e.g. a label over the magnified canvas; the box
  // has a thin border in the text colour, or a bold one in `border`.
  void draw_boxed(FrameView& image, const std::string& text, Point top_left, TextStyle style,
                  const Scalar& colour, const Scalar& box,
                  std::optional<Scalar> border = std::nullopt,
                  std::optional<Mark> mark = std::nullopt) const;
  // The frame area draw_boxed covers, box, border and its anti-aliased edge included: what a
  // label must keep clear of other marks.
  Rect boxed_area(const std::string& text, Point top_left, TextStyle style,
                  bool bold_border = false) const;
  // Splits `text` at spaces into lines no wider than `max_width`. A '~' is a space that does not
  // break ("ceil(y_max)~-~1"); the lines returned have it replaced.
  std::vector<std::string> wrap(const std::string& text, TextStyle style, int max_width) const;

 private:
  double scale(TextStyle style) const;
  int thickness(TextStyle style) const;
  HersheyFont font(TextStyle style) const;
  static bool bold(TextStyle style);

  double unit_;
};

}  // namespace scantrace::viz
