// `diff` against renderers broken on purpose in the test (wrong_renderers.hpp): each mistake's
// differences land in the category the issue names, with the count the test makes on its own.
#include <algorithm>
#include <set>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "grade/diff_report.hpp"
#include "src/painter.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::grade::diff;
using scantrace::grade::DiffReport;

namespace {

bool mentions(const std::vector<std::string>& lines, const std::string& words) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(words) != std::string::npos; });
}

bool has_global(const DiffReport& r, const std::string& kind) {
  return std::any_of(r.global.begin(), r.global.end(),
                     [&](const auto& g) { return g.kind == kind; });
}

std::string global_text(const DiffReport& r, const std::string& kind) {
  for (const auto& g : r.global)
    if (g.kind == kind) return g.text;
  return "(no " + kind + " mistake)";
}

// The faces the correct picture shows somewhere: per pixel the last face, in the test's own
// painter's order, whose exact coverage holds the centre.
std::set<int> visible_faces(const Scene& s) {
  std::vector<int> top(static_cast<std::size_t>(s.width) * s.height, -1);
  for (int f : order(s, false)) {
    const reference::Polygon poly(points(s, f), 8);
    if (poly.degenerate()) continue;
    for (long long y = std::max<long long>(poly.min_py(), 0);
         y <= std::min<long long>(poly.max_py(), s.height - 1); ++y)
      for (long long x = std::max<long long>(poly.min_px(), 0);
           x <= std::min<long long>(poly.max_px(), s.width - 1); ++x)
        if (poly.covers(x, y, FillRule::top_left))
          top[static_cast<std::size_t>(y) * s.width + x] = f;
  }
  return {top.begin(), top.end()};
}

}  // namespace

TEST_CASE("the test's correct renderer agrees with the fill: the grader's baseline",
          "[grade][diff]") {
  const Scene s = generated_scene();
  for (Shading sh : {Shading::flat, Shading::gouraud}) {
    const RgbImage mine = render_wrong(s, sh, Mistake::none);
    REQUIRE(count_differing(mine, render<Rgb32f>(s, opts(sh))) == 0);
    const DiffReport r = diff(s, opts(sh), as_8bit(mine));
    CHECK(r.agrees());
    CHECK(r.differing_pixels == 0);
    CHECK(r.global.empty());
    CHECK(r.compared_pixels == 200 * 160);
    CHECK(r.examples.empty());
  }
}

TEST_CASE("the closed rule's extra edge pixels are boundary", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::closed_rule);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 50);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("boundary") == expected);
  CHECK_FALSE(r.agrees());
}

TEST_CASE("dropping every face's last row is near_boundary, missing, bottom row", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::bottom_row_dropped);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 50);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  INFO(r.to_json()["categories"].dump() << " " << r.to_json()["examples"].dump());
  CHECK(r.differing_pixels == expected);
  // A dropped row that is the whole overlap of a face with the one below it reads as that face
  // painted over (`order`): a few pixels, no more.
  CHECK(r.categories.at("near_boundary") + r.categories.at("order") == expected);
  CHECK(r.categories.at("near_boundary") >= expected * 98 / 100);
  CHECK(r.near_boundary_missing == r.categories.at("near_boundary"));
  CHECK(r.near_boundary_extra == 0);
  CHECK(mentions(r.patterns, "bottom row"));
}

TEST_CASE("a span one pixel too wide is near_boundary, extra, right of the span", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  std::vector<int> painted;
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::span_one_too_wide, 8, &painted);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 50);
  // The extra pixel is exactly on the face's outline where the span ends on a pixel centre (the
  // integer tiles): that is the closed rule's pixel, `boundary`; elsewhere `near_boundary`.
  long long on_outline = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const Rgb32f p = good(x, y), q = bad(x, y);
      if (std::max({std::fabs(p.r - q.r), std::fabs(p.g - q.g), std::fabs(p.b - q.b)}) <= 1.0 / 255)
        continue;
      const int f = painted[static_cast<std::size_t>(y) * s.width + x];
      REQUIRE(f >= 0);
      on_outline += reference::Polygon(points(s, f), 8).covers(x, y, FillRule::closed);
    }
  REQUIRE(on_outline > 0);
  REQUIRE(on_outline < expected);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  INFO(r.to_json()["categories"].dump() << " " << r.to_json()["examples"].dump());
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("boundary") == on_outline);
  // A tile's lower triangle loses its left-end pixels to its neighbour and gains one on the right:
  // in the image it is the face translated by one pixel, `shifted` by definition.
  CHECK(r.categories.at("near_boundary") + r.categories.at("shifted") == expected - on_outline);
  CHECK(r.categories.at("near_boundary") > 0);
  CHECK(r.near_boundary_extra == r.categories.at("near_boundary"));
  CHECK(mentions(r.patterns, "right of the span"));
}

