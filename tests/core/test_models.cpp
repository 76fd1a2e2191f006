// Models in the core: culling by winding, the z-buffer against painter's order, Lambert lighting
// and gamma at chosen pixels (values computed by hand), and the generated torus's orientation.
#include <array>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "demo/demo_mesh.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"

using namespace scantrace;

namespace {

Color at(const RgbImage& img, int x, int y) {
  return img(x, y).color();
}

void check_color(Color got, Color want, double tol = 1e-6) {
  INFO("got " << got.r << "," << got.g << "," << got.b << " want " << want.r << "," << want.g << ","
              << want.b);
  CHECK(std::abs(got.r - want.r) < tol);
  CHECK(std::abs(got.g - want.g) < tol);
  CHECK(std::abs(got.b - want.b) < tol);
}

// Two triangles passing through each other (docs/zbuffer_vs_painter.png). In pixels:
// A (blue): (50,50) (50,450) (450,50), depth (x − 50)/200 — 0 on its left edge, 2 at x = 450;
// B (red):  (450,50) (50,50) (450,450), depth (450 − x)/200 + 0.2.
// Both cover the wedge x + y < 500, y < x; there they are equally deep where
// (x − 50) = (450 − x) + 40, i.e. x = 270: A is nearer left of it, B right of it.
// Mean depths: A 2/3, B 2.6/3, so the painter's order draws B first and A over the whole wedge.
const Color kBlue{0, 0, 1}, kRed{1, 0, 0};
Scene interpenetrating() {
  Scene s;
  s.width = s.height = 500;
  s.vertices = {{50, 50}, {50, 450}, {450, 50}, {450, 50}, {50, 50}, {450, 450}};
  s.depth = {0, 0, 2, 0.2, 2.2, 0.2};
  s.vcolors = {kBlue, kBlue, kBlue, kRed, kRed, kRed};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  return s;
}

}  // namespace

TEST_CASE("culling keeps front faces: negative signed area on the y-down canvas", "[models]") {
  // (10,10) → (10,100) → (100,10): counter-clockwise as the picture shows it (down the left
  // side, then up to the right), i.e. a front face of a y-up model after the y flip.
  const std::array<Vec2, 3> front{Vec2{10, 10}, Vec2{10, 100}, Vec2{100, 10}};
  const std::array<Vec2, 3> back{front[0], front[2], front[1]};
  const std::array<Color, 3> c{Color{1, 0, 0}, Color{1, 0, 0}, Color{1, 0, 0}};
  for (Cull cull : {Cull::none, Cull::back, Cull::front}) {
    FillOptions o;
    o.cull = cull;
    RgbImage a(128, 128), b(128, 128);
    const FillResult rf = fill_triangle(a, front, c, o);
    const FillResult rb = fill_triangle(b, back, c, o);
    INFO(to_string(cull));
    CHECK((rf.skipped == SkipReason::culled) == (cull == Cull::front));
    CHECK((rb.skipped == SkipReason::culled) == (cull == Cull::back));
    if (cull == Cull::none) CHECK(a == b);  // winding changes nothing else
  }
}

TEST_CASE("render counts culled faces apart from skipped ones", "[models]") {
  Scene s = interpenetrating();
  // Face 2: a degenerate face (skipped, not culled); face 3: B reversed (a back face).
  s.faces.push_back({0, 0, 1});
  s.faces.push_back({3, 5, 4});
  FillOptions o;
  o.cull = Cull::back;
  RenderStats st;
  render(s, o, &st);
  CHECK(st.triangles_filled == 2);
  CHECK(st.triangles_culled == 1);
  CHECK(st.triangles_skipped == 1);
}

TEST_CASE("the z-buffer gets interpenetrating triangles right where painter's order cannot",
          "[models]") {
  const Scene s = interpenetrating();
  FillOptions painter, zbuffer;
  zbuffer.visibility = Visibility::zbuffer;
  const RgbImage p = render(s, painter), z = render(s, zbuffer);
  // In the wedge, left of x = 270: A (blue) is nearer; both methods show it.
  for (auto [x, y] : {std::pair{100, 60}, {200, 150}, {260, 230}}) {
    check_color(at(p, x, y), kBlue);
    check_color(at(z, x, y), kBlue);
  }
  // Right of x = 270: B (red) is nearer; painter's order paints A over it.
  for (auto [x, y] : {std::pair{400, 60}, {300, 150}, {280, 215}}) {
    check_color(at(p, x, y), kBlue);
    check_color(at(z, x, y), kRed);
  }
  // Outside the wedge each triangle is alone, and both methods agree.
  for (auto [x, y] : {std::pair{60, 300}, {440, 300}}) check_color(at(p, x, y), at(z, x, y));
  // The seam follows x = 270 on every row of the wedge: exact up to the pixel next to it.
  for (int y = 60; y < 220; y += 7) {
    check_color(at(z, 268, y), kBlue);
    check_color(at(z, 272, y), kRed);
  }
}

