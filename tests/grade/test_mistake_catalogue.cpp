// The one mistake catalogue (python/scantrace/grade/mistakes.json, embedded at build time): the
// wrong renderers of these tests name their mistakes by its ids, and diff reads its verdicts and
// whole-image thresholds from it.
#include <fstream>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "grade/mistake_catalogue.hpp"
#include "wrong_renderers.hpp"

using namespace scantrace::grade;
using gradetest::Mistake;

TEST_CASE("catalogue: the embedded file is the package's, ids unique", "[grade][catalogue]") {
  std::ifstream in(SCANTRACE_SOURCE_DIR "/python/scantrace/grade/mistakes.json");
  REQUIRE(in);
  std::stringstream file;
  file << in.rdbuf();
  CHECK(nlohmann::json::parse(file.str()) == nlohmann::json::parse(mistake_catalogue_json()));
  std::set<std::string> ids;
  for (const auto& m : mistake_catalogue()) {
    CHECK(ids.insert(m.id).second);
    CHECK_FALSE(m.sentence.empty());
    CHECK_FALSE(m.fix.empty());
  }
  CHECK_THROWS_AS(catalogue_mistake("drop_last_row"), std::out_of_range);
}

TEST_CASE("catalogue: every wrong renderer's mistake is a catalogue mistake with a verdict",
          "[grade][catalogue]") {
  for (Mistake m : {Mistake::closed_rule, Mistake::bottom_row_dropped, Mistake::span_too_wide,
                    Mistake::order_reversed, Mistake::horizontal_edge_skipped,
                    Mistake::degenerate_drawn, Mistake::flat_colour_not_mean,
                    Mistake::gouraud_weights_permuted}) {
    const char* id = gradetest::catalogue_id(m);
    REQUIRE(id != nullptr);
    INFO(id);
    CHECK_FALSE(catalogue_mistake(id).verdict.empty());
  }
  // The words, verbatim.
  CHECK(catalogue_mistake("span_too_wide").verdict ==
        "spans are one pixel too wide on both sides (floor(x_L) .. ceil(x_R)?)");
  CHECK(catalogue_mistake("order_reversed").verdict == "faces are painted nearest first");
  CHECK(catalogue_mistake("float_drift").verdict ==
        "x drifts: accumulated with x += dx/dy in floating point");
}

TEST_CASE("catalogue: the whole-image thresholds", "[grade][catalogue]") {
  CHECK(whole_image_tolerance("transform_gain") == 2.0);
  CHECK(whole_image_tolerance("background_share") == 0.9);
  CHECK_THROWS_AS(whole_image_tolerance("about"), std::out_of_range);
  CHECK_THROWS_AS(whole_image_tolerance("nothing"), std::out_of_range);
}
