#include "painter.hpp"

#include <algorithm>
#include <utility>

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
  // Sorting (depth, index) pairs with the index as the tie-break gives exactly the stable order,
  // and is faster than std::stable_sort through an index indirection.
  std::vector<std::pair<double, int>> keyed(d.size());
  for (std::size_t f = 0; f < d.size(); ++f) keyed[f] = {d[f], static_cast<int>(f)};
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<int> order(d.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace scantrace
