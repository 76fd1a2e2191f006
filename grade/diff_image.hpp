#pragma once
// diff.png: the reference in grey, every differing pixel in the colour of its category, a legend
// with the counts, and a magnified inset of the worst region (the 32×32 window holding the most
// differing pixels), so a grader sees at a glance where and what kind the mistakes are.
#include <filesystem>

#include "grade/diff_report.hpp"

namespace scantrace::grade {

// The PNG's bytes. Throws std::runtime_error naming `file` (where it is meant to go).
std::string diff_image_png(const DiffReport& report, const std::filesystem::path& file);

// Written atomically (temporary name, then rename). Throws std::runtime_error naming the file.
void write_diff_image(const DiffReport& report, const std::filesystem::path& file);

}  // namespace scantrace::grade
