#pragma once
// The part of a scene around one pixel: the faces whose bounding box holds the pixel centre, as a
// scene of their own (same canvas, same background). Filled in painter's order it draws those
// faces in the order the whole scene draws them (the sort is stable, so ties keep scene order),
// and they are the only faces that can touch the pixel: `why` traces this instead of the scene.
#include <vector>

#include "src/scene.hpp"
#include "src/tracer.hpp"
#include "trace/trace.hpp"

namespace scantrace::grade {

// `faces` receives the original index of each face of the result. `margin` widens the bounding
// boxes (the fill decides on vertices snapped to its grid, which can move them by half a grid
// step).
Scene scene_around(const Scene& scene, int x, int y, double margin, std::vector<int>* faces);

// The margin for `options`: half a step of its subpixel grid, what snapping can move a vertex by.
double snap_margin(const FillOptions& options);

// The trace, at `level`, of the faces around pixel (x, y) as the whole scene draws them: every
// face is filled and only those around the pixel are recorded, so the trace — and a replay of it —
// names each face by its index in the scene, as `why`'s text does.
trace::Trace trace_around(const Scene& scene, const FillOptions& options, int x, int y,
                          TraceLevel level);

}  // namespace scantrace::grade
