// exactccd: scene-level continuous collision detection over one time step.
//
// A scene is a set of vertices moving linearly from their positions at t = 0 to their positions
// at t = 1, with triangles, optional extra (codimensional) edges and optional isolated points
// over them. Its primitives:
// - the vertices of the scene: every vertex referenced by a triangle, an extra edge or a point
//   (vertices referenced by nothing take part in nothing);
// - its edges: the unique undirected edges of the triangles, and the extra edges;
// - its triangles.
// A vertex-face (VF) pair is a vertex and a triangle, an edge-edge (EE) pair two distinct edges.
// Pairs sharing a vertex index are never tested (a vertex against its own triangles, edges with
// a common endpoint): they touch by construction. Every other pair is decided exactly, as the
// primitive queries of ccd.hpp decide it, so the scene answers are exact too: a broad phase of
// swept boxes drops only pairs that cannot touch (its box test is exact), and a time of impact
// is the tightest double interval holding the exact time.
//
// All functions are thread-safe and keep no global state; they throw std::invalid_argument on a
// malformed scene (see validate()).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd {

/// Vertices moving linearly over one step, x(t) = positions_t0 + t (positions_t1 -
/// positions_t0) for t in [0, 1], and the primitives over them (indices are 0-based).
struct Scene {
  std::vector<Vec3> positions_t0;              ///< vertex positions at t = 0
  std::vector<Vec3> positions_t1;              ///< vertex positions at t = 1 (same size)
  std::vector<std::array<int, 3>> triangles;   ///< triangles (three distinct vertex indices)
  std::vector<std::array<int, 2>> edges;       ///< extra edges (codimensional), in EE and VF
  std::vector<int> points;                     ///< isolated points, VF vertices only
};

/// Options of the scene functions.
struct SceneOptions {
  /// Threads of the narrow phase; 0 means std::thread::hardware_concurrency(); at most 1024
  /// are used, and fewer when the system refuses to start more. The results do not depend
  /// on it.
  unsigned threads = 0;
};

/// Which kind of pair a Collision is.
enum class CollisionKind {
  vertex_face,  ///< a vertex and a triangle
  edge_edge,    ///< two edges
};

/// A colliding pair of primitives and its certified time of impact.
struct Collision {
  CollisionKind kind = CollisionKind::vertex_face;  ///< vertex-face or edge-edge
  int vertex = -1;               ///< vertex-face: the vertex (else -1)
  int triangle = -1;             ///< vertex-face: index into Scene::triangles (else -1)
  std::array<int, 2> edge_a{{-1, -1}};  ///< edge-edge: first edge, ascending vertex indices
  std::array<int, 2> edge_b{{-1, -1}};  ///< edge-edge: second edge, ascending; edge_a < edge_b
  TimeInterval toi;              ///< tightest double enclosure of the earliest contact time
};

/// Throws std::invalid_argument, with a message naming the offending element, when the scene
/// is malformed: positions_t0 and positions_t1 differ in size, a coordinate is NaN or infinite,
/// an index (of a triangle, edge or point) is out of range, or a triangle or edge repeats a
/// vertex index. Every other function calls it first.
void validate(const Scene& scene);

/// Every colliding pair of the scene with its time of impact: the vertex-face pairs sorted by
/// (vertex, triangle), then the edge-edge pairs sorted by (edge_a, edge_b). Pairs sharing a
/// vertex index are excluded. The narrow phase runs on options.threads threads; the result is
/// the same for any number of threads.
std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options = {});

/// The earliest time of impact over the scene (the tightest double interval holding the exact
/// earliest contact time of all pairs), or std::nullopt when no pair collides. Prunes by time:
/// once a contact with upper bound h is known, a pair is skipped when its primitives' boxes
/// over [0, h] (enclosed with interval arithmetic) do not overlap, and evaluation stops at a
/// contact at t = 0.
std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneOptions& options = {});

/// The earliest of the collisions' times of impact (ordered by lo, then hi), or std::nullopt
/// for an empty list: earliest_toi(find_collisions(s)) == earliest_toi(s).
std::optional<TimeInterval> earliest_toi(const std::vector<Collision>& collisions);

/// True iff no pair of the scene collides during the step; stops at the first collision found.
bool is_collision_free(const Scene& scene, const SceneOptions& options = {});

/// The largest step the motion can take without a collision, conservatively: 1 when the scene
/// is collision-free; otherwise, with [lo, hi] the earliest time of impact, the largest double
/// strictly below lo, so that the motion over [0, s] is collision-free exactly. A contact at
/// t = 0 (lo == 0) allows no step: the result is 0 (and 0 is then not itself collision-free
/// when the contact is exactly at t = 0).
double max_collision_free_step(const Scene& scene, const SceneOptions& options = {});

/// max_collision_free_step given the scene's earliest time of impact (std::nullopt: none).
double max_collision_free_step(const std::optional<TimeInterval>& earliest);

/// Exact static self-intersection check of a triangle mesh: true iff
/// - every two triangles with no vertex index in common are disjoint as closed triangles, and
/// - for every two triangles sharing exactly one vertex index v, the edge of each opposite v is
///   disjoint from the other closed triangle. For non-degenerate triangles this holds iff the
///   two meet only at v's position; a degenerate triangle whose vertex v lies on its opposite
///   edge counts as meeting its neighbours there.
/// Triangles sharing two or three vertex indices are not checked (they meet along the shared
/// edge; a coplanar fold-over beyond it is not reported). Degenerate triangles (collinear or
/// coincident positions) are their hulls. Throws std::invalid_argument on non-finite
/// coordinates, out-of-range or repeated indices.
bool intersection_free(const std::vector<Vec3>& positions,
                       const std::vector<std::array<int, 3>>& triangles);

}  // namespace exactccd
