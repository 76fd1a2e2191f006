#include "io/json_input.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <unistd.h>

#include "io/input_file.hpp"
#include "io/memory_budget.hpp"

namespace scantrace::json_input {

std::string read_text_file(const std::filesystem::path& file) {
  // A FIFO, a device or a directory is refused before any read (io/input_file.hpp): /dev/zero
  // was read on until std::bad_alloc, a FIFO without a writer blocked in open() for good.
  const RegularFile in(file);
  // The file's size against the memory there is, before the string is allocated.
  check_memory(in.size() + kReadPadding, "reading the file (" + format_bytes(in.size()) + ")",
               file.string(), "");
  // Read in one call at its size, into a string with kReadPadding bytes to spare. Appending 64 KB
  // at a time, the string grew by doubling: a 10 MB scene was copied about twice over and its
  // pages faulted in twice, 12-18 ms against 1.5 (docs/performance.md). A file that grows while
  // it is read is read to its end at opening (what it holds past that is not looked at).
  std::string text;
  text.reserve(in.size() + kReadPadding);
  text.resize(in.size());
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(in.fd(), text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw InputError(file.string(), "", std::string("cannot read file: ") + std::strerror(errno));
    if (n == 0) break;  // shrunk while being read
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return text;
}

TextPosition position_of(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::string_view before = text.substr(0, offset);
  TextPosition p;
  p.line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t last_newline = before.rfind('\n');
  p.column = last_newline == std::string_view::npos ? offset + 1 : offset - last_newline;
  return p;
}

namespace {

// nlohmann's message is "[json.exception.parse_error.101] parse error at line 3, column 17:
// syntax error while parsing value - invalid literal; last read: 'tru,'"; keep what follows the
// position, which we report in the usual file:line:column form ourselves.
std::string explanation(const nlohmann::json::parse_error& e) {
  const std::string what = e.what();
  std::size_t start = what.find("parse error");
  start = start == std::string::npos ? std::string::npos : what.find(": ", start);
  return start == std::string::npos ? what : what.substr(start + 2);
}

// Tells, character by character, whether a JSON text is inside a string literal, where brackets
// and commas are not structure: a backslash hides the next character (\" too).
class StringLiterals {
 public:
  // True when `c` belongs to a string literal, its quotes included.
  bool contain(char c) {
    if (in_string_) {
      if (escaped_)
        escaped_ = false;
      else if (c == '\\')
        escaped_ = true;
      else if (c == '"')
        in_string_ = false;
      return true;
    }
    in_string_ = c == '"';
    return in_string_;
  }

 private:
  bool in_string_ = false, escaped_ = false;
};

}  // namespace

std::optional<std::size_t> find_excess_nesting(std::string_view text, int max_depth) {
  int depth = 0;
  StringLiterals strings;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (strings.contain(c)) continue;
    if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

std::string nesting_problem(int max_depth) {
  return "JSON nested deeper than " + std::to_string(max_depth) + " levels";
}

std::uint64_t estimated_dom_bytes(std::string_view text) {
  std::uint64_t values = 1, containers = 0;
  StringLiterals strings;
  for (const char c : text) {
    if (strings.contain(c)) continue;
    if (c == ',')
      ++values;
    else if (c == '[' || c == '{')
      ++values, ++containers;
  }
  return 16 * values + 64 * containers;
}

nlohmann::json parse(std::string_view text, const std::string& name_for_errors, int max_depth) {
  // A file of 10^7 faces is 350 MB of text and about 2.5 GB as a DOM: refused here, naming the
  // file, when that is more than the memory there is, instead of being killed by the kernel.
  check_memory(estimated_dom_bytes(text), "parsing its JSON (" + format_bytes(text.size()) + ")",
               name_for_errors, "");
  if (const auto at = find_excess_nesting(text, max_depth)) {
    const TextPosition p = position_of(text, *at);
    throw InputError(
        name_for_errors + ":" + std::to_string(p.line) + ":" + std::to_string(p.column), "",
        nesting_problem(max_depth));
  }
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte counts from 1 and points at the last character read, i.e. the offending one.
    const TextPosition p = position_of(text, e.byte == 0 ? 0 : e.byte - 1);
    throw InputError(
        name_for_errors + ":" + std::to_string(p.line) + ":" + std::to_string(p.column), "",
        "JSON syntax error: " + explanation(e));
  } catch (const nlohmann::json::out_of_range& e) {
    // The one out_of_range a parse throws is 406, a number beyond a double ("1e999"): it carries
    // no position, so the literal it quotes is looked up in the text.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string literal =
        open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = literal.empty() ? std::string_view::npos : text.find(literal);
    std::string where = name_for_errors;
    if (at != std::string_view::npos) {
      const TextPosition p = position_of(text, at);
      where += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
    }
    throw InputError(where, "",
                     "number " + (literal.empty() ? std::string("literal") : literal) +
                         " is too large for a double (infinite and NaN values are not accepted)");
  }
}

std::string quote(const nlohmann::json& value, std::size_t max_chars) {
  // Strings in parsed input are valid UTF-8, but replace rather than throw if one is not.
  std::string s = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (s.size() > max_chars) {
    std::size_t cut = max_chars;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // UTF-8 start
    s = s.substr(0, cut) + "...";
  }
  return s;
}

}  // namespace scantrace::json_input
