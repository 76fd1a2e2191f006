#pragma once
// Writes a column of text blocks (headings, paragraphs, tables, colour swatches, formulas) into a
// rectangle of a frame, top to bottom, the way the side panel and the cards are built.
#include <optional>
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "src/color.hpp"
#include "viz/palette.hpp"
#include "viz/typography.hpp"

namespace scantrace::viz {

struct TableColumn {
  std::string header;
  bool right_aligned = true;  // numbers line up on their last digit
};

struct TableRow {
  std::vector<std::string> cells;
  std::optional<Scalar> marker;  // a colour bar before the row (an edge's colour)
  bool highlighted = false;      // pale background: the entry this step is about
  bool muted = false;            // grey text: no longer (or not yet) in play
};

// Everything is drawn into the area only (a view of the frame, in the area's own coordinates), so
// a text that runs long is cut at the area's edge instead of painting over its neighbours.
class PanelWriter {
 public:
  PanelWriter(FrameView& frame, Rect area, const Typography& type);

  // For drawings of a caller's own, in the same coordinates as y() and left().
  FrameView& canvas() { return frame_; }
  int y() const { return y_; }
  int bottom() const { return area_.height; }
  int left() const { return 0; }
  int width() const { return area_.width; }
  bool full() const { return y_ >= bottom(); }
  void gap(double design_pixels);
  void move_to(int y) { y_ = y; }

  void heading(const std::string& text);
  // Wrapped to the panel's width.
  void paragraph(const std::string& text, TextStyle style = TextStyle::body,
                 const Scalar& colour = palette::kText);
  // One line; wrapped at its spaces when wider than the panel (keeping its leading spaces), and
  // not drawn when it would run below the panel: no text is ever cut at the panel's edge.
  void line(const std::string& text, TextStyle style = TextStyle::body,
            const Scalar& colour = palette::kText, int indent = 0);
  void table(const std::vector<TableColumn>& columns, const std::vector<TableRow>& rows);
  // A colour sample followed by its text.
  void swatch(const Color& c, const std::string& text, TextStyle style = TextStyle::body);
  // Lines in a tinted box: the formula being applied; drawn whole or not at all.
  void formula(const std::vector<std::string>& lines);

 private:
  std::vector<std::string> fitted(const std::string& text, TextStyle style, int indent) const;
  void draw_line(const std::string& text, TextStyle style, const Scalar& colour, int indent);
  FrameView frame_;  // the area of the frame
  Rect area_;
  const Typography& type_;
  int y_;
};

// A filled square of colour `c` (RGB in [0, 1]) with a thin border.
void draw_swatch(FrameView& frame, Rect where, const Color& c);

}  // namespace scantrace::viz
