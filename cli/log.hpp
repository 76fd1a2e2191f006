#pragma once
#include <string>
#include <string_view>

namespace scantrace::cli {

// Messages go to stderr as "scantrace: <message>" (stdout stays free for data a later subcommand
// may print); errors are logged as "error: <file>: <element>: <problem>". Control characters in a
// message (it may quote a trace's strings) are written as escapes: escape_controls.
void setup_logging();
void set_quiet(bool quiet);

// `text` with every control character but newline and tab written as \xHH (C1 controls, UTF-8
// C2 80..C2 9F, as \u00HH), so that quoted input cannot drive the terminal.
std::string escape_controls(std::string_view text);

}  // namespace scantrace::cli
