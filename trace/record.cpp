#include "record.hpp"

#include "event_tracer.hpp"
#include "jsonl_writer.hpp"
#include "recorder.hpp"
#include "src/painter.hpp"

namespace scantrace::trace {
namespace {

// The two places that run the fill under a tracer: every entry point goes through them, so the
// trace always narrates the real fill of the real image.
template <class Tracer>
void fill_traced(Tracer& tracer, const TriangleInput& t, const FillOptions& options,
                 RgbImage* image) {
  RgbImage canvas(t.width, t.height, Rgb32f::from(t.background));
  fill_triangle(canvas, t.vertices, t.colors, options, tracer);
  if (image) *image = std::move(canvas);
}

template <class Tracer>
void fill_traced(Tracer& tracer, const Scene& scene, const FillOptions& options, RgbImage* image) {
  RgbImage canvas = render(scene, options, tracer);
  if (image) *image = std::move(canvas);
}

int width_of(const TriangleInput& t) {
  return t.width;
}
int height_of(const TriangleInput& t) {
  return t.height;
}
int width_of(const Scene& s) {
  return s.width;
}
int height_of(const Scene& s) {
  return s.height;
}

template <class Input>
Trace record(const Input& input, const FillOptions& options, const TraceFilter& filter,
             RgbImage* image) {
  EventTracer<Recorder> tracer(
      Recorder(make_header(width_of(input), height_of(input), options, filter.level)), filter);
  fill_traced(tracer, input, options, image);
  return tracer.finish();
}

template <class Input>
Footer write(const std::filesystem::path& path, const Input& input, const FillOptions& options,
             const TraceFilter& filter, RgbImage* image) {
  EventTracer<JsonlFileWriter> tracer(
      JsonlFileWriter(path, make_header(width_of(input), height_of(input), options, filter.level)),
      filter);
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

Footer write_triangle_trace(const std::filesystem::path& path, const TriangleInput& t,
                            const FillOptions& options, const TraceFilter& filter,
                            RgbImage* image) {
  return write(path, t, options, filter, image);
}

Footer write_scene_trace(const std::filesystem::path& path, const Scene& scene,
                         const FillOptions& options, const TraceFilter& filter, RgbImage* image) {
  return write(path, scene, options, filter, image);
}

}  // namespace scantrace::trace