TEST_CASE("z-buffer depth is the linear interpolation of the vertex depths", "[models]") {
  // Checked against the plane through the vertices, written out by hand for face A and B.
  RgbImage img(500, 500);
  ZBufferCanvas<Rgb32f> canvas(img);
  const Scene s = interpenetrating();
  const SubpixelGrid grid(kDefaultSubpixelBits);
  const std::array<Vec2, 3> a{s.vertices[0], s.vertices[1], s.vertices[2]};
  const std::array<double, 3> da{0, 0, 2};
  canvas.begin_triangle(a, da, grid);
  for (auto [x, y] : {std::pair{50, 50}, {123, 77}, {300, 100}, {449, 50}})
    CHECK(canvas.depth_at(x, y) == Approx((x - 50) / 200.0).margin(1e-12));
  const std::array<Vec2, 3> b{s.vertices[3], s.vertices[4], s.vertices[5]};
  const std::array<double, 3> db{0.2, 2.2, 0.2};
  canvas.begin_triangle(b, db, grid);
  for (auto [x, y] : {std::pair{450, 50}, {123, 77}, {300, 100}, {449, 440}})
    CHECK(canvas.depth_at(x, y) == Approx((450 - x) / 200.0 + 0.2).margin(1e-12));
}

namespace {

// The triangle (0,0,0) (1,0,0) (0,1,0), counter-clockwise from +z, fitted orthographically to a
// 100×100 canvas with a 5% margin: scale 90, so its corners land on (4.5,94.5) (94.5,94.5)
// (4.5,4.5), and the model point (0.25, 0.25) on pixel (27, 72) with barycentric weights
// (0.5, 0.25, 0.25).
Mesh lit_triangle() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.faces = {{0, 1, 2}};
  // Corner normals: +z, +x, and (0, 0.6, 0.8).
  m.normals = {{0, 0, 1}, {1, 0, 0}, {0, 0.6, 0.8}};
  m.face_normals = {{0, 1, 2}};
  return m;
}

ShadeOptions lit_options(Shading shading) {
  ShadeOptions o;
  o.camera.width = o.camera.height = 100;
  o.shading = shading;
  o.colors = ColorSource::white;
  // The light travels along (0, −0.6, −0.8): it comes from (0, 0.6, 0.8).
  o.light.direction = {0, -0.6, -0.8};
  o.light.ambient = 0.1;
  return o;
}

}  // namespace

TEST_CASE("flat Lambert lighting: one intensity per face from its normal", "[models]") {
  // Face normal (0,0,1) · (0,0.6,0.8) = 0.8 → 0.1 + 0.9·0.8 = 0.82, everywhere on the face.
  const Scene s = shade_mesh(lit_triangle(), lit_options(Shading::flat));
  FillOptions o;
  o.shading = Shading::flat;
  const RgbImage img = render(s, o);
  for (auto [x, y] : {std::pair{27, 72}, {10, 90}, {30, 60}})
    check_color(at(img, x, y), {0.82, 0.82, 0.82});
  check_color(at(img, 90, 10), {1, 1, 1});  // outside: the white background

  // Gamma 2.2 encodes the same face as 0.82^(1/2.2).
  ShadeOptions g = lit_options(Shading::flat);
  g.gamma = 2.2;
  const RgbImage enc = render(shade_mesh(lit_triangle(), g), o);
  const double e = std::pow(0.82, 1 / 2.2);
  check_color(at(enc, 27, 72), {e, e, e});
}

TEST_CASE("Gouraud Lambert lighting: intensities at the corners, interpolated", "[models]") {
  // Corner intensities: +z → 0.82; +x → max(0, 0) → ambient 0.1; (0,0.6,0.8) → 1.0.
  // At (27, 72): 0.5·0.82 + 0.25·0.1 + 0.25·1.0 = 0.685. Times a vertex colour (0.5, 1, 0.2).
  Mesh m = lit_triangle();
  m.colors.assign(3, Color{0.5, 1, 0.2});
  ShadeOptions so = lit_options(Shading::gouraud);
  so.colors = ColorSource::file;
  const RgbImage img = render(shade_mesh(m, so));
  check_color(at(img, 27, 72), {0.5 * 0.685, 0.685, 0.2 * 0.685}, 1e-5);
  // Model point (0.45, 0.25) → pixel (45, 72), weights (0.3, 0.45, 0.25):
  // 0.3·0.82 + 0.45·0.1 + 0.25·1.0 = 0.541.
  check_color(at(img, 45, 72), {0.5 * 0.541, 0.541, 0.2 * 0.541}, 1e-5);
}

