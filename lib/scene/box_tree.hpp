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

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <stdexcept>
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
  /// Primitives per leaf: 16 (four SSE2 registers per bound) measured faster than 8 (fewer node
  /// pairs visited, the leaf tests vectorised; on the 102k-triangle cloth the streamed broad
  /// phase's traversal went from about 54 to 45 ms), 4 slower still.
  static constexpr int kLeafSize = 16;

  /// Orders the n primitives along a Morton curve of the centres of their boxes box_of(i) (a
  /// Box, or a FloatBox holding it) and fits the tree to them, on up to `threads` threads.
  /// box_of must be thread-safe; it is called twice per primitive.
  template <class BoxOf>
  void build(std::size_t n, BoxOf&& box_of, unsigned threads) {
    {  // the boxes only while the sort keys are made, the keys only while sorted (then refit()
       // takes the boxes again): less peak memory
      std::vector<std::uint64_t> keys;
      {
        std::vector<FloatBox> boxes(n);
        parallel_ranges(n, threads, kGrain, [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) boxes[i] = as_float_box(box_of(i));
        });
        keys = morton_keys(boxes, threads);
      }
      set_order(keys, threads);
    }
    refit(n, box_of, threads);
  }

  /// Keeps the order and recomputes every box from box_of(i) (as in build; n as at build; throws
  /// std::invalid_argument otherwise), on up to `threads` threads.
  template <class BoxOf>
  void refit(std::size_t n, BoxOf&& box_of, unsigned threads) {
    require_size(n);
    parallel_ranges(n, threads, kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) set_leaf_box(k, as_float_box(box_of(static_cast<std::size_t>(order_[k]))));
    });
    fit_nodes(threads);
  }

  /// Gives every primitive i (as in build) its `count` (1 to 3) vertex indices vertices_of(i)
  /// (a std::array<int, 3>; the first `count` entries, each >= 0), after build() (a later
  /// build() forgets them; refit() keeps them). pairs_from between two trees that both have
  /// them then drops every pair of primitives sharing a vertex index before reporting it: the
  /// pairs the broad phase never forms, compared four lanes at a time instead of one report
  /// (and one unpredictable branch) each. Throws std::invalid_argument for a negative index.
  template <class VerticesOf>
  void set_vertices(int count, VerticesOf&& vertices_of, unsigned threads) {
    if (count < 1 || count > 3) throw std::invalid_argument("BoxTree::set_vertices: 1 to 3 vertices");
    leaf_ids_.assign(leaves_.size() * static_cast<std::size_t>(count * kLeafSize), -1);
    std::atomic<bool> negative{false};
    parallel_ranges(order_.size(), threads, kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) {
        const std::array<int, 3> v = vertices_of(static_cast<std::size_t>(order_[k]));
        for (int m = 0; m < count; ++m) {
          if (v[static_cast<std::size_t>(m)] < 0) negative = true;
          leaf_ids_[(k / kLeafSize * static_cast<std::size_t>(count) + static_cast<std::size_t>(m)) * kLeafSize +
                    k % kLeafSize] = v[static_cast<std::size_t>(m)];
        }
      }
    });
    if (negative) {
      leaf_ids_.clear();
      throw std::invalid_argument("BoxTree::set_vertices: a negative vertex index");
    }
    id_count_ = count;
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

  /// The same node pairs, written into `tasks` with `scratch` for the levels in between (both
  /// cleared first; kept by a caller that asks repeatedly, they allocate nothing once grown).
  void pair_tasks(const BoxTree& other, std::size_t wanted, std::vector<NodePair>& tasks,
                  std::vector<NodePair>& scratch) const;

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

  /// The boxes of one leaf, structure of arrays: bound[axis][lane] for the kLeafSize
  /// primitives of the leaf (lanes past the last primitive hold empty boxes and are masked
  /// off), so that one box is tested against the whole leaf at once (overlap_mask).
  struct alignas(32) LeafBoxes {
    float lo[3][kLeafSize];
    float hi[3][kLeafSize];
  };

  /// The lanes of `leaf` (a bit per lane) whose boxes overlap `box`, among `lanes`: the test of
  /// overlap(FloatBox, FloatBox), lane by lane (the same six exact comparisons), four lanes per
  /// SSE2 instruction where available. cmpltps is the scalar `<` (false on a NaN operand, as in
  /// overlap(): a NaN bound never makes boxes apart, in either form; float_box never makes one).
  static unsigned overlap_mask(const LeafBoxes& leaf, const FloatBox& box, unsigned lanes) {
#if defined(__SSE2__)
    static_assert(kLeafSize % 4 == 0, "whole SSE2 registers per leaf");
    unsigned apart = 0;
    for (int q = 0; q < kLeafSize; q += 4) {
      __m128 away = _mm_setzero_ps();
      for (int k = 0; k < 3; ++k) {
        const __m128 lo = _mm_load_ps(&leaf.lo[k][q]), hi = _mm_load_ps(&leaf.hi[k][q]);
        away = _mm_or_ps(away, _mm_or_ps(_mm_cmplt_ps(_mm_set1_ps(box.hi[k]), lo), _mm_cmplt_ps(hi, _mm_set1_ps(box.lo[k]))));
      }
      apart |= static_cast<unsigned>(_mm_movemask_ps(away)) << q;
    }
    return lanes & ~apart;
#else
    unsigned mask = 0;
    for (int l = 0; l < kLeafSize; ++l) {
      const FloatBox b{{{leaf.lo[0][l], leaf.lo[1][l], leaf.lo[2][l]}}, {{leaf.hi[0][l], leaf.hi[1][l], leaf.hi[2][l]}}};
      mask |= static_cast<unsigned>(overlap(box, b)) << l;
    }
    return lanes & mask;
#endif
  }

  /// The vertex indices of leaf g's primitives (set_vertices), structure of arrays: index m of
  /// lane l at ids(g)[m * kLeafSize + l] (-1 past the last primitive).
  const int* ids(int g) const {
    return &leaf_ids_[static_cast<std::size_t>(g) * static_cast<std::size_t>(id_count_ * kLeafSize)];
  }

  /// The lanes of `lanes` (among `wanted`, a bit per lane) whose primitives share a vertex index
  /// with the primitive in lane `row` of `rows` (its first row_count indices, all >= 0, against
  /// the lanes' first lane_count, where -1 matches none of them), four lanes per SSE2 compare.
  static unsigned shared_lanes(const int* rows, int row, int row_count, const int* lanes, int lane_count,
                               unsigned wanted) {
    unsigned shared = 0;
#if defined(__SSE2__)
    for (int q = 0; q < kLeafSize; q += 4) {
      if ((wanted >> q & 0xfu) == 0) continue;
      __m128i equal = _mm_setzero_si128();
      for (int m = 0; m < row_count; ++m) {
        const __m128i id = _mm_set1_epi32(rows[m * kLeafSize + row]);
        for (int s = 0; s < lane_count; ++s)
          equal = _mm_or_si128(equal, _mm_cmpeq_epi32(id, _mm_loadu_si128(reinterpret_cast<const __m128i*>(lanes + s * kLeafSize + q))));
      }
      shared |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(equal))) << q;
    }
