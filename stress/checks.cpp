#include "stress/checks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "reference/exact_reference.hpp"

namespace scantrace::stress {
namespace {

using Clock = std::chrono::steady_clock;

std::string pixel_name(int x, int y) {
  return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

std::string color_text(Color c) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", c.r, c.g, c.b);
  return buf;
}

bool finite(Color c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

// The window to compare: where the reference covers anything, plus where anything was written.
struct Window {
  int x0, y0, x1, y1;
};
Window compared_window(const ReferenceWindow& ref, const StressCanvas& canvas) {
  const bool has_ref = ref.x0() < ref.x1(), has_written = canvas.written();
  if (!has_ref && !has_written) return {0, 0, 0, 0};
  if (!has_written) return {ref.x0(), ref.y0(), ref.x1(), ref.y1()};
  if (!has_ref) return {canvas.x0(), canvas.y0(), canvas.x1(), canvas.y1()};
  return {std::min(ref.x0(), canvas.x0()), std::min(ref.y0(), canvas.y0()),
          std::max(ref.x1(), canvas.x1()), std::max(ref.y1(), canvas.y1())};
}

}  // namespace

std::string points_text(const Triangle& t) {
  std::string s;
  char buf[80];
  for (const Vec2& p : t.v) {
    std::snprintf(buf, sizeof buf, "%s%.17g,%.17g", s.empty() ? "" : " ", p.x, p.y);
    s += buf;
  }
  return s;
}

Triangle permuted(const Triangle& t, int order) {
  Triangle p;
  for (int i = 0; i < 3; ++i) {
    p.v[i] = t.v[kOrders[order][i]];
    p.c[i] = t.c[kOrders[order][i]];
  }
  return p;
}

void Checker::note(CaseResult& result, int order, const std::string& problem) const {
  if (!result.problem.empty()) return;
  result.problem = problem;
  result.problem_order = order;
}

void Checker::snapshot(std::vector<Written>& out) const {
  out.clear();
  if (!canvas_.written()) return;
  for (int y = canvas_.y0(); y < canvas_.y1(); ++y)
    for (int x = canvas_.x0(); x < canvas_.x1(); ++x) {
      const std::uint32_t n = static_cast<std::uint32_t>(canvas_.count(x, y));
      if (n == 0) continue;
      const Color c = canvas_.color(x, y);
      out.push_back(
          {x, y, n, static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)});
    }
}

void Checker::compare_orders(int order, CaseResult& result) {
  snapshot(order == 0 ? first_ : current_);
  if (order == 0 || current_ == first_) return;
  result.order_differs = true;
  // Name the first pixel (row-major) where the two images disagree.
  const auto [a, b] = std::mismatch(first_.begin(), first_.end(), current_.begin(), current_.end());
  const Written* at = a != first_.end() ? &*a : b != current_.end() ? &*b : nullptr;
  std::string where = at ? " first at " + pixel_name(at->x, at->y) : "";
  const auto& o = kOrders[order];
  note(result, order,
       "the image for vertex order (" + std::to_string(o[0]) + "," + std::to_string(o[1]) + "," +
           std::to_string(o[2]) + ") differs from order (0,1,2)" + where);
}

CaseResult Checker::check_triangle(Rasterizer& r, const StressCase& c, const ReferenceWindow& ref) {
  CaseResult result;
  const bool shade = r.shades();
  for (int order = 0; order < 6; ++order) {
    const Triangle t = permuted(c.triangles.front(), order);
    canvas_.reset(c.width, c.height);
    r.begin(canvas_);
    const Clock::time_point start = Clock::now();
    r.draw(canvas_, t, c.bits, Shading::gouraud);
    result.fill_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    r.collect(canvas_, t);
    ++result.fills;
    result.ref_pixels += ref.count();

    if (canvas_.out_of_bounds() > 0) {
      result.extra += canvas_.out_of_bounds();
      note(result, order, std::to_string(canvas_.out_of_bounds()) + " writes outside the canvas");
    }
    const Window w = compared_window(ref, canvas_);
    for (int y = w.y0; y < w.y1; ++y)
      for (int x = w.x0; x < w.x1; ++x) {
        const int n = canvas_.count(x, y);
        const bool covered = ref.covers(x, y);
        if (n == 0) {
          if (covered) {
            ++result.missing;
            note(result, order, pixel_name(x, y) + " is covered by the reference, not written");
          }
          continue;
        }
        if (n > 1) {
          ++result.overlaps;
          note(result, order, pixel_name(x, y) + " written " + std::to_string(n) + " times");
        }
        if (!covered) {
          ++result.extra;
          note(result, order, pixel_name(x, y) + " written, the reference does not cover it");
        }
        const Color got = canvas_.color(x, y);
        if (!finite(got)) {
          ++result.nonfinite;
          note(result, order, pixel_name(x, y) + " has colour " + color_text(got));
        }
        if (!covered || !shade) continue;
        const Color want = ref.color(x, y);
        const double before = result.colour.max;
        result.colour.add(got.r, want.r);
        result.colour.add(got.g, want.g);
        result.colour.add(got.b, want.b);
        if (result.colour.max > tolerance_ && before <= tolerance_)
          note(result, order,
               pixel_name(x, y) + " colour " + color_text(got) + ", exact " + color_text(want));
      }
    compare_orders(order, result);
  }
  return result;
}

CaseResult Checker::check_mesh(Rasterizer& r, const StressCase& c, const ReferenceWindow& region) {
  CaseResult result;
  // The triangles (in the given vertex order) whose closed coverage holds pixel (x, y): the ones
  // that compete for it, which is what a reproducer of a gap or an overlap needs.
  const auto around = [&](int order, int x, int y) {
    std::string s;
    int listed = 0;
    for (std::size_t i = 0; i < c.triangles.size() && listed < 4; ++i) {
      const Triangle t = permuted(c.triangles[i], order);
      const reference::Polygon poly(t.v, reference::kExactBits);
      if (!poly.covers(x, y, FillRule::closed)) continue;
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
      s += listed++ ? "; " : "; triangles touching it: ";
      s += "#";
      s += std::to_string(i);
      s += " \"";
      s += points_text(t);
      s += "\"";
    }
    return s;
  };
  for (int order = 0; order < 6; ++order) {
    canvas_.reset(c.width, c.height);
    r.begin(canvas_);
    for (const Triangle& original : c.triangles) {
      const Triangle t = permuted(original, order);
      const Clock::time_point start = Clock::now();
      r.draw(canvas_, t, c.bits, Shading::flat);
      result.fill_seconds += std::chrono::duration<double>(Clock::now() - start).count();
      r.collect(canvas_, t);
      ++result.fills;
    }
    result.ref_pixels += region.count();
    if (canvas_.out_of_bounds() > 0) {
      result.extra += canvas_.out_of_bounds();
      note(result, order, std::to_string(canvas_.out_of_bounds()) + " writes outside the canvas");
    }
    const Window w = compared_window(region, canvas_);
    for (int y = w.y0; y < w.y1; ++y)
      for (int x = w.x0; x < w.x1; ++x) {
        const int n = canvas_.count(x, y);
        const bool inside = region.covers(x, y);
        if (inside && n == 0) {
          ++result.gaps;
          if (result.problem.empty())
            note(result, order, "gap at " + pixel_name(x, y) + around(order, x, y));
        }
        if (n > 1) {
          ++result.overlaps;
          if (result.problem.empty())
            note(result, order,
                 pixel_name(x, y) + " written " + std::to_string(n) + " times" +
                     around(order, x, y));
        }
        if (!inside && n > 0) {
          ++result.extra;
          if (result.problem.empty())
            note(result, order,
                 pixel_name(x, y) + " written outside the tiled rectangle" + around(order, x, y));
        }
        if (n > 0 && !finite(canvas_.color(x, y))) {
          ++result.nonfinite;
          note(result, order, pixel_name(x, y) + " has colour " + color_text(canvas_.color(x, y)));
        }
      }
    compare_orders(order, result);
  }
  return result;
}

}  // namespace scantrace::stress
