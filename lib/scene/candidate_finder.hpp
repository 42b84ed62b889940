// The broad phase's candidate pairs from bounding volume hierarchies (box_tree.hpp) over the
// triangles, the edges and the isolated points, in parallel, refitted when only the vertex
// boxes change (exactccd::SceneBroadPhase reuses one across calls).
#pragma once

#include <vector>

#include "scene/box_tree.hpp"
#include "scene/broad_phase.hpp"

namespace exactccd::scene {

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

  /// Every pair of find_candidates() for the boxes of the last fit(): the pairs whose boxes
  /// overlap (closed, exact) and which share no vertex; sorted, without duplicates. Each pair
  /// is found once by a traversal of two trees (or of one against itself). Up to `threads`
  /// threads; the result does not depend on them.
  Candidates candidates(unsigned threads) const;

 private:
  const std::vector<Triangle>& triangles_;
  const std::vector<Edge>& edges_;
  const std::vector<int>& vertices_;
  const std::vector<int>& points_;
  /// The boxes of the last fit(): of a vertex, and of a triangle, an edge, an isolated point
  /// (hulls of their vertices' boxes, computed when needed rather than stored).
  std::vector<Box> vertex_boxes_;
  Box triangle_box(std::size_t t) const;
  Box edge_box(std::size_t e) const;
  Box point_box(std::size_t i) const { return vertex_boxes_[static_cast<std::size_t>(points_[i])]; }
  /// vertex_tree_: over `vertices` (empty without triangles), for the vertex-face pairs.
  BoxTree vertex_tree_, triangle_tree_, edge_tree_, point_tree_;
  bool built_ = false;
};

}  // namespace exactccd::scene