TEST_CASE("spans one pixel too wide at both ends are widened, a face moved one pixel shifted",
          "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage wide = render_wrong(s, Shading::flat, Mistake::span_too_wide);
  const RgbImage moved = render_wrong(s, Shading::flat, Mistake::shift_right);
  const long long n_wide = count_differing(good, wide), n_moved = count_differing(good, moved);
  REQUIRE(n_wide > 50);
  REQUIRE(n_moved > 50);
  const DiffReport w = diff(s, opts(Shading::flat), as_8bit(wide));
  INFO("widened image: " << w.to_json()["categories"].dump());
  const DiffReport m = diff(s, opts(Shading::flat), as_8bit(moved));
  INFO("moved image: " << m.to_json()["categories"].dump());
  CHECK(w.differing_pixels == n_wide);
  CHECK(m.differing_pixels == n_moved);
  // Each mistake in its own category: most of the widened image's pixels are `widened` (the rest
  // mostly on the tiles' outlines, `boundary`; measured: 909 widened, 463 boundary, 60 shifted of
  // 1432), few `shifted`; the moved image is never `widened`.
  CHECK(w.categories.at("widened") + w.categories.at("boundary") >= n_wide * 9 / 10);
  CHECK(w.categories.at("widened") > w.categories.at("boundary"));
  CHECK(w.categories.at("shifted") <= n_wide / 20);
  CHECK(m.categories.at("widened") == 0);
  CHECK(m.categories.at("shifted") >= n_moved / 2);
}

TEST_CASE("nearest-first painting is order", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::gouraud, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::gouraud, Mistake::order_reversed);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 1000);
  const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("order") == expected);
}

TEST_CASE("faces with a horizontal edge skipped are missing_face, each listed", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::horizontal_edge_skipped);
  const long long expected = count_differing(good, bad);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("missing_face") == expected);
  std::set<int> want;
  for (int f : visible_faces(s))
    if (f >= 0 && has_horizontal_edge(s, f, 8)) want.insert(f);
  std::set<int> got;
  for (const auto& m : r.missing_faces) {
    got.insert(m.face);
    CHECK(m.shape.find("horizontal edge") != std::string::npos);
  }
  CHECK(got == want);
}

TEST_CASE("zero-area faces painted are degenerate_drawn", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::degenerate_drawn);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 20);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("degenerate_drawn") == expected);
}

TEST_CASE("flat colour = the first vertex's colour is colour, diagnosed", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::flat, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::flat, Mistake::flat_colour_not_mean);
  const long long expected = count_differing(good, bad);
  REQUIRE(expected > 1000);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("colour") == expected);
  REQUIRE_FALSE(r.colour_diagnosis.empty());
  CHECK(r.colour_diagnosis.front().find("first vertex") != std::string::npos);
  CHECK(r.max_colour_error > 1.0 / 255);
}

TEST_CASE("Gouraud with two vertex colours swapped is colour, permutation named", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::gouraud, Mistake::none);
  const RgbImage bad = render_wrong(s, Shading::gouraud, Mistake::gouraud_weights_permuted);
  // Counted on the 8-bit image the grader reads: near the tolerance, rounding decides.
  const long long expected = count_differing(good, as_8bit(bad).pixels);
  REQUIRE(expected > 1000);
  const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(bad));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("colour") == expected);
  REQUIRE_FALSE(r.colour_diagnosis.empty());
  CHECK(r.colour_diagnosis.front().find("colours of 1, 0, 2") != std::string::npos);
}

