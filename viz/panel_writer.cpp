#include "viz/panel_writer.hpp"

#include <algorithm>

#include "src/image.hpp"
#include "viz/palette.hpp"

namespace scantrace::viz {

void draw_swatch(FrameView& frame, Rect where, const Color& c) {
  const Scalar bgr(to_byte(static_cast<float>(c.b)), to_byte(static_cast<float>(c.g)),
                   to_byte(static_cast<float>(c.r)));
  frame.rectangle(where, bgr, FILLED);
  frame.rectangle(where, palette::kMutedText, 1);
}

PanelWriter::PanelWriter(FrameView& frame, Rect area, const Typography& type)
    : frame_(frame(area & Rect(0, 0, frame.width(), frame.height()))),
      area_(0, 0, frame_.width(), frame_.height()),
      type_(type),
      y_(0) {}

void PanelWriter::gap(double design_pixels) {
  y_ += type_.px(design_pixels);
}

void PanelWriter::heading(const std::string& text) {
  draw_line(text, TextStyle::heading, palette::kText, 0);
  y_ += type_.px(2);
}

void PanelWriter::paragraph(const std::string& text, TextStyle style, const Scalar& colour) {
  for (const std::string& l : type_.wrap(text, style, area_.width)) line(l, style, colour);
}

std::vector<std::string> PanelWriter::fitted(const std::string& text, TextStyle style,
                                             int indent) const {
  if (type_.width(text, style) + indent <= area_.width) return {text};
  // Wrapped at its spaces, each piece keeping the line's leading spaces (a formula's indent).
  const std::size_t lead = text.find_first_not_of(' ');
  if (lead == std::string::npos) return {text};
  const std::string pad(lead, ' ');
  std::vector<std::string> pieces =
      type_.wrap(text.substr(lead), style, area_.width - indent - type_.width(pad, style));
  for (std::string& p : pieces) p.insert(0, pad);
  return pieces;
}

void PanelWriter::draw_line(const std::string& text, TextStyle style, const Scalar& colour,
                            int indent) {
  // A line that would run below the panel is not drawn: a reader is better told nothing than
  // shown the top half of a formula.
  if (y_ + type_.box_height(style) <= area_.height)
    type_.draw(frame_, text, {area_.x + indent, y_}, style, colour);
  y_ += type_.line_height(style);
}

void PanelWriter::line(const std::string& text, TextStyle style, const Scalar& colour, int indent) {
  for (const std::string& piece : fitted(text, style, indent)) draw_line(piece, style, colour, indent);
}

void PanelWriter::table(const std::vector<TableColumn>& columns,
                        const std::vector<TableRow>& rows) {
  const TextStyle body = TextStyle::body, head = TextStyle::small;
  const int marker_width = type_.px(6), marker_gap = type_.px(6);
  std::vector<int> widths(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    widths[c] = type_.width(columns[c].header, head);
    for (const TableRow& r : rows)
      if (c < r.cells.size()) widths[c] = std::max(widths[c], type_.width(r.cells[c], body));
  }
  int total = marker_width + marker_gap;
  for (int w : widths) total += w;
  // Spread what is left between the columns, within reason.
  const int spare = std::max(0, area_.width - total);
  const int gutter =
      columns.size() > 1 ? std::min(type_.px(28), spare / static_cast<int>(columns.size() - 1)) : 0;
  std::vector<int> x(columns.size());
  int at = area_.x + marker_width + marker_gap;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    x[c] = at;
    at += widths[c] + gutter;
  }
  auto place = [&](std::size_t c, const std::string& text, TextStyle style) {
    return columns[c].right_aligned ? x[c] + widths[c] - type_.width(text, style) : x[c];
  };
  for (std::size_t c = 0; c < columns.size(); ++c)
    type_.draw(frame_, columns[c].header, {place(c, columns[c].header, head), y_}, head,
               palette::kMutedText);
  y_ += type_.line_height(head);
  const int row_height = type_.line_height(body);
  for (const TableRow& r : rows) {
    const int pad = type_.px(2);
    if (r.highlighted)
      frame_.rectangle(
          {area_.x, y_ - pad, std::min(at - gutter, area_.x + area_.width) - area_.x, row_height},
          palette::kHighlightRow, FILLED);
    if (r.marker)
      frame_.rectangle({area_.x, y_ - pad, marker_width, row_height - pad}, *r.marker, FILLED);
    for (std::size_t c = 0; c < columns.size() && c < r.cells.size(); ++c)
      type_.draw(frame_, r.cells[c], {place(c, r.cells[c], body), y_}, body,
                 r.muted ? palette::kMutedText : palette::kText);
    y_ += row_height;
  }
}

void PanelWriter::swatch(const Color& c, const std::string& text, TextStyle style) {
  const int h = type_.line_height(style) - type_.px(4);
  draw_swatch(frame_, {area_.x, y_ - type_.px(1), h * 2, h}, c);
  type_.draw(frame_, text, {area_.x + h * 2 + type_.px(8), y_}, style, palette::kText);
  y_ += type_.line_height(style) + type_.px(2);
}

void PanelWriter::formula(const std::vector<std::string>& lines) {
  const int pad = type_.px(6);
  std::vector<std::string> fitted_lines;
  for (const std::string& l : lines)
    for (std::string& piece : fitted(l, TextStyle::body, pad)) fitted_lines.push_back(std::move(piece));
  const int h = static_cast<int>(fitted_lines.size()) * type_.line_height(TextStyle::body) + pad;
  // A formula is drawn whole or not at all (its last line lost under the legend read as a
  // complete formula); nothing after it is drawn either, so the panel never skips a step.
  if (y_ + h > area_.height) {
    y_ = area_.height;
    return;
  }
  frame_.rectangle({area_.x, y_ - pad, area_.width, h + pad}, palette::kFormulaBox, FILLED);
  for (const std::string& l : fitted_lines) draw_line(l, TextStyle::body, palette::kText, pad);
  y_ += pad;
}

}  // namespace scantrace::viz
