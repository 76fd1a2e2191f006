// scantrace bench: the report's tables and targets, the CSV and the plot are all written, and the
// exact method's rows report no coverage error (the accuracy part, not the timing: timing is never
// asserted in tests). --quick keeps the workloads small.
#include <catch2/catch.hpp>

#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"

using namespace scantrace::test;

TEST_CASE("bench writes its report, CSV and plot", "[command][bench]") {
  TempDir dir;
  const auto r = run_scantrace(
      dir.path(), {"bench", "--quick", "--rounds", "1", "--scene", "absent.json", "-o", "b"});
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* heading :
       {"### built-in scene", "### small triangles (10 px²)", "### vertex at −1e9",
        "## The float canvas", "## What the fill skips", "## Parallel render", "## Targets"})
    CHECK_THAT(r.out, Catch::Contains(heading));
  // --quick draws the half-canvas triangle on 1024²: every heading says so (issue 36: the table
  // said "half of 4096²").
  CHECK_THAT(r.out, Catch::Contains("### half of 1024² (one triangle)") &&
                        Catch::Contains("## One triangle over half of a 1024² canvas") &&
                        !Catch::Contains("4096"));
  CHECK_THAT(r.out, Catch::Contains("| exact | flat |") && Catch::Contains("| opencv | flat |") &&
                        Catch::Contains("| memset |"));
  // Bit-identical parallel output is checked by the bench itself: every row of its table says
  // "yes" in the last column. (The check used to look for "**no** |" before a "| 1200" line, which
  // also matched an unmet timing target followed by the 1200x1200 target row on a loaded machine.)
  const std::size_t table = r.out.find("## Parallel render");
  REQUIRE(table != std::string::npos);
  const std::string parallel = r.out.substr(table, r.out.find("\n## ", table + 1) - table);
  CHECK_THAT(parallel, Catch::Contains("| yes |") && !Catch::Contains("**no**"));

  const std::string csv = read_text(dir / "b.csv");
  CHECK(csv.rfind("workload,variant,shading,image,median_ms", 0) == 0);
  // The exact method's coverage errors: zero on every workload with an error column.
  std::istringstream lines(csv);
  int exact_rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find(",exact,") == std::string::npos || line.find(",8-bit,") == std::string::npos)
      continue;
    std::vector<std::string> f;
    std::string field;
    for (std::istringstream in(line.substr(line.find(",exact,"))); std::getline(in, field, ',');)
      f.push_back(field);
    // ",exact,shading,image,ms,tri/s,px/s,wrong,..." → f[0] is empty, f[7] the errors.
    REQUIRE(f.size() >= 8);
    if (f[7].empty()) continue;
    CHECK(f[7] == "0");
    ++exact_rows;
  }
  CHECK(exact_rows >= 8);
  const cv::Mat plot = cv::imread((dir / "b.png").string());
  CHECK(plot.cols > 0);
  CHECK_FALSE(std::filesystem::exists(dir / "absent.json"));
}
