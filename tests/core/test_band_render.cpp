// The parallel band render draws exactly what the single-threaded render draws: every band
// receives the same writes in the same painter's order (z-buffered: the same depth tests in scene
// order), so the images are equal bit for bit.
#include <catch2/catch.hpp>

#include <filesystem>

#include "demo/demo_scene.hpp"
#include "overlapping_scene.hpp"
#include "src/band_render.hpp"

namespace {

using namespace scantrace;
using sttest::overlapping_scene;

// The three ways a scene is drawn: the painter's far to near (as taught) and near to far (each
// pixel once, occlusion_canvas.hpp), and the z-buffer.
struct Way {
  Visibility visibility;
  Occlusion occlusion;
};
constexpr Way kWays[] = {{Visibility::painter, Occlusion::far_to_near},
                         {Visibility::painter, Occlusion::near_to_far},
                         {Visibility::zbuffer, Occlusion::far_to_near}};

}  // namespace

TEST_CASE("band render: bit-identical to the single-threaded render", "[band]") {
  const Scene scenes[] = {demo_scene(), overlapping_scene(7, 300, 211, 2000),
                          overlapping_scene(8, 64, 17, 300)};
  for (const Scene& scene : scenes)
    for (Shading shading : {Shading::flat, Shading::gouraud})
      for (FillRule rule : {FillRule::top_left, FillRule::closed})
        for (const Way way : kWays) {
          const FillOptions opt{.shading = shading,
                                .fill_rule = rule,
                                .visibility = way.visibility,
                                .occlusion = way.occlusion};
          RenderStats one, many;
          const Bgr8Image expected = render<Bgr8>(scene, opt, &one);
          for (int threads : {1, 2, 3, 7}) {
            INFO(scene.faces.size() << " faces, " << threads << " threads, " << to_string(shading)
                                    << ", " << to_string(rule) << ", " << to_string(way.visibility)
                                    << ", " << to_string(way.occlusion));
            CHECK(render_parallel<Bgr8>(scene, opt, threads, &many) == expected);
            CHECK(many.pixels == one.pixels);
            CHECK(many.triangles_filled == one.triangles_filled);
            // Near to far, a face owning no pixel may be hidden in one and skipped in the other
            // (RenderStats).
            CHECK(many.triangles_hidden + many.triangles_skipped ==
                  one.triangles_hidden + one.triangles_skipped);
            if (one.path == Occlusion::far_to_near)
              CHECK(many.triangles_skipped == one.triangles_skipped);
            CHECK(many.path == one.path);
          }
          CHECK(render_parallel<Rgb32f>(scene, opt, 2) == render<Rgb32f>(scene, opt));
        }
}

TEST_CASE("a render into the caller's image equals a fresh render, whatever the image held",
          "[band][painter]") {
  // One image and one scratch for every render, as the bench and an animation keep them: the
  // scenes change size (the storage is replaced) and repeat a size (it is kept, and must be
  // cleared: none of these scenes covers its whole canvas), and the depths, the order and the
  // fill's scratch carry over from a different scene each time.
  const Scene scenes[] = {overlapping_scene(7, 300, 211, 2000), overlapping_scene(8, 64, 17, 300),
                          overlapping_scene(9, 64, 17, 40), demo_scene(),
                          overlapping_scene(10, 300, 211, 500)};
  Bgr8Image image(5, 5, Bgr8{1, 2, 3});
  RgbImage float_image;
  RenderScratch scratch;
  for (int pass = 0; pass < 2; ++pass)
    for (const Scene& scene : scenes)
      for (const Way way : kWays)
        for (Shading shading : {Shading::flat, Shading::gouraud}) {
          const FillOptions opt{
              .shading = shading, .visibility = way.visibility, .occlusion = way.occlusion};
          INFO(scene.width << "x" << scene.height << ", " << scene.faces.size() << " faces, "
                           << to_string(shading) << ", " << to_string(way.visibility) << ", "
                           << to_string(way.occlusion));
          RenderStats fresh_stats;
          const Bgr8Image fresh = render<Bgr8>(scene, opt, &fresh_stats);
          const RenderStats stats = render(image, scene, opt, scratch);
          CHECK(image == fresh);
          CHECK(stats.pixels == fresh_stats.pixels);
          CHECK(stats.triangles_filled == fresh_stats.triangles_filled);
          CHECK(render_parallel(image, scene, opt, 2, scratch).pixels == fresh_stats.pixels);
          CHECK(image == fresh);
          render(float_image, scene, opt, scratch);
          CHECK(float_image == render<Rgb32f>(scene, opt));
        }
}
