// The narrow phase over the caller's own candidate pairs (exactccd/candidates.hpp): the
// CandidateSet as a range of the shared narrow phase (scene/narrow_phase.hpp), the one the
// scene functions run over their broad phase's candidates.
#include "exactccd/candidates.hpp"

#include <climits>
#include <stdexcept>
#include <string>

#include "filter/fp_environment.hpp"
#include "scene/narrow_phase.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"

namespace exactccd {
namespace {

using scene::PairSides;

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("exactccd candidates: " + what);
}

/// The kinds in CollisionKind order (the order of the CandidateSet's lists and of the results).
constexpr std::array<CollisionKind, 4> kKinds{CollisionKind::vertex_face, CollisionKind::edge_edge,
                                              CollisionKind::point_edge, CollisionKind::point_point};
/// The lists' names, as in the messages and the Python keywords.
constexpr std::array<const char*, 4> kListNames{"vertex_face", "edge_edge", "point_edge", "point_point"};

/// Candidate `row` of a list whose rows are N vertex indices, the first `first` of them one side
/// and the others the other side ({vertex | a b c}, {a0 a1 | b0 b1}, {p | a b}, {p | q}), as a
/// pair of sides.
template <std::size_t N>
PairSides sides_of(CollisionKind kind, const std::array<int, N>& row, int first) {
  PairSides r;
  r.kind = kind;
  for (int i = 0; i < static_cast<int>(N); ++i) {
    scene::Side& s = r.side[i < first ? 0 : 1];
    s.v[static_cast<std::size_t>(s.n++)] = row[static_cast<std::size_t>(i)];
  }
  return r;
}

/// The size of side 0 of each kind's rows.
constexpr std::array<int, 4> kFirstSide{1, 2, 1, 1};

/// Checks list `list` (kKinds order) of N-index rows against n vertices (messages built only on
/// failure: this runs on every call).
template <std::size_t N>
void require_valid_rows(const std::vector<std::array<int, N>>& rows, std::size_t list, std::size_t n) {
  const auto which = [&](std::size_t i) { return std::string(kListNames[list]) + " candidate " + std::to_string(i); };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (int v : rows[i])
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        fail(which(i) + " has vertex index " + std::to_string(v) + ", out of range [0, " + std::to_string(n) + ")");
    const PairSides r = sides_of(kKinds[list], rows[i], kFirstSide[list]);
    for (int s = 0; s < 2; ++s)
      for (int a = 0; a < r.side[s].n; ++a)
        for (int b = 0; b < a; ++b)
          if (r.side[s].v[a] == r.side[s].v[b])
            fail(which(i) + ": its " + (r.side[s].n == 3 ? "triangle" : "edge") + " repeats vertex index " +
                 std::to_string(r.side[s].v[a]) + " (a degenerate element)");
    for (int a = 0; a < r.side[0].n; ++a)
      for (int b = 0; b < r.side[1].n; ++b)
        if (r.side[0].v[a] == r.side[1].v[b])
          fail(which(i) + ": its two sides share vertex index " + std::to_string(r.side[0].v[a]) +
               " (such a pair is within distance 0 at t = 0 by construction; exclude it from the candidates)");
  }
}

/// A CandidateSet as one range of the shared narrow phase, the kinds' lists one after the other
/// in CollisionKind order.
struct CandidateSetRange {
  const CandidateSet& set;
  std::array<std::size_t, 5> offsets{};

  explicit CandidateSetRange(const CandidateSet& s) : set(s) {
    offsets[1] = set.vertex_face.size();
    offsets[2] = offsets[1] + set.edge_edge.size();
    offsets[3] = offsets[2] + set.point_edge.size();
    offsets[4] = offsets[3] + set.point_point.size();
  }

  std::size_t size() const { return offsets[4]; }

  /// The list (kKinds order) of candidate k.
  std::size_t list_of(std::size_t k) const {
    std::size_t i = 0;
    while (k >= offsets[i + 1]) ++i;
    return i;
  }

  /// Candidate k as two sides of vertices.
  PairSides pair(std::size_t k) const {
    const std::size_t i = list_of(k), j = k - offsets[i];
    switch (i) {
      case 0: return sides_of(kKinds[0], set.vertex_face[j], kFirstSide[0]);
      case 1: return sides_of(kKinds[1], set.edge_edge[j], kFirstSide[1]);
      case 2: return sides_of(kKinds[2], set.point_edge[j], kFirstSide[2]);
      default: break;
    }
    return sides_of(kKinds[3], set.point_point[j], kFirstSide[3]);
  }

