#pragma once
// The byte layout of a MATLAB v5 .mat file checked before matio reads it. matio 1.5 reads a
// numeric variable's values by the count its dimensions declare, not by the length its data
// element holds: a file missing its last 8 bytes rendered (the painter's order flipped by the
// garbage read), and a `faces` declaring 2×3 while holding 1×3 took its second row from the heap
// (the previous variable's freed buffer). Here every top-level element must end inside the file,
// a compressed one must inflate to the whole element it declares, and each numeric matrix's real
// part must hold exactly the elements its dimensions declare. Only v5 is read at all: v7.3 files
// are HDF5 and v4 files have no header (mat_file_version below, and why in io/mat_scene.cpp).
#include <optional>
#include <string>
#include <string_view>

namespace scantrace {

// What the 128-byte header says the file is. v5 and v7.3 share it (0x0100 or 0x0200 at byte 124,
// in the byte order "IM"/"MI" at byte 126 names); a v4 file has no such header.
enum class MatFileVersion { v5, v73, other };
MatFileVersion mat_file_version(std::string_view bytes);

struct Mat5Problem {
  std::string element;  // the variable's name, or "" for the file as a whole
  std::string problem;
};

// The first structural problem of the v5 file `bytes`, nullopt when there is none (or when the
// file is not a v5 file). Inflating a compressed element works in a fixed buffer: its memory is
// bounded whatever the element declares.
std::optional<Mat5Problem> mat5_layout_problem(std::string_view bytes);

}  // namespace scantrace