TEST_CASE("without normals in the mesh, Gouraud averages the face normals", "[models]") {
  // Two faces folded along the y axis: (0,0,0) (1,0,1) (0,1,0) and (0,0,0) (0,1,0) (-1,0,1).
  // Normals (-1,0,1)/√2 and (1,0,1)/√2: the shared corners average to (0,0,1).
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 1}, {0, 1, 0}, {-1, 0, 1}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Vec3> n = averaged_vertex_normals(m);
  CHECK(n[0].x == Approx(0).margin(1e-12));
  CHECK(n[0].z == Approx(1));
  CHECK(n[2].z == Approx(1));
  CHECK(n[1].x == Approx(-std::sqrt(0.5)));
  CHECK(n[3].x == Approx(std::sqrt(0.5)));
}

TEST_CASE("random face colours: one per face, named by the seed", "[models]") {
  const Mesh m = demo_torus(1, 0.4, 8, 6, 30);
  ShadeOptions o;
  o.colors = ColorSource::random;
  o.light.enabled = false;
  o.shading = Shading::flat;
  o.seed = 7;
  const Scene a = shade_mesh(m, o), b = shade_mesh(m, o);
  o.seed = 8;
  const Scene c = shade_mesh(m, o);
  CHECK(a.vcolors == b.vcolors);
  CHECK(a.vcolors != c.vcolors);
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    CHECK(a.vcolors[3 * f] == a.vcolors[3 * f + 1]);
    CHECK(a.vcolors[3 * f] == a.vcolors[3 * f + 2]);
  }
}

TEST_CASE("the generated torus is counter-clockwise seen from outside", "[models]") {
  // Untilted, the ring lies in the xz plane; the tube's centre line nearest a face is R times
  // the unit direction of the face's centroid in that plane. Outward = away from it.
  const double R = 1;
  const Mesh m = demo_torus(R, 0.4, 16, 8, 0);
  for (const auto& f : m.faces) {
    const Vec3 a = m.positions[f[0]], b = m.positions[f[1]], c = m.positions[f[2]];
    const Vec3 centroid = (a + b + c) * (1.0 / 3);
    const Vec3 ring = normalized(Vec3{centroid.x, 0, centroid.z}) * R;
    CHECK(dot(cross(b - a, c - a), centroid - ring) > 0);
  }
}

TEST_CASE("orthographic fit: the model fills the canvas minus the margin, aspect kept",
          "[models]") {
  Mesh m;
  m.positions = {{-2, -1, 0}, {2, -1, 0}, {2, 1, 0}};  // 4 wide, 2 high
  m.faces = {{0, 1, 2}};
  Camera cam;
  cam.width = 200;
  cam.height = 100;
  const Projection p = project(m, cam);
  // Width 4 → 180 px, height 2 → 90 px: scale min(45, 45) = 45; centre (99.5, 49.5); y flipped.
  CHECK(p.points[0].x == Approx(99.5 - 90));
  CHECK(p.points[0].y == Approx(49.5 + 45));
  CHECK(p.points[2].x == Approx(99.5 + 90));
  CHECK(p.points[2].y == Approx(49.5 - 45));
}

TEST_CASE("perspective: nearer is smaller depth, and the target projects to the centre",
          "[models]") {
  Mesh m;
  m.positions = {{0, 0, 0}, {0, 0, -1}, {1, 0, 0}};
  m.faces = {{0, 1, 2}};
  Camera cam;
  cam.perspective = true;
  cam.eye = {0, 0, 5};
  cam.target = Vec3{0, 0, 0};
  cam.fov_degrees = 90;
  const Projection p = project(m, cam);
  CHECK(p.points[0].x == Approx(255.5));
  CHECK(p.points[0].y == Approx(255.5));
  CHECK(p.depth[0] < p.depth[1]);
  // fov 90: tan 45° = 1, so x = 1 at distance 5 is 256/5 pixels right of the centre.
  CHECK(p.points[2].x == Approx(255.5 + 256.0 / 5));
}
