#pragma once
#include "fixed_point.hpp"

namespace scantrace {

// flat: one colour per polygon, the mean of its vertex colours (the course's flat shading).
// gouraud: vertex colours interpolated along the two active edges, then along the span.
enum class Shading { flat, gouraud };

// top_left: the half-open rule of docs/design.md §3 — rows ceil(y_min) … ceil(y_max) − 1, columns
// ceil(x_left) … ceil(x_right) − 1 — so triangles sharing an edge never both own a pixel.
// closed: every centre inside or on the boundary (both span ends and the last row inclusive), the
// course's and OpenCV's behaviour, kept to show why shared edges get painted twice.
enum class FillRule { top_left, closed };

// How coverage and colour are computed (docs/accuracy.md compares them):
// exact: the edge table with exact fixed-point stepping (the default, docs/design.md §3);
// float: the same edge table stepped the textbook way, x += 1/m and colours += Δ in float32;
// double: the same edge table, x recomputed from the edge equation in double on every row;
// halfspace: no edge table — bounding box and exact edge functions per pixel (tinyrenderer's
// barycentric approach), the other classic family.
enum class Method { exact, float32, double64, halfspace };

// Which pixels of a general polygon (concave, self-intersecting, several contours) are inside
// (docs/polygons.md): even_odd — the centre is crossed by an odd number of edges to its left;
// non_zero — the signed sum of those crossings (+1 for an edge going down, −1 up) is not zero.
// Only the general polygon fill (winding_fill.hpp) reads it; for a convex polygon both agree.
enum class WindingRule { even_odd, non_zero };

// Back-face culling, decided by the sign of the exact (snapped) signed area. "Front" is the
// winding that OBJ and OpenGL call front: counter-clockwise seen from the viewer in a y-up world.
// Pixel coordinates point y down, and that flip negates the signed area
// sum(x_i·y_{i+1} − x_{i+1}·y_i), so on the canvas a front face has a *negative* twice_area
// (clockwise in y-down maths, though it still looks counter-clockwise in the picture).
enum class Cull { none, back, front };

// Which face is visible where faces overlap (read by render(), not by the fill of one polygon):
// painter: the course's order — farthest mean depth first, later faces overwrite (docs/design.md
// §2); zbuffer: per-pixel depth, interpolated over the triangle like a Gouraud colour; the nearest
// (smallest) depth wins, ties keep the face drawn first.
enum class Visibility { painter, zbuffer };

// How an untraced painter's render draws (read by render(); docs/performance.md measures both):
// near_to_far: the painter's order reversed, each pixel written once, by the face the painter
// would paint last, spans clipped to what nearer faces left and faces whose box is all covered
// rejected before their set-up, the background written last (fast/occlusion_canvas.hpp): the same
// image, bit for bit, without the overdraw; far_to_near: the course's algorithm as it is taught,
// every face painted over the farther ones. A traced render is always far_to_near: the trace
// shows the algorithm the course asks students to understand. The z-buffered render reads it too
// (one thread, untraced): near_to_far draws its faces in that same order, an exact depth tie still
// going to the face first in the scene, and rejects before set-up a face whose box a coarse view
// of the depth buffer shows all nearer (fast/depth_tiles.hpp); far_to_near is its scene order.
// automatic (the default): one of the two, chosen from the scene (fast/occlusion_choice.hpp says how),
// which RenderStats::path reports.
enum class Occlusion { near_to_far, far_to_near, automatic };

struct FillOptions {
  Shading shading = Shading::gouraud;
  FillRule fill_rule = FillRule::top_left;
  int subpixel_bits = kDefaultSubpixelBits;
  Method method = Method::exact;
  WindingRule winding_rule = WindingRule::even_odd;
  Cull cull = Cull::none;
  Visibility visibility = Visibility::painter;
  // Chosen per scene: near to far is faster where most faces are hidden whole (the course scene:
  // 0.66 of the time) and slower where few are (a 1200² mesh: 1.3-1.4, its clipping costs more
  // than it saves), as `scantrace bench` measures (docs/performance.md).
  Occlusion occlusion = Occlusion::automatic;
};

const char* to_string(Shading s);
const char* to_string(FillRule r);
const char* to_string(Method m);      // "exact", "float", "double", "halfspace"
const char* to_string(Cull c);        // "none", "back", "front"
const char* to_string(Visibility v);  // "painter", "zbuffer"
const char* to_string(Occlusion o);   // "near-to-far", "far-to-near", "auto"
// The method named `name`, or false when there is none.
bool parse_method(const char* name, Method& out);
const char* to_string(WindingRule w);  // "even-odd", "non-zero"
bool parse_winding_rule(const char* name, WindingRule& out);

}  // namespace scantrace