  /// Candidate k as a CandidateCollision with the given time of impact.
  CandidateCollision collision(std::size_t k, const TimeInterval& toi) const {
    const std::size_t i = list_of(k);
    return {kKinds[i], k - offsets[i], toi};
  }
};

/// The validated question {d, tmax} of the options, after the input.
CcdParams checked(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const CandidateSet& candidates,
                  const SceneOptions& options) {
  validate(options);
  validate(x0, x1, candidates);
  return {options.min_distance, options.tmax};
}

}  // namespace

CandidateSet candidates_from_elements(const std::vector<std::array<int, 3>>& faces,
                                      const std::vector<std::array<int, 2>>& edges,
                                      const std::vector<std::array<int, 2>>& vertex_face,
                                      const std::vector<std::array<int, 2>>& edge_edge,
                                      const std::vector<std::array<int, 2>>& point_edge,
                                      const std::vector<std::array<int, 2>>& point_point) {
  const auto element = [](int index, std::size_t count, const char* list, std::size_t i, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= count)
      fail(std::string(list) + " candidate " + std::to_string(i) + " has " + what + " index " + std::to_string(index) +
           ", out of range [0, " + std::to_string(count) + ")");
    return static_cast<std::size_t>(index);
  };
  CandidateSet c;
  c.vertex_face.reserve(vertex_face.size());
  for (std::size_t i = 0; i < vertex_face.size(); ++i) {
    const auto& f = faces[element(vertex_face[i][1], faces.size(), "vertex_face", i, "face")];
    c.vertex_face.push_back({vertex_face[i][0], f[0], f[1], f[2]});
  }
  c.edge_edge.reserve(edge_edge.size());
  for (std::size_t i = 0; i < edge_edge.size(); ++i) {
    const auto& a = edges[element(edge_edge[i][0], edges.size(), "edge_edge", i, "edge")];
    const auto& b = edges[element(edge_edge[i][1], edges.size(), "edge_edge", i, "edge")];
    c.edge_edge.push_back({a[0], a[1], b[0], b[1]});
  }
  c.point_edge.reserve(point_edge.size());
  for (std::size_t i = 0; i < point_edge.size(); ++i) {
    const auto& e = edges[element(point_edge[i][1], edges.size(), "point_edge", i, "edge")];
    c.point_edge.push_back({point_edge[i][0], e[0], e[1]});
  }
  c.point_point = point_point;
  return c;
}

void validate(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
              const CandidateSet& candidates) {
  const std::size_t n = positions_t0.size();
  if (positions_t1.size() != n)
    fail("positions_t0 has " + std::to_string(n) + " vertices but positions_t1 has " +
         std::to_string(positions_t1.size()));
  if (n > static_cast<std::size_t>(INT_MAX)) fail("more than INT_MAX vertices");
  scene::require_finite_positions(positions_t0, "positions_t0");
  scene::require_finite_positions(positions_t1, "positions_t1");
  require_valid_rows(candidates.vertex_face, 0, n);
  require_valid_rows(candidates.edge_edge, 1, n);
  require_valid_rows(candidates.point_edge, 2, n);
  require_valid_rows(candidates.point_point, 3, n);
}

std::vector<CandidateCollision> find_collisions(const std::vector<Vec3>& positions_t0,
                                                const std::vector<Vec3>& positions_t1,
                                                const CandidateSet& candidates, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = checked(positions_t0, positions_t1, candidates, options);
  const CandidateSetRange range(candidates);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  std::vector<CandidateCollision> all;
  for (const auto& [k, toi] : scene::colliding_pairs(range, tests, scene::resolve_threads(options.threads)))
    all.push_back(range.collision(k, toi));
  return all;  // ascending k: by kind, then by position in the kind's list
}

std::optional<TimeInterval> earliest_toi(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                                         const CandidateSet& candidates, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = checked(positions_t0, positions_t1, candidates, options);
  const CandidateSetRange range(candidates);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  return scene::earliest_pair_toi(range, tests, scene::resolve_threads(options.threads));
}

std::optional<TimeInterval> earliest_toi(const std::vector<CandidateCollision>& collisions) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  return scene::earliest_of(collisions);
}

bool is_collision_free(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                       const CandidateSet& candidates, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = checked(positions_t0, positions_t1, candidates, options);
  const CandidateSetRange range(candidates);
  const scene::PairTests<Vec3> tests(positions_t0, positions_t1, params);
  return !scene::any_pair_collides(range, tests, scene::resolve_threads(options.threads));
}

double max_collision_free_step(const std::vector<Vec3>& positions_t0, const std::vector<Vec3>& positions_t1,
                               const CandidateSet& candidates, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(positions_t0, positions_t1, candidates, options), options.tmax);
}

}  // namespace exactccd
