#pragma once
// A CLI11 validator from a parser that throws: option values are checked while the command line
// is parsed, so a malformed value is a usage error (exit status 2) that quotes the parser's reason.
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

namespace scantrace::cli {

template <class Parse>
CLI::Validator parsed_by(Parse parse) {
  return CLI::Validator(
      [parse](std::string& value) -> std::string {
        try {
          parse(value);
          return {};
        } catch (const std::exception& e) {
          return e.what();
        }
      },
      "");
}

}  // namespace scantrace::cli
