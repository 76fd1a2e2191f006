// The pixel classification of `diff` (diff_report.hpp): global mistakes are found and undone by
// global_mistakes.cpp; here every remaining differing pixel is matched against the faces around it
// and given the first category that applies. `DiffRun` is the pipeline: one member function per
// stage, run in order by DiffRun::run (adding a category is adding a classifier to
// classify_pixel, in the documented order, and a stage if it needs evidence of its own).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <spdlog/fmt/fmt.h>

#include "grade/diff_report.hpp"
#include "grade/diff_verdict.hpp"
#include "grade/face_geometry.hpp"
#include "grade/face_id_render.hpp"
#include "grade/global_mistakes.hpp"
#include "grade/pixel_story.hpp"
#include "src/depth_plane.hpp"
#include "src/painter.hpp"

namespace scantrace::grade {
namespace {

constexpr int kBackground = -1;  // the image shows the background there
constexpr int kNoFace = -2;      // no face's colour matches the image there

double max_diff(Rgb32f a, Rgb32f b) {
  return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}
double max_diff(Color a, Rgb32f b) {
  return max_diff(Rgb32f::from(a), b);
}

// Faces by 8×8-pixel cell of their bounding box widened by 1.5 px: the faces "around" a pixel.
class FaceGrid {
 public:
  static constexpr int kCell = 8;
  FaceGrid(const Scene& s)
      : cw_((s.width + kCell - 1) / kCell), ch_((s.height + kCell - 1) / kCell) {
    cells_.resize(static_cast<std::size_t>(cw_) * ch_);
    for (int f = 0; f < static_cast<int>(s.faces.size()); ++f) {
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (int v : s.faces[f]) {
        x0 = std::min(x0, s.vertices[v].x), x1 = std::max(x1, s.vertices[v].x);
        y0 = std::min(y0, s.vertices[v].y), y1 = std::max(y1, s.vertices[v].y);
      }
      if (!(x1 >= -2 && y1 >= -2 && x0 <= s.width + 1 && y0 <= s.height + 1)) continue;
      const int cx0 = std::clamp(static_cast<int>(std::floor((x0 - 1.5) / kCell)), 0, cw_ - 1);
      const int cx1 = std::clamp(static_cast<int>(std::floor((x1 + 1.5) / kCell)), 0, cw_ - 1);
      const int cy0 = std::clamp(static_cast<int>(std::floor((y0 - 1.5) / kCell)), 0, ch_ - 1);
      const int cy1 = std::clamp(static_cast<int>(std::floor((y1 + 1.5) / kCell)), 0, ch_ - 1);
      for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx)
          cells_[static_cast<std::size_t>(cy) * cw_ + cx].push_back(f);
    }
  }
  const std::vector<int>& at(int x, int y) const {
    return cells_[static_cast<std::size_t>(y / kCell) * cw_ + x / kCell];
  }

 private:
  int cw_, ch_;
  std::vector<std::vector<int>> cells_;
};

class Faces {
 public:
  Faces(const Scene& s, int bits) : scene_(s), bits_(bits), geo_(s.faces.size()) {}
  const FaceGeometry& operator[](int f) {
    auto& g = geo_[static_cast<std::size_t>(f)];
    if (!g) g = std::make_unique<FaceGeometry>(scene_, f, bits_);
    return *g;
  }

 private:
  const Scene& scene_;
  int bits_;
  std::vector<std::unique_ptr<FaceGeometry>> geo_;
};

struct Hypothesis {
  std::string text;
  std::int64_t matches = 0;
};

class DiffRun {
 public:
  DiffRun(const Scene& scene, const FillOptions& options, const SubmittedImage& submitted,
          const DiffOptions& dopt)
      : scene_(scene),
        options_(options),
        submitted_(submitted),
        dopt_(dopt),
        W_(scene.width),
        H_(scene.height),
        tol_(dopt.tolerance),
        // Matching a colour to a face allows for the image's own 8-bit rounding on top of the
        // tolerance.
        match_tol_(dopt.tolerance + 0.5 / 255),
        rule_(options.fill_rule),
        ids_(render_face_ids(scene, options)),
        depth_(face_depths(scene)),
        grid_(scene),
        faces_(scene, options.subpixel_bits),
        n_faces_(scene.faces.size()) {}

  DiffReport run() {
    start_report();
    compare_pixels();
    match_shown_faces();
    index_reference_pixels();
    unmatch_recoloured_flat_faces();
    find_missing_and_shifted();
    find_widened();
    classify_pixels();
    settle_ambiguous_pixels();
    count_categories();
    find_patterns();
    diagnose_colours();
    list_faces();
    name_mistakes();
    explain_examples();
    return std::move(report_);
  }

