#include "stress/reference_window.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "reference/exact_reference.hpp"

namespace scantrace::stress {

ReferenceWindow::ReferenceWindow(int width, int height, std::span<const Vec2> points,
                                 std::span<const Color> colors, FillRule rule) {
  const reference::Polygon poly(points, reference::kExactBits);
  const bool interpolate = points.size() == 3 && colors.size() == 3;
  const auto clamp = [](std::int64_t v, int lo, int hi) {
    return static_cast<int>(std::clamp<std::int64_t>(v, lo, hi));
  };
  x0_ = clamp(poly.min_px(), 0, width);
  x1_ = clamp(poly.max_px() + 1, 0, width);
  y0_ = clamp(poly.min_py(), 0, height);
  y1_ = clamp(poly.max_py() + 1, 0, height);
  if (x0_ >= x1_ || y0_ >= y1_) {
    x0_ = x1_ = y0_ = y1_ = 0;
    return;
  }
  runs_.resize(static_cast<std::size_t>(y1_ - y0_));
  for (int y = y0_; y < y1_; ++y) {
    Run& run = runs_[static_cast<std::size_t>(y - y0_)];
    run.first_color = static_cast<long long>(colors_.size());
    bool open = false, closed = false;
    for (int x = x0_; x < x1_; ++x) {
      if (!poly.covers(x, y, rule)) {
        if (open) closed = true;
        continue;
      }
      // A second run on one row would mean a non-convex coverage: impossible for the half-plane
      // tests of a convex polygon, so a broken invariant of the reference itself.
      if (closed) throw std::logic_error("reference: row " + std::to_string(y) + " is not one run");
      if (!open) run.begin = x;
      open = true;
      run.end = x + 1;
      ++count_;
      if (interpolate) {
        const std::array<double, 3> w = poly.barycentric(x, y);
        colors_.push_back(colors[0] * w[0] + colors[1] * w[1] + colors[2] * w[2]);
      }
    }
  }
}

}  // namespace scantrace::stress
