#include "cli/step_player.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/atomic_write.hpp"
#include "viz/frame_layout.hpp"
#include "viz/step_label.hpp"
#include "viz/typography.hpp"
#include "viz/web_player_files.hpp"

namespace scantrace::cli {

namespace {

// The name of a key code, as keys.json spells keys (KeyboardEvent.key): the backends' codes of
// keys without text, else the character ("" for none).
std::string key_name(int code) {
  switch (code) {
    // Qt (OpenCV's Qt backend passes Qt::Key for keys without text), GTK/X11 keysyms, Windows.
    case 0x01000014:
    case 0xff53:
    case 0x270000:
      return "ArrowRight";
    case 0x01000012:
    case 0xff51:
    case 0x250000:
      return "ArrowLeft";
    case 0x01000017:
    case 0xff56:
    case 0x220000:
      return "PageDown";
    case 0x01000016:
    case 0xff55:
    case 0x210000:
      return "PageUp";
    case 0x01000010:
    case 0xff50:
    case 0x240000:
      return "Home";
    case 0x01000011:
    case 0xff57:
    case 0x230000:
      return "End";
    case 0x01000004:
    case 0x01000005:
    case 0xff0d:
    case 0xff8d:
    case '\r':
    case '\n':
      return "Enter";
    case 0x01000003:
    case 0xff08:
    case 8:
      return "Backspace";
    case 0x01000000:
    case 0xff1b:
    case 27:
      return "Escape";
    default:
      break;
  }
  const int c = code & 0xff;  // GTK adds modifier bits above the character
  if (c < ' ' || c > '~') return "";
  // A digit only below the modifier bits: Qt's F keys (0x01000030..) hold one in their low byte.
  if (c >= '0' && c <= '9' && code >= 0x10000) return "";
  return std::string(1, static_cast<char>(c));
}

// One action of the players' key table (web/player/keys.json, shared with every page's player)
// that the window has: its keys, and its label and help line for the help and the hint.
struct WindowAction {
  PlayerKey key;
  std::vector<std::string> keys;
  std::string label, help;
};

// The window's actions of keys.json, in the table's order.
const std::vector<WindowAction>& window_actions() {
  static const std::vector<WindowAction> out = [] {
    const std::map<std::string, PlayerKey> actions = {{"next", PlayerKey::next},
                                                      {"previous", PlayerKey::previous},
                                                      {"forward10", PlayerKey::forward10},
                                                      {"back10", PlayerKey::back10},
                                                      {"first", PlayerKey::first},
                                                      {"last", PlayerKey::last},
                                                      {"go_to_row", PlayerKey::go_to_row},
                                                      {"play", PlayerKey::play},
                                                      {"toggle_rows", PlayerKey::toggle_rows},
                                                      {"save", PlayerKey::save},
                                                      {"help", PlayerKey::help},
                                                      {"quit", PlayerKey::quit}};
    std::vector<WindowAction> v;
    const nlohmann::json table = nlohmann::json::parse(viz::web_player::keys_json);
    for (const nlohmann::json& a : table["actions"]) {
      const auto& in = a["in"];
      if (std::find(in.begin(), in.end(), "window") == in.end()) continue;
      const auto action = actions.find(a["action"].get<std::string>());
      if (action == actions.end())
        throw std::logic_error("keys.json: the window has no action " + a["action"].dump());
      v.push_back({action->second, a["keys"].get<std::vector<std::string>>(),
                   a["label"].get<std::string>(), a["help"].get<std::string>()});
    }
    return v;
  }();
  return out;
}

// Each key's action in the window.
const std::map<std::string, PlayerKey>& window_keys() {
  static const std::map<std::string, PlayerKey> keys = [] {
    std::map<std::string, PlayerKey> out;
    for (const WindowAction& a : window_actions())
      for (const std::string& k : a.keys) out.emplace(k, a.key);
    return out;
  }();
  return keys;
}

// A window action's label and help line (the key hint of the status strip).
std::string key_hint(PlayerKey key) {
  for (const WindowAction& a : window_actions())
    if (a.key == key) return a.label + " " + a.help;
  throw std::logic_error("keys.json: the window has no key for its hint");
}

// A key's part while a row is typed after g (keys.json's row_entry, as every player reads it).
enum class RowKey { none, character, go, erase, cancel };

RowKey row_key(const std::string& name) {
  static const std::map<std::string, RowKey> keys = [] {
    const nlohmann::json table = nlohmann::json::parse(viz::web_player::keys_json)["row_entry"];
    std::map<std::string, RowKey> out;
    for (const auto& [part, key] : {std::pair{"characters", RowKey::character},
                                    {"go", RowKey::go},
                                    {"erase", RowKey::erase},
                                    {"cancel", RowKey::cancel}})
      for (const nlohmann::json& k : table.at(part)) out.emplace(k.get<std::string>(), key);
    return out;
  }();
  const auto k = keys.find(name);
  return k == keys.end() ? RowKey::none : k->second;
}

}  // namespace

std::vector<std::string> key_help_lines() {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const WindowAction& a : window_actions()) rows.emplace_back(a.label, a.help);
  // The mouse's one action: no key, so not in the key table.
  rows.emplace_back("click a pixel", "select it: marked, with its history");
  // Characters, not bytes: the labels' arrows are three bytes of UTF-8.
  const auto chars = [](const std::string& s) {
    return static_cast<std::size_t>(
        std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xc0) != 0x80; }));
  };
  std::size_t wide = 0;
  for (const auto& [label, help] : rows) wide = std::max(wide, chars(label));
  std::vector<std::string> lines;
  for (const auto& [label, help] : rows)
    lines.push_back(label + std::string(wide - chars(label) + 2, ' ') + help);
  return lines;
}

