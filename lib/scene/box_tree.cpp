#include "scene/box_tree.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "scene/time_bounds.hpp"

namespace exactccd::scene {
namespace {

/// Morton codes of 3 x 11 bits, above the primitive's index (below 2^30: set_order's limit) in
/// one 64-bit sort key. The order only affects speed (box_tree.hpp), so the codes need no care
/// about rounding; 11 bits per axis (21 before) measured no slower traversal on the cloth
/// scenes and cost three radix passes.
constexpr int kAxisBits = 11, kIndexBits = 30, kRadixBits = 11;
constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << kIndexBits) - 1;
constexpr int kCells = 1 << kAxisBits;

/// spread[x]: the bits of x (< 2^11) moved to every third bit (bit b to bit 3b).
constexpr std::array<std::uint32_t, kCells> spread_table() {
  std::array<std::uint32_t, kCells> t{};
  for (std::uint32_t x = 0; x < kCells; ++x)
    for (int b = 0; b < kAxisBits; ++b) t[x] |= (x >> b & 1u) << (3 * b);
  return t;
}
constexpr std::array<std::uint32_t, kCells> kSpread = spread_table();

/// Twice the centre of a float box on axis k (infinite or NaN for a box grown to infinity).
float centre2(const FloatBox& b, int k) { return b.lo[k] + b.hi[k]; }

/// The bounds of the finite doubled centres of boxes [begin, end) (lo > hi on an axis without one).
FloatBox centre_bounds(const std::vector<FloatBox>& boxes, std::size_t begin, std::size_t end) {
  FloatBox bounds = empty_float_box();
  for (std::size_t i = begin; i < end; ++i)
    for (int k = 0; k < 3; ++k) {
      const float c = centre2(boxes[i], k);
      if (!std::isfinite(c)) continue;
      bounds.lo[k] = std::min(bounds.lo[k], c);
      bounds.hi[k] = std::max(bounds.hi[k], c);
    }
  return bounds;
}

/// Quantises doubled centres to kAxisBits per axis over `bounds` (one that is not finite: 0).
struct MortonFrame {
  std::array<float, 3> lo{}, scale{};
  explicit MortonFrame(const FloatBox& bounds) {
    for (int k = 0; k < 3; ++k) {
      const float extent = bounds.hi[k] - bounds.lo[k];
      lo[k] = bounds.lo[k];
      scale[k] = extent > 0 && std::isfinite(extent) ? static_cast<float>(kCells - 1) / extent : 0.0f;
    }
  }
  std::uint64_t code(const FloatBox& box) const {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      float q = (centre2(box, k) - lo[k]) * scale[k];
      if (!(q >= 0)) q = 0;  // also NaN
      if (q > static_cast<float>(kCells - 1)) q = static_cast<float>(kCells - 1);
      code |= static_cast<std::uint64_t>(kSpread[static_cast<std::size_t>(q)]) << k;
    }
    return code;
  }
};

/// Sorts the keys by their bits [kIndexBits, kIndexBits + 3 kAxisBits) (their Morton codes):
/// a least-significant-digit radix sort, stable, so keys made in index order stay in index
/// order among equal codes. `pieces` parts of the keys are counted and scattered in parallel
/// (each part's keys keep their order within a bucket, parts in order).
void radix_sort(std::vector<std::uint64_t>& keys, unsigned pieces) {
  constexpr std::size_t kBuckets = std::size_t{1} << kRadixBits;
  const std::size_t n = keys.size(), piece = (n + pieces - 1) / pieces;
  std::vector<std::uint64_t> out(n);
  std::vector<std::array<std::size_t, kBuckets>> count(pieces);
  for (int shift = kIndexBits; shift < kIndexBits + 3 * kAxisBits; shift += kRadixBits) {
    const auto digit = [shift](std::uint64_t key) { return static_cast<std::size_t>(key >> shift) & (kBuckets - 1); };
    parallel_chunks(pieces, pieces, 1, [&](std::size_t p, std::size_t, unsigned) {
      count[p].fill(0);
      for (std::size_t i = p * piece; i < std::min(n, (p + 1) * piece); ++i) ++count[p][digit(keys[i])];
      return true;
    });
    std::size_t sum = 0;  // count[p][d] becomes where piece p's keys of digit d start
    for (std::size_t d = 0; d < kBuckets; ++d)
      for (unsigned p = 0; p < pieces; ++p) sum += std::exchange(count[p][d], sum);
    parallel_chunks(pieces, pieces, 1, [&](std::size_t p, std::size_t, unsigned) {
      for (std::size_t i = p * piece; i < std::min(n, (p + 1) * piece); ++i) out[count[p][digit(keys[i])]++] = keys[i];
      return true;
    });
    keys.swap(out);
  }
}

}  // namespace

