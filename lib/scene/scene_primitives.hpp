// The primitives of a public exactccd::Scene (exactccd/scene.hpp) and its broad-phase
// candidates, shared by the scene functions, the CLI and the scene benchmark.
#pragma once

#include <cstddef>
#include <vector>

#include "exactccd/scene.hpp"
#include "scene/broad_phase.hpp"

namespace exactccd::scene {

/// A scene's vertex-face vertices, its edges and its candidate pairs.
struct ScenePrimitives {
  /// Vertices referenced by a triangle, an extra edge or a point; ascending, no duplicates.
  std::vector<int> vertices;
  /// The triangles' unique edges and the extra edges, each ascending, sorted, no duplicates.
  std::vector<Edge> edges;
  /// {vertex, triangle} and {edge i, edge j} (indices into `edges`, i < j), pairs sharing a
  /// vertex index excluded; both lists sorted.
  Candidates candidates;
};

/// Throws std::invalid_argument naming `name`[i] when a position has a NaN or infinite
/// coordinate.
void require_finite_positions(const std::vector<Vec3>& positions, const char* name);

/// Throws std::invalid_argument when a triangle has an index outside [0, vertex_count) or a
/// repeated index.
void require_valid_triangles(const std::vector<Triangle>& triangles, std::size_t vertex_count);

/// Validates the scene (exactccd::validate) and computes its primitives and candidates.
ScenePrimitives scene_primitives(const Scene& scene);

/// The vertex-face query of vertex v against triangle t of the scene.
VertexFaceQuery vertex_face_query(const Scene& scene, int v, int t);

/// The edge-edge query of edges a and b of the scene.
EdgeEdgeQuery edge_edge_query(const Scene& scene, const Edge& a, const Edge& b);

}  // namespace exactccd::scene
