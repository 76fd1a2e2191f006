// The scene file's fast path (io/scene_json_fast.hpp) against the nlohmann reader it stands in for:
// on every input made here, the same scene (bit for bit) or the same error message, with and
// without --clamp-colors; and the fast path really taken on well-formed scenes.
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "io/scene_json_fast.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

namespace {

// The scene as JSON (every double with enough digits to read back bit for bit, -0 included), or
// "error: " and the message.
std::string outcome(const std::string& text, bool fast, bool clamp) {
  ColorClamping clamping;
  try {
    const Scene s =
        fast ? parse_scene_text(text, "s.json", clamp ? &clamping : nullptr)
             : parse_scene_text_without_fast_path(text, "s.json", clamp ? &clamping : nullptr);
    return scene_to_json(s) + " clamped " + std::to_string(clamping.clamped) + " " + clamping.first;
  } catch (const std::exception& e) {
    return std::string("error: ") + e.what();
  }
}

// How many texts the On-Demand reader took, to check that the damage below reaches it.
int on_demand_taken = 0;

void check_agree(const std::string& text) {
  INFO("text: " << text.substr(0, 300));
  for (bool clamp : {false, true}) CHECK(outcome(text, true, clamp) == outcome(text, false, clamp));
  // What the On-Demand reader takes, the DOM reader takes too, with the same bits: On-Demand
  // checks only what it reads, so a value it skipped unchecked would show here.
  if (const std::optional<Scene> s = detail::read_scene_on_demand(text)) {
    ++on_demand_taken;
    const std::optional<Scene> dom = detail::read_scene_dom(text);
    REQUIRE(dom.has_value());
    CHECK(scene_to_json(*s) == scene_to_json(*dom));
  }
}

// Each edit (the first occurrence of a piece replaced) of `original`.
void check_edited(const std::string& original,
                  const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    std::string text = original;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    check_agree(text);
  }
}

// Random damage: a character deleted, doubled or replaced anywhere, `count` times.
void check_damaged(const std::string& original, int count, std::uint64_t seed) {
  SplitMix64 rng(seed);
  const std::string alphabet = "[]{},:\"0123456789.-eE tnull";
  for (int k = 0; k < count; ++k) {
    std::string text = original;
    const std::size_t at = rng.next() % text.size();
    switch (rng.next() % 3) {
      case 0:
        text.erase(at, 1);
        break;
      case 1:
        text.insert(at, 1, text[at]);
        break;
      default:
        text[at] = alphabet[rng.next() % alphabet.size()];
    }
    check_agree(text);
  }
}

const std::string kSmall =
    R"({"vertices": [[1.5, 2], [10, -0.0], [3e1, 7]], "vcolors": [[1, 0, 0], [0, 1, 0.25],)"
    R"( [0, 0, 1]], "faces": [[0, 1, 2]], "depth": [1, 2, 3], "width": 40, "height": 30,)"
    R"( "background": [0.5, 0.5, 0.5], "comment": "ignored"})";

}  // namespace

TEST_CASE("scene fast path: well-formed scenes read the same, and take the fast path",
          "[scene_json]") {
  SplitMix64 rng(5);
  std::vector<Scene> scenes{demo_scene()};
  for (int k = 0; k < 20; ++k) {
    Scene s;
    const int n = 3 + static_cast<int>(rng.next() % 50);
    for (int i = 0; i < n; ++i) {
      s.vertices.push_back({rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3)});
      s.vcolors.push_back({rng.unit(), rng.unit(), rng.unit()});
      s.depth.push_back(k % 2
                            ? std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.next() % 80) - 40)
                            : static_cast<double>(rng.next() % 7));
    }
    for (int f = 0; f < 2 * n; ++f)
      s.faces.push_back({static_cast<int>(rng.next() % n), static_cast<int>(rng.next() % n),
                         static_cast<int>(rng.next() % n)});
    s.width = 1 + static_cast<int>(rng.next() % 900);
    scenes.push_back(s);
  }
  for (const Scene& s : scenes) {
    const std::string text = scene_to_json(s);
    CHECK(read_scene_fast(text).has_value());
    check_agree(text);
  }
  CHECK(read_scene_fast(kSmall).has_value());
  check_agree(kSmall);
}

