#pragma once
// `diff`: where and why a submitted image differs from the reference render of the same scene.
//
//   1. Global mistakes first, each one line: canvas size, background colour, transposed image,
//      vertical/horizontal flip, RGB/BGR swapped, colours scaled to [0, 255] (.npy). When one
//      explains the image it is undone (unless DiffOptions::undo is false) and the rest is
//      classified after it.
//   2. Every pixel that still differs by more than the tolerance is matched against the faces
//      around it (which face does the image show there?) and put into the first category that
//      applies (kCategories, in that order; docs/grading.md explains each).
//
//   3. The verdict: the mistakes of the catalogue the global mistakes and the categories point to,
//      in the catalogue's words (diff_verdict.hpp), printed first.
//
// The result is a value type: the CLI prints it (Markdown, JSON) and draws it (diff.png); tests
// read its numbers.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grade/image_header.hpp"
#include "src/fill_options.hpp"
#include "src/image.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {

// The per-pixel categories, in the order they are tried (docs/grading.md's table).
enum class Category : std::uint8_t {
  boundary,
  near_boundary,
  widened,
  shifted,
  order,
  order_tie,
  missing_face,
  degenerate_drawn,
  colour,
  background,
  other
};
inline constexpr std::size_t kCategoryCount = 11;
// Their names, indexed by Category: the JSON report's keys, diff.png's legend.
inline constexpr std::array<const char*, kCategoryCount> kCategories{
    "boundary",     "near_boundary",    "widened", "shifted",    "order", "order_tie",
    "missing_face", "degenerate_drawn", "colour",  "background", "other"};
constexpr const char* category_name(Category c) {
  return kCategories[static_cast<std::size_t>(c)];
}
constexpr Category category_at(std::size_t index) {
  return static_cast<Category>(index);
}
// The category of a name of kCategories; none for any other text.
std::optional<Category> category_named(std::string_view name);

struct DiffOptions {
  double tolerance = 1.0 / 255.0;  // per channel
  bool undo = true;                // undo the global mistakes found before classifying
  int examples_per_category = 3;   // pixels of each category explained with `why`
};

struct GlobalMistake {
  std::string kind;  // "canvas_size", "background", "transposed", "flipped_vertically",
                     // "flipped_horizontally", "bgr", "scaled_255"
  std::string text;  // one line in words
  bool undone = false;
};

struct FaceDamage {
  int face = 0;
  std::int64_t pixels = 0;  // differing pixels where the reference or the image shows it
  std::string category;     // the most frequent category among them
};

struct MissingFace {
  int face = 0;
  std::int64_t pixels = 0;  // pixels the reference shows of it
  std::string shape;        // "horizontal edge", "sliver", …
};

struct Example {
  std::string category;
  int x = 0, y = 0;
  Color expected, got;
  int reference_face = -1, image_face = -1;  // -1: background, -2: no face matches
  std::string why;                           // the one-paragraph story of the pixel
};

// One line of the verdict: a mistake of the catalogue (grade/mistake_catalogue.hpp) in its words,
// or (id empty) what the image cannot tell and what would.
struct Verdict {
  std::string id;        // the catalogue's id; "" for a line that names no mistake
  std::string text;      // the catalogue's verdict sentence
  std::string evidence;  // the counts behind it, in words
};

struct DiffReport {
  int width = 0, height = 0;              // the scene's canvas
  int image_width = 0, image_height = 0;  // the submitted image's
  double tolerance = 0;
  std::int64_t compared_pixels = 0;
  std::int64_t differing_pixels = 0;
  std::vector<GlobalMistake> global;
  std::vector<Verdict> verdict;  // the mistakes named, first in the report (diff_verdict.hpp)
  std::map<std::string, std::int64_t> categories;  // every name of kCategories
  std::int64_t near_boundary_extra = 0, near_boundary_missing = 0;
  std::vector<std::string> patterns;  // dominant patterns in words
  std::vector<FaceDamage> faces;      // the most affected faces, most first (at most 5)
  std::vector<MissingFace> missing_faces;
  std::vector<std::string> colour_diagnosis;  // what explains the `colour` pixels
  double max_colour_error = 0;
  std::vector<std::string> notes;  // e.g. 8-bit truncation within the tolerance
  std::vector<Example> examples;
  // Per pixel of the scene's canvas: 0 agrees, 1 + category index otherwise (diff.png).
  std::vector<std::uint8_t> category_map;
  RgbImage reference;

  bool agrees() const { return differing_pixels == 0 && global.empty(); }
  nlohmann::json to_json() const;
  std::string to_markdown() const;
};

DiffReport diff(const Scene& scene, const FillOptions& options, const SubmittedImage& image,
                const DiffOptions& diff_options = {});

}  // namespace scantrace::grade
