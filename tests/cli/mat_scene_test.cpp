// MATLAB .mat scenes (io/mat_scene.hpp), written here with matio in both formats it writes: the
// 1-based, column-major mapping on a scene small enough to derive by hand, a generated scene
// whose render must equal its JSON twin's, and the bad files.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <matio.h>
#include <catch2/catch.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "demo/demo_scene.hpp"
#include "io/mat_scene.hpp"
#include "io/scene_json.hpp"
#include "scene_compare.hpp"

using namespace scantrace;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

namespace {

// One variable: a rows×cols matrix given in MATLAB's memory order (column after column).
struct MatVar {
  std::string name;
  std::size_t rows = 0, cols = 0;
  std::vector<double> column_major;
  matio_classes cls = MAT_C_DOUBLE;  // MAT_C_DOUBLE, MAT_C_INT32 or MAT_C_CHAR
  bool complex = false;
};

void write_mat(const std::filesystem::path& file, const std::vector<MatVar>& vars,
               mat_ft version = MAT_FT_MAT5, matio_compression compression = MAT_COMPRESSION_NONE) {
  mat_t* mat = Mat_CreateVer(file.c_str(), nullptr, version);
  REQUIRE(mat != nullptr);
  for (const MatVar& v : vars) {
    std::size_t dims[2] = {v.rows, v.cols};
    // Converted only for the class that stores them: the double cases hold values (NaN, 132.1)
    // that no int32 or char can represent.
    std::vector<std::int32_t> ints;
    std::vector<char> chars;
    if (v.cls == MAT_C_INT32) ints.assign(v.column_major.begin(), v.column_major.end());
    if (v.cls == MAT_C_CHAR) chars.assign(v.column_major.begin(), v.column_major.end());
    std::vector<double> re = v.column_major, im(v.column_major.size(), 1.0);
    mat_complex_split_t split{re.data(), im.data()};
    matvar_t* var = nullptr;
    if (v.cls == MAT_C_INT32)
      var = Mat_VarCreate(v.name.c_str(), MAT_C_INT32, MAT_T_INT32, 2, dims, ints.data(), 0);
    else if (v.cls == MAT_C_CHAR)
      var = Mat_VarCreate(v.name.c_str(), MAT_C_CHAR, MAT_T_UINT8, 2, dims, chars.data(), 0);
    else if (v.complex)
      var =
          Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &split, MAT_F_COMPLEX);
    else
      var = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, re.data(), 0);
    REQUIRE(var != nullptr);
    REQUIRE(Mat_VarWrite(mat, var, compression) == 0);
    Mat_VarFree(var);
  }
  Mat_Close(mat);
}

// A scene in the course's MATLAB conventions, converted here independently of the reader: rows
// are vertices/faces, stored column after column, face indices + 1, coordinates + 1 (MATLAB's
// pixel (1, 1) is scantrace's (0, 0)).
std::vector<MatVar> course_vars(const Scene& s) {
  const std::size_t n = s.vertices.size(), k = s.faces.size();
  MatVar v{"vertices_2d", n, 2, {}}, f{"faces", k, 3, {}}, c{"vertex_colors", n, 3, {}},
      d{"depth", n, 1, s.depth};
  for (std::size_t i = 0; i < n; ++i) v.column_major.push_back(s.vertices[i].x + 1);
  for (std::size_t i = 0; i < n; ++i) v.column_major.push_back(s.vertices[i].y + 1);
  for (std::size_t col = 0; col < 3; ++col)
    for (std::size_t i = 0; i < k; ++i) f.column_major.push_back(s.faces[i][col] + 1);
  for (std::size_t i = 0; i < n; ++i) c.column_major.push_back(s.vcolors[i].r);
  for (std::size_t i = 0; i < n; ++i) c.column_major.push_back(s.vcolors[i].g);
  for (std::size_t i = 0; i < n; ++i) c.column_major.push_back(s.vcolors[i].b);
  return {v, f, c, d};
}

// Two triangles sharing the edge 2-3 (MATLAB numbering), 4 vertices.
std::vector<MatVar> small_vars() {
  return {{"vertices_2d", 4, 2, {10, 100, 10, 100, /* y: */ 10, 10, 90, 90}},
          {"faces", 2, 3, {1, 2, /* col 2 */ 2, 4, /* col 3 */ 3, 3}},
          {"vertex_colors", 4, 3, {1, 0, 0, 0.5, 0, 1, 0, 0.5, 0, 0, 1, 0.5}},
          {"depth", 4, 1, {4, 3, 2, 1}}};
}

