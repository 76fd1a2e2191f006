#pragma once
// Opening a user's input file so that no path can hang the command or feed it without end: a
// FIFO given as a scene blocked forever in open() (and the interrupt handler's flag was never
// looked at), /dev/zero read on until std::bad_alloc. Every reader of a named input opens it
// here first: without blocking (O_NONBLOCK), then fstat, and anything but a regular file is
// refused with one line that says what it is. A regular file's size is then checked against the
// memory budget before it is read.
#include <cstdint>
#include <filesystem>
#include <string>

namespace scantrace {

// An open file descriptor of a regular file, closed at scope exit.
class RegularFile {
 public:
  // Throws InputError("<file>: cannot read file: <reason>") when `file` cannot be opened, or is
  // a directory, a FIFO, a character or block device or a socket.
  explicit RegularFile(const std::filesystem::path& file);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  int fd() const { return fd_; }
  std::uint64_t size() const { return size_; }  // at the time of opening

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// Throws as RegularFile does; for readers that open the file themselves afterwards (matio,
// std::ifstream). The check is made on the descriptor it opens, without blocking, so a FIFO or a
// device never reaches their blocking open().
void check_regular_file(const std::filesystem::path& file);

// Why `file` cannot be read as a regular file ("No such file or directory", "it is a FIFO (named
// pipe); ..."), empty when it can: for readers whose errors are not InputErrors (traces).
std::string regular_file_problem(const std::filesystem::path& file);

// "a FIFO (named pipe)", "a character device", ...: what a non-regular file is, for messages.
std::string file_kind(unsigned mode);

}  // namespace scantrace
