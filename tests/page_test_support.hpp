#pragma once
// Reading back the step page (viz/step_page.hpp) in tests: an independent base64 decoder and the
// JSON object the page's script starts from.
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace scantrace::test {

// An independent base64 decoder (RFC 4648), to read the page's data back.
inline std::vector<unsigned char> unbase64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    const int v = value(c);
    if (v < 0) continue;  // '=' padding
    bits = bits << 6 | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>(bits >> count & 0xff));
    }
  }
  return out;
}

// The JSON object the page's script starts from.
inline nlohmann::json page_data(const std::string& page) {
  const std::string start = "const DATA = ";
  const std::size_t a = page.find(start);
  REQUIRE(a != std::string::npos);
  const std::size_t b = page.find(";\n", a);  // the data is one line
  REQUIRE(b != std::string::npos);
  return nlohmann::json::parse(page.substr(a + start.size(), b - a - start.size()));
}

}  // namespace scantrace::test
