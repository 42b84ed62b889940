// Scene-level CCD (exactccd/scene.hpp), 3D and 2D scenes by the same templates: the broad phase
// of lib/scene/broad_phase.hpp, then the exact primitive queries of exactccd/ccd.hpp with
// CcdParams{min_distance, tmax} over the candidates, on several threads.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <type_traits>

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

/// The kinds in CollisionKind order (the order of the candidate lists and of the results).
constexpr std::array<CollisionKind, 4> kKinds{CollisionKind::vertex_face, CollisionKind::edge_edge,
                                              CollisionKind::point_edge, CollisionKind::point_point};

/// The vertex indices of one side of a pair (1 to 3 of them).
struct Side {
  std::array<int, 3> v{};
  int n = 0;
};

/// One candidate: its kind and its two indices ({vertex, triangle}, {edge, edge}, {point,
/// edge}, {point, point}; edges index ScenePrimitives::edges).
struct Ref {
  CollisionKind kind;
  std::array<int, 2> pair;
};

/// The candidates of a 3D or 2D scene as one index range, the kinds' lists one after the other
/// in CollisionKind order, with the question params = {d, tmax}. Every kind is handled by the
/// same code: a pair is two sides of vertices, its query their points at t0 and t1 (the query
/// type chosen by kind and dimension), its time-bounded box the hull of its vertices' boxes.
template <class SceneT>
struct CandidateRange {
  using Point = typename decltype(SceneT::positions_t0)::value_type;
  static constexpr bool planar = std::is_same_v<Point, Vec2>;
  using EE = std::conditional_t<planar, EdgeEdge2dQuery, EdgeEdgeQuery>;
  using PE = std::conditional_t<planar, PointEdge2dQuery, PointEdgeQuery>;
  using PP = std::conditional_t<planar, PointPoint2dQuery, PointPointQuery>;

  const SceneT& scene;
  const ScenePrimitives& prim;
  CcdParams params;
  std::array<const std::vector<std::array<int, 2>>*, 4> lists;
  std::array<std::size_t, 5> offsets{};

  CandidateRange(const SceneT& s, const ScenePrimitives& p, const CcdParams& q)
      : scene(s), prim(p), params(q),
        lists{{&p.candidates.vertex_face, &p.candidates.edge_edge, &p.candidates.point_edge,
               &p.candidates.point_point}} {
    for (std::size_t i = 0; i < 4; ++i) offsets[i + 1] = offsets[i] + lists[i]->size();
  }

  std::size_t size() const { return offsets[4]; }

  /// Candidate k of the range.
  Ref at(std::size_t k) const {
    std::size_t i = 0;
    while (k >= offsets[i + 1]) ++i;
    return {kKinds[i], (*lists[i])[k - offsets[i]]};
  }

  /// The two sides of a candidate.
  std::array<Side, 2> sides(const Ref& r) const {
    const auto point = [](int v) { return Side{{{v, 0, 0}}, 1}; };
    const auto edge = [&](int e) { return Side{{{prim.edges[e][0], prim.edges[e][1], 0}}, 2}; };
    switch (r.kind) {
      case CollisionKind::vertex_face: {
        const scene::Triangle& t = scene::triangles_of(scene)[r.pair[1]];
        return {point(r.pair[0]), Side{t, 3}};
      }
      case CollisionKind::edge_edge: return {edge(r.pair[0]), edge(r.pair[1])};
      case CollisionKind::point_edge: return {point(r.pair[0]), edge(r.pair[1])};
      case CollisionKind::point_point: break;
    }
    return {point(r.pair[0]), point(r.pair[1])};
  }

  /// f(query) for the candidate's query of its kind (in 2D there are no vertex-face pairs).
  template <class F>
  auto with_query(const Ref& r, F&& f) const {
    const std::array<Side, 2> side = sides(r);
    const auto make = [&](auto tag) {
      using Query = decltype(tag);
      return scene::pair_query<Query>(scene.positions_t0, scene.positions_t1, side[0].v.data(), side[0].n,
                                      side[1].v.data(), side[1].n);
    };
    switch (r.kind) {
      case CollisionKind::vertex_face:
        if constexpr (!planar) return f(make(VertexFaceQuery{}));
        break;
      case CollisionKind::edge_edge: return f(make(EE{}));
      case CollisionKind::point_edge: return f(make(PE{}));
      case CollisionKind::point_point: return f(make(PP{}));
    }
    throw std::logic_error("exactccd scene: a vertex-face pair in a 2D scene");
  }

  /// The time of impact of a candidate (std::nullopt: no collision in [0, tmax]).
  std::optional<TimeInterval> toi(const Ref& r) const {
    return with_query(r, [&](const auto& q) { return exactccd::toi(q, params); });
  }

  /// Whether a candidate collides at all.
  bool collides(const Ref& r) const {
    return with_query(r, [&](const auto& q) { return exactccd::ccd(q, params); });
  }

  /// A candidate as a Collision with the given time of impact.
  Collision collision(const Ref& r, const TimeInterval& toi) const {
    Collision c;
    c.kind = r.kind;
    c.toi = toi;
    switch (r.kind) {
      case CollisionKind::vertex_face:
        c.vertex = r.pair[0];
        c.triangle = r.pair[1];
        break;
      case CollisionKind::edge_edge:
        c.edge_a = prim.edges[r.pair[0]];
        c.edge_b = prim.edges[r.pair[1]];
        break;
      case CollisionKind::point_edge:
        c.vertex = r.pair[0];
        c.edge_a = prim.edges[r.pair[1]];
        break;
      case CollisionKind::point_point:
        c.vertex = r.pair[0];
        c.vertex_b = r.pair[1];
        break;
    }
    return c;
  }

