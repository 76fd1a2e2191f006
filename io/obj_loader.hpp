#pragma once
// Wavefront OBJ models, read with tinyobjloader (Debian's libtinyobjloader-dev): positions, the
// optional per-vertex colours ("v x y z r g b"), normals ("vn", per face corner) and faces of any
// number of corners, triangulated by tinyobjloader (a quad along its shorter diagonal).
//
// tinyobjloader is lenient: a malformed number reads as 0, an index out of range only gives a
// warning naming the *last* line of the file, a face with two corners is dropped. So the text is
// checked line by line first, and every problem is an InputError naming "file:line" and the
// problem, e.g. "head.obj:1207: f: vertex index 1260 is out of range (1258 vertices so far)".
// tinyobjloader's own errors and warnings (materials, ...) are passed on as they are.
#include <filesystem>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "src/mesh.hpp"

namespace scantrace {

// `name` starts every error message; `warnings` (optional) receives tinyobjloader's warnings.
Mesh parse_obj(const std::string& text, const std::string& name,
               std::vector<std::string>* warnings = nullptr);
Mesh load_obj(const std::filesystem::path& file, std::vector<std::string>* warnings = nullptr);

// True when `file` names an OBJ model (by its extension, any case).
bool is_obj_file(const std::filesystem::path& file);

}  // namespace scantrace
