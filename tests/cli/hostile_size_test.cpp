// Inputs larger than the memory there is are refused before they are parsed or loaded, naming
// the file (a scene of 10^7 faces, a trace of 10^7 lines: docs/robustness.md, "Hostile sizes";
// here the same paths with SCANTRACE_MAX_MEMORY lowered to fit a test).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "cli_test_support.hpp"

using namespace scantrace::test;

namespace {

// `n` faces over 3 vertices: about 10 bytes of text and 4 JSON values (64 + 3·16 + 16 bytes of
// DOM) per face.
std::string scene_with_faces(int n) {
  std::string s =
      R"({"vertices":[[0,0],[9,0],[0,9]],"vcolors":[[1,0,0],[0,1,0],[0,0,1]],"depth":[1,1,1],"faces":[)";
  for (int i = 0; i < n; ++i) s += i ? ",[0,1,2]" : "[0,1,2]";
  return s + "]}";
}

}  // namespace

TEST_CASE("a scene whose JSON would not fit in memory is refused before parsing",
          "[command][robustness][size]") {
  TempDir dir;
  write_text(dir / "many.json", scene_with_faces(100000));  // about 13 MB of DOM
  ::setenv("SCANTRACE_MAX_MEMORY", "4M", 1);
  const RunResult r = run_scantrace(dir.path(), {"render", "many.json", "-o", "many.png"});
  ::unsetenv("SCANTRACE_MAX_MEMORY");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::StartsWith("scantrace: error: many.json: parsing its JSON (") &&
                        Catch::Contains("more than the 4 MiB of memory available"));
  // Within the memory there is, the same file renders.
  const RunResult ok = run_scantrace(dir.path(), {"render", "many.json", "-o", "many.png"});
  CHECK(ok.exit_code == 0);
}

TEST_CASE("a trace file that would not fit in memory is refused before it is read",
          "[command][robustness][size]") {
  TempDir dir;
  const RunResult t =
      run_scantrace(dir.path(), {"-q", "trace", "--triangle", "0,0 300,0 0,300", "--size",
                                 "300x300", "--level", "pixel", "-o", "big.jsonl"});
  REQUIRE(t.exit_code == 0);  // about 45,000 pixel events, 4 MB
  ::setenv("SCANTRACE_MAX_MEMORY", "8M", 1);
  const RunResult r = run_scantrace(dir.path(), {"replay", "big.jsonl", "-o", "frames/"});
  const RunResult c = run_scantrace(dir.path(), {"check", "big.jsonl", "--partial"});
  ::unsetenv("SCANTRACE_MAX_MEMORY");
  for (const RunResult& x : {r, c}) {
    CHECK(x.exit_code == 1);
    CHECK_THAT(x.err, Catch::StartsWith("scantrace: error: big.jsonl: loading this trace of ") &&
                          Catch::Contains("more than the 8 MiB of memory available"));
  }
  CHECK(file_names(dir.path()) == std::vector<std::string>{"big.jsonl"});
}