TEST_CASE("scene fast path: every malformed or unusual scene gives the nlohmann reader's answer",
          "[scene_json]") {
  // Each replaces a piece of kSmall: shapes, types, ranges, the forms only nlohmann accepts
  // (3.0 as an index, 40.0 as a width), a key given twice, and meanings validate() refuses.
  const std::vector<std::pair<std::string, std::string>> edits{
      {"[0, 1, 2]", "[0, 1, 3]"},
      {"[0, 1, 2]", "[0, 1, -1]"},
      {"[0, 1, 2]", "[0, 1, 2.0]"},
      {"[0, 1, 2]", "[0, 1, 2e0]"},
      {"[0, 1, 2]", "[0, 1]"},
      {"[0, 1, 2]", "[0, 1, 2, 2]"},
      {"[0, 1, 2]", "[0, 1, true]"},
      {"[0, 1, 2]", "[0, 1, 99999999999999999999]"},
      {"[0, 1, 2]", "[0, 1, \"2\"]"},
      {"[0, 1, 2]", "[0, 0, 0]"},
      {"[1.5, 2]", "[1.5]"},
      {"[1.5, 2]", "[1.5, null]"},
      {"[1.5, 2]", "[1.5, 1e999]"},
      {"[1.5, 2]", "[1.5, 18446744073709551615]"},
      {"[1.5, 2]", "[1.5, -9223372036854775808]"},
      {"[1.5, 2]", "[1.5, 123456789012345678901234567890]"},
      {"[1, 0, 0]", "[1.5, 0, 0]"},
      {"[1, 0, 0]", "[-0.25, 0, 2]"},
      {"[1, 0, 0]", "[1, 0]"},
      {"\"width\": 40", "\"width\": 40.0"},
      {"\"width\": 40", "\"width\": 0"},
      {"\"width\": 40", "\"width\": -3"},
      {"\"width\": 40", "\"width\": 3000000000"},
      {"\"width\": 40", "\"width\": 100000"},
      {"\"width\": 40", "\"width\": \"40\""},
      {"\"height\": 30", "\"height\": 30, \"height\": 31"},
      {"\"depth\": [1, 2, 3]", "\"depth\": [1, 2, 3], \"depth\": [1, 2]"},
      {"\"depth\": [1, 2, 3]", "\"depth\": [1, 2]"},
      {"\"depth\": [1, 2, 3]", "\"depth\": 1"},
      {"\"depth\": [1, 2, 3], ", ""},
      {"[0.5, 0.5, 0.5]", "[0.5, 0.5]"},
      {"[0.5, 0.5, 0.5]", "[2, 0.5, 0.5]"},
      {"\"faces\": [[0, 1, 2]]", "\"faces\": []"},
      {"\"comment\": \"ignored\"", "\"comment\": [[[{}]]]"},
      {"{\"vertices\"", "[{\"vertices\""}};
  check_edited(kSmall, edits);
  check_agree(kSmall + "]");
  check_agree("");
  check_agree("[]");
  check_agree("null");
  check_damaged(kSmall, 3000, 9);
}

TEST_CASE("scene fast path: On-Demand reads a scene of only the scene's keys, or declines",
          "[scene_json]") {
  // kSmall without its "comment": every key is read, so the On-Demand reader is the one tried
  // (a key the scene does not use makes it decline, and the DOM reader reads the text).
  std::string plain = kSmall;
  plain.replace(plain.find(", \"comment\": \"ignored\""),
                std::string(", \"comment\": \"ignored\"").size(), "");
  REQUIRE(detail::read_scene_on_demand(plain).has_value());
  CHECK_FALSE(detail::read_scene_on_demand(kSmall).has_value());
  CHECK(detail::read_scene_dom(kSmall).has_value());
  // The keys in another order (faces before vertices: indices checked after the last key), a
  // key escaped, trailing text, the same key twice, an index past the vertices.
  const std::vector<std::pair<std::string, std::string>> edits{
      {"{\"vertices\": [[1.5, 2], [10, -0.0], [3e1, 7]], ",
       "{\"faces\": [[0, 1, 2]], \"vertices\": [[1.5, 2], [10, -0.0], [3e1, 7]], "},
      {"\"faces\": [[0, 1, 2]], ", ""},
      {"\"vcolors\"", "\"vcol\\u006frs\""},
      {"\"width\": 40", "\"width\": 40, \"width\": 40"},
      {"[0, 1, 2]", "[0, 1, 3]"},
      {"[0, 1, 2]", "[0, 1, 2147483648]"},
      {"[1.5, 2]", "[-0, 2]"},
      {"[1.5, 2]", "[1.5, 18446744073709551615]"},
      {"[1.5, 2]", "[1.5, 123456789012345678901234567890]"},
      {"[1.5, 2]", "[1.5, 2, 3]"},
      {"\"height\": 30", "\"height\": 30.5"}};
  check_edited(plain, edits);
  check_agree(plain);
  check_agree(plain + " ");
  check_agree(plain + "]");
  check_agree(plain + "{}");
  check_agree(plain.substr(0, plain.size() - 1));
  on_demand_taken = 0;
  check_damaged(plain, 3000, 11);
  // About a fifth of the damage leaves a scene (a digit changed, a space doubled): those are read
  // by On-Demand, and held above to the DOM reader and to nlohmann.
  CHECK(on_demand_taken > 300);
}

TEST_CASE("scene fast path: declined where simdjson's buffers would not fit, the scene still read",
          "[scene_json][size]") {
  const std::string text = scene_to_json(demo_scene());
  REQUIRE(read_scene_fast(text).has_value());
  // Room for the nlohmann DOM (about 2 bytes per byte of this text), not for simdjson's 15.
  ::setenv("SCANTRACE_MAX_MEMORY", std::to_string(10 * text.size()).c_str(), 1);
  const bool declined = !read_scene_fast(text).has_value();
  const std::string slow = outcome(text, true, false);
  ::unsetenv("SCANTRACE_MAX_MEMORY");
  CHECK(declined);
  CHECK(slow == outcome(text, false, false));
  CHECK(slow.rfind("error", 0) != 0);
}
