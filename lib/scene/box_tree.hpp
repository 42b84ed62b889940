// A bounding volume hierarchy over a fixed list of boxes, refitted when the boxes move.
//
// The primitives are ordered once (build) along a Morton curve of their box centres and grouped
// in leaves of kLeafSize consecutive primitives; the tree is the implicit complete binary tree
// over the leaves (node 1 the root, node i's children 2i and 2i + 1), so it is stored as one
// array of node boxes, the leaf-ordered primitive boxes and the order: memory linear in the
// number of primitives, no pointers. refit() keeps the order and recomputes every box.
//
// Exactness: a node box is the hull (exact min and max) of the boxes below it, so a query box
// overlapping a primitive's box overlaps every node box above it, and query() reports exactly
// the primitives whose boxes overlap the query box (the same closed <= test as overlap()),
// whatever the order is: the order (and a stale one after refit) only changes the speed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "scene/broad_phase.hpp"
#include "scene/parallel.hpp"

namespace exactccd::scene {

/// A refittable bounding volume hierarchy over n boxes (see above), given by box_of(i) for i in
/// [0, n). Queries are const and thread-safe; build() and refit() are not (one writer).
class BoxTree {
 public:
  /// Primitives per leaf.
  static constexpr int kLeafSize = 8;

  /// Orders the n primitives along a Morton curve of the centres of their boxes box_of(i) and
  /// fits the tree to them (refit), on up to `threads` threads. box_of must be thread-safe.
  template <class BoxOf>
  void build(std::size_t n, BoxOf&& box_of, unsigned threads) {
    std::vector<std::pair<std::uint64_t, int>> keys(n);
    const MortonFrame frame = morton_frame(n, box_of);
    parallel_ranges(n, threads, kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) keys[i] = {frame.code(box_of(i)), static_cast<int>(i)};
    });
    set_order(keys, threads);
    refit(n, box_of, threads);
  }

  /// Keeps the order and recomputes every box from box_of(i) (n as at build; throws
  /// std::invalid_argument otherwise), on up to `threads` threads.
  template <class BoxOf>
  void refit(std::size_t n, BoxOf&& box_of, unsigned threads) {
    require_size(n);
    parallel_ranges(n, threads, kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) leaf_boxes_[k] = box_of(static_cast<std::size_t>(order_[k]));
    });
    fit_nodes(threads);
  }

  /// The number of primitives.
  int size() const { return static_cast<int>(order_.size()); }

  /// Calls report(i) for every primitive i whose box overlaps `query` (closed boxes, exact),
  /// in tree order (not sorted).
  template <class Report>
  void query(const Box& query, Report&& report) const {
    if (order_.empty()) return;
    int stack[64];  // depth <= 30 (at most 2^31 / kLeafSize leaves), one sibling pending per level
    int top = 0;
    stack[top++] = 1;
    while (top > 0) {
      const int node = stack[--top];
      if (!overlap(nodes_[node], query)) continue;
      if (node >= first_leaf_) {
        const int begin = (node - first_leaf_) * kLeafSize;
        const int end = std::min(begin + kLeafSize, size());
        for (int k = begin; k < end; ++k)
          if (overlap(leaf_boxes_[k], query)) report(order_[k]);
      } else {
        stack[top++] = 2 * node + 1;
        stack[top++] = 2 * node;
      }
    }
  }

 private:
  /// Indices per piece of parallel work.
  static constexpr std::size_t kGrain = 1 << 12;

  /// The bounding box of the finite box centres, quantised to 21 bits per axis.
  struct MortonFrame {
    std::array<double, 3> lo, scale;
    /// The Morton code of a box's centre (0 for a centre that is not finite).
    std::uint64_t code(const Box& box) const;
  };

  template <class BoxOf>
  static MortonFrame morton_frame(std::size_t n, BoxOf& box_of) {
    Box bounds = empty_bounds();
    for (std::size_t i = 0; i < n; ++i) add_centre(bounds, box_of(i));
    return frame_of(bounds);
  }
  static Box empty_bounds();
  static void add_centre(Box& bounds, const Box& box);
  static MortonFrame frame_of(const Box& bounds);
  void set_order(std::vector<std::pair<std::uint64_t, int>>& keys, unsigned threads);
  void require_size(std::size_t n) const;
  void fit_nodes(unsigned threads);

  std::vector<int> order_;       ///< primitive indices in leaf order
  std::vector<Box> leaf_boxes_;  ///< the primitives' boxes in leaf order
  std::vector<Box> nodes_;       ///< node boxes, index 1..2 * first_leaf_ - 1 (0 unused)
  int first_leaf_ = 1;           ///< the index of the first leaf node (a power of two)
};

}  // namespace exactccd::scene
