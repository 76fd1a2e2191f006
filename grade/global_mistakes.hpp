#pragma once
// The mistakes that change every pixel at once, found (and undone) before any pixel is
// classified: one line each instead of 200,000 pixel errors.
#include <string>
#include <vector>

#include "grade/diff_report.hpp"
#include "grade/face_id_render.hpp"

namespace scantrace::grade {

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
