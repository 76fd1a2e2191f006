// Levels, filters, the event cap, determinism and the writer → reader round trip.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "trace/event_json.hpp"
#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;
namespace fs = std::filesystem;

namespace {

// Forty disjoint triangles in a grid on a 160×160 canvas: face k at column k % 8, row k / 8.
Scene grid_scene() {
  Scene s;
  s.width = s.height = 160;
  for (int k = 0; k < 40; ++k) {
    const double x = 20.0 * (k % 8) + 1.5, y = 20.0 * (k / 8) + 1.25;
    for (Vec2 p : {Vec2{x, y}, Vec2{x + 15, y + 3}, Vec2{x + 4, y + 16}}) {
      s.vertices.push_back(p);
      s.vcolors.push_back({0.1 * (k % 10), 0.5, 1.0 - 0.02 * k});
      s.depth.push_back(100.0 - k);  // face 0 farthest: painter's order is face order
    }
    s.faces.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  return s;
}

fs::path temp_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("scantrace-trace-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_type(const Trace& t, const char* type) {
  std::size_t n = 0;
  for (const Event& e : t.events()) n += std::string(type_name(e)) == type;
  return n;
}

}  // namespace

TEST_CASE("triangle index lists and ranges select what is traced", "[trace][filter]") {
  const IndexSet set = IndexSet::parse("3,17,40-45,44-50");
  CHECK(set.contains(3));
  CHECK(set.contains(17));
  CHECK_FALSE(set.contains(16));
  CHECK(set.contains(40));
  CHECK(set.contains(50));
  CHECK_FALSE(set.contains(51));
  CHECK_THROWS_WITH(IndexSet::parse("3,x"), Catch::Contains("\"x\""));
  CHECK_THROWS(IndexSet::parse("5-2"));
  CHECK_THROWS(IndexSet::parse(""));
  CHECK(RowRange::parse("10:20").contains(20));
  CHECK_FALSE(RowRange::parse("10:20").contains(21));
  CHECK(RowRange::parse(":5").contains(-100));
  CHECK_THROWS(RowRange::parse("7"));

  const Trace t = record_scene(grid_scene(), FillOptions{},
                               TraceFilter{.triangles = IndexSet::parse("1,3-4,39")});
  CHECK(t.triangles() == std::vector<int>{1, 3, 4, 39});
  CHECK(count_type(t, "triangle_begin") == 4);
}

TEST_CASE("a row range limits scanline and pixel events, not the triangles", "[trace][filter]") {
  const Trace t = record_scene(grid_scene(), FillOptions{},
                               TraceFilter{.level = TraceLevel::pixel, .rows = RowRange{10, 12}});
  CHECK(t.triangles().size() == 40);
  for (const Event& e : t.events()) {
    if (const auto* s = std::get_if<Scanline>(&e)) CHECK((s->y >= 10 && s->y <= 12));
    if (const auto* p = std::get_if<Pixel>(&e)) CHECK((p->y >= 10 && p->y <= 12));
  }
  CHECK(count_type(t, "scanline") == 8 * 3);  // the first band of 8 triangles, 3 rows each
}

TEST_CASE("levels add events: triangle < scanline < pixel", "[trace][filter]") {
  const Scene s = grid_scene();
  const Trace tri = record_scene(s, {}, TraceFilter{.level = TraceLevel::triangle});
  const Trace row = record_scene(s, {}, TraceFilter{.level = TraceLevel::scanline});
  const Trace pix = record_scene(s, {}, TraceFilter{.level = TraceLevel::pixel});
  CHECK(count_type(tri, "scanline") == 0);
  CHECK(count_type(tri, "edge_table") == 40);
  CHECK(count_type(tri, "triangle_end") == 40);
  CHECK(count_type(row, "scanline") > 0);
  CHECK(count_type(row, "pixel") == 0);
  i64 pixels = 0;
  for (int t : pix.triangles()) pixels += pix.triangle_end(t)->pixels;
  CHECK(count_type(pix, "pixel") == static_cast<std::size_t>(pixels));
  CHECK(pix.header().level == TraceLevel::pixel);
}

TEST_CASE("the event cap truncates the trace and says so", "[trace][filter]") {
  const Trace t = record_scene(grid_scene(), {}, TraceFilter{.max_events = 25});
  REQUIRE(t.complete());
  CHECK(t.truncated());
  CHECK(t.footer()->events == 25);
  CHECK(t.events().size() == 25 + 2);  // header and footer around the capped body
  const Trace all = record_scene(grid_scene(), {}, TraceFilter{});
  CHECK_FALSE(all.truncated());
  CHECK(all.footer()->events == static_cast<i64>(all.events().size()) - 2);
}

TEST_CASE("writing is deterministic and reads back to the recorded events", "[trace][io]") {
  const fs::path dir = temp_dir();
  const Scene s = grid_scene();
  for (Shading shading : {Shading::flat, Shading::gouraud}) {
    const FillOptions options{.shading = shading};
    const TraceFilter filter{.level = TraceLevel::pixel, .triangles = IndexSet::parse("2-9")};
    const Footer a = write_scene_trace(dir / "a.jsonl", s, options, filter);
    const Footer b = write_scene_trace(dir / "b.jsonl", s, options, filter);
    CHECK(a.events == b.events);
    CHECK(slurp(dir / "a.jsonl") == slurp(dir / "b.jsonl"));

    const Trace read = Trace::load(dir / "a.jsonl");
    const Trace memory = record_scene(s, options, filter);
    REQUIRE(read.events().size() == memory.events().size());
    for (std::size_t i = 0; i < read.events().size(); ++i)
      CHECK(event_to_json(read.events()[i]).dump() == event_to_json(memory.events()[i]).dump());
    // No temporary file is left behind.
    for (const auto& entry : fs::directory_iterator(dir))
      CHECK(entry.path().filename().string().rfind(".", 0) != 0);
  }
  fs::remove_all(dir);
}
