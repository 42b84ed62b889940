// Scene-level CCD (exactccd/scene.hpp), 3D and 2D scenes by the same templates: the broad phase
// of lib/scene/broad_phase.hpp, then the shared narrow phase of lib/scene/narrow_phase.hpp (the
// exact primitive queries with CcdParams{min_distance, tmax}, on several threads) over its
// candidates.
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "exactccd/scene.hpp"
#include "filter/fp_environment.hpp"
#include "scene/narrow_phase.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"

namespace exactccd {
namespace {

using scene::PairSides;
using scene::ScenePrimitives;

/// The kinds in CollisionKind order (the order of the candidate lists and of the results).
constexpr std::array<CollisionKind, 4> kKinds{CollisionKind::vertex_face, CollisionKind::edge_edge,
                                              CollisionKind::point_edge, CollisionKind::point_point};

/// The candidates of a 3D or 2D scene's broad phase as one range of the shared narrow phase
/// (scene/narrow_phase.hpp), the kinds' lists one after the other in CollisionKind order.
template <class SceneT>
struct CandidateRange {
  using Point = typename decltype(SceneT::positions_t0)::value_type;

  const SceneT& scene;
  const ScenePrimitives& prim;
  std::array<const std::vector<std::array<int, 2>>*, 4> lists;
  std::array<std::size_t, 5> offsets{};

  CandidateRange(const SceneT& s, const ScenePrimitives& p)
      : scene(s), prim(p),
        lists{{&p.candidates.vertex_face, &p.candidates.edge_edge, &p.candidates.point_edge,
               &p.candidates.point_point}} {
    for (std::size_t i = 0; i < 4; ++i) offsets[i + 1] = offsets[i] + lists[i]->size();
  }

  std::size_t size() const { return offsets[4]; }

  /// The kind of candidate k and its two indices ({vertex, triangle}, {edge, edge}, {point,
  /// edge}, {point, point}; edges index ScenePrimitives::edges).
  std::pair<CollisionKind, std::array<int, 2>> at(std::size_t k) const {
    std::size_t i = 0;
    while (k >= offsets[i + 1]) ++i;
    return {kKinds[i], (*lists[i])[k - offsets[i]]};
  }

  /// Candidate k as two sides of vertices.
  PairSides pair(std::size_t k) const {
    const auto [kind, ij] = at(k);
    const auto edge = [&](int e) { return scene::edge_side(prim.edges[e][0], prim.edges[e][1]); };
    switch (kind) {
      case CollisionKind::vertex_face:
        return {kind, {scene::point_side(ij[0]), scene::triangle_side(scene::triangles_of(scene)[ij[1]])}};
      case CollisionKind::edge_edge: return {kind, {edge(ij[0]), edge(ij[1])}};
      case CollisionKind::point_edge: return {kind, {scene::point_side(ij[0]), edge(ij[1])}};
      case CollisionKind::point_point: break;
    }
    return {kind, {scene::point_side(ij[0]), scene::point_side(ij[1])}};
  }

  /// Candidate k as a Collision with the given time of impact.
  Collision collision(std::size_t k, const TimeInterval& toi) const {
    const auto [kind, ij] = at(k);
    Collision c;
    c.kind = kind;
    c.toi = toi;
    switch (kind) {
      case CollisionKind::vertex_face:
        c.vertex = ij[0];
        c.triangle = ij[1];
        break;
      case CollisionKind::edge_edge:
        c.edge_a = prim.edges[ij[0]];
        c.edge_b = prim.edges[ij[1]];
        break;
      case CollisionKind::point_edge:
        c.vertex = ij[0];
        c.edge_a = prim.edges[ij[1]];
        break;
      case CollisionKind::point_point:
        c.vertex = ij[0];
        c.vertex_b = ij[1];
        break;
    }
    return c;
  }
};

/// The sort key of a collision: by kind, then vertex-face by (vertex, triangle), edge-edge by
/// (edge_a, edge_b), point-edge by (vertex, edge_a), point-point by (vertex, vertex_b) (the
/// fields a kind does not set are -1 throughout it).
auto key(const Collision& c) {
  return std::make_tuple(static_cast<int>(c.kind), c.vertex, c.triangle, c.edge_a, c.edge_b, c.vertex_b);
}

CcdParams params_of(const SceneOptions& options) {
  validate(options);
  return {options.min_distance, options.tmax};
}

template <class SceneT>
std::vector<Collision> find_collisions_in(const SceneT& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim);
  const scene::PairTests<typename CandidateRange<SceneT>::Point> tests(scene.positions_t0, scene.positions_t1, params);
  std::vector<Collision> all;
  for (const auto& [k, toi] : scene::colliding_pairs(range, tests, scene::resolve_threads(options.threads)))
    all.push_back(range.collision(k, toi));
  std::sort(all.begin(), all.end(), [](const Collision& a, const Collision& b) { return key(a) < key(b); });
  return all;
}

template <class SceneT>
std::optional<TimeInterval> earliest_toi_in(const SceneT& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim);
  const scene::PairTests<typename CandidateRange<SceneT>::Point> tests(scene.positions_t0, scene.positions_t1, params);
  return scene::earliest_pair_toi(range, tests, scene::resolve_threads(options.threads));
}

template <class SceneT>
bool is_collision_free_in(const SceneT& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const scene::CancelScope cancel_scope(options.cancel);  // SceneOptions::cancel
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim);
  const scene::PairTests<typename CandidateRange<SceneT>::Point> tests(scene.positions_t0, scene.positions_t1, params);
  return !scene::any_pair_collides(range, tests, scene::resolve_threads(options.threads));
}

}  // namespace

std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options) {
  return find_collisions_in(scene, options);
}

std::vector<Collision> find_collisions(const Scene2d& scene, const SceneOptions& options) {
  return find_collisions_in(scene, options);
}

std::optional<TimeInterval> earliest_toi(const std::vector<Collision>& collisions) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  return scene::earliest_of(collisions);
}

std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneOptions& options) {
  return earliest_toi_in(scene, options);
}

std::optional<TimeInterval> earliest_toi(const Scene2d& scene, const SceneOptions& options) {
  return earliest_toi_in(scene, options);
}

bool is_collision_free(const Scene& scene, const SceneOptions& options) {
  return is_collision_free_in(scene, options);
}

bool is_collision_free(const Scene2d& scene, const SceneOptions& options) {
  return is_collision_free_in(scene, options);
}

double max_collision_free_step(const std::optional<TimeInterval>& earliest, double tmax) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  scene::require_valid_params(CcdParams{0.0, tmax});
  if (!earliest) return tmax;
  // Every collision time t >= lo; the largest double s < lo gives [0, s] without one (and
  // s < lo <= t <= tmax).
  if (earliest->lo <= 0) return 0.0;
  return std::nextafter(earliest->lo, 0.0);
}

double max_collision_free_step(const Scene& scene, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(scene, options), options.tmax);
}

double max_collision_free_step(const Scene2d& scene, const SceneOptions& options) {
  return max_collision_free_step(earliest_toi(scene, options), options.tmax);
}

}  // namespace exactccd
