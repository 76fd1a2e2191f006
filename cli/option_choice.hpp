#pragma once
// A command-line option whose value is one of an option table's names (src/option_table.hpp):
// its help and its choices come from the table, so every subcommand spells them alike.
#include <string>

#include <CLI/CLI.hpp>

#include "src/option_table.hpp"

namespace scantrace::cli {

template <class E>
CLI::Option* add_choice(CLI::App& command, const std::string& flag, std::string& value) {
  const OptionTable<E>& table = option_table<E>();
  return command.add_option(flag, value, table.help)->check(CLI::IsMember(table.names()));
}

// The value `name` stands for; `name` passed add_choice's check, or is a table's default.
template <class E>
E chosen(const std::string& name) {
  return parse_option<E>(name).value_or(option_table<E>().default_value);
}

}  // namespace scantrace::cli
