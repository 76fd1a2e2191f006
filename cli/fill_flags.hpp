#pragma once
// The options that choose how triangles are filled, shared by every subcommand that fills
// (render now; trace and explain later), so they are spelled and explained the same everywhere.
#include <string>

#include "src/fill_options.hpp"
#include "src/option_table.hpp"

namespace CLI {
class App;
}

namespace scantrace::cli {

struct FillFlags {
  // Names from the option tables (src/option_table.hpp), checked by the options' choices.
  std::string shading = option_table<Shading>().default_name();
  std::string fill_rule = option_table<FillRule>().default_name();
  int subpixel_bits = kDefaultSubpixelBits;
  std::string method = option_table<Method>().default_name();
  bool clamp_colors = false;  // for the SCENE these commands read (cli/scene_input.hpp)

  FillOptions options() const;
};

// Adds --shading, --fill-rule, --subpixel-bits and --method to `command`, writing into `flags`
// (which must outlive the parse). Invalid values are usage errors.
void add_fill_flags(CLI::App& command, FillFlags& flags);

}  // namespace scantrace::cli
