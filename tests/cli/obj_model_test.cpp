// OBJ models: the loader (triangulation, colours, errors with file:line), and render / trace of a
// model from the command line, including the african head of ../shared/data when it exists.
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "io/obj_loader.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "trace/trace.hpp"

using namespace scantrace;
using test::run_scantrace;
using test::TempDir;

namespace {

// A unit cube around the origin, six quads counter-clockwise seen from outside.
const char* const kCube =
    "# cube\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 5 6 7 8\n"   // +z
    "f 2 1 4 3\n"   // -z
    "f 6 2 3 7\n"   // +x
    "f 1 5 8 4\n"   // -x
    "f 8 7 3 4\n"   // +y
    "f 1 2 6 5\n";  // -y

}  // namespace

TEST_CASE("OBJ: a cube of quads becomes 12 outward triangles", "[obj]") {
  const Mesh m = parse_obj(kCube, "cube.obj");
  CHECK(m.positions.size() == 8);
  REQUIRE(m.faces.size() == 12);
  CHECK(m.colors.empty());
  CHECK(m.normals.empty());
  for (const auto& f : m.faces) {
    const Vec3 a = m.positions[f[0]], b = m.positions[f[1]], c = m.positions[f[2]];
    // Outward: the normal points the way the centroid lies from the cube's centre.
    CHECK(dot(cross(b - a, c - a), a + b + c) > 0);
  }
}

TEST_CASE("OBJ: a quad is triangulated and covers exactly its rectangle", "[obj]") {
  const Mesh m = parse_obj("v 0 0 0\nv 4 0 0\nv 4 2 0\nv 0 2 0\nf 1 2 3 4\n", "quad.obj");
  REQUIRE(m.faces.size() == 2);
  ShadeOptions o;
  o.camera.width = 100;
  o.camera.height = 50;
  o.light.enabled = false;
  o.colors = ColorSource::white;
  o.background = {0, 0, 0};
  // Fitted: scale min(90/4, 45/2) = 22.5 about (49.5, 24.5): x 4.5…94.5, y 2…47. Top-left rule:
  // columns 5…94, rows 2…46 — every pixel once, nothing else.
  const RgbImage img = render(shade_mesh(m, o));
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 100; ++x) {
      const bool inside = x >= 5 && x <= 94 && y >= 2 && y <= 46;
      INFO(x << "," << y);
      CHECK((img(x, y).color() == Color{1, 1, 1}) == inside);
    }
}

TEST_CASE("OBJ: vertex colours and normals are read", "[obj]") {
  const Mesh m = parse_obj(
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 0.5\nvn 0 0 1\nf 1//1 2//1 3//1\n", "c.obj");
  REQUIRE(m.colors.size() == 3);
  CHECK(m.colors[2] == Color{0, 0, 0.5});
  REQUIRE(m.normals.size() == 1);
  CHECK(m.face_normals == std::vector<std::array<int, 3>>{{0, 0, 0}});
  // A file that colours only some vertices has no colours.
  CHECK(parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "p.obj").colors.empty());
}

