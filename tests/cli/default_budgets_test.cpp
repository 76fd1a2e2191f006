// The defaults the README and docs/robustness.md quote: `trace --max-bytes` 1 GiB, `--max-frames`
// 20000 for replays, frame sizes even and 320x180 .. 7680x4320 (docs/usage.md "Outputs").
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"

using scantrace::test::file_names;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

TEST_CASE("trace's default byte budget is 1 GiB", "[command][budget]") {
  TempDir dir;
  // Writing a GiB to see the cut would take minutes; the default the option holds is what
  // --help prints from it (CLI11's captured default), and it must be 2^30.
  const auto r = run_scantrace(dir.path(), {"trace", "--help"});
  REQUIRE(r.exit_code == 0);
  const std::size_t option = r.out.find("--max-bytes");
  REQUIRE(option != std::string::npos);
  const std::string line = r.out.substr(option, r.out.find('\n', option) - option);
  std::string expected = "=";
  expected += std::to_string(1LL << 30);  // appended: GCC 12 warns on "literal" + std::string&&
  CHECK_THAT(line, Catch::EndsWith(expected));
}

TEST_CASE("a replay needing more than 20000 frames is refused by default, before any frame",
          "[command][budget]") {
  TempDir dir;
  // One step per row of a 5100-row triangle: 5100 scanline steps of round(5 fps × 0.8 s) = 4
  // frames each, so more than 20400 frames — over the default budget with no --max-frames.
  const auto r = run_scantrace(dir.path(), {"explain", "--triangle", "0,0 8,0 4,5100", "--size",
                                            "8x5100", "--rows-per-step", "1", "-o", "v.mp4"});
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("v.mp4: the replay needs") &&
                        Catch::Contains("more than the budget of 20000 (--max-frames)"));
  CHECK(file_names(dir.path()).empty());
}

TEST_CASE("frame sizes are even, from 320x180 to 7680x4320", "[command][budget]") {
  TempDir dir;
  for (const std::string size : {"318x180", "320x178", "7682x4320", "7680x4322", "321x180"}) {
    INFO(size);
    const auto r = run_scantrace(dir.path(), {"explain", "--triangle", "2,1 9,3 4,8", "--size",
                                              "12x10", "--video-size", size, "-o", "f/"});
    CHECK(r.exit_code == 2);  // a usage error, named
    CHECK_THAT(r.err, Catch::Contains("--video-size"));
  }
  CHECK(file_names(dir.path()).empty());
  for (const cv::Size size : {cv::Size(320, 180), cv::Size(7680, 4320)}) {
    const std::string text = std::to_string(size.width) + "x" + std::to_string(size.height);
    INFO(text);
    const auto r =
        run_scantrace(dir.path(), {"-q", "explain", "--triangle", "2,1 9,3 4,8", "--size", "12x10",
                                   "--video-size", text, "--steps", "1", "-o", "f/"});
    REQUIRE(r.exit_code == 0);
    const cv::Mat frame = cv::imread((dir / "f" / "frame_00001.png").string());
    CHECK(frame.cols == size.width);
    CHECK(frame.rows == size.height);
  }
}
