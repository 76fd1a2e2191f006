#pragma once
// The legend: every colour and mark of the view, drawn with the same primitives the view uses.
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "viz/typography.hpp"

namespace scantrace::viz {

enum class LegendKind { triangle, scene };

// What the one-shape view shows: a triangle (3 edges) or a general polygon of `edges` edges
// (over all its contours); its legend names the shape and its edges as they are. A replay about
// one pixel (`why --explain`) rings it on every frame: `ringed_pixel` says what the ring is.
struct LegendShape {
  bool polygon = false;
  int edges = 3;
  bool ringed_pixel = false;
};

// The legend's entries, in order (the texts beside the icons).
std::vector<std::string> legend_texts(LegendKind kind, LegendShape shape = {});

int legend_height(const Typography& type, LegendKind kind, LegendShape shape = {});
// Draws the legend in `area`, bottom-aligned.
void draw_legend(FrameView& frame, const Rect& area, const Typography& type, LegendKind kind,
                 LegendShape shape = {});

}  // namespace scantrace::viz
