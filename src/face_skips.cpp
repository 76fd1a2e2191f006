#include "face_skips.hpp"

#include <array>
#include <vector>

#include "fill_setup.hpp"
#include "scanline_fill.hpp"

namespace scantrace {

namespace {

// skip_before_fill with the grid made and checked once, and one vector for every face: a grid and
// a vector per face cost more than the test itself.
SkipReason skip_on_grid(const Scene& scene, int f, const FillOptions& opt, const SubpixelGrid& grid,
                        std::vector<FixedPoint>& snapped) {
  const FaceCorners c = corners_of(scene, scene.faces[static_cast<std::size_t>(f)]);
  snapped.clear();
  if (const SkipReason r = snap_vertices(c.points, c.colors, grid, snapped); r != SkipReason::none)
    return r;
  const i128 area2 = detail::twice_area(snapped);
  if (area2 == 0) return SkipReason::degenerate;
  if (opt.cull != Cull::none && (opt.cull == Cull::back ? area2 > 0 : area2 < 0))
    return SkipReason::culled;
  return covers_pixels(grid_box(snapped, grid, opt.fill_rule), scene.width,
                       RowBand{0, scene.height});
}

}  // namespace

SkipReason skip_before_fill(const Scene& scene, int f, const FillOptions& opt) {
  const SubpixelGrid grid(opt.subpixel_bits);
  require_valid(grid);
  std::vector<FixedPoint> snapped;
  return skip_on_grid(scene, f, opt, grid, snapped);
}

void count_skips_by_geometry(const Scene& scene, const FillOptions& opt, RenderStats& stats) {
  const SubpixelGrid grid(opt.subpixel_bits);
  require_valid(grid);
  std::vector<FixedPoint> snapped;
  long long culled = 0, skipped = 0;
  for (int f = 0, n = static_cast<int>(scene.faces.size()); f < n; ++f) {
    const SkipReason r = skip_on_grid(scene, f, opt, grid, snapped);
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
