// `scantrace why` and `scantrace diff` as a user runs them: exit statuses, outputs under -o, and
// bad inputs (one line on stderr, exit 1, nothing half-written).
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>
#include <nlohmann/json.hpp>

#include "../cli/cli_test_support.hpp"
#include "io/scene_json.hpp"
#include "viz/image_file.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

namespace {

int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace

TEST_CASE("diff: an identical image exits 0, a wrong one 3 with diff.png and report.json",
          "[grade][cli]") {
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  scantrace::write_png(render_wrong(s, Shading::gouraud, Mistake::none), dir / "good.png");
  const auto same = run_scantrace(dir.path(), {"diff", "scene.json", "good.png", "-o", "same"});
  CHECK(same.exit_code == 0);
  CHECK(same.out.find("agrees") != std::string::npos);
  // The paths printed are joined: `-o graded/` printed graded//diff.png (issue 36).
  const auto slash = run_scantrace(dir.path(), {"diff", "scene.json", "good.png", "-o", "graded/"});
  CHECK(slash.exit_code == 0);
  CHECK_THAT(slash.err, Catch::Contains("-> graded/diff.png, report.json"));
  const auto report = nlohmann::json::parse(scantrace::test::read_text(dir / "same/report.json"));
  CHECK(report["differing_pixels"] == 0);
  CHECK(report["global"].empty());

  const RgbImage bad = render_wrong(s, Shading::gouraud, Mistake::closed_rule);
  scantrace::write_png(bad, dir / "closed.png");
  const auto differ = run_scantrace(dir.path(), {"diff", "scene.json", "closed.png", "-o", "out"});
  CHECK(differ.exit_code == 3);
  CHECK(differ.out.find("`boundary`") != std::string::npos);
  const auto j = nlohmann::json::parse(scantrace::test::read_text(dir / "out/report.json"));
  const long long expected = count_differing(render_wrong(s, Shading::gouraud, Mistake::none), bad);
  CHECK(j["differing_pixels"] == expected);
  CHECK(j["categories"]["boundary"] == expected);
  CHECK(j["examples"].size() == 3);
  const RgbImage png = scantrace::read_png(dir / "out/diff.png");
  CHECK(png.width() > s.width);
  CHECK(scantrace::test::file_names(dir / "out") ==
        std::vector<std::string>{"diff.png", "report.json"});

  const auto json = run_scantrace(dir.path(), {"-q", "diff", "scene.json", "closed.png", "--json"});
  CHECK(json.exit_code == 3);
  CHECK(nlohmann::json::parse(json.out)["categories"]["boundary"] == expected);
}

TEST_CASE("diff: bad inputs are one line and exit 1, usage errors exit 2", "[grade][cli]") {
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  scantrace::write_png(render_wrong(s, Shading::gouraud, Mistake::none), dir / "good.png");
  const std::string png = scantrace::test::read_text(dir / "good.png");
  scantrace::test::write_text(dir / "cut.png", png.substr(0, png.size() / 2));
  const auto npy_file = [](const std::string& descr, const std::string& shape,
                           const std::string& data) {
    std::string header =
        "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
    while ((10 + header.size() + 1) % 64) header += ' ';
    header += '\n';
    return std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(header.size()) + '\0' + header +
           data;
  };
  scantrace::test::write_text(dir / "pickle.npy", npy_file("|O", "(160, 200, 3)", "\x80\x04"));
  scantrace::test::write_text(dir / "complex.npy", npy_file("<c16", "(160, 200, 3)", ""));
  scantrace::test::write_text(dir / "shape.npy",
                              npy_file("<f4", "(160, 200)", std::string(160 * 200 * 4, '\0')));
  std::string nan(160 * 200 * 3 * 4, '\0');
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[4 * 3 * (200 * 7 + 9)], &q, 4);
  scantrace::test::write_text(dir / "nan.npy", npy_file("<f4", "(160, 200, 3)", nan));
  for (const auto& [file, words] :
       std::vector<std::pair<std::string, std::string>>{{"cut.png", "truncated"},
                                                        {"pickle.npy", "pickles"},
                                                        {"complex.npy", "dtype '<c16'"},
                                                        {"shape.npy", "shape (160, 200)"},
                                                        {"nan.npy", "pixel [7][9]: NaN"},
                                                        {"missing.png", "cannot read file"}}) {
    INFO(file);
    const auto r = run_scantrace(dir.path(), {"diff", "scene.json", file, "-o", "out-" + file});
    CHECK(r.exit_code == 1);
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(file) != std::string::npos);
    CHECK(r.err.find(words) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / ("out-" + file)));
  }
  CHECK(run_scantrace(dir.path(), {"diff", "scene.json"}).exit_code == 2);
  CHECK(
      run_scantrace(dir.path(), {"diff", "scene.json", "good.png", "--tolerance", "2"}).exit_code ==
      2);
}

