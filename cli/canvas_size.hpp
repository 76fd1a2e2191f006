#pragma once
// --size WxH: the CANVAS, with one meaning on every command that takes a scene (render, trace,
// explain, and the commands built on them). For --triangle, --polygon and OBJ models it is the
// canvas drawn on (default 512x512); for a scene file it overrides the file's width and height.
// The frame size of a video is --video-size (cli/replay_flags.hpp), never --size.
#include <string>

#include "src/scene.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace scantrace::cli {

// Adds --size bound to `size` (empty when not given).
CLI::Option* add_canvas_size_option(CLI::App& command, std::string& size);

// `size` ("WxH", validated) or `fallback_w` x `fallback_h` when it is empty.
std::pair<int, int> canvas_size_or(const std::string& size, int fallback_w, int fallback_h);

// A scene file's canvas replaced by --size when it was given; the memory budget is checked for
// the new size (InputError naming --size).
void apply_canvas_size(Scene& scene, const std::string& size);

}  // namespace scantrace::cli
