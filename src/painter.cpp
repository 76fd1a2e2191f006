#include "painter.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <numeric>
#include <utility>

namespace scantrace {

void face_depths(const Scene& scene, std::vector<double>& d) {
  d.resize(scene.faces.size());
  for (std::size_t f = 0; f < d.size(); ++f) {
    const auto& face = scene.faces[f];
    d[f] = (scene.depth[face[0]] + scene.depth[face[1]] + scene.depth[face[2]]) / 3.0;
  }
}

std::vector<double> face_depths(const Scene& scene) {
  std::vector<double> d;
  face_depths(scene, d);
  return d;
}

namespace {

// An unsigned key whose ascending order is the painter's order: farthest (largest depth) first.
// The IEEE-754 bit pattern orders non-negative doubles as integers; flipping all bits of negative
// ones and the sign bit of the others extends that to every double, and complementing the result
// turns ascending into descending. −0 is folded onto +0 first: the two compare equal, so their
// faces must keep their scene order, as equal depths do.
std::uint64_t farthest_first_key(double d) {
  const auto bits = std::bit_cast<std::uint64_t>(d == 0.0 ? 0.0 : d);
  const std::uint64_t ascending = (bits >> 63) ? ~bits : bits | (std::uint64_t{1} << 63);
  return ~ascending;
}

}  // namespace

void painter_order(std::span<const double> d, std::vector<int>& order, PainterSortBuffers& buf) {
  // A least-significant-digit radix sort of the keys, 11 bits per pass: it is stable, so faces of
  // equal depth keep their order with no tie-break, and unlike a comparison sort it has no
  // data-dependent branches (on the course scene std::sort's mispredictions made the sort an eighth
  // of the render). Passes whose digit is the same for every key are skipped.
  constexpr int kBits = 11, kPasses = 6, kBuckets = 1 << kBits;
  const std::size_t n = d.size();
  std::vector<std::uint64_t>&key = buf.key, &key_tmp = buf.key_tmp;
  std::vector<int>& order_tmp = buf.order_tmp;
  key.resize(n);
  key_tmp.resize(n);
  order.resize(n);
  order_tmp.resize(n);
  buf.count.assign(std::size_t{kPasses} * kBuckets, 0);
  const auto count = [&](int pass) {
    return std::span<std::uint32_t, kBuckets>(buf.count.data() + pass * kBuckets, kBuckets);
  };
  for (std::size_t f = 0; f < n; ++f) {
    key[f] = farthest_first_key(d[f]);
    order[f] = static_cast<int>(f);
    for (int p = 0; p < kPasses; ++p) ++count(p)[(key[f] >> (p * kBits)) & (kBuckets - 1)];
  }
  for (int p = 0; p < kPasses; ++p) {
    const auto c = count(p);
    if (n == 0 || c[(key[0] >> (p * kBits)) & (kBuckets - 1)] == n) continue;
    std::uint32_t sum = 0;
    for (std::uint32_t& bucket : c) sum += std::exchange(bucket, sum);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t at = c[(key[i] >> (p * kBits)) & (kBuckets - 1)]++;
      key_tmp[at] = key[i];
      order_tmp[at] = order[i];
    }
    key.swap(key_tmp);
    order.swap(order_tmp);
  }
}

void drawing_order(const Scene& scene, Visibility visibility, RenderScratch& scratch,
                   Occlusion occlusion) {
  face_depths(scene, scratch.depth);
  if (visibility == Visibility::zbuffer) {
    scratch.order.resize(scene.faces.size());
    std::iota(scratch.order.begin(), scratch.order.end(), 0);
  } else {
    painter_order(scratch.depth, scratch.order, scratch.sort);
    // Reversed, not sorted nearest first: faces of equal depth must come in reverse scene order,
    // so that the one the painter paints last (and keeps) is the one drawn first here.
    if (occlusion == Occlusion::near_to_far)
      std::reverse(scratch.order.begin(), scratch.order.end());
  }
}

std::vector<int> painter_order(const std::vector<double>& d) {
  std::vector<int> order;
  PainterSortBuffers buffers;
  painter_order(d, order, buffers);
  return order;
}

}  // namespace scantrace