PlayerKey decode_key(int code) {
  if (code < 0) return PlayerKey::none;
  const std::string name = key_name(code);
  if (const auto k = window_keys().find(name); k != window_keys().end()) return k->second;
  return PlayerKey::none;
}

int status_strip_height(int height) {
  return std::max(2, 2 * ((height * 16 + 360) / 720));
}

StepPlayer::StepPlayer(const trace::Trace& trace, const viz::StepOptions& options, cv::Size window,
                       std::string source, std::filesystem::path save_dir)
    : trace_(trace),
      options_(options),
      window_(window),
      strip_height_(status_strip_height(window.height)),
      source_(std::move(source)),
      save_dir_(std::move(save_dir)) {
  rebuild(options.rows_per_step == 1);
}

void StepPlayer::rebuild(bool per_row) {
  viz::StepOptions o = options_;
  if (per_row) o.rows_per_step = 1;
  // Why per_row lifts the scanline-step limit: "one step per scanline" means every row, however
  // many (rows_per_step 1 is never regrouped).
  replayer_ = std::make_unique<viz::Replayer>(
      trace_, o, cv::Size(window_.width, window_.height - strip_height_), source_);
  per_row_ = per_row;
}

void StepPlayer::show(std::size_t index) {
  index_ = std::min(index, steps() - 1);
}

// A key while a row number is typed after `g`: its part in keys.json's row_entry. A sign only
// leads the number (from_chars reads no other), and the window's quit keys (q) cancel the row as
// Esc does: they never quit mid-row.
void StepPlayer::row_entry_key(int code) {
  const std::string name = key_name(code);
  switch (row_key(name)) {
    case RowKey::character:
      if (name != "-" || row_entry_->empty()) row_entry_->append(name);
      break;
    case RowKey::erase:
      if (!row_entry_->empty()) row_entry_->pop_back();
      break;
    case RowKey::go: {
      const std::string text = *row_entry_;
      row_entry_.reset();
      go_to_row(text);
      break;
    }
    case RowKey::cancel:
      row_entry_.reset();
      message_.clear();
      break;
    case RowKey::none:
      if (decode_key(code) == PlayerKey::quit) {
        row_entry_.reset();
        message_.clear();
      }
      break;
  }
}

void StepPlayer::go_to_row(const std::string& text) {
  std::int64_t row = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), row);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    message_.clear();
    return;
  }
  const std::size_t at = viz::step_of_row(replayer_->plan(), row);
  if (at == steps()) {
    message_ = fmt::format("no step shows scanline {}", row);
    return;
  }
  show(at);
  message_ = fmt::format("scanline {}", row);
}

