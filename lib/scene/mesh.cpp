#include "scene/mesh.hpp"

#include <algorithm>

namespace exactccd::scene {

std::vector<Edge> unique_edges(const std::vector<Triangle>& triangles) {
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

void append(MovingMesh& a, const MovingMesh& b) {
  const int offset = static_cast<int>(a.positions_t0.size());
  a.positions_t0.insert(a.positions_t0.end(), b.positions_t0.begin(), b.positions_t0.end());
  a.positions_t1.insert(a.positions_t1.end(), b.positions_t1.begin(), b.positions_t1.end());
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace exactccd::scene
