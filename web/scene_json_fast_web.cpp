// The scene file's fast path in the WebAssembly build: it always declines, so the nlohmann reader
// (io/scene_json.cpp) reads every scene. io/scene_json_fast.hpp's contract makes that exact: the
// fast path, when it answers, gives the scene the nlohmann reader gives. Debian's simdjson is a
// compiled library for the host, not a header emscripten could compile.
#include "io/scene_json_fast.hpp"

namespace scantrace {

std::optional<Scene> read_scene_fast(std::string_view, std::size_t) { return std::nullopt; }

}  // namespace scantrace
