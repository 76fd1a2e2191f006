#pragma once
// What the exported C functions of the WebAssembly module share (bindings*.cpp): the result they
// leave for JavaScript to read, the options object every call takes, and the scene loading.
//
// Each st_* function returns 0 (done), 1 (bad input: st_error() is the CLI's one-line message)
// or 2 (a bad argument from the JavaScript side). The result stays until the next call.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "src/fill_options.hpp"
#include "src/image.hpp"
#include "src/scene.hpp"

namespace scantrace::web {

struct Result {
  std::string text;                // JSON or JSON Lines
  std::vector<std::uint8_t> bytes;  // pixels
  // When set, the result's bytes are these instead of `bytes`: a buffer the module keeps between
  // calls (st_trace's image, web/traced_image.hpp), handed over without a copy.
  const std::vector<std::uint8_t>* kept_bytes = nullptr;
  std::string error;
  std::string warning;  // a line the command would print as a warning (a trace its cap cut)
  const std::vector<std::uint8_t>& bytes_out() const { return kept_bytes ? *kept_bytes : bytes; }
};
Result& result();

// Runs `work` with the result cleared, mapping exceptions to the status codes above.
int run(const std::function<void()>& work);

// {"shading", "fill_rule", "subpixel_bits", "method", "winding", "cull", "depth"}: the CLI's
// flags of the same names and values (missing keys: the CLI's defaults). Throws
// std::invalid_argument for an unknown value.
FillOptions fill_options(const nlohmann::json& options, bool model);

// The scene at `path` (in the module's file system: JSON, or an OBJ model shaded with the CLI's
// default model flags), as `scantrace render` loads it; options.clamp_colors as --clamp-colors.
Scene load_scene(const std::string& path, const nlohmann::json& options);

nlohmann::json parse_options(const char* text);

// A pixel coordinate handed over as a double (no truncating conversion on the way): an integer
// from 0 to 2^31 - 1, or std::invalid_argument with `scantrace why`'s line for `axis` 'X' or 'Y'
// ("X: must be a pixel column, 0 to the canvas width - 1 (got "100.9")").
int pixel_coordinate(double v, char axis);

// options.tolerance as `scantrace diff --tolerance` takes it: 1/255 when absent, else a finite
// number from 0 to 1, or std::invalid_argument with the command's line.
double tolerance_option(const nlohmann::json& options);

// Whether n bytes at a and b are equal, eight at a time: emscripten's memcmp compares byte by
// byte (comparing each row of a block with the one above was 1.8 ms of a drag's move).
bool same_bytes(const void* a, const void* b, std::size_t n);

// `image` as RGBA bytes, each channel converted by to_byte as the PNG writer converts.
void put_rgba(const RgbImage& image, std::vector<std::uint8_t>& bytes);

}  // namespace scantrace::web
