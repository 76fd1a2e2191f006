// The default way of the untraced render (issue 19, point 4): occlusion_choice.hpp's estimate of
// the overdraw against scenes whose overdraw is known by construction, its test for surfaces, the
// choice it makes, and a render that lets it choose against one told which way to draw.
#include <catch2/catch.hpp>

#include <tuple>
#include <vector>

#include "src/fast/occlusion_choice.hpp"
#include "src/painter.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

namespace {

// `layers` copies of one jittered grid of n × n quads over a size × size canvas, the faces of a
// layer sharing their corners (a surface). Each layer covers the canvas exactly once, so the
// overdraw of the whole is `layers`, whatever the jitter. Layer k lies at depths in [k, k + 1),
// with colours of its own.
Scene stacked_grids(int size, int n, int layers, bool share_vertices = true) {
  SplitMix64 rng(42);
  Scene s;
  s.width = s.height = size;
  std::vector<Vec2> grid;
  const double cell = static_cast<double>(size) / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      grid.push_back({i * cell + (inner ? rng.uniform(-0.3, 0.3) * cell : 0),
                      j * cell + (inner ? rng.uniform(-0.3, 0.3) * cell : 0)});
    }
  for (int k = 0; k < layers; ++k) {
    const int first = static_cast<int>(s.vertices.size());
    const auto add_vertex = [&](int g) {
      s.vertices.push_back(grid[g]);
      s.vcolors.push_back({rng.unit(), rng.unit(), rng.unit()});
      s.depth.push_back(k + rng.uniform(0, 1));
      return static_cast<int>(s.vertices.size()) - 1;
    };
    if (share_vertices)
      for (std::size_t g = 0; g < grid.size(); ++g) add_vertex(static_cast<int>(g));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i;
        for (const std::array<int, 3>& t :
             {std::array<int, 3>{a, a + 1, a + n + 2}, std::array<int, 3>{a, a + n + 2, a + n + 1}})
          if (share_vertices)
            s.faces.push_back({first + t[0], first + t[1], first + t[2]});
          else
            s.faces.push_back({add_vertex(t[0]), add_vertex(t[1]), add_vertex(t[2])});
      }
  }
  return s;
}

void add_triangle(Scene& s, Vec2 a, Vec2 b, Vec2 c, double depth = 0) {
  const int first = static_cast<int>(s.vertices.size());
  for (Vec2 v : {a, b, c}) {
    s.vertices.push_back(v);
    s.vcolors.push_back({0.2, 0.4, 0.6});
    s.depth.push_back(depth);
  }
  s.faces.push_back({first, first + 1, first + 2});
}

}  // namespace

TEST_CASE("estimated overdraw: layers that each cover the canvas once", "[occlusion_choice]") {
  std::vector<float> cells;
  // Faces of 8 px (counted at their centroid) and of 40 px (spread over the cells of their box):
  // both ways of counting a face.
  for (int n : {64, 13})
    for (int layers : {1, 2, 3}) {
      INFO(n << " quads a side, " << layers << " layers");
      const double estimate = estimated_overdraw(stacked_grids(512, n, layers), cells);
      CHECK(estimate == Approx(layers).epsilon(0.1));
    }
}

TEST_CASE("estimated overdraw: shapes whose overdraw is known by hand", "[occlusion_choice]") {
  std::vector<float> cells;
  Scene s;
  s.width = s.height = 256;
  SECTION("small triangles apart: nothing painted twice") {
    for (int y = 4; y < 256; y += 16)
      for (int x = 4; x < 256; x += 16)
        add_triangle(s, {x + 0.0, y + 0.0}, {x + 9.0, y + 1.0}, {x + 2.0, y + 8.0});
    CHECK(estimated_overdraw(s, cells) == Approx(1.0).margin(1e-9));
  }
  SECTION("one triangle over half of the canvas, then the square twice over") {
    add_triangle(s, {0, 0}, {256, 0}, {0, 256});
    CHECK(estimated_overdraw(s, cells) == Approx(1.0).margin(1e-9));
    // The other half completes the square, then a second square on top: 2, each of its cells
    // painted twice over (the large faces' spread must count the cells' share of each face).
    add_triangle(s, {256, 0}, {256, 256}, {0, 256});
    CHECK(estimated_overdraw(s, cells) == Approx(1.0).margin(1e-6));
    add_triangle(s, {0, 0}, {256, 0}, {0, 256}, 1);
    add_triangle(s, {256, 0}, {256, 256}, {0, 256}, 1);
    CHECK(estimated_overdraw(s, cells) == Approx(2.0).margin(1e-6));
  }
  SECTION("faces off the canvas paint nothing on it") {
    add_triangle(s, {10, 10}, {30, 10}, {10, 30});
    for (int k = 0; k < 20; ++k) add_triangle(s, {-50.0 - k, 10}, {-20.0 - k, 10}, {-50.0 - k, 40});
    for (int k = 0; k < 20; ++k) add_triangle(s, {-500, -500}, {900, -500}, {-500, -100});
    CHECK(estimated_overdraw(s, cells) == Approx(1.0).margin(1e-9));
  }
  SECTION("no face at all") {
    CHECK(estimated_overdraw(s, cells) == 1.0);
  }
}

