#pragma once
// The byte layout of a MATLAB v5 .mat file checked before matio reads it. matio 1.5 reads a
// numeric variable's values by the count its dimensions declare, not by the length its data
// element holds: a file missing its last 8 bytes rendered (the painter's order flipped by the
// garbage read), and a `faces` declaring 2×3 while holding 1×3 took its second row from the heap
// (the previous variable's freed buffer). Here every top-level element must end inside the file,
// a compressed one must inflate to the whole element it declares, and each numeric matrix's real
// part must hold exactly the elements its dimensions declare. v7.3 (HDF5, checked by HDF5 itself)
// and v4 files are passed over.
#include <optional>
#include <string>
#include <string_view>

namespace scantrace {

struct Mat5Problem {
  std::string element;  // the variable's name, or "" for the file as a whole
  std::string problem;
};

// The first structural problem of the v5 file `bytes`, nullopt when there is none (or when the
// file is not a v5 file). Inflating a compressed element works in a fixed buffer: its memory is
// bounded whatever the element declares.
std::optional<Mat5Problem> mat5_layout_problem(std::string_view bytes);

}  // namespace scantrace
