#include "record.hpp"

#include "event_tracer.hpp"
#include "jsonl_writer.hpp"
#include "recorder.hpp"
#include "src/painter.hpp"
#include "src/winding_fill.hpp"

#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace scantrace::trace {
namespace {

// The places that run the fill under a tracer: every entry point goes through them, so the
// trace always narrates the real fill of the real image. A triangle or a polygon is drawn onto
// `canvas`, which holds its background (or, for the *_onto entry points, what the caller left
// there).
template <class Tracer>
void fill_onto(Tracer& tracer, RgbImage& canvas, const TriangleInput& t, const FillOptions& options) {
  fill_triangle(canvas, t.vertices, t.colors, options, tracer);
}

template <class Tracer>
void fill_onto(Tracer& tracer, RgbImage& canvas, const GeneralPolygonInput& p,
               const FillOptions& options) {
  fill_polygon_contours(canvas, std::span(p.contours), std::span(p.colors), options, tracer);
}

template <class Tracer, class Input>
void fill_traced(Tracer& tracer, const Input& input, const FillOptions& options, RgbImage* image) {
  RgbImage canvas(input.width, input.height, Rgb32f::from(input.background));
  fill_onto(tracer, canvas, input, options);
  if (image) *image = std::move(canvas);
}

template <class Tracer>
void fill_traced(Tracer& tracer, const Scene& scene, const FillOptions& options, RgbImage* image) {
  RgbImage canvas = render(scene, options, tracer);
  if (image) *image = std::move(canvas);
}

// Only polygon traces name a winding rule: the triangle and scene fills do not use one.
Header header_of(int width, int height, const FillOptions& options, TraceLevel level,
                 bool polygon) {
  Header h = make_header(width, height, options, level);
  if (polygon) h.winding_rule = options.winding_rule;
  return h;
}

template <class Input>
Header header_for(const Input& input, const FillOptions& options, TraceLevel level) {
  Header h = header_of(input.width, input.height, options, level,
                       std::is_same_v<Input, GeneralPolygonInput>);
  h.background = input.background;
  return h;
}

template <class Input>
Trace record(const Input& input, const FillOptions& options, const TraceFilter& filter,
             RgbImage* image) {
  EventTracer<Recorder> tracer(Recorder(header_for(input, options, filter.level), filter.columns),
                               filter);
  fill_traced(tracer, input, options, image);
  return tracer.finish();
}

template <class Input>
Trace record_onto(RgbImage& canvas, const Input& input, const FillOptions& options,
                  const TraceFilter& filter) {
  if (canvas.width() != input.width || canvas.height() != input.height)
    throw std::invalid_argument("record onto a canvas of " + std::to_string(canvas.width()) + "x" +
                                std::to_string(canvas.height()) + " for an input of " +
                                std::to_string(input.width) + "x" + std::to_string(input.height));
  EventTracer<Recorder> tracer(Recorder(header_for(input, options, filter.level), filter.columns),
                               filter);
  fill_onto(tracer, canvas, input, options);
  return tracer.finish();
}

template <class Input>
Footer write(const std::filesystem::path& path, const Input& input, const FillOptions& options,
             const TraceFilter& filter, RgbImage* image) {
  EventTracer<JsonlFileWriter> tracer(
      JsonlFileWriter(path, header_for(input, options, filter.level)), filter);
  fill_traced(tracer, input, options, image);
  tracer.finish();
  return tracer.footer();
}

}  // namespace

Trace record_triangle(const TriangleInput& t, const FillOptions& options, const TraceFilter& filter,
                      RgbImage* image) {
  return record(t, options, filter, image);
}

Trace record_scene(const Scene& scene, const FillOptions& options, const TraceFilter& filter,
                   RgbImage* image) {
  return record(scene, options, filter, image);
}

Trace record_triangle_onto(RgbImage& canvas, const TriangleInput& t, const FillOptions& options,
                           const TraceFilter& filter) {
  return record_onto(canvas, t, options, filter);
}

Trace record_polygon_onto(RgbImage& canvas, const GeneralPolygonInput& p,
                          const FillOptions& options, const TraceFilter& filter) {
  return record_onto(canvas, p, options, filter);
}

Footer write_triangle_trace(const std::filesystem::path& path, const TriangleInput& t,
                            const FillOptions& options, const TraceFilter& filter,
                            RgbImage* image) {
  return write(path, t, options, filter, image);
}

Trace record_polygon(const GeneralPolygonInput& p, const FillOptions& options,
                     const TraceFilter& filter, RgbImage* image) {
  return record(p, options, filter, image);
}

Footer write_polygon_trace(const std::filesystem::path& path, const GeneralPolygonInput& p,
                           const FillOptions& options, const TraceFilter& filter, RgbImage* image) {
  return write(path, p, options, filter, image);
}

Footer write_scene_trace(const std::filesystem::path& path, const Scene& scene,
                         const FillOptions& options, const TraceFilter& filter, RgbImage* image) {
  return write(path, scene, options, filter, image);
}

}  // namespace scantrace::trace