std::string load_error(const std::filesystem::path& file) {
  try {
    load_mat_scene(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE(".mat: 1-based rows and columns map to scantrace's scene", "[mat]") {
  TempDir dir;
  for (const matio_compression compression : {MAT_COMPRESSION_NONE, MAT_COMPRESSION_ZLIB}) {
    CAPTURE(compression == MAT_COMPRESSION_NONE ? "v5" : "v7 (compressed v5)");
    const auto file = dir / "small.mat";
    write_mat(file, small_vars(), MAT_FT_MAT5, compression);
    const Scene s = load_mat_scene(file);
    // By hand from small_vars(): row i of each matrix is vertex i - 1, at MATLAB's 1-based
    // pixel coordinates minus 1.
    CHECK(s.vertices == std::vector<Vec2>{{9, 9}, {99, 9}, {9, 89}, {99, 89}});
    CHECK(s.faces == std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 2}});
    CHECK(s.vcolors == std::vector<Color>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0.5}});
    CHECK(s.depth == std::vector<double>{4, 3, 2, 1});
    CHECK(s.width == 512);
    CHECK(s.height == 512);
    CHECK(s.background == Color{1, 1, 1});
  }
  // Integer classes are read too (MATLAB users often store faces as int32).
  auto vars = small_vars();
  vars[1].cls = MAT_C_INT32;
  write_mat(dir / "int_faces.mat", vars);
  CHECK(load_mat_scene(dir / "int_faces.mat").faces ==
        std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 2}});
  // A 1×L depth is the same vector.
  vars = small_vars();
  vars[3].rows = 1;
  vars[3].cols = 4;
  write_mat(dir / "row_depth.mat", vars);
  CHECK(load_mat_scene(dir / "row_depth.mat").depth == std::vector<double>{4, 3, 2, 1});
}

