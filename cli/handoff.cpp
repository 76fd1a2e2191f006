#include "cli/handoff.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace scantrace::cli {
namespace {

namespace fs = std::filesystem;

// Where the scantrace Python package is: $SCANTRACE_PYTHONPATH, else beside this executable in
// the build tree (build/cli/ -> build/python/) or in its install prefix (bin/ ->
// lib/python3/dist-packages/); else wherever python3 finds it.
std::string package_dir() {
  if (const char* env = std::getenv("SCANTRACE_PYTHONPATH")) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& dir : {exe.parent_path().parent_path() / "python",
                              exe.parent_path().parent_path() / "lib/python3/dist-packages"})
    if (fs::exists(dir / "scantrace/grade/__main__.py", ec)) return dir.string();
  return {};
}

// JPEG's start-of-image marker, or a BMP's "BM" (grade/image_header.hpp reads both headers).
bool starts_like_jpeg_or_bmp(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return false;
  std::ifstream in(file, std::ios::binary);
  char head[3] = {};
  in.read(head, sizeof head);
  const auto got = in.gcount();
  if (got >= 2 && head[0] == 'B' && head[1] == 'M') return true;
  return got == 3 && static_cast<unsigned char>(head[0]) == 0xFF &&
         static_cast<unsigned char>(head[1]) == 0xD8 && static_cast<unsigned char>(head[2]) == 0xFF;
}

}  // namespace

fs::path beside_this_executable(std::string_view name, const char* argv0) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path dir = ec ? fs::path(argv0).parent_path() : self.parent_path();
  return dir / name;
}

bool names_jpeg_or_bmp_file(int argc, char** argv, int from) {
  for (int i = from; i < argc; ++i)
    if (starts_like_jpeg_or_bmp(argv[i])) return true;
  return false;
}

void run_grader(const std::vector<std::string>& args) {
  const std::string dir = package_dir();
  if (!dir.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = old && *old ? dir + ":" + old : dir;
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  // Debian's interpreter: its numpy is the one deps.sh installs (a python3 earlier in PATH may
  // have none); SCANTRACE_PYTHON overrides.
  const char* python = std::getenv("SCANTRACE_PYTHON");
  if (!python) python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::vector<const char*> argv{python, "-m", "scantrace.grade"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execvp(python, const_cast<char* const*>(argv.data()));
  std::fprintf(stderr, "scantrace grade: error: cannot run %s: %s\n", python,
               std::strerror(errno));
  std::exit(1);
}

}  // namespace scantrace::cli
