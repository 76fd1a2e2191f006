// Any bytes given to the trace reader either give a Trace whose queries and thorough consistency
// check work, or a TraceError (an InputError); nothing else may escape.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "trace/trace.hpp"
#include "trace/trace_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const scantrace::trace::Trace t = scantrace::trace::Trace::parse(in, "fuzz.jsonl");
    // The queries replay makes: every triangle listed can be asked about.
    for (int tri : t.triangles()) {
      (void)t.triangle_end(tri);
      (void)t.skipped(tri);
      for (const auto* s : t.scanlines(tri))
        if (s->span) (void)t.pixel_history(s->span->x_begin, s->y);
      (void)t.pixels(tri);
    }
    (void)t.header();
    // The thorough checks of `scantrace check` (exact arithmetic on whatever the input holds).
    scantrace::trace::check_consistency(t.events(), "fuzz.jsonl",
                                        scantrace::trace::CheckDepth::thorough);
  } catch (const scantrace::InputError&) {
  }
  return 0;
}
