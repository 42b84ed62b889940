// The narrow phase, shared by the scene functions (streamed_step.cpp: the pairs of the scene's
// broad phase as they are found) and the batch functions over the caller's own candidates
// (candidates_ccd.cpp, exactccd/candidates.hpp): every pair decided by the exact primitive
// queries of exactccd/ccd.hpp with CcdParams{min_distance, tmax}, as one of three questions
// (CollectCollisions, EarliestCollision with its shrinking time window, AnyCollision) that take
// the pairs one at a time on any worker; decide_checked_range hands a caller's list over on
// several threads (parallel.hpp: oneTBB).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "api/checked_query.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"
#include "questions/contact_question.hpp"
#include "scene/parallel.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/time_bounds.hpp"

namespace exactccd::scene {

/// Candidates per chunk of work: large enough to make handing out chunks cheap, small enough
/// to balance queries whose costs differ by 100x.
constexpr std::size_t kNarrowPhaseChunk = 64;

/// The vertex indices of one side of a pair (1 to 3 of them: a point, an edge, a triangle).
struct Side {
  std::array<int, 3> v{};  ///< the vertex indices, the first n of them used
  int n = 0;               ///< how many
};

/// One candidate pair: its kind and the vertices of its two sides (vertex-face: the vertex, the
/// triangle; edge-edge: two edges; point-edge: the point, the edge; point-point: two points).
struct PairSides {
  CollisionKind kind = CollisionKind::vertex_face;  ///< which kind of pair
  std::array<Side, 2> side;                         ///< its two sides
};

/// A point side (one vertex).
inline Side point_side(int v) { return Side{{{v, 0, 0}}, 1}; }
/// An edge side (two vertices).
inline Side edge_side(int a, int b) { return Side{{{a, b, 0}}, 2}; }
/// A triangle side (three vertices).
inline Side triangle_side(const std::array<int, 3>& t) { return Side{t, 3}; }

/// The questions asked of one pair of vertices moving from x0 to x1 (Vec3, or Vec2 for the
/// plane), with params = {d, tmax}: every kind is handled by the same code, a pair being two
/// sides of vertices, its query their points at t0 and t1 (the query type chosen by kind and
/// dimension), its time-bounded box the hull of its vertices' boxes.
template <class Point>
class PairTests {
 public:
  static constexpr bool planar = std::is_same_v<Point, Vec2>;
  using EE = std::conditional_t<planar, EdgeEdge2dQuery, EdgeEdgeQuery>;
  using PE = std::conditional_t<planar, PointEdge2dQuery, PointEdgeQuery>;
  using PP = std::conditional_t<planar, PointPoint2dQuery, PointPointQuery>;

  /// The tests of pairs over these positions (kept by reference) for the question params.
  /// The caller has validated both (finite coordinates; scene::validate(SceneOptions)) and
  /// runs the tests under the default floating-point environment (scene::SceneCall on its
  /// thread, parallel_chunks in every task body): the queries are answered by answer_checked_query.
  PairTests(const std::vector<Point>& x0, const std::vector<Point>& x1, const CcdParams& params)
      : x0_(x0), x1_(x1), params_(params) {}

  /// The question {d, tmax}.
  const CcdParams& params() const { return params_; }

  /// The rows of a four-point pair's query (vertex-face, edge-edge: pair_rows, as with_query
  /// builds the query), without building the query.
  std::array<Point, 8> four_point_rows(const PairSides& r) const {
    return pair_rows<4>(x0_, x1_, r.side[0].v.data(), r.side[0].n, r.side[1].v.data(), r.side[1].n);
  }

