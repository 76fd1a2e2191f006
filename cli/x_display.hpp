#pragma once
// Whether an X server accepts a client on DISPLAY, asked before HighGUI opens its first window:
// Qt's xcb platform aborts the whole process (status −6, "could not connect to display") when the
// server turns it away, so `scantrace step` makes the same connection first and turns a refusal
// into a one-line error that says why.
#include <optional>
#include <string>

namespace scantrace::cli {

// Empty when a client can connect to `display` (":99", "unix:0.0"); otherwise why it cannot.
std::optional<std::string> x_display_refusal(const std::string& display);

}  // namespace scantrace::cli
