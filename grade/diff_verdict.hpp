#pragma once
// diff's verdict: from the global mistakes and the per-pixel categories to the mistakes of the
// catalogue (grade/mistake_catalogue.hpp), in its words, so that `diff` names "spans are one
// pixel too wide on both sides" where the table says `widened 909, boundary 463, shifted 60`.
// Several mistakes may be named (too wide and the bottom row dropped); where the image cannot
// tell two mistakes apart (spans too wide, faces moved by a pixel) a line says so.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "grade/diff_report.hpp"

namespace scantrace::grade {

// What the categories' counts do not hold, gathered by the classification (diff.cpp).
struct VerdictEvidence {
  // Pixels showing a face just outside its spans: left of a span's start, right of its end.
  std::int64_t extended_left = 0, extended_right = 0;
  // Of those, the ones whose centre is not on the face's outline, and of these the ones more
  // than half a pixel from the face along the row: none when span ends are rounded to the
  // nearest pixel, about half when they are floor(x_L) .. ceil(x_R).
  std::int64_t extended_off_outline = 0, extended_beyond_half = 0;
  // The missing near-boundary pixels by pattern (diff.cpp's tag_missing).
  std::map<std::string, std::int64_t> missing_tags;
  // Of the reference's pixels of faces two rows high or more: those in each face's first row,
  // its last row and the rows between, and how many of each the image does not show the face on.
  struct Rows {
    std::int64_t pixels = 0, lost = 0;
    double share() const { return pixels ? static_cast<double>(lost) / static_cast<double>(pixels) : 0; }
  } first_rows, last_rows, middle_rows;
  // Of the pixels the closed rule would change, the share where the image differs on the
  // outline (`boundary`); -1 when not computed (few `boundary` pixels).
  double closed_rule_share = -1;
};

// A mistake is named when its evidence is at least this share of the differing pixels.
inline constexpr double kVerdictShare = 0.2;

std::vector<Verdict> diff_verdict(const DiffReport& report, const VerdictEvidence& evidence);

}  // namespace scantrace::grade
