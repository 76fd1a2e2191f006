#pragma once
// A CLI11 validator from a parser that throws: option values are checked while the command line
// is parsed, so a malformed value is a usage error (exit status 2) that quotes the parser's reason.
#include <cmath>
#include <cstdlib>
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

// Refuses NaN and the infinities (and literals beyond a double, which strtod makes infinite):
// CLI11 reads "nan" and "inf" into a double, and its Range(0, 1) lets NaN through, so `diff
// --tolerance nan` passed every image. require_finite_numbers puts it on every option of type
// FLOAT; options whose text holds numbers (X,Y,Z, WxH, A:B) refuse them in their own parsers.
inline CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        const char* text = value.c_str();
        char* end = nullptr;
        const double v = std::strtod(text, &end);
        if (end != text && !std::isfinite(v)) return "\"" + value + "\" is not a finite number";
        return {};  // not a number at all: CLI11's conversion says so
      },
      "");
}

// Adds finite_number() to every floating-point option of `app` and of its subcommands, at any
// depth: no command takes NaN or an infinity for a number (tests/cli/finite_options_test.cpp
// walks every option of every subcommand's --help).
inline void require_finite_numbers(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite_number());
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    require_finite_numbers(*sub);
}

}  // namespace scantrace::cli
