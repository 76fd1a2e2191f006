#pragma once
// The mistakes that change every pixel at once, found (and undone) before any pixel is
// classified: one line each instead of 200,000 pixel errors.
#include <cstdint>
#include <string>
#include <vector>

#include "grade/diff_report.hpp"
#include "grade/face_id_render.hpp"

namespace scantrace::grade {

// Whether `pixels` hold colours on a 0–255 scale: more than the catalogue's scaled_share of the
// painted pixels (neither the scene's background nor black) above 1, none above 255. `above`
// counts the pixels above 1, `top` is the largest value. When scaled and `undo`, the painted
// pixels are divided by 255 in place (pixels of exactly the background stay when they outnumber
// those of 255 x the background: a fill of colour * 255 on a blank canvas).
struct Scale255 {
  bool scaled = false;
  float top = 0;
  std::int64_t above = 0;
};
Scale255 find_scale_255(RgbImage& pixels, Color background, double tolerance, bool undo);

// Finds the global mistakes of `image` against the reference render `reference` (whose face ids
// are `ids`); returns them, and (when `undo`) `image` brought back to the scene's canvas with the
// mistakes undone. Without undo, `image` is only cropped/padded to the canvas. What is odd but no
// global mistake (a few values above 1) is added to `notes`.
std::vector<GlobalMistake> find_global_mistakes(const Scene& scene, const RgbImage& reference,
                                                const FaceIdImage& ids, const SubmittedImage& in,
                                                double tolerance, bool undo, RgbImage& image,
                                                std::vector<unsigned char>& compared,
                                                std::vector<std::string>& notes);

}  // namespace scantrace::grade
