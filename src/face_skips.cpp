#include "face_skips.hpp"

#include <array>
#include <vector>

#include "fill_setup.hpp"
#include "scanline_fill.hpp"

namespace scantrace {

SkipReason skip_before_fill(const Scene& scene, int f, const FillOptions& opt) {
  const SubpixelGrid grid(opt.subpixel_bits);
  require_valid(grid);
  const FaceCorners c = corners_of(scene, scene.faces[static_cast<std::size_t>(f)]);
  // One vector per call: a pass over a scene for a report, not a render's inner loop.
  std::vector<FixedPoint> snapped;
  if (const SkipReason r = snap_vertices(c.points, c.colors, grid, snapped); r != SkipReason::none)
    return r;
  const i128 area2 = detail::twice_area(snapped);
  if (area2 == 0) return SkipReason::degenerate;
  if (opt.cull != Cull::none && (opt.cull == Cull::back ? area2 > 0 : area2 < 0))
    return SkipReason::culled;
  return covers_pixels(grid_box(snapped, grid, opt.fill_rule), scene.width,
                       RowBand{0, scene.height});
}

void count_skips_by_geometry(const Scene& scene, const FillOptions& opt, RenderStats& stats) {
  long long culled = 0, skipped = 0;
  for (int f = 0, n = static_cast<int>(scene.faces.size()); f < n; ++f) {
    const SkipReason r = skip_before_fill(scene, f, opt);
    if (r == SkipReason::culled)
      ++culled;
    else if (r != SkipReason::none)
      ++skipped;
  }
  stats.triangles_culled = culled;
  stats.triangles_skipped = skipped;
  if (stats.path == Occlusion::near_to_far)
    stats.triangles_hidden =
        static_cast<long long>(scene.faces.size()) - culled - skipped - stats.triangles_filled;
}

}  // namespace scantrace
