#pragma once
// Reading user-supplied JSON with error messages a person can act on: the file, line and column of
// a syntax error, and a short quotation of a value that has the wrong shape. Shared by the readers
// of every JSON-based input (scene files now, traces later).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/input_error.hpp"

namespace scantrace::json_input {

// The whole file as bytes; InputError("<file>: cannot read file: <reason>") when it cannot be read,
// is not a regular file (a FIFO, a device: io/input_file.hpp) or is larger than the memory
// available. The string's capacity keeps at least kReadPadding bytes after the text, so that a
// parser reading whole vectors past its end (simdjson) can use the text in place.
std::string read_text_file(const std::filesystem::path& file);
inline constexpr std::size_t kReadPadding = 64;

// 1-based line and column of the byte at 0-based `offset` in `text`.
struct TextPosition {
  std::size_t line = 1, column = 1;
};
TextPosition position_of(std::string_view text, std::size_t offset);

// How deep JSON input may nest arrays and objects. Real inputs nest 3 levels (a scene's
// "faces": [[0, 1, 2]]) or 5 (a trace's scanline); a few hundred thousand levels made the
// recursive parts of nlohmann (copy, dump, from_json, destruction in older versions) overflow the
// stack. 64 is far beyond any real input and far below what the stack holds.
inline constexpr int kMaxNestingDepth = 64;

// The 0-based offset of the bracket ('[' or '{' outside strings) that opens level max_depth + 1,
// or nullopt when `text` nests no deeper than max_depth. One pass, no recursion, no allocation:
// run it before handing untrusted text to nlohmann. Text that is not valid JSON is scanned as far
// as it goes; the parser reports its syntax errors afterwards.
std::optional<std::size_t> find_excess_nesting(std::string_view text,
                                               int max_depth = kMaxNestingDepth);

// What nlohmann's DOM of `text` will take in memory: 16 bytes a value and 64 more a container
// (its vector or map and the allocation), counted in one pass. parse() checks it against the
// memory available (io/memory_budget.hpp) before parsing.
std::uint64_t estimated_dom_bytes(std::string_view text);

// "JSON nested deeper than 64 levels": the problem, for readers that format their own position.
std::string nesting_problem(int max_depth = kMaxNestingDepth);

// Parses `text`; a syntax error becomes InputError "<name>:<line>:<column>: JSON syntax error:
// ...", nesting beyond max_depth "<name>:<line>:<column>: JSON nested deeper than 64 levels"
// (checked before parsing). Every reader of user-supplied JSON goes through here (or through
// find_excess_nesting when it reports positions its own way, as the trace reader does per line).
nlohmann::json parse(std::string_view text, const std::string& name_for_errors,
                     int max_depth = kMaxNestingDepth);

// A value quoted for an error message: compact JSON, cut to about `max_chars` characters.
std::string quote(const nlohmann::json& value, std::size_t max_chars = 60);

}  // namespace scantrace::json_input
