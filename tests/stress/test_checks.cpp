// The checks catch what they claim to catch: rasterizers broken on purpose (an extra pixel that
// depends on the vertex order, a NaN colour, a lost row, the closed rule passed off as top-left)
// must each show up in their own column, and the exact method on the same cases shows nothing.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "src/scanline_fill.hpp"
#include "stress/checks.hpp"
#include "stress/rasterizer.hpp"
#include "stress/reference_window.hpp"

using namespace scantrace;
using namespace scantrace::stress;

namespace {

// The exact method with one deliberate defect after (or instead of) the fill.
class Broken final : public Rasterizer {
 public:
  enum class Defect { none, order_dependent_pixel, nan_colour, lose_first_row, closed_rule };
  explicit Broken(Defect d) : defect_(d), exact_(make_method(Method::exact)) {}

  std::string name() const override { return "broken"; }
  FillRule rule() const override { return FillRule::top_left; }
  bool shades() const override { return true; }

  void draw(StressCanvas& canvas, const Triangle& t, int bits, Shading shading) override {
    if (defect_ == Defect::closed_rule) {
      FillScratch scratch;
      FillOptions opt;
      opt.shading = shading;
      opt.fill_rule = FillRule::closed;
      opt.subpixel_bits = bits;
      fill_polygon(canvas, PolygonInput{t.v, t.c, 0, std::nullopt}, opt, scratch);
      return;
    }
    if (defect_ == Defect::lose_first_row) {
      // Fill into a side canvas, then copy everything but the topmost written row.
      side_.reset(canvas.width(), canvas.height());
      exact_->draw(side_, t, bits, shading);
      for (int y = side_.y0() + 1; y < side_.y1(); ++y)
        for (int x = side_.x0(); x < side_.x1(); ++x)
          if (side_.count(x, y) > 0) canvas.set(x, y, side_.color(x, y));
      return;
    }
    exact_->draw(canvas, t, bits, shading);
    if (defect_ == Defect::order_dependent_pixel) {
      // The pixel of the first vertex as listed: a different pixel for each vertex order.
      const int x = static_cast<int>(std::floor(t.v[0].x)) + 1;
      const int y = static_cast<int>(std::floor(t.v[0].y)) + 1;
      if (x >= 0 && y >= 0 && x < canvas.width() && y < canvas.height()) canvas.set(x, y, t.c[0]);
    }
    if (defect_ == Defect::nan_colour && canvas.written())
      canvas.set(canvas.x0(), canvas.y0(), Color{std::numeric_limits<double>::quiet_NaN(), 0, 0});
  }

 private:
  Defect defect_;
  std::unique_ptr<Rasterizer> exact_;
  StressCanvas side_;
};

StressCase one_triangle() {
  StressCase c;
  c.width = 64;
  c.height = 48;
  c.triangles = {Triangle{{Vec2{3.5, 2.25}, Vec2{60, 20}, Vec2{12.75, 44}},
                          {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}}};
  return c;
}

CaseResult check(Rasterizer& r, const StressCase& c) {
  const Triangle& t = c.triangles[0];
  const ReferenceWindow ref(c.width, c.height, t.v, t.c, r.rule());
  Checker checker;
  return checker.check_triangle(r, c, ref);
}

}  // namespace

TEST_CASE("the exact method passes the checks of a plain triangle", "[stress][checks]") {
  auto exact = make_method(Method::exact);
  const CaseResult r = check(*exact, one_triangle());
  CHECK(r.fills == 6);
  CHECK(r.ref_pixels > 6 * 500);
  CHECK_FALSE(r.failed(1e-4));
  CHECK(r.problem.empty());
  CHECK(r.colour.max < 1e-12);
}

TEST_CASE("an order-dependent pixel is an order difference and an extra pixel",
          "[stress][checks]") {
  Broken broken(Broken::Defect::order_dependent_pixel);
  const CaseResult r = check(broken, one_triangle());
  CHECK(r.order_differs);
  CHECK(r.extra > 0);
  CHECK(r.failed(1e-4));
  CHECK_FALSE(r.problem.empty());
}

TEST_CASE("a NaN colour is counted", "[stress][checks]") {
  Broken broken(Broken::Defect::nan_colour);
  const CaseResult r = check(broken, one_triangle());
  CHECK(r.nonfinite == 6);
  CHECK(r.colour.max == std::numeric_limits<double>::infinity());
  CHECK(r.failed(1e-4));
}

TEST_CASE("a lost row is counted pixel by pixel as missing", "[stress][checks]") {
  Broken broken(Broken::Defect::lose_first_row);
  const StressCase c = one_triangle();
  const CaseResult r = check(broken, c);
  CHECK(r.missing > 0);
  CHECK(r.missing % 6 == 0);  // the same row lost in every vertex order
  CHECK(r.extra == 0);
  CHECK_FALSE(r.order_differs);
}

TEST_CASE("the closed rule passed off as top-left overlaps itself in a mesh", "[stress][checks]") {
  // An integer grid: every shared edge runs through pixel centres, which the closed rule gives to
  // both triangles.
  StressCase c;
  for (std::uint64_t i = 1; c.kind.rfind("integer grid", 0) != 0; i += 3) {
    REQUIRE(i < 3000);
    c = generate(Family::meshes, 3, i);
  }
  const ReferenceWindow region(c.width, c.height, c.region, {}, FillRule::top_left);
  Checker checker;
  Broken closed(Broken::Defect::closed_rule);
  const CaseResult bad = checker.check_mesh(closed, c, region);
  CHECK(bad.overlaps > 0);
  CHECK(bad.failed(1e-4));
  auto exact = make_method(Method::exact);
  const CaseResult good = checker.check_mesh(*exact, c, region);
  CHECK(good.gaps == 0);
  CHECK(good.overlaps == 0);
  CHECK(good.extra == 0);
  CHECK_FALSE(good.failed(1e-4));
  CHECK(good.fills == 6 * static_cast<long long>(c.triangles.size()));
}
