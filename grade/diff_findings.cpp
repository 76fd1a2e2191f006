// diff's last stages (diff_stages.hpp): from the categories to the report: counts, dominant
// patterns, the colour diagnosis, the faces hit, the verdict's evidence and a few pixels explained.
#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "grade/diff_stages.hpp"
#include "grade/pixel_story.hpp"

namespace scantrace::grade::diff_stages {

Tally tally_categories(const DiffScene& s, const Comparison& cmp, const Attribution& shown,
                       const Classification& cls) {
  Tally t;
  for (const char* c : kCategories) t.counts[c] = 0;
  t.category_map.assign(static_cast<std::size_t>(s.width) * s.height, 0);
  for (std::size_t k = 0; k < cmp.differing.size(); ++k) {
    const std::size_t i = cmp.differing[k];
    const int R = s.ids.ids[i], I = shown.seen[i];
    const Category cat = cls.categories[k];
    const char* name = category_name(cat);
    ++t.counts[name];
    t.category_map[i] = static_cast<std::uint8_t>(1 + static_cast<int>(cat));
    if (cat == Category::colour) t.colour_pixels.push_back(i);
    const int blamed = R >= 0 ? R : I;
    if (blamed >= 0) ++t.damage[blamed][name];
    auto& examples = t.examples[static_cast<std::size_t>(cat)];
    if (static_cast<int>(examples.size()) < s.dopt.examples_per_category) examples.push_back(i);
  }
  return t;
}

std::vector<std::string> find_patterns(const Classification& cls) {
  std::vector<std::string> out;
  const auto dominant = [&](const std::map<std::string, std::int64_t>& tags, std::int64_t total,
                            const char* what) {
    for (const auto& [text, n] : tags)
      if (total > 0 && 2 * n > total)
        out.push_back(fmt::format("{}: {} on {:.0f} % of the {} pixels", what, text,
                                  100.0 * n / total, what));
  };
  dominant(cls.tags_missing, cls.near_boundary_missing, "missing");
  dominant(cls.tags_extra, cls.near_boundary_extra, "extra");
  return out;
}

namespace {

// A usual colour mistake, and how many of the `colour` pixels it reproduces.
struct Hypothesis {
  std::string text;
  std::int64_t matches = 0;
};

// The hypotheses of the colour diagnosis, tried on the `colour` pixels.
class ColourHypotheses {
 public:
  ColourHypotheses(const DiffScene& s, const RgbImage& image, const std::vector<std::size_t>& px)
      : s_(s), image_(image), pixels_(px) {}

  std::vector<Hypothesis> flat() {
    static constexpr const char* kOrdinal[3] = {"first", "second", "third"};
    for (int k = 0; k < 3; ++k)
      test(fmt::format("flat colour is the {} vertex's colour, not the mean of the three",
                       kOrdinal[k]),
           [k](const FaceGeometry& g, int, int) { return g.colors()[k]; });
    test("Gouraud shading where flat was asked",
         [](const FaceGeometry& g, int x, int y) { return g.color_at(x, y, Shading::gouraud); });
    return std::move(out_);
  }

