#pragma once
// Which way an untraced render draws when FillOptions::occlusion is Occlusion::automatic: near to
// far (occlusion_canvas.hpp) or far to near, chosen from the scene before anything is drawn.
//
// Why a prediction and not one way for all: near to far saves the work of faces it rejects
// before their set-up, and pays for its bookkeeping (a box test per face, a claim per span) on
// every other face. `scantrace bench` measured (docs/performance.md, "Choosing the way"):
//   - the course scene, a closed mesh seen through its front surface, hides 58 % of its faces
//     whole behind nearer faces: near to far takes 0.66 of the time;
//   - a mesh in one layer hides nothing (1.3-1.4×), the built-in scene little (1.0);
//   - soups of independent triangles stacked 1.2 to 2.9 deep hide at most 4 % whole: each
//     face's box keeps a gap between the nearer faces (1.15-1.6×).
// So near to far is chosen when the faces form surfaces (they share their vertices) and those
// surfaces lie on top of each other (the estimated overdraw). Both tests are cheap: the first is
// a count, the second one pass over the faces (under 3 % of a render of the course scene) and
// is made only when the first passes. The choice never changes a pixel: both ways draw the same
// image, bit for bit.
#include <vector>

#include "src/fill_options.hpp"
#include "src/scene.hpp"

namespace scantrace {

// The paint the faces put on the canvas over the area they cover, estimated on a grid of 32 × 32
// pixel cells: the sum of the faces' areas (on the canvas) over the sum, cell by cell, of the
// smaller of that cell's area and the area the faces put in it. 1 when no face overlaps another,
// 2.4 for the course scene (the exact figure is 2.39: 209,870 pixels painted for 87,925 seen).
// A face no larger than a cell counts in the cell of its centroid; a larger one is spread over
// the cells of its box, in proportion to the box's overlap with each. `cells` is scratch storage.
double estimated_overdraw(const Scene& scene, std::vector<float>& cells);

// Whether the faces share their vertices as a mesh's do (each vertex used by three faces or more
// on average), rather than being a soup of triangles with vertices of their own.
bool forms_surfaces(const Scene& scene);

// Estimated overdraw from which near to far is chosen for a scene that forms surfaces, measured as
// the break-even on shared-vertex grids stacked partly twice (docs/performance.md). It depends on
// the shading: near to far saves the set-up of the faces it hides, and a small flat face's costs
// little since its spans come from SIMD lanes and it is set up in a batch of eight
// (small_triangle.hpp, small_triangle_batch.hpp), so flat needs more overdraw to pay for the
// per-face box tests and span claims (near ÷ far at overdraw 1.75: flat 1.16, Gouraud 0.90; at
// 1.9: flat 1.08; at 2: 1.00 and 0.75; at 3: flat 0.83).
inline constexpr double kNearToFarOverdrawFlat = 2.0;
inline constexpr double kNearToFarOverdraw = 1.6;  // Gouraud

// The threshold for a render's shading.
constexpr double near_to_far_overdraw(Shading shading) {
  return shading == Shading::flat ? kNearToFarOverdrawFlat : kNearToFarOverdraw;
}

// The way an untraced render of `scene` draws with these options: opt.occlusion itself unless it
// is automatic. The painter's render goes near to far on surfaces stacked
// near_to_far_overdraw(opt.shading) deep or more; the z-buffer, which pays for near to far in
// random accesses to its depth and owner buffers, only when the image is also no larger than 512 ×
// 512 (the course's canvas).
Occlusion choose_occlusion(const Scene& scene, const FillOptions& opt, std::vector<float>& cells);

}  // namespace scantrace
