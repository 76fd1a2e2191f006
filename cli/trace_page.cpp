#include "cli/trace_page.hpp"

#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/web_dir.hpp"  // generated: kWebBuildDir (cli/CMakeLists.txt)
#include "io/atomic_write.hpp"
#include "io/gzip.hpp"
#include "io/json_input.hpp"
#include "trace/jsonl_writer.hpp"
#include "viz/step_page.hpp"

namespace scantrace::cli {
namespace {

// Where make_page.mjs leaves the page data: replaced by {"cfg": …, "trace": …}.
constexpr std::string_view kMarker = "/*SCANTRACE_PAGE_DATA*/null";

std::string jsonl_of(const trace::Trace& t) {
  std::ostringstream out;
  trace::JsonlWriter w(out, t.header());
  // The header and the footer are among the events the reader kept; the writer adds its own.
  for (const trace::Event& e : t.events())
    if (!std::holds_alternative<trace::Header>(e) && !std::holds_alternative<trace::Footer>(e))
      w.write(e);
  if (t.footer()) w.finish(*t.footer());
  return out.str();
}

}  // namespace

std::filesystem::path trace_page_template() {
  const std::filesystem::path page = std::filesystem::path(kWebBuildDir) / "player.html";
  return std::filesystem::is_regular_file(page) ? page : std::filesystem::path();
}

std::size_t write_trace_page(const trace::Trace& trace, const viz::ReplayOptions& options,
                             const std::filesystem::path& out) {
  const std::filesystem::path tmpl = trace_page_template();
  std::string page = json_input::read_text_file(tmpl);
  const std::size_t at = page.find(kMarker);
  if (at == std::string::npos)
    throw std::runtime_error(tmpl.string() + ": not the player page's template (no data marker)");
  nlohmann::json cfg{{"source", options.source.empty() ? "the trace" : options.source},
                     {"width", options.size.width},
                     {"height", options.size.height},
                     {"rows_per_step", options.plan.rows_per_step},
                     {"mode", viz::to_string(options.plan.mode)},
                     {"first", options.steps.first - 1}};
  if (options.steps.last != SIZE_MAX) cfg["last"] = options.steps.last - 1;
  if (options.marked_pixel) cfg["marked_pixel"] = {options.marked_pixel->x, options.marked_pixel->y};
  // Inside a <script>: "<" escaped, so no text of the trace's source can close the element.
  std::string data = nlohmann::json{{"cfg", cfg}, {"trace", viz::base64(gzip(jsonl_of(trace)))}}.dump();
  for (std::size_t i = 0; (i = data.find('<', i)) != std::string::npos;) data.replace(i, 1, "\\u003c");
  page.replace(at, kMarker.size(), data);
  write_file_atomically(out, page);
  return page.size();
}

}  // namespace scantrace::cli
