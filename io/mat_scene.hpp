#pragma once
// The 2021 course's scene as handed out: a MATLAB .mat file (v5, or v7 = compressed v5) holding
//
//   vertices_2d    L×2  [x, y] 1-based pixels, x = column, y = row (pointing down)
//   faces          K×3  1-based vertex indices (MATLAB's convention)
//   vertex_colors  L×3  [r, g, b] in [0, 1]
//   depth          L×1  one number per vertex (larger = farther); 1×L is accepted too
//
// Any numeric class (double, single, integers). It maps to a Scene as: vertices_2d(i,:) - 1 is
// vertices[i-1] (MATLAB's pixel (x, y) is scantrace's (x - 1, y - 1)), faces(k,:) - 1 is
// faces[k-1], vertex_colors(i,:) is vcolors[i-1], depth(i) is depth[i-1]; the canvas is the
// default 512×512 on white (the file has no canvas size). Every
// problem is an InputError naming the file and the variable in MATLAB's 1-based notation, e.g.
// "scene.mat: faces(813,:): vertex index 5012 is out of range 1..4999".
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "io/input_error.hpp"
#include "io/scene_json.hpp"
#include "src/scene.hpp"

namespace scantrace {

// Reads and validates a .mat scene. Colours outside [0, 1] are an error unless `clamping` is
// given: then they are clamped and counted in it (like load_scene).
Scene load_mat_scene(const std::filesystem::path& file, ColorClamping* clamping = nullptr);

// True for a name ending in .mat (any case): what render, trace and explain read as MATLAB.
// Inline, so that `scantrace`, which does not link matio, can tell such a file and hand it on
// (cli/main_render.cpp).
inline bool is_mat_file(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".mat";
}

}  // namespace scantrace
