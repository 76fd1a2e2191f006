#pragma once
// The stages of `diff` (diff_report.hpp), each a function from the evidence it reads to a struct of
// what it found, run in order by diff() in diff.cpp:
//
//   align            the reference, the image on its canvas, global mistakes found and undone
//   compare          the pixels that differ beyond the tolerance
//   attribute        which face the image shows at each pixel (diff_attribute.cpp)
//   find faces       faces missing, moved or drawn too wide (diff_attribute.cpp)
//   classify         every differing pixel's category (diff_classify.cpp)
//   tally, patterns  counts, dominant patterns, the colour diagnosis, faces hit (diff_findings.cpp)
//   report           the verdict and a few pixels explained (diff_findings.cpp)
//
// Internal to grade/: only diff*.cpp include it.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grade/diff_report.hpp"
#include "grade/diff_verdict.hpp"
#include "grade/face_geometry.hpp"
#include "grade/face_id_render.hpp"

namespace scantrace::grade::diff_stages {

inline constexpr int kBackground = -1;  // the image shows the background there
inline constexpr int kNoFace = -2;      // no face's colour matches the image there

double max_diff(Rgb32f a, Rgb32f b);
double max_diff(Color a, Rgb32f b);

// Faces by 8×8-pixel cell of their bounding box widened by 1.5 px: the faces "around" a pixel.
class FaceGrid {
 public:
  static constexpr int kCell = 8;
  explicit FaceGrid(const Scene& s);
  const std::vector<int>& at(int x, int y) const {
    return cells_[static_cast<std::size_t>(y / kCell) * cw_ + x / kCell];
  }

 private:
  int cw_, ch_;
  std::vector<std::vector<int>> cells_;
};

// Each face's geometry, built the first time a stage asks for it (most faces never differ).
class Faces {
 public:
  Faces(const Scene& s, int bits) : scene_(s), bits_(bits), geo_(s.faces.size()) {}
  const FaceGeometry& operator[](int f) const {
    auto& g = geo_[static_cast<std::size_t>(f)];
    if (!g) g = std::make_unique<FaceGeometry>(scene_, f, bits_);
    return *g;
  }

 private:
  const Scene& scene_;
  int bits_;
  mutable std::vector<std::unique_ptr<FaceGeometry>> geo_;
};

// What every stage reads: the scene, the options, and the reference's face per pixel.
struct DiffScene {
  DiffScene(const Scene& scene, const FillOptions& options, const DiffOptions& dopt);

  const Scene& scene;
  const FillOptions& options;
  const DiffOptions& dopt;
  const int width, height;
  const double tolerance;
  // Matching a colour to a face allows for the image's own 8-bit rounding on top of the tolerance.
  const double match_tolerance;
  const FillRule rule;
  const FaceIdImage ids;            // the face the reference shows, per pixel
  const std::vector<double> depth;  // each face's mean depth (the painter's order)
  const FaceGrid grid;
  const Faces faces;
  const std::size_t n_faces;

