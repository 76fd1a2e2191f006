// An SVG frame is well-formed XML whatever bytes a trace or a scene puts into its text (issue 46
// #15: a trace whose `generator` held ESC gave "PCDATA invalid Char value 27"): every character
// XML 1.0 forbids and every byte that is not UTF-8 is replaced by U+FFFD (frame_text::xml_escape),
// for every kind of operation a frame holds; xmllint reads the result against the SVG 1.1 subset.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "viz/frame.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/frame_text.hpp"
#include "viz/svg_frame.hpp"
#include "chromium_compare.hpp"

using namespace scantrace;
using namespace scantrace::test::chromium;
namespace fs = std::filesystem;

namespace {

const std::string kBad = "\xEF\xBF\xBD";  // U+FFFD, by hand

// Every kind of byte sequence XML 1.0 or UTF-8 refuses, between letters, with & and <.
const std::string kHostile = std::string("a\x1b[31mFAKE\x07 \x00 b", 15) +
                             "\x7f<&>\"'\x01\x1f\t\xEF\xBF\xBF\xEF\xBF\xBE\xED\xA0\x80\xC3\xC0\xAF"
                             "\xF4\x90\x80\x80\xFF\xE2\x82 end";

// Whether `svg` is well-formed and valid against tests/viz/svg11_subset.dtd (xmllint); true with a
// warning when xmllint is not installed.
bool xmllint_accepts(const std::string& svg, const std::string& name) {
  if (!have("xmllint")) {
    WARN("skipped: xmllint is not installed (scripts/deps.sh installs libxml2-utils)");
    return true;
  }
  const fs::path dir = scratch(name);
  const fs::path file = dir / "frame.svg";
  write(file, svg);
  const std::string dtd = std::string(SCANTRACE_SOURCE_DIR) + "/tests/viz/svg11_subset.dtd";
  const bool ok = std::system(fmt::format("xmllint --noout --nonet --dtdvalid '{}' '{}'", dtd,
                                          file.string())
                                  .c_str()) == 0;
  fs::remove_all(dir);
  return ok;
}

}  // namespace

TEST_CASE("xml_escape: forbidden characters and bytes that are not UTF-8 become U+FFFD",
          "[viz][svg][robustness]") {
  using viz::frame_text::xml_escape;
  // Kept: tab, LF, CR, every printable ASCII character, 2-, 3- and 4-byte UTF-8, U+FFFD itself.
  CHECK(xml_escape("a\tb\nc\rd ~") == "a\tb\nc\rd ~");
  CHECK(xml_escape("\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\xEF\xBF\xBD") ==
        "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\xEF\xBF\xBD");
  CHECK(xml_escape("<a href=\"x\">&</a>") == "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
  // Replaced, one U+FFFD per character refused, or per byte that starts no UTF-8 sequence.
  CHECK(xml_escape("a\x1b[2Jb") == "a" + kBad + "[2Jb");
  CHECK(xml_escape(std::string("\x00\x01\x08\x0b\x0c\x0e\x1f", 7)) == [] {
    std::string s;
    for (int i = 0; i < 7; ++i) s += kBad;
    return s;
  }());
  CHECK(xml_escape("\x7f") == "\x7f");  // DEL is an XML Char (§2.2)
  CHECK(xml_escape("\xEF\xBF\xBE|\xEF\xBF\xBF") == kBad + "|" + kBad);  // U+FFFE, U+FFFF
  CHECK(xml_escape("\xED\xA0\x80") == kBad + kBad + kBad);              // a lone surrogate
  CHECK(xml_escape("\xC0\xAF") == kBad + kBad);                         // an overlong '/'
  CHECK(xml_escape("\xF4\x90\x80\x80") == kBad + kBad + kBad + kBad);   // above U+10FFFF
  CHECK(xml_escape("x\xE2\x82") == "x" + kBad + kBad);                  // cut short
  CHECK(xml_escape("\xFF\xFEz") == kBad + kBad + "z");
  CHECK(xml_escape("\xE2\x82\xAC\xC3") == "\xE2\x82\xAC" + kBad);
}

TEST_CASE("an SVG frame of a trace whose strings hold ESC and non-UTF-8 bytes is valid XML",
          "[viz][svg][robustness]") {
  // The course triangle's events with the header's generator made hostile, and a hostile name
  // for the trace's file: the title and end cards print both.
  std::vector<trace::Event> events = course_triangle().events();
  std::get<trace::Header>(events.front()).generator = "scantrace \x1b]0;owned\x07" + kHostile;
  const trace::Trace t = trace::Trace::from_events(std::move(events), "t.jsonl");
  viz::FrameSequence s(t, {}, {1280, 720}, "dir/\x1b[2J" + kHostile + ".jsonl");
  bool shown = false;
  for (const std::size_t i : {std::size_t{0}, s.steps().size() - 1}) {
    INFO("step " << i);
    const std::string svg = viz::to_svg(s.frame(i));
    CHECK(svg.find('\x1b') == std::string::npos);
    CHECK(svg.find('\x07') == std::string::npos);
    shown |= svg.find("]0;owned") != std::string::npos;
    CHECK(xmllint_accepts(svg, fmt::format("hostile-trace-{}", i)));
  }
  // The hostile text is there, not left out: the cards print the generator, its control
  // characters as '?' (a text op holds the ASCII its fonts draw: viz::hershey_ascii).
  CHECK(shown);
}

TEST_CASE("every kind of frame operation with hostile text gives valid XML",
          "[viz][svg][robustness]") {
  // A new kind of operation must be added here (and to the SVG backend's escaping).
  static_assert(std::variant_size_v<viz::DrawOpBody> == 5);
  viz::Frame f({320, 200}, viz::Scalar(255, 255, 255));
  const viz::Scalar red(0, 0, 255);
  const auto mark = [](viz::MarkKind k) { return viz::Mark{k, kHostile, {1, 2, 3, 4}}; };
  const viz::Rect clip{10, 10, 200, 100};
  std::vector<viz::DrawOpBody> bodies{
      viz::RectOp{{1, 1, 20, 10}, red, 1},
      viz::RectOp{{1, 1, 20, 10}, red, viz::FILLED},
      viz::LineOp{{0, 0}, {40, 40}, red, 2},
      viz::CircleOp{{30, 30}, 5, red, 1},
      viz::TextOp{kHostile, {5, 50}, viz::HersheyFont::simplex, 0.5, red, 1},
      viz::TextOp{std::string(1, '\x1b'), {5, 80}, viz::HersheyFont::simplex, 1, red, 1},
      viz::PixelsOp{{0, 0, 2, 2}, std::make_shared<const std::vector<viz::Vec3b>>(4)},
      viz::PixelsOp{{5, 5, 1, 1}, std::make_shared<const std::vector<viz::Vec3b>>(1)}};
  std::vector<bool> kinds(std::variant_size_v<viz::DrawOpBody>, false);
  for (const auto& body : bodies) {
    kinds[body.index()] = true;
    f.add({body, std::nullopt, mark(viz::MarkKind::label)});
    f.add({body, clip, mark(viz::MarkKind::vertex)});
  }
  for (const bool k : kinds) CHECK(k);
  const std::string svg = viz::to_svg(f);
  CHECK(svg.find('\x1b') == std::string::npos);
  CHECK(svg.find("\xEF\xBF\xBF") == std::string::npos);
  CHECK(svg.find(kBad) != std::string::npos);
  CHECK(xmllint_accepts(svg, "hostile-ops"));
}
