#include "grade/diff_verdict.hpp"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "grade/mistake_catalogue.hpp"

namespace scantrace::grade {
namespace {

class Verdicts {
 public:
  Verdicts(const DiffReport& r, const VerdictEvidence& e) : r_(r), e_(e) {}

  std::vector<Verdict> run() {
    for (const auto& g : r_.global) name_if_known(g.kind, g.text);
    if (r_.differing_pixels == 0) return std::move(out_);
    explained_ = false;
    const std::string wide = spans_too_wide();
    order();
    rows();
    moved(wide);
    if (wide.empty()) outline();  // a span too wide puts its right end on outlines: not another rule
    missing_faces();
    colours();
    if (at(Category::degenerate_drawn) >= share())
      name("degenerate_drawn", count(Category::degenerate_drawn));
    if (!explained_)
      out_.push_back({"", "no usual mistake explains most of the differing pixels",
                      "the categories below say where they are"});
    return std::move(out_);
  }

 private:
  std::int64_t at(Category c) const { return r_.categories.at(category_name(c)); }
  double share() const { return kVerdictShare * static_cast<double>(r_.differing_pixels); }
  std::string count(Category c) const {
    return fmt::format("{} of the {} differing pixels are `{}`", at(c), r_.differing_pixels,
                       category_name(c));
  }

  void name(const std::string& id, std::string evidence) {
    out_.push_back({id, catalogue_mistake(id).verdict, std::move(evidence)});
    explained_ = true;
  }
  void name_if_known(const std::string& id, const std::string& evidence) {
    for (const auto& m : mistake_catalogue())
      if (m.id == id && !m.verdict.empty()) return name(id, evidence);
  }

  // Extra pixels on both ends of the spans (a face moved sideways gains on one side only, the
  // closed rule on the right end only): floor(x_L) .. ceil(x_R), or span ends rounded to the
  // nearest pixel when no extra pixel is more than half a pixel from its face.
  // Returns the words for the mistake named ("" for none).
  std::string spans_too_wide() {
    const std::int64_t L = e_.extended_left, R = e_.extended_right;
    if (!(static_cast<double>(L + R) >= share() && 4 * std::min(L, R) >= L + R)) return "";
    const bool rounded = 10 * e_.extended_beyond_half < e_.extended_off_outline;
    name(rounded ? "span_end_rounding" : "span_too_wide",
         fmt::format("{} pixels show a face left of its span's start and {} right of its end; "
                     "of the {} not on its outline, {} are more than half a pixel from it; {} "
                     "near-boundary pixels are missing",
                     L, R, e_.extended_off_outline, e_.extended_beyond_half,
                     r_.near_boundary_missing));
    return rounded ? "span ends rounded" : "spans one pixel too wide";
  }

  void order() {
    const std::int64_t o = at(Category::order), t = at(Category::order_tie);
    if (static_cast<double>(o + t) < share()) return;
    name(t > o ? "order_unstable_on_ties" : "order_reversed",
         fmt::format("{} of the {} differing pixels show a face the reference paints earlier",
                     o + t, r_.differing_pixels));
  }

  // A row lost: the faces' last (first) rows are mostly not shown, the rows between mostly are
  // (a face painted over loses all its rows; one moved or widened loses a pixel of each). Else a
  // pattern of the missing near-boundary pixels: the span's right end.
  void rows() {
    using Rows = VerdictEvidence::Rows;
    const auto lost_row = [&](const Rows& row, const char* id, const char* which) {
      if (!(row.share() >= 0.5 && 4 * e_.middle_rows.share() <= row.share() &&
            static_cast<double>(row.lost) >= share() / 2))
        return false;
      name(id, fmt::format("the image leaves out {} of the {} pixels of the faces' {} rows, "
                           "{:.0f} % of the rows between",
                           row.lost, row.pixels, which, 100 * e_.middle_rows.share()));
      return true;
    };
    const bool bottom = lost_row(e_.last_rows, "bottom_row_dropped", "last");
    const bool top = lost_row(e_.first_rows, "top_row_dropped", "first");
    const std::int64_t n = r_.near_boundary_missing;
    const char* tag = "the right end of the span is one pixel short";
    const auto it = e_.missing_tags.find(tag);
    if (!bottom && !top && static_cast<double>(n) >= share() && it != e_.missing_tags.end() &&
        2 * it->second > n)
      name("right_end_excluded",
           fmt::format("{} of the {} missing near-boundary pixels: {}", it->second, n, tag));
  }

  // Faces moved by one pixel; and what the image cannot tell.
  void moved(const std::string& wide) {
    const std::int64_t s = at(Category::shifted);
    const std::string settle =
        "`scantrace grade` on the code settles it: its probes fill one triangle at a time";
    if (!wide.empty() && 10 * s >= r_.differing_pixels) {
      out_.push_back({"", "an image cannot always tell " + wide + " from faces moved by one pixel",
                      fmt::format("{} pixels read as moved (`shifted`); {}", s, settle)});
    } else if (wide.empty() && static_cast<double>(s) >= share()) {
      name("edge_lag", count(Category::shifted));
      out_.push_back({"",
                      "an image cannot always tell a face moved by one pixel from span ends "
                      "rounded or one pixel too wide",
                      settle});
    }
  }

  // Centres exactly on an outline given to the wrong face: the closed rule changes most of the
  // pixels it would change; accumulated x changes some of them, and others the closed rule
  // would not (a left end one pixel short).
  void outline() {
    if (static_cast<double>(at(Category::boundary)) < share() || e_.closed_rule_share < 0) return;
    const std::string evidence =
        fmt::format("{}; they are {:.0f} % of the pixels the closed rule changes",
                    count(Category::boundary), 100 * e_.closed_rule_share);
    name(e_.closed_rule_share >= 0.5 ? "closed_rule" : "float_drift", evidence);
  }

  void missing_faces() {
    if (static_cast<double>(at(Category::missing_face)) < share() || r_.missing_faces.empty())
      return;
    const auto horizontal = std::count_if(r_.missing_faces.begin(), r_.missing_faces.end(),
                                          [](const MissingFace& m) {
                                            return m.shape.find("horizontal edge") !=
                                                   std::string::npos;
                                          });
    if (5 * horizontal >= 4 * static_cast<std::int64_t>(r_.missing_faces.size()))
      name("horizontal_edge_skipped",
           fmt::format("{} of the {} missing faces have a horizontal edge", horizontal,
                       r_.missing_faces.size()));
  }

  void colours() {
    if (static_cast<double>(at(Category::colour)) < share() || r_.colour_diagnosis.empty()) return;
    const std::string& d = r_.colour_diagnosis.front();
    const auto has = [&](const char* words) { return d.find(words) != std::string::npos; };
    if (has("vertex's colour, not the mean"))
      name("flat_colour_not_mean", d);
    else if (has("permuted"))
      name("gouraud_weights_permuted", d);
    else if (has("after sorting"))
      name("colours_paired_after_sort", d);
    else
      out_.push_back({"", d, count(Category::colour)}), explained_ = true;
  }

  const DiffReport& r_;
  const VerdictEvidence& e_;
  std::vector<Verdict> out_;
  bool explained_ = false;  // a line names what the differing pixels show
};

}  // namespace

std::vector<Verdict> diff_verdict(const DiffReport& report, const VerdictEvidence& evidence) {
  return Verdicts(report, evidence).run();
}

}  // namespace scantrace::grade