 private:
  int px(std::size_t i) const { return static_cast<int>(i % W_); }
  int py(std::size_t i) const { return static_cast<int>(i / W_); }
  std::size_t idx(int x, int y) const { return static_cast<std::size_t>(y) * W_ + x; }

  // Stage 1: the reference, and the global mistakes found and undone (global_mistakes.cpp).
  void start_report() {
    report_.width = W_, report_.height = H_;
    report_.image_width = submitted_.pixels.width();
    report_.image_height = submitted_.pixels.height();
    report_.tolerance = tol_;
    for (const char* c : kCategories) report_.categories[c] = 0;
    report_.reference = render<Rgb32f>(scene_, options_);
    report_.global = find_global_mistakes(scene_, report_.reference, ids_, submitted_, tol_,
                                          dopt_.undo, image_, compared_, report_.notes);
  }

  // Stage 2: which pixels differ, and the 8-bit truncation note.
  void compare_pixels() {
    seen_.assign(static_cast<std::size_t>(W_) * H_, kNoFace);  // the image's face per pixel
    EightBit counts;
    for (int y = 0; y < H_; ++y)
      for (int x = 0; x < W_; ++x) {
        const std::size_t i = idx(x, y);
        if (!compared_[i]) continue;
        ++report_.compared_pixels;
        const Rgb32f r = report_.reference(x, y), g = image_(x, y);
        if (max_diff(r, g) > tol_) {
          differing_.push_back(i);
        } else {
          seen_[i] = ids_.ids[i];
        }
        count_eight_bit(r, g, ids_.ids[i] >= 0, counts);
      }
    report_.differing_pixels = static_cast<std::int64_t>(differing_.size());
    // The note is for 8-bit input only: an image file, a uint8 array, or a float array whose
    // faces' values are (almost all) multiples of 1/255, floor(255·c)/255 saved as floats. A float
    // render that never went through 8 bits has a few values on a level by chance (617 of the
    // course scene's: the note was false, issue 47).
    const bool eight_bit = submitted_.eight_bit || 10 * counts.on_level >= 9 * counts.face_values;
    if (eight_bit && counts.truncated > counts.rounded && counts.truncated > 0)
      report_.notes.push_back(fmt::format(
          "8-bit truncation instead of rounding: {} channel values are floor(255·c) where "
          "round(255·c) is larger ({} are rounded){}",
          counts.truncated, counts.rounded,
          report_.differing_pixels == 0 ? ", within the tolerance" : ""));
  }

  struct EightBit {
    std::int64_t truncated = 0, rounded = 0;  // values at floor(255·c) / round(255·c) where they differ
    std::int64_t face_values = 0, on_level = 0;  // the faces' channel values, and those k/255
  };

  // 8-bit values: those of an image file, and those of a float array that holds multiples of
  // 1/255 (floor(255·c)/255 written as floats had no note, issue 36).
  void count_eight_bit(Rgb32f r, Rgb32f g, bool face, EightBit& n) const {
    for (const auto& [rv, gv] : {std::pair{r.r, g.r}, {r.g, g.g}, {r.b, g.b}}) {
      const double level = 255.0 * gv;
      const bool on_level = std::fabs(level - std::round(level)) < 1e-3;
      n.face_values += face, n.on_level += face && on_level;
      if (!submitted_.eight_bit && !on_level) continue;
      const int round = to_byte(rv), floor = static_cast<int>(std::floor(255.0 * rv + 1e-9));
      const int got = static_cast<int>(std::lround(level));
      if (round == floor) continue;
      if (got == floor)
        ++n.truncated;
      else if (got == round)
        ++n.rounded;
    }
  }

  // Stage 3: which face does the image show at each differing pixel? Of the faces whose colour
  // matches: one with an area before a zero-area one (a face the fill draws wrote the pixel more
  // likely than one the reference never draws: a zero-area face lying on a neighbour's outline
  // with the neighbour's mean colour was named `degenerate_drawn` for the neighbour's extra
  // pixels), then one covering the pixel (closed rule), then the closest colour.
  void match_shown_faces() {
    const Rgb32f background = Rgb32f::from(scene_.background);
    for (std::size_t i : differing_) {
      const int x = px(i), y = py(i);
      const Rgb32f got = image_(x, y);
      int best = kNoFace;
      double best_err = match_tol_;
      bool best_covers = false, best_area = false;
      for (int f : grid_.at(x, y)) {
        const FaceGeometry& g = faces_[f];
        if (!g.within(x, y, 1.5)) continue;
        const double err = max_diff(g.color_at(x, y, options_.shading), got);
        if (err > match_tol_) continue;
        const bool area = !g.degenerate();
        const bool covers = f != ids_.ids[i] && g.covers(x, y, FillRule::closed);
        const bool better = best != kNoFace && area != best_area ? area
                            : covers != best_covers                ? covers
                                                                   : err < best_err - 1e-7;
        if (better) best = f, best_err = err, best_covers = covers, best_area = area;
      }
      const double bg_err = max_diff(got, background);
      if (bg_err <= tol_ && (best == kNoFace || bg_err <= best_err)) best = kBackground;
      seen_[i] = best;
    }
  }

