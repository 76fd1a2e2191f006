// GridView::cells, the magnified canvas of a step frame (the block of pixels the explorer's
// module scans into runs on every mouse move of a drag): every frame pixel of the view is the
// outside-the-canvas colour where its canvas pixel is off the canvas, the pixel's colour where the
// state holds it written, and the empty cell (or the background given) elsewhere. Checked pixel
// by pixel against that rule, for cells smaller and larger than a frame pixel, views reaching past
// every edge of the canvas and state windows smaller than the canvas.
#include <catch2/catch.hpp>

#include "src/image.hpp"
#include "viz/canvas_state.hpp"
#include "viz/grid_view.hpp"
#include "viz/palette.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

using namespace scantrace;

namespace {

viz::Vec3b bgr(const viz::Scalar& s) {
  return {static_cast<std::uint8_t>(s[0]), static_cast<std::uint8_t>(s[1]), static_cast<std::uint8_t>(s[2])};
}

// The cells' block GridView::cells adds to a frame of `view` showing `region` of a 64 x 48 canvas.
const viz::PixelsOp& cells_of(viz::Frame& frame, const viz::Rect& view, const viz::PixelBox& region,
                              const viz::CanvasState& state, std::optional<Color> background) {
  viz::FrameView fv(frame);
  const viz::ViewGeometry g(view, region, 64);
  viz::GridView grid(fv, g, viz::Typography(frame.size()), {64, 48});
  grid.cells(state, background);
  return std::get<viz::PixelsOp>(frame.ops().back().body);
}

}  // namespace

TEST_CASE("the cells of a view are the written pixels, empty cells and the outside, pixel by pixel") {
  const viz::Rect window{5, 3, 50, 40};  // canvas pixels the state keeps
  viz::CanvasState state(window);
  // A diagonal band of written pixels in colours that vary with x and y, some on the window's
  // edges, and one pixel outside the window (not kept).
  for (std::int64_t y = 0; y < 48; ++y)
    for (std::int64_t x = 0; x < 64; ++x)
      if (std::abs(x - y - 8) < 6 || (x == 5 && y == 3) || (x == 54 && y == 42))
        if (x >= window.x && x < window.x + window.width && y >= window.y && y < window.y + window.height)
          state.put(x, y, Color{x / 64.0, y / 48.0, 0.5});
  const viz::Vec3b outside = bgr(viz::palette::kOutsideCanvas);
  int checked = 0, written = 0, outs = 0;
  struct Case {
    viz::Rect view;
    viz::PixelBox region;
    std::optional<Color> background;
  };
  for (const Case& c : {Case{{10, 20, 300, 200}, {0, 0, 63, 47}, std::nullopt},       // cells of ~4 px
                        Case{{0, 0, 50, 40}, {-20, -10, 90, 70}, std::nullopt},       // cells under 1 px
                        Case{{7, 3, 333, 211}, {-3, -2, 20, 15}, Color{0.2, 0.4, 0.6}},  // past the top left
                        Case{{0, 0, 200, 120}, {50, 40, 70, 60}, std::nullopt}}) {  // past the bottom right
    viz::Frame frame({400, 260}, viz::Scalar{});
    const viz::PixelsOp& p = cells_of(frame, c.view, c.region, state, c.background);
    const viz::ViewGeometry g(c.view, c.region, 64);
    REQUIRE(p.area.width == c.view.width);
    REQUIRE(p.area.height == c.view.height);
    // The background as the composer writes a colour: each channel by to_byte, from a float.
    const auto byte = [](double v) { return to_byte(static_cast<float>(v)); };
    const viz::Vec3b empty = c.background ? viz::Vec3b(byte(c.background->b), byte(c.background->g), byte(c.background->r))
                                          : bgr(viz::palette::kEmptyCell);
    for (int r = 0; r < p.area.height; ++r)
      for (int u = 0; u < p.area.width; ++u) {
        const std::int64_t x = g.pixel_x(c.view.x + u), y = g.pixel_y(c.view.y + r);
        viz::Vec3b want = empty;
        if (x < 0 || x >= 64 || y < 0 || y >= 48) {
          want = outside;
          ++outs;
        } else if (state.written(x, y)) {
          want = state.bgr(x, y);
          ++written;
        }
        INFO("frame pixel (" << u << ", " << r << ") of view " << c.view.width << "x" << c.view.height
                             << ": canvas pixel (" << x << ", " << y << ")");
        REQUIRE((*p.bgr)[static_cast<std::size_t>(r) * static_cast<std::size_t>(p.area.width) +
                         static_cast<std::size_t>(u)] == want);
        ++checked;
      }
  }
  CHECK(written > 1000);
  CHECK(outs > 1000);
  CHECK(checked > 100000);
}
