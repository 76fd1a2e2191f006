#include "cli/fill_flags.hpp"

#include <CLI/CLI.hpp>

namespace scantrace::cli {

FillOptions FillFlags::options() const {
  FillOptions o;
  o.shading = shading == "flat" ? Shading::flat : Shading::gouraud;
  o.fill_rule = fill_rule == "closed" ? FillRule::closed : FillRule::top_left;
  o.subpixel_bits = subpixel_bits;
  // Validated by the option's check, so parsing cannot fail here.
  parse_method(method.c_str(), o.method);
  return o;
}

void add_fill_flags(CLI::App& command, FillFlags& flags) {
  command
      .add_option("--shading", flags.shading,
                  "flat: each triangle in the mean of its vertex colours\n"
                  "gouraud: vertex colours interpolated along the edges,\n"
                  "then along each scanline")
      ->check(CLI::IsMember({"flat", "gouraud"}))
      ->capture_default_str();
  command
      .add_option("--fill-rule", flags.fill_rule,
                  "top-left: a pixel on an edge shared by two triangles\n"
                  "belongs to exactly one of them (no overlap, no gaps)\n"
                  "closed: every centre inside or on the boundary is\n"
                  "filled, so shared edges are painted twice (the\n"
                  "course's and OpenCV's rule)")
      ->check(CLI::IsMember({"top-left", "closed"}))
      ->capture_default_str();
  command
      .add_option("--subpixel-bits", flags.subpixel_bits,
                  "vertices are snapped to 1/2^N pixel, then every\n"
                  "coverage decision is exact integer arithmetic\n"
                  "(0 = whole pixels)")
      ->check(CLI::Range(0, kMaxSubpixelBits))
      ->capture_default_str();
  command
      .add_option("--method", flags.method,
                  "exact: fixed-point edge table, exact decisions\n"
                  "float: the textbook loop, x += 1/m in float32\n"
                  "double: x recomputed per row in double\n"
                  "halfspace: bounding box + exact edge functions\n"
                  "(docs/accuracy.md: what each gets wrong)")
      ->check(CLI::IsMember({"exact", "float", "double", "halfspace"}))
      ->capture_default_str();
  command.add_flag("--clamp-colors", flags.clamp_colors,
                   "clamp scene colours outside [0, 1] into it, with a\n"
                   "warning (without it they are an error)");
}

}  // namespace scantrace::cli
