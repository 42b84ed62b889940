// A uniform grid broad phase, measured against the library's bounding volume hierarchies and
// the sort-and-sweep for issue 23's choice (docs/scene.md, "Streamed step": BVH, sort and sweep
// or uniform grid). Not part of the installed library: the benchmark's alternative, tested to
// find exactly the library's candidates (tests/tools/test_uniform_grid.cpp).
//
// Cells are cubes of side h over the bounding box of every primitive's box. Each primitive
// (triangle, edge, vertex-face vertex) is listed in every cell its box meets, as (cell, index)
// entries sorted by cell. Two primitives are tested in each cell both are listed in, and a pair
// whose boxes overlap is reported only in the cell holding the corner max(lo_a, lo_b) of the
// boxes' intersection, so exactly once. Exact: the cell of a coordinate, floor((x - origin) / h)
// computed in doubles and clamped to the grid, is a monotone function of x (each rounded step
// is), so two overlapping boxes are both listed in the cell of that corner (every coordinate of
// the corner lies between each box's bounds); the pair test itself is the exact box test on
// the double boxes (hulls of the vertex boxes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/broad_phase.hpp"
#include "scene/candidate_finder.hpp"

namespace exactccd::tools {

/// The uniform grid's pairs of one step: built from the vertex boxes and the topology (kept by
/// reference), cell side `cell` (> 0; a multiple of the primitives' typical size).
class UniformGrid {
 public:
  /// Lists the primitives in the grid's cells (vertex_boxes indexed by vertex; `vertices` the
  /// vertex-face vertices, as BroadPhaseTrees; no isolated points).
  UniformGrid(const std::vector<scene::Box>& vertex_boxes, const std::vector<scene::Triangle>& triangles,
              const std::vector<scene::Edge>& edges, const std::vector<int>& vertices, double cell);

  /// Calls report(FoundPair) for every vertex-face and edge-edge candidate (the pairs whose
  /// boxes overlap and which share no vertex: BroadPhaseTrees::visit's pairs), each once, in
  /// no particular order; returns the number reported.
  template <class Report>
  std::size_t pairs(Report&& report) const;

  /// The mean of the largest extent of the edges' boxes: the grid's cell side for a factor 1.
  static double mean_edge_extent(const std::vector<scene::Box>& vertex_boxes, const std::vector<scene::Edge>& edges);

 private:
  using Entry = std::pair<std::uint64_t, int>;  // (cell key, primitive)
  std::array<std::int64_t, 3> cell_of(const std::array<double, 3>& x) const;
  std::uint64_t key(const std::array<std::int64_t, 3>& c) const;
  template <class BoxOf>
  std::vector<Entry> entries(std::size_t n, BoxOf&& box_of) const;
  /// Whether the cell `key` is where boxes a and b report their pair (max of the lower bounds).
  bool owns(std::uint64_t cell_key, const scene::Box& a, const scene::Box& b) const;
  scene::Box triangle_box(std::size_t t) const;
  scene::Box edge_box(std::size_t e) const;

  const std::vector<scene::Box>& vertex_boxes_;
  const std::vector<scene::Triangle>& triangles_;
  const std::vector<scene::Edge>& edges_;
  const std::vector<int>& vertices_;
  std::array<double, 3> origin_{};
  double inverse_cell_ = 1;
  std::array<std::int64_t, 3> cells_{{1, 1, 1}};  // cells per axis
  std::vector<Entry> triangle_cells_, edge_cells_, vertex_cells_;
  std::vector<scene::Box> triangle_boxes_, edge_boxes_;  // hulls of their vertices' boxes
};

template <class Report>
std::size_t UniformGrid::pairs(Report&& report) const {
  std::size_t found = 0;
  // Edge-edge: every pair of edges listed in one cell.
  for (std::size_t begin = 0; begin < edge_cells_.size();) {
    std::size_t end = begin + 1;
    while (end < edge_cells_.size() && edge_cells_[end].first == edge_cells_[begin].first) ++end;
    for (std::size_t x = begin; x < end; ++x) {
      const int i = edge_cells_[x].second;
      const scene::Edge& a = edges_[static_cast<std::size_t>(i)];
      const scene::Box& box_a = edge_boxes_[static_cast<std::size_t>(i)];
      for (std::size_t y = x + 1; y < end; ++y) {
        const int j = edge_cells_[y].second;
        const scene::Edge& b = edges_[static_cast<std::size_t>(j)];
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
        const scene::Box& box_b = edge_boxes_[static_cast<std::size_t>(j)];
        if (!scene::overlap(box_a, box_b) || !owns(edge_cells_[begin].first, box_a, box_b)) continue;
        report(scene::FoundPair{CollisionKind::edge_edge, {{i < j ? i : j, i < j ? j : i}}});
        ++found;
      }
    }
    begin = end;
  }
  // Vertex-face: the vertices and the triangles listed in one cell (both lists sorted by cell).
  std::size_t t = 0;
  for (std::size_t begin = 0; begin < vertex_cells_.size();) {
    const std::uint64_t cell = vertex_cells_[begin].first;
    std::size_t end = begin + 1;
    while (end < vertex_cells_.size() && vertex_cells_[end].first == cell) ++end;
    while (t < triangle_cells_.size() && triangle_cells_[t].first < cell) ++t;
    for (std::size_t u = t; u < triangle_cells_.size() && triangle_cells_[u].first == cell; ++u) {
      const int tri = triangle_cells_[u].second;
      const scene::Triangle& corners = triangles_[static_cast<std::size_t>(tri)];
      const scene::Box& box_t = triangle_boxes_[static_cast<std::size_t>(tri)];
      for (std::size_t x = begin; x < end; ++x) {
        const int v = vertices_[static_cast<std::size_t>(vertex_cells_[x].second)];
        if (corners[0] == v || corners[1] == v || corners[2] == v) continue;
        const scene::Box& box_v = vertex_boxes_[static_cast<std::size_t>(v)];
        if (!scene::overlap(box_v, box_t) || !owns(cell, box_v, box_t)) continue;
        report(scene::FoundPair{CollisionKind::vertex_face, {{v, tri}}});
        ++found;
      }
    }
    begin = end;
  }
  return found;
}

}  // namespace exactccd::tools
