// diff's categories are an enum with one table of names: the names are those docs/grading.md
// documents (written out here by hand, in its order), every one reads back to its category, and
// the report's JSON and per-pixel map use them in that order.
#include <array>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "grade/diff_report.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::grade::Category;

namespace {

// docs/grading.md's table, in the order the classifiers are tried.
const std::array<std::string, 11> kDocumented{
    "boundary",     "near_boundary",    "widened", "shifted",    "order", "order_tie",
    "missing_face", "degenerate_drawn", "colour",  "background", "other"};

}  // namespace

TEST_CASE("every diff category's name reads back to it, names as documented", "[grade][diff]") {
  REQUIRE(grade::kCategoryCount == kDocumented.size());
  for (std::size_t i = 0; i < kDocumented.size(); ++i) {
    INFO(kDocumented[i]);
    const Category c = grade::category_at(i);
    CHECK(grade::category_name(c) == kDocumented[i]);
    const auto back = grade::category_named(kDocumented[i]);
    REQUIRE(back.has_value());
    CHECK(*back == c);
  }
  CHECK(grade::category_name(Category::colour) == std::string("colour"));
  CHECK(grade::category_name(Category::order_tie) == std::string("order_tie"));
  CHECK_FALSE(grade::category_named("color").has_value());
  CHECK_FALSE(grade::category_named("").has_value());
}

TEST_CASE("the report's JSON and category map use the documented names in order", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::flat_colour_not_mean);
  const grade::DiffReport r = grade::diff(s, opts(Shading::flat), as_8bit(bad));
  REQUIRE(r.differing_pixels > 1000);
  const nlohmann::json j = r.to_json();
  std::size_t keys = 0;
  for (const auto& name : kDocumented) keys += j.at("categories").contains(name);
  CHECK(keys == kDocumented.size());
  CHECK(j.at("categories").size() == kDocumented.size());
  CHECK(j.at("categories").at("colour") == r.differing_pixels);
  const auto& legend = j.at("category_map").at("legend");
  REQUIRE(legend.size() == kDocumented.size());
  for (std::size_t i = 0; i < kDocumented.size(); ++i) CHECK(legend[i] == kDocumented[i]);
  // Every differing pixel is `colour`: 1 + its place in the documented list.
  std::int64_t colour = 0;
  for (std::uint8_t c : r.category_map) colour += c == 1 + 8;
  CHECK(colour == r.differing_pixels);
  for (const auto& e : r.examples) CHECK(e.category == "colour");
}