  /// f(query) for the pair's query of its kind (in 2D there are no vertex-face pairs).
  template <class F>
  auto with_query(const PairSides& r, F&& f) const {
    const auto make = [&](auto tag) {
      using Query = decltype(tag);
      return pair_query<Query>(x0_, x1_, r.side[0].v.data(), r.side[0].n, r.side[1].v.data(), r.side[1].n);
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

  /// The time of impact of a pair (std::nullopt: no collision in [0, tmax]); `resume`: what the
  /// contact question's block stages handed over for its 3D vertex-face or edge-edge query at
  /// d = 0 (CoplanarBlocks), whose per-pair stages then resume after them, or null.
  std::optional<TimeInterval> toi(const PairSides& r, const questions::ContactFindings* resume = nullptr) const {
    return with_query(r, [&](const auto& q) { return answer(q, true, resume); });
  }

  /// Whether a pair collides at all (`resume` as for toi).
  bool collides(const PairSides& r, const questions::ContactFindings* resume = nullptr) const {
    return with_query(r, [&](const auto& q) { return answer(q, false, resume).has_value(); });
  }

  /// Whether the boxes of the pair's two primitives over [0, tmax], grown by d, overlap: the
  /// broad phase's box test, bound for bound (the exact swept boxes when tmax = 1, else
  /// add_vertex_until's certified ones; inflated(), which commutes with the hull); false proves
  /// that the pair is not within d anywhere in [0, tmax].
  bool boxes_overlap(const PairSides& r) const {
    if (!params_.whole_step()) return may_touch_until(r, params_.tmax);
    Box a = swept_box_of(r.side[0]), b = swept_box_of(r.side[1]);
    if (!params_.contact_only()) {
      a = inflated(a, params_.min_distance);
      b = inflated(b, params_.min_distance);
    }
    return overlap(a, b);
  }

  /// Whether the boxes of the pair's two primitives over the times [0, h] (h in [0, 1]), grown
  /// by d, overlap; false proves that the pair is not within d anywhere in [0, h].
  bool may_touch_until(const PairSides& r, double h) const {
    const auto box_of = [&](const Side& side) {
      Box box = empty_box();
      for (int i = 0; i < side.n; ++i) add_vertex_until(box, lift(x0_[side.v[i]]), lift(x1_[side.v[i]]), h);
      return inflated(box, params_.min_distance);
    };
    return overlap(box_of(r.side[0]), box_of(r.side[1]));
  }

  /// True only if the pair certainly has no contact in [0, h]: for 3D vertex-face and edge-edge
  /// pairs at d = 0, its four points are never coplanar during [0, h] (a contact needs
  /// coplanarity; within d > 0 it does not, and the other kinds are not four points).
  bool never_coplanar_until(const PairSides& r, double h) const {
    if (planar || !params_.contact_only() ||
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

 private:
  /// The answer to the question of query q: from the first stage, or after the block stages
  /// whose handover is `resume`.
  template <class Query>
  std::optional<TimeInterval> answer(const Query& q, bool want_toi, const questions::ContactFindings* resume) const {
    if constexpr (std::is_same_v<Query, VertexFaceQuery> || std::is_same_v<Query, EdgeEdgeQuery>) {
      if (resume) return questions::contact_question_resumed(q, pipeline::Question{params_, want_toi}, *resume);
    }
    return answer_checked_query(q, params_, want_toi);
  }

  /// The exact swept box over [0, 1] of a side's vertices (min and max of input coordinates).
  Box swept_box_of(const Side& side) const {
    const Vec3 p = lift(x0_[side.v[0]]), q = lift(x1_[side.v[0]]);
    Box box{{{p.x < q.x ? p.x : q.x, p.y < q.y ? p.y : q.y, p.z < q.z ? p.z : q.z}},
            {{p.x < q.x ? q.x : p.x, p.y < q.y ? q.y : p.y, p.z < q.z ? q.z : p.z}}};
    for (int i = 1; i < side.n; ++i) add_vertex(box, lift(x0_[side.v[i]]), lift(x1_[side.v[i]]));
    return box;
  }

  const std::vector<Point>& x0_;
  const std::vector<Point>& x1_;
  CcdParams params_;
};

/// The order of enclosures of exact times (design.md, 5.3): by lo, then hi. For tightest
/// enclosures, a precedes b iff a's time is smaller, or both lie in the same open interval
/// between consecutive doubles (then they compare equal).
inline bool earlier(const TimeInterval& a, const TimeInterval& b) {
  return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi);
}

/// The earliest TOI (in the order `earlier`) of found collisions (anything with a `toi`
/// member), or none: the scene's and the batch call's earliest_toi(collisions).
template <class Collision>
std::optional<TimeInterval> earliest_of(const std::vector<Collision>& collisions) {
  std::optional<TimeInterval> best;
  for (const Collision& c : collisions)
    if (!best || earlier(c.toi, *best)) best = c.toi;
  return best;
}

// The three questions of the narrow phase, each deciding pairs one at a time as a broad phase
// (pair_stream.hpp) or a caller's candidate list hands them over, on any worker: call(r, id, w)
// returns false when nothing more needs deciding. `boxes_checked`: whether every pair handed
// over is known to have overlapping boxes over [0, tmax] grown by d (the scene's broad phase
// found it so); otherwise that box test comes first, so that a pair whose boxes do not overlap
// costs the box test and nothing more (exact: the boxes hold the motion, boxes_overlap()).

/// find_collisions: every colliding pair with its time of impact, as {id, toi}, per worker.
template <class Point, class Id>
class CollectCollisions {
 public:
  /// For a loop of parallel_chunks(..., threads, ...) started where this is constructed (its
  /// workers are below worker_slots(threads) there).
  CollectCollisions(const PairTests<Point>& tests, unsigned threads, bool boxes_checked)
      : tests_(tests), found_(worker_slots(threads)), boxes_checked_(boxes_checked) {}

  bool operator()(const PairSides& r, const Id& id, unsigned worker, const questions::ContactFindings* resume = nullptr) {
    if (!boxes_checked_ && !tests_.boxes_overlap(r)) return true;
    if (const auto toi = tests_.toi(r, resume)) found_[worker].value.emplace_back(id, *toi);
    return true;
  }

  /// Every colliding pair found, in no particular order.
  std::vector<std::pair<Id, TimeInterval>> take() {
    std::size_t n = 0;
    for (const auto& f : found_) n += f.value.size();
    std::vector<std::pair<Id, TimeInterval>> all;
    all.reserve(n);
    for (auto& f : found_) {
      all.insert(all.end(), f.value.begin(), f.value.end());
      std::vector<std::pair<Id, TimeInterval>>().swap(f.value);
    }
    return all;
  }

 private:
  const PairTests<Point>& tests_;
  std::vector<PerWorker<std::vector<std::pair<Id, TimeInterval>>>> found_;
  bool boxes_checked_;
};

/// earliest_toi: the earliest time of impact (the tightest double interval holding the exact
/// earliest time), pruning by time as it goes and stopping at a collision at t = 0; the result
/// does not depend on the order the pairs come in nor on the number of workers.
template <class Point>
class EarliestCollision {
 public:
  EarliestCollision(const PairTests<Point>& tests, bool boxes_checked) : tests_(tests), boxes_checked_(boxes_checked) {}

  // `bound`: the smallest hi of a collision found by any worker. A pair with no collision in
  // [0, bound] has its time t > bound >= (that collision's time), so its tightest enclosure
  // comes strictly later in the order `earlier`: skipping it cannot change the result, whichever
  // worker found what first.
  template <class Id>
  bool operator()(const PairSides& r, const Id&, unsigned, const questions::ContactFindings* resume = nullptr) {
    // Cheapest first: boxes over [0, h] grown by d (h >= tmax: the broad phase's boxes over
    // [0, tmax]); whether the pair collides at all (a miss is mostly decided by the static
    // filter in ~20 ns); whether its points can be coplanar before h (interval arithmetic on
    // the volume cubic; contact pairs at d = 0 only); only then the time of impact, whose
    // refinement to adjacent doubles costs microseconds.
    const double h = bound_.load(std::memory_order_relaxed);
    if (h < tests_.params().tmax) {
      if (!tests_.may_touch_until(r, h)) return true;
      if (!tests_.collides(r, resume) || tests_.never_coplanar_until(r, h)) return true;
    } else if (!boxes_checked_ && !tests_.boxes_overlap(r)) {
      return true;
    }
    const auto toi = tests_.toi(r, resume);  // std::nullopt when the query does not collide
    if (!toi) return true;
    {
      // Found collisions are few (the window prunes the later ones): one lock each, no
      // per-worker state, nothing allocated.
      const std::lock_guard<std::mutex> lock(best_mutex_);
      if (!best_ || earlier(*toi, *best_)) best_ = toi;
    }
    for (double current = bound_.load(); toi->hi < current && !bound_.compare_exchange_weak(current, toi->hi);) {
    }
    return toi->hi != 0;  // a collision exactly at t = 0: nothing is earlier
  }

  /// The earliest time of impact of every pair decided, or std::nullopt.
  std::optional<TimeInterval> result() const {
    const std::lock_guard<std::mutex> lock(best_mutex_);
    return best_;
  }

 private:
  const PairTests<Point>& tests_;
  std::atomic<double> bound_{std::numeric_limits<double>::infinity()};
  mutable std::mutex best_mutex_;
  std::optional<TimeInterval> best_;  // the earliest in the order `earlier`, under best_mutex_
  bool boxes_checked_;
};

/// is_collision_free: whether some pair collides, stopping at the first one found.
template <class Point>
class AnyCollision {
 public:
  AnyCollision(const PairTests<Point>& tests, bool boxes_checked) : tests_(tests), boxes_checked_(boxes_checked) {}

  template <class Id>
  bool operator()(const PairSides& r, const Id&, unsigned, const questions::ContactFindings* resume = nullptr) {
    if (hit_.load(std::memory_order_relaxed)) return false;
    if (!boxes_checked_ && !tests_.boxes_overlap(r)) return true;
    if (tests_.collides(r, resume)) hit_ = true;
    return !hit_.load(std::memory_order_relaxed);
  }

  /// Whether a colliding pair was found.
  bool hit() const { return hit_.load(); }

 private:
  const PairTests<Point>& tests_;
  std::atomic<bool> hit_{false};
  bool boxes_checked_;
};

/// Hands every candidate k of a range to the question, question(r, k, worker), on `threads`
/// threads in chunks of kNarrowPhaseChunk, until it returns false. The range has size() and
/// bool scan(begin, end, visit), which reads candidates [begin, end) in order, checks each as it
/// is read and does the box test (so the question is asked with boxes_checked), calls
/// visit(r, k) or visit(r, k, resume) (CoplanarBlocks' handover) for the others, and returns false at an invalid candidate or when visit does. An
/// invalid candidate stops the loop. Returns true when every candidate was read and valid,
/// false when the loop stopped early (a question's early exit or an invalid candidate: the
/// caller then validates the whole range, so that bad input is reported, never answered).
template <class Range, class Question>
bool decide_checked_range(const Range& range, unsigned threads, Question& question) {
  std::atomic<bool> stopped{false};
  parallel_chunks(range.size(), threads, kNarrowPhaseChunk, [&](std::size_t begin, std::size_t end, unsigned w) {
    const auto visit = [&](const PairSides& r, std::size_t k, const questions::ContactFindings* resume = nullptr) {
      return question(r, k, w, resume);
    };
    if (range.scan(begin, end, visit)) return true;
    stopped = true;
    return false;
  });
  return !stopped.load();
}

}  // namespace exactccd::scene
