#pragma once
// Which face the reference shows at each pixel: the scene rendered by the real fill, in the same
// order and with the same visibility, onto a canvas of face indices instead of colours (-1: the
// background). This is the "face-ID render" the grader compares a submitted image against.
#include <vector>

#include "src/fill_options.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {

struct FaceIdImage {
  int width = 0, height = 0;
  std::vector<int> ids;  // ids[y * width + x]
  int at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

FaceIdImage render_face_ids(const Scene& scene, const FillOptions& options);

}  // namespace scantrace::grade