TEST_CASE("8-bit truncation stays inside the tolerance and is noted", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::gouraud, Mistake::none);
  const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(good, true));
  CHECK(r.differing_pixels == 0);
  CHECK(r.agrees());
  CHECK(mentions(r.notes, "truncation"));
  const DiffReport rounded = diff(s, opts(Shading::gouraud), as_8bit(good, false));
  CHECK_FALSE(mentions(rounded.notes, "truncation"));
  // The same values as a float .npy, floor(255·c)/255 (issue 36: no note for floats before); a
  // float image of the exact colours is not 8-bit and gets none.
  grade::SubmittedImage floats = as_8bit(good, true);
  floats.format = "npy", floats.eight_bit = false;
  CHECK(mentions(diff(s, opts(Shading::gouraud), floats).notes, "truncation"));
  CHECK_FALSE(mentions(diff(s, opts(Shading::gouraud), as_npy(good)).notes, "truncation"));
}

TEST_CASE("a float render that never went through 8 bits gets no truncation note",
          "[grade][diff]") {
  // Every value 0.7 of a level below the exact colour: within the tolerance, never 8-bit. A few
  // values land on a multiple of 1/255 by chance, and there floor(255·c) = round(255·c) - 1:
  // they read as truncated, but the image is no 8-bit image (issue 47: 617 such values on the
  // course scene gave the note).
  const Scene s = generated_scene();
  RgbImage img = render_wrong(s, Shading::gouraud, Mistake::none);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      Rgb32f& p = img(x, y);
      p = {p.r - 0.7f / 255, p.g - 0.7f / 255, p.b - 0.7f / 255};
    }
  const DiffReport r = diff(s, opts(Shading::gouraud), as_npy(img));
  CHECK(r.differing_pixels == 0);
  CHECK_FALSE(mentions(r.notes, "truncation"));
}

TEST_CASE("one bright pixel is one differing pixel, and values above 1 are a note, not a scale",
          "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::gouraud, Mistake::none);
  SECTION("one pixel at 1.01") {
    RgbImage img = good;
    img(50, 30) = {1.01f, 0.5f, 0.5f};
    const long long expected = count_differing(good, img);  // 1, unless (50, 30) was that colour
    REQUIRE(expected == 1);
    const DiffReport r = diff(s, opts(Shading::gouraud), as_npy(img));
    INFO(r.to_markdown());
    CHECK(r.global.empty());
    CHECK(r.differing_pixels == 1);
    CHECK(mentions(r.notes, "1 pixel above 1.0 (largest 1.01)"));
  }
  SECTION("Gouraud colours extrapolated up to 1.28 on 12 pixels") {
    RgbImage img = good;
    for (int k = 0; k < 12; ++k) img(20 + 7 * k, 40 + 3 * k) = {1.0f + 0.02f * (k + 3), 0.2f, 0.9f};
    const DiffReport r = diff(s, opts(Shading::gouraud), as_npy(img));
    INFO(r.to_markdown());
    CHECK(r.global.empty());
    CHECK(r.differing_pixels == count_differing(good, img));
    CHECK(r.differing_pixels == 12);
    CHECK(mentions(r.notes, "12 pixels above 1.0 (largest 1.28)"));
  }
}

