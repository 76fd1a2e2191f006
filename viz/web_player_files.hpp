#pragma once
// The player's web files (web/player/), embedded at configure time by cmake/web_player.cmake:
// each one's text, zero-terminated.
namespace scantrace::viz::web_player {

// web/player/frame_draw.js: drawScantraceFrame
extern const char frame_draw_js[];
// the player core: the key table, keys.mjs, controller.mjs, bind.mjs, hershey.mjs
extern const char player_core_js[];
// web/player/keys.json: the players' keys
extern const char keys_json[];
// web/player/step_page.html with its scripts inlined
extern const char step_page_html[];

}  // namespace scantrace::viz::web_player