TEST_CASE("why: text, JSON, a pixel outside the canvas", "[grade][cli]") {
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  const auto text = run_scantrace(dir.path(), {"why", "scene.json", "40", "40"});
  CHECK(text.exit_code == 0);
  CHECK(text.out.find("pixel (40, 40)") != std::string::npos);
  CHECK(text.out.find("final colour") != std::string::npos);
  const auto json = run_scantrace(dir.path(), {"-q", "why", "scene.json", "40", "40", "--json"});
  CHECK(json.exit_code == 0);
  const auto j = nlohmann::json::parse(json.out);
  CHECK(j["pixel"] == nlohmann::json::array({40, 40}));
  CHECK(j["format"] == "scantrace-why");
  const auto outside = run_scantrace(dir.path(), {"why", "scene.json", "200", "5"});
  CHECK(outside.exit_code == 1);
  CHECK(lines(outside.err) == 1);
  CHECK(run_scantrace(dir.path(), {"why", "scene.json", "5"}).exit_code == 2);
  // An --explain output replay cannot write is a usage error before any work: no story on
  // stdout, as `replay -o x.avi` (issue 36: the story was printed, then exit 1).
  const auto txt =
      run_scantrace(dir.path(), {"why", "scene.json", "40", "40", "--explain", "why.txt"});
  CHECK(txt.exit_code == 2);
  CHECK(txt.out.empty());
  CHECK_THAT(txt.err, Catch::Contains("--explain") && Catch::Contains("why.txt"));
  // The help names every input and output it takes.
  for (const char* sub : {"why", "diff"}) {
    const auto help = run_scantrace(dir.path(), {sub, "--help"});
    CHECK_THAT(help.out, Catch::Contains("JSON or MATLAB .mat"));
  }
  CHECK_THAT(run_scantrace(dir.path(), {"why", "--help"}).out, Catch::Contains("OUT.html"));
}

TEST_CASE("why --explain replays at most the last 100 faces drawn over the pixel, and says so",
          "[grade][cli][explain]") {
  // 130 faces over pixel (10, 10), depths 130 .. 1: drawn in scene order, face 129 last. Every
  // row of 10k faces took over a minute and 1.75 GB (issue 37): the replay keeps the last 100.
  TempDir dir;
  Scene s;
  s.width = s.height = 24;
  for (int f = 0; f < 130; ++f) {
    const int base = static_cast<int>(s.vertices.size());
    for (const Vec2 v : {Vec2{4, 4}, Vec2{20, 6}, Vec2{8, 19}}) {
      s.vertices.push_back(v);
      s.vcolors.push_back({0.2, 0.4, 0.6});
      s.depth.push_back(130.0 - f);
    }
    s.faces.push_back({base, base + 1, base + 2});
  }
  scantrace::save_scene(s, dir / "scene.json");
  const auto r = run_scantrace(dir.path(), {"-q", "why", "scene.json", "10", "10", "--explain", "out/"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("--explain shows the last 100 of the 130 faces around the "
                                    "pixel, in drawing order"));
  CHECK(lines(r.err) == 1);
  // The text still lists all 130.
  CHECK_THAT(r.out, Catch::Contains("face 0 ") && Catch::Contains("face 129 "));
  std::size_t frames = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "out")) ++frames;
  CHECK(frames >= 100);
}

TEST_CASE("diff: what the image decoder prints goes into scantrace's one warning line",
          "[grade][cli]") {
  // The right image with an ancillary tEXt chunk whose CRC is wrong, after IHDR: libpng warns
  // ("libpng warning: tEXt: CRC error") on stderr by itself and decodes the image. scantrace
  // captures that text: one line of its own naming the file, never the library's line before it
  // (issue 37, point 17).
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  scantrace::write_png(render_wrong(s, Shading::gouraud, Mistake::none), dir / "good.png");
  std::string png = scantrace::test::read_text(dir / "good.png");
  REQUIRE(png.substr(12, 4) == "IHDR");
  const std::string text = "Comment";
  std::string chunk = {0, 0, 0, static_cast<char>(text.size()), 't', 'E', 'X', 't'};
  chunk += text + std::string("\x12\x34\x56\x78", 4);  // not the CRC of "tEXtComment"
  png.insert(8 + 25, chunk);
  scantrace::test::write_text(dir / "crc.png", png);
  const auto r = run_scantrace(dir.path(), {"-q", "diff", "scene.json", "crc.png", "-o", "out"});
  INFO(r.err);
  CHECK(r.exit_code == 0);  // the pixels are the right ones
  CHECK(lines(r.err) == 1);
  CHECK(r.err == "scantrace: warning: crc.png: the png decoder said: libpng warning: tEXt: CRC "
                 "error\n");
}

