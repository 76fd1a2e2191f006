#pragma once
// Renderers written in the test, independently of the fill: every face's coverage is the exact
// reference's (src/exact_reference.hpp) on the fill's subpixel grid, its colour the barycentric
// interpolation there, and the painter's order a sort of their own. Each Mistake reproduces one
// thing real submissions of the course get wrong, so the grader's report can be checked against
// what the test knows it did.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "grade/image_input.hpp"
#include "reference/exact_reference.hpp"
#include "src/fill_options.hpp"
#include "src/image.hpp"
#include "src/scene.hpp"

namespace gradetest {

using namespace scantrace;

// The mistakes are named by the catalogue's ids (python/scantrace/grade/mistakes.json, the
// grader's causes); the three that are no cause of the catalogue are variants only the test needs.
enum class Mistake {
  none,
  closed_rule,               // both span ends inclusive, the last row too
  bottom_row_dropped,        // range(ymin, ymax): the last row of every face is missing
  span_one_too_wide,         // (test only) one extra pixel right of every span
  span_too_wide,             // one extra pixel left of every span and one right of it
  shift_right,               // (test only) every face drawn one pixel to the right of its place
  order_reversed,            // painter's order reversed: nearest first
  horizontal_edge_skipped,   // faces with a horizontal edge are not drawn
  degenerate_drawn,          // zero-area faces drawn as the pixels their segment crosses
  flat_colour_not_mean,      // flat colour = the first vertex's colour
  gouraud_weights_permuted,  // Gouraud with vertices 0 and 1's colours swapped
  truncate_8bit,             // (test only) 8-bit output truncated instead of rounded
};

// The catalogue id of a mistake; nullptr for the test's own variants.
inline const char* catalogue_id(Mistake m) {
  switch (m) {
    case Mistake::closed_rule: return "closed_rule";
    case Mistake::bottom_row_dropped: return "bottom_row_dropped";
    case Mistake::span_too_wide: return "span_too_wide";
    case Mistake::order_reversed: return "order_reversed";
    case Mistake::horizontal_edge_skipped: return "horizontal_edge_skipped";
    case Mistake::degenerate_drawn: return "degenerate_drawn";
    case Mistake::flat_colour_not_mean: return "flat_colour_not_mean";
    case Mistake::gouraud_weights_permuted: return "gouraud_weights_permuted";
    default: return nullptr;
  }
}


// The fill options of the reference a test compares with: the shading, the rest by default.
inline FillOptions opts(Shading shading) {
  FillOptions o;
  o.shading = shading;
  return o;
}

inline std::array<Vec2, 3> points(const Scene& s, int f) {
  return {s.vertices[s.faces[f][0]], s.vertices[s.faces[f][1]], s.vertices[s.faces[f][2]]};
}
inline std::array<Color, 3> colours(const Scene& s, int f) {
  return {s.vcolors[s.faces[f][0]], s.vcolors[s.faces[f][1]], s.vcolors[s.faces[f][2]]};
}
inline double mean_depth(const Scene& s, int f) {
  return (s.depth[s.faces[f][0]] + s.depth[s.faces[f][1]] + s.depth[s.faces[f][2]]) / 3.0;
}
inline bool has_horizontal_edge(const Scene& s, int f, int bits) {
  const auto p = points(s, f);
  for (int i = 0; i < 3; ++i)
    if (reference::snap(p[i], bits).y == reference::snap(p[(i + 1) % 3], bits).y) return true;
  return false;
}

// Painter's order by the test's own stable sort (farthest first; `reverse`: nearest first).
inline std::vector<int> order(const Scene& s, bool reverse) {
  std::vector<int> o(s.faces.size());
  std::iota(o.begin(), o.end(), 0);
  std::stable_sort(o.begin(), o.end(), [&](int a, int b) {
    return reverse ? mean_depth(s, a) < mean_depth(s, b) : mean_depth(s, a) > mean_depth(s, b);
  });
  return o;
}

// The float canvas the test's renderer draws.
// `painted` (when given) receives the face that wrote each pixel last (-1: none).
// Several mistakes at once: `mistakes` (a span too wide and the bottom row dropped, say).
inline RgbImage render_wrong(const Scene& s, Shading shading, std::vector<Mistake> mistakes,
                             int bits = 8, std::vector<int>* painted = nullptr) {
  const auto has = [&](Mistake m) {
    return std::find(mistakes.begin(), mistakes.end(), m) != mistakes.end();
  };
  RgbImage img(s.width, s.height, Rgb32f::from(s.background));
  if (painted) painted->assign(static_cast<std::size_t>(s.width) * s.height, -1);
  const auto mark = [&](long long x, long long y, int f) {
    if (painted) (*painted)[static_cast<std::size_t>(y) * s.width + x] = f;
  };
  const FillRule rule = has(Mistake::closed_rule) ? FillRule::closed : FillRule::top_left;
  for (int f : order(s, has(Mistake::order_reversed))) {
    const auto p = points(s, f);
    auto c = colours(s, f);
    if (has(Mistake::horizontal_edge_skipped) && has_horizontal_edge(s, f, bits)) continue;
    if (has(Mistake::gouraud_weights_permuted)) std::swap(c[0], c[1]);
    const reference::Polygon poly(p, bits);
    if (poly.degenerate()) {
      if (!has(Mistake::degenerate_drawn)) continue;
      // The pixels whose centre is within half a pixel of the segment, in the flat colour.
      const Color flat = reference::mean_color(c);
      for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
          double best = 1e9;
          for (int i = 0; i < 3; ++i) {
            const Vec2 a = p[i], b = p[(i + 1) % 3];
            const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
            const double t =
                l2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / l2, 0.0, 1.0) : 0;
            best = std::min(best, std::hypot(a.x + t * dx - x, a.y + t * dy - y));
          }
          if (best <= 0.5) img(x, y) = Rgb32f::from(flat), mark(x, y, f);
        }
      continue;
    }
    const long long x0 = std::max<long long>(poly.min_px(), 0),
                    x1 = std::min<long long>(poly.max_px(), s.width - 1);
    const long long y0 = std::max<long long>(poly.min_py(), 0),
                    y1 = std::min<long long>(poly.max_py(), s.height - 1);
    // The face's last covered row (under the true rule), for bottom_row_dropped.
    long long last_row = -1;
    for (long long y = y0; y <= y1; ++y)
      for (long long x = x0; x <= x1; ++x)
        if (poly.covers(x, y, FillRule::top_left)) last_row = y;
    for (long long y = y0; y <= y1; ++y) {
      if (has(Mistake::bottom_row_dropped) && y == last_row) continue;
      long long row_first = -1, row_last = -1;
      for (long long x = x0; x <= x1; ++x) {
        if (!poly.covers(x, y, rule)) continue;
        if (row_first < 0) row_first = x;
        row_last = x;
        const auto w = poly.barycentric(x, y);
        Color col = shading == Shading::flat || has(Mistake::flat_colour_not_mean)
                        ? (has(Mistake::flat_colour_not_mean) ? c[0] : reference::mean_color(c))
                        : c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
        const long long to = has(Mistake::shift_right) ? x + 1 : x;
        if (to >= s.width) continue;
        img(static_cast<int>(to), static_cast<int>(y)) = Rgb32f::from(col);
        mark(to, y, f);
      }
      const auto extra = [&](long long x) {
        if (x < 0 || x >= s.width) return;
        const auto w = poly.barycentric(x, y);
        const Color col = shading == Shading::flat ? reference::mean_color(c)
                                                   : c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
        img(static_cast<int>(x), static_cast<int>(y)) = Rgb32f::from(col);
        mark(x, y, f);
      };
      if ((has(Mistake::span_one_too_wide) || has(Mistake::span_too_wide)) && row_last >= 0)
        extra(row_last + 1);
      if (has(Mistake::span_too_wide) && row_first >= 0) extra(row_first - 1);
    }
  }
  return img;
}

