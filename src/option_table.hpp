#pragma once
// One table per option of a fill or a trace: its key, its names, its default and its help. The
// command line (its choices and --help), the scene and trace JSON readers and writers, the Python
// module and the WebAssembly API all read these tables, so a name is spelled once, here.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/fill_options.hpp"

namespace scantrace {

enum class TraceLevel;  // src/tracer.hpp

template <class E>
struct OptionName {
  E value;
  const char* name;
};

template <class E>
struct OptionTable {
  const char* key;  // the option's key in a trace header and in the APIs' options ("fill_rule")
  E default_value;
  std::vector<OptionName<E>> names_;  // in the order help and error messages list them
  const char* help;                   // what `--help` says of the option, one line a value or so

  // The name of `v` (every value has one).
  const char* name(E v) const {
    for (const OptionName<E>& n : names_)
      if (n.value == v) return n.name;
    return names_.front().name;
  }
  const char* default_name() const { return name(default_value); }
  // The value named `text` exactly, or nothing.
  std::optional<E> parse(std::string_view text) const {
    for (const OptionName<E>& n : names_)
      if (text == n.name) return n.value;
    return std::nullopt;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const OptionName<E>& n : names_) out.emplace_back(n.name);
    return out;
  }
  // "a, b or c" (`last` = " or ") — for messages that list the choices.
  std::string listed(const char* last = " or ", const char* quote = "") const {
    std::string out;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (i > 0) out += i + 1 == names_.size() ? last : ", ";
      out += std::string(quote) + names_[i].name + quote;
    }
    return out;
  }
};

// The table of each option: Shading, FillRule, Method, WindingRule, Cull, Visibility, Occlusion
// and TraceLevel (which lists the three levels a trace records, not `none`).
template <class E>
const OptionTable<E>& option_table();
template <>
const OptionTable<Shading>& option_table<Shading>();
template <>
const OptionTable<FillRule>& option_table<FillRule>();
template <>
const OptionTable<Method>& option_table<Method>();
template <>
const OptionTable<WindingRule>& option_table<WindingRule>();
template <>
const OptionTable<Cull>& option_table<Cull>();
template <>
const OptionTable<Visibility>& option_table<Visibility>();
template <>
const OptionTable<Occlusion>& option_table<Occlusion>();
template <>
const OptionTable<TraceLevel>& option_table<TraceLevel>();

template <class E>
const char* option_name(E v) {
  return option_table<E>().name(v);
}
template <class E>
std::optional<E> parse_option(std::string_view text) {
  return option_table<E>().parse(text);
}

}  // namespace scantrace