  int px(std::size_t i) const { return static_cast<int>(i % static_cast<std::size_t>(width)); }
  int py(std::size_t i) const { return static_cast<int>(i / static_cast<std::size_t>(width)); }
  std::size_t idx(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

// Align: the submitted image on the scene's canvas, the global mistakes undone (unless
// DiffOptions::undo is false), and the pixels compared.
struct Aligned {
  std::vector<GlobalMistake> global;
  RgbImage image;
  std::vector<unsigned char> compared;
  std::vector<std::string> notes;  // what is odd but no global mistake
};
Aligned undo_global_mistakes(const DiffScene& s, const RgbImage& reference,
                             const SubmittedImage& submitted);

// Compare: the pixels differing by more than the tolerance, and the 8-bit truncation note.
struct Comparison {
  std::int64_t compared_pixels = 0;
  std::vector<std::size_t> differing;  // pixel indices, ascending
  std::optional<std::string> truncation_note;
};
Comparison compare_pixels(const DiffScene& s, const RgbImage& reference, const Aligned& aligned,
                          bool eight_bit_input);

// Each face's pixels in the reference, in y order (a counting sort by face id).
struct FacePixels {
  std::vector<std::size_t> start, pixels;  // face f's are pixels[start[f] .. start[f + 1])
  std::size_t count(std::size_t f) const { return start[f + 1] - start[f]; }
};

// Attribute: the face the image shows at each pixel (a face, kBackground or kNoFace).
struct Attribution {
  std::vector<int> seen;
  FacePixels reference;
};
Attribution attribute_pixels(const DiffScene& s, const Aligned& aligned, const RgbImage& reference,
                             const Comparison& cmp);

// Find faces: per face, what the image did to it as a whole.
struct FaceFindings {
  std::vector<std::int64_t> ref_pixels, shown;  // pixels the reference / the image shows it on
  std::vector<char> missing;                    // shown nowhere
  std::vector<char> shifted;                    // shown translated by one pixel
  std::vector<char> widened;                    // drawn one pixel too wide at both span ends
  // Pixels showing a face just outside its spans (VerdictEvidence's extended_* counts).
  std::int64_t extended_left = 0, extended_right = 0;
  std::int64_t extended_off_outline = 0, extended_beyond_half = 0;
};
FaceFindings find_face_mistakes(const DiffScene& s, const Comparison& cmp,
                                const Attribution& shown);

// Classify: every differing pixel's category, and the near-boundary pixels' patterns.
struct Classification {
  std::vector<Category> categories;  // per differing pixel (Comparison::differing's order)
  std::int64_t near_boundary_extra = 0, near_boundary_missing = 0;
  std::map<std::string, std::int64_t> tags_missing, tags_extra;  // pattern → pixels
};
Classification classify_pixels(const DiffScene& s, const Comparison& cmp, const Attribution& shown,
                               const FaceFindings& faces);

// Tally: the counts, the per-pixel map, the damage per face, the examples to explain.
struct Tally {
  std::map<std::string, std::int64_t> counts;  // every name of kCategories
  std::vector<std::uint8_t> category_map;      // DiffReport::category_map
  // Per face the reference (else the image) shows at a differing pixel: pixels by category name.
  std::map<int, std::map<std::string, std::int64_t>> damage;
  std::vector<std::size_t> colour_pixels;
  std::array<std::vector<std::size_t>, kCategoryCount> examples;  // the first few of each
};
Tally tally_categories(const DiffScene& s, const Comparison& cmp, const Attribution& shown,
                       const Classification& cls);

// Patterns: the dominant near-boundary patterns, in words.
std::vector<std::string> find_patterns(const Classification& cls);

// Which usual mistake reproduces the wrong colours, and the largest colour error.
struct ColourDiagnosis {
  std::vector<std::string> lines;
  double max_error = 0;
};
ColourDiagnosis diagnose_colours(const DiffScene& s, const RgbImage& reference,
                                 const RgbImage& image, const std::vector<std::size_t>& colour);

// The faces most affected (at most 5), and the faces the table counts as missing.
struct FaceLists {
  std::vector<FaceDamage> most_affected;
  std::vector<MissingFace> missing;
};
FaceLists list_faces(const DiffScene& s, const Comparison& cmp, const Classification& cls,
                     const FaceFindings& faces, const Tally& tally);

// What the categories' counts do not hold, for the verdict (diff_verdict.hpp).
VerdictEvidence verdict_evidence(const DiffScene& s, const DiffReport& report,
                                 const Aligned& aligned, const Comparison& cmp,
                                 const Attribution& shown, const FaceFindings& faces,
                                 const Classification& cls);

// A few pixels of each category, explained.
std::vector<Example> explain_examples(const DiffScene& s, const RgbImage& reference,
                                      const RgbImage& image, const Attribution& shown,
                                      const Tally& tally);

}  // namespace scantrace::grade::diff_stages
