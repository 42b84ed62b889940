// Scene-level CCD (exactccd/scene.hpp): the broad phase of lib/scene/broad_phase.hpp, then the
// exact primitive queries of exactccd/ccd.hpp over the candidates, on several threads.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <tuple>

#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"
#include "filter/fp_environment.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/time_bounds.hpp"

namespace exactccd {
namespace {

using scene::Box;
using scene::Edge;
using scene::ScenePrimitives;

/// Candidates per chunk of work: large enough to make handing out chunks cheap, small enough
/// to balance queries whose costs differ by 100x.
constexpr std::size_t kChunk = 64;

/// The candidates of a scene as one index range: [0, vf) vertex-face, then edge-edge.
struct CandidateRange {
  const Scene& scene;
  const ScenePrimitives& prim;
  std::size_t vertex_face_count() const { return prim.candidates.vertex_face.size(); }
  std::size_t size() const { return vertex_face_count() + prim.candidates.edge_edge.size(); }
  bool is_vertex_face(std::size_t k) const { return k < vertex_face_count(); }
  const std::array<int, 2>& vf(std::size_t k) const { return prim.candidates.vertex_face[k]; }
  const Edge& edge_a(std::size_t k) const { return prim.edges[prim.candidates.edge_edge[k - vertex_face_count()][0]]; }
  const Edge& edge_b(std::size_t k) const { return prim.edges[prim.candidates.edge_edge[k - vertex_face_count()][1]]; }

  /// The time of impact of candidate k (std::nullopt: no collision).
  std::optional<TimeInterval> toi(std::size_t k) const {
    if (is_vertex_face(k)) return vertex_face_toi(scene::vertex_face_query(scene, vf(k)[0], vf(k)[1]));
    return edge_edge_toi(scene::edge_edge_query(scene, edge_a(k), edge_b(k)));
  }

  /// Whether candidate k collides at all.
  bool collides(std::size_t k) const {
    if (is_vertex_face(k)) return vertex_face_ccd(scene::vertex_face_query(scene, vf(k)[0], vf(k)[1]));
    return edge_edge_ccd(scene::edge_edge_query(scene, edge_a(k), edge_b(k)));
  }

  /// Candidate k as a Collision with the given time of impact.
  Collision collision(std::size_t k, const TimeInterval& toi) const {
    Collision c;
    c.toi = toi;
    if (is_vertex_face(k)) {
      c.kind = CollisionKind::vertex_face;
      c.vertex = vf(k)[0];
      c.triangle = vf(k)[1];
    } else {
      c.kind = CollisionKind::edge_edge;
      c.edge_a = edge_a(k);
      c.edge_b = edge_b(k);
    }
    return c;
  }

  /// Whether the boxes of candidate k's two primitives over the times [0, h] overlap (h in
  /// [0, 1]); false proves that the pair has no contact in [0, h].
  bool may_touch_until(std::size_t k, double h) const;

  /// True only if candidate k's four points are certainly never coplanar during [0, h], which
  /// proves that the pair has no contact in [0, h].
  bool never_coplanar_until(std::size_t k, double h) const {
    const auto r = is_vertex_face(k) ? rows(scene::vertex_face_query(scene, vf(k)[0], vf(k)[1]))
                                     : rows(scene::edge_edge_query(scene, edge_a(k), edge_b(k)));
    return scene::never_coplanar_until({r[0], r[1], r[2], r[3]}, {r[4], r[5], r[6], r[7]}, h);
  }
};

bool CandidateRange::may_touch_until(std::size_t k, double h) const {
  Box first = scene::empty_box(), second = scene::empty_box();
  const auto add = [&](Box& box, int v) {
    scene::add_vertex_until(box, scene.positions_t0[v], scene.positions_t1[v], h);
  };
  if (is_vertex_face(k)) {
    add(first, vf(k)[0]);
    for (int v : scene.triangles[vf(k)[1]]) add(second, v);
  } else {
    for (int v : edge_a(k)) add(first, v);
    for (int v : edge_b(k)) add(second, v);
  }
  return scene::overlap(first, second);
}

/// The order of enclosures of exact times (design.md, 5.3): by lo, then hi. For tightest
/// enclosures, a precedes b iff a's time is smaller, or both lie in the same open interval
/// between consecutive doubles (then they compare equal).
bool earlier(const TimeInterval& a, const TimeInterval& b) {
  return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi);
}

/// The sort key of a collision: vertex-face first by (vertex, triangle), then edge-edge.
auto key(const Collision& c) {
  return std::make_tuple(c.kind == CollisionKind::edge_edge, c.vertex, c.triangle, c.edge_a, c.edge_b);
}

}  // namespace