// The 2021 course's MATLAB code paints a vertex at img(floor(y + 0.5), floor(x + 0.5), :), 1-based:
// a triangle around MATLAB's pixel (x, y) = (5, 7) must colour scantrace's pixel (4, 6), the
// fifth column and seventh row, and nothing else (issue 36: the reader did not subtract 1).
TEST_CASE(".mat: MATLAB's pixel (x, y) is scantrace's (x - 1, y - 1)", "[mat][command]") {
  TempDir dir;
  // One red triangle whose 0.8-pixel extent holds only the centre of MATLAB pixel (5, 7).
  const std::vector<MatVar> vars{{"vertices_2d", 3, 2, {4.6, 5.4, 5, /* y: */ 6.6, 6.6, 7.4}},
                                 {"faces", 1, 3, {1, 2, 3}},
                                 {"vertex_colors", 3, 3, {1, 1, 1, 0, 0, 0, 0, 0, 0}},
                                 {"depth", 3, 1, {1, 1, 1}}};
  write_mat(dir / "one_pixel.mat", vars);
  const auto r = run_scantrace(dir.path(), {"-q", "render", "one_pixel.mat", "--size", "12x12",
                                            "--unlit", "-o", "one_pixel.png"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const cv::Mat png = cv::imread((dir / "one_pixel.png").string(), cv::IMREAD_COLOR);
  REQUIRE(png.size() == cv::Size(12, 12));
  std::vector<cv::Point> red;
  for (int y = 0; y < png.rows; ++y)
    for (int x = 0; x < png.cols; ++x)
      if (png.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255)) red.emplace_back(x, y);
  REQUIRE(red.size() == 1);
  CHECK(red[0] == cv::Point(4, 6));
  CHECK(png.at<cv::Vec3b>(6, 4) == cv::Vec3b(0, 0, 255));  // BGR
}

TEST_CASE(".mat: v7.3 (HDF5) and v4 files are refused before matio opens them", "[mat][errors]") {
  // Both written by matio itself, holding the same valid scene that loads from v5: the refusal is
  // for the format, not the content. (Without the check the v7.3 file loads through HDF5, which
  // the fuzz target found unsafe; the v4 one loads through matio's unchecked v4 reader.)
  TempDir dir;
  write_mat(dir / "v73.mat", small_vars(), MAT_FT_MAT73);
  write_mat(dir / "v4.mat", small_vars(), MAT_FT_MAT4);
  write_mat(dir / "v5.mat", small_vars(), MAT_FT_MAT5);
  CHECK(load_mat_scene(dir / "v5.mat").faces.size() == 2);
  CHECK_THAT(load_error(dir / "v73.mat"),
             Catch::StartsWith((dir / "v73.mat").string() + ": is a MATLAB v7.3 (HDF5) file") &&
                 Catch::Contains("'-v7'"));
  CHECK_THAT(load_error(dir / "v4.mat"),
             Catch::StartsWith((dir / "v4.mat").string() + ": is not a MATLAB v5/v7 .mat file"));
  const auto r = run_scantrace(dir.path(), {"render", "v73.mat", "-o", "x.png"});
  CHECK(r.exit_code == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST_CASE(".mat: a generated scene renders like its JSON twin, v5 and v7", "[mat][command]") {
  TempDir dir;
  Scene scene = demo_scene();
  // Coordinates on a 1/256 grid, so that the + 1 of course_vars and the reader's - 1 are exact.
  for (Vec2& v : scene.vertices) v = {std::round(v.x * 256) / 256, std::round(v.y * 256) / 256};
  // A .mat scene has no canvas: the JSON twin states the default explicitly.
  scene.width = scene.height = kDefaultCanvasSize;
  scene.background = {1, 1, 1};
  REQUIRE(scene.faces.size() > 100);
  save_scene(scene, dir / "twin.json");
  write_mat(dir / "v7.mat", course_vars(scene), MAT_FT_MAT5, MAT_COMPRESSION_ZLIB);
  write_mat(dir / "v5.mat", course_vars(scene), MAT_FT_MAT5);
  scantrace::test::require_equal_scenes(load_mat_scene(dir / "v5.mat"), scene);
  scantrace::test::require_equal_scenes(load_mat_scene(dir / "v7.mat"), scene);

  for (const char* name : {"twin.json", "v5.mat", "v7.mat"}) {
    const auto r =
        run_scantrace(dir.path(), {"-q", "render", name, "-o", std::string(name) + ".png"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
  const cv::Mat json = cv::imread((dir / "twin.json.png").string(), cv::IMREAD_UNCHANGED);
  REQUIRE(json.cols == 512);
  for (const char* name : {"v5.mat.png", "v7.mat.png"}) {
    const cv::Mat mat = cv::imread((dir / name).string(), cv::IMREAD_UNCHANGED);
    REQUIRE(mat.size() == json.size());
    CHECK(cv::norm(mat, json, cv::NORM_INF) == 0);
  }
  // trace reads it too; its header names the default canvas.
  const auto t =
      run_scantrace(dir.path(), {"-q", "trace", "v5.mat", "--level", "triangle", "-o", "v5.jsonl"});
  INFO(t.err);
  CHECK(t.exit_code == 0);
  CHECK_THAT(scantrace::test::read_text(dir / "v5.jsonl"),
             Catch::Contains(R"("canvas":{"width":512,"height":512})"));
}

TEST_CASE(".mat: bad files name the variable and the row, one line, exit 1", "[mat][errors]") {
  TempDir dir;
  struct Case {
    const char* what;
    std::vector<MatVar> vars;
    std::string expected;
  };
  auto with = [](std::size_t i, auto change) {
    auto vars = small_vars();
    change(vars[i]);
    return vars;
  };
  auto without = [](std::size_t i) {
    auto vars = small_vars();
    vars.erase(vars.begin() + static_cast<long>(i));
    return vars;
  };
  const std::vector<Case> cases{
      {"missing variable", without(2), "bad.mat: vertex_colors: missing variable"},
      {"wrong shape",
       with(0,
            [](MatVar& v) {
              v.rows = 2;
              v.cols = 4;
            }),
       "bad.mat: vertices_2d: is 2x4, expected L x 2"},
      {"index 0", with(1, [](MatVar& v) { v.column_major[3] = 0; }),
       "bad.mat: faces(2,:): vertex index 0 is out of range 1..4"},
      {"index out of range", with(1, [](MatVar& v) { v.column_major[4] = 5; }),
       "bad.mat: faces(1,:): vertex index 5 is out of range 1..4"},
      {"fractional index", with(1, [](MatVar& v) { v.column_major[0] = 1.5; }),
       "bad.mat: faces(1,:): vertex index 1.5 is not an integer"},
      {"non-numeric",
       with(3,
            [](MatVar& v) {
              v.cls = MAT_C_CHAR;
              v.column_major = {65, 66, 67, 68};
            }),
       "bad.mat: depth: is a char array, expected a numeric matrix"},
      {"complex", with(0, [](MatVar& v) { v.complex = true; }), "bad.mat: vertices_2d: is complex"},
      {"colour rows",
       with(2,
            [](MatVar& v) {
              v.rows = 3;
              v.column_major.resize(9);
            }),
       "bad.mat: vertex_colors: has 3 rows but vertices_2d has 4"},
      {"colour range", with(2, [](MatVar& v) { v.column_major[5] = 2; }),
       "bad.mat: vertex_colors(2,:): colour [0, 2, 0] has a component outside [0, 1]"},
      {"NaN", with(0, [](MatVar& v) { v.column_major[6] = std::nan(""); }),
       "bad.mat: vertices_2d(3,:): coordinate is not a finite number"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    write_mat(dir / "bad.mat", c.vars);
    CHECK_THAT(load_error(dir / "bad.mat"), Catch::Contains(c.expected));
  }

  // Through the command: one line on stderr, exit status 1, for each command that reads scenes.
  write_mat(dir / "bad.mat", with(1, [](MatVar& v) { v.column_major[3] = 0; }));
  for (const std::vector<std::string>& args : {std::vector<std::string>{"render", "bad.mat"},
                                               {"trace", "bad.mat", "-o", "t.jsonl"},
                                               {"explain", "bad.mat", "-o", "e.mp4"}}) {
    CAPTURE(args[0]);
    const auto r = run_scantrace(dir.path(), args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Catch::Contains("bad.mat: faces(2,:): vertex index 0 is out of range"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  // Not a .mat file at all.
  scantrace::test::write_text(dir / "text.mat", "vertices_2d = [1 2; 3 4]\n");
  CHECK_THAT(load_error(dir / "text.mat"),
             Catch::Contains("text.mat: is not a MATLAB v5/v7 .mat file (no v5 header"));
}

TEST_CASE(".mat: a damaged v5 file is one line, never values from beyond its data",
          "[mat][errors][robustness]") {
  // matio reads a numeric variable by the count its dimensions declare: a file missing its last
  // bytes rendered differently from the intact one, and a faces variable declaring 2x3 while
  // holding 1x3 took its second row from freed memory (issue 37 #2).
  TempDir dir;
  const std::vector<MatVar> vars = small_vars();
  write_mat(dir / "v5.mat", vars);
  write_mat(dir / "zlib.mat", vars, MAT_FT_MAT5, MAT_COMPRESSION_ZLIB);
  REQUIRE_NOTHROW(load_mat_scene(dir / "v5.mat"));
  REQUIRE_NOTHROW(load_mat_scene(dir / "zlib.mat"));
  const std::string v5 = scantrace::test::read_text(dir / "v5.mat");
  const std::string zlib = scantrace::test::read_text(dir / "zlib.mat");

  // Cut at every length from 8 bytes short down to the header: each one refused.
  for (std::size_t cut = 1; cut <= 8; ++cut) {
    CAPTURE(cut);
    scantrace::test::write_text(dir / "cut.mat", v5.substr(0, v5.size() - cut));
    CHECK_THAT(load_error(dir / "cut.mat"), Catch::Contains("cut.mat") &&
                                                Catch::Contains("truncated"));
  }
  for (std::size_t cut : {1, 4, 12}) {
    CAPTURE(cut);
    scantrace::test::write_text(dir / "cut.mat", zlib.substr(0, zlib.size() - cut));
    CHECK_THAT(load_error(dir / "cut.mat"), Catch::Contains("cut.mat: ") &&
                                                (Catch::Contains("truncated") ||
                                                 Catch::Contains("damaged")));
  }

  // faces written as 1x3, its dimensions then patched to 2x3: the data holds 3 values.
  std::vector<MatVar> one_face = vars;
  one_face[1].rows = 1;
  one_face[1].column_major = {1, 2, 3};
  write_mat(dir / "one.mat", one_face);
  std::string patched = scantrace::test::read_text(dir / "one.mat");
  const std::size_t name = patched.find("faces");
  REQUIRE(name != std::string::npos);
  // Before the name: its tag (8 bytes), and before that the dimensions' data, rows then columns.
  REQUIRE(patched[name - 16] == 1);
  patched[name - 16] = 2;
  scantrace::test::write_text(dir / "patched.mat", patched);
  CHECK_THAT(load_error(dir / "patched.mat"),
             Catch::Contains("patched.mat: faces: the file is damaged: its dimensions 2x3 declare "
                             "6 values but its data holds 3"));

  // Through the command: one line, exit 1.
  const auto r = run_scantrace(dir.path(), {"render", "patched.mat", "-o", "p.png"});
  CHECK(r.exit_code == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "p.png"));
}
