#include "io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/input_error.hpp"

namespace scantrace {
namespace {

// Opens `file` read-only and checks it is a regular file; returns the descriptor, or -1 with
// `problem` saying why not.
int open_regular(const std::filesystem::path& file, std::uint64_t& size, std::string& problem) {
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting for one (with
  // SA_RESTART, a signal did not even interrupt that wait). It changes nothing for a regular
  // file, whose reads never block.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    problem = std::strerror(errno);
    return -1;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    problem = std::strerror(errno);
    ::close(fd);
    return -1;
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    // A pipe or a device has no end to check against the memory budget (/dev/zero, /dev/urandom)
    // or may never deliver anything (a FIFO without a writer): inputs are files.
    problem = "it is " + file_kind(info.st_mode);
    if (!S_ISDIR(info.st_mode)) problem += ", not a regular file";
    return -1;
  }
  size = info.st_size > 0 ? static_cast<std::uint64_t>(info.st_size) : 0;
  return fd;
}

}  // namespace

std::string file_kind(unsigned mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

RegularFile::RegularFile(const std::filesystem::path& file) {
  std::string problem;
  fd_ = open_regular(file, size_, problem);
  if (fd_ < 0) throw InputError(file.string(), "", "cannot read file: " + problem);
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

void check_regular_file(const std::filesystem::path& file) {
  const RegularFile checked(file);
}

std::string regular_file_problem(const std::filesystem::path& file) {
  std::uint64_t size = 0;
  std::string problem;
  const int fd = open_regular(file, size, problem);
  if (fd >= 0) ::close(fd);
  return problem;
}

}  // namespace scantrace