  /// Whether the boxes of the candidate's two primitives over the times [0, h] (h in [0, 1]),
  /// grown by d, overlap; false proves that the pair is not within d anywhere in [0, h].
  bool may_touch_until(const Ref& r, double h) const {
    const std::array<Side, 2> side = sides(r);
    const auto box_of = [&](const Side& side) {
      Box box = scene::empty_box();
      for (int i = 0; i < side.n; ++i)
        scene::add_vertex_until(box, scene::lift(scene.positions_t0[side.v[i]]),
                                scene::lift(scene.positions_t1[side.v[i]]), h);
      return scene::inflated(box, params.min_distance);
    };
    return scene::overlap(box_of(side[0]), box_of(side[1]));
  }

  /// True only if the candidate certainly has no contact in [0, h]: for 3D vertex-face and
  /// edge-edge pairs at d = 0, its four points are never coplanar during [0, h] (a contact
  /// needs coplanarity; within d > 0 it does not, and the other kinds are not four points).
  bool never_coplanar_until(const Ref& r, double h) const {
    if (planar || params.min_distance > 0 ||
        (r.kind != CollisionKind::vertex_face && r.kind != CollisionKind::edge_edge))
      return false;
    return with_query(r, [&](const auto& q) {
      using Query = std::decay_t<decltype(q)>;
      if constexpr (std::is_same_v<Query, VertexFaceQuery> || std::is_same_v<Query, EdgeEdgeQuery>) {
        const auto p = rows(q);
        return scene::never_coplanar_until({p[0], p[1], p[2], p[3]}, {p[4], p[5], p[6], p[7]}, h);
      } else {
        return false;
      }
    });
  }
};

/// The order of enclosures of exact times (design.md, 5.3): by lo, then hi. For tightest
/// enclosures, a precedes b iff a's time is smaller, or both lie in the same open interval
/// between consecutive doubles (then they compare equal).
bool earlier(const TimeInterval& a, const TimeInterval& b) {
  return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi);
}

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
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim, params);
  const unsigned threads = scene::resolve_threads(options.threads);
  std::vector<std::vector<Collision>> found(threads);
  scene::parallel_chunks(range.size(), threads, kChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    for (std::size_t k = begin; k < end; ++k) {
      const Ref r = range.at(k);
      if (const auto toi = range.toi(r)) found[w].push_back(range.collision(r, *toi));
    }
    return true;
  });
  std::vector<Collision> all;
  for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
  std::sort(all.begin(), all.end(), [](const Collision& a, const Collision& b) { return key(a) < key(b); });
  return all;
}

template <class SceneT>
std::optional<TimeInterval> earliest_toi_in(const SceneT& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim, params);
  const unsigned threads = scene::resolve_threads(options.threads);
  // `bound`: the smallest hi of a collision found by any worker. A pair with no collision in
  // [0, bound] has its time t > bound >= (that collision's time), so its tightest enclosure
  // comes strictly later in the order `earlier`: skipping it cannot change the result, whichever
  // worker found what first. The result is the same for any number of threads.
  std::atomic<double> bound{std::numeric_limits<double>::infinity()};
  std::vector<std::optional<TimeInterval>> best(threads);
  scene::parallel_chunks(range.size(), threads, kChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    for (std::size_t k = begin; k < end; ++k) {
      // Cheapest first: boxes over [0, h] grown by d (with h >= 1 they are the swept boxes,
      // which the broad phase found overlapping); whether the pair collides at all (a miss is
      // mostly decided by the static filter in ~20 ns); whether its points can be coplanar
      // before h (interval arithmetic on the volume cubic; contact pairs at d = 0 only);
      // only then the time of impact, whose refinement to adjacent doubles costs microseconds.
      const Ref r = range.at(k);
      const double h = bound.load(std::memory_order_relaxed);
      if (h < 1 && !range.may_touch_until(r, h)) continue;
      if (h < 1 && (!range.collides(r) || range.never_coplanar_until(r, h))) continue;
      const auto toi = range.toi(r);  // std::nullopt when the query does not collide
      if (!toi) continue;
      if (!best[w] || earlier(*toi, *best[w])) best[w] = toi;
      for (double current = bound.load(); toi->hi < current && !bound.compare_exchange_weak(current, toi->hi);) {
      }
      if (toi->hi == 0) return false;  // a collision exactly at t = 0: nothing is earlier
    }
    return true;
  });
  std::optional<TimeInterval> result;
  for (const auto& b : best)
    if (b && (!result || earlier(*b, *result))) result = b;
  return result;
}

template <class SceneT>
bool is_collision_free_in(const SceneT& scene, const SceneOptions& options) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  const CcdParams params = params_of(options);
  const ScenePrimitives prim = scene::scene_primitives(scene, params, scene::resolve_threads(options.threads));
  const CandidateRange<SceneT> range(scene, prim, params);
  std::atomic<bool> hit{false};
  scene::parallel_chunks(range.size(), scene::resolve_threads(options.threads), kChunk,
                         [&](std::size_t begin, std::size_t end, unsigned) {
                           for (std::size_t k = begin; k < end && !hit.load(std::memory_order_relaxed); ++k)
                             if (range.collides(range.at(k))) hit = true;
                           return !hit.load(std::memory_order_relaxed);
                         });
  return !hit;
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
  std::optional<TimeInterval> best;
  for (const Collision& c : collisions)
    if (!best || earlier(c.toi, *best)) best = c.toi;
  return best;
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
