// DiffReport as report.json and as the Markdown summary printed by `scantrace diff`.
#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>

#include "grade/diff_report.hpp"

namespace scantrace::grade {
namespace {

nlohmann::json color_json(Color c) {
  return nlohmann::json::array({c.r, c.g, c.b});
}
std::string face_name(int f) {
  return f >= 0 ? fmt::format("face {}", f) : f == -1 ? "background" : "no face";
}
double percent(std::int64_t n, std::int64_t of) {
  return of > 0 ? 100.0 * n / of : 0.0;
}

// The per-pixel categories, compactly: runs [start, length, code] of equal categories along the
// canvas's rows (pixel p = y * width + x), code indexing `legend`; agreeing pixels are in no run.
nlohmann::json category_runs(const std::vector<std::uint8_t>& map) {
  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t p = 0; p < map.size();) {
    const std::uint8_t c = map[p];
    std::size_t end = p + 1;
    while (end < map.size() && map[end] == c) ++end;
    if (c != 0) runs.push_back({p, end - p, c - 1});
    p = end;
  }
  nlohmann::json legend = nlohmann::json::array();
  for (const char* c : kCategories) legend.push_back(c);
  return {{"encoding", "runs"}, {"legend", legend}, {"runs", runs}};
}

}  // namespace

std::optional<Category> category_named(std::string_view name) {
  for (std::size_t i = 0; i < kCategoryCount; ++i)
    if (name == kCategories[i]) return category_at(i);
  return std::nullopt;
}

nlohmann::json DiffReport::to_json() const {
  nlohmann::json global_json = nlohmann::json::array();
  for (const auto& g : global)
    global_json.push_back({{"kind", g.kind}, {"text", g.text}, {"undone", g.undone}});
  nlohmann::json faces_json = nlohmann::json::array();
  for (const auto& f : faces)
    faces_json.push_back({{"face", f.face}, {"pixels", f.pixels}, {"category", f.category}});
  nlohmann::json missing_json = nlohmann::json::array();
  for (const auto& m : missing_faces)
    missing_json.push_back({{"face", m.face}, {"pixels", m.pixels}, {"shape", m.shape}});
  nlohmann::json examples_json = nlohmann::json::array();
  for (const auto& e : examples)
    examples_json.push_back({{"category", e.category},
                             {"pixel", {e.x, e.y}},
                             {"expected", color_json(e.expected)},
                             {"got", color_json(e.got)},
                             {"reference_face", e.reference_face},
                             {"image_face", e.image_face},
                             {"why", e.why}});
  nlohmann::json verdict_json = nlohmann::json::array();
  for (const auto& v : verdict)
    verdict_json.push_back({{"id", v.id.empty() ? nlohmann::json(nullptr) : nlohmann::json(v.id)},
                            {"text", v.text},
                            {"evidence", v.evidence}});
  nlohmann::json cats = nlohmann::json::object();
  for (const char* c : kCategories) cats[c] = categories.at(c);
  return {{"format", "scantrace-diff"},
          {"version", 1},
          {"canvas", {{"width", width}, {"height", height}}},
          {"image", {{"width", image_width}, {"height", image_height}}},
          {"tolerance", tolerance},
          {"compared_pixels", compared_pixels},
          {"differing_pixels", differing_pixels},
          {"agrees", agrees()},
          {"verdict", verdict_json},
          {"global", global_json},
          {"categories", cats},
          {"near_boundary", {{"extra", near_boundary_extra}, {"missing", near_boundary_missing}}},
          {"patterns", patterns},
          {"faces", faces_json},
          {"missing_faces", missing_json},
          {"colour", {{"diagnosis", colour_diagnosis}, {"max_error", max_colour_error}}},
          {"notes", notes},
          {"examples", examples_json},
          {"category_map", category_runs(category_map)}};
}

std::string DiffReport::to_markdown() const {
  std::string md = "# scantrace diff\n\n";
  md += fmt::format("Canvas {}x{}, image {}x{}, tolerance {:.4g} per channel.\n\n", width, height,
                    image_width, image_height, tolerance);
  if (agrees()) {
    md += fmt::format("**The image agrees with the reference** ({} pixels compared).\n",
                      compared_pixels);
    for (const auto& n : notes) md += "\nNote: " + n + "\n";
    return md;
  }
  // The verdict first, in the catalogue's words; the categories after it say where.
  for (const auto& v : verdict)
    md += fmt::format("{} **{}**{}\n", v.id.empty() ? "-" : "- Verdict:", v.text,
                      v.evidence.empty() ? "" : " (" + v.evidence + ")");
  if (!verdict.empty()) md += "\n";
  md += fmt::format("**{} of {} pixels differ ({:.2f} %).**\n\n", differing_pixels, compared_pixels,
                    percent(differing_pixels, compared_pixels));
  if (!global.empty()) {
    md += "## Global mistakes\n\n";
    for (const auto& g : global)
      md += fmt::format("- `{}`: {}{}\n", g.kind, g.text,
                        g.undone ? " — undone before classifying the pixels" : "");
    md += "\n";
  }
  if (differing_pixels > 0) {
    md +=
        "## Differing pixels by category\n\n| category | pixels | % of differing "
        "|\n|---|---:|---:|\n";
    for (const char* c : kCategories) {
      const auto n = categories.at(c);
      if (n > 0) md += fmt::format("| `{}` | {} | {:.1f} |\n", c, n, percent(n, differing_pixels));
    }
    md += "\n";
  }
  if (near_boundary_extra + near_boundary_missing > 0)
    md += fmt::format(
        "Near the boundary: {} extra pixels (outside their face), {} missing (inside "
        "their face).\n\n",
        near_boundary_extra, near_boundary_missing);
  for (const auto& p : patterns) md += "- Pattern: " + p + "\n";
  if (!patterns.empty()) md += "\n";
  if (!missing_faces.empty()) {
    md += fmt::format("## Missing faces ({})\n\n", missing_faces.size());
    std::size_t shown = 0;
    for (const auto& m : missing_faces) {
      if (++shown > 20) {
        md += fmt::format("- … and {} more (report.json lists them all)\n",
                          missing_faces.size() - 20);
        break;
      }
      md += fmt::format("- face {} ({} pixel{} in the reference): {}\n", m.face, m.pixels,
                        m.pixels == 1 ? "" : "s", m.shape);
    }
    md += "\n";
  }
  if (categories.at("colour") > 0) {
    md += fmt::format("## Colour\n\nMax error {:.4f} per channel.\n", max_colour_error);
    for (const auto& d : colour_diagnosis) md += "- " + d + "\n";
    if (colour_diagnosis.empty()) md += "- no usual mistake explains most of them\n";
    md += "\n";
  }
  if (!faces.empty()) {
    md += "## Most affected faces\n\n";
    for (const auto& f : faces)
      md += fmt::format("- face {}: {} pixels, mostly `{}`\n", f.face, f.pixels, f.category);
    md += "\n";
  }
  for (const auto& n : notes) md += "Note: " + n + "\n\n";
  if (!examples.empty()) {
    md += "## Examples\n\n";
    for (const auto& e : examples)
      md += fmt::format("- `{}` at ({}, {}): expected {}, the image shows {}. {}\n", e.category,
                        e.x, e.y, face_name(e.reference_face), face_name(e.image_face), e.why);
  }
  return md;
}

}  // namespace scantrace::grade
