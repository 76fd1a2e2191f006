#include "cli/x_display.hpp"

#ifdef SCANTRACE_HAVE_XCB
#include <xcb/xcb.h>
#else
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#endif

namespace scantrace::cli {

#ifdef SCANTRACE_HAVE_XCB

// The whole connection set-up, as Qt will make it: the socket, then the X protocol's handshake
// (authorisation included). A socket that accepts and then closes, a server that refuses the
// client or has no such screen all fail here, with xcb's reason.
std::optional<std::string> x_display_refusal(const std::string& display) {
  int screen = 0;
  xcb_connection_t* c = xcb_connect(display.c_str(), &screen);
  const int error = xcb_connection_has_error(c);
  const xcb_setup_t* setup = error == 0 ? xcb_get_setup(c) : nullptr;
  const bool has_screen = setup && screen < xcb_setup_roots_length(setup);
  xcb_disconnect(c);
  switch (error) {
    case 0:
      if (!has_screen) return "the X server has no screen " + std::to_string(screen);
      return std::nullopt;
    case XCB_CONN_ERROR:
      return "no X server answers there, or it closed the connection";
    case XCB_CONN_CLOSED_PARSE_ERR:
      return "the display name cannot be parsed";
    case XCB_CONN_CLOSED_INVALID_SCREEN:
      return "the X server has no such screen";
    case XCB_CONN_CLOSED_MEM_INSUFFICIENT:
      return "out of memory while connecting";
    default:
      return "the X server refused the connection (xcb error " + std::to_string(error) + ")";
  }
}

#else

// Without libxcb's headers: only whether the local socket accepts (displays on other hosts are
// left to Qt).
std::optional<std::string> x_display_refusal(const std::string& display) {
  const std::size_t colon = display.rfind(':');
  if (colon == std::string::npos) return "the display name cannot be parsed";
  const std::string host = display.substr(0, colon);
  if (!host.empty() && host != "unix") return std::nullopt;
  const std::string number = display.substr(colon + 1, display.find('.', colon) - colon - 1);
  const std::string path = "/tmp/.X11-unix/X" + number;
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  if (fd < 0) return "no socket could be made";
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, path.c_str(), sizeof addr.sun_path - 1);
  const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
  ::close(fd);
  if (!ok) return "no X server answers there";
  return std::nullopt;
}

#endif

}  // namespace scantrace::cli
