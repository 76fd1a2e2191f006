#include "painter.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>

#include "src/std_compat.hpp"

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
// The IEEE-754 bit pattern orders non-negative floats as integers; flipping all bits of negative
// ones and the sign bit of the others extends that to every float, and complementing the result
// turns ascending into descending. −0 is folded onto +0 first: the two compare equal, so their
// faces must keep their scene order, as equal depths do.
std::uint32_t farthest_first_key(float d) {
  const auto bits = scantrace::bit_cast<std::uint32_t>(d == 0.0f ? 0.0f : d);
  const std::uint32_t ascending = (bits >> 31) ? ~bits : bits | (std::uint32_t{1} << 31);
  return ~ascending;
}

}  // namespace

void painter_order(std::span<const double> d, std::vector<int>& order, PainterSortBuffers& buf) {
  // A least-significant-digit radix sort, 11 bits per pass: it is stable, so faces of equal depth
  // keep their order with no tie-break, and unlike a comparison sort it has no data-dependent
  // branches, which std::sort mispredicts on depths. Passes whose digit is the same for every key are skipped.
  //
  // The keys are the depths rounded to float: three passes where the doubles' 64 bits take six.
  // Rounding is monotonic, so faces come
  // out in the painter's order except within a run of equal floats, where the sort keeps scene
  // order; a run whose doubles are not all equal (depths closer than a float's precision, or
  // beyond its range) is then sorted again on the doubles themselves. The order is exactly the
  // stable sort of the doubles, farthest first.
  constexpr int kBits = 11, kPasses = 3, kBuckets = 1 << kBits;
  const std::size_t n = d.size();
  std::vector<std::uint32_t>&key = buf.key, &key_tmp = buf.key_tmp;
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
    key[f] = farthest_first_key(static_cast<float>(d[f]));
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
  // Runs of equal floats whose doubles differ: sorted on the doubles.
  for (std::size_t begin = 0, i = 1; i <= n; ++i) {
    if (i < n && key[i] == key[i - 1]) continue;
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(begin),
               last = order.begin() + static_cast<std::ptrdiff_t>(i);
    begin = i;
    if (last - first < 2) continue;
    const double depth = d[*first];
    if (std::all_of(first + 1, last, [&](int f) { return d[f] == depth; })) continue;
    // The run is in scene order (the radix sort is stable): std::sort with the face index as
    // the tie-break gives what a stable sort would, without the buffer std::stable_sort allocates.
    std::sort(first, last, [&](int a, int b) { return d[a] > d[b] || (d[a] == d[b] && a < b); });
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
