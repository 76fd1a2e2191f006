// The course's real scene (../shared/data/hw1_2024.json, when present) renders, and sampled
// pixels equal what the independent reference says: the last face in painter's order (computed
// here) whose exact coverage test holds, in its flat mean or barycentric colour.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <numeric>
#include <random>

#include "core/reference_raster.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"

using namespace scantrace;

namespace {

const std::filesystem::path kCourseScene = SCANTRACE_SHARED_DATA "/hw1_2024.json";

struct Expected {
  bool covered = false;
  Color color;
};

class ReferenceScene {
 public:
  explicit ReferenceScene(const Scene& s) : scene_(s) {
    std::vector<double> depth(s.faces.size());
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      const auto& v = s.faces[f];
      depth[f] = (s.depth[v[0]] + s.depth[v[1]] + s.depth[v[2]]) / 3.0;
      const std::array<Vec2, 3> pts{s.vertices[v[0]], s.vertices[v[1]], s.vertices[v[2]]};
      polygons_.emplace_back(pts, kDefaultSubpixelBits);
    }
    order_.resize(s.faces.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](int a, int b) { return depth[a] > depth[b]; });
  }

  Expected at(int x, int y, Shading shading) const {
    Expected e;
    for (int f : order_) {
      const sttest::RefPolygon& p = polygons_[f];
      if (p.degenerate() || !p.covers(x, y, sttest::RefRule::top_left)) continue;
      const auto& v = scene_.faces[f];
      const Color c0 = scene_.vcolors[v[0]], c1 = scene_.vcolors[v[1]], c2 = scene_.vcolors[v[2]];
      e.covered = true;
      if (shading == Shading::flat) {
        e.color = (c0 + c1 + c2) * (1.0 / 3.0);
      } else {
        const auto w = p.barycentric(x, y);
        e.color = c0 * w[0] + c1 * w[1] + c2 * w[2];
      }
    }
    return e;
  }

 private:
  const Scene& scene_;
  std::vector<sttest::RefPolygon> polygons_;
  std::vector<int> order_;
};

}  // namespace

TEST_CASE("the course scene renders, and sampled pixels match the reference", "[course]") {
  if (!std::filesystem::exists(kCourseScene)) {
    WARN("skipped: " << kCourseScene << " is not present");
    return;
  }
  const Scene scene = load_scene(kCourseScene);
  REQUIRE(scene.faces.size() == 10000);
  REQUIRE(scene.width == 512);
  const ReferenceScene reference(scene);

  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int> coord(0, 511);
  std::vector<std::pair<int, int>> samples;
  for (int i = 0; i < 600; ++i) samples.emplace_back(coord(rng), coord(rng));
  // Dense samples across the figure too, where faces are small and shared edges are everywhere.
  for (int y = 150; y < 350; y += 7)
    for (int x = 180; x < 330; x += 5) samples.emplace_back(x, y);

  for (Shading shading : {Shading::flat, Shading::gouraud}) {
    RenderStats stats;
    const RgbImage image = render(scene, FillOptions{.shading = shading}, &stats);
    // Every face is counted once: drawn, skipped, or (near to far) hidden.
    CHECK(stats.triangles_filled + stats.triangles_skipped + stats.triangles_hidden == 10000);
    int covered = 0;
    for (auto [x, y] : samples) {
      CAPTURE(x, y, to_string(shading));
      const Expected e = reference.at(x, y, shading);
      const Color got = image(x, y).color();
      const Color want = e.covered ? e.color : Color{1, 1, 1};
      covered += e.covered;
      CHECK(got.r == Approx(want.r).margin(1e-4));
      CHECK(got.g == Approx(want.g).margin(1e-4));
      CHECK(got.b == Approx(want.b).margin(1e-4));
    }
    CHECK(covered > 300);  // the samples do hit the figure, not only the background
  }
}
