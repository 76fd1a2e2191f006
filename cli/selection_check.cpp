#include "cli/selection_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "io/input_error.hpp"

namespace scantrace::cli {
namespace {

// Rows floor(y_min) … ceil(y_max) of the vertices: every row a face can own lies among them
// (snapping moves a vertex by at most half a pixel; src/band_render.hpp makes the same bound).
// A range inside them may still hold none of the face's pixel centres; the bound is only meant to
// catch a --rows that misses the selection altogether. {1, 0} (empty) when nothing is selected.
struct RowBounds {
  double y_min = std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
  void add(const Vec2& v) {
    y_min = std::min(y_min, v.y);
    y_max = std::max(y_max, v.y);
  }
  std::pair<std::int64_t, std::int64_t> rows() const {
    if (!(y_min <= y_max)) return {1, 0};
    return {static_cast<std::int64_t>(std::floor(std::max(y_min, -1e15))),
            static_cast<std::int64_t>(std::ceil(std::min(y_max, 1e15)))};
  }
};

std::pair<std::int64_t, std::int64_t> selected_rows(const Scene& s,
                                                    const trace::TraceFilter& filter) {
  RowBounds b;
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    if (!filter.triangles || filter.triangles->contains(static_cast<int>(f)))
      for (const int v : s.faces[f]) b.add(s.vertices[static_cast<std::size_t>(v)]);
  return b.rows();
}

std::pair<std::int64_t, std::int64_t> selected_rows(const trace::TriangleInput& t,
                                                    const trace::TraceFilter&) {
  RowBounds b;
  for (const Vec2& v : t.vertices) b.add(v);
  return b.rows();
}

std::pair<std::int64_t, std::int64_t> selected_rows(const trace::GeneralPolygonInput& p,
                                                    const trace::TraceFilter&) {
  RowBounds b;
  for (const auto& contour : p.contours)
    for (const Vec2& v : contour) b.add(v);
  return b.rows();
}

}  // namespace

void check_selection(
    const std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput>& in,
    const trace::TraceFilter& filter, const std::string& input_name) {
  const auto [faces, height] = std::visit(
      [](const auto& x) -> std::pair<long long, int> {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Scene>)
          return {static_cast<long long>(x.faces.size()), x.height};
        else
          return {1, x.height};
      },
      in);
  if (filter.triangles) {
    const auto& r = filter.triangles->ranges();
    if (!r.empty() && r.front().first >= faces)
      throw InputError(input_name, "--triangles",
                       "selects no face: the input has " + std::to_string(faces) + " face" +
                           (faces == 1 ? "" : "s") + " (indices 0.." + std::to_string(faces - 1) +
                           "), so there is nothing to trace");
  }
  if (filter.rows && (filter.rows->last < 0 || filter.rows->first > height - 1))
    throw InputError(input_name, "--rows",
                     "selects no row of the canvas (rows 0.." + std::to_string(height - 1) +
                         "), so there is nothing to trace");
  if (!filter.rows) return;
  // The rows the selected faces can cover: `--triangles 40 --rows 0:5` of a face far below gave
  // a trace without a scanline and exit 0, which looked like success.
  const auto [first, last] =
      std::visit([&](const auto& x) { return selected_rows(x, filter); }, in);
  const std::int64_t lo = std::max<std::int64_t>(first, 0),
                     hi = std::min<std::int64_t>(last, height - 1);
  if (lo > hi) return;  // nothing on the canvas at all: the fill itself says so
  if (filter.rows->last < lo || filter.rows->first > hi)
    throw InputError(input_name, "--rows",
                     "selects no row of " +
                         std::string(filter.triangles ? "the selected faces" : "the input") +
                         " (its faces lie within rows " + std::to_string(lo) + ".." +
                         std::to_string(hi) + "), so there is nothing to trace");
}

}  // namespace scantrace::cli
