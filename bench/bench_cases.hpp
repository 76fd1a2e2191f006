#pragma once
// The workloads of `scantrace bench`, each a Scene so that every method and OpenCV draw them the
// same way (painter's order, same canvas): the course scene, the built-in scene, fields of small
// random triangles, one triangle covering half of a 4096² canvas, a triangle with a vertex a
// billion pixels away and its visible part alone, and a large mesh for the parallel render.
#include <cstdint>
#include <string>

#include "src/scene.hpp"

namespace scantrace::bench {

// `count` triangles of mean area `mean_area` px² at random places on a width × height canvas
// (vertices uniform in a square of side L around a random centre: E[area] = 11/144·L²).
Scene small_triangles(std::uint64_t seed, int width, int height, int count, double mean_area);

// The triangle (0,0), (size,0), (0,size): half of a size × size canvas.
Scene half_canvas_triangle(int size);

// A triangle with a vertex at x = −1e9 reaching across a 512×512 canvas, and the same triangle
// clipped to the canvas (a fan of the clipped polygon): the cost of what is visible.
Scene far_vertex_triangle();
Scene far_vertex_visible_part();

// A jittered-grid mesh of `cells_x` × `cells_y` quads (two triangles each) filling a
// width × height canvas, random colours and depths.
Scene grid_mesh(std::uint64_t seed, int width, int height, int cells_x, int cells_y);

// `layers` jittered-grid meshes of `cells_x` × `cells_y` quads over a width × height canvas, whose
// faces share their corners as a model's do (a surface, not a soup), layer k at depths in
// [k, k + 1): nearer layers hide whole faces of farther ones, as the course scene's front hides
// its back. One layer hides nothing.
Scene surface_layers(std::uint64_t seed, int width, int height, int cells_x, int cells_y,
                     int layers);

// `count` copies of a small triangle placed off the canvas (all to its left), or with zero area.
Scene offscreen_triangles(int count);
Scene zero_area_triangles(int count);
// The course-like field of small triangles with all three colours of each face equal.
Scene uniform_colour_triangles(std::uint64_t seed, int count);

}  // namespace scantrace::bench
