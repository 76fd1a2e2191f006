#include "grade/captured_stderr.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace scantrace::grade {

CapturedStderr::CapturedStderr() {
  std::fflush(stderr);
  capture_ = ::memfd_create("scantrace-decoder-messages", MFD_CLOEXEC);
  if (capture_ < 0) return;  // then the libraries print as before
  saved_ = ::dup(STDERR_FILENO);
  if (saved_ < 0 || ::dup2(capture_, STDERR_FILENO) < 0) {
    if (saved_ >= 0) ::close(saved_);
    ::close(capture_);
    saved_ = capture_ = -1;
  }
}

CapturedStderr::~CapturedStderr() {
  restore();
  if (capture_ >= 0) ::close(capture_);
}

void CapturedStderr::restore() {
  if (saved_ < 0) return;
  std::cerr.flush();
  std::fflush(stderr);
  ::dup2(saved_, STDERR_FILENO);
  ::close(saved_);
  saved_ = -1;
}

std::string CapturedStderr::text() {
  restore();
  if (capture_ < 0) return {};
  std::string raw;
  char buffer[4096];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(capture_, buffer, sizeof buffer, at);
    if (n <= 0 || raw.size() > 4096) break;
    raw.append(buffer, static_cast<std::size_t>(n));
    at += n;
  }
  std::string out;
  for (const char c : raw) {
    if (c == '\n') {
      if (!out.empty() && out.substr(out.size() >= 2 ? out.size() - 2 : 0) != "; ") out += "; ";
    } else if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  if (out.size() > 300) out = out.substr(0, 300) + "...";
  return out;
}

}  // namespace scantrace::grade
