#pragma once
// The error every reader of user-supplied files throws: one line naming the file, the element and
// the problem ("scene.json: faces[812]: vertex index 5012 is out of range (4999 vertices)"), so the
// command line can print it as is and exit with status 1 (docs/design.md §7).
#include <stdexcept>
#include <string>

namespace scantrace {

class InputError : public std::runtime_error {
 public:
  // "<file>: <element>: <problem>", or "<file>: <problem>" when no single element is at fault
  // (a reader that reports positions may pass "file:line" as `file`).
  InputError(const std::string& file, const std::string& element, const std::string& problem)
      : std::runtime_error(compose(file, element, problem)),
        file_(file),
        element_(element),
        problem_(problem) {}

  const std::string& file() const { return file_; }
  const std::string& element() const { return element_; }  // may be empty
  const std::string& problem() const { return problem_; }

 private:
  static std::string compose(const std::string& file, const std::string& element,
                             const std::string& problem) {
    std::string s = file;
    if (!element.empty()) s += ": " + element;
    if (!problem.empty()) s += ": " + problem;
    // The message is one line even when a problem quotes input text.
    for (char& c : s)
      if (c == '\n' || c == '\r') c = ' ';
    return s;
  }

  std::string file_, element_, problem_;
};

}  // namespace scantrace
