#pragma once
// A --triangles or --rows selection that matches nothing is an error, not an empty trace (or a
// video of an empty canvas) with exit status 0: the user asked for something that is not there.
#include <string>
#include <variant>

#include "src/scene.hpp"
#include "trace/record.hpp"
#include "trace/trace_filter.hpp"

namespace scantrace::cli {

// Throws InputError naming `input_name` and the option when `filter` selects no face of the input
// (faces 0..N-1 of a scene, face 0 of --triangle/--polygon) or no row of its canvas.
void check_selection(
    const std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput>& in,
    const trace::TraceFilter& filter, const std::string& input_name);

}  // namespace scantrace::cli
