#include "viz/svg_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "viz/frame_text.hpp"
#include "viz/glyph_table.hpp"

namespace scantrace::viz {
namespace {

using frame_text::hex_colour;
using frame_text::markup_number;

// A pixel-centre coordinate (OpenCV) as an SVG coordinate.
std::string at(double v) {
  return markup_number(v + 0.5);
}

struct Writer {
  std::ostringstream& out;
  GlyphTable& glyphs;  // the glyphs the text places, written once in <defs>

  void operator()(const RectOp& r) const {
    if (r.thickness < 0) {
      out << "<rect x=\"" << r.rect.x << "\" y=\"" << r.rect.y << "\" width=\"" << r.rect.width
          << "\" height=\"" << r.rect.height << "\" fill=\"" << hex_colour(r.colour) << "\"/>\n";
      return;
    }
    // The outline runs through the centres of the first and last rows and columns.
    out << "<rect x=\"" << at(r.rect.x) << "\" y=\"" << at(r.rect.y) << "\" width=\""
        << std::max(0, r.rect.width - 1) << "\" height=\"" << std::max(0, r.rect.height - 1)
        << "\" fill=\"none\" stroke=\"" << hex_colour(r.colour) << "\" stroke-width=\""
        << r.thickness << "\"/>\n";
  }
  void operator()(const LineOp& l) const {
    const double s = 1.0 / (1 << l.shift);
    out << "<line x1=\"" << at(l.a.x * s) << "\" y1=\"" << at(l.a.y * s) << "\" x2=\""
        << at(l.b.x * s) << "\" y2=\"" << at(l.b.y * s) << "\" stroke=\"" << hex_colour(l.colour)
        << "\" stroke-width=\"" << l.thickness << "\" stroke-linecap=\"round\"/>\n";
  }
  void operator()(const CircleOp& c) const {
    out << "<circle cx=\"" << at(c.centre.x) << "\" cy=\"" << at(c.centre.y) << "\" r=\"";
    if (c.thickness < 0)  // the disc covers the pixels whose centres are within the radius
      out << markup_number(c.radius + 0.5) << "\" fill=\"" << hex_colour(c.colour) << "\"/>\n";
    else
      out << c.radius << "\" fill=\"none\" stroke=\"" << hex_colour(c.colour)
          << "\" stroke-width=\"" << c.thickness << "\"/>\n";
  }
  void operator()(const TextOp& t) const {
    // Each glyph placed with <use> from <defs>: the glyph's path is relative to its origin, the
    // group's stroke is inherited by every use (a point lands where hershey_strokes puts it).
    out << "<g fill=\"none\" stroke=\"" << hex_colour(t.colour) << "\" stroke-width=\""
        << t.thickness << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>"
        << frame_text::xml_escape(t.text) << "</title>";
    const double s = hershey_scale(t.scale);
    for (const PlacedGlyph& g : hershey_layout(t.text, t.font, t.scale, t.origin))
      out << "<use xlink:href=\"#g" << glyphs.id(g.c, t.font, s) << "\" x=\"" << at(g.origin.x)
          << "\" y=\"" << at(g.origin.y) << "\"/>";
    out << "</g>\n";
  }
  void operator()(const PixelsOp& p) const {
    if (p.area.area() == 1) {  // a grid's centre dot: a rectangle, not an image
      const Vec3b& c = p.bgr->front();
      (*this)(RectOp{p.area, Scalar(c[0], c[1], c[2]), FILLED});
      return;
    }
    out << "<image x=\"" << p.area.x << "\" y=\"" << p.area.y << "\" width=\"" << p.area.width
        << "\" height=\"" << p.area.height << "\" preserveAspectRatio=\"none\" xlink:href=\""
        << frame_text::png_data_uri(p) << "\"/>\n";
  }
};

// <defs> of the glyphs `glyphs` holds: path gN is glyph N's strokes relative to its origin.
std::string glyph_defs(const GlyphTable& glyphs) {
  if (glyphs.glyphs().empty()) return {};
  std::string out = "<defs>\n";
  for (std::size_t id = 0; id < glyphs.glyphs().size(); ++id) {
    // Appended piece by piece: a literal plus a temporary string is GCC 12's -Wrestrict false
    // positive (frame_json.cpp).
    out += "<path id=\"g";
    out += std::to_string(id);
    out += "\" d=\"";
    for (const auto& stroke : glyphs.strokes(static_cast<int>(id)))
      for (std::size_t i = 0; i < stroke.size(); ++i) {
        out += i == 0 ? 'M' : 'L';
        out += markup_number(stroke[i].x);
        out += ' ';
        out += markup_number(stroke[i].y);
      }
    out += "\"/>\n";
  }
  return out + "</defs>\n";
}

}  // namespace

std::string to_svg(const Frame& frame) {
  std::ostringstream body;
  GlyphTable glyphs;
  // Consecutive ops confined to one area share a group clipped to it and moved to its corner.
  std::optional<Rect> open;
  int clips = 0;
  for (const DrawOp& op : frame.ops()) {
    if (op.clip != open) {
      if (open) body << "</g>\n";
      open = op.clip;
      if (open) {
        const Rect& c = *open;
        body << "<clipPath id=\"c" << clips << "\"><rect x=\"0\" y=\"0\" width=\"" << c.width
             << "\" height=\"" << c.height << "\"/></clipPath>\n"
             << "<g transform=\"translate(" << c.x << "," << c.y << ")\" clip-path=\"url(#c" << clips
             << ")\">\n";
        ++clips;
      }
    }
    std::visit(Writer{body, glyphs}, op.body);
  }
  if (open) body << "</g>\n";
  std::ostringstream out;
  const Size s = frame.size();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
         "version=\"1.1\" width=\""
      << s.width << "\" height=\"" << s.height << "\" viewBox=\"0 0 " << s.width << " " << s.height
      << "\">\n"
      << "<rect width=\"" << s.width << "\" height=\"" << s.height << "\" fill=\""
      << hex_colour(frame.background()) << "\"/>\n"
      << glyph_defs(glyphs) << body.str();
  out << "</svg>\n";
  return out.str();
}

}  // namespace scantrace::viz
