#include "grade/global_mistakes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

#include <spdlog/fmt/fmt.h>

#include "grade/mistake_catalogue.hpp"

namespace scantrace::grade {
namespace {

double max_diff(Rgb32f a, Rgb32f b) {
  return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

// Three decimals at most, without trailing zeros: 0.99 as 0.99, 1 as 1, 252/255 as 0.988.
std::string component(double v) {
  std::string s = fmt::format("{:.3f}", v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

// fmt, not "(" + std::string: GCC 12 warns falsely (-Wrestrict, its bug 105651) on a literal
// prepended to a temporary string.
std::string rgb(Color c) {
  return fmt::format("({}, {}, {})", component(c.r), component(c.g), component(c.b));
}

// A way the image may have been produced wrongly, as the pixel of the image that lands on the
// scene's pixel (x, y) (false when the image has none there).
struct Transform {
  const char* kind;
  const char* text;
  std::function<bool(const RgbImage&, int, int, Rgb32f&)> sample;
};

bool inside(const RgbImage& m, int x, int y) {
  return x >= 0 && y >= 0 && x < m.width() && y < m.height();
}

// The image's pixel (x, y) with red and blue swapped (false when it has none there).
bool swapped(const RgbImage& m, int x, int y, Rgb32f& out) {
  if (!inside(m, x, y)) return false;
  const Rgb32f p = m(x, y);
  out = {p.b, p.g, p.r};
  return true;
}

// The transforms, the identity first and the transposition second (transform_applies() and
// find_transform() know them by position).
const std::vector<Transform>& transforms() {
  static const std::vector<Transform> all{
      {"identity", "",
       [](const RgbImage& m, int x, int y, Rgb32f& out) {
         return inside(m, x, y) ? (out = m(x, y), true) : false;
       }},
      {"transposed", "the image is transposed (x and y swapped: img[x][y] instead of img[y][x])",
       [](const RgbImage& m, int x, int y, Rgb32f& out) {
         return inside(m, y, x) ? (out = m(y, x), true) : false;
       }},
      {"flipped_vertically", "the image is flipped vertically (row 0 at the bottom)",
       [](const RgbImage& m, int x, int y, Rgb32f& out) {
         return inside(m, x, m.height() - 1 - y) ? (out = m(x, m.height() - 1 - y), true) : false;
       }},
      {"flipped_horizontally", "the image is flipped horizontally",
       [](const RgbImage& m, int x, int y, Rgb32f& out) {
         return inside(m, m.width() - 1 - x, y) ? (out = m(m.width() - 1 - x, y), true) : false;
       }},
      {"bgr", "red and blue are swapped (BGR instead of RGB)",
       [](const RgbImage& m, int x, int y, Rgb32f& out) { return swapped(m, x, y, out); }},
      // Both at once (img[x][y] and a BGR canvas): neither alone makes the faces match, so
      // each must be tried with the other. Named as the two mistakes it is.
      {"transposed+bgr", "",
       [](const RgbImage& m, int x, int y, Rgb32f& out) { return swapped(m, y, x, out); }},
  };
  return all;
}

constexpr std::size_t kIdentity = 0, kTransposed = 1, kBgr = 4, kTransposedBgr = 5;

bool transposes(std::size_t t) { return t == kTransposed || t == kTransposedBgr; }

// Whether transform t can explain an image of iw x ih on a canvas of W x H: the transposition
// only an image of the swapped size, the others only one of the canvas's size (the identity
// always: it is the image as it is, cropped or padded).
bool transform_applies(std::size_t t, int iw, int ih, int W, int H) {
  if (transposes(t)) return iw == H && ih == W;
  return t == kIdentity || (iw == W && ih == H);
}

}  // namespace

Scale255 find_scale_255(RgbImage& src, Color scene_background, double tol, bool undo) {
  const Rgb32f background = Rgb32f::from(scene_background);
  const Rgb32f background_255{255 * background.r, 255 * background.g, 255 * background.b};
  Scale255 s;
  std::int64_t painted = 0, as_background = 0, as_background_255 = 0;
  for (const Rgb32f p : src.pixels()) {
    const float m = std::max({p.r, p.g, p.b});
    s.top = std::max(s.top, m);
    // Black is black on both scales: it says nothing about the scale.
    if (max_diff(p, background) > tol && m > 0) ++painted;
    s.above += m > 1.0f;
    as_background += p == background;
    as_background_255 += p == background_255;
  }
  s.scaled = s.above > 0 &&
             static_cast<double>(s.above) >
                 whole_image_tolerance("scaled_share") * static_cast<double>(painted) &&
             s.top <= 255 + tol;
  if (!s.scaled || !undo) return s;
  // The painted pixels only: a fill writing colour * 255 on a canvas of the background (the
  // grader's blank canvas of ones) leaves that canvas as it was, and divided by 255 it would be
  // black; a canvas of its own at 255 x the background is divided with the rest.
  const bool keep_background = as_background > as_background_255;
  for (int y = 0; y < src.height(); ++y)
    for (Rgb32f* p = src.row(y); p != src.row(y) + src.width(); ++p)
      if (!(keep_background && *p == background))
        *p = {p->r / 255.0f, p->g / 255.0f, p->b / 255.0f};
  return s;
}

namespace {

// Colours in [0, 255] (find_scale_255), named when found and undone in `src` when `undo`. One
// bright pixel, or a Gouraud colour extrapolated a little beyond a vertex's, is not a scale: the
// pixels above 1 are then a note saying what they are, and are compared as they are (else one
// pixel at 1.01 would make the whole image "scaled_255" and every pixel differ).
void find_scaled_255(const Scene& scene, const SubmittedImage& in, double tol, bool undo,
                     RgbImage& src, std::vector<GlobalMistake>& found,
                     std::vector<std::string>& notes) {
  if (in.format != "npy" || in.eight_bit) return;
  const Scale255 s = find_scale_255(src, scene.background, tol, undo);
  if (s.above == 0) return;
  if (!s.scaled) {
    notes.push_back(fmt::format("{} pixel{} above 1.0 (largest {:.4g}): colours extrapolated "
                                "outside the triangle?",
                                s.above, s.above == 1 ? "" : "s", s.top));
    return;
  }
  found.push_back({"scaled_255",
                   fmt::format("colours are scaled to [0, 255] (the largest value is {:.4g}), "
                               "not [0, 1]",
                               s.top),
                   undo});
}

// The transform that explains the image, kIdentity when none does clearly. Each is scored on the
// pixels where the reference shows a face (a wrong background would otherwise weigh on all of
// them alike); one must explain clearly more than the image as it is, and a good share of the
// faces' pixels. Reports it, and a canvas of the wrong size that it does not explain.
std::size_t find_transform(const Scene& scene, const RgbImage& reference, const FaceIdImage& ids,
                           const RgbImage& src, double tol, bool undo,
                           std::vector<GlobalMistake>& found) {
  const int W = scene.width, H = scene.height, iw = src.width(), ih = src.height();
  std::int64_t face_pixels = 0;
  std::vector<std::int64_t> score(transforms().size(), 0);
  for (std::size_t t = 0; t < transforms().size(); ++t) {
    if (!transform_applies(t, iw, ih, W, H)) continue;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        if (ids.at(x, y) < 0) continue;
        if (t == kIdentity) ++face_pixels;
        Rgb32f p;
        if (transforms()[t].sample(src, x, y, p) && max_diff(p, reference(x, y)) <= tol) ++score[t];
      }
  }
  std::size_t best = kIdentity;
  for (std::size_t t = 1; t < transforms().size(); ++t)
    if (score[t] > score[best]) best = t;
  // The thresholds are the catalogue's, shared with the Python grader's diagnose_image.
  const double gain = whole_image_tolerance("transform_gain"),
               share = whole_image_tolerance("transform_share");
  const auto d = [](std::int64_t n) { return static_cast<double>(n); };
  if (best != kIdentity && (d(score[best]) < gain * d(score[kIdentity]) ||
                            d(score[best]) < share * d(face_pixels)))
    best = kIdentity;
  const std::vector<std::size_t> named =
      best == kTransposedBgr ? std::vector<std::size_t>{kTransposed, kBgr}
      : best != kIdentity    ? std::vector<std::size_t>{best}
                             : std::vector<std::size_t>{};
  for (const std::size_t t : named)
    found.push_back({transforms()[t].kind,
                     fmt::format("{} ({} of {} face pixels match after undoing it{}, {} before)",
                                 transforms()[t].text, score[best], face_pixels,
                                 named.size() > 1 ? " with the other" : "", score[kIdentity]),
                     undo});
  if ((iw != W || ih != H) && !transposes(best)) {
    const bool transposed_size = iw == H && ih == W && iw != ih;
    found.push_back({"canvas_size",
                     fmt::format("the image is {}x{}, the scene's canvas is {}x{}{}", iw, ih, W, H,
                                 transposed_size ? " (width and height swapped)" : ""),
                     false});
  }
  return best;
}

// `src` through transform `use` onto the scene's canvas (the background where it has no pixel),
// and which canvas pixels it gave.
void resample(const Scene& scene, const RgbImage& src, std::size_t use, RgbImage& image,
              std::vector<unsigned char>& compared) {
  const int W = scene.width, H = scene.height;
  image = RgbImage(W, H, Rgb32f::from(scene.background));
  compared.assign(static_cast<std::size_t>(W) * H, 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      Rgb32f p;
      if (transforms()[use].sample(src, x, y, p)) {
        image(x, y) = p;
        compared[static_cast<std::size_t>(y) * W + x] = 1;
      }
    }
}

// The background: the most common colour where the reference shows none of the faces, reported
// when it is not the scene's, and (when `undo`) replaced by the scene's.
void find_background(const Scene& scene, const FaceIdImage& ids,
                     const std::vector<unsigned char>& compared, double tol, bool undo,
                     RgbImage& image, std::vector<GlobalMistake>& found) {
  const int W = scene.width, H = scene.height;
  const auto background_pixel = [&](int x, int y) {
    return ids.at(x, y) < 0 && compared[static_cast<std::size_t>(y) * W + x];
  };
  const auto bin = [](Rgb32f p) {  // the pixel's 8-bit colour, as one key
    const Bgr8 b = Bgr8::from(p.color());
    return static_cast<std::uint32_t>(b.r) << 16 | static_cast<std::uint32_t>(b.g) << 8 | b.b;
  };
  std::unordered_map<std::uint32_t, std::int64_t> counts;
  std::int64_t bg_pixels = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (background_pixel(x, y)) ++bg_pixels, ++counts[bin(image(x, y))];
  std::uint32_t mode = 0;
  std::int64_t mode_count = 0;
  for (const auto& [key, n] : counts)
    if (n > mode_count || (n == mode_count && key < mode)) mode = key, mode_count = n;
  if (bg_pixels == 0 || static_cast<double>(mode_count) <
                            whole_image_tolerance("background_share") * static_cast<double>(bg_pixels))
    return;
  const Color seen{(mode >> 16) / 255.0, ((mode >> 8) & 255) / 255.0, (mode & 255) / 255.0};
  // The mode is 8-bit; compare with half a level of slack on top of the tolerance.
  const Rgb32f expected = Rgb32f::from(scene.background);
  const Rgb32f seen_px = Rgb32f::from(seen);
  if (max_diff(seen_px, expected) <= tol + 0.5 / 255) return;
  // Printed: the mean of the values in the mode's 8-bit bin, not the bin, so that a float
  // image's 0.99 is not reported as 252/255 = 0.988.
  double sum[3] = {0, 0, 0};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (background_pixel(x, y) && bin(image(x, y)) == mode) {
        const Rgb32f p = image(x, y);
        sum[0] += p.r, sum[1] += p.g, sum[2] += p.b;
      }
  const double n = static_cast<double>(mode_count);
  const Color seen_mean{sum[0] / n, sum[1] / n, sum[2] / n};
  found.push_back({"background",
                   fmt::format("the background is {} instead of {} ({} of {} background "
                               "pixels)",
                               rgb(seen_mean), rgb(scene.background), mode_count, bg_pixels),
                   undo});
  if (!undo) return;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (max_diff(image(x, y), seen_px) <= 0.5 / 255 + 1e-4) image(x, y) = expected;
}

}  // namespace

std::vector<GlobalMistake> find_global_mistakes(const Scene& scene, const RgbImage& reference,
                                                const FaceIdImage& ids, const SubmittedImage& in,
                                                double tol, bool undo, RgbImage& image,
                                                std::vector<unsigned char>& compared,
                                                std::vector<std::string>& notes) {
  std::vector<GlobalMistake> found;
  RgbImage src = in.pixels;
  find_scaled_255(scene, in, tol, undo, src, found, notes);
  const std::size_t best = find_transform(scene, reference, ids, src, tol, undo, found);
  resample(scene, src, undo ? best : kIdentity, image, compared);
  find_background(scene, ids, compared, tol, undo, image, found);
  return found;
}

}  // namespace scantrace::grade