void StepPlayer::toggle_rows() {
  // Keep the place: the same scanline when there is one, else the same kind of step of the same
  // triangle, else the same position.
  const viz::Step was = replayer_->steps()[index_];
  rebuild(!per_row_);
  std::size_t at = std::min(index_, steps() - 1);
  if (was.kind == viz::StepKind::scanlines) {
    at = viz::step_of_row(replayer_->plan(), was.last_row);
  } else {
    const auto& s = replayer_->steps();
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i].kind == was.kind && s[i].triangle == was.triangle && s[i].entry == was.entry) {
        at = i;
        break;
      }
  }
  show(at);
  message_ = per_row_ ? "one step per scanline" : "grouped steps";
}

bool StepPlayer::key(int code) {
  if (row_entry_) {
    row_entry_key(code);
    return true;
  }
  const PlayerKey k = decode_key(code);
  switch (k) {
    case PlayerKey::next:
      show(index_ + 1);
      break;
    case PlayerKey::previous:
      show(index_ == 0 ? 0 : index_ - 1);
      break;
    case PlayerKey::forward10:
      show(index_ + 10);
      break;
    case PlayerKey::back10:
      show(index_ < 10 ? 0 : index_ - 10);
      break;
    case PlayerKey::first:
      show(0);
      break;
    case PlayerKey::last:
      show(steps() - 1);
      break;
    case PlayerKey::go_to_row:
      row_entry_ = "";
      playing_ = false;
      break;
    case PlayerKey::play:
      playing_ = !playing_;
      if (playing_ && index_ + 1 == steps()) show(0);
      break;
    case PlayerKey::toggle_rows:
      toggle_rows();
      break;
    case PlayerKey::save:
      message_ = "saved " + save().string();
      break;
    case PlayerKey::help:
      help_ = !help_;
      break;
    case PlayerKey::quit:
      // Esc closes the keys first; q always quits, as the keys say.
      if (help_ && (code & 0xff) != 'q') {
        help_ = false;
        break;
      }
      return false;
    default:
      break;
  }
  return true;
}

void StepPlayer::click(cv::Point p) {
  const auto g = replayer_->geometry(index_);
  if (!g) return;
  const trace::CanvasSize& c = trace_.header().canvas;
  if (const auto px = viz::pixel_at(*g, p, {c.width, c.height})) {
    selected_ = *px;
    message_ = fmt::format("selected pixel ({}, {})", px->x, px->y);
  }
}

void StepPlayer::tick() {
  if (!playing_) return;
  if (index_ + 1 >= steps()) {
    playing_ = false;
    return;
  }
  show(index_ + 1);
}

cv::Mat StepPlayer::frame() {
  cv::Mat f = replayer_->frame(index_);
  if (selected_)
    if (const auto g = replayer_->geometry(index_)) viz::mark_pixel(f, *g, *selected_);
  return f;
}

cv::Mat StepPlayer::image() {
  cv::Mat f = frame();
  const viz::Typography type(f.size());
  if (selected_ && replayer_->geometry(index_)) {
    const viz::FrameLayout layout = viz::FrameLayout::for_frame(f.size(), type);
    viz::draw_history_box(f, layout.panel, type,
                          viz::pixel_history_lines(trace_, replayer_->plan(), index_, *selected_));
  }
  if (help_) viz::draw_key_help(f, type, key_help_lines());
  std::string left =
      fmt::format("step {} / {}{}", index_ + 1, steps(), playing_ ? "   playing" : "");
  if (row_entry_)
    left += "   go to scanline: " + *row_entry_ + "_";
  else if (!message_.empty())
    left += "   " + message_;
  const cv::Mat strip = viz::status_strip(
      f.cols, strip_height_, type, left,
      fmt::format("click a pixel   {}   {}", key_hint(PlayerKey::help), key_hint(PlayerKey::quit)));
  cv::Mat out;
  cv::vconcat(f, strip, out);
  return out;
}

std::filesystem::path StepPlayer::save() {
  std::vector<unsigned char> png;
  // What the window shows, so the file matches the screen: the frame with its boxes, and the status line.
  if (!cv::imencode(".png", image(), png))
    throw std::runtime_error(fmt::format("cannot encode step {} as PNG", index_ + 1));
  const std::filesystem::path file =
      (save_dir_ / fmt::format("step_{:05d}.png", index_ + 1)).lexically_normal();
  write_file_atomically(file,
                        std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
  return file;
}

}  // namespace scantrace::cli
