#pragma once
// What the text backends of the display list (SVG, the canvas JSON) write alike: numbers, colours,
// escaped strings, and a block of pixels as a PNG data URI.
#include <string>
#include <string_view>

#include "viz/frame.hpp"

namespace scantrace::viz::frame_text {

// At most two decimals, trailing zeros dropped ("12.5", "3", "-0.25").
std::string markup_number(double v);
// The number a reader of markup_number(v)'s digits gets, as a double (the canvas frame's numbers
// without their text, viz/frame_json.hpp's to_numbers).
double number_value(double v);
// The same digits by snprintf("%.2f") alone: markup_number()'s reference
// (tests/viz/test_frame_text.cpp).
std::string number_by_printf(double v);
// "#rrggbb" of a BGR colour.
std::string hex_colour(const Scalar& c);
// `s` with & < > " escaped (XML attribute and text content), and every character XML 1.0 forbids
// (C0 controls but tab, LF and CR; U+FFFE, U+FFFF) and every byte that is not well-formed UTF-8
// (a lone surrogate too) replaced by U+FFFD: always well-formed XML, whatever the bytes.
std::string xml_escape(const std::string& s);
// Standard base64 (RFC 4648, with padding), as data: URLs need it.
std::string base64(std::string_view bytes);
// `s` as a JSON string literal, quotes included.
std::string json_string(const std::string& s);
// "data:image/png;base64,..." of the block's pixels.
std::string png_data_uri(const PixelsOp& pixels);

}  // namespace scantrace::viz::frame_text
