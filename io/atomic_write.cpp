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

namespace {

// `bytes` into the file `temp`, errors naming `target`.
void write_bytes(const std::filesystem::path& temp, const std::filesystem::path& target,
                 std::string_view bytes) {
  // stdio rather than ofstream: it reports *why* a write failed (errno), and fclose reports
  // errors of the final flush such as a full disk.
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) fail(target, "cannot create file", std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const int write_errno = errno;
  if (std::fclose(f) != 0 || !written)
    fail(target, "cannot write file", std::strerror(written ? errno : write_errno));
}

}  // namespace

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
  write_atomically(target,
                   [&](const std::filesystem::path& temp) { write_bytes(temp, target, bytes); });
}

void write_files_atomically(
    const std::vector<std::pair<std::filesystem::path, std::string_view>>& files) {
  std::vector<std::filesystem::path> temps;
  const auto discard = [&] {
    for (const auto& temp : temps) {
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      unregister_temporary(temp);
    }
  };
  try {
    for (const auto& [target, bytes] : files) {
      if (!target.has_filename()) fail(target, "cannot write", "not a file name");
      // What would make a rename fail is looked for before the first rename: a directory in
      // the way (`diff -o d` with d/report.json a directory left d/diff.png behind).
      std::error_code ec;
      if (std::filesystem::is_directory(target, ec))
        fail(target, "cannot write file", "it is a directory");
      temps.push_back(temporary_name_for(target));
      register_temporary(temps.back());
      write_bytes(temps.back(), target, bytes);
    }
    check_interrupt();
  } catch (...) {
    discard();
    throw;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(temps[i], files[i].first, ec);
    if (ec) {
      // Rare past the checks above (the directory changed meanwhile): the files already renamed
      // are removed too, so that no set is left half new.
      for (std::size_t j = 0; j < i; ++j) std::filesystem::remove(files[j].first, ec);
      discard();
      fail(files[i].first, "cannot write", ec.message());
    }
    unregister_temporary(temps[i]);
  }
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