  // Stage 4: the pixels of each face in the reference (a counting sort by face id).
  void index_reference_pixels() {
    start_.assign(n_faces_ + 1, 0);
    for (int id : ids_.ids)
      if (id >= 0) ++start_[static_cast<std::size_t>(id) + 1];
    for (std::size_t f = 0; f < n_faces_; ++f) start_[f + 1] += start_[f];
    pixels_.assign(start_[n_faces_], 0);
    std::vector<std::size_t> fill = start_;
    for (std::size_t i = 0; i < ids_.ids.size(); ++i)
      if (ids_.ids[i] >= 0) pixels_[fill[static_cast<std::size_t>(ids_.ids[i])]++] = i;
    own_.assign(n_faces_, 0);
    for (std::size_t i = 0; i < seen_.size(); ++i)
      if (ids_.ids[i] >= 0 && seen_[i] == ids_.ids[i])
        ++own_[static_cast<std::size_t>(ids_.ids[i])];
  }

  bool shown_right(int f) const {
    const auto u = static_cast<std::size_t>(f);
    return 2 * own_[u] > static_cast<std::int64_t>(start_[u + 1] - start_[u]);
  }

  // Stage 5: a flat face painted all over in one wrong colour (the first vertex's colour instead
  // of the mean, say) shows that colour on every one of its pixels. Where a neighbour's colour
  // happens to match it, the neighbour would be taken for the face shown — but a face drawn over
  // this one covers its pixels, and one drawn too wide reaches only some of them. So when all of a
  // face's pixels show one colour, not its own, and the face matched does not cover them, the
  // image shows this face in the wrong colour.
  // (A neighbour shown right on most of its own pixels is not such a coincidence: it reached
  // over, as a span one pixel too wide does.)
  void unmatch_recoloured_flat_faces() {
    if (options_.shading != Shading::flat) return;
    for (std::size_t f = 0; f < n_faces_; ++f) {
      if (start_[f + 1] - start_[f] < 2 || !recoloured(f)) continue;
      for (std::size_t k = start_[f]; k < start_[f + 1]; ++k) {
        const std::size_t i = pixels_[k];
        const int I = seen_[i];
        if (I >= 0 && !shown_right(I) && !faces_[I].covers(px(i), py(i), FillRule::closed))
          seen_[i] = kNoFace;
      }
    }
  }

  // Every pixel of face f shows one colour, and not the reference's.
  bool recoloured(std::size_t f) const {
    const std::size_t p0 = pixels_[start_[f]];
    for (std::size_t k = start_[f]; k < start_[f + 1]; ++k)
      if (!compared_[pixels_[k]] ||
          max_diff(image_(px(pixels_[k]), py(pixels_[k])), image_(px(p0), py(p0))) != 0)
        return false;
    return max_diff(report_.reference(px(p0), py(p0)), image_(px(p0), py(p0))) > tol_;
  }

  // Stage 6: faces shown nowhere in the image, and faces shown translated by one pixel.
  void find_missing_and_shifted() {
    ref_pixels_.assign(n_faces_, 0);
    shown_.assign(n_faces_, 0);
    for (std::size_t i = 0; i < seen_.size(); ++i) {
      if (ids_.ids[i] >= 0) ++ref_pixels_[static_cast<std::size_t>(ids_.ids[i])];
      if (seen_[i] >= 0) ++shown_[static_cast<std::size_t>(seen_[i])];
    }
    missing_.assign(n_faces_, 0);
    shifted_.assign(n_faces_, 0);
    for (std::size_t f = 0; f < n_faces_; ++f)
      missing_[f] = ref_pixels_[f] > 0 && shown_[f] == 0;
    std::vector<char> touched(n_faces_, 0);
    for (std::size_t i : differing_) {
      if (ids_.ids[i] >= 0) touched[static_cast<std::size_t>(ids_.ids[i])] = 1;
      if (seen_[i] >= 0) touched[static_cast<std::size_t>(seen_[i])] = 1;
    }
    for (std::size_t f = 0; f < n_faces_; ++f)
      if (touched[f] && shown_[f] >= 3 && ref_pixels_[f] >= 3) shifted_[f] = is_shifted(f);
  }

