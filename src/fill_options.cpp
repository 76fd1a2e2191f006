#include "fill_options.hpp"

namespace scantrace {

const char* to_string(Shading s) {
  return s == Shading::flat ? "flat" : "gouraud";
}
const char* to_string(FillRule r) {
  return r == FillRule::top_left ? "top-left" : "closed";
}

}  // namespace scantrace
