// Any bytes given to the scene parser either give a valid scene or an InputError; nothing else
// may escape (another exception, a crash, a sanitizer report, a hang).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const scantrace::Scene scene = scantrace::parse_scene_text(text, "fuzz.json");
    // What the parser accepted must be what validate() accepts: the renderer relies on it.
    if (scantrace::validate(scene)) __builtin_trap();
  } catch (const scantrace::InputError&) {
  }
  return 0;
}
