// A bounding volume hierarchy over a fixed list of boxes, refitted when the boxes move.
//
// The primitives are ordered once (build) along a Morton curve of their box centres and grouped
// in leaves of kLeafSize consecutive primitives; the tree is the implicit complete binary tree
// over the leaves (node 1 the root, node i's children 2i and 2i + 1), so it is stored as one
// array of node boxes, the leaf-ordered primitive boxes and the order: memory linear in the
// number of primitives, no pointers. refit() keeps the order and recomputes every box.
//
// Pairs are found by traversing two trees (or one against itself) together, from the node
// pairs of pair_tasks() (independent pieces of work): each pair of primitives is met once.
//
// Exactness: the tree stores each primitive's box as a float box rounded outwards
// (float_box.hpp: half the memory), and a node box is the hull (exact min and max) of the float
// boxes below it; so two overlapping primitive boxes make their float boxes and every pair of
// node boxes above them overlap, and pairs_from() reports every primitive pair whose boxes
// overlap, and a few more whose float boxes overlap (the caller tests those on the exact double
// boxes), whatever the order is: the order (and a stale one after refit) only changes the speed.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "scene/broad_phase.hpp"
#include "scene/float_box.hpp"
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
      for (std::size_t k = begin; k < end; ++k) leaf_boxes_[k] = float_box(box_of(static_cast<std::size_t>(order_[k])));
    });
    fit_nodes(threads);
  }

  /// The number of primitives.
  int size() const { return static_cast<int>(order_.size()); }

  /// A pair of nodes still to be compared by a pair traversal (self_pairs, pairs_with): node
  /// indices of the first and of the second tree.
  using NodePair = std::array<int, 2>;

  /// The node pairs from which a traversal of this tree against `other` (or against itself,
  /// `other` == this) covers every overlapping pair of primitives, at least `wanted` of them
  /// when the trees are deep enough (the roots expanded level by level, disjoint pairs
  /// dropped): independent pieces of work for pairs_from().
  std::vector<NodePair> pair_tasks(const BoxTree& other, std::size_t wanted) const;

  /// Calls report(i, j) for every primitive i of this tree and j of `other` whose float boxes
  /// overlap (closed; every pair whose boxes overlap, and a few more: the caller tests the
  /// exact boxes) and which lie below the node pair `task` (from pair_tasks(other)); when
  /// `other` is this tree, every unordered pair i != j once, as (min, max). Each pair of the
  /// trees is below exactly one task of pair_tasks, so the tasks together report each pair
  /// exactly once (in no particular order). A report returning bool stops the
  /// traversal by returning false; pairs_from then returns false (else true).
  template <class Report>
  bool pairs_from(const BoxTree& other, NodePair task, Report&& report) const {
    const bool self = &other == this;
    NodePair stack[kPairStack];
    int top = 0;
    stack[top++] = task;
    while (top > 0) {
      const auto [a, b] = stack[--top];
      if (!overlap(nodes_[a], other.nodes_[b])) continue;
      const bool leaf_a = a >= first_leaf_, leaf_b = b >= other.first_leaf_;
      if (leaf_a && leaf_b) {
        if (!leaf_pairs(other, a, b, self, report)) return false;
      } else if (self && a == b) {  // same depth: both internal
        stack[top++] = {2 * a, 2 * a};
        stack[top++] = {2 * a, 2 * a + 1};
        stack[top++] = {2 * a + 1, 2 * a + 1};
      } else if (leaf_a) {
        stack[top++] = {a, 2 * b};
        stack[top++] = {a, 2 * b + 1};
      } else if (leaf_b) {
        stack[top++] = {2 * a, b};
        stack[top++] = {2 * a + 1, b};
      } else {
        for (int ca = 2 * a; ca <= 2 * a + 1; ++ca)
          for (int cb = 2 * b; cb <= 2 * b + 1; ++cb) stack[top++] = {ca, cb};
      }
    }
    return true;
  }

 private:
  /// Indices per piece of parallel work.
  static constexpr std::size_t kGrain = 1 << 12;
  /// Pending node pairs of pairs_from: each step pops one pair and pushes at most 4, and lowers
  /// the depth of one of them (at most 2 x 30 levels below the task), so at most 3 x 60 + 1
  /// are pending.
  static constexpr int kPairStack = 192;

  /// The overlapping primitive pairs of leaf node a of this tree and leaf node b of `other`
  /// (self: same tree, each unordered pair once as (min, max), none with itself); false when
  /// the report stopped the traversal.
  template <class Report>
  bool leaf_pairs(const BoxTree& other, int a, int b, bool self, Report& report) const {
    const int begin_a = (a - first_leaf_) * kLeafSize, end_a = std::min(begin_a + kLeafSize, size());
    const int begin_b = (b - other.first_leaf_) * kLeafSize, end_b = std::min(begin_b + kLeafSize, other.size());
    // Only the boxes of each leaf that overlap the other leaf's box can be in a pair (it is the
    // hull of that leaf's boxes): the pairs are tested among those.
    int rows[kLeafSize], cols[kLeafSize], n_rows = 0, n_cols = 0;
    for (int k = begin_a; k < end_a; ++k)
      if (overlap(leaf_boxes_[k], other.nodes_[b])) rows[n_rows++] = k;
    for (int l = begin_b; l < end_b; ++l)
      if (overlap(other.leaf_boxes_[l], nodes_[a])) cols[n_cols++] = l;
    for (int r = 0; r < n_rows; ++r) {
      const int k = rows[r];
      const FloatBox& box = leaf_boxes_[k];
      const int i = order_[k];
      for (int c = 0; c < n_cols; ++c) {
        const int l = cols[c];
        if (self && a == b && l <= k) continue;
        if (!overlap(box, other.leaf_boxes_[l])) continue;
        const int j = other.order_[l];
        if (!(self ? go_on(report, std::min(i, j), std::max(i, j)) : go_on(report, i, j))) return false;
      }
    }
    return true;
  }

  /// report(i, j), and whether to go on (a report returning void always goes on).
  template <class Report>
  static bool go_on(Report& report, int i, int j) {
    if constexpr (std::is_void_v<std::invoke_result_t<Report&, int, int>>) {
      report(i, j);
      return true;
    } else {
      return report(i, j);
    }
  }

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
  std::vector<FloatBox> leaf_boxes_;  ///< the primitives' boxes in leaf order (float_box)
  std::vector<FloatBox> nodes_;       ///< node boxes, index 1..2 * first_leaf_ - 1 (0 unused)
  int first_leaf_ = 1;           ///< the index of the first leaf node (a power of two)
};

}  // namespace exactccd::scene
