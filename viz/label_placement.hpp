#pragma once
// Labels and zoom insets on the magnified canvas are placed, not just drawn. A label that covers a
// vertex, an active point or another label hides exactly what the frame is there to explain, so
// each one takes the first of its candidate boxes that lies inside the view and overlaps nothing
// already there. Markers go in first: they sit where the geometry puts them. Labels follow in
// order of importance (the row's x values, the row's y, the vertices), insets last.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "viz/frame.hpp"

namespace scantrace::viz {

enum class PlacedKind { vertex, active_point, label, inset };

// One thing on a frame's view: where it was drawn and, for labels and insets, what it says.
struct PlacedBox {
  PlacedKind kind = PlacedKind::label;
  Rect box;
  std::string text;
  // 0: the main view; k > 0: inside zoom inset k, whose own marks and labels are placed
  // against each other (the inset itself is a box of layer 0).
  int layer = 0;
};

class Placement {
 public:
  explicit Placement(Rect area, int layer = 0) : area_(area), layer_(layer) {}

  const Rect& area() const { return area_; }
  int layer() const { return layer_; }
  // A marker (or a box drawn regardless of room, such as an inset's title) where it is.
  void mark(PlacedKind kind, const Rect& box, std::string text = {});
  // Inside the area and overlapping nothing placed so far.
  bool free(const Rect& box) const;
  // Records and returns the first free candidate, each moved inside the area first; nullopt when
  // none is free (the label is then left out: a hidden mark would be worse than a missing label,
  // whose number the side panel shows anyway).
  std::optional<Rect> place(PlacedKind kind, std::span<const Rect> candidates, std::string text);

  const std::vector<PlacedBox>& boxes() const { return boxes_; }

 private:
  Rect area_;
  int layer_;
  std::vector<PlacedBox> boxes_;
};

// Candidate boxes of `size` around a marker of radius `radius` at `p`: the eight directions, those
// closest to `preferred` first, at `gap` from the marker and then further out in steps of `step`.
std::vector<Rect> boxes_around(Point2d p, int radius, Size size, Point2d preferred, int gap,
                               int step, int rings = 6);

// The square a round marker of `radius` centred at `p` covers, anti-aliased edge included.
Rect marker_box(Point2d p, int radius);

}  // namespace scantrace::viz
