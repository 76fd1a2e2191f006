// diff's classification stage (diff_stages.hpp): every differing pixel gets the first category
// that applies, in the order of docs/grading.md's table; the pixels two readings fit are settled
// by the rest of the image.
#include <array>
#include <map>

#include "grade/diff_stages.hpp"
#include "src/depth_plane.hpp"

namespace scantrace::grade::diff_stages {
namespace {

class Classifier {
 public:
  Classifier(const DiffScene& s, const Comparison& cmp, const Attribution& shown,
             const FaceFindings& faces)
      : s_(s), differing_(cmp.differing), seen_(shown.seen), ref_(shown.reference), found_(faces) {}

  Classification run() {
    const std::size_t n = differing_.size();
    out_.categories.assign(n, Category::other);
    hidden_.assign(n, 0);
    ambiguous_.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) out_.categories[k] = classify(k);
    settle_ambiguous_pixels();
    return std::move(out_);
  }

 private:
  const FaceGeometry& face(int f) const { return s_.faces[f]; }
  bool missing(int f) const { return f >= 0 && found_.missing[static_cast<std::size_t>(f)]; }
  bool shifted(int f) const { return f >= 0 && found_.shifted[static_cast<std::size_t>(f)]; }

  // The classifiers, in the order of docs/grading.md's table. R: the face the reference shows;
  // I: the face the image shows.
  Category classify(std::size_t k) {
    const std::size_t i = differing_[k];
    const int x = s_.px(i), y = s_.py(i);
    const int R = s_.ids.ids[i], I = seen_[i];
    if (I >= 0 && face(I).degenerate()) return Category::degenerate_drawn;
    if (I == kNoFace || I == R) return R >= 0 ? Category::colour : Category::background;
    if (on_boundary(R, I, x, y)) return Category::boundary;
    // A widened neighbour over a face missing everywhere: the missing face is the finding.
    if (!missing(R) && widened_pixel(I, x, y)) return Category::widened;
    if (shifted(R) || shifted(I)) return Category::shifted;
    if (missing(R)) {
      // A skipped face or a face painted over everywhere: the rest of the image decides which
      // (settle_ambiguous_pixels).
      hidden_[k] =
          I >= 0 && face(I).covers(x, y, s_.rule) && order_category(I, R, x, y) != Category::other;
      return Category::missing_face;
    }
    if (I >= 0 && R >= 0 && face(I).covers(x, y, s_.rule)) return classify_covered(k, I, R, x, y);
    if (I >= 0 && face(I).outline_within(x, y, 1.0)) {
      ++out_.near_boundary_extra;
      tag_extra(face(I), x, y);
      return Category::near_boundary;
    }
    if (I == kBackground && R >= 0 && face(R).outline_within(x, y, 1.0)) {
      ++out_.near_boundary_missing;
      tag_missing(face(R), x, y);
      return Category::near_boundary;
    }
    if ((I == kBackground && R >= 0) || (I >= 0 && R < 0)) return Category::background;
    return Category::other;
  }

  // The image shows a face that does cover the pixel. Painted over in the wrong order, the whole
  // overlap of the two faces shows it; a face that lost its edge pixels (a row or a span end
  // dropped) shows the face below only near its outline. Where the two overlap only near R's
  // outline (R's last row over the face below, say), both readings fit; the rest of the image
  // decides (settle_ambiguous_pixels).
  Category classify_covered(std::size_t k, int I, int R, int x, int y) {
    const bool near_outline = face(R).outline_within(x, y, 1.0);
    if (near_outline && pair_share(I, R) < 1.0) {
      ++out_.near_boundary_missing;
      tag_missing(face(R), x, y);
      ++edge_evidence_;
      return Category::near_boundary;
    }
    const Category cat = order_category(I, R, x, y);
    ambiguous_[k] = near_outline && cat != Category::other;
    if (!near_outline) order_evidence_ += cat != Category::other;
    return cat;
  }

  // The other fill rule: the image paints a face on its own outline where the rule does not give
  // it the centre (the closed rule, a face drawn with all its edge pixels), so that of two faces
  // whose outlines pass through the centre the wrong one keeps it. A face missing everywhere is
  // not a matter of the rule.
  bool on_boundary(int R, int I, int x, int y) const {
    const bool I_on = I >= 0 && face(I).on_outline(x, y) != OnOutline::no;
    if (I_on && !face(I).covers(x, y, s_.rule)) return true;
    const bool R_on = R >= 0 && face(R).on_outline(x, y) != OnOutline::no;
    return R_on && I_on && !missing(R);
  }

  // (x, y) is a pixel one beyond either end of a span of widened face I.
  bool widened_pixel(int I, int x, int y) const {
    if (I < 0 || !found_.widened[static_cast<std::size_t>(I)] || face(I).covers(x, y, s_.rule))
      return false;
    return face(I).covers(x + 1, y, s_.rule) || face(I).covers(x - 1, y, s_.rule);
  }

  void tag_missing(const FaceGeometry& g, int x, int y) {
    auto& tags = out_.tags_missing;
    if (!g.covers(x + 1, y, s_.rule)) ++tags["the right end of the span is one pixel short"];
    if (!g.covers(x - 1, y, s_.rule)) ++tags["the left end of the span is one pixel short"];
    if (!g.covers(x, y + 1, s_.rule)) ++tags["the bottom row of the face is missing"];
    if (!g.covers(x, y - 1, s_.rule)) ++tags["the top row of the face is missing"];
  }

