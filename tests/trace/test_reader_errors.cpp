// A bad trace is a clear error naming the line; an interrupted one is readable but incomplete.
#include <catch2/catch.hpp>
#include <sstream>

#include "trace/trace.hpp"

using namespace scantrace::trace;

namespace {

const std::string kHeader =
    R"({"type":"header","format":"scantrace-trace","version":1,"canvas":{"width":8,"height":8},)"
    R"("shading":"flat","fill_rule":"top-left","subpixel_bits":8,"level":"scanline","generator":"scantrace 0.1.0"})";
const std::string kSkipped = R"({"type":"triangle_skipped","triangle":0,"reason":"degenerate"})";
const std::string kFooter = R"({"type":"footer","events":1,"truncated":false})";

Trace parse(const std::string& text) {
  std::istringstream in(text);
  return Trace::parse(in, "t.jsonl");
}

}  // namespace

TEST_CASE("a well-formed trace parses, and without its footer it is incomplete",
          "[trace][reader]") {
  const Trace t = parse(kHeader + "\n" + kSkipped + "\n" + kFooter + "\n");
  CHECK(t.complete());
  CHECK(t.skipped(0)->reason == "degenerate");
  const Trace cut = parse(kHeader + "\n" + kSkipped + "\n");
  CHECK_FALSE(cut.complete());
  CHECK_FALSE(cut.truncated());
}

TEST_CASE("malformed traces name the file, the line and the problem", "[trace][reader]") {
  CHECK_THROWS_WITH(parse(kHeader + "\n" + kSkipped + "\n{not json\n"),
                    Catch::StartsWith("t.jsonl:3: not valid JSON"));
  CHECK_THROWS_WITH(parse(kSkipped + "\n"),
                    Catch::Contains("t.jsonl:1:") && Catch::Contains("header"));
  std::string v2 = kHeader;
  v2.replace(v2.find("\"version\":1"), 11, "\"version\":2");
  CHECK_THROWS_WITH(parse(v2 + "\n"), Catch::Contains("version 2 is not supported"));
  // A later version may change any other key: the version is what the message must name.
  CHECK_THROWS_WITH(parse(R"({"type":"header","format":"scantrace-trace","version":2})"
                          "\n"),
                    Catch::Contains("t.jsonl:1: trace format version 2 is not supported"));
  std::string other = kHeader;
  other.replace(other.find("scantrace-trace"), 15, "something-else!");
  CHECK_THROWS_WITH(parse(other + "\n"), Catch::Contains("not a scantrace trace"));
  CHECK_THROWS_WITH(parse(kHeader + "\n" + R"({"type":"scanline","triangle":0})" + "\n"),
                    Catch::StartsWith("t.jsonl:2: malformed event"));
  CHECK_THROWS_WITH(parse(kHeader + "\n" + R"({"type":"bogus"})" + "\n"),
                    Catch::Contains("unknown event type"));
  CHECK_THROWS_WITH(parse(kHeader + "\n" + kFooter + "\n" + kSkipped + "\n"),
                    Catch::Contains("t.jsonl:3: event after the footer"));
  CHECK_THROWS_WITH(parse(""), Catch::Contains("empty file"));
  CHECK_THROWS_WITH(Trace::load("/nonexistent/x.jsonl"), Catch::Contains("cannot open"));
}

TEST_CASE("queries about absent things say what is missing", "[trace][reader]") {
  const Trace t = parse(kHeader + "\n" + kSkipped + "\n" + kFooter + "\n");
  CHECK_THROWS_WITH(t.scanline(0, 3), Catch::Contains("no scanline 3"));
  CHECK_THROWS_WITH(t.edge_table(7), Catch::Contains("triangle 7 is not in the trace"));
  CHECK(t.pixel_history(1, 1).empty());
  CHECK_THROWS(t.pixel_history(1, 1).final());
}

TEST_CASE("inputs found by fuzzing are errors naming the line, not crashes",
          "[trace][reader][fuzz]") {
  // fuzz/regressions/trace_reader/number-overflow: nlohmann throws out_of_range, not parse_error,
  // for a number beyond a double; it escaped the reader and terminated the program.
  CHECK_THROWS_AS(parse("-66E666"), TraceError);
  CHECK_THROWS_WITH(
      parse(kHeader + "\n" + R"({"type":"triangle_skipped","triangle":1e999})" + "\n"),
      Catch::StartsWith("t.jsonl:2: a number is too large for a double"));
}

TEST_CASE("the reader bounds a line's length and tells a cut-off last line from damage",
          "[trace][reader]") {
  // 16 MiB of one line: refused without reading further.
  CHECK_THROWS_WITH(parse(kHeader + "\n" + std::string((16u << 20) + 10, 'x')),
                    Catch::StartsWith("t.jsonl:2: line longer than 16 MiB"));
  // The last line without its newline: the writer was cut off there.
  CHECK_THROWS_WITH(parse(kHeader + "\n" + kSkipped + "\n" + kFooter.substr(0, 12)),
                    Catch::StartsWith("t.jsonl:3: the file ends in the middle of this line") &&
                        Catch::Contains("it holds the header and 1 events, the last for "
                                        "triangle 0"));
  // The same damage in the middle is a syntax error.
  CHECK_THROWS_WITH(parse(kHeader + "\n" + kFooter.substr(0, 12) + "\n" + kSkipped + "\n"),
                    Catch::StartsWith("t.jsonl:2: not valid JSON"));
  // A header whose canvas no writer could produce: replay would allocate from it.
  std::string huge = kHeader;
  huge.replace(huge.find("\"width\":8"), 9, "\"width\":-3");
  CHECK_THROWS_WITH(parse(huge + "\n"), Catch::Contains("t.jsonl:1: header: canvas -3x8"));
}

TEST_CASE("integers out of range or fractional are malformed events, not casts (found by fuzzing)",
          "[trace][reader][fuzz]") {
  // fuzz/regressions/trace_reader/header-canvas-float-to-int: get<int>() of 5.5e33 was a float to
  // int cast out of range, undefined behaviour caught by UBSan.
  std::string huge = kHeader;
  huge.replace(huge.find("\"height\":8"), 10, "\"height\":5555555555555555555555555555555554");
  CHECK_THROWS_WITH(parse(huge + "\n"), Catch::StartsWith("t.jsonl:1: malformed event") &&
                                            Catch::Contains("expected an integer in range"));
  CHECK_THROWS_WITH(
      parse(kHeader + "\n" + R"({"type":"triangle_skipped","triangle":4294967296,"reason":"x"})" +
            "\n"),
      Catch::StartsWith("t.jsonl:2: malformed event"));
  CHECK_THROWS_WITH(
      parse(kHeader + "\n" + R"({"type":"triangle_skipped","triangle":1.5,"reason":"x"})" + "\n"),
      Catch::StartsWith("t.jsonl:2: malformed event"));
  CHECK_THROWS_WITH(parse(kHeader + "\n" +
                          R"({"type":"scanline","triangle":0,"y":1,"entered":[1e300],)"
                          R"("retired":[],"active_edges":[],"active_points":[]})" + "\n"),
                    Catch::StartsWith("t.jsonl:2: malformed event"));
}
