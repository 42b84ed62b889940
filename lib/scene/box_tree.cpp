#include "scene/box_tree.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/time_bounds.hpp"

namespace exactccd::scene {
namespace {

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

double centre(const Box& b, int k) { return b.lo[k] / 2 + b.hi[k] / 2; }

}  // namespace

// The order only affects speed (box_tree.hpp), so the Morton codes need no care about rounding:
// centres that are not finite (boxes grown to infinity after an overflow) get code 0.
Box BoxTree::empty_bounds() { return empty_box(); }

void BoxTree::add_centre(Box& bounds, const Box& box) {
  for (int k = 0; k < 3; ++k) {
    const double c = centre(box, k);
    if (!std::isfinite(c)) continue;
    bounds.lo[k] = std::min(bounds.lo[k], c);
    bounds.hi[k] = std::max(bounds.hi[k], c);
  }
}

BoxTree::MortonFrame BoxTree::frame_of(const Box& bounds) {
  MortonFrame f{};
  for (int k = 0; k < 3; ++k) {
    const double extent = bounds.hi[k] - bounds.lo[k];
    f.lo[k] = bounds.lo[k];
    f.scale[k] = extent > 0 && std::isfinite(extent) ? 2097151.0 / extent : 0.0;
  }
  return f;
}

std::uint64_t BoxTree::MortonFrame::code(const Box& box) const {
  std::uint64_t code = 0;
  for (int k = 0; k < 3; ++k) {
    double q = (centre(box, k) - lo[k]) * scale[k];
    if (!(q >= 0)) q = 0;  // also NaN
    if (q > 2097151.0) q = 2097151.0;
    code |= spread(static_cast<std::uint64_t>(q)) << k;
  }
  return code;
}

void BoxTree::set_order(std::vector<std::pair<std::uint64_t, int>>& keys, unsigned threads) {
  const std::size_t n = keys.size();
  if (n > static_cast<std::size_t>(INT32_MAX / kLeafSize)) throw std::invalid_argument("BoxTree: too many boxes");
  // Sorted in one piece per thread, then merged.
  const unsigned pieces = n < 4 * kGrain ? 1 : std::max(1u, threads);
  const std::size_t piece = (n + pieces - 1) / pieces;
  parallel_chunks(pieces, pieces, 1, [&](std::size_t p, std::size_t, unsigned) {
    const std::size_t a = std::min(n, p * piece), b = std::min(n, a + piece);
    std::sort(keys.begin() + static_cast<std::ptrdiff_t>(a), keys.begin() + static_cast<std::ptrdiff_t>(b));
    return true;
  });
  for (std::size_t width = piece; width > 0 && width < n; width *= 2)
    for (std::size_t a = 0; a + width < n; a += 2 * width)
      std::inplace_merge(keys.begin() + static_cast<std::ptrdiff_t>(a),
                         keys.begin() + static_cast<std::ptrdiff_t>(a + width),
                         keys.begin() + static_cast<std::ptrdiff_t>(std::min(n, a + 2 * width)));
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = keys[i].second;
  const std::size_t leaves = (n + kLeafSize - 1) / kLeafSize;
  first_leaf_ = 1;
  while (static_cast<std::size_t>(first_leaf_) < leaves) first_leaf_ *= 2;
  nodes_.assign(2 * static_cast<std::size_t>(first_leaf_), empty_float_box());
  leaf_boxes_.resize(n);
}

std::vector<BoxTree::NodePair> BoxTree::pair_tasks(const BoxTree& other, std::size_t wanted) const {
  std::vector<NodePair> tasks;
  if (order_.empty() || other.order_.empty()) return tasks;
  const bool self = &other == this;
  tasks.push_back({1, 1});
  // Level by level (both nodes of a pair are always at the same depth, or one a leaf), the
  // children pairs exactly as pairs_from expands them, so the tasks partition its work.
  while (tasks.size() < wanted) {
    std::vector<NodePair> next;
    bool expanded = false;
    for (const auto& [a, b] : tasks) {
      if (!overlap(nodes_[a], other.nodes_[b])) continue;
      const bool leaf_a = a >= first_leaf_, leaf_b = b >= other.first_leaf_;
      if (leaf_a && leaf_b) {
        next.push_back({a, b});
        continue;
      }
      expanded = true;
      if (self && a == b) {
        next.push_back({2 * a, 2 * a});
        next.push_back({2 * a, 2 * a + 1});
        next.push_back({2 * a + 1, 2 * a + 1});
      } else if (leaf_a) {
        next.push_back({a, 2 * b});
        next.push_back({a, 2 * b + 1});
      } else if (leaf_b) {
        next.push_back({2 * a, b});
        next.push_back({2 * a + 1, b});
      } else {
        for (int ca = 2 * a; ca <= 2 * a + 1; ++ca)
          for (int cb = 2 * b; cb <= 2 * b + 1; ++cb) next.push_back({ca, cb});
      }
    }
    tasks.swap(next);
    if (!expanded) break;
  }
  return tasks;
}

void BoxTree::require_size(std::size_t n) const {
  if (n != order_.size()) throw std::invalid_argument("BoxTree::refit: the number of boxes changed");
}

void BoxTree::fit_nodes(unsigned threads) {
  const std::size_t n = order_.size();
  if (n == 0) return;
  const std::size_t leaves = (n + kLeafSize - 1) / kLeafSize;
  parallel_ranges(leaves, threads, kGrain / kLeafSize, [&](std::size_t begin, std::size_t end) {
    for (std::size_t g = begin; g < end; ++g) {
      FloatBox box = leaf_boxes_[g * kLeafSize];
      for (std::size_t k = g * kLeafSize + 1; k < std::min(n, (g + 1) * kLeafSize); ++k) box = hull(box, leaf_boxes_[k]);
      nodes_[static_cast<std::size_t>(first_leaf_) + g] = box;
    }
  });
  // Level by level upwards: nodes [first, 2 first) from their children (padding nodes stay
  // empty: the hull of two empty boxes is empty).
  for (std::size_t first = static_cast<std::size_t>(first_leaf_) / 2; first >= 1; first /= 2)
    parallel_ranges(first, threads, kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = first + begin; i < first + end; ++i) nodes_[i] = hull(nodes_[2 * i], nodes_[2 * i + 1]);
    });
}

}  // namespace exactccd::scene