  void tag_extra(const FaceGeometry& g, int x, int y) {
    auto& tags = out_.tags_extra;
    if (g.covers(x - 1, y, s_.rule)) ++tags["right of the span's end (one pixel too wide)"];
    if (g.covers(x + 1, y, s_.rule)) ++tags["left of the span's start (one pixel too wide)"];
    if (g.covers(x, y - 1, s_.rule)) ++tags["below the face's last row"];
    if (g.covers(x, y + 1, s_.rule)) ++tags["above the face's first row"];
  }

  // Of the pixels where the reference shows R, I covers them too, and the image shows one of the
  // two, the share it gives to I (1: the whole overlap is painted over; a third face on top of
  // part of it does not count).
  double pair_share(int I, int R) {
    const auto [it, fresh] = shares_.try_emplace({I, R}, 0.0);
    if (fresh) {
      std::int64_t overlap = 0, shows = 0;
      const auto r = static_cast<std::size_t>(R);
      for (std::size_t k = ref_.start[r]; k < ref_.start[r + 1]; ++k) {
        const std::size_t p = ref_.pixels[k];
        if (seen_[p] != I && seen_[p] != R) continue;
        if (!face(I).covers(s_.px(p), s_.py(p), s_.rule)) continue;
        ++overlap;
        shows += seen_[p] == I;
      }
      it->second = overlap ? static_cast<double>(shows) / static_cast<double>(overlap) : 0.0;
    }
    return it->second;
  }

  double depth_at(int f, int x, int y) {
    auto it = planes_.find(f);
    if (it == planes_.end()) {
      const auto& v = s_.scene.faces[static_cast<std::size_t>(f)];
      const auto& d = s_.scene.depth;
      const std::array<double, 3> vd{d[v[0]], d[v[1]], d[v[2]]};
      it = planes_.emplace(f, DepthPlane::through(face(f).snapped(), vd)).first;
    }
    return it->second.at(x, y);
  }

  // Which face wins at (x, y) in the reference's visibility: the painter's order of mean depths,
  // or the z-buffer's depth test at that pixel (zbuffer_canvas.hpp: the nearer wins, a tie keeps
  // the face drawn first).
  Category order_category(int I, int R, int x, int y) {
    if (s_.options.visibility == Visibility::zbuffer) {
      const double dI = depth_at(I, x, y), dR = depth_at(R, x, y);
      if (dI == dR || static_cast<float>(dI) == static_cast<float>(dR)) return Category::order_tie;
      return dI > dR ? Category::order : Category::other;
    }
    const auto& depth = s_.depth;
    const bool drawn_before = depth[I] > depth[R] || (depth[I] == depth[R] && I < R);
    const bool tie =
        depth[I] == depth[R] || static_cast<float>(depth[I]) == static_cast<float>(depth[R]);
    return tie ? Category::order_tie : drawn_before ? Category::order : Category::other;
  }

  void settle_ambiguous_pixels();

  const DiffScene& s_;
  const std::vector<std::size_t>& differing_;
  const std::vector<int>& seen_;
  const FacePixels& ref_;
  const FaceFindings& found_;
  Classification out_;
  std::vector<char> hidden_;     // missing_face pixels a face covering them may have painted over
  std::vector<char> ambiguous_;  // pixels both the painter's order and lost edge pixels explain
  std::int64_t order_evidence_ = 0, edge_evidence_ = 0;
  std::map<std::pair<int, int>, double> shares_;  // pair_share's, by (I, R)
  std::map<int, DepthPlane> planes_;              // depth_at's, by face
};

// The pixels both readings fit. When faces that are partly visible show the wrong painter's
// order on a good share of the differing pixels, the faces hidden everywhere were painted over
// too, not skipped. So are they when most of the faces the reference shows are hidden: no usual
// special case loses most faces, painting nearest first does.
// Pixels where a face covering them shows only near the outline of the face the reference shows:
// lost edge pixels when that is what the clear cases show (a face's last row dropped everywhere),
// the painter's order otherwise. (Faces hidden everywhere count for the order: lost edge pixels
// hide only faces a row high.)
void Classifier::settle_ambiguous_pixels() {
  std::int64_t n_missing = 0, n_visible = 0, n_hidden = 0;
  for (std::size_t f = 0; f < s_.n_faces; ++f)
    n_missing += found_.missing[f], n_visible += found_.ref_pixels[f] > 0;
  for (char h : hidden_) n_hidden += h;
  const bool edge_mistake = edge_evidence_ > order_evidence_ + n_hidden;
  for (std::size_t k = 0; k < differing_.size(); ++k)
    if (ambiguous_[k]) {
      if (edge_mistake) {
        const std::size_t i = differing_[k];
        out_.categories[k] = Category::near_boundary;
        ++out_.near_boundary_missing;
        tag_missing(face(s_.ids.ids[i]), s_.px(i), s_.py(i));
      } else {
        ++order_evidence_;
      }
    }
  const bool order_mistake = 5 * order_evidence_ >= static_cast<std::int64_t>(differing_.size()) ||
                             2 * n_missing >= n_visible;
  for (std::size_t k = 0; k < differing_.size(); ++k)
    if (hidden_[k] && order_mistake) {
      const std::size_t i = differing_[k];
      out_.categories[k] = order_category(seen_[i], s_.ids.ids[i], s_.px(i), s_.py(i));
    }
}

}  // namespace

Classification classify_pixels(const DiffScene& s, const Comparison& cmp, const Attribution& shown,
                               const FaceFindings& faces) {
  return Classifier(s, cmp, shown, faces).run();
}

}  // namespace scantrace::grade::diff_stages
