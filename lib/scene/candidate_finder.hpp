// The broad phase's candidate pairs from bounding volume hierarchies (box_tree.hpp) over the
// triangles, the edges and the isolated points, in parallel, refitted when only the vertex
// boxes change (exactccd::SceneBroadPhase reuses one across calls).
#pragma once

#include <array>
#include <vector>

#include "scene/box_tree.hpp"
#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// A candidate pair as the broad phase finds it: its kind and its two indices, as in
/// SceneCandidates ({vertex, triangle}, {edge i, edge j} with i < j into the edges, {point,
/// edge}, {point p, point q} with p < q).
struct FoundPair {
  CollisionKind kind = CollisionKind::vertex_face;  ///< which kind of pair
  std::array<int, 2> ij{};                          ///< its two indices
};

/// A piece of the broad phase's work: the pairs of one kind below one node pair of its trees.
struct PairTask {
  CollisionKind kind = CollisionKind::vertex_face;  ///< which kind (which two trees)
  BoxTree::NodePair nodes{};                        ///< the node pair (BoxTree::pair_tasks)
};

/// Trees over one topology (triangles, edges, vertex-face vertices, isolated points, as in
/// find_candidates; kept by reference: they must outlive this object and not change).
class BroadPhaseTrees {
 public:
  /// Keeps references to the topology; fit() must be called before candidates().
  BroadPhaseTrees(const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                  const std::vector<int>& vertices, const std::vector<int>& points);

  /// Takes the box of every vertex (indexed by vertex): the first call orders the trees by the
  /// boxes and fits them, later calls refit them in the first call's order (no rebuild). Up to
  /// `threads` threads. Throws std::invalid_argument when a later call has another vertex count.
  void fit(std::vector<Box> vertex_boxes, unsigned threads);

  /// The vertex boxes of the last fit(), for a caller that overwrites them in place (same
  /// count) before refit(): a line search's refit then allocates nothing.
  std::vector<Box>& vertex_boxes() { return vertex_boxes_; }

  /// Refits the trees, after fit(), to the vertex boxes as they are now (vertex_boxes()), in
  /// the first fit's order, on up to `threads` threads; allocates nothing.
  void refit(unsigned threads);

  /// Every pair of find_candidates() for the boxes of the last fit(): the pairs whose boxes
  /// overlap (closed, exact) and which share no vertex; sorted, without duplicates. Each pair
  /// is found once by a traversal of two trees (or of one against itself). Up to `threads`
  /// threads; the result does not depend on them.
  Candidates candidates(unsigned threads) const;

  /// Independent pieces of work that together find every pair of candidates() exactly once
  /// (every kind's node pairs, about 32 per thread and kind when threads > 1, one per kind
  /// otherwise); for the streamed broad phase (pair_stream.hpp).
  std::vector<PairTask> pair_tasks(unsigned threads) const;

  /// The same tasks, written into `tasks` (cleared first) with `nodes` and `scratch` for each
  /// kind's node pairs: kept by a caller that streams repeatedly, they allocate nothing once
  /// grown.
  void pair_tasks(unsigned threads, std::vector<PairTask>& tasks, std::vector<BoxTree::NodePair>& nodes,
                  std::vector<BoxTree::NodePair>& scratch) const;

  /// Calls report(FoundPair) for every pair of candidates() below the task (in no particular
  /// order: the trees' pairs whose exact double boxes overlap and which share no vertex) until
  /// report returns false; returns false when it did.
  template <class Report>
  bool visit(const PairTask& task, Report&& report) const {
    const CollisionKind kind = task.kind;
    switch (kind) {
      case CollisionKind::vertex_face:
        return vertex_tree_.pairs_from(triangle_tree_, task.nodes, [&](int i, int t) {
          const int v = vertices_[static_cast<std::size_t>(i)];
          const Triangle& tri = triangles_[static_cast<std::size_t>(t)];
          return tri[0] == v || tri[1] == v || tri[2] == v ||
                 !overlap(vertex_boxes_[static_cast<std::size_t>(v)], triangle_box(static_cast<std::size_t>(t))) ||
                 report(FoundPair{kind, {{v, t}}});
        });
      case CollisionKind::edge_edge:
        return edge_tree_.pairs_from(edge_tree_, task.nodes, [&](int i, int j) {
          const Edge& a = edges_[static_cast<std::size_t>(i)];
          const Edge& b = edges_[static_cast<std::size_t>(j)];
          const bool share = a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
          return share || !overlap(edge_box(static_cast<std::size_t>(i)), edge_box(static_cast<std::size_t>(j))) ||
                 report(FoundPair{kind, {{i, j}}});  // i < j
        });
      case CollisionKind::point_edge:  // isolated points are on no edge: no shared vertex
        return point_tree_.pairs_from(edge_tree_, task.nodes, [&](int i, int e) {
          return !overlap(point_box(static_cast<std::size_t>(i)), edge_box(static_cast<std::size_t>(e))) ||
                 report(FoundPair{kind, {{points_[static_cast<std::size_t>(i)], e}}});
        });
      case CollisionKind::point_point:  // points ascending: i < j gives p < q
        return point_tree_.pairs_from(point_tree_, task.nodes, [&](int i, int j) {
          return !overlap(point_box(static_cast<std::size_t>(i)), point_box(static_cast<std::size_t>(j))) ||
                 report(FoundPair{kind, {{points_[static_cast<std::size_t>(i)], points_[static_cast<std::size_t>(j)]}}});
        });
    }
    return true;
  }

 private:
  const std::vector<Triangle>& triangles_;
  const std::vector<Edge>& edges_;
  const std::vector<int>& vertices_;
  const std::vector<int>& points_;
  /// The boxes of the last fit(): of a vertex, and of a triangle, an edge, an isolated point
  /// (hulls of their vertices' boxes, computed when needed rather than stored).
  std::vector<Box> vertex_boxes_;
  Box triangle_box(std::size_t t) const {
    const Triangle& tri = triangles_[t];
    return hull(hull(vertex_boxes_[static_cast<std::size_t>(tri[0])], vertex_boxes_[static_cast<std::size_t>(tri[1])]),
                vertex_boxes_[static_cast<std::size_t>(tri[2])]);
  }
  Box edge_box(std::size_t e) const {
    return hull(vertex_boxes_[static_cast<std::size_t>(edges_[e][0])], vertex_boxes_[static_cast<std::size_t>(edges_[e][1])]);
  }
  Box point_box(std::size_t i) const { return vertex_boxes_[static_cast<std::size_t>(points_[i])]; }
  /// The float boxes of the vertices (float_box of vertex_boxes_), kept between fits.
  std::vector<FloatBox> float_boxes_;
  /// Builds or refits the four trees from vertex_boxes_.
  void fit_trees(unsigned threads);
  /// Builds (first fit) or refits one tree (0: edges, 1: triangles, 2: vertices, 3: points)
  /// from the vertices' float boxes, on up to `threads` threads.
  void fit_tree(int which, const std::vector<FloatBox>& fboxes, unsigned threads);
  /// vertex_tree_: over `vertices` (empty without triangles), for the vertex-face pairs.
  BoxTree vertex_tree_, triangle_tree_, edge_tree_, point_tree_;
  bool built_ = false;
};

}  // namespace exactccd::scene