TEST_CASE("forms_surfaces: a mesh shares its vertices, a soup does not", "[occlusion_choice]") {
  CHECK(forms_surfaces(stacked_grids(256, 16, 1)));
  CHECK(forms_surfaces(stacked_grids(256, 16, 3)));
  CHECK_FALSE(forms_surfaces(stacked_grids(256, 16, 1, false)));
  CHECK_FALSE(forms_surfaces(Scene{}));
}

TEST_CASE("choose_occlusion: near to far for surfaces stacked deep enough, else far to near",
          "[occlusion_choice]") {
  std::vector<float> cells;
  const FillOptions painter{}, zbuffer{.visibility = Visibility::zbuffer};
  REQUIRE(painter.occlusion == Occlusion::automatic);  // the default lets the scene decide
  const Scene one = stacked_grids(512, 40, 1), three = stacked_grids(512, 40, 3),
              soup = stacked_grids(512, 40, 3, false), large = stacked_grids(1024, 40, 3);
  CHECK(choose_occlusion(one, painter, cells) == Occlusion::far_to_near);
  CHECK(choose_occlusion(three, painter, cells) == Occlusion::near_to_far);
  CHECK(choose_occlusion(soup, painter, cells) == Occlusion::far_to_near);
  CHECK(choose_occlusion(large, painter, cells) == Occlusion::near_to_far);
  // The z-buffer near to far only on canvases up to the course's 512 × 512.
  CHECK(choose_occlusion(three, zbuffer, cells) == Occlusion::near_to_far);
  CHECK(choose_occlusion(large, zbuffer, cells) == Occlusion::far_to_near);
  CHECK(choose_occlusion(one, zbuffer, cells) == Occlusion::far_to_near);
  // Overdraw 1.25, 1.75 and 1.925 (a second layer over a quarter, three quarters or 37/40 of the
  // canvas, its columns cut at whole quads): on either side of the Gouraud threshold, and all below
  // the flat one, which needs more overdraw (near_to_far_overdraw).
  const FillOptions flat{.shading = Shading::flat}, gouraud{.shading = Shading::gouraud};
  REQUIRE(painter.shading == Shading::gouraud);  // the default's
  for (const auto& [quads, flat_way, gouraud_way] :
       {std::tuple{10, Occlusion::far_to_near, Occlusion::far_to_near},
        std::tuple{30, Occlusion::far_to_near, Occlusion::near_to_far},
        std::tuple{37, Occlusion::far_to_near, Occlusion::near_to_far}}) {
    Scene partial = stacked_grids(512, 40, 2);
    // Drop the second layer's faces outside its first `quads` columns of quads.
    const std::size_t layer = partial.faces.size() / 2;
    std::vector<std::array<int, 3>> kept(partial.faces.begin(), partial.faces.begin() + layer);
    for (std::size_t f = layer; f < partial.faces.size(); ++f)
      if (static_cast<int>((f - layer) / 2 % 40) < quads) kept.push_back(partial.faces[f]);
    partial.faces = kept;
    INFO(quads << " of 40 columns twice over");
    // 37 columns: between 1.9 and 2, where flat went near to far before its faces were set up in
    // batches (small_triangle_batch.hpp) and now stays far to near.
    if (quads == 37) CHECK(estimated_overdraw(partial, cells) > 1.9);
    CHECK(choose_occlusion(partial, flat, cells) == flat_way);
    CHECK(choose_occlusion(partial, gouraud, cells) == gouraud_way);
  }
  CHECK(choose_occlusion(three, flat, cells) == Occlusion::near_to_far);
  CHECK(choose_occlusion(one, flat, cells) == Occlusion::far_to_near);
  // An explicit way is kept, whatever the scene.
  for (Occlusion way : {Occlusion::near_to_far, Occlusion::far_to_near}) {
    CHECK(choose_occlusion(soup, FillOptions{.occlusion = way}, cells) == way);
    CHECK(choose_occlusion(three, FillOptions{.occlusion = way}, cells) == way);
  }
}

TEST_CASE("the default render: the way it chose, and the far-to-near image", "[occlusion_choice]") {
  for (const Scene& scene :
       {stacked_grids(300, 23, 3), stacked_grids(300, 23, 1), stacked_grids(300, 23, 3, false)}) {
    std::vector<float> cells;
    for (Shading shading : {Shading::flat, Shading::gouraud})
      for (Visibility visibility : {Visibility::painter, Visibility::zbuffer}) {
        const Occlusion chosen = choose_occlusion(
            scene, FillOptions{.shading = shading, .visibility = visibility}, cells);
        INFO(to_string(shading) << ", " << to_string(visibility) << ", chose "
                                << to_string(chosen));
        const FillOptions automatic{.shading = shading, .visibility = visibility},
            far{.shading = shading, .visibility = visibility, .occlusion = Occlusion::far_to_near};
        RenderStats stats;
        CHECK(render<Bgr8>(scene, automatic, &stats) == render<Bgr8>(scene, far));
        CHECK(stats.path == chosen);
        CHECK(render<Rgb32f>(scene, automatic) == render<Rgb32f>(scene, far));
      }
  }
}
