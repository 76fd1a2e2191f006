#pragma once
// The `scantrace` command line: the main app (its help, --version, --quiet, the exit statuses of
// docs/design.md §7) around the subcommands it is given. Two executables run it: `scantrace`
// itself with `render` alone, and `scantrace-tools` with every subcommand (cli/main_render.cpp
// says why they are two).
#include <span>

#include "cli/commands.hpp"

namespace scantrace::cli {

using AddCommand = Command (*)(CLI::App&);

// Parses argv against the subcommands `add` registers, runs the one given, and returns the exit
// status: 0 success, 1 bad input data or a failed output, 2 usage error, 130/143 interrupted.
// `left_out`: subcommands this build does not have (the demo's build, cli/main.cpp); naming one is
// a usage error that says how to build it.
int run_app(int argc, char** argv, std::span<const AddCommand> add,
            std::span<const char* const> left_out = {});

}  // namespace scantrace::cli
