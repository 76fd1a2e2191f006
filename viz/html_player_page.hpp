#pragma once
// The HTML, CSS and script of the HTML player (viz/html_player.hpp), with two placeholders the
// writer replaces: @TITLE@ (HTML-escaped text) and @DATA@ (a JSON object: the frames as data:
// URLs, the step labels and rows, the numbering, the play speed).
#include <string_view>

namespace scantrace::viz {

std::string_view html_player_page();

}  // namespace scantrace::viz
