// A bounding volume hierarchy over a fixed list of boxes, refitted when the boxes move.
//
// The primitives are ordered once (build) along a Morton curve of their box centres and grouped
// in leaves of kLeafSize consecutive primitives; the tree is the implicit complete binary tree
// over the leaves (node 1 the root, node i's children 2i and 2i + 1), so it is stored as one
// array of node boxes plus the order: memory linear in the number of primitives, no pointers.
// refit() keeps the order and recomputes every node box bottom-up from the new primitive boxes.
//
// Exactness: a node box is the hull (exact min and max) of the boxes below it, so a query box
// overlapping a primitive's box overlaps every node box above it, and query() reports exactly
// the primitives whose boxes overlap the query box (the same closed <= test as overlap()),
// whatever the order is: the order (and a stale one after refit) only changes the speed.
#pragma once

#include <algorithm>
#include <vector>

#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// A refittable bounding volume hierarchy over n boxes (see above). Queries are const and
/// thread-safe; build() and refit() are not (one writer).
class BoxTree {
 public:
  /// Primitives per leaf.
  static constexpr int kLeafSize = 4;

  /// Orders the primitives along a Morton curve of their box centres and fits the tree to
  /// `boxes` (refit) on up to `threads` threads.
  void build(const std::vector<Box>& boxes, unsigned threads);

  /// Keeps the order and recomputes every node box from `boxes` (the same count as at build;
  /// throws std::invalid_argument otherwise), on up to `threads` threads.
  void refit(const std::vector<Box>& boxes, unsigned threads);

  /// The number of primitives.
  int size() const { return static_cast<int>(order_.size()); }

  /// Calls report(i) for every primitive i whose box overlaps `query` (closed boxes, exact),
  /// in tree order (not sorted).
  template <class Report>
  void query(const Box& query, Report&& report) const {
    if (order_.empty()) return;
    int stack[64];
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
  std::vector<int> order_;       ///< primitive indices in leaf order
  std::vector<Box> leaf_boxes_;  ///< the primitives' boxes in leaf order
  std::vector<Box> nodes_;       ///< node boxes, index 1..2 * first_leaf_ - 1 (0 unused)
  int first_leaf_ = 1;           ///< the index of the first leaf node (a power of two)
};

}  // namespace exactccd::scene
