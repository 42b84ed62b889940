#include "scene/sim_queries.hpp"

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

}  // namespace exactccd::scene
