#include "cli/selection_check.hpp"

#include "io/input_error.hpp"

namespace scantrace::cli {

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
}

}  // namespace scantrace::cli
