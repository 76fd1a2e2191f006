// `diff` (diff_report.hpp) as a pipeline of stages (diff_stages.hpp): align the image with the
// reference and undo its global mistakes, compare, attribute every differing pixel to the face the
// image shows there, classify it, find the patterns, report. Adding a category is adding a
// classifier to diff_classify.cpp, in the documented order, and a stage if it needs evidence of
// its own.
#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "grade/diff_stages.hpp"
#include "grade/global_mistakes.hpp"
#include "src/painter.hpp"

namespace scantrace::grade {
namespace diff_stages {

double max_diff(Rgb32f a, Rgb32f b) {
  return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}
double max_diff(Color a, Rgb32f b) {
  return max_diff(Rgb32f::from(a), b);
}

FaceGrid::FaceGrid(const Scene& s)
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

DiffScene::DiffScene(const Scene& scene_, const FillOptions& options_, const DiffOptions& dopt_)
    : scene(scene_),
      options(options_),
      dopt(dopt_),
      width(scene_.width),
      height(scene_.height),
      tolerance(dopt_.tolerance),
      match_tolerance(dopt_.tolerance + 0.5 / 255),
      rule(options_.fill_rule),
      ids(render_face_ids(scene_, options_)),
      depth(face_depths(scene_)),
      grid(scene_),
      faces(scene_, options_.subpixel_bits),
      n_faces(scene_.faces.size()) {}

Aligned undo_global_mistakes(const DiffScene& s, const RgbImage& reference,
                             const SubmittedImage& submitted) {
  Aligned a;
  a.global = find_global_mistakes(s.scene, reference, s.ids, submitted, s.tolerance, s.dopt.undo,
                                  a.image, a.compared, a.notes);
  return a;
}

namespace {

// Channel values where floor(255·c) and round(255·c) differ, and which of the two the image holds.
struct EightBit {
  // Values at floor(255·c) / at round(255·c), where those differ.
  std::int64_t truncated = 0, rounded = 0;
  std::int64_t face_values = 0, on_level = 0;  // the faces' channel values, and those k/255
};

// 8-bit values: those of an image file, and those of a float array that holds multiples of
// 1/255 (floor(255·c)/255 written as floats is truncated 8-bit output too).
void count_eight_bit(Rgb32f r, Rgb32f g, bool face, bool eight_bit_input, EightBit& n) {
  for (const auto& [rv, gv] : {std::pair{r.r, g.r}, {r.g, g.g}, {r.b, g.b}}) {
    const double level = 255.0 * gv;
    const bool on_level = std::fabs(level - std::round(level)) < 1e-3;
    n.face_values += face, n.on_level += face && on_level;
    if (!eight_bit_input && !on_level) continue;
    const int round = to_byte(rv), floor = static_cast<int>(std::floor(255.0 * rv + 1e-9));
    const int got = static_cast<int>(std::lround(level));
    if (round == floor) continue;
    if (got == floor)
      ++n.truncated;
    else if (got == round)
      ++n.rounded;
  }
}

}  // namespace

Comparison compare_pixels(const DiffScene& s, const RgbImage& reference, const Aligned& aligned,
                          bool eight_bit_input) {
  Comparison c;
  EightBit counts;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = s.idx(x, y);
      if (!aligned.compared[i]) continue;
      ++c.compared_pixels;
      const Rgb32f r = reference(x, y), g = aligned.image(x, y);
      if (max_diff(r, g) > s.tolerance) c.differing.push_back(i);
      count_eight_bit(r, g, s.ids.ids[i] >= 0, eight_bit_input, counts);
    }
  // The note is for 8-bit input only: an image file, a uint8 array, or a float array whose
  // faces' values are (almost all) multiples of 1/255, floor(255·c)/255 saved as floats. A float
  // render that never went through 8 bits has a few values on a level by chance (617 of the
  // course scene's), which alone must not make the note.
  const bool eight_bit = eight_bit_input || 10 * counts.on_level >= 9 * counts.face_values;
  if (eight_bit && counts.truncated > counts.rounded && counts.truncated > 0)
    c.truncation_note = fmt::format(
        "8-bit truncation instead of rounding: {} channel values are floor(255·c) where "
        "round(255·c) is larger ({} are rounded){}",
        counts.truncated, counts.rounded, c.differing.empty() ? ", within the tolerance" : "");
  return c;
}

}  // namespace diff_stages

using namespace diff_stages;

namespace {

// The report's frame: sizes, the tolerance, every category at zero, the reference render.
DiffReport blank_report(const DiffScene& s, const SubmittedImage& submitted) {
  DiffReport r;
  r.width = s.width, r.height = s.height;
  r.image_width = submitted.pixels.width();
  r.image_height = submitted.pixels.height();
  r.tolerance = s.tolerance;
  for (const char* c : kCategories) r.categories[c] = 0;
  r.reference = render<Rgb32f>(s.scene, s.options);
  return r;
}

}  // namespace

DiffReport diff(const Scene& scene, const FillOptions& options, const SubmittedImage& submitted,
                const DiffOptions& dopt) {
  const DiffScene s(scene, options, dopt);
  DiffReport report = blank_report(s, submitted);
  // Align, and undo the global mistakes.
  Aligned aligned = undo_global_mistakes(s, report.reference, submitted);
  report.global = aligned.global;
  report.notes = aligned.notes;
  // Compare.
  const Comparison cmp = compare_pixels(s, report.reference, aligned, submitted.eight_bit);
  report.compared_pixels = cmp.compared_pixels;
  report.differing_pixels = static_cast<std::int64_t>(cmp.differing.size());
  if (cmp.truncation_note) report.notes.push_back(*cmp.truncation_note);
  // Attribute the pixels to faces.
  const Attribution shown = attribute_pixels(s, aligned, report.reference, cmp);
  const FaceFindings faces = find_face_mistakes(s, cmp, shown);
  // Classify.
  const Classification cls = classify_pixels(s, cmp, shown, faces);
  Tally tally = tally_categories(s, cmp, shown, cls);
  report.categories = tally.counts;
  report.category_map = std::move(tally.category_map);
  report.near_boundary_extra = cls.near_boundary_extra;
  report.near_boundary_missing = cls.near_boundary_missing;
  // Find the patterns.
  report.patterns = find_patterns(cls);
  ColourDiagnosis colours =
      diagnose_colours(s, report.reference, aligned.image, tally.colour_pixels);
  report.colour_diagnosis = std::move(colours.lines);
  report.max_colour_error = colours.max_error;
  FaceLists lists = list_faces(s, cmp, cls, faces, tally);
  report.faces = std::move(lists.most_affected);
  report.missing_faces = std::move(lists.missing);
  // Report: the verdict, and a few pixels of each category explained.
  report.verdict =
      diff_verdict(report, verdict_evidence(s, report, aligned, cmp, shown, faces, cls));
  report.examples = explain_examples(s, report.reference, aligned.image, shown, tally);
  return report;
}

}  // namespace scantrace::grade
