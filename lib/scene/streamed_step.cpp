#include "scene/streamed_step.hpp"

#include <algorithm>
#include <chrono>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "numeric/fp_environment.hpp"
#include "scene/coplanar_blocks.hpp"
#include "scene/narrow_phase.hpp"
#include "scene/pair_stream.hpp"
#include "scene/parallel.hpp"

namespace exactccd::scene {
namespace {

/// A found pair as two sides of vertices (edges index the topology's edges).
template <class SceneT>
PairSides sides_of(const SceneT& scene, const ScenePrimitives& prim, const FoundPair& p) {
  const auto edge = [&](int e) {
    const Edge& x = prim.edges[static_cast<std::size_t>(e)];
    return edge_side(x[0], x[1]);
  };
  switch (p.kind) {
    case CollisionKind::vertex_face:
      return {p.kind, {point_side(p.ij[0]), triangle_side(triangles_of(scene)[static_cast<std::size_t>(p.ij[1])])}};
    case CollisionKind::edge_edge: return {p.kind, {edge(p.ij[0]), edge(p.ij[1])}};
    case CollisionKind::point_edge: return {p.kind, {point_side(p.ij[0]), edge(p.ij[1])}};
    case CollisionKind::point_point: break;
  }
  return {p.kind, {point_side(p.ij[0]), point_side(p.ij[1])}};
}

/// A found pair as a Collision with the given time of impact.
Collision collision_of(const ScenePrimitives& prim, const FoundPair& p, const TimeInterval& toi) {
  Collision c;
  c.kind = p.kind;
  c.toi = toi;
  const auto edge = [&](int e) { return prim.edges[static_cast<std::size_t>(e)]; };
  switch (p.kind) {
    case CollisionKind::vertex_face:
      c.vertex = p.ij[0];
      c.triangle = p.ij[1];
      break;
    case CollisionKind::edge_edge:
      c.edge_a = edge(p.ij[0]);
      c.edge_b = edge(p.ij[1]);
      break;
    case CollisionKind::point_edge:
      c.vertex = p.ij[0];
      c.edge_a = edge(p.ij[1]);
      break;
    case CollisionKind::point_point:
      c.vertex = p.ij[0];
      c.vertex_b = p.ij[1];
      break;
  }
  return c;
}

/// The sort key of a collision: by kind, then vertex-face by (vertex, triangle), edge-edge by
/// (edge_a, edge_b), point-edge by (vertex, edge_a), point-point by (vertex, vertex_b) (the
/// fields a kind does not set are -1 throughout it).
auto key(const Collision& c) {
  return std::make_tuple(static_cast<int>(c.kind), c.vertex, c.triangle, c.edge_a, c.edge_b, c.vertex_b);
}

template <class SceneT>
using PointOf = typename decltype(SceneT::positions_t0)::value_type;

/// Streams the trees' pairs, as sides, into the question (narrow_phase.hpp; every pair handed
/// over has overlapping boxes), at d = 0 through each worker's CoplanarBlocks (the contact
/// question's block stages: the pairs they prove apart have no contact; the others resume after
/// them).
template <class SceneT, class Question>
void stream_into(const SceneT& scene, const SceneTrees& st, const PairTests<PointOf<SceneT>>& tests, unsigned threads,
                 Question& question, StepStats* stats) {
  const Kept<StreamBuffers>::Loan kept(&st.stream_buffers());
  StreamBuffers own;  // when another stream holds the kept ones (nothing allocated otherwise)
  StreamBuffers& buffers = kept.get() != nullptr ? *kept.get() : own;
  const auto each_pair = [&](const FoundPair& p, unsigned w) {
    return question(sides_of(scene, st.topology(), p), p, w);
  };
  if constexpr (std::is_same_v<PointOf<SceneT>, Vec3>) {  // 3D: vertex-face and edge-edge pairs
    if (CoplanarBlocks<FoundPair>::applies(tests.params())) {
      stream_pair_batches(
          st.trees(), threads,
          [&](const std::vector<FoundPair>& batch, unsigned w) {
            CoplanarBlocks<FoundPair> blocks(tests);  // on this worker's stack: nothing allocated
            const auto visit = [&](const PairSides& r, const FoundPair& p, const questions::ContactFindings* resume) {
              return question(r, p, w, resume);
            };
            for (const FoundPair& p : batch)
              if (!blocks.add(sides_of(scene, st.topology(), p), p, visit)) return false;
            return blocks.flush(visit);
          },
          buffers, stats);
      return;
    }
  }
  stream_pairs(st.trees(), threads, each_pair, buffers, stats);
}

template <class SceneT>
std::vector<Collision> find_in(const SceneT& scene, const SceneTrees& st, const CcdParams& params, unsigned threads,
                               StepStats* stats) {
  const PairTests<PointOf<SceneT>> tests(scene.positions_t0, scene.positions_t1, params);
  CollectCollisions<PointOf<SceneT>, FoundPair> question(tests, threads, /*boxes_checked=*/true);
  stream_into(scene, st, tests, threads, question, stats);
  std::vector<Collision> all;
  for (const auto& [p, toi] : question.take()) all.push_back(collision_of(st.topology(), p, toi));
  std::sort(all.begin(), all.end(), [](const Collision& a, const Collision& b) { return key(a) < key(b); });
  return all;
}

template <class SceneT>
std::optional<TimeInterval> earliest_in(const SceneT& scene, const SceneTrees& st, const CcdParams& params,
                                        unsigned threads, StepStats* stats) {
  const PairTests<PointOf<SceneT>> tests(scene.positions_t0, scene.positions_t1, params);
  EarliestCollision<PointOf<SceneT>> question(tests, /*boxes_checked=*/true);
  stream_into(scene, st, tests, threads, question, stats);
  return question.result();
}

template <class SceneT>
bool any_in(const SceneT& scene, const SceneTrees& st, const CcdParams& params, unsigned threads, StepStats* stats) {
  const PairTests<PointOf<SceneT>> tests(scene.positions_t0, scene.positions_t1, params);
  AnyCollision<PointOf<SceneT>> question(tests, /*boxes_checked=*/true);
  stream_into(scene, st, tests, threads, question, stats);
  return question.hit();
}

}  // namespace

SceneTrees::SceneTrees(const Scene& scene, const CcdParams& params, unsigned threads)
    : prim_(scene_topology(scene, params)), trees_(scene.triangles, prim_.edges, prim_.vertices, prim_.points) {
  trees_.fit(vertex_boxes(scene.positions_t0, scene.positions_t1, params, threads), threads);
}

SceneTrees::SceneTrees(const Scene2d& scene, const CcdParams& params, unsigned threads)
    : prim_(scene_topology(scene, params)), trees_(triangles_of(scene), prim_.edges, prim_.vertices, prim_.points) {
  trees_.fit(vertex_boxes(scene.positions_t0, scene.positions_t1, params, threads), threads);
}

void SceneTrees::refit(const Scene& scene, const CcdParams& params, unsigned threads) {
  vertex_boxes(scene.positions_t0, scene.positions_t1, params, threads, trees_.vertex_boxes());
  trees_.refit(threads);
}

std::vector<Collision> find_collisions(const Scene& s, const SceneTrees& t, const CcdParams& p, unsigned threads,
                                       StepStats* stats) {
  return find_in(s, t, p, threads, stats);
}
std::vector<Collision> find_collisions(const Scene2d& s, const SceneTrees& t, const CcdParams& p, unsigned threads,
                                       StepStats* stats) {
  return find_in(s, t, p, threads, stats);
}
std::optional<TimeInterval> earliest_toi(const Scene& s, const SceneTrees& t, const CcdParams& p, unsigned threads,
                                         StepStats* stats) {
  return earliest_in(s, t, p, threads, stats);
}
std::optional<TimeInterval> earliest_toi(const Scene2d& s, const SceneTrees& t, const CcdParams& p, unsigned threads,
                                         StepStats* stats) {
  return earliest_in(s, t, p, threads, stats);
}
bool any_collision(const Scene& s, const SceneTrees& t, const CcdParams& p, unsigned threads, StepStats* stats) {
  return any_in(s, t, p, threads, stats);
}
bool any_collision(const Scene2d& s, const SceneTrees& t, const CcdParams& p, unsigned threads, StepStats* stats) {
  return any_in(s, t, p, threads, stats);
}

std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options, StepStats* stats) {
  const SceneCall call(options.cancel);  // FP environment and SceneOptions::cancel
  validate(options);
  const CcdParams params{options.min_distance, options.tmax};
  const unsigned threads = resolve_threads(options.threads);
  return with_threads(threads, [&] {
    const auto start = std::chrono::steady_clock::now();
    const SceneTrees trees(scene, params, threads);
    if (stats) stats->setup_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return find_collisions(scene, trees, params, threads, stats);
  });
}

}  // namespace exactccd::scene
