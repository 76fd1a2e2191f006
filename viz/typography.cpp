#include "viz/typography.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace scantrace::viz {

Typography::Typography(Size frame)
    // Wide or tall frames scale by their tighter side, so a text never outgrows its panel.
    : unit_(std::min(frame.height / 720.0, frame.width / 1280.0)) {}

int Typography::px(double design_pixels) const {
  return std::max(1, static_cast<int>(std::lround(design_pixels * unit_)));
}

double Typography::scale(TextStyle style) const {
  switch (style) {
    case TextStyle::small:
      return 0.42 * unit_;
    case TextStyle::body:
      return 0.48 * unit_;
    case TextStyle::strong:
      return 0.48 * unit_;
    case TextStyle::heading:
      return 0.6 * unit_;
    case TextStyle::title:
      return 0.9 * unit_;
    case TextStyle::huge:
      return 1.3 * unit_;
  }
  return 0.48 * unit_;
}

int Typography::thickness(TextStyle style) const {
  // Strokes grow more slowly than the glyphs: a one-pixel stroke reads best up to 1080p, and a
  // doubled one blurs small letters together (bold text is drawn twice, offset, instead).
  const double base = style == TextStyle::title || style == TextStyle::huge ? 2.0 : 1.0;
  return std::max(1, static_cast<int>(std::floor(base * unit_ + 0.3)));
}

bool Typography::bold(TextStyle style) {
  return style == TextStyle::strong || style == TextStyle::heading;
}

HersheyFont Typography::font(TextStyle style) const {
  return style == TextStyle::small ? HersheyFont::simplex : HersheyFont::duplex;
}

Size Typography::measure(const std::string& text, TextStyle style) const {
  int baseline = 0;
  Size s = hershey_text_size(text, font(style), scale(style), thickness(style), &baseline);
  if (bold(style)) s.width += std::max(1, px(0.8));
  return s;
}

int Typography::box_height(TextStyle style) const {
  int baseline = 0;
  const int ascent =
      hershey_text_size("A", font(style), scale(style), thickness(style), &baseline).height;
  return ascent + baseline;
}

int Typography::line_height(TextStyle style) const {
  int baseline = 0;
  const Size s = hershey_text_size("Ag", font(style), scale(style), thickness(style), &baseline);
  return s.height + baseline + px(style == TextStyle::small ? 3 : 5);
}

int Typography::draw(FrameView& image, const std::string& text, Point top_left, TextStyle style,
                     const Scalar& colour) const {
  // Lines of one style share one ascent ("A"), so mixed texts on one line share a baseline.
  int baseline = 0;
  const int ascent =
      hershey_text_size("A", font(style), scale(style), thickness(style), &baseline).height;
  const Point origin(top_left.x, top_left.y + ascent);
  image.text(text, origin, font(style), scale(style), colour, thickness(style), LINE_AA);
  if (bold(style))
    image.text(text, origin + Point(std::max(1, px(0.8)), 0), font(style), scale(style), colour,
               thickness(style), LINE_AA);
  return top_left.x + measure(text, style).width;
}

void Typography::draw_boxed(FrameView& image, const std::string& text, Point top_left,
                            TextStyle style, const Scalar& colour, const Scalar& box,
                            std::optional<Scalar> border, std::optional<Mark> mark) const {
  const int m = px(3);
  const Rect r(top_left.x - m, top_left.y - m, width(text, style) + 2 * m,
               box_height(style) + 2 * m);
  // Keep in step with boxed_area.
  image.rectangle(r, box, FILLED, LINE_8, std::move(mark));
  image.rectangle(r, border.value_or(colour), border ? px(2) : 1, LINE_AA);
  draw(image, text, top_left, style, colour);
}

Rect Typography::boxed_area(const std::string& text, Point top_left, TextStyle style,
                            bool bold_border) const {
  // draw_boxed's box is `m` around the text; its border line is centred on the box's edge and
  // anti-aliased one pixel wider.
  const int out = px(3) + (bold_border ? px(2) / 2 + 1 : 1);
  return {top_left.x - out, top_left.y - out, width(text, style) + 2 * out,
          box_height(style) + 2 * out};
}

std::vector<std::string> Typography::wrap(const std::string& text, TextStyle style,
                                          int max_width) const {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string line;
  for (std::string word; words >> word;) {
    std::string candidate = line;
    if (!candidate.empty()) candidate += ' ';
    candidate += word;
    if (!line.empty() && width(candidate, style) > max_width) {
      lines.push_back(line);
      line = word;
    } else {
      line = candidate;
    }
  }
  if (!line.empty()) lines.push_back(line);
  for (std::string& l : lines) std::replace(l.begin(), l.end(), '~', ' ');
  return lines;
}

}  // namespace scantrace::viz
