#pragma once

namespace scantrace::cli {

// Messages go to stderr as "scantrace: <message>" (stdout stays free for data a later subcommand
// may print); errors are logged as "error: <file>: <element>: <problem>".
void setup_logging();
void set_quiet(bool quiet);

}  // namespace scantrace::cli
