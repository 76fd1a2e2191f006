// The demo's build (SCANTRACE_TOOLS off: `scantrace` alone, cli/main_render.cpp) leaves out the
// subcommands the demo does not run: naming one is a usage error that says how to build it, not
// "unknown subcommand". Run in-process through run_app with such a list, as that build's main()
// does (the suite itself is the full build).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "cli/app.hpp"
#include "cli_test_support.hpp"

namespace {

// run_app's exit status and what it wrote on stderr.
std::pair<int, std::string> run(std::vector<std::string> words) {
  using namespace scantrace::cli;
  scantrace::test::TempDir dir;
  const std::string err_file = (dir / "err.txt").string();
  std::fflush(stderr);
  const int saved = dup(fileno(stderr));
  REQUIRE(std::freopen(err_file.c_str(), "w", stderr) != nullptr);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  constexpr AddCommand commands[]{add_render_command};
  constexpr const char* left_out[]{"stress", "bench"};
  const int status = run_app(static_cast<int>(argv.size()), argv.data(), commands, left_out);
  std::fflush(stderr);
  dup2(saved, fileno(stderr));
  close(saved);
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  return {status, text.str()};
}

}  // namespace

TEST_CASE("a subcommand left out of the demo's build says how to build it", "[command]") {
  const auto [status, err] = run({"scantrace", "-q", "bench", "--quick"});
  CHECK(status == 2);
  CHECK(err ==
        "scantrace: usage error: 'bench' is not in the demo's build (scripts/build.sh --demo "
        "builds what the demo runs); 'bash scripts/build.sh' builds every subcommand\n"
        "Run 'scantrace --help' for the list of subcommands.\n");
  // A misspelt one is still a typo of what the build has.
  const auto [typo_status, typo] = run({"scantrace", "rendr"});
  CHECK(typo_status == 2);
  CHECK_THAT(typo, Catch::Contains("did you mean 'render'?"));
}
