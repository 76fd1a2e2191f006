#pragma once
// The interactive player behind `scantrace step`, without the window: which step is shown, what
// the keys and clicks do, and the image the window shows. The window code (cli/step_command.cpp)
// only moves keys, clicks and images between this and OpenCV's HighGUI, so everything here runs
// and is tested without a display.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "trace/trace.hpp"
#include "viz/opencv/step_overlay_raster.hpp"
#include "viz/replayer.hpp"

namespace scantrace::cli {

enum class PlayerKey {
  none,
  next,
  previous,
  forward10,
  back10,
  first,
  last,
  go_to_row,  // g: then a row typed with keys.json's row_entry keys
  play,
  toggle_rows,
  save,
  help,
  quit  // q, or Esc when nothing else is open
};

// A key code from cv::waitKeyEx, whichever HighGUI backend produced it (Qt key codes, GTK/X11
// keysyms, or the Windows virtual keys shifted by 16 bits).
PlayerKey decode_key(int code);

// The window's keys for its `?` overlay: a line per action of the players' key table
// (web/player/keys.json) the window has, its label and help line, then the mouse's click.
std::vector<std::string> key_help_lines();

class StepPlayer {
 public:
  // `window`: the size of the image the window shows (frame above, status strip below).
  StepPlayer(const trace::Trace& trace, const viz::StepOptions& options, cv::Size window,
             std::string source, std::filesystem::path save_dir);

  // What the key does; false when it quits. `code` is the raw key code (for digits).
  bool key(int code);
  // A left click at `p` on the window's image.
  void click(cv::Point p);
  // Play: the step after the current one, stopping at the last.
  void tick();

  bool playing() const { return playing_; }
  std::size_t index() const { return index_; }  // 0-based
  std::size_t steps() const { return replayer_->steps().size(); }
  const viz::StepPlan& plan() const { return replayer_->plan(); }
  bool one_row_per_step() const { return per_row_; }
  const std::optional<viz::CanvasPixel>& selected() const { return selected_; }
  const std::string& message() const { return message_; }
  cv::Size frame_size() const { return replayer_->frame_size(); }

  void show(std::size_t index);  // clamped to the steps
  // The frame of the current step with the selection marked.
  cv::Mat frame();
  // The whole image of the window (what `s` saves): frame() with the help or history boxes, and
  // the status strip.
  cv::Mat image();
  // Writes image() to DIR/step_NNNNN.png atomically and returns the path.
  std::filesystem::path save();

 private:
  void row_entry_key(int code);
  void go_to_row(const std::string& text);
  void toggle_rows();
  void rebuild(bool per_row);

  const trace::Trace& trace_;
  viz::StepOptions options_;
  cv::Size window_;
  int strip_height_;
  std::string source_;
  std::filesystem::path save_dir_;
  std::unique_ptr<viz::Replayer> replayer_;
  std::size_t index_ = 0;
  bool per_row_ = false, playing_ = false, help_ = false;
  std::optional<std::string> row_entry_;  // after g
  std::optional<viz::CanvasPixel> selected_;
  std::string message_;
};

// The height of the status strip below the frame for a window `height` high (even, so the frame
// keeps the even height videos need).
int status_strip_height(int height);

}  // namespace scantrace::cli
