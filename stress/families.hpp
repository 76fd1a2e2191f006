#pragma once
// The named families of stress cases: each aims at one way a scanline fill can go wrong
// (docs/accuracy.md says which method falls into which).
#include <array>
#include <string_view>

namespace scantrace::stress {

enum class Family {
  random,           // triangles of every size on and around the canvas, grids of 1 to 1/4096 px
  slivers,          // width below 1 px, length up to 16,000 px
  near_collinear,   // area down to 1e-6 px² (on the 1/4096 grid)
  huge,             // vertices up to ±1e9 around a 512×512 canvas
  subpixel,         // the whole triangle inside a box smaller than a pixel
  near_horizontal,  // an edge with slope dy/dx down to 1e-6, hovering over a row of centres
  near_vertical,    // the same, transposed
  centres,          // every vertex exactly on a pixel centre (integers)
  half_way,         // every vertex exactly half-way between centres (k + 0.5)
  long_spans,       // Gouraud spans across canvases 16,384 px wide
  meshes,           // fans of 1,000 triangles and random triangulations of a rectangle
};

inline constexpr std::array<Family, 11> kAllFamilies{
    Family::random,   Family::slivers,         Family::near_collinear, Family::huge,
    Family::subpixel, Family::near_horizontal, Family::near_vertical,  Family::centres,
    Family::half_way, Family::long_spans,      Family::meshes};

const char* to_string(Family f);    // "random", "slivers", "near-collinear", …
const char* description(Family f);  // one line, for --help and the docs
// The family named `name`, or false when there is none.
bool parse_family(std::string_view name, Family& out);

}  // namespace scantrace::stress
