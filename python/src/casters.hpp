#pragma once
// Points and colours reach Python as plain tuples, (x, y) and (r, g, b): what a numpy user prints,
// compares and unpacks without learning a scantrace type.
#include <pybind11/pybind11.h>

#include "src/color.hpp"
#include "src/vec2.hpp"

namespace pybind11::detail {

template <>
struct type_caster<scantrace::Vec2> {
  PYBIND11_TYPE_CASTER(scantrace::Vec2, const_name("tuple[float, float]"));
  bool load(handle src, bool) {
    if (!isinstance<sequence>(src)) return false;
    const sequence s = reinterpret_borrow<sequence>(src);
    if (s.size() != 2) return false;
    value = {s[0].cast<double>(), s[1].cast<double>()};
    return true;
  }
  static handle cast(scantrace::Vec2 v, return_value_policy, handle) {
    return make_tuple(v.x, v.y).release();
  }
};

template <>
struct type_caster<scantrace::Color> {
  PYBIND11_TYPE_CASTER(scantrace::Color, const_name("tuple[float, float, float]"));
  bool load(handle src, bool) {
    if (!isinstance<sequence>(src)) return false;
    const sequence s = reinterpret_borrow<sequence>(src);
    if (s.size() != 3) return false;
    value = {s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()};
    return true;
  }
  static handle cast(scantrace::Color c, return_value_policy, handle) {
    return make_tuple(c.r, c.g, c.b).release();
  }
};

}  // namespace pybind11::detail
