#include "scene/mesh.hpp"

#include <algorithm>

namespace exactccd::scene {

namespace {

/// unique_edges by sorting every triangle edge (any indices).
std::vector<Edge> sorted_unique_edges(const std::vector<Triangle>& triangles) {
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

// Indices in [0, n): a counting sort by the lower index (the edges' second indices bucketed by
// their first), then each bucket (a vertex's few higher neighbours) sorted and deduplicated in
// place: linear in the triangles and the vertices, the same list as sorting every edge.
// Used when the highest index is below 4 T + 16 (T triangles): the two per-index arrays then
// hold at most 4 T + 17 ints each, a small multiple of the 3 T triangle edges bucketed anyway;
// a mesh whose triangles use every vertex has at most 3 T of them, so this admits every such
// mesh with room for some unused vertices. Sparser indices (or negative ones) take the general
// sort: the same list, any index range.
std::vector<Edge> unique_edges(const std::vector<Triangle>& triangles) {
  int lowest = 0, highest = -1;
  for (const Triangle& t : triangles)
    for (const int v : t) {
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
  if (lowest < 0 || static_cast<std::size_t>(highest) >= 4 * triangles.size() + 16) return sorted_unique_edges(triangles);
  const std::size_t n = static_cast<std::size_t>(highest) + 1;
  std::vector<int> start(n + 1, 0);
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) ++start[static_cast<std::size_t>(std::min(t[i], t[(i + 1) % 3])) + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> higher(static_cast<std::size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      higher[static_cast<std::size_t>(fill[static_cast<std::size_t>(std::min(a, b))]++)] = std::max(a, b);
    }
  std::vector<Edge> edges;
  edges.reserve(higher.size() / 2 + 1);
  for (std::size_t v = 0; v < n; ++v) {
    const auto begin = higher.begin() + start[v], end = higher.begin() + start[v + 1];
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it)
      if (it == begin || *it != *(it - 1)) edges.push_back({static_cast<int>(v), *it});
  }
  return edges;
}

void append(MovingMesh& a, const MovingMesh& b) {
  const int offset = static_cast<int>(a.positions_t0.size());
  a.positions_t0.insert(a.positions_t0.end(), b.positions_t0.begin(), b.positions_t0.end());
  a.positions_t1.insert(a.positions_t1.end(), b.positions_t1.begin(), b.positions_t1.end());
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace exactccd::scene