  // More of face f's reference pixels, moved one pixel in some direction, show f than in place,
  // and those are at least half of the pixels showing f.
  bool is_shifted(std::size_t f) const {
    constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
    std::int64_t same = 0, best = 0;
    for (std::size_t k = start_[f]; k < start_[f + 1]; ++k)
      same += seen_[pixels_[k]] == static_cast<int>(f);
    for (int d = 0; d < 4; ++d) {
      std::int64_t n = 0;
      for (std::size_t k = start_[f]; k < start_[f + 1]; ++k) {
        const int x = px(pixels_[k]) + kDx[d], y = py(pixels_[k]) + kDy[d];
        n += x >= 0 && y >= 0 && x < W_ && y < H_ && seen_[idx(x, y)] == static_cast<int>(f);
      }
      best = std::max(best, n);
    }
    return best > same && 2 * best >= shown_[f];
  }

  // Stage 7: faces drawn one pixel too wide at both ends of their spans (a floor/ceil rule, the
  // line-drawing pixels as span ends). Such a face gains pixels beyond both ends of its spans and
  // loses pixels only where a neighbour widened over them; a face translated by one pixel gains on
  // one side and uncovers pixels on the other (a vertical move gains on the left and the right of
  // its lower edges, but uncovers its upper ones). Widened faces are not `shifted`.
  void find_widened() {
    std::vector<std::int64_t> left(n_faces_, 0), right(n_faces_, 0), uncovered(n_faces_, 0);
    for (std::size_t i : differing_) {
      const int R = ids_.ids[i], I = seen_[i], x = px(i), y = py(i);
      if (I == R) continue;
      const bool extension = I >= 0 && !faces_[I].degenerate() && !faces_[I].covers(x, y, rule_);
      if (extension) {
        const bool l = faces_[I].covers(x + 1, y, rule_), r = faces_[I].covers(x - 1, y, rule_);
        left[static_cast<std::size_t>(I)] += l;
        right[static_cast<std::size_t>(I)] += r;
        // Span ends rounded to the nearest pixel reach only centres at most half a pixel from
        // the face along the row; floor(x_L) .. ceil(x_R) reaches farther ones too. (Centres on
        // the outline, an exact crossing, both reach: they do not tell.)
        if ((l || r) && faces_[I].on_outline(x, y) == OnOutline::no) {
          ++evidence_.extended_off_outline;
          evidence_.extended_beyond_half += (l && !faces_[I].within(x + 0.5, y, 0)) ||
                                            (r && !faces_[I].within(x - 0.5, y, 0));
        }
      }
      if (R >= 0 && !extension) ++uncovered[static_cast<std::size_t>(R)];
    }
    widened_.assign(n_faces_, 0);
    for (std::size_t f = 0; f < n_faces_; ++f) {
      evidence_.extended_left += left[f], evidence_.extended_right += right[f];
      widened_[f] = left[f] > 0 && right[f] > 0 && 4 * uncovered[f] <= left[f] + right[f];
      if (widened_[f]) shifted_[f] = 0;
    }
  }

  // (x, y) is a pixel one beyond either end of a span of widened face I.
  bool widened_pixel(int I, int x, int y) {
    if (I < 0 || !widened_[static_cast<std::size_t>(I)] || faces_[I].covers(x, y, rule_))
      return false;
    return faces_[I].covers(x + 1, y, rule_) || faces_[I].covers(x - 1, y, rule_);
  }

  void tag_missing(const FaceGeometry& g, int x, int y) {
    if (!g.covers(x + 1, y, rule_)) ++tags_missing_["the right end of the span is one pixel short"];
    if (!g.covers(x - 1, y, rule_)) ++tags_missing_["the left end of the span is one pixel short"];
    if (!g.covers(x, y + 1, rule_)) ++tags_missing_["the bottom row of the face is missing"];
    if (!g.covers(x, y - 1, rule_)) ++tags_missing_["the top row of the face is missing"];
  }

  void tag_extra(const FaceGeometry& g, int x, int y) {
    if (g.covers(x - 1, y, rule_)) ++tags_extra_["right of the span's end (one pixel too wide)"];
    if (g.covers(x + 1, y, rule_)) ++tags_extra_["left of the span's start (one pixel too wide)"];
    if (g.covers(x, y - 1, rule_)) ++tags_extra_["below the face's last row"];
    if (g.covers(x, y + 1, rule_)) ++tags_extra_["above the face's first row"];
  }

