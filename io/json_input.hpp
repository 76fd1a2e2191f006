#pragma once
// Reading user-supplied JSON with error messages a person can act on: the file, line and column of
// a syntax error, and a short quotation of a value that has the wrong shape. Shared by the readers
// of every JSON-based input (scene files now, traces later).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/input_error.hpp"

namespace scantrace::json_input {

// The whole file as bytes; InputError("<file>: cannot read file: <reason>") when it cannot be read.
std::string read_text_file(const std::filesystem::path& file);

// 1-based line and column of the byte at 0-based `offset` in `text`.
struct TextPosition {
  std::size_t line = 1, column = 1;
};
TextPosition position_of(std::string_view text, std::size_t offset);

// Parses `text`; a syntax error becomes InputError "<name>:<line>:<column>: JSON syntax error:
// ...".
nlohmann::json parse(std::string_view text, const std::string& name_for_errors);

// A value quoted for an error message: compact JSON, cut to about `max_chars` characters.
std::string quote(const nlohmann::json& value, std::size_t max_chars = 60);

}  // namespace scantrace::json_input