  std::vector<Hypothesis> gouraud() {
    static constexpr int kPerms[5][3] = {{1, 0, 2}, {0, 2, 1}, {2, 1, 0}, {1, 2, 0}, {2, 0, 1}};
    for (const auto& p : kPerms)
      test(fmt::format("Gouraud with the vertex colours permuted: vertices 0, 1, 2 get "
                       "the colours of {}, {}, {}",
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
    return std::move(out_);
  }

 private:
  template <class ColourOf>
  void test(const std::string& text, ColourOf&& colour_of) {
    Hypothesis h{text, 0};
    for (std::size_t i : pixels_) {
      const int x = s_.px(i), y = s_.py(i);
      if (max_diff(colour_of(s_.faces[s_.ids.ids[i]], x, y), image_(x, y)) <= s_.match_tolerance)
        ++h.matches;
    }
    out_.push_back(h);
  }

  const DiffScene& s_;
  const RgbImage& image_;
  const std::vector<std::size_t>& pixels_;
  std::vector<Hypothesis> out_;
};

}  // namespace

ColourDiagnosis diagnose_colours(const DiffScene& s, const RgbImage& reference,
                                 const RgbImage& image, const std::vector<std::size_t>& colour) {
  ColourDiagnosis d;
  if (colour.empty()) return d;
  ColourHypotheses tried(s, image, colour);
  std::vector<Hypothesis> hyp = s.options.shading == Shading::flat ? tried.flat() : tried.gouraud();
  std::stable_sort(hyp.begin(), hyp.end(),
                   [](const Hypothesis& a, const Hypothesis& b) { return a.matches > b.matches; });
  const auto n = static_cast<std::int64_t>(colour.size());
  for (const auto& h : hyp)
    if (2 * h.matches > n)
      d.lines.push_back(
          fmt::format("{} (explains {} of the {} colour pixels)", h.text, h.matches, n));
  for (std::size_t i : colour)
    d.max_error =
        std::max(d.max_error, max_diff(reference(s.px(i), s.py(i)), image(s.px(i), s.py(i))));
  return d;
}

FaceLists list_faces(const DiffScene& s, const Comparison& cmp, const Classification& cls,
                     const FaceFindings& faces, const Tally& tally) {
  FaceLists out;
  for (const auto& [face, cats] : tally.damage) {
    // The most frequent category; of equal counts, the first name in alphabetical order.
    FaceDamage d{face, 0, ""};
    std::int64_t top = -1;
    for (const auto& [cat, n] : cats) {
      d.pixels += n;
      if (n > top) top = n, d.category = cat;
    }
    out.most_affected.push_back(d);
  }
  std::stable_sort(out.most_affected.begin(), out.most_affected.end(),
                   [](const FaceDamage& a, const FaceDamage& b) { return a.pixels > b.pixels; });
  if (out.most_affected.size() > 5) out.most_affected.resize(5);
  // The faces listed are those whose pixels the table counts as `missing_face`, so the list and
  // the table agree: a face hidden everywhere that the painter's order explains is `order`.
  std::vector<char> listed(s.n_faces, 0);
  for (std::size_t k = 0; k < cmp.differing.size(); ++k)
    if (cls.categories[k] == Category::missing_face && s.ids.ids[cmp.differing[k]] >= 0)
      listed[static_cast<std::size_t>(s.ids.ids[cmp.differing[k]])] = 1;
  for (std::size_t f = 0; f < s.n_faces; ++f)
    if (listed[f]) {
      const auto pixels = faces.ref_pixels[f];
      const int face = static_cast<int>(f);
      out.missing.push_back({face, pixels, s.faces[face].shape(static_cast<int>(pixels))});
    }
  return out;
}

namespace {

// Per face of two rows or more, its reference pixels in its first row, its last row and the
// rows between, and those the image does not show it on (FacePixels run in y order per face).
void count_row_losses(const DiffScene& s, const Aligned& aligned, const Attribution& shown,
                      VerdictEvidence& e) {
  const FacePixels& ref = shown.reference;
  for (std::size_t f = 0; f < s.n_faces; ++f) {
    if (ref.count(f) == 0) continue;
    const int first = s.py(ref.pixels[ref.start[f]]), last = s.py(ref.pixels[ref.start[f + 1] - 1]);
    if (first == last) continue;
    for (std::size_t k = ref.start[f]; k < ref.start[f + 1]; ++k) {
      const std::size_t i = ref.pixels[k];
      if (!aligned.compared[i]) continue;
      const int y = s.py(i);
      auto& rows = y == first ? e.first_rows : y == last ? e.last_rows : e.middle_rows;
      ++rows.pixels;
      rows.lost += shown.seen[i] != static_cast<int>(f);
    }
  }
}

// Of the pixels a face-ID render under the closed rule changes, the share the image shows as
// `boundary`.
double closed_rule_share(const DiffScene& s, const Comparison& cmp, const Classification& cls) {
  FillOptions closed = s.options;
  closed.fill_rule = FillRule::closed;
  const FaceIdImage c = render_face_ids(s.scene, closed);
  std::int64_t changed = 0, seen = 0;
  std::vector<char> boundary(s.ids.ids.size(), 0);
  for (std::size_t k = 0; k < cmp.differing.size(); ++k)
    boundary[cmp.differing[k]] = cls.categories[k] == Category::boundary;
  for (std::size_t i = 0; i < c.ids.size(); ++i)
    if (c.ids[i] != s.ids.ids[i]) ++changed, seen += boundary[i];
  return changed ? static_cast<double>(seen) / static_cast<double>(changed) : 0.0;
}

}  // namespace

// The missing pixels' patterns, the spans' extensions, the rows lost, and where many centres on
// outlines went to the wrong face, how many of those the closed rule would change.
VerdictEvidence verdict_evidence(const DiffScene& s, const DiffReport& report,
                                 const Aligned& aligned, const Comparison& cmp,
                                 const Attribution& shown, const FaceFindings& faces,
                                 const Classification& cls) {
  VerdictEvidence e;
  e.extended_left = faces.extended_left, e.extended_right = faces.extended_right;
  e.extended_off_outline = faces.extended_off_outline;
  e.extended_beyond_half = faces.extended_beyond_half;
  e.missing_tags = cls.tags_missing;
  count_row_losses(s, aligned, shown, e);
  if (static_cast<double>(report.categories.at(category_name(Category::boundary))) >=
      kVerdictShare * static_cast<double>(report.differing_pixels))
    e.closed_rule_share = closed_rule_share(s, cmp, cls);
  return e;
}

std::vector<Example> explain_examples(const DiffScene& s, const RgbImage& reference,
                                      const RgbImage& image, const Attribution& shown,
                                      const Tally& tally) {
  std::vector<Example> out;
  for (std::size_t c = 0; c < kCategoryCount; ++c)
    for (std::size_t i : tally.examples[c]) {
      const int x = s.px(i), y = s.py(i);
      Example e;
      e.category = kCategories[c];
      e.x = x, e.y = y;
      e.expected = reference(x, y).color();
      e.got = image(x, y).color();
      e.reference_face = s.ids.ids[i];
      e.image_face = shown.seen[i];
      // The faces in question, traced even where their bounding box ends a pixel short of the
      // centre (a span one pixel too wide reaches past it): their row's span and where x falls
      // is the line that matters, also for a face that does not write the pixel.
      e.why = why(s.scene, s.options, x, y, 1.5).summary({e.reference_face, e.image_face});
      out.push_back(std::move(e));
    }
  return out;
}

}  // namespace scantrace::grade::diff_stages
