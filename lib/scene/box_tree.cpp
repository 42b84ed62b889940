#include "scene/box_tree.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "scene/parallel.hpp"
#include "scene/time_bounds.hpp"

namespace exactccd::scene {
namespace {

/// Loops over fewer indices than this run on the calling thread (starting threads costs more).
constexpr std::size_t kParallelMin = 1 << 14;

/// The bits of x (< 2^21) spread to every third bit.
std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

/// Runs body(begin, end) over [0, n) on up to `threads` threads (in one piece when n is small).
template <class Body>
void parallel_for(std::size_t n, unsigned threads, Body&& body) {
  if (threads <= 1 || n < kParallelMin) {
    body(std::size_t{0}, n);
    return;
  }
  parallel_chunks(n, threads, kParallelMin / 4, [&](std::size_t begin, std::size_t end, unsigned) {
    body(begin, end);
    return true;
  });
}

}  // namespace

// The order only affects speed (box_tree.hpp), so the Morton codes need no care about rounding:
// centres that are not finite (boxes grown to infinity after an overflow) get code 0.
void BoxTree::build(const std::vector<Box>& boxes, unsigned threads) {
  const std::size_t n = boxes.size();
  if (n > static_cast<std::size_t>(INT32_MAX / kLeafSize)) throw std::invalid_argument("BoxTree: too many boxes");
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  const auto centre = [&](const Box& b, int k) { return b.lo[k] / 2 + b.hi[k] / 2; };
  for (const Box& b : boxes)
    for (int k = 0; k < 3; ++k) {
      const double c = centre(b, k);
      if (!std::isfinite(c)) continue;
      lo[k] = std::min(lo[k], c);
      hi[k] = std::max(hi[k], c);
    }
  std::vector<std::pair<std::uint64_t, int>> keys(n);
  parallel_for(n, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::uint64_t code = 0;
      for (int k = 0; k < 3; ++k) {
        const double extent = hi[k] - lo[k], c = centre(boxes[i], k);
        double q = extent > 0 && std::isfinite(extent) ? (c - lo[k]) / extent * 2097151.0 : 0.0;
        if (!(q >= 0)) q = 0;  // also NaN
        if (q > 2097151.0) q = 2097151.0;
        code |= spread(static_cast<std::uint64_t>(q)) << k;
      }
      keys[i] = {code, static_cast<int>(i)};
    }
  });
  // Sorted in one piece per thread, then merged.
  const unsigned pieces = n < kParallelMin ? 1 : std::max(1u, threads);
  const std::size_t piece = (n + pieces - 1) / std::max(1u, pieces);
  parallel_chunks(pieces, pieces, 1, [&](std::size_t begin, std::size_t, unsigned) {
    const std::size_t a = std::min(n, begin * piece), b = std::min(n, a + piece);
    std::sort(keys.begin() + static_cast<std::ptrdiff_t>(a), keys.begin() + static_cast<std::ptrdiff_t>(b));
    return true;
  });
  for (std::size_t width = piece; width < n; width *= 2)
    for (std::size_t a = 0; a + width < n; a += 2 * width)
      std::inplace_merge(keys.begin() + static_cast<std::ptrdiff_t>(a),
                         keys.begin() + static_cast<std::ptrdiff_t>(a + width),
                         keys.begin() + static_cast<std::ptrdiff_t>(std::min(n, a + 2 * width)));
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = keys[i].second;
  const std::size_t leaves = (n + kLeafSize - 1) / kLeafSize;
  first_leaf_ = 1;
  while (static_cast<std::size_t>(first_leaf_) < leaves) first_leaf_ *= 2;
  nodes_.assign(2 * static_cast<std::size_t>(first_leaf_), empty_box());
  leaf_boxes_.resize(n);
  refit(boxes, threads);
}

void BoxTree::refit(const std::vector<Box>& boxes, unsigned threads) {
  const std::size_t n = order_.size();
  if (boxes.size() != n) throw std::invalid_argument("BoxTree::refit: the number of boxes changed");
  if (n == 0) return;
  const std::size_t leaves = (n + kLeafSize - 1) / kLeafSize;
  parallel_for(leaves, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t g = begin; g < end; ++g) {
      Box box = empty_box();
      for (std::size_t k = g * kLeafSize; k < std::min(n, (g + 1) * kLeafSize); ++k) {
        leaf_boxes_[k] = boxes[static_cast<std::size_t>(order_[k])];
        box = hull(box, leaf_boxes_[k]);
      }
      nodes_[static_cast<std::size_t>(first_leaf_) + g] = box;
    }
  });
  // Level by level upwards: nodes [first, 2 first) from their children (padding nodes stay
  // empty: the hull of two empty boxes is empty).
  for (std::size_t first = static_cast<std::size_t>(first_leaf_) / 2; first >= 1; first /= 2)
    parallel_for(first, threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = first + begin; i < first + end; ++i) nodes_[i] = hull(nodes_[2 * i], nodes_[2 * i + 1]);
    });
}

}  // namespace exactccd::scene
