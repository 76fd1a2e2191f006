// diff's attribution stages (diff_stages.hpp): which face the image shows at each pixel, and what
// the image did to each face as a whole (missing, moved by a pixel, drawn too wide).
#include <algorithm>

#include "grade/diff_stages.hpp"

namespace scantrace::grade::diff_stages {
namespace {

// The face the image shows at a differing pixel. Of the faces whose colour matches: one with an
// area before a zero-area one (a face the fill draws wrote the pixel more likely than one the
// reference never draws: a zero-area face lying on a neighbour's outline with the neighbour's
// mean colour would otherwise take the neighbour's extra pixels as `degenerate_drawn`), then one
// covering the pixel (closed rule), then the closest colour; the background when it matches at
// least as well.
int shown_face(const DiffScene& s, const RgbImage& image, std::size_t i) {
  const int x = s.px(i), y = s.py(i);
  const Rgb32f got = image(x, y);
  int best = kNoFace;
  double best_err = s.match_tolerance;
  bool best_covers = false, best_area = false;
  for (int f : s.grid.at(x, y)) {
    const FaceGeometry& g = s.faces[f];
    if (!g.within(x, y, 1.5)) continue;
    const double err = max_diff(g.color_at(x, y, s.options.shading), got);
    if (err > s.match_tolerance) continue;
    const bool area = !g.degenerate();
    const bool covers = f != s.ids.ids[i] && g.covers(x, y, FillRule::closed);
    const bool better = best != kNoFace && area != best_area ? area
                        : covers != best_covers              ? covers
                                                             : err < best_err - 1e-7;
    if (better) best = f, best_err = err, best_covers = covers, best_area = area;
  }
  const double bg_err = max_diff(got, Rgb32f::from(s.scene.background));
  if (bg_err <= s.tolerance && (best == kNoFace || bg_err <= best_err)) best = kBackground;
  return best;
}

FacePixels index_reference_pixels(const DiffScene& s) {
  FacePixels p;
  p.start.assign(s.n_faces + 1, 0);
  for (int id : s.ids.ids)
    if (id >= 0) ++p.start[static_cast<std::size_t>(id) + 1];
  for (std::size_t f = 0; f < s.n_faces; ++f) p.start[f + 1] += p.start[f];
  p.pixels.assign(p.start[s.n_faces], 0);
  std::vector<std::size_t> fill = p.start;
  for (std::size_t i = 0; i < s.ids.ids.size(); ++i)
    if (s.ids.ids[i] >= 0) p.pixels[fill[static_cast<std::size_t>(s.ids.ids[i])]++] = i;
  return p;
}

// Every pixel of face f shows one colour, and not the reference's.
bool recoloured(const DiffScene& s, const Aligned& aligned, const RgbImage& reference,
                const FacePixels& ref, std::size_t f) {
  const RgbImage& image = aligned.image;
  const std::size_t p0 = ref.pixels[ref.start[f]];
  const int x0 = s.px(p0), y0 = s.py(p0);
  for (std::size_t k = ref.start[f]; k < ref.start[f + 1]; ++k) {
    const std::size_t p = ref.pixels[k];
    if (!aligned.compared[p] || max_diff(image(s.px(p), s.py(p)), image(x0, y0)) != 0) return false;
  }
  return max_diff(reference(x0, y0), image(x0, y0)) > s.tolerance;
}

// A flat face painted all over in one wrong colour (the first vertex's colour instead of the
// mean, say) shows that colour on every one of its pixels. Where a neighbour's colour happens to
// match it, the neighbour would be taken for the face shown — but a face drawn over this one
// covers its pixels, and one drawn too wide reaches only some of them. So when all of a face's
// pixels show one colour, not its own, and the face matched does not cover them, the image shows
// this face in the wrong colour. (A neighbour shown right on most of its own pixels is not such a
// coincidence: it reached over, as a span one pixel too wide does.)
void unmatch_recoloured_flat_faces(const DiffScene& s, const Aligned& aligned,
                                   const RgbImage& reference, Attribution& a) {
  if (s.options.shading != Shading::flat) return;
  std::vector<std::int64_t> own(s.n_faces, 0);  // pixels showing their reference face
  for (std::size_t i = 0; i < a.seen.size(); ++i)
    if (s.ids.ids[i] >= 0 && a.seen[i] == s.ids.ids[i])
      ++own[static_cast<std::size_t>(s.ids.ids[i])];
  const auto shown_right = [&](int f) {
    const auto u = static_cast<std::size_t>(f);
    return 2 * own[u] > static_cast<std::int64_t>(a.reference.count(u));
  };
  for (std::size_t f = 0; f < s.n_faces; ++f) {
    if (a.reference.count(f) < 2 || !recoloured(s, aligned, reference, a.reference, f)) continue;
    for (std::size_t k = a.reference.start[f]; k < a.reference.start[f + 1]; ++k) {
      const std::size_t i = a.reference.pixels[k];
      const int I = a.seen[i];
      if (I >= 0 && !shown_right(I) && !s.faces[I].covers(s.px(i), s.py(i), FillRule::closed))
        a.seen[i] = kNoFace;
    }
  }
}

}  // namespace

Attribution attribute_pixels(const DiffScene& s, const Aligned& aligned, const RgbImage& reference,
                             const Comparison& cmp) {
  Attribution a;
  a.seen.assign(static_cast<std::size_t>(s.width) * s.height, kNoFace);
  for (std::size_t i = 0; i < a.seen.size(); ++i)
    if (aligned.compared[i]) a.seen[i] = s.ids.ids[i];  // agreeing pixels; differing ones next
  for (std::size_t i : cmp.differing) a.seen[i] = shown_face(s, aligned.image, i);
  a.reference = index_reference_pixels(s);
  unmatch_recoloured_flat_faces(s, aligned, reference, a);
  return a;
}

namespace {

// More of face f's reference pixels, moved one pixel in some direction, show f than in place,
// and those are at least half of the pixels showing f.
bool is_shifted(const DiffScene& s, const Attribution& a, std::int64_t shown, std::size_t f) {
  constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
  const FacePixels& ref = a.reference;
  std::int64_t same = 0, best = 0;
  for (std::size_t k = ref.start[f]; k < ref.start[f + 1]; ++k)
    same += a.seen[ref.pixels[k]] == static_cast<int>(f);
  for (int d = 0; d < 4; ++d) {
    std::int64_t n = 0;
    for (std::size_t k = ref.start[f]; k < ref.start[f + 1]; ++k) {
      const int x = s.px(ref.pixels[k]) + kDx[d], y = s.py(ref.pixels[k]) + kDy[d];
      n += x >= 0 && y >= 0 && x < s.width && y < s.height &&
           a.seen[s.idx(x, y)] == static_cast<int>(f);
    }
    best = std::max(best, n);
  }
  return best > same && 2 * best >= shown;
}

// Faces shown nowhere in the image, and faces shown translated by one pixel.
void find_missing_and_shifted(const DiffScene& s, const Comparison& cmp, const Attribution& a,
                              FaceFindings& out) {
  out.ref_pixels.assign(s.n_faces, 0);
  out.shown.assign(s.n_faces, 0);
  for (std::size_t i = 0; i < a.seen.size(); ++i) {
    if (s.ids.ids[i] >= 0) ++out.ref_pixels[static_cast<std::size_t>(s.ids.ids[i])];
    if (a.seen[i] >= 0) ++out.shown[static_cast<std::size_t>(a.seen[i])];
  }
  out.missing.assign(s.n_faces, 0);
  out.shifted.assign(s.n_faces, 0);
  for (std::size_t f = 0; f < s.n_faces; ++f)
    out.missing[f] = out.ref_pixels[f] > 0 && out.shown[f] == 0;
  std::vector<char> touched(s.n_faces, 0);
  for (std::size_t i : cmp.differing) {
    if (s.ids.ids[i] >= 0) touched[static_cast<std::size_t>(s.ids.ids[i])] = 1;
    if (a.seen[i] >= 0) touched[static_cast<std::size_t>(a.seen[i])] = 1;
  }
  for (std::size_t f = 0; f < s.n_faces; ++f)
    if (touched[f] && out.shown[f] >= 3 && out.ref_pixels[f] >= 3)
      out.shifted[f] = is_shifted(s, a, out.shown[f], f);
}

// Faces drawn one pixel too wide at both ends of their spans (a floor/ceil rule, the
// line-drawing pixels as span ends). Such a face gains pixels beyond both ends of its spans and
// loses pixels only where a neighbour widened over them; a face translated by one pixel gains on
// one side and uncovers pixels on the other (a vertical move gains on the left and the right of
// its lower edges, but uncovers its upper ones). Widened faces are not `shifted`.
void find_widened(const DiffScene& s, const Comparison& cmp, const Attribution& a,
                  FaceFindings& out) {
  std::vector<std::int64_t> left(s.n_faces, 0), right(s.n_faces, 0), uncovered(s.n_faces, 0);
  for (std::size_t i : cmp.differing) {
    const int R = s.ids.ids[i], I = a.seen[i], x = s.px(i), y = s.py(i);
    if (I == R) continue;
    const FaceGeometry* g = I >= 0 ? &s.faces[I] : nullptr;
    const bool extension = g && !g->degenerate() && !g->covers(x, y, s.rule);
    if (extension) {
      const bool l = g->covers(x + 1, y, s.rule), r = g->covers(x - 1, y, s.rule);
      left[static_cast<std::size_t>(I)] += l;
      right[static_cast<std::size_t>(I)] += r;
      // Span ends rounded to the nearest pixel reach only centres at most half a pixel from
      // the face along the row; floor(x_L) .. ceil(x_R) reaches farther ones too. (Centres on
      // the outline, an exact crossing, both reach: they do not tell.)
      if ((l || r) && g->on_outline(x, y) == OnOutline::no) {
        ++out.extended_off_outline;
        out.extended_beyond_half +=
            (l && !g->within(x + 0.5, y, 0)) || (r && !g->within(x - 0.5, y, 0));
      }
    }
    if (R >= 0 && !extension) ++uncovered[static_cast<std::size_t>(R)];
  }
  out.widened.assign(s.n_faces, 0);
  for (std::size_t f = 0; f < s.n_faces; ++f) {
    out.extended_left += left[f], out.extended_right += right[f];
    out.widened[f] = left[f] > 0 && right[f] > 0 && 4 * uncovered[f] <= left[f] + right[f];
    if (out.widened[f]) out.shifted[f] = 0;
  }
}

}  // namespace

FaceFindings find_face_mistakes(const DiffScene& s, const Comparison& cmp,
                                const Attribution& shown) {
  FaceFindings out;
  find_missing_and_shifted(s, cmp, shown, out);
  find_widened(s, cmp, shown, out);
  return out;
}

}  // namespace scantrace::grade::diff_stages
