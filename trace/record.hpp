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
