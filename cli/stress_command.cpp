// scantrace stress [--seconds N] [--seed S] [--family NAME…] [--method NAME…] [--case I]
// Hunts for accuracy failures: generated cases of every family, checked against the exact
// reference with every method, a Markdown table on stdout, progress on stderr. Exits 1 when the
// default method (exact) fails any check; the other methods' failures are reported, not fatal.
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "io/interrupt.hpp"
#include "stress/opencv_rasterizer.hpp"
#include "stress/report.hpp"
#include "stress/runner.hpp"

namespace scantrace::cli {
namespace {

struct StressArgs {
  double seconds = 10;
  std::optional<std::uint64_t> seed;
  std::vector<std::string> families;
  std::vector<std::string> methods;
  std::optional<std::uint64_t> only_case;
  int reproducers = 5;
};

const std::vector<std::string> kMethodNames{"exact", "float", "double", "halfspace", "opencv"};

std::vector<std::string> family_names() {
  std::vector<std::string> names;
  for (stress::Family f : stress::kAllFamilies) names.push_back(to_string(f));
  return names;
}

// A fresh seed when none is given; printed, so that the run can be replayed.
std::uint64_t fresh_seed() {
  std::random_device device;
  const std::uint64_t t =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  return ((static_cast<std::uint64_t>(device()) << 32) ^ device() ^ t) & 0xffffffffffffULL;
}

std::string command_line(const StressArgs& a, std::uint64_t seed) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", a.seconds);
  std::string s =
      "scantrace stress --seconds " + std::string(seconds) + " --seed " + std::to_string(seed);
  for (const std::string& f : a.families) s += " --family " + f;
  for (const std::string& m : a.methods) s += " --method " + m;
  if (a.only_case) s += " --case " + std::to_string(*a.only_case);
  return s;
}

stress::RunOptions run_options(const StressArgs& args) {
  stress::RunOptions options;
  options.seed = args.seed ? *args.seed : fresh_seed();
  options.seconds = args.seconds;
  options.only_case = args.only_case;
  options.reproducers_per_cell = args.reproducers;
  if (!args.families.empty()) {
    options.families.clear();
    for (const std::string& name : args.families) {
      stress::Family f;
      stress::parse_family(name, f);  // validated by the option's check
      options.families.push_back(f);
    }
  }
  // Ctrl-C ends the run after the case in hand; the table of what was checked is printed.
  options.stop = [] { return interrupt_signal() != 0; };
  options.progress = [](const stress::Progress& p) {
    spdlog::info("stress: {:.0f}/{:.0f} s, {} cases, {} failing exact cases", p.elapsed, p.budget,
                 p.cases, p.default_failures);
  };
  return options;
}

std::vector<std::unique_ptr<stress::Rasterizer>> make_rasterizers(const StressArgs& args) {
  std::vector<std::unique_ptr<stress::Rasterizer>> owned;
  for (const std::string& name : args.methods.empty() ? kMethodNames : args.methods) {
    Method m;
    if (parse_method(name.c_str(), m))
      owned.push_back(stress::make_method(m));
    else
      owned.push_back(stress::make_opencv_rasterizer());
  }
  return owned;
}

// The report on stdout: the command line to replay, the table, the failing cases.
void print_report(const StressArgs& args, const stress::RunOptions& options,
                  const stress::RunResult& result, long long cases) {
  std::printf("# scantrace stress\n\n");
  std::printf(
      "`%s` — seed %llu, %.1f s, %lld cases; every triangle filled in all 6 vertex "
      "orders.\n\n",
      command_line(args, options.seed).c_str(), static_cast<unsigned long long>(options.seed),
      result.seconds, cases);
  std::printf("%s\n", stress::markdown_table(result).c_str());

  bool any = false;
  for (const stress::CellStats& c : result.cells)
    for (const std::string& line : c.reproducers) {
      if (!any)
        std::printf("Failing cases (every one of exact, the first %d of each other row):\n\n",
                    args.reproducers);
      any = true;
      std::printf("    %s\n", line.c_str());
    }
  if (any) std::printf("\n");
}

// Interrupted: what was checked is printed; the verdict is only about those cases, and the
// status is the shell's for the signal (130, 143), not a pass.
[[noreturn]] void end_interrupted(const stress::RunResult& result, long long cases) {
  const int signal = interrupt_signal();
  std::printf("Interrupted by %s after %.1f s: the table holds the %lld cases checked so far.\n",
              signal == SIGTERM ? "SIGTERM" : "SIGINT", result.seconds, cases);
  std::fflush(stdout);
  spdlog::warn("warning: stress: interrupted by {} after {:.1f} s; {} cases checked{}",
               signal == SIGTERM ? "SIGTERM" : "SIGINT", result.seconds, cases,
               result.default_failed ? ", exact FAILED some (reproducers on stdout)" : "");
  throw ExitStatus{128 + signal};
}

// The last line: the default method's verdict; a failure is the command's (exit 1).
void print_verdict(const stress::RunOptions& options, const stress::RunResult& result,
                   bool default_checked) {
  if (!default_checked) {
    std::printf("exact: not run (--method without exact).\n");
    return;
  }
  if (!result.default_failed) {
    std::printf(
        "exact: PASS — no coverage mismatch, gap, overlap, order dependence, NaN or "
        "colour error above %g.\n",
        options.colour_tolerance);
    return;
  }
  std::printf("exact: FAIL — %lld failing cases (reproducers above).\n",
              result.default_failing_cases);
  std::fflush(stdout);
  throw std::runtime_error("stress: the exact method failed " +
                           std::to_string(result.default_failing_cases) +
                           " cases; see the FAIL lines on stdout");
}

void run_stress_command(const StressArgs& args) {
  const stress::RunOptions options = run_options(args);
  const std::vector<std::unique_ptr<stress::Rasterizer>> owned = make_rasterizers(args);
  std::vector<stress::Rasterizer*> rasterizers;
  bool default_checked = false;
  for (const auto& r : owned) {
    rasterizers.push_back(r.get());
    default_checked |= r->name() == options.default_method;
  }

  spdlog::info("stress: seed {} (replay with --seed {}), {} s", options.seed, options.seed,
               options.seconds);
  const stress::RunResult result = stress::run_stress(options, rasterizers);

  long long cases = 0;
  for (const stress::CellStats& c : result.cells)
    if (c.method == result.cells.front().method) cases += c.cases;
  print_report(args, options, result, cases);
  if (result.stopped) end_interrupted(result, cases);
  print_verdict(options, result, default_checked);
}

}  // namespace

