// The z-buffer render (FillOptions::visibility = zbuffer) shows, at every pixel, the face whose
// depth there is the smallest among the faces covering the pixel (design.md, docs/models.md).
// The reference is written here, independently of the fill and of src/depth_plane.hpp: coverage
// from the exact reference's half-plane test, depth from its exact barycentric weights of the
// pixel centre on the snapped vertices, the nearest chosen by a plain minimum.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "random.hpp"
#include "reference/exact_reference.hpp"
#include "src/painter.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::Scene;
using scantrace::Vec2;
using sttest::Rng;

// Faces of their own vertices, one colour per face (flat: the face's colour), random depths per
// vertex so that faces pass through each other.
Scene random_scene(Rng& r, int faces, int w, int h) {
  Scene s;
  s.width = w, s.height = h;
  s.background = {1, 1, 1};
  for (int f = 0; f < faces; ++f) {
    // Face colours on a 0.05 lattice, distinct per face: the colour names the face.
    const Color c{0.05 * (f % 20), 0.05 * ((f / 20) % 20), 0.05 * (f / 400)};
    const Vec2 centre = r.point(0, w, 0, h);
    const double size = r.uniform(4, 30);
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back({centre.x + r.uniform(-size, size), centre.y + r.uniform(-size, size)});
      s.vcolors.push_back(c);
      s.depth.push_back(r.uniform(0, 10));
    }
    s.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  return s;
}

struct Nearest {
  int face = -1;      // -1: no face covers the pixel
  bool clear = true;  // the nearest is nearer than the next by a clear margin
};

// The per-pixel nearest face, by brute force over every face.
std::vector<Nearest> nearest_faces(const Scene& s, const FillOptions& opt) {
  std::vector<Nearest> out(static_cast<std::size_t>(s.width) * s.height);
  std::vector<double> best(out.size(), std::numeric_limits<double>::infinity()),
      second(out.size(), std::numeric_limits<double>::infinity());
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const Vec2 p[3] = {s.vertices[s.faces[f][0]], s.vertices[s.faces[f][1]],
                       s.vertices[s.faces[f][2]]};
    const scantrace::reference::Polygon tri(p, opt.subpixel_bits);
    if (tri.degenerate()) continue;
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        if (!tri.covers(x, y, opt.fill_rule)) continue;
        const auto wgt = tri.barycentric(x, y);
        double depth = 0;
        for (int k = 0; k < 3; ++k) depth += wgt[k] * s.depth[s.faces[f][k]];
        const std::size_t i = static_cast<std::size_t>(y) * s.width + x;
        if (depth < best[i]) {
          second[i] = best[i];
          best[i] = depth;
          out[i].face = static_cast<int>(f);
        } else if (depth < second[i]) {
          second[i] = depth;
        }
      }
  }
  // Two depths closer than this are a tie for rounding to decide (the render's plane and these
  // weights round differently): such pixels are not judged.
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i].clear = out[i].face < 0 || second[i] - best[i] > 1e-9;
  return out;
}

bool same_colour(const scantrace::Rgb32f& p, const Color& c) {
  return std::abs(p.r - c.r) < 1e-6 && std::abs(p.g - c.g) < 1e-6 && std::abs(p.b - c.b) < 1e-6;
}

}  // namespace

TEST_CASE("the z-buffer render shows the nearest face at every pixel", "[zbuffer][render]") {
  Rng rng(0x20f4);
  long long judged = 0, painter_wrong = 0;
  for (int scene_index = 0; scene_index < 12; ++scene_index) {
    const Scene s = random_scene(rng, 8 + 4 * scene_index, 64, 48);
    for (const auto rule : {scantrace::FillRule::top_left, scantrace::FillRule::closed}) {
      FillOptions opt;
      opt.shading = scantrace::Shading::flat;
      opt.fill_rule = rule;
      opt.visibility = scantrace::Visibility::zbuffer;
      const auto image = scantrace::render(s, opt);
      FillOptions painter_opt = opt;
      painter_opt.visibility = scantrace::Visibility::painter;
      const auto painted = scantrace::render(s, painter_opt);
      const std::vector<Nearest> nearest = nearest_faces(s, opt);
      int wrong = 0;
      for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
          const Nearest& n = nearest[static_cast<std::size_t>(y) * s.width + x];
          if (!n.clear) continue;
          const Color expected = n.face < 0 ? s.background : s.vcolors[3 * n.face];
          ++judged;
          if (!same_colour(image(x, y), expected)) {
            if (++wrong <= 3)
              UNSCOPED_INFO("scene " << scene_index << ", pixel (" << x << ", " << y
                                     << "): nearest is face " << n.face);
          }
          painter_wrong += !same_colour(painted(x, y), expected);
        }
      CHECK(wrong == 0);
    }
  }
  CHECK(judged > 50000);
  // The reference tells the rules apart: the painter's order (by mean depth) misses the nearest
  // face where faces pass through each other.
  CHECK(painter_wrong > 100);
}
