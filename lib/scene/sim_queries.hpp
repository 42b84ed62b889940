// The CCD queries of one step of a moving mesh: its broad-phase candidates as primitive queries.
#pragma once

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

}  // namespace exactccd::scene
