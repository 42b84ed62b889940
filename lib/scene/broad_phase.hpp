// Broad phase over one time step: swept (space-time) axis-aligned boxes and sort-and-sweep.
//
// The box of a moving vertex is the box of its two positions; of an edge or triangle, the box
// of all its vertices' positions at t0 and t1. A linearly moving point stays on the segment
// between its positions, so every primitive stays in its box for the whole step, and two
// primitives that touch at some t have overlapping boxes. The bounds are input coordinates
// themselves (min and max involve no rounding) and overlap is tested with <=, so the test is
// exact: no margin is needed and no touching pair is dropped, not even one that touches only
// on a box face. (A conservative margin is what a broad phase needs when its bounds are
// computed, e.g. positions at intermediate times or a minimum separation added: a rounded
// bound can land inside the true extent and drop a colliding pair, which CCD then never sees.
// Such an extension must round its bounds outwards: inflated() does so for a minimum
// separation d, add_vertex_until() in time_bounds.hpp for boxes over [0, h].)
#pragma once

#include <array>
#include <vector>

#include "exactccd/scene.hpp"
#include "scene/mesh.hpp"

namespace exactccd::scene {

/// An axis-aligned box [lo, hi] (closed).
struct Box {
  std::array<double, 3> lo, hi;
};

/// Candidate pairs of one step: (vertex, triangle) and (edge, edge) by index into the mesh's
/// vertices, triangles and unique_edges(), and (point, edge), (point, point) of isolated
/// points. Pairs sharing a vertex are excluded (a vertex against its own triangles, edges with
/// a common endpoint). Sorted, without duplicates. (The public exactccd::SceneCandidates.)
using Candidates = exactccd::SceneCandidates;

/// The smallest box holding both boxes (exact: min and max).
inline Box hull(const Box& a, const Box& b) {
  Box h;
  for (int k = 0; k < 3; ++k) {
    h.lo[k] = a.lo[k] < b.lo[k] ? a.lo[k] : b.lo[k];
    h.hi[k] = a.hi[k] > b.hi[k] ? a.hi[k] : b.hi[k];
  }
  return h;
}

/// `box` grown by d >= 0 on every side with outward rounding: it holds every point whose
/// distance to the box is at most d. Two primitives within distance d of each other have
/// overlapping inflated boxes. d = 0 returns the box itself.
Box inflated(const Box& box, double d);

/// The swept box of a set of vertices of the mesh.
Box swept_box(const MovingMesh& mesh, const int* vertices, int count);

/// The swept box of a set of vertices moving from positions_t0 to positions_t1.
Box swept_box(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
              const int* vertices, int count);

/// Whether two closed boxes overlap (exact). Inline: the broad phase's innermost test. The six
/// comparisons are combined with | rather than || (the same value, no short circuit): the
/// outcome of each is hard to predict in tree traversals, and branches on them cost more than
/// evaluating all six.
inline bool overlap(const Box& a, const Box& b) {
  const auto apart = [](double hi, double lo) { return static_cast<int>(hi < lo); };
  return (apart(a.hi[0], b.lo[0]) | apart(b.hi[0], a.lo[0]) | apart(a.hi[1], b.lo[1]) | apart(b.hi[1], a.lo[1]) |
          apart(a.hi[2], b.lo[2]) | apart(b.hi[2], a.lo[2])) == 0;
}

/// All candidate pairs whose swept boxes overlap (sort-and-sweep along the axis of largest
/// extent, within strips along the second: broad_phase.cpp); every vertex of the
/// mesh is a vertex-face candidate.
Candidates find_candidates(const MovingMesh& mesh, const std::vector<Edge>& edges);

/// As above for vertices moving from positions_t0 to positions_t1, with only the listed
/// `vertices` (indices into the positions, ascending) as vertex-face candidates: the pairs
/// report vertex indices, not positions in the list.
Candidates find_candidates(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                           const std::vector<Triangle>& triangles, const std::vector<Edge>& edges,
                           const std::vector<int>& vertices);

/// The candidates given the box of every vertex (indexed by vertex; the box of a triangle or
/// edge is the hull of its vertices' boxes): {vertex, triangle} for the `vertices` (ascending),
/// {edge i, edge j}, and, for the isolated `points` (ascending, distinct, on no edge), {point,
/// edge} and {point p, point q}; every pair whose boxes overlap and which shares no vertex.
/// Bounding volume hierarchies (BroadPhaseTrees, candidate_finder.hpp) on up to `threads`
/// threads; the result does not depend on `threads`.
Candidates find_candidates(const std::vector<Box>& vertex_boxes, const std::vector<Triangle>& triangles,
                           const std::vector<Edge>& edges, const std::vector<int>& vertices,
                           const std::vector<int>& points, unsigned threads = 1);

/// The same candidates as find_candidates(vertex_boxes, ...) by the serial sort-and-sweep the
/// scene functions used before the bounding volume hierarchies: the reference of the tests and
/// the benchmark.
Candidates sweep_candidates(const std::vector<Box>& vertex_boxes, const std::vector<Triangle>& triangles,
                            const std::vector<Edge>& edges, const std::vector<int>& vertices,
                            const std::vector<int>& points);

/// Pairs {i, j}, i < j, of triangles whose boxes over `positions` (a static mesh) overlap,
/// adjacent triangles included; sorted.
std::vector<std::array<int, 2>> overlapping_triangle_pairs(const std::vector<Vec3>& positions,
                                                           const std::vector<Triangle>& triangles);

}  // namespace exactccd::scene
