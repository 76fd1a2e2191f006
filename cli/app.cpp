// The `scantrace` command: subcommand dispatch and exit status (docs/design.md §7):
// 0 success, 1 bad input data or a failed output (one line on stderr naming the file, the element
// and the problem), 2 usage error.
#include "cli/app.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/log.hpp"
#include "cli/validators.hpp"
#include "io/interrupt.hpp"

namespace {

constexpr int kExitSuccess = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

// CLI11's own message plus where to find help, naming the subcommand when one was reached.
std::string usage_failure(const CLI::App* app, const CLI::Error& e) {
  std::string help = "scantrace --help";
  for (const CLI::App* sub : app->get_subcommands())
    help = "scantrace " + sub->get_name() + " --help";
  return "scantrace: usage error: " + std::string(e.what()) + "\nRun '" + help +
         "' for more information.\n";
}

// Edits (insert, delete, substitute one character) that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The first word that is not an option of the main command, when it names no subcommand: CLI11
// would only say "A subcommand is required", which does not tell a typo from a
// missing word. The closest name within two edits is suggested.
std::optional<std::string> unknown_subcommand(const CLI::App& app, int argc, char** argv,
                                              std::span<const char* const> left_out) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.starts_with("-")) continue;  // -q, --quiet (the main command's only options)
    for (const char* name : left_out)
      if (word == name)
        return "'" + std::string(word) +
               "' is not in the demo's build (scripts/build.sh --demo builds what the demo "
               "runs); 'bash scripts/build.sh' builds every subcommand";
    std::string closest;
    std::size_t best = 3;
    for (const CLI::App* sub : app.get_subcommands({})) {
      if (sub->get_name() == word) return std::nullopt;
      const std::size_t d = edit_distance(word, sub->get_name());
      if (d < best) best = d, closest = sub->get_name();
    }
    return "unknown subcommand '" + std::string(word) + "'" +
           (closest.empty() ? "" : " (did you mean '" + closest + "'?)");
  }
  return std::nullopt;
}

}  // namespace

namespace scantrace::cli {

int run_app(int argc, char** argv, std::span<const AddCommand> add,
            std::span<const char* const> left_out) {
  scantrace::cli::setup_logging();
  scantrace::install_interrupt_handlers();

  CLI::App app("scantrace " SCANTRACE_VERSION
               ": an educational, exact edge-table scanline rasterizer.\n"
               "Fills triangles with the course's edge table and active edge list, flat or\n"
               "Gouraud, in painter's order, with exact integer coverage decisions.\n",
               "scantrace");
  app.set_version_flag("--version", "scantrace " SCANTRACE_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // app-level flags (--quiet) are accepted after the subcommand too
  app.failure_message(usage_failure);
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "print only warnings and errors");
  app.footer(
      "Run 'scantrace SUBCOMMAND --help' for the options of a subcommand.\n"
      "Exit status: 0 success, 1 bad input data (one line on stderr naming the\n"
      "file, the element and the problem), a failed write, or a failure of the\n"
      "exact method found by 'stress', 2 usage error, 3 'diff': the images differ,\n"
      "130/143 interrupted by\n"
      "SIGINT/SIGTERM (no output is left under its final name).");

  std::vector<scantrace::cli::Command> commands;
  for (const AddCommand add_command : add) commands.push_back(add_command(app));
  require_finite_numbers(app);
  // --quiet belongs to the main command but works after any subcommand: say so in their help.
  for (const auto& command : commands)
    command.app->footer(command.app->get_footer() +
                        "\n\nAlso: -q, --quiet (before or after the subcommand) prints only "
                        "warnings and errors.\n");
  if (const auto unknown = unknown_subcommand(app, argc, argv, left_out)) {
    std::fputs(("scantrace: usage error: " + *unknown +
                "\nRun 'scantrace --help' for the list of subcommands.\n")
                   .c_str(),
               stderr);
    return kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive as "errors" with status 0; every real parse error is a usage
    // error, whatever CLI11's own code for it.
    return app.exit(e) == 0 ? kExitSuccess : kExitUsage;
  }
  scantrace::cli::set_quiet(quiet);

  try {
    for (const auto& command : commands)
      if (command.app->parsed()) command.run();
  } catch (const scantrace::cli::ExitStatus& e) {
    return e.status;
  } catch (const scantrace::Interrupted& e) {
    spdlog::error("error: {}", e.what());
    return e.exit_status();  // 130 (SIGINT) or 143 (SIGTERM), as the shell reports a signal
  } catch (const std::bad_alloc&) {
    // The readers name their file (io/memory_budget.hpp's within_memory); anything else that
    // runs out still says what happened in one line, not "std::bad_alloc".
    spdlog::error("error: ran out of memory; SCANTRACE_MAX_MEMORY sets the budget that is checked "
                  "before large allocations");
    return kExitBadInput;
  } catch (const std::exception& e) {
    spdlog::error("error: {}", e.what());
    return kExitBadInput;
  }
  return kExitSuccess;
}

}  // namespace scantrace::cli