TEST_CASE("OBJ: a malformed file is one error naming file, line and problem", "[obj]") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"v 1 2\n", "m.obj:1: v: expected 3 to 6 numbers, got 2"},
      {"# c\nv 0 nan 0\n", "m.obj:2: v: \"nan\" is not a finite number"},
      {"v 0 1e999 0\n", "m.obj:1: v: \"1e999\" is not a finite number"},
      {"v 0 abc 0\n", "m.obj:1: v: \"abc\" is not a finite number"},
      {"v 0 0 0 1 2 0\n", "m.obj:1: v: colour component 2 is outside [0, 1]"},
      {tri + "f 1 2 4\n",
       "m.obj:4: f: corner \"4\": vertex index 4 is out of range (3 vertices so far)"},
      {tri + "f 1 2 0\n",
       "m.obj:4: f: corner \"0\": vertex index 0 is out of range (3 vertices so far)"},
      {tri + "f -4 2 3\n",
       "m.obj:4: f: corner \"-4\": vertex index -4 is out of range (3 vertices so far)"},
      {tri + "f 1 2\n", "m.obj:4: f: a face needs at least 3 corners, got 2"},
      {tri + "f 1 x 3\n", "m.obj:4: f: corner \"x\": \"x\" is not an integer index"},
      {tri + "vn 0 0 1\nf 1//1 2//2 3//1\n",
       "m.obj:5: f: corner \"2//2\": normal index 2 is out of range (1 normals so far)"},
      {"# nothing\n", "m.obj: the model has no faces"},
      // Found by fuzzing (fuzz/regressions/obj_loader/): tinyobjloader ends a line at a lone
      // '\r', so this face was read with index 21 and read past the vertices.
      {tri + "v1 2  1\rf 1 1 21\n",
       "m.obj: face 1: vertex index 21 is out of range (3 vertices; lines ended by a lone "
       "carriage return count too)"},
  };
  for (const auto& [text, message] : cases) {
    INFO(text);
    try {
      parse_obj(text, "m.obj");
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()) == message);
    }
  }
  // Negative (relative) indices are valid.
  CHECK(parse_obj(tri + "f -3 -2 -1\n", "m.obj").faces.size() == 1);
}

