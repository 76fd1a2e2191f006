#pragma once
// gzip (RFC 1952) through libdeflate: what the pages this project writes carry, and
// what a browser inflates with DecompressionStream("gzip") (the trace page, cli/trace_page.hpp;
// the page of SVG frames, viz/step_page.hpp).
#include <string_view>
#include <vector>

namespace scantrace {

// `level`: libdeflate's, 1 (fastest) .. 12 (smallest). Throws std::runtime_error when out of
// memory.
std::vector<unsigned char> gzip(std::string_view bytes, int level = 12);

}  // namespace scantrace
