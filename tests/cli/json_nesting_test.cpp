// JSON nested a few hundred thousand levels deep used to end render and replay with a segmentation
// fault (nlohmann's recursive copy/dump/destruction overflowed the stack): every JSON reader now
// refuses nesting beyond 64 levels, at the bracket that opens level 65, before parsing.
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "cli_test_support.hpp"
#include "io/json_input.hpp"
#include "io/scene_json.hpp"
#include "trace/trace.hpp"

using namespace scantrace;
using namespace scantrace::test;

namespace {

constexpr int kDeep = 300000;  // a few hundred thousand levels, about 600 KB

const std::string kHeader =
    R"({"type":"header","format":"scantrace-trace","version":1,"canvas":{"width":8,"height":8},)"
    R"("shading":"flat","fill_rule":"top-left","subpixel_bits":8,"level":"scanline","generator":"scantrace 0.1.0"})";

std::string nested(int depth) {
  return std::string(depth, '[') + std::string(depth, ']');
}

}  // namespace

TEST_CASE("find_excess_nesting finds the bracket that opens level 65", "[json][robustness]") {
  using json_input::find_excess_nesting;
  CHECK_FALSE(find_excess_nesting(nested(64)).has_value());
  CHECK(find_excess_nesting(nested(65)) == std::size_t{64});
  // Objects count as arrays do; brackets inside strings (also after an escaped quote) do not.
  CHECK(find_excess_nesting(R"({"a":{"b":[1]}})", 2) == std::size_t{10});
  CHECK_FALSE(find_excess_nesting(R"({"a":"[[[[\"[[[[","b":"\\"})", 1).has_value());
  CHECK(find_excess_nesting(R"(["\\",[]])", 1) == std::size_t{6});
  // Closing brackets never take the depth below zero (the parser reports such text).
  CHECK_FALSE(find_excess_nesting("]]]]" + nested(64)).has_value());
}

TEST_CASE("a deeply nested scene is refused with its position, not a crash", "[json][robustness]") {
  const std::string text = "{\n  \"vertices\": " + nested(kDeep) + "}";
  // Level 1 is the object, so the 64th '[' opens level 65: line 2, column 15 + 63.
  CHECK_THROWS_WITH(parse_scene_text(text, "deep.json"),
                    "deep.json:2:78: JSON nested deeper than 64 levels");
  CHECK_THROWS_AS(parse_scene_text(text, "deep.json"), InputError);
  // 64 levels are parsed (and then refused for their shape).
  CHECK_THROWS_WITH(parse_scene_text("{\"vertices\": " + nested(63) + "}", "ok.json"),
                    !Catch::Contains("nested deeper"));

  TempDir dir;
  write_text(dir / "deep.json", text);
  const RunResult r = run_scantrace(dir.path(), {"render", "deep.json", "-o", "deep.png"});
  CHECK(r.exit_code == 1);
  CHECK(r.err == "scantrace: error: deep.json:2:78: JSON nested deeper than 64 levels\n");
  const RunResult t = run_scantrace(dir.path(), {"trace", "deep.json", "-o", "deep.jsonl"});
  CHECK(t.exit_code == 1);
  CHECK_THAT(t.err, Catch::Contains("deep.json:2:78: JSON nested deeper than 64 levels"));
  CHECK(file_names(dir.path()) == std::vector<std::string>{"deep.json"});
}

TEST_CASE("a deeply nested trace line is refused with its line and column", "[json][robustness]") {
  const std::string line = R"({"type":"triangle_begin","triangle":)" + nested(kDeep) + "}";
  std::istringstream in(kHeader + "\n" + line + "\n");
  // The 64th '[' of line 2 (after the 36 characters before the value) opens level 65. (main
  // crashed here: the message about a non-integer "triangle" dumped the value recursively.)
  CHECK_THROWS_WITH(trace::Trace::parse(in, "t.jsonl"),
                    "t.jsonl:2:100: JSON nested deeper than 64 levels");

  TempDir dir;
  write_text(dir / "deep.jsonl", kHeader + "\n" + line + "\n");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"replay", "deep.jsonl", "-o", "frames/"},
        std::vector<std::string>{"replay", "deep.jsonl", "-o", "frames/", "--partial"},
        std::vector<std::string>{"check", "deep.jsonl"}}) {
    const RunResult r = run_scantrace(dir.path(), args);
    INFO(args[0]);
    CHECK(r.exit_code == 1);
    CHECK(r.err == "scantrace: error: deep.jsonl:2:100: JSON nested deeper than 64 levels\n");
  }
  // A deep header line too (the first line is decoded before the rest).
  write_text(dir / "deep1.jsonl", nested(kDeep) + "\n");
  const RunResult h = run_scantrace(dir.path(), {"replay", "deep1.jsonl", "-o", "f/"});
  CHECK(h.exit_code == 1);
  CHECK_THAT(h.err, Catch::Contains("deep1.jsonl:1:65: JSON nested deeper than 64 levels"));
}

TEST_CASE("the fuzz regressions of deep nesting are refused", "[json][robustness]") {
  // fuzz/regressions/*/deep-nesting: 50000 levels, each a segmentation fault on main before.
  const std::filesystem::path dir =
      std::filesystem::path(SCANTRACE_SOURCE_DIR) / "fuzz/regressions";
  CHECK_THROWS_WITH(parse_scene_text(read_text(dir / "scene_parser/deep-nesting"), "s.json"),
                    "s.json:1:112: JSON nested deeper than 64 levels");
  std::istringstream in(read_text(dir / "trace_reader/deep-nesting"));
  CHECK_THROWS_WITH(trace::Trace::parse(in, "t.jsonl"),
                    "t.jsonl:2:100: JSON nested deeper than 64 levels");
}
