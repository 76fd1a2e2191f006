// `scantrace stress` as a user runs it: the table on stdout with the seed, the exit status, the
// help, usage errors; and `--method` on the commands that fill.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/child_process.hpp"

namespace {

struct Output {
  int status = -1;
  std::string out;  // stdout only; stderr holds the progress
};

Output run_scantrace(const std::string& args) {
  const std::string command = std::string(SCANTRACE_BINARY) + " " + args + " 2>/dev/null";
  Output o;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::array<char, 4096> buf;
  for (std::size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;)
    o.out.append(buf.data(), n);
  const int raw = pclose(pipe);
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return o;
}

// The cells of the table row starting with "| family | method |".
std::vector<std::string> row(const std::string& table, const std::string& family,
                             const std::string& method) {
  const std::string start = "| " + family + " | " + method + " |";
  std::istringstream in(table);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(start, 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream cols(line.substr(1));
    for (std::string cell; std::getline(cols, cell, '|');)
      cells.push_back(cell.substr(1, cell.size() - 2));
    return cells;
  }
  return {};
}

// Column indices of the table (see markdown_table).
constexpr int kCases = 2, kExtra = 7, kGaps = 8, kOverlaps = 9, kFailing = 17;

}  // namespace

TEST_CASE("stress prints the seed and a table, and passes for exact", "[stress][command]") {
  const Output o = run_scantrace(
      "stress --seconds 0 --seed 9 --family meshes,centres "
      "--method exact --method opencv");
  CAPTURE(o.out);
  CHECK(o.status == 0);
  CHECK(o.out.find("seed 9") != std::string::npos);
  CHECK(o.out.find("exact: PASS") != std::string::npos);
  const std::vector<std::string> exact = row(o.out, "meshes", "exact");
  REQUIRE(exact.size() == 18);
  CHECK(exact[kCases] == "1");
  CHECK(exact[kGaps] == "0");
  CHECK(exact[kOverlaps] == "0");
  CHECK(exact[kFailing] == "0");
  // OpenCV's closed rule paints the shared edges of a mesh twice — and that is reported (with a
  // reproducer) without failing the run.
  const std::vector<std::string> opencv = row(o.out, "meshes", "opencv");
  REQUIRE(opencv.size() == 18);
  CHECK(std::stoll(opencv[kOverlaps]) > 0);
  CHECK(std::stoll(opencv[kExtra]) >= 0);
  CHECK(o.out.find("FAIL opencv meshes seed=9 index=0") != std::string::npos);
}

TEST_CASE("stress draws a fresh seed when none is given, and prints it", "[stress][command]") {
  const Output o = run_scantrace("stress --seconds 0 --family subpixel --method exact");
  CHECK(o.status == 0);
  const std::size_t at = o.out.find("--seed ");
  REQUIRE(at != std::string::npos);
  CHECK(std::isdigit(static_cast<unsigned char>(o.out[at + 7])));
}

TEST_CASE("stress --help explains families, methods and exit status", "[stress][command]") {
  const Output o = run_scantrace("stress --help");
  CHECK(o.status == 0);
  for (const char* word :
       {"--seconds", "--seed", "--family", "--method", "--case", "slivers", "near-collinear",
        "long-spans", "meshes", "opencv", "1e-4", "Exit status"})
    CHECK(o.out.find(word) != std::string::npos);
}

TEST_CASE("stress usage errors exit 2", "[stress][command]") {
  CHECK(run_scantrace("stress --family nope").status == 2);
  CHECK(run_scantrace("stress --method fast").status == 2);
  CHECK(run_scantrace("stress --seconds -1").status == 2);
}

TEST_CASE("the method flag selects the fill method of trace and render", "[stress][command]") {
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("scantrace-stress-method-" + std::to_string(::getpid()) + ".jsonl"))
                              .string();
  const auto slurp = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  };
  // Not only accepted: the float method's x += dx/dy in float32 gives other active-edge x values
  // than the exact method, so its trace differs — while two exact traces are byte-identical.
  const std::string tri = "trace --triangle \"0,0 40,3 7,30\" --size 48x48 ";
  REQUIRE(run_scantrace(tri + "--method float -o " + out).status == 0);
  const std::string float_trace = slurp(out);
  REQUIRE(run_scantrace(tri + "--method exact -o " + out).status == 0);
  const std::string exact_trace = slurp(out);
  REQUIRE(run_scantrace(tri + "-o " + out).status == 0);
  CHECK(slurp(out) == exact_trace);
  CHECK(!float_trace.empty());
  CHECK(float_trace != exact_trace);
  std::remove(out.c_str());
  CHECK(run_scantrace("trace --triangle \"0,0 40,3 7,30\" --method fast -o " + out).status == 2);
  CHECK(run_scantrace("render --help").out.find("--method") != std::string::npos);
}

TEST_CASE("stress interrupted by SIGINT prints the table of what it checked, then exits 130",
          "[stress][command][signal]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("scantrace-stress-sigint-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  scantrace::test::Child child(
      scantrace::test::spawn_scantrace(dir, {"stress", "--seconds", "3600", "--seed", "5",
                                             "--family", "centres,slivers", "--method", "exact"}));
  // Started: the first progress line (printed after a second of checking) is on stderr.
  const auto progress = [&] {
    std::ifstream err(dir / ".stderr.txt");
    std::stringstream s;
    s << err.rdbuf();
    return s.str().find("stress: 1/3600 s") != std::string::npos;
  };
  REQUIRE(child.wait_until(progress));
  child.signal(SIGINT);
  CHECK(child.wait() == 130);
  std::ifstream out_file(dir / ".stdout.txt");
  std::stringstream out;
  out << out_file.rdbuf();
  std::filesystem::remove_all(dir);
  const std::string text = out.str();
  CAPTURE(text);
  CHECK(text.find("# scantrace stress") != std::string::npos);
  CHECK(text.find("Interrupted by SIGINT after") != std::string::npos);
  CHECK(text.find("exact: PASS") == std::string::npos);  // not a verdict on the whole budget
  // The table holds the cases checked before the signal.
  const std::vector<std::string> centres = row(text, "centres", "exact");
  REQUIRE(centres.size() == 18);
  CHECK(std::stoll(centres[kCases]) > 0);
  CHECK(centres[kFailing] == "0");
}
