#pragma once
// Output files appear complete or not at all (docs/design.md §7): the content is written under a
// temporary name in the target's directory (".NAME.tmp-PID", hidden, so an interrupted run never
// leaves a file that looks finished) and renamed over the target only once it is complete; a
// rename within one directory is atomic on POSIX file systems.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

namespace scantrace {

// The temporary sibling `write_atomically` uses for `target`.
std::filesystem::path temporary_name_for(const std::filesystem::path& target);
// The same with the target's extension at the end (".NAME.tmp-PID.EXT"), for writers that choose
// the file format by the name's extension (OpenCV's VideoWriter).
std::filesystem::path temporary_name_keeping_extension(const std::filesystem::path& target);

// Calls `write(temp)`, which must create the complete file at `temp` or throw, then renames `temp`
// to `target`. On any failure the temporary file is removed and an exception whose message starts
// with the target's name is thrown (or the one `write` threw is rethrown).
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temp)>& write);

// Writes `bytes` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

// Writes several files so that all of them appear or none: each is written to its temporary
// first, a target that is a directory is refused before anything is renamed, then each is renamed
// into place (should a rename still fail, the ones already renamed are removed).
void write_files_atomically(
    const std::vector<std::pair<std::filesystem::path, std::string_view>>& files);

// The streaming form, for outputs written piece by piece (a trace): the stream writes the
// temporary file; commit() renames it into place. Destroyed without commit — an error, an
// exception — it removes the temporary, so a truncated file never looks finished.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);  // throws std::runtime_error
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return out_; }
  const std::filesystem::path& path() const { return target_; }
  // Flushes, checks that every write succeeded, and renames into place; throws on failure.
  void commit();

 private:
  std::filesystem::path target_, temp_;
  std::ofstream out_;
  bool done_ = false;
};

}  // namespace scantrace
