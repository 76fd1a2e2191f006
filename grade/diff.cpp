// The pixel classification of `diff` (diff_report.hpp): global mistakes are found and undone by
// global_mistakes.cpp; here every remaining differing pixel is matched against the faces around it
// and given the first category that applies.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <spdlog/fmt/fmt.h>

#include "grade/diff_report.hpp"
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

}  // namespace

int category_index(const std::string& name) {
  for (std::size_t i = 0; i < kCategories.size(); ++i)
    if (name == kCategories[i]) return static_cast<int>(i);
  return -1;
}

DiffReport diff(const Scene& scene, const FillOptions& options, const SubmittedImage& submitted,
                const DiffOptions& dopt) {
  DiffReport report;
  const int W = scene.width, H = scene.height;
  const double tol = dopt.tolerance;
  // Matching a colour to a face allows for the image's own 8-bit rounding on top of the tolerance.
  const double match_tol = tol + 0.5 / 255;
  report.width = W, report.height = H;
  report.image_width = submitted.pixels.width(), report.image_height = submitted.pixels.height();
  report.tolerance = tol;
  for (const char* c : kCategories) report.categories[c] = 0;
  report.reference = render<Rgb32f>(scene, options);
  const FaceIdImage ids = render_face_ids(scene, options);
  const std::vector<double> depth = face_depths(scene);
  const FillRule rule = options.fill_rule;

  RgbImage image;
  std::vector<unsigned char> compared;
  report.global = find_global_mistakes(scene, report.reference, ids, submitted, tol, dopt.undo,
                                       image, compared);
  const auto idx = [W](int x, int y) { return static_cast<std::size_t>(y) * W + x; };

  // Which pixels differ, and the 8-bit truncation note.
  std::vector<int> seen(static_cast<std::size_t>(W) * H, kNoFace);  // the image's face per pixel
  std::vector<std::size_t> differing;
  std::int64_t truncated = 0, rounded = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = idx(x, y);
      if (!compared[i]) continue;
      ++report.compared_pixels;
      const Rgb32f r = report.reference(x, y), g = image(x, y);
      if (max_diff(r, g) > tol) {
        differing.push_back(i);
      } else {
        seen[i] = ids.ids[i];
      }
      // 8-bit values: those of an image file, and those of a float array that holds multiples of
      // 1/255 (floor(255·c)/255 written as floats had no note, issue 36).
      for (const auto& [rv, gv] : {std::pair{r.r, g.r}, {r.g, g.g}, {r.b, g.b}}) {
        const double level = 255.0 * gv;
        if (!submitted.eight_bit && !(std::fabs(level - std::round(level)) < 1e-3)) continue;
        const int round = to_byte(rv), floor = static_cast<int>(std::floor(255.0 * rv + 1e-9));
        const int got = static_cast<int>(std::lround(level));
        if (round == floor) continue;
        if (got == floor)
          ++truncated;
        else if (got == round)
          ++rounded;
      }
    }
  report.differing_pixels = static_cast<std::int64_t>(differing.size());
  if (truncated > rounded && truncated > 0)
    report.notes.push_back(fmt::format(
        "8-bit truncation instead of rounding: {} channel values are floor(255·c) where "
        "round(255·c) is larger ({} are rounded){}",
        truncated, rounded, report.differing_pixels == 0 ? ", within the tolerance" : ""));

  // Which face does the image show at each differing pixel?
  const FaceGrid grid(scene);
  Faces faces(scene, options.subpixel_bits);
  const Rgb32f background = Rgb32f::from(scene.background);
  for (std::size_t i : differing) {
    const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
    const Rgb32f got = image(x, y);
    int best = kNoFace;
    double best_err = match_tol;
    bool best_covers = false;
    for (int f : grid.at(x, y)) {
      const FaceGeometry& g = faces[f];
      if (!g.within(x, y, 1.5)) continue;
      const double err = max_diff(g.color_at(x, y, options.shading), got);
      if (err > match_tol) continue;
      const bool covers = f != ids.ids[i] && g.covers(x, y, FillRule::closed);
      if ((covers && !best_covers) || (covers == best_covers && err < best_err - 1e-7))
        best = f, best_err = err, best_covers = covers;
    }
    const double bg_err = max_diff(got, background);
    if (bg_err <= tol && (best == kNoFace || bg_err <= best_err)) best = kBackground;
    seen[i] = best;
  }

  const std::size_t n_faces = scene.faces.size();
  // Pixels of each face in the reference (counting sort by face id).
  std::vector<std::size_t> start(n_faces + 1, 0);
  for (int id : ids.ids)
    if (id >= 0) ++start[static_cast<std::size_t>(id) + 1];
  for (std::size_t f = 0; f < n_faces; ++f) start[f + 1] += start[f];
  std::vector<std::size_t> pixels(start[n_faces]), fill = start;
  for (std::size_t i = 0; i < ids.ids.size(); ++i)
    if (ids.ids[i] >= 0) pixels[fill[static_cast<std::size_t>(ids.ids[i])]++] = i;

  // A flat face painted all over in one wrong colour (the first vertex's colour instead of the
  // mean, say) shows that colour on every one of its pixels. Where a neighbour's colour happens
  // to match it, the neighbour would be taken for the face shown — but a face drawn over this one
  // covers its pixels, and one drawn too wide reaches only some of them. So when all of a face's
  // pixels show one colour, not its own, and the face matched does not cover them, the image shows
  // this face in the wrong colour.
  // (A neighbour shown right on most of its own pixels is not such a coincidence: it reached
  // over, as a span one pixel too wide does.)
  std::vector<std::int64_t> own(n_faces, 0);
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (ids.ids[i] >= 0 && seen[i] == ids.ids[i]) ++own[static_cast<std::size_t>(ids.ids[i])];
  const auto shown_right = [&](int f) {
    const auto u = static_cast<std::size_t>(f);
    return 2 * own[u] > static_cast<std::int64_t>(start[u + 1] - start[u]);
  };
  if (options.shading == Shading::flat)
    for (std::size_t f = 0; f < n_faces; ++f) {
      if (start[f + 1] - start[f] < 2) continue;
      const std::size_t p0 = pixels[start[f]];
      bool uniform = true;
      for (std::size_t k = start[f]; k < start[f + 1] && uniform; ++k)
        uniform = compared[pixels[k]] &&
                  max_diff(image(static_cast<int>(pixels[k] % W), static_cast<int>(pixels[k] / W)),
                           image(static_cast<int>(p0 % W), static_cast<int>(p0 / W))) == 0;
      if (!uniform || max_diff(report.reference(static_cast<int>(p0 % W), static_cast<int>(p0 / W)),
                               image(static_cast<int>(p0 % W), static_cast<int>(p0 / W))) <= tol)
        continue;
      for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
        const std::size_t i = pixels[k];
        const int I = seen[i];
        if (I >= 0 && !shown_right(I) &&
            !faces[I].covers(static_cast<int>(i % W), static_cast<int>(i / W), FillRule::closed))
          seen[i] = kNoFace;
      }
    }

  // Faces shown nowhere in the image, and faces shown translated by one pixel.
  std::vector<std::int64_t> ref_pixels(n_faces, 0), shown(n_faces, 0);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (ids.ids[i] >= 0) ++ref_pixels[static_cast<std::size_t>(ids.ids[i])];
    if (seen[i] >= 0) ++shown[static_cast<std::size_t>(seen[i])];
  }
  std::vector<char> missing(n_faces, 0), shifted(n_faces, 0);
  for (std::size_t f = 0; f < n_faces; ++f) missing[f] = ref_pixels[f] > 0 && shown[f] == 0;
  {
    std::vector<char> touched(n_faces, 0);
    for (std::size_t i : differing) {
      if (ids.ids[i] >= 0) touched[static_cast<std::size_t>(ids.ids[i])] = 1;
      if (seen[i] >= 0) touched[static_cast<std::size_t>(seen[i])] = 1;
    }
    constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
    for (std::size_t f = 0; f < n_faces; ++f) {
      if (!touched[f] || shown[f] < 3 || ref_pixels[f] < 3) continue;
      std::int64_t same = 0, best = 0;
      for (std::size_t k = start[f]; k < start[f + 1]; ++k)
        same += seen[pixels[k]] == static_cast<int>(f);
      for (int d = 0; d < 4; ++d) {
        std::int64_t n = 0;
        for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
          const int x = static_cast<int>(pixels[k] % W) + kDx[d],
                    y = static_cast<int>(pixels[k] / W) + kDy[d];
          n += x >= 0 && y >= 0 && x < W && y < H && seen[idx(x, y)] == static_cast<int>(f);
        }
        best = std::max(best, n);
      }
      shifted[f] = best > same && 2 * best >= shown[f];
    }
  }

  // Classify.
  report.category_map.assign(static_cast<std::size_t>(W) * H, 0);
  std::map<std::string, std::int64_t> tags_missing, tags_extra;
  std::map<int, std::map<std::string, std::int64_t>> damage;
  std::vector<std::size_t> colour_pixels;
  std::map<std::string, std::vector<std::size_t>> first;
  const auto tag_missing = [&](const FaceGeometry& g, int x, int y) {
    if (!g.covers(x + 1, y, rule)) ++tags_missing["the right end of the span is one pixel short"];
    if (!g.covers(x - 1, y, rule)) ++tags_missing["the left end of the span is one pixel short"];
    if (!g.covers(x, y + 1, rule)) ++tags_missing["the bottom row of the face is missing"];
    if (!g.covers(x, y - 1, rule)) ++tags_missing["the top row of the face is missing"];
  };
  // The other fill rule: the image paints a face on its own outline where the rule does not give
  // it the centre (the closed rule, a face drawn with all its edge pixels), so that of two faces
  // whose outlines pass through the centre the wrong one keeps it. A face missing everywhere is
  // not a matter of the rule.
  const auto on_boundary = [&](int R, int I, int x, int y) {
    const bool I_on = I >= 0 && faces[I].on_outline(x, y) != OnOutline::no;
    if (I_on && !faces[I].covers(x, y, rule)) return true;
    const bool R_on = R >= 0 && faces[R].on_outline(x, y) != OnOutline::no;
    return R_on && I_on && !missing[static_cast<std::size_t>(R)];
  };
  // Of the pixels where the reference shows R, I covers them too, and the image shows one of the
  // two, the share it gives to I (1: the whole overlap is painted over; a third face on top of
  // part of it does not count).
  std::map<std::pair<int, int>, double> shares;
  const auto pair_share = [&](int I, int R) {
    const auto [it, fresh] = shares.try_emplace({I, R}, 0.0);
    if (fresh) {
      std::int64_t overlap = 0, shows = 0;
      for (std::size_t k = start[static_cast<std::size_t>(R)];
           k < start[static_cast<std::size_t>(R) + 1]; ++k) {
        const std::size_t p = pixels[k];
        if (seen[p] != I && seen[p] != R) continue;
        if (!faces[I].covers(static_cast<int>(p % W), static_cast<int>(p / W), rule)) continue;
        ++overlap;
        shows += seen[p] == I;
      }
      it->second = overlap ? static_cast<double>(shows) / static_cast<double>(overlap) : 0.0;
    }
    return it->second;
  };
  // Which face wins at (x, y) in the reference's visibility: the painter's order of mean depths,
  // or the z-buffer's depth test at that pixel (zbuffer_canvas.hpp: the nearer wins, a tie keeps
  // the face drawn first).
  std::map<int, DepthPlane> planes;
  const auto depth_at = [&](int f, int x, int y) {
    auto it = planes.find(f);
    if (it == planes.end()) {
      const auto& v = scene.faces[static_cast<std::size_t>(f)];
      const std::array<double, 3> d{scene.depth[v[0]], scene.depth[v[1]], scene.depth[v[2]]};
      it = planes.emplace(f, DepthPlane::through(faces[f].snapped(), d)).first;
    }
    return it->second.at(x, y);
  };
  const auto order_category = [&](int I, int R, int x, int y) -> const char* {
    if (options.visibility == Visibility::zbuffer) {
      const double dI = depth_at(I, x, y), dR = depth_at(R, x, y);
      if (dI == dR || static_cast<float>(dI) == static_cast<float>(dR)) return "order_tie";
      return dI > dR ? "order" : "other";
    }
    const bool drawn_before = depth[I] > depth[R] || (depth[I] == depth[R] && I < R);
    const bool tie =
        depth[I] == depth[R] || static_cast<float>(depth[I]) == static_cast<float>(depth[R]);
    return tie ? "order_tie" : drawn_before ? "order" : "other";
  };
  std::vector<std::string> cats(differing.size());
  // Pixels of a missing face that show a face drawn earlier and covering them: a skipped face or
  // a face painted over everywhere — the rest of the image decides which (below).
  std::vector<char> hidden(differing.size(), 0);
  std::int64_t order_evidence = 0, edge_evidence = 0;
  std::vector<char> ambiguous(differing.size(), 0);
  for (std::size_t k = 0; k < differing.size(); ++k) {
    const std::size_t i = differing[k];
    const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
    const int R = ids.ids[i], I = seen[i];
    std::string& cat = cats[k];
    if (I >= 0 && faces[I].degenerate()) {
      cat = "degenerate_drawn";
    } else if (I == kNoFace || I == R) {
      cat = R >= 0 ? "colour" : "background";
    } else if (on_boundary(R, I, x, y)) {
      cat = "boundary";
    } else if ((R >= 0 && shifted[static_cast<std::size_t>(R)]) ||
               (I >= 0 && shifted[static_cast<std::size_t>(I)])) {
      cat = "shifted";
    } else if (R >= 0 && missing[static_cast<std::size_t>(R)]) {
      cat = "missing_face";
      hidden[k] = I >= 0 && faces[I].covers(x, y, rule) &&
                  std::string(order_category(I, R, x, y)) != "other";
    } else if (I >= 0 && R >= 0 && faces[I].covers(x, y, rule)) {
      // The image shows a face that does cover the pixel. Painted over in the wrong order, the
      // whole overlap of the two faces shows it; a face that lost its edge pixels (a row or a
      // span end dropped) shows the face below only near its outline.
      // Where the two overlap only near R's outline (R's last row over the face below, say),
      // both readings fit; the rest of the image decides (below).
      const bool near_outline = faces[R].distance_to_outline(x, y) <= 1.0;
      if (near_outline && pair_share(I, R) < 1.0) {
        cat = "near_boundary";
        ++report.near_boundary_missing;
        tag_missing(faces[R], x, y);
        ++edge_evidence;
      } else {
        cat = order_category(I, R, x, y);
        ambiguous[k] = near_outline && cat != "other";
        if (!near_outline) order_evidence += cat != "other";
      }
    } else if (I >= 0 && faces[I].distance_to_outline(x, y) <= 1.0) {
      cat = "near_boundary";
      ++report.near_boundary_extra;
      const FaceGeometry& g = faces[I];
      if (g.covers(x - 1, y, rule)) ++tags_extra["right of the span's end (one pixel too wide)"];
      if (g.covers(x + 1, y, rule)) ++tags_extra["left of the span's start (one pixel too wide)"];
      if (g.covers(x, y - 1, rule)) ++tags_extra["below the face's last row"];
      if (g.covers(x, y + 1, rule)) ++tags_extra["above the face's first row"];
    } else if (I == kBackground && R >= 0 && faces[R].distance_to_outline(x, y) <= 1.0) {
      cat = "near_boundary";
      ++report.near_boundary_missing;
      tag_missing(faces[R], x, y);
    } else if ((I == kBackground && R >= 0) || (I >= 0 && R < 0)) {
      cat = "background";
    } else {
      cat = "other";
    }
  }
  // When faces that are partly visible show the wrong painter's order on a good share of the
  // differing pixels, the faces hidden everywhere were painted over too, not skipped.
  // So are they when most of the faces the reference shows are hidden: no usual special case
  // loses most faces, painting nearest first does.
  std::int64_t n_missing = 0, n_visible = 0;
  for (std::size_t f = 0; f < n_faces; ++f) n_missing += missing[f], n_visible += ref_pixels[f] > 0;
  // Pixels where a face covering them shows only near the outline of the face the reference
  // shows: lost edge pixels when that is what the clear cases show (a face's last row dropped
  // everywhere), the painter's order otherwise.
  // (Faces hidden everywhere count for the order: lost edge pixels hide only faces a row high.)
  std::int64_t n_hidden = 0;
  for (char h : hidden) n_hidden += h;
  const bool edge_mistake = edge_evidence > order_evidence + n_hidden;
  for (std::size_t k = 0; k < differing.size(); ++k)
    if (ambiguous[k]) {
      if (edge_mistake) {
        const std::size_t i = differing[k];
        cats[k] = "near_boundary";
        ++report.near_boundary_missing;
        tag_missing(faces[ids.ids[i]], static_cast<int>(i % W), static_cast<int>(i / W));
      } else {
        ++order_evidence;
      }
    }
  const bool order_mistake = 5 * order_evidence >= static_cast<std::int64_t>(differing.size()) ||
                             2 * n_missing >= n_visible;
  for (std::size_t k = 0; k < differing.size(); ++k) {
    const std::size_t i = differing[k];
    const int R = ids.ids[i], I = seen[i];
    if (hidden[k] && order_mistake)
      cats[k] = order_category(I, R, static_cast<int>(i % W), static_cast<int>(i / W));
    const std::string& cat = cats[k];
    ++report.categories[cat];
    report.category_map[i] = static_cast<std::uint8_t>(1 + category_index(cat));
    if (cat == "colour") colour_pixels.push_back(i);
    const int blamed = R >= 0 ? R : I;
    if (blamed >= 0) ++damage[blamed][cat];
    auto& examples = first[cat];
    if (static_cast<int>(examples.size()) < dopt.examples_per_category) examples.push_back(i);
  }

  // Dominant near-boundary patterns.
  const auto dominant = [&](const std::map<std::string, std::int64_t>& tags, std::int64_t total,
                            const char* what) {
    for (const auto& [text, n] : tags)
      if (total > 0 && 2 * n > total)
        report.patterns.push_back(fmt::format("{}: {} on {:.0f} % of the {} pixels", what, text,
                                              100.0 * n / total, what));
  };
  dominant(tags_missing, report.near_boundary_missing, "missing");
  dominant(tags_extra, report.near_boundary_extra, "extra");

  // The colour diagnosis: which usual mistake reproduces the wrong colours?
  if (!colour_pixels.empty()) {
    std::vector<Hypothesis> hyp;
    const auto test = [&](const std::string& text, auto&& colour_of) {
      Hypothesis h{text, 0};
      for (std::size_t i : colour_pixels) {
        const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
        if (max_diff(colour_of(faces[ids.ids[i]], x, y), image(x, y)) <= match_tol) ++h.matches;
      }
      hyp.push_back(h);
    };
    static constexpr const char* kOrdinal[3] = {"first", "second", "third"};
    if (options.shading == Shading::flat) {
      for (int k = 0; k < 3; ++k)
        test(fmt::format("flat colour is the {} vertex's colour, not the mean of the three",
                         kOrdinal[k]),
             [k](const FaceGeometry& g, int, int) { return g.colors()[k]; });
      test("Gouraud shading where flat was asked",
           [](const FaceGeometry& g, int x, int y) { return g.color_at(x, y, Shading::gouraud); });
    } else {
      static constexpr int kPerms[5][3] = {{1, 0, 2}, {0, 2, 1}, {2, 1, 0}, {1, 2, 0}, {2, 0, 1}};
      for (const auto& p : kPerms)
        test(fmt::format("Gouraud with the vertex colours permuted: vertices 0, 1, 2 get the "
                         "colours of {}, {}, {}",
                         p[0], p[1], p[2]),
             [&p](const FaceGeometry& g, int x, int y) {
               const auto& c = g.colors();
               return g.color_at(x, y, Shading::gouraud, {c[p[0]], c[p[1]], c[p[2]]});
             });
      test("colours paired with the wrong vertices after sorting the vertices by y",
           [](const FaceGeometry& g, int x, int y) {
             const auto& v = g.snapped();
             std::array<int, 3> o{0, 1, 2};
             std::stable_sort(o.begin(), o.end(), [&](int a, int b) { return v[a].y < v[b].y; });
             std::array<Color, 3> c{};
             for (int k = 0; k < 3; ++k) c[o[k]] = g.colors()[k];
             return g.color_at(x, y, Shading::gouraud, c);
           });
      test("flat shading where Gouraud was asked",
           [](const FaceGeometry& g, int x, int y) { return g.color_at(x, y, Shading::flat); });
    }
    std::stable_sort(hyp.begin(), hyp.end(), [](const Hypothesis& a, const Hypothesis& b) {
      return a.matches > b.matches;
    });
    const auto n = static_cast<std::int64_t>(colour_pixels.size());
    for (const auto& h : hyp)
      if (2 * h.matches > n)
        report.colour_diagnosis.push_back(
            fmt::format("{} (explains {} of the {} colour pixels)", h.text, h.matches, n));
    for (std::size_t i : colour_pixels)
      report.max_colour_error =
          std::max(report.max_colour_error,
                   max_diff(report.reference(static_cast<int>(i % W), static_cast<int>(i / W)),
                            image(static_cast<int>(i % W), static_cast<int>(i / W))));
  }

  // The faces most affected, and the missing ones.
  for (const auto& [face, cats] : damage) {
    FaceDamage d{face, 0, ""};
    std::int64_t top = -1;
    for (const auto& [cat, n] : cats) {
      d.pixels += n;
      if (n > top) top = n, d.category = cat;
    }
    report.faces.push_back(d);
  }
  std::stable_sort(report.faces.begin(), report.faces.end(),
                   [](const FaceDamage& a, const FaceDamage& b) { return a.pixels > b.pixels; });
  if (report.faces.size() > 5) report.faces.resize(5);
  for (std::size_t f = 0; f < n_faces; ++f)
    if (missing[f]) {
      const auto pixels = ref_pixels[f];
      report.missing_faces.push_back({static_cast<int>(f), pixels,
                                      faces[static_cast<int>(f)].shape(static_cast<int>(pixels))});
    }

  // A few pixels of each category, explained.
  for (const char* cat : kCategories)
    for (std::size_t i : first[cat]) {
      const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
      Example e;
      e.category = cat;
      e.x = x, e.y = y;
      e.expected = report.reference(x, y).color();
      e.got = image(x, y).color();
      e.reference_face = ids.ids[i];
      e.image_face = seen[i];
      e.why = why(scene, options, x, y).summary();
      report.examples.push_back(std::move(e));
    }
  return report;
}

}  // namespace scantrace::grade
