// The scantrace binary, run through the shell as a user would: exit status, messages, outputs.
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/commands.hpp"
#include "cli_test_support.hpp"
#include "page_test_support.hpp"
#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "scene_compare.hpp"
#include "src/painter.hpp"
#include "trace/trace.hpp"
#include "viz/opencv_image.hpp"

using namespace scantrace;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

namespace {

// Two flat triangles far from pixel (0, 0), with known mean colours:
// A, around (100, 100): mean of red, green, blue = (1/3, 1/3, 1/3);
// B, around (300, 300): mean of (1, 0.5, 0), (1, 0.5, 0), (1, 0.2, 0.1) = (1, 0.4, 1/30).
Scene two_triangles() {
  Scene s;
  s.vertices = {{60, 60}, {160, 70}, {90, 150}, {250, 250}, {380, 260}, {300, 380}};
  s.vcolors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0.5, 0}, {1, 0.5, 0}, {1, 0.2, 0.1}};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  s.depth = {1, 1, 1, 2, 2, 2};
  return s;
}

cv::Vec3b bgr_of(Color c) {
  auto byte = [](double v) { return static_cast<unsigned char>(std::lround(255.0 * v)); };
  return {byte(c.b), byte(c.g), byte(c.r)};
}

cv::Mat read_bgr(const std::filesystem::path& file) {
  return cv::imread(file.string(), cv::IMREAD_UNCHANGED);
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

bool one_line(const std::string& s) {
  return !s.empty() && s.find('\n') == s.size() - 1;
}

}  // namespace

TEST_CASE("scantrace --version and --help exit 0", "[command]") {
  TempDir dir;
  const auto version = run_scantrace(dir.path(), {"--version"});
  CHECK(version.exit_code == 0);
  CHECK(version.out == "scantrace 0.2.0\n");

  const auto help = run_scantrace(dir.path(), {"--help"});
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Contains("render") && Catch::Contains("demo") &&
                           Catch::Contains("Exit status"));

  const auto render_help = run_scantrace(dir.path(), {"render", "--help"});
  CHECK(render_help.exit_code == 0);
  CHECK_THAT(render_help.out, Catch::Contains("--fill-rule") && Catch::Contains("top-left") &&
                                  Catch::Contains("closed") && Catch::Contains("--shading") &&
                                  Catch::Contains("--subpixel-bits"));

  const auto demo_help = run_scantrace(dir.path(), {"demo", "--help"});
  CHECK(demo_help.exit_code == 0);
  CHECK_THAT(demo_help.out, Catch::Contains("-o,--output"));
}

