// Traces are byte-identical across processes (README, trace format): the same input and options
// give the same bytes, run after run, so traces can be diffed and checked into a course's
// material. Each kind of trace is written by two separate scantrace processes, run at the same
// time, and compared byte for byte.
#include <catch2/catch.hpp>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli_test_support.hpp"

using scantrace::test::Child;
using scantrace::test::read_text;
using scantrace::test::spawn_scantrace;
using scantrace::test::TempDir;
using scantrace::test::write_text;

namespace {

// 60 random triangles with random colours and depths on a 64x48 canvas.
std::string random_scene(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-8, 72), y(-8, 56), unit(0, 1);
  std::ostringstream v, c, d, f;
  v.precision(17), c.precision(17), d.precision(17);
  for (int i = 0; i < 180; ++i) {
    const char* sep = i ? "," : "";
    v << sep << '[' << x(rng) << ',' << y(rng) << ']';
    c << sep << '[' << unit(rng) << ',' << unit(rng) << ',' << unit(rng) << ']';
    d << sep << unit(rng);
    if (i % 3 == 0) f << (i ? "," : "") << '[' << i << ',' << i + 1 << ',' << i + 2 << ']';
  }
  std::ostringstream scene;
  scene << R"({"vertices": [)" << v.str() << R"(], "vcolors": [)" << c.str() << R"(], "depth": [)"
        << d.str() << R"(], "faces": [)" << f.str() << R"(], "width": 64, "height": 48})";
  return scene.str();
}

}  // namespace

TEST_CASE("two processes write byte-identical traces", "[command][trace][determinism]") {
  TempDir dir;
  write_text(dir / "scene.json", random_scene(20));
  const std::string model =
      std::string(SCANTRACE_SOURCE_DIR) + "/examples/models/interpenetrating.obj";
  const std::vector<std::vector<std::string>> inputs = {
      {"scene.json", "--level", "pixel"},
      {"scene.json", "--level", "scanline", "--shading", "flat", "--fill-rule", "closed"},
      {"--triangle", "20,20 250,80 300,400"},
      {"--polygon", "10,1 15.5,18.2 1.3,7.3 18.7,7.3 4.5,18.2", "--winding", "non-zero", "--level",
       "pixel", "--size", "20x20"},
      {model, "--level", "pixel", "--rows", "240:260"},
  };
  for (const auto& input : inputs) {
    std::string described;
    for (const std::string& word : input) described += word + " ";
    INFO(described);
    std::vector<std::unique_ptr<Child>> runs;
    for (const char* name : {"a.jsonl", "b.jsonl"}) {
      std::vector<std::string> args = {"-q", "trace"};
      args.insert(args.end(), input.begin(), input.end());
      args.insert(args.end(), {"-o", name});
      runs.push_back(std::make_unique<Child>(spawn_scantrace(dir.path(), args)));
    }
    for (auto& run : runs) REQUIRE(run->wait() == 0);
    const std::string a = read_text(dir / "a.jsonl"), b = read_text(dir / "b.jsonl");
    CHECK(a.size() > 1000);  // a trace with content, not two empty files
    CHECK(a == b);
  }
}
