#include "trace_filter.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <stdexcept>

namespace scantrace::trace {
namespace {

std::int64_t parse_integer(std::string_view s, const std::string& context) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size())
    throw std::invalid_argument("\"" + std::string(s) + "\" is not an integer in " + context);
  return v;
}

}  // namespace

IndexSet IndexSet::parse(const std::string& text) {
  IndexSet set;
  std::string_view rest = text;
  const std::string context = "triangle list \"" + text + "\"";
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    const std::size_t dash = item.find('-', 1);  // a leading '-' would be a (bad) negative number
    const std::int64_t lo = parse_integer(item.substr(0, dash), context);
    const std::int64_t hi =
        dash == std::string_view::npos ? lo : parse_integer(item.substr(dash + 1), context);
    if (lo < 0 || hi < lo || hi > INT32_MAX)
      throw std::invalid_argument("\"" + std::string(item) +
                                  "\" is not a valid index or range in " + context);
    set.ranges_.emplace_back(static_cast<int>(lo), static_cast<int>(hi));
  }
  if (set.ranges_.empty()) throw std::invalid_argument("empty " + context);
  set.merge();
  return set;
}

IndexSet IndexSet::of(const std::vector<int>& indices) {
  IndexSet set;
  for (int i : indices) set.ranges_.emplace_back(i, i);
  set.merge();
  return set;
}

void IndexSet::merge() {
  // Sorted and merged, so that membership is one binary search.
  std::sort(ranges_.begin(), ranges_.end());
  std::vector<std::pair<int, int>> merged;
  for (const auto& r : ranges_)
    if (!merged.empty() &&
        static_cast<std::int64_t>(r.first) <= merged.back().second + std::int64_t{1})
      merged.back().second = std::max(merged.back().second, r.second);  // touching or overlapping
    else
      merged.push_back(r);
  ranges_ = std::move(merged);
}

bool IndexSet::contains(int i) const {
  auto it = std::upper_bound(ranges_.begin(), ranges_.end(), i,
                             [](int v, const std::pair<int, int>& r) { return v < r.first; });
  return it != ranges_.begin() && std::prev(it)->second >= i;
}

RowRange RowRange::parse(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string context = "row range \"" + text + "\" (expected A:B)";
  if (colon == std::string::npos) throw std::invalid_argument("missing ':' in " + context);
  RowRange r;
  const std::string_view s = text;
  if (colon > 0) r.first = parse_integer(s.substr(0, colon), context);
  if (colon + 1 < s.size()) r.last = parse_integer(s.substr(colon + 1), context);
  if (r.first > r.last) throw std::invalid_argument("first row after last row in " + context);
  return r;
}

const char* to_string(TraceLevel level) {
  return level == TraceLevel::none ? "none" : option_name(level);
}

TraceLevel parse_level(const std::string& text) {
  if (const std::optional<TraceLevel> level = parse_option<TraceLevel>(text)) return *level;
  throw std::invalid_argument("unknown trace level \"" + text + "\" (expected " +
                              option_table<TraceLevel>().listed() + ")");
}

}  // namespace scantrace::trace
