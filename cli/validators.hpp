#pragma once
// A CLI11 validator from a parser that throws: option values are checked while the command line
// is parsed, so a malformed value is a usage error (exit status 2) that quotes the parser's reason.
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

namespace scantrace::cli {

// CLI11 already prefixes the message with the option's name; the parsers name it too (they are
// also used outside option parsing), so a leading "--name: " or "--name " is dropped here rather
// than printed twice ("--colors: --colors: ...").
inline std::string without_option_prefix(std::string message) {
  if (message.rfind("--", 0) != 0) return message;
  const std::size_t end = message.find_first_of(": ");
  if (end == std::string::npos) return message;
  const std::size_t skip = message.compare(end, 2, ": ") == 0 ? end + 2 : end + 1;
  return message.substr(skip);
}

template <class Parse>
CLI::Validator parsed_by(Parse parse) {
  return CLI::Validator(
      [parse](std::string& value) -> std::string {
        try {
          parse(value);
          return {};
        } catch (const std::exception& e) {
          return without_option_prefix(e.what());
        }
      },
      "");
}

}  // namespace scantrace::cli
