// Triangle meshes moving over one time step, and their derived edges.
#pragma once

#include <array>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::scene {

using Triangle = std::array<int, 3>;
using Edge = std::array<int, 2>;  ///< vertex indices, ascending

/// A mesh whose vertices move linearly from positions_t0 to positions_t1 over the step.
struct MovingMesh {
  std::vector<Vec3> positions_t0, positions_t1;
  std::vector<Triangle> triangles;
};

/// The unique undirected edges of the triangles, each with ascending vertex indices, sorted.
std::vector<Edge> unique_edges(const std::vector<Triangle>& triangles);

/// Appends mesh b to mesh a (b's indices shifted by a's vertex count).
void append(MovingMesh& a, const MovingMesh& b);

}  // namespace exactccd::scene