inline RgbImage render_wrong(const Scene& s, Shading shading, Mistake m, int bits = 8,
                             std::vector<int>* painted = nullptr) {
  return render_wrong(s, shading, std::vector<Mistake>{m}, bits, painted);
}

// As an 8-bit image file would hold it (round, or truncate for truncate_8bit).
inline grade::SubmittedImage as_8bit(const RgbImage& img, bool truncate = false) {
  grade::SubmittedImage out;
  out.format = "png";
  out.eight_bit = true;
  out.name = "test.png";
  out.pixels = RgbImage(img.width(), img.height());
  const auto q = [truncate](float v) {
    const double s = 255.0 * std::clamp(static_cast<double>(v), 0.0, 1.0);
    return static_cast<float>((truncate ? std::floor(s + 1e-9) : std::floor(s + 0.5)) / 255.0);
  };
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const Rgb32f p = img(x, y);
      out.pixels(x, y) = {q(p.r), q(p.g), q(p.b)};
    }
  return out;
}

// As a float .npy array (values as they are).
inline grade::SubmittedImage as_npy(const RgbImage& img) {
  grade::SubmittedImage out;
  out.format = "npy";
  out.eight_bit = false;
  out.name = "test.npy";
  out.pixels = img;
  return out;
}

// Pixels where two images differ by more than `tol` in some channel.
inline long long count_differing(const RgbImage& a, const RgbImage& b, double tol = 1.0 / 255) {
  long long n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgb32f p = a(x, y), q = b(x, y);
      n += std::max({std::fabs(p.r - q.r), std::fabs(p.g - q.g), std::fabs(p.b - q.b)}) > tol;
    }
  return n;
}

