#include "io/atomic_write.hpp"
#include "io/interrupt.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

namespace scantrace {
namespace {

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& what,
                       const std::string& reason) {
  throw std::runtime_error(target.string() + ": " + what + ": " + reason);
}

}  // namespace

std::filesystem::path temporary_name_for(const std::filesystem::path& target) {
  // The process id keeps two concurrent runs writing the same target from sharing a temporary.
  // Appending (rather than "." + name + ...) also sidesteps GCC 12's false -Wrestrict alarm.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  return target.parent_path() / name;
}

std::filesystem::path temporary_name_keeping_extension(const std::filesystem::path& target) {
  std::filesystem::path temp = temporary_name_for(target);
  temp += target.extension();
  return temp;
}

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temp)>& write) {
  if (!target.has_filename()) fail(target, "cannot write", "not a file name");
  const std::filesystem::path temp = temporary_name_for(target);
  register_temporary(temp);
  auto discard = [&] {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    unregister_temporary(temp);
  };
  try {
    write(temp);
    // A run interrupted while it computed or wrote (a render does not look at the flag while
    // it fills) must not put its output in place of an existing one: the rename is the commit.
    check_interrupt();
  } catch (...) {
    discard();
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    discard();
    fail(target, "cannot write", ec.message());
  }
  unregister_temporary(temp);
}

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
  write_atomically(target, [&](const std::filesystem::path& temp) {
    // stdio rather than ofstream: it reports *why* a write failed (errno), and fclose reports
    // errors of the final flush such as a full disk.
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    if (!f) fail(target, "cannot create file", std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const int write_errno = errno;
    if (std::fclose(f) != 0 || !written)
      fail(target, "cannot write file", std::strerror(written ? errno : write_errno));
  });
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temp_(temporary_name_for(target_)) {
  register_temporary(temp_);
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    unregister_temporary(temp_);
    fail(target_, "cannot create file", std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (done_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
  unregister_temporary(temp_);
}

void AtomicFile::commit() {
  check_interrupt();  // as in write_atomically: an interrupted run commits nothing
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) fail(target_, "cannot write", "write failed (disk full?)");
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) fail(target_, "cannot write", ec.message());
  done_ = true;
  unregister_temporary(temp_);
}

}  // namespace scantrace
