#pragma once
// Helpers of the tests in tests/viz: small traced triangles, the documented hold weights of the
// replay steps, and ffprobe.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <opencv2/core.hpp>

#include "trace/record.hpp"
#include "trace/trace.hpp"
#include "viz/replay_steps.hpp"

namespace scantrace::test {

// A triangle small enough that every pixel is a big cell at 640x360: rows 2..11 (y from 1.2 to
// 11.6: ceil(1.2) = 2 .. ceil(11.6) - 1 = 11), ten scanlines.
inline trace::TriangleInput small_triangle() {
  trace::TriangleInput t;
  t.vertices = {Vec2{2.3, 1.2}, Vec2{13, 4.5}, Vec2{5, 11.6}};
  t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  t.width = 16;
  t.height = 14;
  return t;
}

// Big enough to leave many cells clear of the outline and the vertex labels, small enough for
// cells of ~19 px at 1280x720: rows 2..27.
inline trace::TriangleInput medium_triangle() {
  trace::TriangleInput t;
  t.vertices = {Vec2{2.3, 1.2}, Vec2{29, 9.5}, Vec2{8, 27.6}};
  t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  t.width = 32;
  t.height = 30;
  return t;
}

inline trace::Trace record(const trace::TriangleInput& t, Shading shading = Shading::gouraud,
                           TraceLevel level = TraceLevel::scanline) {
  FillOptions options;
  options.shading = shading;
  trace::TraceFilter filter;
  filter.level = level;
  return trace::record_triangle(t, options, filter);
}

// The hold of each kind of step of a triangle replay in multiples of --hold, as the README
// documents them: cards, set-up and the finished triangle 3, edge-table entries, skipped
// triangles and scanlines where the active edge table changes 2, other scanlines 1. (A painter's
// batch depends on the number of batches; the scene tests bound frames instead.)
inline double documented_weight(viz::StepKind kind, bool active_edges_change) {
  using K = viz::StepKind;
  switch (kind) {
    case K::title:
    case K::end:
    case K::triangle_setup:
    case K::triangle_done:
    case K::scene_done:
      return 3;
    case K::edge_table_entry:
    case K::triangle_skipped:
      return 2;
    case K::scanlines:
      return active_edges_change ? 2 : 1;
    case K::painter_batch:
      return 1;
  }
  return 1;
}

inline cv::Vec3b bgr8(const Color& c) {
  auto byte = [](double v) {
    return static_cast<unsigned char>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
  };
  return {byte(c.b), byte(c.g), byte(c.r)};
}

inline int max_channel_difference(const cv::Vec3b& a, const cv::Vec3b& b) {
  int d = 0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
  return d;
}

inline bool have_ffprobe() {
  return std::system("command -v ffprobe >/dev/null 2>&1") == 0;
}

// Whether FFmpeg (the library OpenCV's backend writes with) has a software H.264 encoder, as
// `ffmpeg -encoders` lists them: 1 yes, 0 no, -1 ffmpeg is not installed (unknown). Hardware
// encoders (nvenc, vaapi, ...) are listed without a device and are not counted.
inline int have_software_h264_encoder() {
  std::FILE* p = ::popen("ffmpeg -hide_banner -encoders 2>/dev/null", "r");
  if (!p) return -1;
  bool any_line = false, found = false;
  char line[512];
  while (std::fgets(line, sizeof line, p)) {
    const std::string s(line);
    any_line = true;
    if (s.find(" libx264 ") != std::string::npos || s.find(" libopenh264 ") != std::string::npos)
      found = true;
  }
  ::pclose(p);
  return any_line ? found : -1;
}

// ffprobe's view of the first video stream: codec_name, width, height, nb_read_frames.
inline std::map<std::string, std::string> ffprobe(const std::filesystem::path& video) {
  const std::string command =
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of default=noprint_wrappers=1 '" +
      video.string() + "'";
  std::map<std::string, std::string> out;
  std::FILE* p = ::popen(command.c_str(), "r");
  if (!p) return out;
  char line[512];
  while (std::fgets(line, sizeof line, p)) {
    std::string s(line);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    const auto eq = s.find('=');
    if (eq != std::string::npos) out[s.substr(0, eq)] = s.substr(eq + 1);
  }
  ::pclose(p);
  return out;
}

}  // namespace scantrace::test
