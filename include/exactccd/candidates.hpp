// exactccd: the narrow phase over candidate pairs from the caller's own broad phase.
//
// A simulator that keeps its own broad phase (a BVH, a spatial hash) hands its candidate list
// to these functions, often many times per step: a line search (e.g. IPC's) re-checks the same
// candidates with a shorter step, i.e. with other positions_t1 or a smaller tmax. Build the
// CandidateSet once and pass it to every call; the positions are taken per call.
//
// Every candidate is decided exactly, as the primitive queries of ccd.hpp decide it with
// CcdParams{min_distance, tmax}, by the same narrow phase as the scene functions of scene.hpp
// (same threads, same early exit and time pruning in earliest_toi): given the candidates the
// scene's own broad phase forms for the same min_distance and tmax, the answers are those of
// find_collisions / earliest_toi / max_collision_free_step of the Scene. A broad phase must keep
// every pair that can come within min_distance during [0, tmax] (e.g. boxes grown by d): the
// batch functions answer for the candidates given, and a pair left out is not seen. Every kind is tested for every d >= 0, including
// point-edge and point-point at d = 0 (in 3D a point meeting a segment or another point), since
// the caller asked for them.
//
// A candidate whose two sides share a vertex index (a vertex against its own triangle, edges
// with a common endpoint, a point against itself) is rejected with std::invalid_argument, as is
// a triangle or edge repeating a vertex index. Such a pair is within distance 0 at t = 0 by
// construction: testing it would report a collision at t = 0 and allow no step at all, silently
// stalling the simulation, so it is an error in the caller's broad phase (the scene functions
// never form such pairs either). Distinct indices at the same position are tested as usual.
//
// All functions are thread-safe, keep no global state, and leave the caller's floating-point
// environment unchanged (see ccd.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "exactccd/scene.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// Candidate pairs of primitives, by vertex index into the positions (0-based). Each kind's list
/// is in the caller's order; results name a candidate by its kind and its position in that list.
struct CandidateSet {
  std::vector<std::array<int, 4>> vertex_face;  ///< {vertex, a, b, c}: a vertex and a triangle (a, b, c)
  std::vector<std::array<int, 4>> edge_edge;    ///< {a0, a1, b0, b1}: edges (a0, a1) and (b0, b1)
  std::vector<std::array<int, 3>> point_edge;   ///< {p, a, b}: a point and an edge (a, b)
  std::vector<std::array<int, 2>> point_point;  ///< {p, q}: two points

  /// The number of candidates of every kind.
  std::size_t size() const {
    return vertex_face.size() + edge_edge.size() + point_edge.size() + point_point.size();
  }
};

/// A colliding candidate: its kind, its position in that kind's list of the CandidateSet, and
/// its certified time of impact (the tightest double interval holding the earliest t in
/// [0, tmax] at which its primitives are within distance <= min_distance).
struct CandidateCollision {
  CollisionKind kind = CollisionKind::vertex_face;  ///< which list of the CandidateSet
  std::size_t index = 0;                            ///< the position in that list
  TimeInterval toi;                                 ///< tightest double enclosure of the time of impact
};

/// The CandidateSet of candidates given by element index, as many simulators keep them:
/// vertex_face {vertex, face} (face indexes `faces`), edge_edge {edge, edge} (indexing
/// `edges`), point_edge {vertex, edge}, point_point {vertex, vertex}; each list keeps its order.
/// Throws std::invalid_argument, naming the candidate, when a face or edge index is out of
/// range (the vertex indices are checked by the functions below, against the positions).
CandidateSet candidates_from_elements(const std::vector<std::array<int, 3>>& faces,
                                      const std::vector<std::array<int, 2>>& edges,
                                      const std::vector<std::array<int, 2>>& vertex_face,
                                      const std::vector<std::array<int, 2>>& edge_edge,
                                      const std::vector<std::array<int, 2>>& point_edge = {},
                                      const std::vector<std::array<int, 2>>& point_point = {});

/// Throws std::invalid_argument, with a message naming the offending element, when the input is
/// malformed: positions_t0 and positions_t1 differ in size or have more than INT_MAX vertices, a
/// coordinate is NaN or infinite (positions_t0[i]), a candidate has a vertex index out of range
/// (e.g. "edge_edge candidate 7 has vertex index 12, out of range [0, 10)"), or a candidate
/// repeats a vertex index (its sides share a vertex, or its triangle or edge is degenerate).
/// Every function below calls it first (O(n + m) per call).
void validate(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
              const CandidateSet& candidates);

/// Every colliding candidate with its time of impact (the earliest t in [0, tmax] at which its
/// primitives are within distance <= d, d = options.min_distance, tmax = options.tmax), sorted
/// by kind in CollisionKind order, then by position in the kind's list. Runs on options.threads
/// threads; the result is the same for any number of threads. Throws std::invalid_argument on
/// malformed input (validate) or options (validate(const SceneOptions&)).
std::vector<CandidateCollision> find_collisions(const std::vector<Vec3>& positions_t0,
                                                const std::vector<Vec3>& positions_t1,
                                                const CandidateSet& candidates, const SceneOptions& options = {});

/// The earliest time of impact over the candidates (the tightest double interval holding the
/// exact earliest time in [0, tmax] at which some candidate is within distance <= d), or
/// std::nullopt when none collides; equal to earliest_toi(find_collisions(...)) but cheaper:
/// prunes by time as earliest_toi(const Scene&, const SceneOptions&) does (a candidate is
/// skipped when its boxes over [0, h] do not overlap, h the earliest upper bound found so far)
/// and stops at a collision at t = 0. Throws as find_collisions.
std::optional<TimeInterval> earliest_toi(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                                         const CandidateSet& candidates, const SceneOptions& options = {});

/// The earliest of the collisions' times of impact (ordered by lo, then hi), or std::nullopt
/// for an empty list.
std::optional<TimeInterval> earliest_toi(const std::vector<CandidateCollision>& collisions);

/// True iff no candidate collides (comes within distance <= d at some t in [0, tmax]); stops at
/// the first collision found. Throws as find_collisions.
bool is_collision_free(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                       const CandidateSet& candidates, const SceneOptions& options = {});

/// The largest step s <= tmax over which the motion keeps every candidate at distance > d, as
/// max_collision_free_step(const Scene&, const SceneOptions&): tmax when no candidate collides
/// in [0, tmax]; otherwise the largest double strictly below the earliest time of impact's lo
/// (0 for a collision at t = 0). Throws as find_collisions.
double max_collision_free_step(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                               const CandidateSet& candidates, const SceneOptions& options = {});

}  // namespace exactccd
