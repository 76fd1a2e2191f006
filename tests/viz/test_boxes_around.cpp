// viz::boxes_around, the candidate boxes of a label around its marker (the step frames' vertex and
// active-point labels): the eight directions ordered by how well they point to `preferred` (ties
// in the order top-left, top, top-right, right, bottom-right, bottom, bottom-left, left), ring
// after ring. Checked against the definition written out here, for random markers, sizes and
// preferences, axis-aligned and zero preferences (ties) among them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "viz/label_placement.hpp"

using namespace scantrace::viz;

namespace {

std::vector<Rect> by_definition(Point2d p, int radius, Size size, Point2d preferred, int gap, int step,
                                int rings) {
  std::vector<Point> directions{{-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}};
  const auto cosine = [&](Point d) {
    return (d.x * preferred.x + d.y * preferred.y) / std::sqrt(double(d.x * d.x + d.y * d.y));
  };
  // Insertion sort: stable, the best first.
  for (std::size_t i = 1; i < directions.size(); ++i)
    for (std::size_t j = i; j > 0 && cosine(directions[j]) > cosine(directions[j - 1]); --j)
      std::swap(directions[j], directions[j - 1]);
  std::vector<Rect> out;
  for (int ring = 0; ring < rings; ++ring)
    for (const Point d : directions) {
      const double reach = radius + gap + ring * step;
      const double x = d.x == 0 ? p.x - size.width / 2.0 : d.x < 0 ? p.x - reach - size.width : p.x + reach;
      const double y = d.y == 0 ? p.y - size.height / 2.0 : d.y < 0 ? p.y - reach - size.height : p.y + reach;
      out.push_back({static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)), size.width, size.height});
    }
  return out;
}

}  // namespace

TEST_CASE("label candidates around a marker: directions best first, ring after ring") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-50, 700), unit(-1, 1);
  const Point2d fixed[] = {{0, 0}, {1, 0}, {0, -1}, {-1, 0}, {1, 1}, {-0.5, 0.5}, {0, 3}};
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const Point2d p{coord(rng), coord(rng)};
    const Point2d preferred = i < 7 ? fixed[i] : Point2d{unit(rng), i % 5 == 0 ? 0.0 : unit(rng)};
    const Size size{static_cast<int>(rng() % 120) + 1, static_cast<int>(rng() % 30) + 1};
    const int radius = static_cast<int>(rng() % 12), gap = static_cast<int>(rng() % 5), step = size.height / 2;
    const int rings = static_cast<int>(rng() % 8);
    INFO("preferred (" << preferred.x << ", " << preferred.y << ")");
    const std::vector<Rect> got = boxes_around(p, radius, size, preferred, gap, step, rings);
    const std::vector<Rect> want = by_definition(p, radius, size, preferred, gap, step, rings);
    REQUIRE(got.size() == want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      REQUIRE(got[k].x == want[k].x);
      REQUIRE(got[k].y == want[k].y);
      REQUIRE(got[k].width == want[k].width);
      REQUIRE(got[k].height == want[k].height);
    }
    ++checked;
  }
  CHECK(checked == 3000);
}