// `scantrace` renders itself and hands every other command to `scantrace-tools` beside it
// (cli/main_render.cpp): the one loads no OpenCV, the other is found where the first is.
TEST_CASE("scantrace renders without OpenCV and hands the other commands on", "[command]") {
  TempDir dir;
  // The dynamic loader's own list of what the executable loads (ldd, from libc-bin).
  const std::string ldd = "ldd " + test::shell_quote(SCANTRACE_BINARY) + " > " +
                          test::shell_quote((dir / "ldd.txt").string());
  REQUIRE(std::system(ldd.c_str()) == 0);
  const std::string libraries = test::read_text(dir / "ldd.txt");
  // (libdeflate, the PNG writer's compressor: the list is the executable's own.)
  CHECK_THAT(libraries, Catch::Contains("libdeflate") && !Catch::Contains("libopencv") &&
                            !Catch::Contains("libmatio"));
  // Commands it hands on, with their exit status and output: a trace, then its check.
  save_scene(two_triangles(), dir / "scene.json");
  const auto traced = run_scantrace(dir.path(), {"-q", "trace", "scene.json", "-o", "t.jsonl"});
  INFO("stderr: " << traced.err);
  CHECK(traced.exit_code == 0);
  const auto check = run_scantrace(dir.path(), {"check", "t.jsonl"});
  INFO("stderr: " << check.err);
  CHECK(check.exit_code == 0);
  // Without scantrace-tools beside it (the demo's build), the other commands are usage errors
  // naming the build that has them, and render still works.
  const std::filesystem::path alone = dir / "alone" / "scantrace";
  std::filesystem::create_directories(alone.parent_path());
  std::filesystem::copy_file(SCANTRACE_BINARY, alone);
  const std::string run_alone = test::shell_quote(alone.string());
  const std::string trace = "cd " + test::shell_quote(dir.path().string()) + " && " + run_alone +
                            " trace scene.json -o t.jsonl 2> err.txt";
  const int trace_status = std::system(trace.c_str());
  CHECK((WIFEXITED(trace_status) && WEXITSTATUS(trace_status) == 2));
  CHECK_THAT(test::read_text(dir / "err.txt"),
             Catch::Contains("'trace' is not in the demo's build") &&
                 Catch::Contains("'bash scripts/build.sh' builds every subcommand"));
  const std::string render = "cd " + test::shell_quote(dir.path().string()) + " && " + run_alone +
                             " -q render scene.json --shading flat -o alone.png";
  CHECK(std::system(render.c_str()) == 0);
  const cv::Mat png = read_bgr(dir / "alone.png");
  REQUIRE_FALSE(png.empty());
  CHECK(png.at<cv::Vec3b>(100, 100) == bgr_of({1.0 / 3, 1.0 / 3, 1.0 / 3}));
}

// The demo's build names the commands it leaves out from a list of its own (kToolsOnlyCommands,
// cli/commands.hpp), kept apart from the full build's registrations (cli/main.cpp): read the
// full build's --help independently and compare, so that a command added to one and not the
// other is caught.
TEST_CASE("the demo's build names exactly the commands the full build adds", "[command]") {
  TempDir dir;
  const auto help = run_scantrace(dir.path(), {"--help"});
  REQUIRE(help.exit_code == 0);
  // CLI11's subcommand list: after "Subcommands:", each name at two spaces' indent.
  const auto list = help.out.find("Subcommands:");
  REQUIRE(list != std::string::npos);
  std::set<std::string> full;
  std::istringstream lines(help.out.substr(list));
  for (std::string line; std::getline(lines, line);)
    if (line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ')
      full.insert(line.substr(2, line.find(' ', 2) - 2));
  std::set<std::string> demo_build{"demo", "render"};
  for (const char* name : scantrace::cli::kToolsOnlyCommands) demo_build.insert(name);
  CHECK(full == demo_build);
}

TEST_CASE("usage errors exit 2", "[command]") {
  TempDir dir;
  save_scene(two_triangles(), dir / "scene.json");
  const std::vector<std::vector<std::string>> usage_errors{
      {},
      {"paint"},
      {"render"},
      {"render", "scene.json", "--bogus"},
      {"render", "scene.json", "--shading", "phong"},
      {"render", "scene.json", "--fill-rule", "even-odd"},
      {"render", "scene.json", "--subpixel-bits", "13"},
      {"render", "scene.json", "--occlusion", "--no-occlusion"},
      {"demo", "extra"}};
  for (const auto& args : usage_errors) {
    const auto r = run_scantrace(dir.path(), args);
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("--help"));
  }
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"scene.json"});
}

// A misspelt subcommand is named, with the closest one, not "A subcommand is required" (issue 36).
TEST_CASE("an unknown subcommand is named, with the closest one", "[command]") {
  TempDir dir;
  const auto typo = run_scantrace(dir.path(), {"rendr", "x.json"});
  CHECK(typo.exit_code == 2);
  CHECK(typo.err ==
        "scantrace: usage error: unknown subcommand 'rendr' (did you mean 'render'?)\n"
        "Run 'scantrace --help' for the list of subcommands.\n");
  // After the main command's flag too; two edits away is still suggested.
  const auto quiet = run_scantrace(dir.path(), {"-q", "expalin"});
  CHECK(quiet.exit_code == 2);
  CHECK_THAT(quiet.err, Catch::Contains("unknown subcommand 'expalin' (did you mean 'explain'?)"));
  // Nothing close: no suggestion.
  const auto bogus = run_scantrace(dir.path(), {"bogus"});
  CHECK(bogus.exit_code == 2);
  CHECK_THAT(bogus.err, Catch::Contains("unknown subcommand 'bogus'") && !Catch::Contains("mean"));
  // No word at all is still CLI11's message.
  CHECK_THAT(run_scantrace(dir.path(), {}).err, Catch::Contains("A subcommand is required"));
}

