// The CCD queries of one step of a moving mesh: its broad-phase candidates as primitive queries.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// Vertex-face query of candidate {vertex, triangle}.
VertexFaceQuery vertex_face_query(const MovingMesh& mesh, int vertex, int triangle);

/// Edge-edge query of candidate {edge i, edge j} (edges from unique_edges()).
EdgeEdgeQuery edge_edge_query(const MovingMesh& mesh, const Edge& a, const Edge& b);

/// Every candidate of the step as queries, in the candidates' order.
struct StepQueries {
  std::vector<VertexFaceQuery> vertex_face;
  std::vector<EdgeEdgeQuery> edge_edge;
};
StepQueries step_queries(const MovingMesh& mesh);

/// Which of the queries to keep, given which collide (collides[i] for query i): all of them
/// when max_queries is 0 or at least their number; otherwise every colliding one (evenly spaced
/// ones if more than max_queries collide), then evenly spaced non-colliding ones up to
/// max_queries. Ascending indices, so the kept queries stay in candidate order. Deterministic.
std::vector<std::size_t> select_queries(const std::vector<bool>& collides, std::size_t max_queries);

}  // namespace exactccd::scene
