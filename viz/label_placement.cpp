#include "viz/label_placement.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace scantrace::viz {

void Placement::mark(PlacedKind kind, const Rect& box, std::string text) {
  const Rect clipped = box & area_;
  if (!clipped.empty()) boxes_.push_back({kind, clipped, std::move(text), layer_});
}

bool Placement::free(const Rect& box) const {
  if ((box & area_) != box) return false;
  return std::none_of(boxes_.begin(), boxes_.end(),
                      [&](const PlacedBox& b) { return !(b.box & box).empty(); });
}

std::optional<Rect> Placement::place(PlacedKind kind, std::span<const Rect> candidates,
                                     std::string text) {
  for (Rect c : candidates) {
    // A box near the view's edge slides inside rather than being given up: it may then cover its
    // own marker, which free() refuses like any other.
    c.x = std::clamp(c.x, area_.x, std::max(area_.x, area_.x + area_.width - c.width));
    c.y = std::clamp(c.y, area_.y, std::max(area_.y, area_.y + area_.height - c.height));
    if (free(c)) {
      boxes_.push_back({kind, c, std::move(text), layer_});
      return c;
    }
  }
  return std::nullopt;
}

std::vector<Rect> boxes_around(Point2d p, int radius, Size size, Point2d preferred, int gap,
                               int step, int rings) {
  // Each direction's score computed once, then sorted by it (stable: ties keep this order). The
  // comparator computed two with std::hypot at each of its ~20 comparisons: with the vector's
  // growth, 0.4 ms of the explorer's step frame in Chromium for its dozen labels (the module's
  // libm; docs/performance.md, "Ninth round").
  struct Scored {
    Point d;
    double score;
  };
  std::array<Scored, 8> directions{};
  const std::array<Point, 8> order{Point{-1, -1}, {0, -1}, {1, -1}, {1, 0},
                                   {1, 1},        {0, 1},  {-1, 1}, {-1, 0}};
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Point d = order[i];
    directions[i] = {d, (d.x * preferred.x + d.y * preferred.y) / std::hypot(double(d.x), double(d.y))};
  }
  std::stable_sort(directions.begin(), directions.end(),
                   [](const Scored& a, const Scored& b) { return a.score > b.score; });
  std::vector<Rect> out;
  out.reserve(static_cast<std::size_t>(std::max(rings, 0)) * directions.size());
  for (int ring = 0; ring < rings; ++ring) {
    const double reach = radius + gap + ring * step;
    for (const Scored& scored : directions) {
      const Point d = scored.d;
      const double x = d.x < 0   ? p.x - reach - size.width
                       : d.x > 0 ? p.x + reach
                                 : p.x - size.width / 2.0;
      const double y = d.y < 0   ? p.y - reach - size.height
                       : d.y > 0 ? p.y + reach
                                 : p.y - size.height / 2.0;
      out.emplace_back(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)), size.width,
                       size.height);
    }
  }
  return out;
}

Rect marker_box(Point2d p, int radius) {
  const int cx = static_cast<int>(std::lround(p.x)), cy = static_cast<int>(std::lround(p.y));
  const int r = radius + 1;
  return {cx - r, cy - r, 2 * r + 1, 2 * r + 1};
}

}  // namespace scantrace::viz