TEST_CASE("render writes the scene's pixels", "[command]") {
  TempDir dir;
  save_scene(two_triangles(), dir / "scene.json");

  const auto r =
      run_scantrace(dir.path(), {"render", "scene.json", "--shading", "flat", "-o", "flat.png"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(one_line(r.err));
  CHECK_THAT(r.err, Catch::Contains("2 faces drawn") && Catch::Contains("0 skipped") &&
                        Catch::Contains("ms"));

  const cv::Mat png = read_bgr(dir / "flat.png");
  REQUIRE(png.type() == CV_8UC3);
  REQUIRE(png.cols == 512);
  REQUIRE(png.rows == 512);
  CHECK(png.at<cv::Vec3b>(0, 0) == cv::Vec3b(255, 255, 255));
  CHECK(png.at<cv::Vec3b>(511, 511) == cv::Vec3b(255, 255, 255));
  CHECK(png.at<cv::Vec3b>(90, 100) == bgr_of({1.0 / 3, 1.0 / 3, 1.0 / 3}));  // at(row, col)
  CHECK(png.at<cv::Vec3b>(300, 310) == bgr_of({1.0, 0.4, 1.0 / 30}));
}

// The report's counts do not depend on the way the render ran (issue 36: near to far counted the
// zero-area faces its box test rejected as hidden, and the bands traded them). A scene built so
// that every count is known: a big face covering the canvas at depth 0, a small one in front of
// it, three small faces behind it and seven zero-area faces (collinear corners) behind it.
TEST_CASE("render's report counts the same faces skipped on every path", "[command]") {
  TempDir dir;
  Scene s;
  s.width = s.height = 64;
  const auto add = [&s](Vec2 a, Vec2 b, Vec2 c, double depth) {
    const int i = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {a, b, c});
    s.vcolors.insert(s.vcolors.end(), {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    s.depth.insert(s.depth.end(), {depth, depth, depth});
    s.faces.push_back({i, i + 1, i + 2});
  };
  add({-10, -10}, {200, -10}, {-10, 200}, 0);  // covers the canvas
  add({20, 20}, {40, 22}, {25, 40}, -1);       // in front of it
  for (int k = 0; k < 3; ++k) add({5.0 + 10 * k, 5}, {12.0 + 10 * k, 6}, {7.0 + 10 * k, 15}, 5);
  for (int k = 0; k < 7; ++k) add({3.0 + 8 * k, 50}, {5.0 + 8 * k, 52}, {7.0 + 8 * k, 54}, 5);
  save_scene(s, dir / "s.json");
  const std::vector<std::pair<std::vector<std::string>, std::string>> paths{
      {{"--no-occlusion"}, "5 faces drawn, 0 culled, 7 skipped"},
      {{"--no-occlusion", "--threads", "3"}, "5 faces drawn, 0 culled, 7 skipped"},
      {{"--occlusion"}, "2 faces drawn, 0 culled, 7 skipped"},
      {{"--occlusion", "--threads", "3"}, "2 faces drawn, 0 culled, 7 skipped"},
      {{"--occlusion", "--shading", "flat"}, "2 faces drawn, 0 culled, 7 skipped"},
      {{"--occlusion", "--depth", "zbuffer"}, "2 faces drawn, 0 culled, 7 skipped"}};
  for (const auto& [options, counts] : paths) {
    std::vector<std::string> args{"render", "s.json", "-o", "s.png"};
    args.insert(args.end(), options.begin(), options.end());
    const auto r = run_scantrace(dir.path(), args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.err, Catch::Contains(counts));
    // Near to far: the three behind are hidden, and the header says the faces were drawn so.
    if (options[0] == "--occlusion")
      CHECK_THAT(r.err, Catch::Contains(", 3 hidden under nearer faces") &&
                            Catch::Contains("near to far, cull"));
    else
      CHECK_THAT(r.err, !Catch::Contains("hidden") && !Catch::Contains("near to far, cull"));
  }
}

TEST_CASE("render writes SCENE's stem .png in the current directory by default", "[command]") {
  TempDir dir;
  std::filesystem::create_directory(dir / "scenes");
  save_scene(two_triangles(), dir / "scenes" / "two.json");
  const auto r = run_scantrace(dir.path(), {"render", "scenes/two.json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"scenes", "two.png"});
  // Default shading is Gouraud: inside triangle B the colour varies, around (300, 300) it is
  // between the vertex colours: red 255, blue small.
  const cv::Mat png = read_bgr(dir / "two.png");
  REQUIRE(png.cols == 512);
  const cv::Vec3b inside = png.at<cv::Vec3b>(300, 310);
  CHECK(inside[2] == 255);
  CHECK(inside[0] <= 26);
}

TEST_CASE("render of the demo scene file matches the library's render", "[command]") {
  TempDir dir;
  save_scene(demo_scene(), dir / "demo.json");
  for (const char* shading : {"flat", "gouraud"}) {
    for (const char* rule : {"top-left", "closed"}) {
      const auto r = run_scantrace(dir.path(), {"render", "demo.json", "--shading", shading,
                                                "--fill-rule", rule, "-o", "out.png"});
      INFO(shading << ", " << rule << ": " << r.err);
      REQUIRE(r.exit_code == 0);
      FillOptions options;
      options.shading = std::string(shading) == "flat" ? Shading::flat : Shading::gouraud;
      options.fill_rule = std::string(rule) == "closed" ? FillRule::closed : FillRule::top_left;
      CHECK(same_pixels(read_bgr(dir / "out.png"), to_bgr8(render(demo_scene(), options))));
    }
  }
}

TEST_CASE("bad input exits 1 with one line naming the file and the element", "[command]") {
  TempDir dir;

  SECTION("a missing scene file") {
    const auto r = run_scantrace(dir.path(), {"render", "missing.json"});
    CHECK(r.exit_code == 1);
    CHECK(r.err == "scantrace: error: missing.json: cannot read file: No such file or directory\n");
  }
  SECTION("a face with an out-of-range vertex index") {
    Scene bad = two_triangles();
    bad.faces[1][2] = 6;
    save_scene(bad, dir / "bad.json");
    const auto r = run_scantrace(dir.path(), {"render", "bad.json", "-o", "bad.png"});
    CHECK(r.exit_code == 1);
    CHECK(r.err ==
          "scantrace: error: bad.json: faces[1]: vertex index 6 is out of range (6 vertices)\n");
  }
  SECTION("a syntax error") {
    test::write_text(dir / "bad.json", "{\"vertices\": [[1, 2],\n [3, 4]]]\n");
    const auto r = run_scantrace(dir.path(), {"render", "bad.json", "-o", "bad.png"});
    CHECK(r.exit_code == 1);
    CHECK(one_line(r.err));
    CHECK_THAT(r.err, Catch::StartsWith("scantrace: error: bad.json:2:9: JSON syntax error: "));
  }
  SECTION("an output that cannot be written") {
    save_scene(two_triangles(), dir / "scene.json");
    const auto r = run_scantrace(dir.path(), {"render", "scene.json", "-o", "no/such/dir.png"});
    CHECK(r.exit_code == 1);
    CHECK(r.err ==
          "scantrace: error: no/such/dir.png: cannot create file: No such file or "
          "directory\n");
  }
  // Never a half-written (or any) output file.
  for (const auto& name : test::file_names(dir.path())) CHECK_THAT(name, !Catch::EndsWith(".png"));
}

TEST_CASE("demo writes the demo renders, the example triangle and the scene", "[command]") {
  TempDir dir;
  const auto r = run_scantrace(dir.path(), {"demo", "-o", "out"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const std::vector<std::string> expected{
      "demo_flat.png", "demo_gouraud.png", "demo_model.png", "demo_scene.json",
      "triangle.html", "triangle.jsonl",   "triangle.mp4",   "triangle_gouraud.png"};
  CHECK(test::file_names(dir / "out") == expected);
  for (const auto& name : expected) CHECK_THAT(r.err, Catch::Contains("out/" + name));

  for (const char* name :
       {"demo_flat.png", "demo_gouraud.png", "demo_model.png", "triangle_gouraud.png"}) {
    const cv::Mat png = read_bgr(dir / "out" / name);
    INFO(name);
    REQUIRE(png.type() == CV_8UC3);
    CHECK(png.cols == 512);
    CHECK(png.rows == 512);
    CHECK(png.at<cv::Vec3b>(0, 0) == cv::Vec3b(255, 255, 255));
  }
  FillOptions flat;
  flat.shading = Shading::flat;
  CHECK(same_pixels(read_bgr(dir / "out" / "demo_flat.png"), to_bgr8(render(demo_scene(), flat))));
  CHECK(same_pixels(read_bgr(dir / "out" / "demo_gouraud.png"), to_bgr8(render(demo_scene()))));

  {
    // The torus: lit (not one flat colour), its hole shows the background at the centre, and
    // Gouraud leaves no two neighbours on a row far apart inside the model.
    const cv::Mat model = read_bgr(dir / "out" / "demo_model.png");
    CHECK(model.at<cv::Vec3b>(256, 256) == cv::Vec3b(255, 255, 255));
    std::set<int> levels;
    int painted = 0;
    for (int y = 0; y < 512; ++y)
      for (int x = 0; x < 512; ++x) {
        const cv::Vec3b p = model.at<cv::Vec3b>(y, x);
        if (p == cv::Vec3b(255, 255, 255)) continue;
        ++painted;
        levels.insert(p[0] + p[1] + p[2]);
      }
    CHECK(painted > 512 * 512 / 8);
    CHECK(levels.size() > 200);
  }

  // The course's triangle (20,20) red, (250,80) green, (300,400) blue: at its centroid
  // (190, 166.67) the colour is close to the mean (1/3 each).
  const cv::Vec3b centre = read_bgr(dir / "out" / "triangle_gouraud.png").at<cv::Vec3b>(167, 190);
  for (int k = 0; k < 3; ++k) CHECK(std::abs(centre[k] - 85) <= 2);

  test::require_equal_scenes(load_scene(dir / "out" / "demo_scene.json"), demo_scene());

  // The page of the course's triangle at 1280x720 stays under the 8 MB the issue allows (the
  // frames are lossless; tests/viz/test_html_player.cpp checks they are the replayer's).
  CHECK(std::filesystem::file_size(dir / "out" / "triangle.html") < 8'000'000);

  // The trace narrates that triangle: its spans cover exactly the non-white pixels of the PNG.
  const trace::Trace tr = trace::Trace::load(dir / "out" / "triangle.jsonl");
  CHECK(tr.triangles() == std::vector<int>{0});
  const cv::Mat triangle_png = read_bgr(dir / "out" / "triangle_gouraud.png");
  for (const trace::Scanline* s : tr.scanlines(0))
    for (int x = 0; x < 512; ++x) {
      const bool in_span = s->span && s->span->contains(x);
      CHECK(in_span ==
            (triangle_png.at<cv::Vec3b>(static_cast<int>(s->y), x) != cv::Vec3b(255, 255, 255)));
    }

  // The default directory.
  const auto default_run = run_scantrace(dir.path(), {"demo"});
  CHECK(default_run.exit_code == 0);
  CHECK(test::file_names(dir / "scantrace-demo") == expected);
}

TEST_CASE("without scantrace-tools beside it (the demo's build), scantrace runs the demo itself",
          "[command]") {
  // The demo's build (scripts/build.sh --demo) has no scantrace-tools and no OpenCV: `scantrace`
  // alone, copied here without its sibling, is that build's command (cli/main_render.cpp).
  TempDir dir;
  std::filesystem::create_directories(dir / "bin");
  std::filesystem::copy_file(SCANTRACE_BINARY, dir / "bin" / "scantrace");
  const auto run = [&](const std::string& args) {
    // Built by appending: GCC 12 raises a false -Wrestrict alarm on "literal" + std::string&&.
    std::string command = "cd ";
    command += test::shell_quote(dir.path().string());
    command += " && bin/scantrace ";
    command += args;
    command += " >out.txt 2>err.txt";
    const int status = std::system(command.c_str());
    return std::pair{WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_text(dir / "err.txt")};
  };
  const auto [status, err] = run("demo -o out");
  INFO("stderr: " << err);
  REQUIRE(status == 0);
  // Everything the full build's demo writes but the video, and a line saying how to make it.
  const std::vector<std::string> expected{"demo_flat.png",  "demo_gouraud.png", "demo_model.png",
                                          "demo_scene.json", "triangle.html",   "triangle.jsonl",
                                          "triangle_gouraud.png"};
  CHECK(test::file_names(dir / "out") == expected);
  CHECK_THAT(err, Catch::Contains("after 'bash scripts/test.sh', run: scantrace replay "
                                  "out/triangle.jsonl -o out/triangle.mp4"));
  FillOptions flat;
  flat.shading = Shading::flat;
  CHECK(same_pixels(read_bgr(dir / "out" / "demo_flat.png"), to_bgr8(render(demo_scene(), flat))));
  CHECK(same_pixels(read_bgr(dir / "out" / "demo_gouraud.png"), to_bgr8(render(demo_scene()))));
  // The page: the triangle's 47 steps as SVG frames (tests/composer checks they are the
  // composer's), small enough to mail.
  const nlohmann::json data = test::page_data(test::read_text(dir / "out" / "triangle.html"));
  CHECK(data["mime"] == "image/svg+xml");
  CHECK(data["frames"].size() == 47);
  CHECK(std::filesystem::file_size(dir / "out" / "triangle.html") < 8'000'000);
  CHECK(trace::Trace::load(dir / "out" / "triangle.jsonl").triangles() == std::vector<int>{0});
}

TEST_CASE("render of the course scene writes a 512x512 PNG", "[command][shared_data]") {
  const auto scene = test::shared_data("hw1_2024.json");
  if (!std::filesystem::exists(scene)) {
    WARN("skipped: " << scene << " does not exist");
    return;
  }
  TempDir dir;
  const auto r = run_scantrace(dir.path(), {"render", scene.string()});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("faces drawn"));
  const cv::Mat png = read_bgr(dir / "hw1_2024.png");
  REQUIRE(png.type() == CV_8UC3);
  CHECK(png.cols == 512);
  CHECK(png.rows == 512);
  CHECK(png.at<cv::Vec3b>(0, 0) == cv::Vec3b(255, 255, 255));
  // The scene hides most of its faces behind its front: the default draws it near to far and
  // says so; --no-occlusion paints far to near, the same pixels.
  CHECK_THAT(r.err, Catch::Contains("written once each, near to far"));
  const auto far =
      run_scantrace(dir.path(), {"render", scene.string(), "--no-occlusion", "-o", "far.png"});
  INFO("stderr: " << far.err);
  REQUIRE(far.exit_code == 0);
  CHECK_THAT(far.err, !Catch::Contains("near to far"));
  CHECK(cv::norm(read_bgr(dir / "far.png"), png, cv::NORM_INF) == 0);
}
