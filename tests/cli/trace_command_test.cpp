// `scantrace trace`: what it writes is the recorded narration of the same fill; filters and caps
// are honoured and reported; bad arguments are usage errors, bad input files input errors.
#include <catch2/catch.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "trace/event_json.hpp"
#include "trace/record.hpp"

using namespace scantrace;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

TEST_CASE("trace --triangle writes the recorded narration of that triangle", "[command][trace]") {
  TempDir dir;
  const auto r = run_scantrace(
      dir.path(), {"trace", "--triangle", "20,20 250,80 300,400", "--colors", "1,0,0 0,1,0 0,0,1",
                   "--shading", "flat", "--level", "pixel", "-o", "t.jsonl"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const trace::Trace written = trace::Trace::load(dir / "t.jsonl");
  trace::TriangleInput in;
  in.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  in.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  const trace::Trace recorded = trace::record_triangle(
      in, FillOptions{.shading = Shading::flat}, trace::TraceFilter{.level = TraceLevel::pixel});
  REQUIRE(written.events().size() == recorded.events().size());
  for (std::size_t i = 0; i < written.events().size(); ++i)
    CHECK(trace::event_to_json(written.events()[i]).dump() ==
          trace::event_to_json(recorded.events()[i]).dump());
  CHECK(written.header().shading == Shading::flat);
  CHECK(written.header().level == TraceLevel::pixel);
}

TEST_CASE("trace of a scene file honours the filters and reports a cap", "[command][trace]") {
  TempDir dir;
  save_scene(demo_scene(), dir / "scene.json");
  const auto r = run_scantrace(dir.path(), {"trace", "scene.json", "--triangles", "5,7-9", "--rows",
                                            "120:160", "-o", "part.jsonl"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const trace::Trace part = trace::Trace::load(dir / "part.jsonl");
  for (int t : part.triangles()) CHECK((t == 5 || (t >= 7 && t <= 9)));
  for (int t : part.triangles())
    for (const trace::Scanline* s : part.scanlines(t)) CHECK((s->y >= 120 && s->y <= 160));

  const auto capped =
      run_scantrace(dir.path(), {"trace", "scene.json", "--max-events", "40", "-o", "cap.jsonl"});
  REQUIRE(capped.exit_code == 0);
  CHECK_THAT(capped.err, Catch::Contains("truncated after 40 events"));
  const trace::Trace cap = trace::Trace::load(dir / "cap.jsonl");
  CHECK(cap.truncated());
  CHECK(cap.footer()->events == 40);
}

TEST_CASE("trace: usage errors exit 2, bad input exits 1 naming the file", "[command][trace]") {
  TempDir dir;
  CHECK(run_scantrace(dir.path(), {"trace", "-o", "x.jsonl"}).exit_code == 2);
  CHECK(run_scantrace(dir.path(), {"trace", "--triangle", "1,2 3,4", "-o", "x.jsonl"}).exit_code ==
        2);
  CHECK(run_scantrace(dir.path(), {"trace", "--triangle", "0,0 9,0 0,9", "--colors",
                                   "2,0,0 0,1,0 "
                                   "0,0,1",
                                   "-o", "x.jsonl"})
            .exit_code == 2);
  CHECK(run_scantrace(dir.path(),
                      {"trace", "--triangle", "0,0 9,0 0,9", "--triangles", "3-1", "-o", "x.jsonl"})
            .exit_code == 2);
  CHECK(run_scantrace(dir.path(),
                      {"trace", "--triangle", "0,0 9,0 0,9", "--level", "every", "-o", "x.jsonl"})
            .exit_code == 2);
  test::write_text(
      dir / "bad.json",
      R"({"vertices": [[0,0]], "vcolors": [[0,0,0]], "faces": [[0,0,3]], "depth": [1]})");
  const auto bad = run_scantrace(dir.path(), {"trace", "bad.json", "-o", "x.jsonl"});
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.err, Catch::StartsWith("scantrace: error: bad.json: faces[0]"));
  CHECK_FALSE(std::filesystem::exists(dir / "x.jsonl"));
}

TEST_CASE("trace --polygon writes the narration of a polygon with a hole under a winding rule",
          "[command][trace][polygon]") {
  TempDir dir;
  const auto r =
      run_scantrace(dir.path(), {"trace", "--polygon", "2,2 20,2 20,20 2,20 | 8,8 14,8 14,14 8,14",
                                 "--winding", "non-zero", "--size", "24x24", "-o", "p.jsonl"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const trace::Trace t = trace::Trace::load(dir / "p.jsonl");
  CHECK(t.header().winding_rule == WindingRule::non_zero);
  // The hole runs the same way round as the square: winding 2 inside it, filled under non-zero.
  CHECK(t.triangle_end(0)->pixels == 18 * 18);
  const trace::Scanline& row = t.scanline(0, 10);
  CHECK(row.active_edges.size() == 4);
  REQUIRE(row.intervals);
  CHECK(row.intervals->size() == 1);
  // Default colours repeat red, green, blue over the eight vertices.
  CHECK(t.triangle_begin(0).colors.size() == 8);
  CHECK(t.triangle_begin(0).colors[3].r == 1);

  const auto eo =
      run_scantrace(dir.path(), {"trace", "--polygon", "2,2 20,2 20,20 2,20 | 8,8 14,8 14,14 8,14",
                                 "--size", "24x24", "-o", "e.jsonl"});
  REQUIRE(eo.exit_code == 0);
  const trace::Trace e = trace::Trace::load(dir / "e.jsonl");
  CHECK(e.header().winding_rule == WindingRule::even_odd);
  CHECK(e.triangle_end(0)->pixels == 18 * 18 - 6 * 6);
  CHECK(e.scanline(0, 10).intervals->size() == 2);
}

TEST_CASE("trace --polygon: malformed polygons, the closed rule and halfspace are usage errors",
          "[command][trace][polygon]") {
  TempDir dir;
  auto code = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "trace");
    args.insert(args.end(), {"-o", "x.jsonl"});
    return run_scantrace(dir.path(), args).exit_code;
  };
  CHECK(code({"--polygon", "0,0 9,0 | 1,1 2,2 3,1"}) == 2);  // a contour of two points
  CHECK(code({"--polygon", "0,0 9,0 x,1"}) == 2);
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--fill-rule", "closed"}) == 2);
  // As docs/polygons.md says (issue 36: exit 1, from the fill).
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--method", "halfspace"}) == 2);
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--method", "double"}) == 0);
  std::filesystem::remove(dir / "x.jsonl");
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--colors", "1,0,0 0,1,0 0,0,1 1,1,1"}) == 2);
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--triangle", "0,0 9,0 0,9"}) == 2);
  CHECK(code({"--triangle", "0,0 9,0 0,9", "--winding", "non-zero"}) == 2);
  CHECK(code({"--polygon", "0,0 9,0 0,9", "--winding", "odd"}) == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "x.jsonl"));
}

TEST_CASE("explain --polygon replays the polygon into frames", "[command][explain][polygon]") {
  TempDir dir;
  const auto r = run_scantrace(
      dir.path(), {"explain", "--polygon", "2,2 20,2 20,20 2,20 | 8,8 14,8 14,14 8,14", "--size",
                   "22x22", "--winding", "non-zero", "-o", "frames/", "--video-size", "640x360"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  // Title, set-up, one step per edge-table entry (4 edges, 4 horizontal), scanline steps, the
  // finished polygon and the end card: more than a dozen frames.
  int frames = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir / "frames"))
    frames += f.path().extension() == ".png";
  CHECK(frames > 12);
}