TEST_CASE("global mistakes are one line each, undone, and the rest agrees", "[grade][diff]") {
  const Scene s = generated_scene();
  const RgbImage good = render_wrong(s, Shading::gouraud, Mistake::none);
  const int W = good.width(), H = good.height();
  SECTION("transposed") {
    RgbImage t(H, W);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) t(y, x) = good(x, y);
    const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(t));
    CHECK(has_global(r, "transposed"));
    CHECK_FALSE(has_global(r, "canvas_size"));
    CHECK(r.differing_pixels == 0);
    CHECK_FALSE(r.agrees());
    const DiffReport raw = diff(s, opts(Shading::gouraud), as_8bit(t), {.undo = false});
    CHECK(has_global(raw, "transposed"));
    CHECK(raw.compared_pixels < W * H);
  }
  SECTION("BGR") {
    RgbImage t(W, H);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) t(x, y) = {good(x, y).b, good(x, y).g, good(x, y).r};
    const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(t));
    CHECK(has_global(r, "bgr"));
    CHECK(r.global.size() == 1);
    CHECK(r.differing_pixels == 0);
  }
  SECTION("flipped vertically") {
    RgbImage t(W, H);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) t(x, H - 1 - y) = good(x, y);
    const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(t));
    CHECK(has_global(r, "flipped_vertically"));
    CHECK(r.differing_pixels == 0);
  }
  SECTION("[0, 255] floats in a .npy") {
    RgbImage t(W, H);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        t(x, y) = {255 * good(x, y).r, 255 * good(x, y).g, 255 * good(x, y).b};
    const DiffReport r = diff(s, opts(Shading::gouraud), as_npy(t));
    CHECK(has_global(r, "scaled_255"));
    CHECK(r.differing_pixels == 0);
  }
  SECTION("a 0.99 grey background") {
    Scene grey = s;
    grey.background = {0.99, 0.99, 0.99};
    const RgbImage t = render_wrong(grey, Shading::gouraud, Mistake::none);
    const DiffReport r = diff(s, opts(Shading::gouraud), as_npy(t));
    CHECK(has_global(r, "background"));
    // The float values as they are, not their 8-bit bin 252/255 = 0.988 (issue 36).
    CHECK_THAT(global_text(r, "background"),
               Catch::StartsWith("the background is (0.99, 0.99, 0.99) instead of (1, 1, 1) ("));
    CHECK(r.differing_pixels == 0);
    const DiffReport raw = diff(s, opts(Shading::gouraud), as_npy(t), {.undo = false});
    CHECK(raw.differing_pixels > 1000);
  }
  SECTION("another canvas size") {
    RgbImage t(W + 10, H);
    const DiffReport r = diff(s, opts(Shading::gouraud), as_8bit(t));
    CHECK(has_global(r, "canvas_size"));
  }
}

TEST_CASE("z-buffer: a painter's image of interpenetrating faces is order, counted per pixel",
          "[grade][diff][zbuffer]") {
  // Two triangles that cross: A tilts from near (depth 1) on the left to far (9) on the right, B
  // is level at depth 5 (mean depths 3.67 and 5: the painter draws B first, A over it). Integer
  // vertices, so snapping moves nothing and the test's own depth planes are the render's.
  Scene s;
  s.width = 64, s.height = 48;
  s.vertices = {{4, 4}, {60, 6}, {8, 44}, {2, 20}, {62, 12}, {40, 46}};
  s.depth = {1, 9, 1, 5, 5, 5};
  s.vcolors = {{0.9, 0.2, 0.1}, {0.9, 0.2, 0.1}, {0.9, 0.2, 0.1},
               {0.1, 0.3, 0.9}, {0.1, 0.3, 0.9}, {0.1, 0.3, 0.9}};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  FillOptions z = opts(Shading::flat);
  z.visibility = Visibility::zbuffer;
  const RgbImage painter = render<Rgb32f>(s, opts(Shading::flat));
  // Independently: where both faces cover the centre, the depth of A at it (the plane through its
  // three points) against B's 5; the painter shows A there, the z-buffer the nearer.
  const reference::Polygon a(points(s, 0), 8), b(points(s, 1), 8);
  long long expected = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      if (!a.covers(x, y, FillRule::top_left) || !b.covers(x, y, FillRule::top_left)) continue;
      // A's depth: 1 + 8 * (barycentric weight of vertex 1).
      const Vec2 p0 = s.vertices[0], p1 = s.vertices[1], p2 = s.vertices[2];
      const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
      const double w1 = ((x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (y - p0.y)) / area;
      expected += 1 + 8 * w1 > 5;  // A farther: the z-buffer shows B, the painter A
    }
  REQUIRE(expected > 50);
  const DiffReport r = diff(s, z, as_8bit(painter));
  CHECK(r.differing_pixels == expected);
  CHECK(r.categories.at("order") == expected);
  // And the z-buffer's own image agrees.
  CHECK(diff(s, z, as_8bit(render<Rgb32f>(s, z))).agrees());
}
