#include "cli/log.hpp"

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace scantrace::cli {

void setup_logging() {
  // Once per process: spdlog refuses a second logger of the same name (run_app called twice, as
  // the app tests do).
  if (spdlog::get("scantrace")) return;
  auto logger = spdlog::stderr_logger_st("scantrace");
  logger->set_pattern("scantrace: %v");
  spdlog::set_default_logger(logger);
}

void set_quiet(bool quiet) {
  spdlog::set_level(quiet ? spdlog::level::warn : spdlog::level::info);
}

}  // namespace scantrace::cli
