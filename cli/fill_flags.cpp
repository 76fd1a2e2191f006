#include "cli/fill_flags.hpp"

#include <CLI/CLI.hpp>

#include "cli/option_choice.hpp"

namespace scantrace::cli {

FillOptions FillFlags::options() const {
  FillOptions o;
  o.shading = chosen<Shading>(shading);
  o.fill_rule = chosen<FillRule>(fill_rule);
  o.subpixel_bits = subpixel_bits;
  o.method = chosen<Method>(method);
  return o;
}

void add_fill_flags(CLI::App& command, FillFlags& flags) {
  add_choice<Shading>(command, "--shading", flags.shading)->capture_default_str();
  add_choice<FillRule>(command, "--fill-rule", flags.fill_rule)->capture_default_str();
  command
      .add_option("--subpixel-bits", flags.subpixel_bits,
                  "vertices are snapped to 1/2^N pixel, then every\n"
                  "coverage decision is exact integer arithmetic\n"
                  "(0 = whole pixels)")
      ->check(CLI::Range(0, kMaxSubpixelBits))
      ->capture_default_str();
  add_choice<Method>(command, "--method", flags.method)->capture_default_str();
  command.add_flag("--clamp-colors", flags.clamp_colors,
                   "clamp scene colours outside [0, 1] into it, with a\n"
                   "warning (without it they are an error)");
}

}  // namespace scantrace::cli
