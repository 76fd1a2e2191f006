#pragma once
// C++20 library pieces that Debian's emscripten 3.1.6 (libc++ 14) lacks, for the WebAssembly build
// (web/, docs/web.md). Native builds get the standard library's own; the fallbacks are used only
// where the library does not declare the feature, so each native build compiles exactly the code
// it did before.
#include <charconv>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <version>
#if defined(__cpp_lib_bit_cast)
#include <bit>
#endif

namespace scantrace {

// std::bit_cast (libc++ 14 has no <bit> bit_cast; clang 14 has the builtin it is made of).
template <class To, class From>
  requires(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> &&
           std::is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
#if defined(__cpp_lib_bit_cast)
  return std::bit_cast<To>(from);
#else
  return __builtin_bit_cast(To, from);
#endif
}

// std::from_chars for a double (libc++ 14 has it only for integers). The fallback keeps
// from_chars's grammar where strtod's is wider: no leading space or '+', no hexadecimal; the
// digits and exponent then read as strtod reads them, correctly rounded like from_chars.
inline std::from_chars_result from_chars_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars) || !defined(_LIBCPP_VERSION)
  return std::from_chars(first, last, value);
#else
  const std::string_view text(first, static_cast<std::size_t>(last - first));
  if (text.empty() || text.front() == '+' || text.find_first_of(" \t\n\v\f\rxX") != text.npos)
    return {first, std::errc::invalid_argument};
  const std::string copy(text);  // strtod needs the terminating NUL
  char* end = nullptr;
  const double v = std::strtod(copy.c_str(), &end);
  if (end == copy.c_str()) return {first, std::errc::invalid_argument};
  value = v;
  return {first + (end - copy.c_str()), std::errc()};
#endif
}

}  // namespace scantrace
