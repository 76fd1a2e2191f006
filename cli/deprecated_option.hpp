#pragma once
// An old spelling of an option that keeps working: it sets the same value as the new name and
// prints one warning line naming the new one (while parsing, so it shows with --quiet too).
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

namespace scantrace::cli {

template <class T>
CLI::Option* add_deprecated_alias(CLI::App& command, const std::string& old_name,
                                  const std::string& new_name, T& target) {
  return command.add_option(old_name, target, "deprecated spelling of " + new_name)
      ->each([old_name, new_name](const std::string&) {
        spdlog::warn("warning: {} is deprecated, use {}", old_name, new_name);
      })
      ->group("Deprecated");
}

}  // namespace scantrace::cli