std::vector<Collision> find_collisions(const Scene& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const ScenePrimitives prim = scene::scene_primitives(scene);
  const CandidateRange range{scene, prim};
  const unsigned threads = scene::resolve_threads(options.threads);
  std::vector<std::vector<Collision>> found(threads);
  scene::parallel_chunks(range.size(), threads, kChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    for (std::size_t k = begin; k < end; ++k)
      if (const auto toi = range.toi(k)) found[w].push_back(range.collision(k, *toi));
    return true;
  });
  std::vector<Collision> all;
  for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
  std::sort(all.begin(), all.end(), [](const Collision& a, const Collision& b) { return key(a) < key(b); });
  return all;
}

std::optional<TimeInterval> earliest_toi(const std::vector<Collision>& collisions) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  std::optional<TimeInterval> best;
  for (const Collision& c : collisions)
    if (!best || earlier(c.toi, *best)) best = c.toi;
  return best;
}

std::optional<TimeInterval> earliest_toi(const Scene& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const ScenePrimitives prim = scene::scene_primitives(scene);
  const CandidateRange range{scene, prim};
  const unsigned threads = scene::resolve_threads(options.threads);
  // `bound`: the smallest hi of a contact found by any worker. A pair with no contact in
  // [0, bound] has its time t > bound >= (that contact's time), so its tightest enclosure comes
  // strictly later in the order `earlier`: skipping it cannot change the result, whichever
  // worker found what first. The result is the same for any number of threads.
  std::atomic<double> bound{std::numeric_limits<double>::infinity()};
  std::vector<std::optional<TimeInterval>> best(threads);
  scene::parallel_chunks(range.size(), threads, kChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    for (std::size_t k = begin; k < end; ++k) {
      // Cheapest first: boxes over [0, h] (with h >= 1 they are the swept boxes, which the broad
      // phase found overlapping); whether the pair collides at all (a miss is mostly decided by
      // the static filter in ~20 ns); whether its points can be coplanar before h (interval
      // arithmetic on the volume cubic);
      // only then the time of impact, whose refinement to adjacent doubles costs microseconds.
      const double h = bound.load(std::memory_order_relaxed);
      if (h < 1 && !range.may_touch_until(k, h)) continue;
      if (h < 1 && (!range.collides(k) || range.never_coplanar_until(k, h))) continue;
      const auto toi = range.toi(k);  // std::nullopt when the query does not collide
      if (!toi) continue;
      if (!best[w] || earlier(*toi, *best[w])) best[w] = toi;
      for (double current = bound.load(); toi->hi < current && !bound.compare_exchange_weak(current, toi->hi);) {
      }
      if (toi->hi == 0) return false;  // a contact exactly at t = 0: nothing is earlier
    }
    return true;
  });
  std::optional<TimeInterval> result;
  for (const auto& b : best)
    if (b && (!result || earlier(*b, *result))) result = b;
  return result;
}

bool is_collision_free(const Scene& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const ScenePrimitives prim = scene::scene_primitives(scene);
  const CandidateRange range{scene, prim};
  std::atomic<bool> hit{false};
  scene::parallel_chunks(range.size(), scene::resolve_threads(options.threads), kChunk,
                         [&](std::size_t begin, std::size_t end, unsigned) {
                           for (std::size_t k = begin; k < end && !hit.load(std::memory_order_relaxed); ++k)
                             if (range.collides(k)) hit = true;
                           return !hit.load(std::memory_order_relaxed);
                         });
  return !hit;
}

double max_collision_free_step(const std::optional<TimeInterval>& earliest) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  if (!earliest) return 1.0;
  // Every contact time t >= lo; the largest double s < lo gives [0, s] without contact.
  if (earliest->lo <= 0) return 0.0;
  return std::nextafter(earliest->lo, 0.0);
}

double max_collision_free_step(const Scene& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  return max_collision_free_step(earliest_toi(scene, options));
}

}  // namespace exactccd
