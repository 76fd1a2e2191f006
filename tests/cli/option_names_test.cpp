// One meaning per option name on every subcommand (issue 20): --size is the canvas wherever a
// scene is taken (render overrides a scene file's canvas with it; it used to ignore it silently),
// --video-size the frame of a video (replay's old --size still works, with a warning), model
// colours are --model-colors everywhere (render's old --colors still works, with a warning). And
// the messages say what is wrong: a selection that matches nothing is an error, --colors given a
// model colour points at --model-colors, the truncation names its budget, --quiet is in every
// subcommand's help.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "trace/trace.hpp"

using namespace scantrace;
using scantrace::test::file_names;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

namespace {

// Two faces on a 20x10 canvas.
void write_small_scene(const std::filesystem::path& file) {
  test::write_text(file,
                   R"({"vertices": [[1, 1], [18, 2], [4, 8], [10, 9]],
                       "vcolors": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]],
                       "faces": [[0, 1, 2], [1, 3, 2]], "depth": [1, 1, 1, 2],
                       "width": 20, "height": 10})");
}

const std::string kModel =
    std::string(SCANTRACE_SOURCE_DIR) + "/examples/models/interpenetrating.obj";

}  // namespace

TEST_CASE(
    "option --size is the canvas in render, trace, explain, why and diff, also for scene files",
    "[command][options]") {
  TempDir dir;
  write_small_scene(dir / "s.json");
  auto r = run_scantrace(dir.path(), {"render", "s.json", "-o", "own.png"});
  REQUIRE(r.exit_code == 0);
  CHECK(cv::imread((dir / "own.png").string()).size() == cv::Size(20, 10));
  r = run_scantrace(dir.path(), {"render", "s.json", "--size", "64x48", "-o", "big.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(cv::imread((dir / "big.png").string()).size() == cv::Size(64, 48));
  // why and diff render the same reference: with --size the 64x48 image agrees (exit 0), without
  // it the canvases differ (exit 3), and pixel (63, 47) exists only on the larger canvas.
  r = run_scantrace(dir.path(), {"diff", "s.json", "big.png", "--size", "64x48"});
  CHECK(r.exit_code == 0);
  r = run_scantrace(dir.path(), {"diff", "s.json", "big.png"});
  CHECK(r.exit_code == 3);
  r = run_scantrace(dir.path(), {"why", "s.json", "63", "47", "--size", "64x48"});
  CHECK(r.exit_code == 0);
  r = run_scantrace(dir.path(), {"why", "s.json", "63", "47"});
  CHECK(r.exit_code != 0);

  r = run_scantrace(dir.path(), {"trace", "s.json", "--size", "30x25", "-o", "s.jsonl"});
  REQUIRE(r.exit_code == 0);
  CHECK(trace::Trace::load(dir / "s.jsonl").header().canvas.width == 30);
  CHECK(trace::Trace::load(dir / "s.jsonl").header().canvas.height == 25);

  // A model: --size in trace (the old --model-size warns but still works).
  r = run_scantrace(dir.path(), {"trace", kModel, "--size", "40x30", "-o", "m.jsonl"});
  REQUIRE(r.exit_code == 0);
  CHECK(trace::Trace::load(dir / "m.jsonl").header().canvas.width == 40);
  r = run_scantrace(dir.path(), {"trace", kModel, "--model-size", "42x30", "-o", "m2.jsonl"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("--model-size is deprecated, use --size"));
  CHECK(trace::Trace::load(dir / "m2.jsonl").header().canvas.width == 42);
  // And in render, as the README says of every command that takes a model (exit 2 before).
  r = run_scantrace(dir.path(), {"render", kModel, "--model-size", "44x30", "-o", "m.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("--model-size is deprecated, use --size"));
  CHECK(cv::imread((dir / "m.png").string()).size() == cv::Size(44, 30));
}

TEST_CASE(
    "option --model-colors everywhere, and render --colors and replay --size are deprecated "
    "aliases",
    "[command][options]") {
  TempDir dir;
  auto r = run_scantrace(
      dir.path(), {"render", kModel, "--model-colors", "random", "--size", "32x32", "-o", "a.png"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  r = run_scantrace(dir.path(),
                    {"render", kModel, "--colors", "random", "--size", "32x32", "-o", "b.png"});
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("--colors is deprecated, use --model-colors"));
  // Both spellings made the same picture.
  const cv::Mat a = cv::imread((dir / "a.png").string()), b = cv::imread((dir / "b.png").string());
  CHECK(cv::norm(a, b, cv::NORM_INF) == 0);

  // In trace, --colors are vertex colours: a model colour there is a usage error that says what
  // to use, with the option named once.
  r = run_scantrace(dir.path(), {"trace", kModel, "--colors", "random", "-o", "t.jsonl"});
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("use --model-colors random"));
  CHECK_THAT(r.err, !Catch::Contains("--colors: --colors"));

  r = run_scantrace(dir.path(),
                    {"trace", "--triangle", "1,1 9,2 4,8", "--size", "12x10", "-o", "tri.jsonl"});
  REQUIRE(r.exit_code == 0);
  r = run_scantrace(
      dir.path(), {"-q", "replay", "tri.jsonl", "-o", "f1/", "--size", "640x360", "--steps", "1"});
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("--size is deprecated, use --video-size"));
  r = run_scantrace(dir.path(), {"-q", "replay", "tri.jsonl", "-o", "f2/", "--video-size",
                                 "640x360", "--steps", "1"});
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(cv::imread((dir / "f2" / "frame_00001.png").string()).size() == cv::Size(640, 360));
}

TEST_CASE("a selection that matches nothing is an error, and nothing is written",
          "[command][options]") {
  TempDir dir;
  write_small_scene(dir / "s.json");
  auto r = run_scantrace(dir.path(), {"trace", "s.json", "--triangles", "812", "-o", "t.jsonl"});
  CHECK(r.exit_code == 1);
  CHECK(r.err ==
        "scantrace: error: s.json: --triangles: selects no face: the input has 2 faces (indices "
        "0..1), so there is nothing to trace\n");
  r = run_scantrace(dir.path(), {"trace", "s.json", "--rows", "50:60", "-o", "t.jsonl"});
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("--rows: selects no row of the canvas (rows 0..9)"));
  // Rows of the canvas that hold none of the selected faces (face 0 lies within rows 1..8, face 1
  // within 2..9 of the 10): an empty trace before (issue 36).
  r = run_scantrace(dir.path(),
                    {"trace", "s.json", "--triangles", "0", "--rows", "9:9", "-o", "t.jsonl"});
  CHECK(r.exit_code == 1);
  CHECK(r.err ==
        "scantrace: error: s.json: --rows: selects no row of the selected faces (its faces lie "
        "within rows 1..8), so there is nothing to trace\n");
  r = run_scantrace(dir.path(), {"trace", "--triangle", "1,5 9,6 4,8", "--size", "12x12", "--rows",
                                 "0:3", "-o", "t.jsonl"});
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("--rows: selects no row of the input (its faces lie within "
                                    "rows 5..8)"));
  r = run_scantrace(dir.path(), {"explain", "s.json", "--triangles", "2-5", "-o", "e.mp4"});
  CHECK(r.exit_code == 1);
  CHECK(file_names(dir.path()) == std::vector<std::string>{"s.json"});
  // A selection that matches something still works.
  CHECK(run_scantrace(dir.path(), {"trace", "s.json", "--triangles", "1-5", "-o", "t.jsonl"})
            .exit_code == 0);
  CHECK(run_scantrace(dir.path(),
                      {"trace", "s.json", "--triangles", "1", "--rows", "9:9", "-o", "t.jsonl"})
            .exit_code == 0);
}

TEST_CASE("help and warnings name the right options", "[command][options]") {
  TempDir dir;
  for (const char* sub : {"render", "trace", "replay", "explain"}) {
    const auto r = run_scantrace(dir.path(), {sub, "--help"});
    INFO(sub);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("--quiet"));
  }
  const auto help = run_scantrace(dir.path(), {"render", "--help"}).out;
  CHECK_THAT(help, Catch::Contains("seed of --model-colors random"));

  write_small_scene(dir / "s.json");
  const auto capped =
      run_scantrace(dir.path(), {"trace", "s.json", "--max-events", "5", "-o", "c.jsonl"});
  CHECK(capped.exit_code == 0);
  CHECK_THAT(capped.err, Catch::Contains("by its budget --max-events 5"));
  const auto bytes =
      run_scantrace(dir.path(), {"trace", "s.json", "--max-bytes", "1024", "-o", "b.jsonl"});
  CHECK(bytes.exit_code == 0);
  CHECK_THAT(bytes.err, Catch::Contains("by its budget --max-bytes 1024"));
  // Replaying the cut trace does not blame --max-events alone (the file does not say which).
  const auto replayed =
      run_scantrace(dir.path(), {"replay", "b.jsonl", "-o", "b/", "--steps", "1"});
  CHECK(replayed.exit_code == 0);
  CHECK_THAT(replayed.err, Catch::Contains("b.jsonl: the trace was truncated after") &&
                               Catch::Contains("(--max-events or --max-bytes)"));
}
