#pragma once
// The checks of one case for one rasterizer: every triangle is filled in all 6 vertex orders and
// each image is compared with the reference pixel by pixel (coverage, colour, NaN/Inf) and with the
// image of the first order (bit for bit, as the library's float32 RgbImage would store it).
#include <array>
#include <string>
#include <vector>

#include "stress/rasterizer.hpp"
#include "stress/reference_window.hpp"
#include "stress/stats.hpp"
#include "stress/stress_canvas.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress {

// The vertices as "x0,y0 x1,y1 x2,y2" with every digit a double holds (%.17g), so a printed
// case reproduces bit for bit (the form `scantrace trace --triangle` reads).
std::string points_text(const Triangle& t);

// The 6 orders in which three vertices can be listed; kOrders[0] is the order as generated.
inline constexpr std::array<std::array<int, 3>, 6> kOrders{
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

Triangle permuted(const Triangle& t, int order);

class Checker {
 public:
  explicit Checker(double colour_tolerance = 1e-4) : tolerance_(colour_tolerance) {}

  // A single-triangle case against `ref`, the reference under r.rule() with colours.
  CaseResult check_triangle(Rasterizer& r, const StressCase& c, const ReferenceWindow& ref);
  // A mesh case against `region`, the reference coverage of c.region under r.rule(): each of its
  // pixels must be written exactly once, no other pixel at all.
  CaseResult check_mesh(Rasterizer& r, const StressCase& c, const ReferenceWindow& region);

 private:
  // A written pixel of an image, as an RgbImage would hold it (float32 channels).
  struct Written {
    int x = 0, y = 0;
    std::uint32_t count = 0;
    float r = 0, g = 0, b = 0;
    friend bool operator==(const Written&, const Written&) = default;
  };

  void snapshot(std::vector<Written>& out) const;
  void compare_orders(int order, CaseResult& result);
  void note(CaseResult& result, int order, const std::string& problem) const;

  double tolerance_;
  StressCanvas canvas_;
  std::vector<Written> first_, current_;
};

}  // namespace scantrace::stress
