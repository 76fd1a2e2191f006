// `scantrace replay` and `scantrace explain`, run as a user would: outputs, and one clear line
// (exit status 1) for every kind of bad trace.
#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/cli_test_support.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;
using test::run_scantrace;
using test::TempDir;

namespace {

bool one_line(const std::string& s) {
  return !s.empty() && s.find('\n') == s.size() - 1;
}

// A complete trace of the small test triangle, written by `scantrace trace`.
std::string good_trace(const TempDir& dir) {
  const auto r = run_scantrace(dir.path(), {"trace", "--triangle", "2.3,1.2 13,4.5 5,11.6",
                                            "--size", "16x14", "-o", "good.jsonl"});
  REQUIRE(r.exit_code == 0);
  return test::read_text(dir / "good.jsonl");
}

}  // namespace

TEST_CASE("replay writes a video and a frame directory", "[viz][command]") {
  TempDir dir;
  good_trace(dir);
  const auto video = run_scantrace(dir.path(), {"replay", "good.jsonl", "-o", "t.mp4",
                                                "--video-size", "640x360", "--hold", "0.4"});
  INFO(video.err);
  REQUIRE(video.exit_code == 0);
  CHECK_THAT(video.err, Catch::Contains("wrote t.mp4") && Catch::Contains("640x360"));
  CHECK(std::filesystem::file_size(dir / "t.mp4") > 0);

  const auto frames = run_scantrace(dir.path(), {"replay", "good.jsonl", "-o", "frames/",
                                                 "--video-size", "640x360", "--steps", "2:4"});
  INFO(frames.err);
  REQUIRE(frames.exit_code == 0);
  CHECK(test::file_names(dir / "frames").size() == 3);
}

TEST_CASE("explain traces and replays in one go", "[viz][command]") {
  TempDir dir;
  const auto r = run_scantrace(dir.path(),
                               {"explain", "--triangle", "2.3,1.2 13,4.5 5,11.6", "--size", "16x14",
                                "--rows-per-step", "1", "-o", "out/", "--video-size", "640x360"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  // Title, set-up, three edge-table entries, ten scanlines, the finished triangle, end.
  CHECK(test::file_names(dir / "out").size() == 17);
  const cv::Mat first = cv::imread((dir / "out" / "frame_00001.png").string());
  CHECK(first.size() == cv::Size(640, 360));
}

TEST_CASE("a bad trace is one line naming the file, exit status 1, and no output",
          "[viz][command]") {
  TempDir dir;
  const std::string good = good_trace(dir);
  struct Bad {
    const char* name;
    std::string text;
    const char* says;
  };
  std::string v2 = good;
  v2.replace(v2.find("\"version\":1"), 11, "\"version\":2");
  const std::size_t last_line = good.rfind('\n', good.size() - 2) + 1;
  const std::vector<Bad> cases{
      {"cut.jsonl", good.substr(0, good.size() / 2), "cut.jsonl:"},
      {"nofooter.jsonl", good.substr(0, last_line), "no footer"},
      {"v2.jsonl", v2, "version 2 is not supported"},
      {"text.jsonl", "this is not a trace\n", "text.jsonl:1: not valid JSON"},
      {"empty.jsonl", "", "empty"}};
  const auto missing = run_scantrace(dir.path(), {"replay", "missing.jsonl", "-o", "bad.mp4"});
  CHECK(missing.exit_code == 1);
  // The reason is the system's (issue 20: it used to give none).
  CHECK(missing.err ==
        "scantrace: error: missing.jsonl: cannot open trace: No such file or directory\n");
  for (const Bad& b : cases) {
    test::write_text(dir / b.name, b.text);
    const auto r = run_scantrace(dir.path(), {"replay", b.name, "-o", "bad.mp4"});
    INFO(b.name << ": " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(one_line(r.err));
    CHECK_THAT(r.err, Catch::StartsWith(std::string("scantrace: error: ") + b.name));
    CHECK_THAT(r.err, Catch::Contains(b.says));
    CHECK_FALSE(std::filesystem::exists(dir / "bad.mp4"));
  }

  // --partial replays what a cut trace holds, with a warning.
  const auto partial =
      run_scantrace(dir.path(), {"replay", "cut.jsonl", "--partial", "-o", "partial/"});
  INFO(partial.err);
  CHECK(partial.exit_code == 0);
  CHECK_THAT(partial.err, Catch::Contains("warning") && Catch::Contains("no footer"));
  CHECK(test::file_names(dir / "partial").size() >= 3);
}

TEST_CASE("replay usage errors exit 2", "[viz][command]") {
  TempDir dir;
  good_trace(dir);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"replay", "good.jsonl"},
           {"replay", "good.jsonl", "-o", "t.avi"},
           {"replay", "good.jsonl", "-o", "t.mp4", "--size", "641x360"},
           {"replay", "good.jsonl", "-o", "t.mp4", "--size", "big"},
           {"replay", "good.jsonl", "-o", "t.mp4", "--steps", "5:2"},
           {"replay", "good.jsonl", "-o", "t.mp4", "--fps", "0"},
           {"explain", "-o", "t.mp4"}}) {
    const auto r = run_scantrace(dir.path(), args);
    INFO(args.back() << ": " << r.err);
    CHECK(r.exit_code == 2);
  }
  CHECK_FALSE(std::filesystem::exists(dir / "t.mp4"));
}
