#pragma once
// The HTML, CSS and script of the HTML player (viz/html_player.hpp): web/player/step_page.html
// and step_page.js, embedded at build time (cmake/web_player.cmake), with two placeholders the
// writer replaces: @TITLE@ (HTML-escaped text) and @DATA@ (a JSON object: the frames as data:
// URLs, the step labels and rows, the numbering, the play speed).
#include <string_view>

namespace scantrace::viz {

std::string_view html_player_page();

}  // namespace scantrace::viz
