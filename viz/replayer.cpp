#include "viz/replayer.hpp"

#include "viz/opencv/frame_raster.hpp"

namespace scantrace::viz {

cv::Mat Replayer::frame(std::size_t index, std::vector<PlacedBox>* placed) {
  return rasterize(sequence_.frame(index, placed));
}

}  // namespace scantrace::viz
