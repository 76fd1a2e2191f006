#pragma once
// Loading the SCENE of render, trace and explain, with --clamp-colors applied the same way.
#include <filesystem>
#include <string>

#include "io/scene_json.hpp"
#include "src/scene.hpp"

namespace scantrace::cli {

// How an executable reads MATLAB .mat scenes (io/mat_scene.hpp's load_mat_scene), or nullptr.
using MatSceneReader = Scene (*)(const std::filesystem::path& file, ColorClamping* clamping);

// Makes `reader` the .mat reader of load_scene_file. Only scantrace-tools and scantrace-diff pass
// one: matio and the HDF5, curl and TLS libraries it brings took 6 of the 9 ms `scantrace` needs
// to start, and `scantrace` hands a .mat scene on (cli/main_render.cpp). Without one a .mat
// scene is an InputError naming the executable that reads it.
void read_mat_scenes_with(MatSceneReader reader);

// Loads and validates `file`. Colours outside [0, 1] are an error naming the element (with a hint
// at --clamp-colors) unless `clamp_colors`: then they are clamped, and one warning line says how
// many and which was first.
// The canvas's memory (its size permitting) is checked too: check_canvas_memory.
Scene load_scene_file(const std::string& file, bool clamp_colors);

// Throws InputError naming `file` and `element` when a width×height render (the float canvas, the
// 8-bit image and the PNG encoder's buffers) would not fit in the memory available.
void check_canvas_memory(int width, int height, const std::string& file,
                         const std::string& element);

}  // namespace scantrace::cli
