#pragma once
// The colours of the marks on a frame (BGR, as OpenCV draws). One place, because the legend must
// show exactly what the views draw. The overlay colours avoid pure red, green and blue, which are
// the usual vertex colours and would vanish into the filled pixels.
#include "viz/frame.hpp"

namespace scantrace::viz::palette {

inline const Scalar kFrame{246, 246, 246};
inline const Scalar kPanel{255, 255, 255};
inline const Scalar kPanelBorder{215, 215, 215};
inline const Scalar kTitleBar{58, 48, 40};
inline const Scalar kTitleText{255, 255, 255};
inline const Scalar kText{35, 35, 35};
inline const Scalar kMutedText{125, 125, 125};
inline const Scalar kHighlightRow{215, 245, 255};  // pale yellow behind the newest table row
inline const Scalar kFormulaBox{250, 240, 232};

// The magnified canvas.
inline const Scalar kEmptyCell{255, 255, 255};
inline const Scalar kOutsideCanvas{205, 205, 205};
inline const Scalar kGridLine{200, 200, 200};
inline const Scalar kCentreOnLight{120, 120, 120};
inline const Scalar kCentreOnDark{215, 215, 215};
inline const Scalar kOutline{20, 20, 20};
inline const Scalar kHalo{0, 0, 0};
// The ring of the pixel a replay is about (`why --explain`) and the history box beside it.
inline const Scalar kSelection{255, 0, 255};  // magenta: no edge, span or fill colour uses it
inline const Scalar kScanline{0, 215, 255};  // amber
inline const Scalar kSpan{255, 255, 255};    // drawn on a black halo
inline const Scalar kCurrentTriangle{0, 215, 255};
inline const Scalar kBatchOutline{60, 60, 60};
// A pixel the z-buffer's depth test rejected (crossed out in the cell).
inline const Scalar kRejected{0, 0, 200};
inline const Scalar kLabelBox{255, 255, 255};

// Edge ids keep their colour in every view and table: 0 orange, 1 magenta, 2 azure, then more for
// polygons with more edges.
inline Scalar edge_colour(int edge) {
  static const Scalar colours[] = {{0, 130, 255}, {200, 40, 200}, {215, 150, 0},   {40, 160, 100},
                                   {90, 90, 200}, {150, 110, 60}, {0, 90, 160},    {160, 160, 0},
                                   {120, 0, 200}, {60, 110, 30},  {200, 100, 140}, {100, 60, 120}};
  const int n = static_cast<int>(sizeof colours / sizeof colours[0]);
  return colours[((edge % n) + n) % n];
}

}  // namespace scantrace::viz::palette