// A generated scene of 20×20 tiles on a 200×160 canvas: each tile is split into two triangles
// sharing its diagonal (integer vertices, so pixel centres lie on the edges), tiles of random
// colours, a few overlapping larger triangles at distinct depths, a sliver, and zero-area faces.
inline Scene generated_scene(unsigned seed = 1) {
  Scene s;
  s.width = 200, s.height = 160;
  std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
  const auto rnd = [&]() {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state % 1000000) / 1000000.0;
  };
  const auto add = [&](Vec2 a, Vec2 b, Vec2 c, double depth, bool random_colours) {
    const int base = static_cast<int>(s.vertices.size());
    for (const Vec2 v : {a, b, c}) {
      s.vertices.push_back(v);
      s.vcolors.push_back(random_colours ? Color{rnd(), rnd(), rnd()} : Color{0.2, 0.4, 0.8});
      s.depth.push_back(depth + rnd() * 0.01);
    }
    s.faces.push_back({base, base + 1, base + 2});
  };
  for (int ty = 0; ty < 4; ++ty)
    for (int tx = 0; tx < 5; ++tx) {
      const double x = 10 + 36 * tx, y = 10 + 36 * ty;
      // Far behind everything (depth 100+), tiles a 30×30 square exactly.
      add({x, y}, {x + 30, y}, {x, y + 30}, 100 + tx + 5 * ty, true);
      add({x + 30, y}, {x + 30, y + 30}, {x, y + 30}, 100 + tx + 5 * ty, true);
    }
  // Overlapping triangles in front, with non-integer vertices, at distinct depths.
  add({20.3, 30.6}, {120.7, 50.2}, {60.1, 140.9}, 50, true);
  add({80.4, 20.2}, {190.6, 90.3}, {100.2, 150.7}, 40, true);
  add({5.5, 100.5}, {90.25, 70.75}, {70.5, 155.5}, 30, true);
  // A sliver and two zero-area faces.
  add({150, 20}, {190, 24}, {150, 21}, 20, true);
  add({30, 20}, {60, 50}, {90, 80}, 10, true);
  add({120, 130}, {180, 130}, {150, 130}, 10, true);
  return s;
}

}  // namespace gradetest
