#pragma once
// A canvas adaptor that adds a depth buffer to an Image<P>: the sweep writes through it unchanged
// (fill_span / set), and it lets a pixel through only where the triangle is nearer than what is
// already there. Depth is linear in the pixel position over the triangle, computed from the
// *snapped* vertices the colour interpolation also uses (edge_color_at): Gouraud's two passes of
// vector_interp evaluate that same linear function, so per-pixel depth is interpolated exactly as
// colours are — here in closed form (the plane through the three (x, y, depth) points), so that
// the sweep needs no extra per-pixel state and the painter's path is untouched.
//
// Depth convention: the scene's (larger = farther). The nearer (smaller) depth wins; equal depth
// keeps the pixel of the face drawn first, so results do not depend on floating-point ties.
#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <vector>

#include "canvas.hpp"
#include "depth_plane.hpp"
#include "depth_test.hpp"
#include "fast/depth_tiles.hpp"
#include "fixed_point.hpp"
#include "vec2.hpp"

namespace scantrace {

template <class P>
class ZBufferCanvas {
 public:
  // `log_tests`: remember each pixel's outcome on the current row for depth_test() (only the
  // pixel-level trace asks; an untraced render leaves it off).
  ZBufferCanvas(Image<P>& image, bool log_tests = false)
      : image_(image),
        own_(static_cast<std::size_t>(image.width()) * image.height(),
             std::numeric_limits<double>::infinity()),
        depth_(own_),
        band_{0, image.height()},
        log_(log_tests ? static_cast<std::size_t>(image.width()) : 0) {}

  // The rows `band` of `image`, with its depth buffer `depth` (width × height values, row-major,
  // +infinity where nothing is drawn yet) kept by the caller: a render that keeps it allocates
  // nothing, and bands on several threads share one buffer, each writing only its own rows
  // (band_render.hpp).
  ZBufferCanvas(Image<P>& image, std::span<double> depth, RowBand band, bool log_tests = false)
      : image_(image),
        depth_(depth),
        band_(band),
        log_(log_tests ? static_cast<std::size_t>(image.width()) : 0) {}

  // Faces in any order (the near-to-far z-buffered render, painter.hpp): `owner` (width × height,
  // −1 where nothing is drawn yet) keeps which face each pixel's depth came from, so that an
  // exact tie goes to the face first in the scene, as in scene order; `tiles` lets admit() reject
  // a face that cannot pass a depth test before its set-up. Untraced only.
  ZBufferCanvas(Image<P>& image, std::span<double> depth, std::span<int> owner, DepthTiles& tiles)
      : image_(image), depth_(depth), band_{0, image.height()}, owner_(owner), tiles_(&tiles) {}

  ZBufferCanvas(const ZBufferCanvas&) = delete;  // depth_ may point into own_
  ZBufferCanvas& operator=(const ZBufferCanvas&) = delete;

  int width() const { return image_.width(); }
  int height() const { return image_.height(); }
  RowBand rows() const { return band_; }

  // Sets up the depth plane of the next triangle from its vertices (pixels, snapped to `grid`
  // as the fill will snap them) and their depths.
  void begin_triangle(std::span<const Vec2> v, std::span<const double> d,
                      const SubpixelGrid& grid) {
    plane_ = DepthPlane{};
    plane_.d0 = d[0];
    // The fill skips such a triangle before writing anything (SkipReason::out_of_range).
    for (int i = 0; i < 3; ++i)
      if (!SubpixelGrid::representable(v[i])) return;
    const std::array<Vec2, 3> p{grid.to_pixels(grid.snap(v[0])), grid.to_pixels(grid.snap(v[1])),
                                grid.to_pixels(grid.snap(v[2]))};
    plane_ = DepthPlane::through(p, d);
  }

  // Called after begin_triangle with face `face` and its vertices (before snapping): false when
  // no pixel it can own (face_pixels, canvas.hpp) can pass a depth test, so that the face need not
  // be set up. In scene order (no tiles) every face is admitted.
  bool admit(int face, std::span<const Vec2> vertices) {
    face_ = face;
    if (!tiles_) return true;
    const PixelBox box = face_pixels(vertices, width(), band_);
    // Strictly farther than every depth stored there: it loses even the ties it would win.
    return box.empty() || !tiles_->all_nearer(box.x0, box.y0, box.x1, box.y1,
                                              plane_.lower_bound(box.x0, box.y0, box.x1, box.y1));
  }

  double depth_at(int x, int y) const { return plane_.at(x, y); }
  double stored(int x, int y) const {
    return depth_[static_cast<std::size_t>(y) * image_.width() + x];
  }

  void fill_span(int y, int x_begin, int x_end, Color c) {
    const P p = P::from(c);
    for (int x = x_begin; x < x_end; ++x) write(x, y, p);
  }
  void set(int x, int y, Color c) { write(x, y, P::from(c)); }

  DepthTest depth_test(int x) const { return log_[x]; }

 private:
  void write(int x, int y, const P& p) {
    const double d = depth_at(x, y);
    const std::size_t i = static_cast<std::size_t>(y) * image_.width() + x;
    double& z = depth_[i];
    bool passed = d < z;
    if (!log_.empty()) log_[x] = DepthTest{passed, d, z};
    if (tiles_) {
      // Faces in any order: an exact tie goes to the face first in the scene, which scene order
      // draws first and the strict test then keeps (owner −1: nothing drawn, no tie to win).
      passed = passed || (d == z && face_ < owner_[i]);
      if (passed) owner_[i] = face_, tiles_->wrote(x, y, z, d);
    }
    if (passed) {
      z = d;
      image_.row(y)[x] = p;
    }
  }

  Image<P>& image_;
  std::vector<double> own_;  // the depth buffer, unless the caller keeps it
  std::span<double> depth_;
  RowBand band_;
  std::vector<DepthTest> log_;
  DepthPlane plane_;
  std::span<int> owner_;
  DepthTiles* tiles_ = nullptr;
  int face_ = 0;
};

}  // namespace scantrace
