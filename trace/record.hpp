#pragma once
// One-call tracing of a triangle or a scene with the real fill: in memory (a Trace to query) or
// to a .jsonl file. Each call also gives back the image it rendered, so a caller can compare the
// narration with the pixels.
#include <array>
#include <filesystem>
#include <vector>

#include "src/image.hpp"
#include "src/scene.hpp"
#include "trace.hpp"
#include "trace_filter.hpp"

namespace scantrace::trace {

struct TriangleInput {
  std::array<Vec2, 3> vertices{};
  std::array<Color, 3> colors{};
  int width = 512, height = 512;  // the course's canvas
  Color background{1, 1, 1};
};

// A general polygon (docs/polygons.md): closed contours, one colour per vertex (the contours'
// vertices one after another), filled under options.winding_rule.
struct GeneralPolygonInput {
  std::vector<std::vector<Vec2>> contours;
  std::vector<Color> colors;
  int width = 512, height = 512;
  Color background{1, 1, 1};
};

// In memory.
Trace record_triangle(const TriangleInput& triangle, const FillOptions& options,
                      const TraceFilter& filter = {}, RgbImage* image = nullptr);
Trace record_scene(const Scene& scene, const FillOptions& options, const TraceFilter& filter = {},
                   RgbImage* image = nullptr);

// The same drawn onto `canvas`, which must be the input's size (else std::invalid_argument) and
// is drawn on as it is: the caller has set it to the input's background, or to that background
// but for pixels it knows the fill writes. A caller that traces again and again (the explorer's
// drag: web/bindings_trace.cpp) keeps one canvas and restores only the pixels the last fill wrote,
// instead of allocating and clearing a new one each time.
Trace record_triangle_onto(RgbImage& canvas, const TriangleInput& triangle,
                           const FillOptions& options, const TraceFilter& filter = {});
Trace record_polygon_onto(RgbImage& canvas, const GeneralPolygonInput& polygon,
                          const FillOptions& options, const TraceFilter& filter = {});

// To a .jsonl file (written under a temporary name, renamed into place when complete).
Footer write_triangle_trace(const std::filesystem::path& path, const TriangleInput& triangle,
                            const FillOptions& options, const TraceFilter& filter = {},
                            RgbImage* image = nullptr);
Trace record_polygon(const GeneralPolygonInput& polygon, const FillOptions& options,
                     const TraceFilter& filter = {}, RgbImage* image = nullptr);
Footer write_polygon_trace(const std::filesystem::path& path, const GeneralPolygonInput& polygon,
                           const FillOptions& options, const TraceFilter& filter = {},
                           RgbImage* image = nullptr);
Footer write_scene_trace(const std::filesystem::path& path, const Scene& scene,
                         const FillOptions& options, const TraceFilter& filter = {},
                         RgbImage* image = nullptr);

}  // namespace scantrace::trace
