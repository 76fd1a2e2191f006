#include "painter.hpp"

#include <algorithm>
#include <numeric>

namespace scantrace {

std::vector<double> face_depths(const Scene& scene) {
  std::vector<double> d(scene.faces.size());
  for (std::size_t f = 0; f < d.size(); ++f) {
    const auto& face = scene.faces[f];
    d[f] = (scene.depth[face[0]] + scene.depth[face[1]] + scene.depth[face[2]]) / 3.0;
  }
  return d;
}

std::vector<int> painter_order(const std::vector<double>& d) {
  std::vector<int> order(d.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return d[a] > d[b]; });
  return order;
}

}  // namespace scantrace