namespace {

// The files the dynamic loader opens while `scantrace` runs `args` in `dir` (its own list, over
// the exec from `scantrace` to scantrace-diff and on), and the exit status.
std::pair<std::string, int> loaded_files(const std::filesystem::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && LD_DEBUG=files '" +
                              SCANTRACE_BINARY + "' " + args + " 2>&1 >/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int status = pclose(pipe);
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

}  // namespace

TEST_CASE("diff: a PNG loads no OpenCV, a BMP goes on to scantrace-tools and is graded alike",
          "[grade][cli]") {
  // `scantrace diff` runs in scantrace-diff (cli/diff_main.cpp), which links no OpenCV: 260
  // libraries and 0.3-0.5 s of start-up with its video and window parts, ~140 and 0.1-0.25 s with
  // imgcodecs alone (docs/grading.md). A JPEG or BMP is decoded by OpenCV in scantrace-tools.
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  const RgbImage bad = render_wrong(s, Shading::gouraud, Mistake::closed_rule);
  scantrace::write_png(bad, dir / "closed.png");
  cv::Mat bgr(bad.height(), bad.width(), CV_8UC3);
  for (int y = 0; y < bad.height(); ++y)
    for (int x = 0; x < bad.width(); ++x) {
      const auto p = bad(x, y);
      const auto byte = [](float c) { return static_cast<unsigned char>(std::lround(255 * c)); };
      bgr.at<cv::Vec3b>(y, x) = {byte(p.b), byte(p.g), byte(p.r)};
    }
  REQUIRE(cv::imwrite((dir / "closed.bmp").string(), bgr));
  const auto [png_files, png_status] =
      loaded_files(dir.path(), "diff scene.json closed.png -o png");
  CHECK(png_status == 3);
  CHECK(png_files.find("libpng16") != std::string::npos);  // the list is the loader's
  CHECK(png_files.find("libopencv") == std::string::npos);
  const auto [bmp_files, bmp_status] =
      loaded_files(dir.path(), "diff scene.json closed.bmp -o bmp");
  CHECK(bmp_status == 3);
  CHECK(bmp_files.find("libopencv_imgcodecs") != std::string::npos);
  // Two programs started each time: scantrace, then scantrace-diff for the PNG and scantrace-tools
  // for the BMP, which `scantrace` hands straight to it (cli/handoff.hpp; the loader names each by
  // the argv[0] handed on, `scantrace`).
  const auto programs = [](const std::string& files) {
    std::size_t n = 0;
    for (std::size_t at = 0; (at = files.find("initialize program:", at)) != std::string::npos; ++at)
      ++n;
    return n;
  };
  CHECK(programs(png_files) == 2);
  CHECK(programs(bmp_files) == 2);
  const auto from_png = nlohmann::json::parse(scantrace::test::read_text(dir / "png/report.json"));
  const auto from_bmp = nlohmann::json::parse(scantrace::test::read_text(dir / "bmp/report.json"));
  CHECK(from_png["categories"] == from_bmp["categories"]);
  CHECK(from_png["differing_pixels"] == from_bmp["differing_pixels"]);
  CHECK(from_png["differing_pixels"] ==
        count_differing(render_wrong(s, Shading::gouraud, Mistake::none), bad));
}

TEST_CASE("diff: a BMP with no scantrace-tools beside scantrace-diff is one line, exit 1",
          "[grade][cli]") {
  // scantrace-diff alone (an install that lost scantrace-tools): it cannot decode a BMP itself,
  // and says so naming the file, instead of exec'ing nothing or crashing.
  TempDir dir;
  const Scene s = generated_scene();
  scantrace::save_scene(s, dir / "scene.json");
  cv::Mat bgr(s.height, s.width, CV_8UC3, cv::Scalar(255, 255, 255));
  REQUIRE(cv::imwrite((dir / "white.bmp").string(), bgr));
  const std::filesystem::path alone = dir / "bin" / "scantrace-diff";
  std::filesystem::create_directories(alone.parent_path());
  std::filesystem::copy_file(std::filesystem::path(SCANTRACE_BINARY).parent_path() /
                                 "scantrace-diff",
                             alone);
  std::string command = "cd ";
  command += scantrace::test::shell_quote(dir.path().string());
  command += " && ";
  command += scantrace::test::shell_quote(alone.string());
  command += " diff scene.json white.bmp >out.txt 2>err.txt";
  const int status = std::system(command.c_str());
  const std::string err = scantrace::test::read_text(dir / "err.txt");
  INFO(err);
  CHECK((WIFEXITED(status) ? WEXITSTATUS(status) : -1) == 1);
  CHECK(lines(err) == 1);
  CHECK_THAT(err, Catch::Contains("white.bmp") && Catch::Contains("scantrace-tools") &&
                      Catch::Contains("cannot be found"));
}
