#pragma once
// Text metrics and glyph strokes of the two Hershey fonts frames use, without OpenCV
// (docs/design.md §6, "Text"). Layout depends on how wide a text is, so every backend must agree
// on it: the composer measures here, with OpenCV's own arithmetic (cv::getTextSize: the sum of
// the glyphs' advances times the scale, the thickness added, rounded as cvRound), and the glyph
// data is the Hershey fonts OpenCV embeds, generated from Debian's hershey-fonts-data
// (viz/hershey/generate.py). The SVG and canvas backends draw the same strokes, so a label has the
// same extent in every backend.
#include <string>
#include <string_view>
#include <vector>

#include "viz/geometry.hpp"

namespace scantrace::viz {

// OpenCV's font numbers (cv::FONT_HERSHEY_SIMPLEX, cv::FONT_HERSHEY_DUPLEX).
enum class HersheyFont { simplex = 0, duplex = 2 };

// The text as the fonts draw it, in ASCII: typographic characters (’ “ ” – — … × − ≤ ≥ →) as their
// look-alikes, anything else not printable ASCII as '?'. Every text op holds this form, so that
// every backend (OpenCV's putText among them) draws the same characters.
std::string hershey_ascii(std::string_view text);

// cv::getTextSize: width and cap height of `text`; `baseline` (when given) receives the depth of
// the descenders below the baseline.
Size hershey_text_size(std::string_view text, HersheyFont font, double scale, int thickness,
                       int* baseline = nullptr);

// The strokes of `text` as putText draws them from `origin` (on the baseline): polylines in frame
// coordinates (double; OpenCV rounds them to 1/65536 pixel).
std::vector<std::vector<Point2d>> hershey_strokes(std::string_view text, HersheyFont font,
                                                  double scale, Point origin);

// The same strokes in two parts, so that a backend can write each glyph's shape once and place it
// many times (viz/glyph_table.hpp): where putText puts each character of `text`, and a glyph's
// strokes relative to that place. hershey_strokes() is their sum, point by point, in the same
// double arithmetic (origin + relative point), so the parts give its numbers exactly.
struct PlacedGlyph {
  unsigned char c;  // the character drawn ('?' for anything not printable ASCII)
  Point2d origin;   // its strokes' points are origin + hershey_glyph_strokes(c, ...)'s
};
// OpenCV's scale as putText uses it: quantised to 1/65536.
double hershey_scale(double scale);
std::vector<PlacedGlyph> hershey_layout(std::string_view text, HersheyFont font, double scale,
                                        Point origin);
// The polylines of one glyph at the quantised scale `s` (hershey_scale), relative to its origin.
std::vector<std::vector<Point2d>> hershey_glyph_strokes(unsigned char c, HersheyFont font,
                                                        double s);

}  // namespace scantrace::viz
