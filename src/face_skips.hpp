#pragma once
// What a render of a scene skips, decided from each face's geometry alone: the same on every way
// the render can run (far to near, near to far, bands on several threads), where the counts of
// RenderStats depend on the way. A render's own counts cannot say it: the near-to-far render
// rejects a face whose box nearer faces cover before its set-up, so a zero-area face there counts
// as hidden, and the bands each meet some faces and not others; a report built from them would
// give one scene different numbers of skipped faces on each way.
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "painter.hpp"
#include "scene.hpp"

namespace scantrace {

// Why face `f` of `scene` fills no pixel before any per-row work, as fill_polygon's set-up decides
// it (out_of_range, degenerate, culled, no_pixel_centre, offscreen, in that order); none when it
// is set up.
SkipReason skip_before_fill(const Scene& scene, int f, const FillOptions& opt);

// `stats` of a render of `scene` with `opt`, its face counts made the same on every path:
// triangles_culled and triangles_skipped counted by skip_before_fill, and triangles_hidden (near
// to far) the faces set up of which no pixel was seen (hidden by nearer faces, or owning none).
// triangles_filled, the pixels and the near-to-far rejections are left as the render counted them.
void count_skips_by_geometry(const Scene& scene, const FillOptions& opt, RenderStats& stats);

}  // namespace scantrace