  // The other fill rule: the image paints a face on its own outline where the rule does not give
  // it the centre (the closed rule, a face drawn with all its edge pixels), so that of two faces
  // whose outlines pass through the centre the wrong one keeps it. A face missing everywhere is
  // not a matter of the rule.
  bool on_boundary(int R, int I, int x, int y) {
    const bool I_on = I >= 0 && faces_[I].on_outline(x, y) != OnOutline::no;
    if (I_on && !faces_[I].covers(x, y, rule_)) return true;
    const bool R_on = R >= 0 && faces_[R].on_outline(x, y) != OnOutline::no;
    return R_on && I_on && !missing_[static_cast<std::size_t>(R)];
  }

  // Of the pixels where the reference shows R, I covers them too, and the image shows one of the
  // two, the share it gives to I (1: the whole overlap is painted over; a third face on top of
  // part of it does not count).
  double pair_share(int I, int R) {
    const auto [it, fresh] = shares_.try_emplace({I, R}, 0.0);
    if (fresh) {
      std::int64_t overlap = 0, shows = 0;
      for (std::size_t k = start_[static_cast<std::size_t>(R)];
           k < start_[static_cast<std::size_t>(R) + 1]; ++k) {
        const std::size_t p = pixels_[k];
        if (seen_[p] != I && seen_[p] != R) continue;
        if (!faces_[I].covers(px(p), py(p), rule_)) continue;
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
      const auto& v = scene_.faces[static_cast<std::size_t>(f)];
      const std::array<double, 3> d{scene_.depth[v[0]], scene_.depth[v[1]], scene_.depth[v[2]]};
      it = planes_.emplace(f, DepthPlane::through(faces_[f].snapped(), d)).first;
    }
    return it->second.at(x, y);
  }

  // Which face wins at (x, y) in the reference's visibility: the painter's order of mean depths,
  // or the z-buffer's depth test at that pixel (zbuffer_canvas.hpp: the nearer wins, a tie keeps
  // the face drawn first).
  const char* order_category(int I, int R, int x, int y) {
    if (options_.visibility == Visibility::zbuffer) {
      const double dI = depth_at(I, x, y), dR = depth_at(R, x, y);
      if (dI == dR || static_cast<float>(dI) == static_cast<float>(dR)) return "order_tie";
      return dI > dR ? "order" : "other";
    }
    const bool drawn_before = depth_[I] > depth_[R] || (depth_[I] == depth_[R] && I < R);
    const bool tie =
        depth_[I] == depth_[R] || static_cast<float>(depth_[I]) == static_cast<float>(depth_[R]);
    return tie ? "order_tie" : drawn_before ? "order" : "other";
  }

  // Stage 8: every differing pixel gets the first category that applies.
  void classify_pixels() {
    cats_.assign(differing_.size(), {});
    hidden_.assign(differing_.size(), 0);
    ambiguous_.assign(differing_.size(), 0);
    for (std::size_t k = 0; k < differing_.size(); ++k) cats_[k] = classify_pixel(k);
  }

  // The classifiers, in the order of docs/grading.md's table.
  std::string classify_pixel(std::size_t k) {
    const std::size_t i = differing_[k];
    const int x = px(i), y = py(i);
    const int R = ids_.ids[i], I = seen_[i];
    if (I >= 0 && faces_[I].degenerate()) return "degenerate_drawn";
    if (I == kNoFace || I == R) return R >= 0 ? "colour" : "background";
    if (on_boundary(R, I, x, y)) return "boundary";
    // A widened neighbour over a face missing everywhere: the missing face is the finding.
    if ((R < 0 || !missing_[static_cast<std::size_t>(R)]) && widened_pixel(I, x, y))
      return "widened";
    if ((R >= 0 && shifted_[static_cast<std::size_t>(R)]) ||
        (I >= 0 && shifted_[static_cast<std::size_t>(I)]))
      return "shifted";
    if (R >= 0 && missing_[static_cast<std::size_t>(R)]) {
      // A skipped face or a face painted over everywhere: the rest of the image decides which
      // (settle_ambiguous_pixels).
      hidden_[k] = I >= 0 && faces_[I].covers(x, y, rule_) &&
                   std::string(order_category(I, R, x, y)) != "other";
      return "missing_face";
    }
    if (I >= 0 && R >= 0 && faces_[I].covers(x, y, rule_)) return classify_covered(k, I, R, x, y);
    if (I >= 0 && faces_[I].outline_within(x, y, 1.0)) {
      ++report_.near_boundary_extra;
      tag_extra(faces_[I], x, y);
      return "near_boundary";
    }
    if (I == kBackground && R >= 0 && faces_[R].outline_within(x, y, 1.0)) {
      ++report_.near_boundary_missing;
      tag_missing(faces_[R], x, y);
      return "near_boundary";
    }
    if ((I == kBackground && R >= 0) || (I >= 0 && R < 0)) return "background";
    return "other";
  }

  // The image shows a face that does cover the pixel. Painted over in the wrong order, the whole
  // overlap of the two faces shows it; a face that lost its edge pixels (a row or a span end
  // dropped) shows the face below only near its outline. Where the two overlap only near R's
  // outline (R's last row over the face below, say), both readings fit; the rest of the image
  // decides (settle_ambiguous_pixels).
  std::string classify_covered(std::size_t k, int I, int R, int x, int y) {
    const bool near_outline = faces_[R].outline_within(x, y, 1.0);
    if (near_outline && pair_share(I, R) < 1.0) {
      ++report_.near_boundary_missing;
      tag_missing(faces_[R], x, y);
      ++edge_evidence_;
      return "near_boundary";
    }
    const std::string cat = order_category(I, R, x, y);
    ambiguous_[k] = near_outline && cat != "other";
    if (!near_outline) order_evidence_ += cat != "other";
    return cat;
  }

  // Stage 9: the pixels both readings fit. When faces that are partly visible show the wrong
  // painter's order on a good share of the differing pixels, the faces hidden everywhere were
  // painted over too, not skipped. So are they when most of the faces the reference shows are
  // hidden: no usual special case loses most faces, painting nearest first does.
  // Pixels where a face covering them shows only near the outline of the face the reference
  // shows: lost edge pixels when that is what the clear cases show (a face's last row dropped
  // everywhere), the painter's order otherwise. (Faces hidden everywhere count for the order:
  // lost edge pixels hide only faces a row high.)
  void settle_ambiguous_pixels() {
    std::int64_t n_missing = 0, n_visible = 0, n_hidden = 0;
    for (std::size_t f = 0; f < n_faces_; ++f)
      n_missing += missing_[f], n_visible += ref_pixels_[f] > 0;
    for (char h : hidden_) n_hidden += h;
    const bool edge_mistake = edge_evidence_ > order_evidence_ + n_hidden;
    for (std::size_t k = 0; k < differing_.size(); ++k)
      if (ambiguous_[k]) {
        if (edge_mistake) {
          const std::size_t i = differing_[k];
          cats_[k] = "near_boundary";
          ++report_.near_boundary_missing;
          tag_missing(faces_[ids_.ids[i]], px(i), py(i));
        } else {
          ++order_evidence_;
        }
      }
    const bool order_mistake =
        5 * order_evidence_ >= static_cast<std::int64_t>(differing_.size()) ||
        2 * n_missing >= n_visible;
    for (std::size_t k = 0; k < differing_.size(); ++k)
      if (hidden_[k] && order_mistake) {
        const std::size_t i = differing_[k];
        cats_[k] = order_category(seen_[i], ids_.ids[i], px(i), py(i));
      }
  }

  // Stage 10: the counts, the per-pixel map, the damage per face, the examples to explain.
  void count_categories() {
    report_.category_map.assign(static_cast<std::size_t>(W_) * H_, 0);
    for (std::size_t k = 0; k < differing_.size(); ++k) {
      const std::size_t i = differing_[k];
      const int R = ids_.ids[i], I = seen_[i];
      const std::string& cat = cats_[k];
      ++report_.categories[cat];
      report_.category_map[i] = static_cast<std::uint8_t>(1 + category_index(cat));
      if (cat == "colour") colour_pixels_.push_back(i);
      const int blamed = R >= 0 ? R : I;
      if (blamed >= 0) ++damage_[blamed][cat];
      auto& examples = first_[cat];
      if (static_cast<int>(examples.size()) < dopt_.examples_per_category) examples.push_back(i);
    }
  }

  // Stage 11: dominant near-boundary patterns.
  void find_patterns() {
    const auto dominant = [&](const std::map<std::string, std::int64_t>& tags,
                              std::int64_t total, const char* what) {
      for (const auto& [text, n] : tags)
        if (total > 0 && 2 * n > total)
          report_.patterns.push_back(fmt::format("{}: {} on {:.0f} % of the {} pixels", what,
                                                 text, 100.0 * n / total, what));
    };
    dominant(tags_missing_, report_.near_boundary_missing, "missing");
    dominant(tags_extra_, report_.near_boundary_extra, "extra");
  }

  template <class ColourOf>
  void test_hypothesis(std::vector<Hypothesis>& hyp, const std::string& text,
                       ColourOf&& colour_of) {
    Hypothesis h{text, 0};
    for (std::size_t i : colour_pixels_) {
      const int x = px(i), y = py(i);
      if (max_diff(colour_of(faces_[ids_.ids[i]], x, y), image_(x, y)) <= match_tol_) ++h.matches;
    }
    hyp.push_back(h);
  }

  void flat_hypotheses(std::vector<Hypothesis>& hyp) {
    static constexpr const char* kOrdinal[3] = {"first", "second", "third"};
    for (int k = 0; k < 3; ++k)
      test_hypothesis(hyp,
                      fmt::format("flat colour is the {} vertex's colour, not the mean of the three",
                                  kOrdinal[k]),
                      [k](const FaceGeometry& g, int, int) { return g.colors()[k]; });
    test_hypothesis(hyp, "Gouraud shading where flat was asked",
                    [](const FaceGeometry& g, int x, int y) {
                      return g.color_at(x, y, Shading::gouraud);
                    });
  }

  void gouraud_hypotheses(std::vector<Hypothesis>& hyp) {
    static constexpr int kPerms[5][3] = {{1, 0, 2}, {0, 2, 1}, {2, 1, 0}, {1, 2, 0}, {2, 0, 1}};
    for (const auto& p : kPerms)
      test_hypothesis(hyp,
                      fmt::format("Gouraud with the vertex colours permuted: vertices 0, 1, 2 get "
                                  "the colours of {}, {}, {}",
                                  p[0], p[1], p[2]),
                      [&p](const FaceGeometry& g, int x, int y) {
                        const auto& c = g.colors();
                        return g.color_at(x, y, Shading::gouraud, {c[p[0]], c[p[1]], c[p[2]]});
                      });
    test_hypothesis(hyp, "colours paired with the wrong vertices after sorting the vertices by y",
                    [](const FaceGeometry& g, int x, int y) {
                      const auto& v = g.snapped();
                      std::array<int, 3> o{0, 1, 2};
                      std::stable_sort(o.begin(), o.end(),
                                       [&](int a, int b) { return v[a].y < v[b].y; });
                      std::array<Color, 3> c{};
                      for (int k = 0; k < 3; ++k) c[o[k]] = g.colors()[k];
                      return g.color_at(x, y, Shading::gouraud, c);
                    });
    test_hypothesis(hyp, "flat shading where Gouraud was asked",
                    [](const FaceGeometry& g, int x, int y) {
                      return g.color_at(x, y, Shading::flat);
                    });
  }

  // Stage 12: the colour diagnosis: which usual mistake reproduces the wrong colours?
  void diagnose_colours() {
    if (colour_pixels_.empty()) return;
    std::vector<Hypothesis> hyp;
    if (options_.shading == Shading::flat)
      flat_hypotheses(hyp);
    else
      gouraud_hypotheses(hyp);
    std::stable_sort(hyp.begin(), hyp.end(), [](const Hypothesis& a, const Hypothesis& b) {
      return a.matches > b.matches;
    });
    const auto n = static_cast<std::int64_t>(colour_pixels_.size());
    for (const auto& h : hyp)
      if (2 * h.matches > n)
        report_.colour_diagnosis.push_back(
            fmt::format("{} (explains {} of the {} colour pixels)", h.text, h.matches, n));
    for (std::size_t i : colour_pixels_)
      report_.max_colour_error =
          std::max(report_.max_colour_error,
                   max_diff(report_.reference(px(i), py(i)), image_(px(i), py(i))));
  }

  // Stage 13: the faces most affected, and the missing ones.
  void list_faces() {
    for (const auto& [face, cats] : damage_) {
      FaceDamage d{face, 0, ""};
      std::int64_t top = -1;
      for (const auto& [cat, n] : cats) {
        d.pixels += n;
        if (n > top) top = n, d.category = cat;
      }
      report_.faces.push_back(d);
    }
    std::stable_sort(report_.faces.begin(), report_.faces.end(),
                     [](const FaceDamage& a, const FaceDamage& b) { return a.pixels > b.pixels; });
    if (report_.faces.size() > 5) report_.faces.resize(5);
    // The faces listed are those whose pixels the table counts as `missing_face`: a face hidden
    // everywhere that the painter's order explains is `order`, not missing (the list and the
    // table disagreed).
    std::vector<char> listed(n_faces_, 0);
    for (std::size_t k = 0; k < differing_.size(); ++k)
      if (cats_[k] == "missing_face" && ids_.ids[differing_[k]] >= 0)
        listed[static_cast<std::size_t>(ids_.ids[differing_[k]])] = 1;
    for (std::size_t f = 0; f < n_faces_; ++f)
      if (listed[f]) {
        const auto pixels = ref_pixels_[f];
        report_.missing_faces.push_back(
            {static_cast<int>(f), pixels, faces_[static_cast<int>(f)].shape(static_cast<int>(pixels))});
      }
  }

  // Stage 14: the verdict (diff_verdict.hpp), with what the categories do not hold: the missing
  // pixels' patterns, and where many centres on outlines went to the wrong face, how many of
  // those the closed rule would change (a face-ID render under it).
  void name_mistakes() {
    evidence_.missing_tags = tags_missing_;
    count_row_losses();
    if (static_cast<double>(report_.categories.at("boundary")) >=
        kVerdictShare * static_cast<double>(report_.differing_pixels)) {
      FillOptions closed = options_;
      closed.fill_rule = FillRule::closed;
      const FaceIdImage c = render_face_ids(scene_, closed);
      std::int64_t changed = 0, seen = 0;
      std::vector<char> boundary(ids_.ids.size(), 0);
      for (std::size_t k = 0; k < differing_.size(); ++k)
        boundary[differing_[k]] = cats_[k] == "boundary";
      for (std::size_t i = 0; i < c.ids.size(); ++i)
        if (c.ids[i] != ids_.ids[i]) ++changed, seen += boundary[i];
      evidence_.closed_rule_share =
          changed ? static_cast<double>(seen) / static_cast<double>(changed) : 0.0;
    }
    report_.verdict = diff_verdict(report_, evidence_);
  }

  // Per face of two rows or more, its reference pixels in its first row, its last row and the
  // rows between, and those the image does not show it on (pixels_ runs in y order per face).
  void count_row_losses() {
    for (std::size_t f = 0; f < n_faces_; ++f) {
      if (start_[f + 1] == start_[f]) continue;
      const int first = py(pixels_[start_[f]]), last = py(pixels_[start_[f + 1] - 1]);
      if (first == last) continue;
      for (std::size_t k = start_[f]; k < start_[f + 1]; ++k) {
        const std::size_t i = pixels_[k];
        if (!compared_[i]) continue;
        const int y = py(i);
        auto& rows = y == first ? evidence_.first_rows
                     : y == last ? evidence_.last_rows
                                 : evidence_.middle_rows;
        ++rows.pixels;
        rows.lost += seen_[i] != static_cast<int>(f);
      }
    }
  }

  // Stage 15: a few pixels of each category, explained.
  void explain_examples() {
    for (const char* cat : kCategories)
      for (std::size_t i : first_[cat]) {
        const int x = px(i), y = py(i);
        Example e;
        e.category = cat;
        e.x = x, e.y = y;
        e.expected = report_.reference(x, y).color();
        e.got = image_(x, y).color();
        e.reference_face = ids_.ids[i];
        e.image_face = seen_[i];
        // The faces in question, traced even where their bounding box ends a pixel short of the
        // centre (a span one pixel too wide reaches past it): their row's span and where x falls
        // is the line that matters (it was left out for faces that do not write the pixel).
        e.why = why(scene_, options_, x, y, 1.5).summary({e.reference_face, e.image_face});
        report_.examples.push_back(std::move(e));
      }
  }

  const Scene& scene_;
  const FillOptions& options_;
  const SubmittedImage& submitted_;
  const DiffOptions& dopt_;
  const int W_, H_;
  const double tol_, match_tol_;
  const FillRule rule_;
  DiffReport report_;
  const FaceIdImage ids_;
  const std::vector<double> depth_;
  const FaceGrid grid_;
  Faces faces_;
  const std::size_t n_faces_;

  RgbImage image_;                        // the submitted image, global mistakes undone
  std::vector<unsigned char> compared_;   // the pixels compared (find_global_mistakes)
  std::vector<int> seen_;                 // the face the image shows, per pixel
  std::vector<std::size_t> differing_;
  std::vector<std::size_t> start_, pixels_;  // each face's reference pixels
  std::vector<std::int64_t> own_, ref_pixels_, shown_;
  std::vector<char> missing_, shifted_, widened_;
  std::map<std::string, std::int64_t> tags_missing_, tags_extra_;
  std::map<std::pair<int, int>, double> shares_;
  std::map<int, DepthPlane> planes_;
  std::vector<std::string> cats_;
  std::vector<char> hidden_, ambiguous_;
  std::int64_t order_evidence_ = 0, edge_evidence_ = 0;
  VerdictEvidence evidence_;
  std::map<int, std::map<std::string, std::int64_t>> damage_;
  std::vector<std::size_t> colour_pixels_;
  std::map<std::string, std::vector<std::size_t>> first_;
};

}  // namespace

int category_index(const std::string& name) {
  for (std::size_t i = 0; i < kCategories.size(); ++i)
    if (name == kCategories[i]) return static_cast<int>(i);
  return -1;
}

DiffReport diff(const Scene& scene, const FillOptions& options, const SubmittedImage& submitted,
                const DiffOptions& dopt) {
  return DiffRun(scene, options, submitted, dopt).run();
}

}  // namespace scantrace::grade
