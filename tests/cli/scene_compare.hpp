#pragma once
#include <catch2/catch.hpp>

#include "src/scene.hpp"

namespace scantrace::test {

// Field by field, exactly: scene files must read back bit for bit.
inline void require_equal_scenes(const Scene& a, const Scene& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.background == b.background);
  REQUIRE(a.vertices == b.vertices);
  REQUIRE(a.vcolors == b.vcolors);
  REQUIRE(a.faces == b.faces);
  REQUIRE(a.depth == b.depth);
}

}  // namespace scantrace::test
