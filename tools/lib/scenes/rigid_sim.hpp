// Simulation-like rigid query sets (issue 24): a few tumbling rigid bodies over many steps, their
// candidate pairs between different bodies from a broad phase of certified swept boxes
// (rigid/swept_box.hpp), as rigid queries. The bodies move on prescribed paths (constant linear
// acceleration, constant spatial angular velocity; no collision response), so they pass through
// each other: the steps around the first contacts hold the colliding candidates. Poses are
// rounded to doubles; each step's pose pair is a query's motion (q1's sign chosen so that
// q0 . q1 > 0, the short arc).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "exactccd/rigid.hpp"

namespace exactccd::rigid_sim {

/// A rigid body: a triangle mesh in body coordinates.
struct Body {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

/// Bodies and their poses at every step: poses[k][b] is body b's pose at the start of step k
/// (step k runs from poses[k] to poses[k + 1]).
struct Scene {
  std::string name;
  std::vector<Body> bodies;
  std::vector<std::vector<RigidPose>> poses;
};

/// A box (edge length 1) tumbling onto a static plane (a 6 x 6 grid of squares, 72 triangles).
Scene box_on_plane();
/// Two interlocked rings (polygonal tori, 24 x 6 quads each), one turning slowly, the other
/// tumbling and drifting until their tubes meet.
Scene interlocked_rings();
/// Both scenes.
std::vector<Scene> all_scenes();

/// The candidate pairs of one step as rigid queries: every vertex of one body against every
/// triangle of another, and every edge (unique per body) of one body against every edge of a
/// later body, whose swept boxes over the step overlap.
struct StepQueries {
  std::vector<RigidVertexFaceQuery> vertex_face;
  std::vector<RigidEdgeEdgeQuery> edge_edge;
};
StepQueries step_queries(const Scene& scene, std::size_t step);

/// The unique edges of a triangle mesh (each ascending, sorted).
std::vector<std::array<int, 2>> unique_edges(const Body& body);

}  // namespace exactccd::rigid_sim
