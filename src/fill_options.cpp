#include "fill_options.hpp"

#include <cstring>
#include <initializer_list>

namespace scantrace {

const char* to_string(Shading s) {
  return s == Shading::flat ? "flat" : "gouraud";
}
const char* to_string(FillRule r) {
  return r == FillRule::top_left ? "top-left" : "closed";
}

const char* to_string(Method m) {
  switch (m) {
    case Method::exact:
      return "exact";
    case Method::float32:
      return "float";
    case Method::double64:
      return "double";
    case Method::halfspace:
      return "halfspace";
  }
  return "exact";
}

const char* to_string(Cull c) {
  return c == Cull::back ? "back" : c == Cull::front ? "front" : "none";
}
const char* to_string(Visibility v) {
  return v == Visibility::zbuffer ? "zbuffer" : "painter";
}

const char* to_string(Occlusion o) {
  return o == Occlusion::far_to_near   ? "far-to-near"
         : o == Occlusion::near_to_far ? "near-to-far"
                                       : "auto";
}

bool parse_method(const char* name, Method& out) {
  for (Method m : {Method::exact, Method::float32, Method::double64, Method::halfspace})
    if (std::strcmp(name, to_string(m)) == 0) {
      out = m;
      return true;
    }
  return false;
}

const char* to_string(WindingRule w) {
  return w == WindingRule::non_zero ? "non-zero" : "even-odd";
}

bool parse_winding_rule(const char* name, WindingRule& out) {
  for (WindingRule w : {WindingRule::even_odd, WindingRule::non_zero})
    if (std::strcmp(name, to_string(w)) == 0) {
      out = w;
      return true;
    }
  return false;
}

}  // namespace scantrace
