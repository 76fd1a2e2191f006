#include "stress/families.hpp"

#include "stress/generators.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress {

const char* to_string(Family f) {
  switch (f) {
    case Family::random:
      return "random";
    case Family::slivers:
      return "slivers";
    case Family::near_collinear:
      return "near-collinear";
    case Family::huge:
      return "huge";
    case Family::subpixel:
      return "subpixel";
    case Family::near_horizontal:
      return "near-horizontal";
    case Family::near_vertical:
      return "near-vertical";
    case Family::centres:
      return "centres";
    case Family::half_way:
      return "half-way";
    case Family::long_spans:
      return "long-spans";
    case Family::meshes:
      return "meshes";
  }
  return "?";
}

const char* description(Family f) {
  switch (f) {
    case Family::random:
      return "triangles of every size (0.5 to 700 px) on and around a 512x512 canvas, on grids "
             "of 1 to 1/4096 px";
    case Family::slivers:
      return "width below 1 px, length up to 16,000 px (canvases up to 16,384 px long)";
    case Family::near_collinear:
      return "area from 1e-6 px^2, vertices on the 1/4096 grid (subpixel bits 12)";
    case Family::huge:
      return "one, two or three vertices up to +-1e9 px away from a 512x512 canvas";
    case Family::subpixel:
      return "the whole triangle inside a box smaller than one pixel";
    case Family::near_horizontal:
      return "an edge of slope dy/dx from 1e-6 to 0.1 hovering over a row of pixel centres";
    case Family::near_vertical:
      return "the same, transposed: dx/dy from 1e-6 to 0.1";
    case Family::centres:
      return "every vertex exactly on a pixel centre (integer coordinates)";
    case Family::half_way:
      return "every vertex exactly half-way between pixel centres (k + 0.5)";
    case Family::long_spans:
      return "Gouraud spans across canvases 16,384 px wide and 4 to 24 px tall";
    case Family::meshes:
      return "fans of 1,000 triangles and random triangulations of a rectangle: each pixel of "
             "it exactly once";
  }
  return "?";
}

bool parse_family(std::string_view name, Family& out) {
  for (Family f : kAllFamilies)
    if (name == to_string(f)) {
      out = f;
      return true;
    }
  return false;
}

StressCase generate(Family family, std::uint64_t seed, std::uint64_t index) {
  StressCase c;
  c.family = family;
  c.seed = seed;
  c.index = index;
  Rng rng = case_rng(seed, static_cast<int>(family), index);
  switch (family) {
    case Family::random:
      detail::generate_random(rng, c);
      break;
    case Family::slivers:
      detail::generate_sliver(rng, c);
      break;
    case Family::near_collinear:
      detail::generate_near_collinear(rng, c);
      break;
    case Family::huge:
      detail::generate_huge(rng, c);
      break;
    case Family::subpixel:
      detail::generate_subpixel(rng, c);
      break;
    case Family::near_horizontal:
      detail::generate_near_horizontal(rng, c);
      break;
    case Family::near_vertical:
      detail::generate_near_vertical(rng, c);
      break;
    case Family::centres:
      detail::generate_on_lattice(rng, c, 0.0);
      break;
    case Family::half_way:
      detail::generate_on_lattice(rng, c, 0.5);
      break;
    case Family::long_spans:
      detail::generate_long_span(rng, c);
      break;
    case Family::meshes:
      detail::generate_mesh(rng, c);
      break;
  }
  return c;
}

}  // namespace scantrace::stress