/// The sort keys of the boxes (the Morton code of each centre above its index), on up to
/// `threads` threads.
std::vector<std::uint64_t> BoxTree::morton_keys(const std::vector<FloatBox>& boxes, unsigned threads) {
  const std::size_t n = boxes.size();
  static_assert(INT32_MAX / kLeafSize < (std::int64_t{1} << kIndexBits), "indices fit below the codes");
  if (n > static_cast<std::size_t>(INT32_MAX / kLeafSize)) throw std::invalid_argument("BoxTree: too many boxes");
  const unsigned pieces = n < 4 * kGrain ? 1 : std::max(1u, threads);
  const std::size_t piece = (n + pieces - 1) / pieces;
  std::vector<FloatBox> bounds(pieces);
  parallel_chunks(pieces, pieces, 1, [&](std::size_t p, std::size_t, unsigned) {
    bounds[p] = centre_bounds(boxes, std::min(n, p * piece), std::min(n, (p + 1) * piece));
    return true;
  });
  for (const FloatBox& b : bounds) bounds[0] = hull(bounds[0], b);
  const MortonFrame frame(bounds[0]);
  std::vector<std::uint64_t> keys(n);
  parallel_ranges(n, threads, kGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) keys[i] = frame.code(boxes[i]) << kIndexBits | i;
  });
  return keys;
}

void BoxTree::set_order(std::vector<std::uint64_t>& keys, unsigned threads) {
  leaf_ids_.clear();  // the order changes
  id_count_ = 0;
  const std::size_t n = keys.size();
  const unsigned pieces = n < 4 * kGrain ? 1 : std::max(1u, threads);
  radix_sort(keys, pieces);
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = static_cast<int>(keys[i] & kIndexMask);
  const std::size_t leaves = (n + kLeafSize - 1) / kLeafSize;
  first_leaf_ = 1;
  while (static_cast<std::size_t>(first_leaf_) < leaves) first_leaf_ *= 2;
  nodes_.assign(2 * static_cast<std::size_t>(first_leaf_), empty_float_box());
  // Every lane starts empty (lo = +inf, hi = -inf): the lanes past the last primitive stay so.
  LeafBoxes empty{};
  for (int a = 0; a < 3; ++a)
    for (int l = 0; l < kLeafSize; ++l) {
      empty.lo[a][l] = std::numeric_limits<float>::infinity();
      empty.hi[a][l] = -std::numeric_limits<float>::infinity();
    }
  leaves_.assign(leaves, empty);
}

std::vector<BoxTree::NodePair> BoxTree::pair_tasks(const BoxTree& other, std::size_t wanted) const {
  std::vector<NodePair> tasks, scratch;
  pair_tasks(other, wanted, tasks, scratch);
  return tasks;
}

void BoxTree::pair_tasks(const BoxTree& other, std::size_t wanted, std::vector<NodePair>& tasks,
                         std::vector<NodePair>& next) const {
  tasks.clear();
  next.clear();
  if (order_.empty() || other.order_.empty()) return;
  const bool self = &other == this;
  tasks.push_back({1, 1});
  // Level by level (both nodes of a pair are always at the same depth, or one a leaf), the
  // children pairs exactly as pairs_from expands them, so the tasks partition its work.
  while (tasks.size() < wanted) {
    next.clear();
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
      FloatBox box = leaf_box(static_cast<int>(g * kLeafSize));
      for (std::size_t k = g * kLeafSize + 1; k < std::min(n, (g + 1) * kLeafSize); ++k)
        box = hull(box, leaf_box(static_cast<int>(k)));
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
