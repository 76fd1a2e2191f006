#include "stress/report.hpp"

#include <cstdio>
#include <string>

#include "src/fill_options.hpp"
#include "stress/checks.hpp"

namespace scantrace::stress {
namespace {

std::string number(long long v) {
  return std::to_string(v);
}

std::string format(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Appended rather than "\"" + …: GCC 12 raises a false -Wrestrict alarm on literal + string&&.
std::string quoted_points(const Triangle& t) {
  std::string s = "\"";
  s += points_text(t);
  s += '"';
  return s;
}

std::string quoted_colors(const Triangle& t) {
  std::string s;
  char buf[96];
  for (const Color& c : t.c) {
    std::snprintf(buf, sizeof buf, "%s%.17g,%.17g,%.17g", s.empty() ? "" : " ", c.r, c.g, c.b);
    s += buf;
  }
  return "\"" + s + "\"";
}

}  // namespace

std::string markdown_table(const RunResult& result) {
  const std::string dash = "—";
  std::string t =
      "| family | method | cases | triangles | fills | ref px | missing | extra | gaps | "
      "overlaps | order diffs | max err | RMS err | max err 8-bit | RMS 8-bit | NaN/Inf | "
      "µs/fill | failing cases |\n"
      "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const CellStats& c : result.cells) {
    const bool colours = c.shades && c.colour.samples > 0;
    t += "| " + std::string(to_string(c.family)) + " | " + c.method + " | " + number(c.cases) +
         " | " + number(c.triangles) + " | " + number(c.fills) + " | " + number(c.ref_pixels) +
         " | " + (c.mesh ? dash : number(c.missing)) + " | " + number(c.extra) + " | " +
         (c.mesh ? number(c.gaps) : dash) + " | " + number(c.overlaps) + " | " +
         number(c.order_diffs) + " | " + (colours ? format("%.2e", c.colour.max) : dash) + " | " +
         (colours ? format("%.2e", c.colour.rms()) : dash) + " | " +
         (colours ? number(c.colour.max8) : dash) + " | " +
         (colours ? format("%.4f", c.colour.rms8()) : dash) + " | " + number(c.nonfinite) + " | " +
         (c.fills ? format("%.2f", 1e6 * c.fill_seconds / static_cast<double>(c.fills)) : dash) +
         " | " + number(c.failing_cases) + " |\n";
  }
  return t;
}

std::string reproducer(const StressCase& c, const std::string& method, const CaseResult& r) {
  const auto& o = kOrders[r.problem_order];
  std::string line =
      "FAIL " + method + " " + to_string(c.family) + " seed=" + std::to_string(c.seed) +
      " index=" + std::to_string(c.index) + " (" + c.kind + ") order=(" + std::to_string(o[0]) +
      "," + std::to_string(o[1]) + "," + std::to_string(o[2]) + "): " + r.problem + "; canvas " +
      std::to_string(c.width) + "x" + std::to_string(c.height) + ", bits " + std::to_string(c.bits);
  if (!c.is_mesh()) {
    const Triangle t = permuted(c.triangles.front(), r.problem_order);
    Method m;
    if (parse_method(method.c_str(), m))
      line += "; trace: scantrace trace --triangle " + quoted_points(t) + " --colors " +
              quoted_colors(t) + " --size " + std::to_string(c.width) + "x" +
              std::to_string(c.height) + " --subpixel-bits " + std::to_string(c.bits) +
              " --method " + method + " -o repro.jsonl";
    else
      line += "; vertices " + quoted_points(t) + " colors " + quoted_colors(t);
  }
  line += "; replay: scantrace stress --seed " + std::to_string(c.seed) + " --family " +
          to_string(c.family) + " --case " + std::to_string(c.index) + " --method " + method;
  return line;
}

}  // namespace scantrace::stress