TEST_CASE("render MODEL.obj: culled faces counted, bad files exit 1 with one line", "[obj]") {
  TempDir dir;
  test::write_text(dir / "cube.obj", kCube);
  // Looking down −z at an axis-aligned cube: +z's two triangles face the viewer, −z's two face
  // away, and the eight side triangles are edge-on (zero area: skipped, not culled).
  auto r = run_scantrace(dir.path(), {"render", "cube.obj", "-o", "cube.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("2 faces drawn, 2 culled, 8 skipped"));
  r = run_scantrace(dir.path(), {"render", "cube.obj", "--cull", "none", "-o", "cube2.png"});
  CHECK_THAT(r.err, Catch::Contains("4 faces drawn, 0 culled, 8 skipped"));

  test::write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  r = run_scantrace(dir.path(), {"render", "bad.obj", "-o", "bad.png"});
  CHECK(r.exit_code == 1);
  CHECK(r.err ==
        "scantrace: error: bad.obj:4: f: corner \"9\": vertex index 9 is out of range (3 "
        "vertices so far)\n");
  CHECK_FALSE(std::filesystem::exists(dir / "bad.png"));

  // trace: the culled faces appear as triangle_skipped with reason "culled".
  r = run_scantrace(dir.path(), {"trace", "cube.obj", "-o", "cube.jsonl"});
  REQUIRE(r.exit_code == 0);
  const trace::Trace t = trace::Trace::load(dir / "cube.jsonl");
  const std::string text = test::read_text(dir / "cube.jsonl");
  std::size_t culled = 0;
  for (std::size_t at = 0; (at = text.find("\"reason\":\"culled\"", at)) != std::string::npos; ++at)
    ++culled;
  CHECK(culled == 2);
}

TEST_CASE("the african head renders lit and culled", "[obj][shared_data]") {
  const auto file = test::shared_data("african_head.obj");
  if (!std::filesystem::exists(file)) {
    WARN("skipped: " << file << " does not exist");
    return;
  }
  TempDir dir;
  const auto r = run_scantrace(dir.path(), {"render", file.string(), "--light", "0,0,-1", "--cull",
                                            "back", "--gamma", "2.2", "-o", "head.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);

  // The culled count, bounded independently: looking down −z orthographically, a face is a back
  // face when its normal's z is negative; faces nearly edge-on may snap to zero area instead.
  const Mesh m = load_obj(file);
  long surely_back = 0, maybe_back = 0;
  for (const auto& f : m.faces) {
    const Vec3 a = m.positions[f[0]], b = m.positions[f[1]], c = m.positions[f[2]];
    const Vec3 n = cross(b - a, c - a);
    const double tol = 1e-3 * length(n);
    surely_back += n.z < -tol;
    maybe_back += n.z < tol;
  }
  const auto pos = r.err.find(" culled");
  REQUIRE(pos != std::string::npos);
  const long culled = std::stol(r.err.substr(r.err.rfind(' ', pos - 1) + 1));
  CHECK(culled >= surely_back);
  CHECK(culled <= maybe_back);
  CHECK(surely_back > 500);

  const cv::Mat png = cv::imread((dir / "head.png").string(), cv::IMREAD_COLOR);
  REQUIRE(png.rows == 512);
  const cv::Vec3b white(255, 255, 255);
  CHECK(png.at<cv::Vec3b>(0, 0) == white);
  CHECK(png.at<cv::Vec3b>(511, 511) == white);
  // The forehead faces the light (0,0,−1): nearly fully lit, grey (white × intensity).
  const cv::Vec3b forehead = png.at<cv::Vec3b>(100, 256);
  CHECK(forehead[0] > 200);
  CHECK(forehead[0] < 255);
  CHECK(forehead[0] == forehead[2]);
  // The head is nearly mirror-symmetric about the canvas's centre column, where the fit puts the
  // model's centre: coverage and its mirror image differ in few pixels.
  long covered = 0, asymmetric = 0;
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 512; ++x) {
      const bool here = png.at<cv::Vec3b>(y, x) != white;
      const bool mirror = png.at<cv::Vec3b>(y, 511 - x) != white;
      covered += here;
      asymmetric += here != mirror;
    }
  CHECK(covered > 512 * 512 / 4);
  CHECK(asymmetric < covered / 10);
}

TEST_CASE("model flags: seeds, perspective, gamma and their errors", "[obj]") {
  TempDir dir;
  test::write_text(dir / "cube.obj", kCube);
  const auto render = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"render", "cube.obj"});
    return run_scantrace(dir.path(), args);
  };
  // --model-colors random: a seed names the picture.
  REQUIRE(render({"--model-colors", "random", "--unlit", "--seed", "3", "-o", "a.png"}).exit_code ==
          0);
  REQUIRE(render({"--model-colors", "random", "--unlit", "--seed", "3", "-o", "b.png"}).exit_code ==
          0);
  REQUIRE(render({"--model-colors", "random", "--unlit", "--seed", "4", "-o", "c.png"}).exit_code ==
          0);
  CHECK(test::read_text(dir / "a.png") == test::read_text(dir / "b.png"));
  CHECK(test::read_text(dir / "a.png") != test::read_text(dir / "c.png"));

  // A perspective camera off the axes sees three faces of the cube: 6 triangles drawn, 6 culled.
  auto r = render({"--eye", "3,2.5,4", "--fov", "40", "-o", "p.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("6 faces drawn, 6 culled, 0 skipped"));

  // Gamma: the +z face lit head-on is white, so with the light from the side (0.6 of it) the
  // face reads 0.1 + 0.9·0.6 = 0.64 linear, encoded 0.64^(1/2.2) = 0.8162 → 208 in 8 bits.
  r = render({"--light", "0,-0.8,-0.6", "--gamma", "2.2", "--shading", "flat", "-o", "g.png"});
  REQUIRE(r.exit_code == 0);
  const cv::Mat g = cv::imread((dir / "g.png").string(), cv::IMREAD_COLOR);
  CHECK(g.at<cv::Vec3b>(256, 256) == cv::Vec3b(208, 208, 208));

  r = render({"--eye", "0,0,0", "--target", "0,0,0", "-o", "e.png"});
  CHECK(r.exit_code == 1);
  CHECK(r.err == "scantrace: error: cube.obj: camera: the eye is at the target\n");
  CHECK(render({"--light", "0,0", "-o", "x.png"}).exit_code == 2);
  CHECK(render({"--cull", "sideways", "-o", "x.png"}).exit_code == 2);
  CHECK(render({"--target", "0,0,0", "-o", "x.png"}).exit_code == 2);  // needs --eye
}
