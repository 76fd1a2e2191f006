#pragma once
// The scene file's fast path: simdjson reads a well-formed scene many times faster than nlohmann's
// DOM (a 1200² scene of 25,088 faces, 10.5 MB: 19 ms against 147), which is much of what
// `scantrace render` of a large scene waits for (docs/performance.md, "The one-shot command").
// It takes only a document of exactly the expected shape: anything else (a syntax error, a wrong
// shape, an index out of range or written 3.0, a number beyond a double, a key given twice) makes
// it decline, and the nlohmann reader (scene_json.cpp), which names the file, the element and the
// problem, reads the text instead. So the two agree on every input: the same scene, or the same
// error.
#include <optional>
#include <string_view>

#include "io/scene_json.hpp"
#include "src/scene.hpp"

namespace scantrace {

// A fast reader parse_scene_text tries before the nlohmann reader: the scene, or nullopt to
// decline (then the nlohmann reader reads the text). `padding` as for read_scene_fast.
using FastSceneReader = std::optional<Scene> (*)(std::string_view text, std::size_t padding);

// Makes `reader` the fast reader of every later parse_scene_text and load_scene; nullptr: none.
// scene_json_fast.cpp registers read_scene_fast when it is linked (every native link of
// scantrace_io: io/CMakeLists.txt); the WebAssembly build, without simdjson, registers none.
void register_fast_scene_reader(FastSceneReader reader);

// The scene's values as the file gives them (colours not yet clamped, the scene not validated),
// or nullopt when the text is not a scene of exactly the expected shape, or when simdjson's
// buffers (about 15 bytes per byte of text) would not fit in the memory available
// (io/memory_budget.hpp). `padding`: how many bytes after the text may be read (not written);
// from 64 on (json_input::read_text_file leaves that) the text is parsed in place, else copied.
std::optional<Scene> read_scene_fast(std::string_view text, std::size_t padding = 0);

namespace detail {
// The two readers read_scene_fast tries, in this order (simdjson's On-Demand front end, which
// declines a key the scene does not use, then its DOM), each on a padded copy of `text`: the tests
// hold each to the other and to the nlohmann reader.
std::optional<Scene> read_scene_on_demand(std::string_view text);
std::optional<Scene> read_scene_dom(std::string_view text);
}  // namespace detail

// parse_scene_text by the nlohmann reader alone: what the fast path must agree with (the tests
// compare the two on every input they make).
Scene parse_scene_text_without_fast_path(std::string_view text, const std::string& name_for_errors,
                                         ColorClamping* clamping = nullptr);

}  // namespace scantrace