Command add_stress_command(CLI::App& app) {
  auto args = std::make_shared<StressArgs>();
  CLI::App* cmd = app.add_subcommand(
      "stress",
      "Stress-tests the fill methods against the exact reference on generated\n"
      "families of hard triangles and meshes, and prints a Markdown table per family\n"
      "and method: triangles tried, coverage mismatches (pixels missing or extra),\n"
      "gaps and double-covered pixels in meshes, vertex-order differences (every\n"
      "triangle is filled in all 6 vertex orders and the images must be identical),\n"
      "maximum and RMS colour error against the exact barycentric colour (as floats,\n"
      "and as 8-bit values |round(255c) - round(255c_ref)|), NaN/Inf written, and\n"
      "fill time. Exits 1 when the default method (exact) fails any check (a\n"
      "coverage mismatch, gap, overlap, order difference, NaN or a colour error\n"
      "above 1e-4), with a one-line reproducer per failing case; the other\n"
      "methods' failures are reported the same way but do not change the exit\n"
      "status. Progress goes to stderr.");
  cmd->add_option("--seconds", args->seconds,
                  "time budget, shared round-robin by the families (each\n"
                  "still runs at least one case)")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed,
                  "seed of the generator (default: a fresh one, printed\n"
                  "so that the run can be replayed); case I of a family\n"
                  "depends only on the seed, the family and I");
  std::string family_help = "families to run (default: all):";
  for (stress::Family f : stress::kAllFamilies)
    family_help += std::string("\n  ") + to_string(f) + ": " + stress::description(f);
  cmd->add_option("--family", args->families, family_help)
      ->check(CLI::IsMember(family_names()))
      ->delimiter(',');
  cmd->add_option("--method", args->methods,
                  "methods to measure (default: all):\n"
                  "  exact, float, double, halfspace: the library's fill\n"
                  "  methods (render --method), top-left rule\n"
                  "  opencv: cv::fillConvexPoly, flat, 8-bit BGR image,\n"
                  "  vertices cv::Point(round(256 v)) with shift = 8,\n"
                  "  checked under the closed rule (OpenCV's own)")
      ->check(CLI::IsMember(kMethodNames))
      ->delimiter(',');
  cmd->add_option("--case", args->only_case,
                  "run only case I of each family: replays a FAIL line\n"
                  "(with its --seed, --family and --method)");
  cmd->add_option("--reproducers", args->reproducers,
                  "failing cases printed per table row of the other\n"
                  "methods (every failing case of exact is printed)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  scantrace stress --seconds 600                 a long hunt with a fresh seed\n"
      "  scantrace stress --seconds 3 --seed 1          the test suite's run\n"
      "  scantrace stress --family slivers,meshes --method exact --method float\n"
      "  scantrace stress --seed 7 --family huge --case 12 --method exact\n"
      "Columns: see docs/accuracy.md. Exit status: 0 when exact passed (or was not\n"
      "run), 1 when exact failed a check, 2 usage error.");
  return {cmd, [args] { run_stress_command(*args); }};
}

}  // namespace scantrace::cli
