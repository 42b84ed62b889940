#include "scenes/sim_queries.hpp"

#include <algorithm>

namespace exactccd::scene {

VertexFaceQuery vertex_face_query(const MovingMesh& m, int v, int t) {
  const Triangle& f = m.triangles[t];
  return {m.positions_t0[v],    m.positions_t0[f[0]], m.positions_t0[f[1]], m.positions_t0[f[2]],
          m.positions_t1[v],    m.positions_t1[f[0]], m.positions_t1[f[1]], m.positions_t1[f[2]]};
}

EdgeEdgeQuery edge_edge_query(const MovingMesh& m, const Edge& a, const Edge& b) {
  return {m.positions_t0[a[0]], m.positions_t0[a[1]], m.positions_t0[b[0]], m.positions_t0[b[1]],
          m.positions_t1[a[0]], m.positions_t1[a[1]], m.positions_t1[b[0]], m.positions_t1[b[1]]};
}

StepQueries step_queries(const MovingMesh& mesh) {
  const std::vector<Edge> edges = unique_edges(mesh.triangles);
  const Candidates c = find_candidates(mesh, edges);
  StepQueries q;
  q.vertex_face.reserve(c.vertex_face.size());
  for (const auto& [v, t] : c.vertex_face) q.vertex_face.push_back(vertex_face_query(mesh, v, t));
  q.edge_edge.reserve(c.edge_edge.size());
  for (const auto& [i, j] : c.edge_edge) q.edge_edge.push_back(edge_edge_query(mesh, edges[i], edges[j]));
  return q;
}

namespace {

/// Appends `count` evenly spaced elements of `from` (from[k * n / count], k < count <= n).
void take_evenly(const std::vector<std::size_t>& from, std::size_t count, std::vector<std::size_t>& to) {
  const std::size_t n = from.size();
  for (std::size_t k = 0; k < count; ++k) to.push_back(from[k * n / count]);
}

}  // namespace

std::vector<std::size_t> select_queries(const std::vector<bool>& collides, std::size_t max_queries) {
  const std::size_t n = collides.size();
  std::vector<std::size_t> positive, negative, kept;
  for (std::size_t i = 0; i < n; ++i) (collides[i] ? positive : negative).push_back(i);
  if (max_queries == 0 || max_queries >= n) {
    kept.resize(n);
    for (std::size_t i = 0; i < n; ++i) kept[i] = i;
    return kept;
  }
  take_evenly(positive, std::min(positive.size(), max_queries), kept);
  take_evenly(negative, max_queries - kept.size(), kept);
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace exactccd::scene
