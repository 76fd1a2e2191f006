// The runner over every family: a fixed-seed run of the exact method finds nothing, while the
// float method — the textbook x += 1/m — does, on the same kind of run (so a run can fail), and
// the report names each failure completely enough to regenerate it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "stress/report.hpp"
#include "stress/runner.hpp"
#include "stress/stress_case.hpp"

using namespace scantrace;
using namespace scantrace::stress;

namespace {

RunResult run(std::vector<Method> methods, std::vector<Family> families, double seconds,
              std::uint64_t max_cases) {
  std::vector<std::unique_ptr<Rasterizer>> owned;
  std::vector<Rasterizer*> rasterizers;
  for (Method m : methods) {
    owned.push_back(make_method(m));
    rasterizers.push_back(owned.back().get());
  }
  RunOptions o;
  o.seed = 20261121;
  o.seconds = seconds;
  o.families = std::move(families);
  o.max_cases = max_cases;
  return run_stress(o, rasterizers);
}

}  // namespace

TEST_CASE("a fixed-seed run of every family finds no failure of the exact method",
          "[stress][runner]") {
  const RunResult r = run({Method::exact}, {kAllFamilies.begin(), kAllFamilies.end()}, 4.0, 40);
  REQUIRE(r.cells.size() == kAllFamilies.size());
  for (const CellStats& c : r.cells) {
    INFO(to_string(c.family) << ": " << (c.reproducers.empty() ? "" : c.reproducers.front()));
    CHECK(c.cases > 0);
    CHECK(c.fills == 6 * c.triangles);
    CHECK(c.missing + c.extra + c.gaps + c.overlaps + c.nonfinite + c.order_diffs == 0);
    CHECK(c.colour.max <= 1e-4);
    CHECK(c.failing_cases == 0);
  }
  CHECK_FALSE(r.default_failed);
  CHECK(r.default_failing_cases == 0);
  // The table has its header, its rule and one row per cell.
  const std::string table = markdown_table(r);
  CHECK(std::count(table.begin(), table.end(), '\n') == 2 + static_cast<long>(kAllFamilies.size()));
  CHECK(table.find("| meshes | exact |") != std::string::npos);
}

TEST_CASE("the float method fails on slivers and long spans, and says where", "[stress][runner]") {
  const RunResult r =
      run({Method::float32, Method::exact}, {Family::slivers, Family::long_spans}, 3.0, 12);
  REQUIRE(r.cells.size() == 4);
  long long float_failures = 0;
  for (const CellStats& c : r.cells)
    if (c.method == "float")
      float_failures += c.failing_cases;
    else
      CHECK(c.failing_cases == 0);
  CHECK(float_failures > 0);
  // Float is not the default method: its failures do not fail the run.
  CHECK_FALSE(r.default_failed);

  // Every reproducer regenerates its case from the seed, family and index it names, and carries
  // the vertices with full precision.
  const CellStats& slivers = r.cells[0];
  REQUIRE(slivers.method == "float");
  REQUIRE(!slivers.reproducers.empty());
  const std::string& line = slivers.reproducers.front();
  CAPTURE(line);
  CHECK(line.rfind("FAIL float slivers seed=20261121 index=", 0) == 0);
  const std::size_t at = line.find("index=") + 6;
  const std::uint64_t index = std::stoull(line.substr(at));
  const StressCase c = generate(Family::slivers, 20261121, index);
  char x0[40];
  std::snprintf(x0, sizeof x0, "%.17g", c.triangles[0].v[0].x);
  CHECK(line.find(x0) != std::string::npos);
  CHECK(line.find("--case " + std::to_string(index)) != std::string::npos);
}

TEST_CASE("a replayed case runs alone", "[stress][runner]") {
  RunOptions o;
  o.seed = 5;
  o.seconds = 0;
  o.families = {Family::huge, Family::meshes};
  o.only_case = 4;
  auto exact = make_method(Method::exact);
  const RunResult r = run_stress(o, {exact.get()});
  REQUIRE(r.cells.size() == 2);
  CHECK(r.cells[0].cases == 1);
  CHECK(r.cells[1].cases == 1);
  CHECK(r.cells[1].triangles ==
        static_cast<long long>(generate(Family::meshes, 5, 4).triangles.size()));
}

TEST_CASE("every failure of the default method fails the run and gets its reproducer",
          "[stress][runner]") {
  // The float method standing in as the default: its failures must now fail the run, each with
  // its own FAIL line, while the other methods' lines stay capped.
  RunOptions o;
  o.seed = 20261121;
  o.seconds = 3;
  o.families = {Family::slivers};
  o.max_cases = 40;
  o.reproducers_per_cell = 1;
  o.default_method = "float";
  auto flt = make_method(Method::float32);
  auto dbl = make_method(Method::double64);
  const RunResult r = run_stress(o, {flt.get(), dbl.get()});
  REQUIRE(r.cells.size() == 2);
  const CellStats& f = r.cells[0];
  CHECK(r.default_failed);
  CHECK(f.failing_cases > 1);
  CHECK(r.default_failing_cases == f.failing_cases);
  CHECK(static_cast<long long>(f.reproducers.size()) == f.failing_cases);
  CHECK(r.cells[1].reproducers.size() <= 1);
}
