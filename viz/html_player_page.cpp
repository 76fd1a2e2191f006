#include "viz/html_player_page.hpp"

#include "viz/web_player_files.hpp"

namespace scantrace::viz {

std::string_view html_player_page() {
  return web_player::step_page_html;
}

}  // namespace scantrace::viz
