#include "cli/log.hpp"

#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

namespace scantrace::cli {

std::string escape_controls(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    // C1 controls in UTF-8 (U+0080..U+009F: C2 80..C2 9F) act like ESC on some terminals.
    const bool c1 = c == 0xC2 && i + 1 < text.size() &&
                    static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (c1) {
      const auto d = static_cast<unsigned char>(text[++i]);
      out += "\\u00";
      out += kHex[d >> 4];
      out += kHex[d & 15];
    } else if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

namespace {

// stderr, with every control character of a message written as an escape: messages quote input
// (a trace's strings, file names), and "\e]0;PWNED\a\e[2J" in a trace retitled and cleared the
// terminal of whoever ran `check` on it.
class EscapingStderrSink final : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    spdlog::memory_buf_t formatted;
    formatter_->format(msg, formatted);
    std::string_view text(formatted.data(), formatted.size());
    const bool newline = !text.empty() && text.back() == '\n';
    if (newline) text.remove_suffix(1);
    std::string out = escape_controls(text);
    if (newline) out += '\n';
    std::fwrite(out.data(), 1, out.size(), stderr);
  }
  void flush_() override { std::fflush(stderr); }
};

}  // namespace

void setup_logging() {
  // Once per process: the logger is registered by name (run_app called twice, as the app tests do,
  // would otherwise make a second one).
  if (spdlog::get("scantrace")) return;
  auto logger = std::make_shared<spdlog::logger>("scantrace", std::make_shared<EscapingStderrSink>());
  logger->set_pattern("scantrace: %v");
  spdlog::set_default_logger(logger);
}

void set_quiet(bool quiet) {
  spdlog::set_level(quiet ? spdlog::level::warn : spdlog::level::info);
}

}  // namespace scantrace::cli
