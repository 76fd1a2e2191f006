#include "fill_result.hpp"

namespace scantrace {

const char* to_string(SkipReason r) {
  switch (r) {
    case SkipReason::none:
      return "none";
    case SkipReason::too_few_vertices:
      return "too_few_vertices";
    case SkipReason::out_of_range:
      return "out_of_range";
    case SkipReason::degenerate:
      return "degenerate";
    case SkipReason::no_pixel_centre:
      return "no_pixel_centre";
    case SkipReason::offscreen:
      return "offscreen";
    case SkipReason::culled:
      return "culled";
    case SkipReason::hidden:
      return "hidden";
  }
  return "unknown";
}

}  // namespace scantrace
