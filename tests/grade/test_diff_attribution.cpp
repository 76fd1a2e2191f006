// `diff` says nothing false (issue 35, point 5): which face wrote a pixel whose colour two faces
// share, the missing faces listed only where the table counts `missing_face`, the examples giving
// the row's span of the face in question and where x falls, and report.json's per-pixel map of
// the categories. Each image is drawn by the test's own renderer (wrong_renderers.hpp).
#include <algorithm>
#include <set>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "grade/diff_report.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::grade::diff;
using scantrace::grade::DiffOptions;
using scantrace::grade::DiffReport;

namespace {

FillOptions flat() {
  FillOptions o;
  o.shading = Shading::flat;
  return o;
}

// A face with one colour at its three vertices.
void add_face(Scene& s, std::array<Vec2, 3> p, Color c, double depth) {
  const int base = static_cast<int>(s.vertices.size());
  for (const Vec2 v : p) {
    s.vertices.push_back(v);
    s.vcolors.push_back(c);
    s.depth.push_back(depth);
  }
  s.faces.push_back({base, base + 1, base + 2});
}

// Face f's pixels on row y under the top-left rule (the exact reference), as "span A..B".
std::string exact_span(const Scene& s, int f, int y) {
  const reference::Polygon poly(points(s, f), 8);
  long long first = -1, last = -1;
  for (long long x = std::max<long long>(poly.min_px(), 0);
       x <= std::min<long long>(poly.max_px(), s.width - 1); ++x)
    if (poly.covers(x, y, FillRule::top_left)) {
      if (first < 0) first = x;
      last = x;
    }
  return first < 0 ? std::string() : fmt::format("span {}..{}", first, last);
}

// The sentence about face f in a `why` paragraph: from "face F (depth" to the next face's.
std::string sentence_of(const std::string& why, int f) {
  const auto start = why.find(fmt::format("face {} (depth", f));
  if (start == std::string::npos) return {};
  const auto end = why.find(" face ", start + 1);
  return why.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace

TEST_CASE("a colour two faces share is the drawn face's, not a zero-area face's",
          "[grade][diff]") {
  // Face 0 has no area: a vertical segment through the centres of column 15, which the fill
  // never draws. Face 1, of the same colour, ends its rows at x = 14.5 (span ..14). The image
  // draws face 1 one pixel too wide: column 15, rows 5..19, in face 1's (and face 0's) colour.
  Scene s;
  s.width = 40, s.height = 30;
  const Color c{0.2, 0.5, 0.7};
  add_face(s, {Vec2{15, 3}, Vec2{15, 12}, Vec2{15, 24}}, c, 5);
  add_face(s, {Vec2{5, 5}, Vec2{14.5, 5}, Vec2{14.5, 20}}, c, 10);
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::span_one_too_wide);
  REQUIRE(count_differing(good, bad) == 15);
  const DiffReport r = diff(s, flat(), as_8bit(bad));
  INFO(r.to_json()["categories"].dump() << " " << r.to_markdown());
  CHECK(r.differing_pixels == 15);
  CHECK(r.categories.at("degenerate_drawn") == 0);
  CHECK(r.categories.at("near_boundary") == 15);
  CHECK(r.near_boundary_extra == 15);
  for (const auto& e : r.examples) CHECK(e.image_face == 1);
}

TEST_CASE("the missing faces listed are those the table counts as missing_face",
          "[grade][diff]") {
  // Face 1 lies inside face 0 and in front of it. Painted nearest first, face 1 is painted over
  // everywhere: `order`, and no face is missing. Skipped for its horizontal edge (both faces have
  // one), each face is missing: `missing_face`, both listed.
  Scene s;
  s.width = 40, s.height = 30;
  add_face(s, {Vec2{2, 2}, Vec2{37, 2}, Vec2{2, 27}}, {0.9, 0.3, 0.1}, 10);
  add_face(s, {Vec2{6, 6}, Vec2{14, 6}, Vec2{6, 14}}, {0.1, 0.3, 0.9}, 5);
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);

