#pragma once
// The trace page (docs/web.md): `replay`/`explain -o OUT.html` write the trace itself (JSON Lines,
// gzip, base64) into the player page the web build made (build/web/player.html, web/player/),
// which composes and draws each step in the browser with the WebAssembly module: a few hundred
// kilobytes where the page of pre-drawn frames (viz/html_player.hpp) took megabytes.
#include <cstddef>
#include <filesystem>

#include "trace/trace.hpp"
#include "viz/replay.hpp"

namespace scantrace::cli {

// The player page's template, when the web build made it (empty path otherwise).
std::filesystem::path trace_page_template();

// Writes the page for `trace` under `options` (frame size, steps, plan, marked pixel, source) to
// `out`, atomically; returns its size in bytes. Throws std::runtime_error naming the file.
std::size_t write_trace_page(const trace::Trace& trace, const viz::ReplayOptions& options,
                             const std::filesystem::path& out);

}  // namespace scantrace::cli
