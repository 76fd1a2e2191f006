#pragma once
#include "fixed_point.hpp"

namespace scantrace {

// flat: one colour per polygon, the mean of its vertex colours (the course's flat shading).
// gouraud: vertex colours interpolated along the two active edges, then along the span.
enum class Shading { flat, gouraud };

// top_left: the half-open rule of design.md §3 — rows ceil(y_min) … ceil(y_max) − 1, columns
// ceil(x_left) … ceil(x_right) − 1 — so triangles sharing an edge never both own a pixel.
// closed: every centre inside or on the boundary (both span ends and the last row inclusive), the
// course's and OpenCV's behaviour, kept to show why shared edges get painted twice.
enum class FillRule { top_left, closed };

struct FillOptions {
  Shading shading = Shading::gouraud;
  FillRule fill_rule = FillRule::top_left;
  int subpixel_bits = kDefaultSubpixelBits;
};

const char* to_string(Shading s);
const char* to_string(FillRule r);

}  // namespace scantrace
