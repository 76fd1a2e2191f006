// Any bytes given to the .mat scene reader (as a file: matio reads paths, not memory) either give
// a valid scene or an InputError; nothing else may escape. A scene that loads is rendered on a
// small canvas, which must not fail on it either.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/mat_scene.hpp"
#include "src/painter.hpp"

// matio sizes some allocations from the file's headers before reading the data: a damaged
// compressed variable makes it malloc up to 4 GiB (fuzz/regressions/mat_scene/), then fail the
// read and free it. Under ASan that is seconds of poisoning (a "timeout") or, above the 2 GB RSS
// limit of scripts/fuzz.sh, an "out-of-memory" that is matio's trust in the file, not a leak.
// Allocations above 1 GiB therefore fail here as on a machine without that memory: malloc
// returns NULL, which matio reports as a failed read (and scantrace as a damaged file).
// (512 MiB, not more: each such allocation is poisoned and quarantined by ASan, and a 10-minute
// run hit the 10-second timeout freeing one while its RSS neared the 2 GB limit; the reproducer
// alone takes 0.8 s.) scantrace's own matrices are checked against a 128 MiB budget first, as
// SCANTRACE_MAX_MEMORY would on a small machine.
extern "C" const char* __asan_default_options() {
  return "max_allocation_size_mb=512:allocator_may_return_null=1";
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("SCANTRACE_MAX_MEMORY", "128M", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // One file per process, rewritten for every input (parallel fuzzing jobs do not collide).
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("scantrace-fuzz-" + std::to_string(::getpid()) + ".mat");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  scantrace::Scene scene;
  try {
    scene = scantrace::load_mat_scene(file);
  } catch (const scantrace::InputError&) {
    return 0;
  }
  scene.width = scene.height = 64;
  const auto image = scantrace::render(scene);
  return image.width() == 64 ? 0 : 1;
}
