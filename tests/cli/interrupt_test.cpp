// The promises of docs/robustness.md and the README about interrupted and failed runs, each run
// as a user would meet it: SIGINT during `render` and during a replay into a frame directory
// (exit 130, nothing under the output's name, no temporary), a second signal ending a run at once
// (from the handler, while the first is still waiting for the run to reach a check), and an
// existing output surviving a run that fails or is interrupted.
#include <signal.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli_test_support.hpp"

using scantrace::test::catches_signal;
using scantrace::test::Child;
using scantrace::test::file_names;
using scantrace::test::has_content;
using scantrace::test::read_text;
using scantrace::test::run_scantrace;
using scantrace::test::spawn_scantrace;
using scantrace::test::TempDir;
using scantrace::test::temporary;
using scantrace::test::write_text;

namespace {

// `faces` copies of a triangle covering half of a size×size canvas: a render of
// faces × size²/2 pixel writes, seconds long, with a small scene file.
std::string heavy_scene(int size, int faces) {
  const std::string s = std::to_string(size);
  std::string text = R"({"vertices": [[0,0],[)" + s + R"(,0],[0,)" + s +
                     R"(]], "vcolors": [[1,0,0],[0,1,0],[0,0,1]], "depth": [1,1,1], "width": )" +
                     s + R"(, "height": )" + s + R"(, "faces": [)";
  for (int i = 0; i < faces; ++i) text += i ? ",[0,1,2]" : "[0,1,2]";
  return text + "]}";
}

// Bytes that are not what any run here writes: an output that must survive.
const std::string kPrecious = "an earlier result that must survive\n";

}  // namespace

TEST_CASE("SIGINT during render: exit 130, no PNG, no temporary, the old PNG kept",
          "[command][robustness][signal]") {
  TempDir dir;
  write_text(dir / "heavy.json", heavy_scene(1000, 1500));
  write_text(dir / "out.png", kPrecious);
  Child child(spawn_scantrace(dir.path(), {"render", "heavy.json", "-o", "out.png"}));
  // Started: the handlers are installed (the first thing scantrace does), so the signal is
  // caught wherever it lands — while the scene loads, renders or is being written.
  REQUIRE(child.wait_until([&] { return catches_signal(child.pid(), SIGINT); }));
  child.signal(SIGINT);
  CHECK(child.wait() == 130);
  CHECK_THAT(read_text(dir / ".stderr.txt"),
             Catch::Contains("interrupted by SIGINT; no output was written under its final name"));
  CHECK(read_text(dir / "out.png") == kPrecious);
  CHECK(file_names(dir.path()) == std::vector<std::string>{"heavy.json", "out.png"});
}

TEST_CASE("a second signal ends the run at once and removes the temporaries",
          "[command][robustness][signal]") {
  TempDir dir;
  // The render loop does not look at the flag the first signal sets (only the step before the
  // PNG is written does): the second signal must end the run from the handler itself.
  write_text(dir / "heavy.json", heavy_scene(1000, 1500));
  write_text(dir / "out.png", kPrecious);
  Child child(spawn_scantrace(dir.path(), {"render", "heavy.json", "-o", "out.png"}));
  REQUIRE(child.wait_until([&] { return catches_signal(child.pid(), SIGINT); }));
  // Two different signals (two of the same kind would merge into one while pending), with the
  // run held by SIGSTOP so that both are pending together however the scheduler runs it: on
  // SIGCONT the second is delivered before the run can act on the first.
  child.signal(SIGSTOP);
  child.signal(SIGINT);
  child.signal(SIGTERM);
  child.signal(SIGCONT);
  const int status = child.wait();
  CHECK((status == 130 || status == 143));
  CHECK_THAT(read_text(dir / ".stderr.txt"),
             Catch::Contains("interrupted again; temporary files removed, exiting now"));
  CHECK(read_text(dir / "out.png") == kPrecious);
  CHECK(file_names(dir.path()) == std::vector<std::string>{"heavy.json", "out.png"});
}

TEST_CASE("a second signal while a trace is being written removes its temporary file",
          "[command][robustness][signal]") {
  TempDir dir;
  write_text(dir / "t.jsonl", kPrecious);
  Child child(spawn_scantrace(dir.path(), {"trace", "--triangle", "0,0 2000,0 0,2000", "--size",
                                           "2000x2000", "--level", "pixel", "-o", "t.jsonl"}));
  const std::filesystem::path temp = dir / temporary("t.jsonl", child.pid());
  REQUIRE(child.wait_until([&] { return has_content(temp); }));
  // SIGSTOP holds the run between the two signals, so that the first cannot be acted on before
  // the second arrives, however the scheduler runs it: both are delivered on SIGCONT.
  child.signal(SIGSTOP);
  child.signal(SIGINT);
  child.signal(SIGTERM);
  child.signal(SIGCONT);
  const int status = child.wait();
  CHECK((status == 130 || status == 143));
  CHECK_THAT(read_text(dir / ".stderr.txt"), Catch::Contains("interrupted again"));
  CHECK(read_text(dir / "t.jsonl") == kPrecious);
  CHECK(file_names(dir.path()) == std::vector<std::string>{"t.jsonl"});
}

TEST_CASE("SIGINT during a replay into a frame directory leaves no directory and no temporary",
          "[command][robustness][signal]") {
  TempDir dir;
  REQUIRE(run_scantrace(dir.path(), {"-q", "trace", "--triangle", "10,10 300,60 80,700", "--size",
                                     "400x720", "-o", "t.jsonl"})
              .exit_code == 0);
  Child child(
      spawn_scantrace(dir.path(), {"replay", "t.jsonl", "--rows-per-step", "1", "-o", "frames/"}));
  // Started: the temporary directory holds a frame.
  const std::filesystem::path temp = dir / temporary("frames", child.pid());
  REQUIRE(child.wait_until([&] {
    std::error_code ec;
    return std::filesystem::is_directory(temp, ec) && !std::filesystem::is_empty(temp, ec);
  }));
  child.signal(SIGINT);
  CHECK(child.wait() == 130);
  CHECK_THAT(read_text(dir / ".stderr.txt"), Catch::Contains("interrupted by SIGINT"));
  CHECK(file_names(dir.path()) == std::vector<std::string>{"t.jsonl"});
}

TEST_CASE("an existing output survives a run that fails", "[command][robustness]") {
  TempDir dir;
  write_text(dir / "bad.json", R"({"vertices": [[0,0],[9,0]], "vcolors": [[1,0,0],[0,1,0]],)"
                               R"( "faces": [[0,1,2]], "depth": [1,1]})");
  write_text(dir / "out.png", kPrecious);
  write_text(dir / "out.jsonl", kPrecious);
  write_text(dir / "out.mp4", kPrecious);
  const std::vector<std::vector<std::string>> runs = {
      {"render", "bad.json", "-o", "out.png"},
      {"trace", "bad.json", "-o", "out.jsonl"},
      {"explain", "bad.json", "-o", "out.mp4"},
      // fails after its writer opened: the replay of a trace that is not there
      {"replay", "nosuch.jsonl", "-o", "out.mp4"},
  };
  for (const auto& args : runs) {
    INFO(args[0]);
    const auto r = run_scantrace(dir.path(), args);
    CHECK(r.exit_code == 1);
  }
  CHECK(read_text(dir / "out.png") == kPrecious);
  CHECK(read_text(dir / "out.jsonl") == kPrecious);
  CHECK(read_text(dir / "out.mp4") == kPrecious);
  CHECK(file_names(dir.path()) ==
        std::vector<std::string>{"bad.json", "out.jsonl", "out.mp4", "out.png"});
}
