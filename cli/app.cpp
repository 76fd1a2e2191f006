// The `scantrace` command: subcommand dispatch and exit status (docs/design.md §7):
// 0 success, 1 bad input data or a failed output (one line on stderr naming the file, the element
// and the problem), 2 usage error.
#include "cli/app.hpp"

#include <exception>
#include <new>
#include <string>
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

}  // namespace

namespace scantrace::cli {

int run_app(int argc, char** argv, std::span<const AddCommand> add) {
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
