#pragma once
// The one mistake catalogue, so every reader names a mistake alike: python/scantrace/grade/mistakes.json, embedded into this
// library at build time (grade/CMakeLists.txt generates mistake_catalogue_data.cpp from it), so
// `diff`'s verdicts speak the grader's words and both use one set of whole-image tolerances.
#include <string>
#include <string_view>
#include <vector>

namespace scantrace::grade {

struct CatalogueMistake {
  std::string id;        // stable: the grader's cause id
  std::string sentence;  // what a student reads ({detail}: filled in by the grader)
  std::string fix;
  std::string verdict;   // diff's one line when the image shows it ("" where it cannot)
};

// Every mistake, in the file's order.
const std::vector<CatalogueMistake>& mistake_catalogue();

// The mistake `id`; throws std::out_of_range for an id the catalogue does not have (a typo in
// the code is a failing test, not a silent empty sentence).
const CatalogueMistake& catalogue_mistake(std::string_view id);

// A tolerance of the whole-image mistakes ("whole_image" in the file); throws std::out_of_range.
double whole_image_tolerance(std::string_view name);

// The file's text, as embedded.
std::string_view mistake_catalogue_json();

}  // namespace scantrace::grade
