#pragma once
// The course's own scene file, hw1.npy: np.save of a dict of four numpy arrays (a pickle), read
// by the restricted reader of io/pickle_reader.hpp, never by Python's unpickler.
//
//   vertices  L×2  integers or floats, [x, y] (x = column, y = row pointing down)
//   vcolors   L×3  floats in [0, 1]
//   faces     K×3  integers, 0-based vertex indices
//   depth     L (or L×1)  integers or floats
//
// No other key; the canvas is the course's 512×512 on white. The same file without the .npy
// header (pickle.dump of the dict, protocols 2–5) is read too.
#include <string>
#include <string_view>

#include "src/scene.hpp"

namespace scantrace {

// Whether `bytes` begin like a .npy file or a pickle (protocol 2 or later): what load_scene hands
// to parse_pickled_scene instead of the JSON parser.
bool looks_pickled(std::string_view bytes);

// The scene the file holds, not yet validated (load_scene validates it as a JSON scene). Throws
// InputError naming `name` and the key or the pickle byte at fault.
Scene parse_pickled_scene(std::string_view bytes, const std::string& name);

}  // namespace scantrace