  const RgbImage reversed = render_wrong(s, Shading::flat, Mistake::order_reversed);
  const long long n_hidden = count_differing(good, reversed);
  REQUIRE(n_hidden > 20);
  const DiffReport r = diff(s, flat(), as_8bit(reversed));
  INFO(r.to_markdown());
  CHECK(r.categories.at("order") == n_hidden);
  CHECK(r.categories.at("missing_face") == 0);
  CHECK(r.missing_faces.empty());
  CHECK(r.to_markdown().find("## Missing faces") == std::string::npos);

  const RgbImage skipped = render_wrong(s, Shading::flat, Mistake::horizontal_edge_skipped);
  const DiffReport m = diff(s, flat(), as_8bit(skipped));
  INFO(m.to_markdown());
  CHECK(m.categories.at("missing_face") == count_differing(good, skipped));
  std::set<int> listed;
  for (const auto& f : m.missing_faces) listed.insert(f.face);
  CHECK(listed == std::set<int>{0, 1});
}

TEST_CASE("near_boundary and shifted examples give the row's span and where x falls",
          "[grade][diff]") {
  const Scene s = generated_scene();
  int checked = 0;
  for (Mistake mistake : {Mistake::span_one_too_wide, Mistake::shift_right}) {
    DiffOptions dopt;
    dopt.examples_per_category = 6;
    const DiffReport r =
        diff(s, flat(), as_8bit(render_wrong(s, Shading::flat, mistake)), dopt);
    for (const auto& e : r.examples) {
      if (e.category != "near_boundary" && e.category != "shifted") continue;
      // The face in question: the one the image shows there (drawn where the reference does not
      // draw it), else the reference's (left out).
      const int f = e.image_face >= 0 ? e.image_face : e.reference_face;
      if (f < 0) continue;
      const std::string span = exact_span(s, f, e.y);
      INFO(e.category << " at (" << e.x << ", " << e.y << "), face " << f << ", " << span
                      << ": " << e.why);
      CHECK(e.why.find(fmt::format("face {} (depth", f)) != std::string::npos);
      if (span.empty()) {
        CHECK(e.why.find(fmt::format("row {} is not among its scanlines", e.y)) !=
              std::string::npos);
      } else {
        const std::string said = sentence_of(e.why, f);
        CHECK(said.find(span) != std::string::npos);
        // Where x falls: left or right of that span, or inside it (the face covers it).
        CHECK((said.find(fmt::format("x = {} is", e.x)) != std::string::npos ||
               said.find("covers it") != std::string::npos));
      }
      ++checked;
    }
  }
  CHECK(checked >= 6);
}

TEST_CASE("report.json carries every differing pixel's category as runs", "[grade][diff]") {
  const Scene s = generated_scene();
  std::vector<int> painted;
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::order_reversed);
  const DiffReport r = diff(s, flat(), as_8bit(bad));
  const nlohmann::json j = r.to_json();
  REQUIRE(j.contains("category_map"));
  const auto& map = j["category_map"];
  CHECK(map["encoding"] == "runs");
  const auto legend = map["legend"].get<std::vector<std::string>>();
  // Expand the runs, then compare with the pixels the test finds differing on its own.
  std::vector<std::string> cat(static_cast<std::size_t>(s.width) * s.height);
  std::map<std::string, std::int64_t> counts;
  long long previous_end = -1;
  for (const auto& run : map["runs"]) {
    const long long start = run[0], length = run[1];
    const std::size_t code = run[2];
    REQUIRE(code < legend.size());
    REQUIRE(length > 0);
    CHECK(start >= previous_end);  // sorted, not overlapping
    previous_end = start + length;
    for (long long p = start; p < start + length; ++p) cat[p] = legend[code];
    counts[legend[code]] += length;
  }
  long long differing = 0, mapped_where_differing = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const Rgb32f p = good(x, y), q = bad(x, y);
      const bool differs =
          std::max({std::fabs(p.r - q.r), std::fabs(p.g - q.g), std::fabs(p.b - q.b)}) > 1.0 / 255;
      const std::string& c = cat[static_cast<std::size_t>(y) * s.width + x];
      differing += differs;
      mapped_where_differing += differs && !c.empty();
      if (!differs) CHECK(c.empty());
    }
  CHECK(mapped_where_differing == differing);
  for (const auto& [name, n] : counts) CHECK(r.categories.at(name) == n);
  CHECK(counts.at("order") == differing);
}
