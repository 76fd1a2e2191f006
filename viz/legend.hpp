#pragma once
// The legend: every colour and mark of the view, drawn with the same primitives the view uses.
#include <opencv2/core.hpp>

#include "viz/typography.hpp"

namespace scantrace::viz {

enum class LegendKind { triangle, scene };

int legend_height(const Typography& type, LegendKind kind);
// Draws the legend in `area`, bottom-aligned.
void draw_legend(cv::Mat& frame, const cv::Rect& area, const Typography& type, LegendKind kind);

}  // namespace scantrace::viz