#else
    for (int l = 0; l < kLeafSize; ++l)
      for (int m = 0; m < row_count; ++m)
        for (int s = 0; s < lane_count; ++s)
          if (rows[m * kLeafSize + row] == lanes[s * kLeafSize + l]) shared |= 1u << l;
#endif
    return shared & wanted;
  }

  /// The box of primitive k (in leaf order).
  FloatBox leaf_box(int k) const {
    const LeafBoxes& leaf = leaves_[static_cast<std::size_t>(k / kLeafSize)];
    const int l = k % kLeafSize;
    return {{{leaf.lo[0][l], leaf.lo[1][l], leaf.lo[2][l]}}, {{leaf.hi[0][l], leaf.hi[1][l], leaf.hi[2][l]}}};
  }

  /// Sets the box of primitive k (in leaf order).
  void set_leaf_box(std::size_t k, const FloatBox& box) {
    LeafBoxes& leaf = leaves_[k / kLeafSize];
    const std::size_t l = k % kLeafSize;
    for (int a = 0; a < 3; ++a) {
      leaf.lo[a][l] = box.lo[a];
      leaf.hi[a][l] = box.hi[a];
    }
  }

  /// The overlapping primitive pairs of leaf node a of this tree and leaf node b of `other`
  /// (self: same tree, each unordered pair once as (min, max), none with itself); false when
  /// the report stopped the traversal.
  template <class Report>
  bool leaf_pairs(const BoxTree& other, int a, int b, bool self, Report& report) const {
    const int leaf_a = a - first_leaf_, leaf_b = b - other.first_leaf_;
    const int begin_a = leaf_a * kLeafSize, begin_b = leaf_b * kLeafSize;
    // A padding leaf (past the last primitive: an empty box, which an unbounded box still
    // "overlaps") holds nothing.
    if (begin_a >= size() || begin_b >= other.size()) return true;
    const LeafBoxes &boxes_a = leaves_[static_cast<std::size_t>(leaf_a)], &boxes_b = other.leaves_[static_cast<std::size_t>(leaf_b)];
    // Only the boxes of each leaf that overlap the other leaf's box can be in a pair (it is the
    // hull of that leaf's boxes): the pairs are tested among those, row by row against the
    // other leaf's lanes at once.
    const unsigned rows = overlap_mask(boxes_a, other.nodes_[b], lanes_of(begin_a, size()));
    const unsigned cols = overlap_mask(boxes_b, nodes_[a], lanes_of(begin_b, other.size()));
    if (cols == 0) return true;
    for (unsigned r = rows; r != 0; r &= r - 1) {
      const int la = lowest_bit(r), k = begin_a + la;
      unsigned hits = overlap_mask(boxes_b, leaf_box(k), cols);
      if (self && a == b) hits &= ~((2u << la) - 1);  // l > k only: each unordered pair once
      if (hits != 0 && id_count_ > 0 && other.id_count_ > 0)
        hits &= ~shared_lanes(ids(leaf_a), la, id_count_, other.ids(leaf_b), other.id_count_, hits);
      const int i = order_[static_cast<std::size_t>(k)];
      for (; hits != 0; hits &= hits - 1) {
        const int j = other.order_[static_cast<std::size_t>(begin_b + lowest_bit(hits))];
        if (!(self ? go_on(report, std::min(i, j), std::max(i, j)) : go_on(report, i, j))) return false;
      }
    }
    return true;
  }

  /// The lanes of the leaf starting at primitive `begin` that hold primitives (of `size`).
  static unsigned lanes_of(int begin, int size) {
    static_assert(kLeafSize < 32, "a bit per lane in an unsigned mask");
    const int count = std::min(kLeafSize, size - begin);
    return count >= kLeafSize ? (1u << kLeafSize) - 1 : (1u << count) - 1;
  }

  /// The index of the lowest set bit of a nonzero mask.
  static int lowest_bit(unsigned mask) {
#if defined(__GNUC__)
    return __builtin_ctz(mask);  // one instruction (GCC and clang); the loop below costs one step per bit
#else
    int i = 0;
    while (!(mask >> i & 1u)) ++i;
    return i;
#endif
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

  static std::vector<std::uint64_t> morton_keys(const std::vector<FloatBox>& boxes, unsigned threads);
  void set_order(std::vector<std::uint64_t>& keys, unsigned threads);
  void require_size(std::size_t n) const;
  void fit_nodes(unsigned threads);

  std::vector<int> order_;       ///< primitive indices in leaf order
  std::vector<LeafBoxes> leaves_;  ///< the primitives' boxes in leaf order (float_box), by leaf
  std::vector<int> leaf_ids_;      ///< the primitives' vertex indices by leaf (ids(), set_vertices), or none
  int id_count_ = 0;               ///< vertex indices per primitive (0: none given)
  std::vector<FloatBox> nodes_;       ///< node boxes, index 1..2 * first_leaf_ - 1 (0 unused)
  int first_leaf_ = 1;           ///< the index of the first leaf node (a power of two)
};

}  // namespace exactccd::scene
