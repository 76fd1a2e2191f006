// Videos and frame directories: the frames written are the steps times their holds, the decoded
// video has the requested size, frame count and codec, colours arrive in the right order, and
// every way a writer can fail is an error rather than a silent or half-written output.
#include <fstream>

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <catch2/catch.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include "cli/cli_test_support.hpp"
#include "viz/frame_directory.hpp"
#include "viz/replay.hpp"
#include "viz/replayer.hpp"
#include "viz/video_writer.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;
using test::TempDir;

namespace {

// The frames a replay must write at `fps` and `hold`, from the documented weights.
std::size_t expected_frames(const trace::Trace& t, const viz::StepPlan& plan, double fps,
                            double hold) {
  std::size_t frames = 0;
  for (const viz::Step& s : plan.steps) {
    bool changes = false;
    if (s.kind == viz::StepKind::scanlines) {
      const trace::Scanline& first = t.scanline(s.triangle, s.first_row);
      changes = !first.entered.empty() || !first.retired.empty();
    }
    frames += static_cast<std::size_t>(
        std::max(1L, std::lround(fps * hold * test::documented_weight(s.kind, changes))));
  }
  return frames;
}

std::size_t decoded_frames(const std::filesystem::path& video, cv::Size* size,
                           std::vector<cv::Mat>* keep = nullptr) {
  cv::VideoCapture in(video.string(), cv::CAP_FFMPEG);
  REQUIRE(in.isOpened());
  std::size_t n = 0;
  for (cv::Mat f; in.read(f);) {
    *size = f.size();
    if (keep) keep->push_back(f.clone());
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("a video has one frame per step and hold, the size asked for, and a known codec",
          "[viz][video]") {
  TempDir dir;
  const trace::Trace t = test::record(test::small_triangle());
  viz::ReplayOptions o;
  o.size = {640, 360};
  o.fps = 4;
  o.hold = 0.5;  // two frames per unit of weight
  o.plan.rows_per_step = 1;
  const viz::ReplayResult r = viz::replay(t, dir / "t.mp4", o);
  const viz::StepPlan plan = viz::plan_steps(t, o.plan);
  const std::size_t expected = expected_frames(t, plan, o.fps, o.hold);
  CHECK(r.steps == plan.steps.size());
  CHECK(r.frames == expected);
  // H.264 wherever FFmpeg has a software H.264 encoder (asked of ffmpeg, which uses the same
  // libavcodec as OpenCV's backend); MPEG-4 only where it has none (the fallback's own test is
  // below).
  const int h264 = test::have_software_h264_encoder();
  if (h264 == 1) CHECK(r.format == "h264");
  if (h264 == 0) CHECK(r.format == "mpeg4");

  cv::Size size;
  CHECK(decoded_frames(dir / "t.mp4", &size) == expected);
  CHECK(size == cv::Size(640, 360));

  if (!test::have_ffprobe()) {
    WARN(
        "skipped: ffprobe is not installed: the codec, size and frame count were not checked by "
        "ffprobe");
    return;
  }
  const auto probe = test::ffprobe(dir / "t.mp4");
  CHECK(probe.at("codec_name") == r.format);
  CHECK(probe.at("width") == "640");
  CHECK(probe.at("height") == "360");
  CHECK(probe.at("nb_read_frames") == std::to_string(expected));
}

TEST_CASE("where H.264 is missing, the video is MPEG-4 and a warning says so", "[viz][video]") {
  TempDir dir;
  // The first codec asked for cannot exist (no encoder has fourcc "QQQQ"): the writer must fall
  // back to MPEG-4 part 2 and say which encoder was missing.
  const viz::VideoCodec codecs[] = {{"QQQQ", "h264"}, {"mp4v", "mpeg4"}};
  std::ostringstream log;
  const auto previous = spdlog::default_logger();
  spdlog::set_default_logger(std::make_shared<spdlog::logger>(
      "capture", std::make_shared<spdlog::sinks::ostream_sink_st>(log)));
  std::string format;
  {
    viz::VideoFile video(dir / "v.mp4", {320, 180}, 5, codecs);
    format = video.format();
    video.write(cv::Mat(180, 320, CV_8UC3, cv::Scalar(0, 0, 255)), 3);
    video.commit();
  }
  spdlog::set_default_logger(previous);
  CHECK(format == "mpeg4");
  CHECK_THAT(log.str(), Catch::Contains("v.mp4: the H.264 encoder (fourcc QQQQ) is not "
                                        "available; writing MPEG-4 part 2 (mp4v) instead"));
  cv::Size size;
  CHECK(decoded_frames(dir / "v.mp4", &size) == 3);
  CHECK(size == cv::Size(320, 180));
  if (!test::have_ffprobe()) {
    WARN("skipped: ffprobe is not installed: the codec was not checked by ffprobe");
    return;
  }
  CHECK(test::ffprobe(dir / "v.mp4").at("codec_name") == "mpeg4");
}

TEST_CASE("a step range writes only those steps", "[viz][video]") {
  TempDir dir;
  const trace::Trace t = test::record(test::small_triangle());
  viz::ReplayOptions o;
  o.size = {640, 360};
  o.plan.rows_per_step = 1;
  o.steps = viz::StepRange::parse("6:9");  // four scanline steps (rows 2..5)
  const viz::ReplayResult r = viz::replay(t, dir / "frames/", o);
  CHECK(r.kind == viz::OutputKind::frames);
  CHECK(r.steps == 4);
  const auto names = test::file_names(dir / "frames");
  // Numbered as the steps are (the frames say "step 6 of 17"), not from 1 (issue 20).
  CHECK(names == std::vector<std::string>{"frame_00006.png", "frame_00007.png", "frame_00008.png",
                                          "frame_00009.png"});
  o.steps = viz::StepRange::parse("90:");
  CHECK_THROWS_WITH(viz::replay(t, dir / "more/", o), Catch::Contains("has 17 steps"));
}

TEST_CASE("a red vertex decodes as red", "[viz][video]") {
  TempDir dir;
  trace::TriangleInput red;
  red.vertices = {Vec2{10, 10}, Vec2{100, 20}, Vec2{40, 110}};
  red.colors = {Color{1, 0, 0}, Color{1, 0, 0}, Color{1, 0, 0}};
  red.width = red.height = 128;
  const trace::Trace t = test::record(red, Shading::flat);
  viz::ReplayOptions o;
  o.size = {640, 360};
  o.fps = 1;
  o.hold = 1;
  viz::Replayer replayer(t, o.plan, o.size, "red");
  const std::size_t done = replayer.steps().size() - 2;  // the finished triangle, before the end
  REQUIRE(replayer.steps()[done].kind == viz::StepKind::triangle_done);
  const cv::Point2d inside = replayer.geometry(done)->to_frame(50, 45);
  std::size_t before = 0;  // frames before the finished triangle's
  for (std::size_t i = 0; i < done; ++i)
    before += static_cast<std::size_t>(viz::frames_for(replayer.steps()[i], o.fps, o.hold));

  viz::replay(t, dir / "red.mp4", o);
  std::vector<cv::Mat> frames;
  cv::Size size;
  decoded_frames(dir / "red.mp4", &size, &frames);
  REQUIRE(frames.size() > before);
  const cv::Vec3b bgr = frames[before].at<cv::Vec3b>(cv::Point(int(inside.x), int(inside.y)));
  INFO("decoded BGR " << int(bgr[0]) << " " << int(bgr[1]) << " " << int(bgr[2]));
  CHECK(bgr[2] >= 200);
  CHECK(bgr[1] <= 60);
  CHECK(bgr[0] <= 60);
}

TEST_CASE("writers refuse frames of the wrong size or type", "[viz][video]") {
  TempDir dir;
  {
    viz::VideoFile video(dir / "v.mp4", {320, 180}, 5);
    CHECK_THROWS_AS(video.write(cv::Mat(181, 320, CV_8UC3), 1), std::logic_error);
    CHECK_THROWS_AS(video.write(cv::Mat(180, 320, CV_8UC1), 1), std::logic_error);
    CHECK_THROWS_AS(video.write(cv::Mat(180, 320, CV_8UC4), 1), std::logic_error);
    video.write(cv::Mat(180, 320, CV_8UC3, cv::Scalar(0, 0, 255)), 2);
    CHECK(video.frames() == 2);
    video.commit();
  }
  CHECK(std::filesystem::file_size(dir / "v.mp4") > 0);
  viz::FrameDirectory pngs(dir / "f", {320, 180});
  CHECK_THROWS_AS(pngs.write(cv::Mat(180, 322, CV_8UC3), 1), std::logic_error);
}

TEST_CASE("a writer that cannot open is an error naming the file, leaving nothing behind",
          "[viz][video]") {
  TempDir dir;
  const trace::Trace t = test::record(test::small_triangle());
  viz::ReplayOptions o;
  o.size = {320, 180};
  CHECK_THROWS_WITH(viz::replay(t, dir / "no" / "such" / "t.mp4", o),
                    Catch::Contains((dir / "no" / "such" / "t.mp4").string()));
  CHECK_THROWS_AS(viz::VideoFile(dir / "odd.mp4", {321, 180}, 5), std::invalid_argument);
  o.size = {322, 181};
  CHECK_THROWS_WITH(viz::replay(t, dir / "odd.mp4", o), Catch::Contains("even"));
  CHECK_THROWS_AS(viz::output_kind("t.avi"), std::invalid_argument);
  // An interrupted replay (an exception while writing) leaves no file that looks complete.
  {
    viz::VideoFile video(dir / "cut.mp4", {320, 180}, 5);
    video.write(cv::Mat(180, 320, CV_8UC3, cv::Scalar::all(0)), 3);
  }
  CHECK(test::file_names(dir.path()).empty());
}

TEST_CASE("a frame directory is replaced by a new replay, other directories are not touched",
          "[viz][video]") {
  TempDir dir;
  const trace::Trace t = test::record(test::small_triangle());
  viz::ReplayOptions o;
  o.size = {320, 180};
  viz::replay(t, dir / "frames", o);
  const std::size_t all = test::file_names(dir / "frames").size();
  CHECK(all == viz::plan_steps(t).steps.size());
  o.steps = viz::StepRange::parse("1:2");
  viz::replay(t, dir / "frames/", o);
  CHECK(test::file_names(dir / "frames").size() == 2);

  std::filesystem::create_directory(dir / "mine");
  test::write_text(dir / "mine" / "notes.txt", "keep me");
  CHECK_THROWS_WITH(viz::replay(t, dir / "mine/", o), Catch::Contains("notes.txt"));
  CHECK(test::read_text(dir / "mine" / "notes.txt") == "keep me");
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"frames", "mine"});
}
