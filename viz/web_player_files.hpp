#pragma once
// The player's web files (web/player/), embedded at configure time by cmake/web_player.cmake:
// each one's text, zero-terminated.
namespace scantrace::viz::web_player {

extern const char frame_draw_js[];   // web/player/frame_draw.js: drawScantraceFrame
extern const char player_core_js[];  // the key table, keys.mjs, controller.mjs, bind.mjs, hershey.mjs
extern const char keys_json[];       // web/player/keys.json: the players' keys
extern const char step_page_html[];  // web/player/step_page.html with its scripts inlined

}  // namespace scantrace::viz::web_player
