// Scene functions with a minimum separation d and a time limit tmax (SceneOptions), and 2D
// scenes (Scene2d): find_collisions, earliest_toi, is_collision_free and
// max_collision_free_step against a brute force over all pairs with the per-kind functions of
// ccd.hpp and CcdParams, on random and degenerate small scenes, for several d and tmax and 1
// and 2 threads; d = 0 / tmax = 1 against the reference of test_scene.cpp (today's pairs only);
// hand-derived cases; invalid options and malformed 2D scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "scene/broad_phase.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

using testing::random_scene;
using testing::scene_with_points;
using testing::same;

std::string describe(const Collision& c) {
  std::ostringstream s;
  switch (c.kind) {
    case CollisionKind::vertex_face: s << "vf " << c.vertex << " " << c.triangle; break;
    case CollisionKind::edge_edge:
      s << "ee " << c.edge_a[0] << "-" << c.edge_a[1] << " " << c.edge_b[0] << "-" << c.edge_b[1];
      break;
    case CollisionKind::point_edge: s << "pe " << c.vertex << " " << c.edge_a[0] << "-" << c.edge_a[1]; break;
    case CollisionKind::point_point: s << "pp " << c.vertex << " " << c.vertex_b; break;
  }
  s << " [" << c.toi.lo << ", " << c.toi.hi << "]";
  return s.str();
}

void expect_same(const std::vector<Collision>& got, const std::vector<Collision>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what << (got.empty() ? "" : ": first got " + describe(got[0]))
                                     << (want.empty() ? "" : ", first want " + describe(want[0]));
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_TRUE(same(got[i], want[i])) << what << ": #" << i << " got " << describe(got[i]) << ", want "
                                       << describe(want[i]);
}

Collision make(CollisionKind kind, const TimeInterval& toi) {
  Collision c;
  c.kind = kind;
  c.toi = toi;
  return c;
}

using Edges = std::vector<std::array<int, 2>>;

/// The scene's edges as scene.hpp defines them (triangle edges and extra edges, ascending).
Edges edges_of(const Edges& extra, const std::vector<std::array<int, 3>>& triangles = {}) {
  std::set<std::array<int, 2>> e;
  const auto add = [&](int a, int b) { e.insert({std::min(a, b), std::max(a, b)}); };
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) add(t[i], t[(i + 1) % 3]);
  for (const auto& x : extra) add(x[0], x[1]);
  return {e.begin(), e.end()};
}

/// Listed points that are an endpoint of no edge, ascending, distinct.
std::vector<int> isolated(const std::vector<int>& points, const Edges& edges) {
  std::set<int> on_edge, out;
  for (const auto& e : edges) on_edge.insert(e.begin(), e.end());
  for (int p : points)
    if (!on_edge.count(p)) out.insert(p);
  return {out.begin(), out.end()};
}

bool share(const std::array<int, 2>& a, const std::array<int, 2>& b) {
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

/// The point-edge and point-point pairs of a scene's isolated points, answered by `pe` and `pp`
/// (which take vertex indices), in the order of find_collisions.
template <class PE, class PP>
void point_pairs(const std::vector<int>& points, const Edges& edges, PE&& pe, PP&& pp, std::vector<Collision>& out) {
  for (int p : points)
    for (const auto& e : edges)
      if (const auto toi = pe(p, e)) {
        Collision c = make(CollisionKind::point_edge, *toi);
        c.vertex = p;
        c.edge_a = e;
        out.push_back(c);
      }
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (const auto toi = pp(points[i], points[j])) {
        Collision c = make(CollisionKind::point_point, *toi);
        c.vertex = points[i];
        c.vertex_b = points[j];
        out.push_back(c);
      }
}

/// Every pair of a 3D scene answered independently by the per-kind functions with
/// CcdParams{d, tmax}: VF and EE as test_scene.cpp, and for d > 0 PE and PP of the isolated
/// points.
std::vector<Collision> brute_force(const Scene& s, const CcdParams& params, Method method = Method::filtered) {
  const auto &x0 = s.positions_t0, &x1 = s.positions_t1;
  std::vector<Collision> out;
  for (int v : testing::scene_vertices(s))
    for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
      const auto& f = s.triangles[t];
      if (f[0] == v || f[1] == v || f[2] == v) continue;
      if (const auto toi = vertex_face_toi(testing::vf_query(s, v, t), params, method)) {
        Collision c = make(CollisionKind::vertex_face, *toi);
        c.vertex = v;
        c.triangle = t;
        out.push_back(c);
      }
    }
  const Edges edges = edges_of(s.edges, s.triangles);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (!share(edges[i], edges[j]))
        if (const auto toi = edge_edge_toi(testing::ee_query(s, edges[i], edges[j]), params, method)) {
          Collision c = make(CollisionKind::edge_edge, *toi);
          c.edge_a = edges[i];
          c.edge_b = edges[j];
          out.push_back(c);
        }
  if (params.min_distance > 0)
    point_pairs(
        isolated(s.points, edges), edges,
        [&](int p, const std::array<int, 2>& e) {
          return point_edge_toi(PointEdgeQuery{x0[p], x0[e[0]], x0[e[1]], x1[p], x1[e[0]], x1[e[1]]}, params, method);
        },
        [&](int p, int q) { return point_point_toi(PointPointQuery{x0[p], x0[q], x1[p], x1[q]}, params, method); },
        out);
  return out;
}

/// The same for a 2D scene: EE, then PE and PP of the isolated points, for every d.
std::vector<Collision> brute_force(const Scene2d& s, const CcdParams& params, Method method = Method::filtered) {
  const auto &x0 = s.positions_t0, &x1 = s.positions_t1;
  std::vector<Collision> out;
  const Edges edges = edges_of(s.edges);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto &a = edges[i], &b = edges[j];
      if (share(a, b)) continue;
      const EdgeEdge2dQuery q{x0[a[0]], x0[a[1]], x0[b[0]], x0[b[1]], x1[a[0]], x1[a[1]], x1[b[0]], x1[b[1]]};
      if (const auto toi = edge_edge_2d_toi(q, params, method)) {
        Collision c = make(CollisionKind::edge_edge, *toi);
        c.edge_a = a;
        c.edge_b = b;
        out.push_back(c);
      }
    }
  point_pairs(
      isolated(s.points, edges), edges,
      [&](int p, const std::array<int, 2>& e) {
        return point_edge_2d_toi(PointEdge2dQuery{x0[p], x0[e[0]], x0[e[1]], x1[p], x1[e[0]], x1[e[1]]}, params,
                                 method);
      },
      [&](int p, int q) { return point_point_2d_toi(PointPoint2dQuery{x0[p], x0[q], x1[p], x1[q]}, params, method); },
      out);
  return out;
}

SceneOptions options(unsigned threads, double d, double tmax) {
  SceneOptions o;
  o.threads = threads;
  o.min_distance = d;
  o.tmax = tmax;
  return o;
}

/// Every scene function against the brute force for one (d, tmax), on 1 and 2 threads; adds the
/// number of collisions of each kind to `kinds`. The step is also checked to be collision-free
/// (when positive).
template <class SceneT>
void check(std::array<std::size_t, 4>& kinds, const SceneT& s, double d, double tmax, const std::string& what) {
  const auto want = brute_force(s, CcdParams{d, tmax});
  const auto earliest = earliest_toi(want);
  const double step = max_collision_free_step(earliest, tmax);
  for (unsigned threads : {1u, 2u}) {
    const SceneOptions o = options(threads, d, tmax);
    const std::string at = what + " d=" + std::to_string(d) + " tmax=" + std::to_string(tmax) +
                           " threads=" + std::to_string(threads);
    expect_same(find_collisions(s, o), want, at);
    const auto got = earliest_toi(s, o);
    EXPECT_EQ(got.has_value(), earliest.has_value()) << at;
    if (got && earliest) {
      EXPECT_TRUE(*got == *earliest) << at << ": [" << got->lo << ", " << got->hi << "]";
    }
    EXPECT_EQ(is_collision_free(s, o), want.empty()) << at;
    EXPECT_EQ(max_collision_free_step(s, o), step) << at;
  }
  EXPECT_LE(step, tmax);
  if (want.empty()) {
    EXPECT_EQ(step, tmax) << what;
  }
  if (step > 0) {
    EXPECT_TRUE(brute_force(s, CcdParams{d, step}).empty()) << what << " step " << step;
  }
  for (const Collision& c : want) ++kinds[static_cast<int>(c.kind)];
}

/// A random 2D scene: n vertices (uniform in [-1, 1]^2, or degenerate: a grid of step 1/4,
/// static vertices, repeated positions), `edges` edges over them, and `extra` isolated points
/// plus a point on an edge.
Scene2d random_scene_2d(std::mt19937_64& rng, int n, int edges, int extra, bool degenerate) {
  std::uniform_int_distribution<int> grid(-2, 2), pick(0, n - 1), choice(0, 4);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Scene2d s;
  for (int i = 0; i < n + extra; ++i) {
    Vec2 p0, p1;
    if (degenerate) {
      p0 = {grid(rng) * 0.25, grid(rng) * 0.25};
      p1 = {grid(rng) * 0.25, grid(rng) * 0.25};
      const int c = choice(rng);
      if (c == 0) p1 = p0;
      if (c == 1 && i > 0) p0 = s.positions_t0[pick(rng) % i];
    } else {
      p0 = {uniform(rng), uniform(rng)};
      p1 = {uniform(rng), uniform(rng)};
    }
    s.positions_t0.push_back(p0);
    s.positions_t1.push_back(p1);
  }
  for (int e = 0; e < edges; ++e) {
    const int a = pick(rng);
    int b = pick(rng);
    if (b == a) b = (a + 1) % n;
    s.edges.push_back({a, b});
  }
  for (int i = 0; i < extra; ++i) s.points.push_back(n + i);
  if (!s.edges.empty()) s.points.push_back(s.edges[0][0]);  // on an edge: not isolated
  return s;
}

TEST(SceneSeparation, RandomScenesMatchBruteForce) {
  std::mt19937_64 rng(20261201);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 8; ++i) {
    const Scene s = scene_with_points(rng, 8, 3, 2, 3, false);
    for (const auto& [d, tmax] : {std::pair{0.0, 0.5}, {0.05, 1.0}, {0.3, 0.6}})
      check(kinds, s, d, tmax, "random scene " + std::to_string(i));
  }
  for (std::size_t n : kinds)  // every kind collides somewhere
    EXPECT_GE(n, 3u) << kinds[0] << " " << kinds[1] << " " << kinds[2] << " " << kinds[3];
}

TEST(SceneSeparation, DegenerateScenesMatchBruteForce) {
  std::mt19937_64 rng(5);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 8; ++i) {
    const Scene s = scene_with_points(rng, 7, 2, 2, 3, true);
    // d = 0.25: grid points exactly d apart; tmax = 0.5: contacts exactly at tmax.
    for (const auto& [d, tmax] : {std::pair{0.25, 1.0}, {0.1, 0.5}, {0.0, 0.5}})
      check(kinds, s, d, tmax, "degenerate scene " + std::to_string(i));
  }
  for (std::size_t n : kinds) EXPECT_GE(n, 3u);
}

TEST(SceneSeparation, Random2dScenesMatchBruteForce) {
  std::mt19937_64 rng(17);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 10; ++i) {
    const Scene2d s = random_scene_2d(rng, 8, 5, 3, false);
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.0, 0.4}, {0.1, 1.0}, {0.3, 0.7}})
      check(kinds, s, d, tmax, "2d scene " + std::to_string(i));
  }
  EXPECT_EQ(kinds[0], 0u);  // no vertex-face pairs in the plane
  for (int k = 1; k < 4; ++k) EXPECT_GE(kinds[k], 3u);
}

TEST(SceneSeparation, Degenerate2dScenesMatchBruteForce) {
  std::mt19937_64 rng(29);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 10; ++i) {
    const Scene2d s = random_scene_2d(rng, 7, 4, 3, true);
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.25, 1.0}, {0.25, 0.5}})
      check(kinds, s, d, tmax, "degenerate 2d scene " + std::to_string(i));
  }
  for (int k = 1; k < 4; ++k) EXPECT_GE(kinds[k], 3u);
}

// d = 0 and tmax = 1, given explicitly or by default: exactly the VF and EE contacts of
// test_scene.cpp's reference, no point pairs.
TEST(SceneSeparation, DefaultsGiveTodaysResults) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 12; ++i) {
    const Scene s = scene_with_points(rng, 9, 4, 2, 3, i % 2 == 1);
    const auto want = testing::brute_force_collisions(s, Method::filtered);
    for (unsigned threads : {1u, 2u}) {
      expect_same(find_collisions(s, options(threads, 0.0, 1.0)), want, "scene " + std::to_string(i));
      SceneOptions defaults;
      defaults.threads = threads;
      expect_same(find_collisions(s, defaults), want, "scene " + std::to_string(i) + ", defaults");
      const auto earliest = earliest_toi(s, defaults);
      ASSERT_EQ(earliest.has_value(), !want.empty());
      if (earliest) {
        EXPECT_TRUE(*earliest == *earliest_toi(want));
      }
      EXPECT_EQ(max_collision_free_step(s, defaults), max_collision_free_step(earliest_toi(want)));
    }
    for (const Collision& c : find_collisions(s))
      EXPECT_TRUE(c.kind == CollisionKind::vertex_face || c.kind == CollisionKind::edge_edge) << describe(c);
  }
}

/// The exact time t lies in the tightest double enclosure [lo, hi].
void expect_encloses(const TimeInterval& toi, const mpq_class& t) {
  EXPECT_TRUE(mpq_class(toi.lo) <= t && t <= mpq_class(toi.hi)) << "[" << toi.lo << ", " << toi.hi << "]";
  EXPECT_TRUE(toi.lo == toi.hi || toi.hi == std::nextafter(toi.lo, 2.0)) << "[" << toi.lo << ", " << toi.hi << "]";
}

// Two particles approach head-on along x: p from -1 to 1, q from 1 to -1, so |p - q| = |2 - 4t|,
// which equals d at t = (2 - d) / 4: 0.375 for d = 0.5. At d = 0 points are not paired in 3D.
TEST(SceneSeparation, ParticlesHeadOn) {
  const Scene s{{{-1, 0, 0}, {1, 0, 0}}, {{1, 0, 0}, {-1, 0, 0}}, {}, {}, {1, 0}};
  auto got = find_collisions(s, options(1, 0.5, 1.0));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].kind, CollisionKind::point_point);
  EXPECT_EQ(got[0].vertex, 0);
  EXPECT_EQ(got[0].vertex_b, 1);
  EXPECT_EQ(got[0].triangle, -1);
  EXPECT_EQ(got[0].edge_a, (std::array<int, 2>{-1, -1}));
  EXPECT_TRUE(got[0].toi == (TimeInterval{0.375, 0.375}));
  EXPECT_EQ(max_collision_free_step(s, options(2, 0.5, 1.0)), std::nextafter(0.375, 0.0));
  // The time limit: at tmax = 0.375 the contact counts (t <= tmax), below it there is none.
  EXPECT_TRUE(*earliest_toi(s, options(1, 0.5, 0.375)) == (TimeInterval{0.375, 0.375}));
  EXPECT_TRUE(is_collision_free(s, options(1, 0.5, std::nextafter(0.375, 0.0))));
  EXPECT_EQ(max_collision_free_step(s, options(1, 0.5, 0.25)), 0.25);
  // d = 0: no pair at all in 3D (today's results); tmax limits the step.
  EXPECT_TRUE(find_collisions(s).empty());
  EXPECT_EQ(max_collision_free_step(s), 1.0);
  EXPECT_EQ(max_collision_free_step(s, options(1, 0.0, 0.75)), 0.75);
  // d = 0.1 (a double near 1/10): t = (2 - d) / 4 exactly, enclosed tightly.
  const auto e = earliest_toi(s, options(1, 0.1, 1.0));
  ASSERT_TRUE(e.has_value());
  expect_encloses(*e, (mpq_class(2) - mpq_class(0.1)) / 4);
  // Already within d at t = 0: no step.
  EXPECT_TRUE(*earliest_toi(s, options(1, 2.0, 1.0)) == (TimeInterval{0, 0}));
  EXPECT_EQ(max_collision_free_step(s, options(1, 2.0, 1.0)), 0.0);
  // The same motion in the plane is a contact at d = 0 too (t = 0.5).
  const Scene2d plane{{{-1, 0}, {1, 0}}, {{1, 0}, {-1, 0}}, {}, {0, 1}};
  EXPECT_TRUE(*earliest_toi(plane) == (TimeInterval{0.5, 0.5}));
  EXPECT_TRUE(*earliest_toi(plane, options(1, 0.5, 1.0)) == (TimeInterval{0.375, 0.375}));
}

// Static particles 0.3 apart (disjoint swept boxes: the broad phase must grow them by d) are
// within d = 0.5 from t = 0 on.
TEST(SceneSeparation, BroadPhaseGrowsBoxesByD) {
  const Scene s{{{0, 0, 0}, {0.3, 0, 0}, {5, 5, 5}}, {{0, 0, 0}, {0.3, 0, 0}, {5, 5, 5}}, {}, {}, {0, 1, 2}};
  const auto got = find_collisions(s, options(1, 0.5, 1.0));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].vertex, 0);
  EXPECT_EQ(got[0].vertex_b, 1);
  EXPECT_TRUE(got[0].toi == (TimeInterval{0, 0}));
  EXPECT_TRUE(find_collisions(s, options(1, 0.25, 1.0)).empty());
  EXPECT_TRUE(find_collisions(s, options(1, 0.3, 1.0)).size() == 1u);  // exactly d apart
  // A huge d: every pair, bounds overflowing to infinity stay outside.
  EXPECT_EQ(find_collisions(s, options(2, std::numeric_limits<double>::max(), 1.0)).size(), 3u);
}

// earliest_toi's pruning by time grows its boxes over [0, h] by d too: on one thread the
// edge-edge pair (first in the candidate order) comes within d = 0.5 at t = 0.5, after which the
// two static points 0.3 apart (within d from t = 0, their boxes disjoint) must not be skipped.
TEST(SceneSeparation, EarliestToiPrunesWithGrownBoxes) {
  const Scene2d s{{{0, 0}, {2, 0}, {0, 1.5}, {2, 1.5}, {10, 0}, {10.3, 0}},
                  {{0, 0}, {2, 0}, {0, -0.5}, {2, -0.5}, {10, 0}, {10.3, 0}},
                  {{0, 1}, {2, 3}},
                  {4, 5}};
  const auto all = find_collisions(s, options(1, 0.5, 1.0));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_TRUE(all[0].toi == (TimeInterval{0.5, 0.5}));
  EXPECT_EQ(all[1].kind, CollisionKind::point_point);
  for (unsigned threads : {1u, 2u}) EXPECT_TRUE(*earliest_toi(s, options(threads, 0.5, 1.0)) == (TimeInterval{0, 0}));
}

// inflated() rounds outwards: against exact rationals, on bounds where fl(lo - d) rounds up
// (towards the box) as often as down.
TEST(SceneSeparation, InflatedBoxesHoldTheExactBounds) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  int inward = 0;
  for (int i = 0; i < 20000; ++i) {
    scene::Box box;
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::ldexp(unit(rng), exponent(rng));
      box.hi[k] = box.lo[k] + std::ldexp(std::fabs(unit(rng)), exponent(rng));
    }
    const double d = std::ldexp(std::fabs(unit(rng)), exponent(rng));
    const scene::Box out = scene::inflated(box, d);
    for (int k = 0; k < 3; ++k) {
      const mpq_class lo = mpq_class(box.lo[k]) - mpq_class(d), hi = mpq_class(box.hi[k]) + mpq_class(d);
      ASSERT_LE(mpq_class(out.lo[k]), lo) << box.lo[k] << " " << d;
      ASSERT_GE(mpq_class(out.hi[k]), hi) << box.hi[k] << " " << d;
      inward += mpq_class(box.lo[k] - d) > lo;  // the plain difference would have cut into the box
    }
  }
  EXPECT_GT(inward, 1000);
  const scene::Box same = scene::inflated(scene::Box{{{1, 2, 3}}, {{4, 5, 6}}}, 0.0);  // d = 0: unchanged
  EXPECT_TRUE(same.lo == (std::array<double, 3>{1, 2, 3}) && same.hi == (std::array<double, 3>{4, 5, 6}));
  const double big = std::numeric_limits<double>::max();
  const scene::Box huge = scene::inflated(scene::Box{{{-big, 0, 0}}, {{big, 0, 0}}}, big);
  EXPECT_TRUE(std::isinf(huge.lo[0]) && huge.lo[0] < 0 && std::isinf(huge.hi[0]) && huge.hi[0] > 0);
}

// A point falls onto a static 2D edge from (0, 0) to (2, 0): p = (1, 1 - 2t) touches it at
// t = 0.5 (a contact at d = 0 in the plane) and is within d = 0.25 at t = (1 - 0.25) / 2.
TEST(SceneSeparation, PointFallsOntoEdge2d) {
  Scene2d s{{{0, 0}, {2, 0}, {1, 1}}, {{0, 0}, {2, 0}, {1, -1}}, {{1, 0}}, {2}};
  auto got = find_collisions(s);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].kind, CollisionKind::point_edge);
  EXPECT_EQ(got[0].vertex, 2);
  EXPECT_EQ(got[0].edge_a, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(got[0].edge_b, (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(got[0].vertex_b, -1);
  EXPECT_TRUE(got[0].toi == (TimeInterval{0.5, 0.5}));
  EXPECT_TRUE(*earliest_toi(s, options(2, 0.25, 1.0)) == (TimeInterval{0.375, 0.375}));
  EXPECT_EQ(max_collision_free_step(s, options(1, 0.25, 1.0)), std::nextafter(0.375, 0.0));
  EXPECT_TRUE(is_collision_free(s, options(1, 0.0, 0.25)));
  EXPECT_EQ(max_collision_free_step(s, options(1, 0.0, 0.25)), 0.25);
  // Passing beside the edge's end at distance 0.5: a contact only for d >= 0.5.
  s.positions_t0[2] = {2.5, 1};
  s.positions_t1[2] = {2.5, -1};
  EXPECT_TRUE(find_collisions(s).empty());
  EXPECT_TRUE(find_collisions(s, options(1, 0.4, 1.0)).empty());
  got = find_collisions(s, options(1, 0.5, 1.0));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_TRUE(got[0].toi == (TimeInterval{0.5, 0.5}));
  // A listed point that is an edge's endpoint is not isolated: no point-edge pair for it.
  s.points = {0};
  EXPECT_TRUE(find_collisions(s, options(1, 10.0, 1.0)).empty());
  // Edge 2-3 falls onto edge 0-1 (edge-edge in the plane) at t = 0.5.
  Scene2d ee{{{0, 0}, {2, 0}, {1, 1}, {1, 3}}, {{0, 0}, {2, 0}, {1, -1}, {1, 1}}, {{0, 1}, {3, 2}}, {}};
  got = find_collisions(ee);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].kind, CollisionKind::edge_edge);
  EXPECT_EQ(got[0].edge_a, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(got[0].edge_b, (std::array<int, 2>{2, 3}));
  EXPECT_TRUE(got[0].toi == (TimeInterval{0.5, 0.5}));
}

// A 3D isolated point passes an extra edge (from (0, 0, 0) to (2, 0, 0)) at distance 0.1: p(t)
// = (1, 1 - 2t, 0.1). Nothing at d = 0 (today's results); within d = 0.25 when
// (1 - 2t)^2 + 0.01 = 0.0625, t = (1 - sqrt(0.0525)) / 2 (irrational: a tight enclosure).
TEST(SceneSeparation, PointPassesExtraEdge3d) {
  const Scene s{{{0, 0, 0}, {2, 0, 0}, {1, 1, 0.1}}, {{0, 0, 0}, {2, 0, 0}, {1, -1, 0.1}}, {}, {{1, 0}}, {2}};
  EXPECT_TRUE(find_collisions(s).empty());
  EXPECT_TRUE(find_collisions(s, options(1, 0.05, 1.0)).empty());
  const auto got = find_collisions(s, options(1, 0.25, 1.0));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].kind, CollisionKind::point_edge);
  EXPECT_EQ(got[0].vertex, 2);
  EXPECT_EQ(got[0].edge_a, (std::array<int, 2>{0, 1}));
  // (1 - 2t)^2 = 0.0625 - 0.01 with the doubles d^2 = 1/16 and z = 0.1: check the enclosure
  // against the exact root by squaring: lo below, hi above (1 - 2t decreasing in t).
  const mpq_class rhs = mpq_class(0.25) * mpq_class(0.25) - mpq_class(0.1) * mpq_class(0.1);
  const auto gap = [&](double t) -> mpq_class {
    const mpq_class a = 1 - 2 * mpq_class(t);
    return a * a - rhs;  // > 0 before the root, < 0 after (while 1 - 2t > 0)
  };
  EXPECT_GT(gap(got[0].toi.lo), 0);
  EXPECT_LT(gap(got[0].toi.hi), 0);
  EXPECT_EQ(got[0].toi.hi, std::nextafter(got[0].toi.lo, 1.0));
  // Together with a triangle: kinds sorted vertex-face, edge-edge, point-edge, point-point.
  Scene t = s;
  t.positions_t0.insert(t.positions_t0.end(), {{0, 0, -0.1}, {2, 0, -0.1}, {1, 2, -0.1}, {1, 1, 0.2}});
  t.positions_t1.insert(t.positions_t1.end(), {{0, 0, -0.1}, {2, 0, -0.1}, {1, 2, -0.1}, {1, -1, 0.2}});
  t.triangles = {{3, 4, 5}};
  t.points = {2, 6};
  const auto all = find_collisions(t, options(2, 0.25, 1.0));
  expect_same(all, brute_force(t, CcdParams{0.25, 1.0}), "with a triangle");
  std::set<CollisionKind> kinds;
  for (std::size_t i = 0; i < all.size(); ++i) {
    kinds.insert(all[i].kind);
    if (i > 0) {
      EXPECT_LE(static_cast<int>(all[i - 1].kind), static_cast<int>(all[i].kind));
    }
  }
  EXPECT_EQ(kinds.size(), 4u);
}

TEST(SceneSeparation, InvalidOptionsThrow) {
  const Scene s{{{0, 0, 0}}, {{0, 0, 0}}, {}, {}, {0}};
  const Scene2d p{{{0, 0}}, {{0, 0}}, {}, {0}};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const auto& [d, tmax] : {std::pair{-1.0, 1.0}, {nan, 1.0}, {inf, 1.0}, {-0.0 - 1e-300, 1.0}, {0.0, 0.0},
                                {0.0, -0.5}, {0.0, 1.5}, {0.0, nan}, {0.0, inf}}) {
    const SceneOptions o = options(1, d, tmax);
    EXPECT_THROW(find_collisions(s, o), std::invalid_argument) << d << " " << tmax;
    EXPECT_THROW(earliest_toi(s, o), std::invalid_argument);
    EXPECT_THROW(is_collision_free(s, o), std::invalid_argument);
    EXPECT_THROW(max_collision_free_step(s, o), std::invalid_argument);
    EXPECT_THROW(find_collisions(p, o), std::invalid_argument);
    EXPECT_THROW(earliest_toi(p, o), std::invalid_argument);
    EXPECT_THROW(is_collision_free(p, o), std::invalid_argument);
    EXPECT_THROW(max_collision_free_step(p, o), std::invalid_argument);
    EXPECT_THROW(validate(o), std::invalid_argument);
  }
  EXPECT_NO_THROW(validate(options(0, 0.0, 1.0)));
  EXPECT_NO_THROW(validate(options(0, 1e300, 0x1p-1074)));
  EXPECT_THROW(max_collision_free_step(std::nullopt, 0.0), std::invalid_argument);
  EXPECT_THROW(max_collision_free_step(std::nullopt, 2.0), std::invalid_argument);
  EXPECT_EQ(max_collision_free_step(std::nullopt, 0.5), 0.5);
}

TEST(SceneSeparation, Malformed2dScenesThrow) {
  const auto throws = [](const Scene2d& s, const std::string& fragment) {
    try {
      validate(s);
      ADD_FAILURE() << "no exception, expected one naming " << fragment;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
    EXPECT_THROW(find_collisions(s), std::invalid_argument);
    EXPECT_THROW(earliest_toi(s), std::invalid_argument);
    EXPECT_THROW(is_collision_free(s), std::invalid_argument);
    EXPECT_THROW(max_collision_free_step(s), std::invalid_argument);
  };
  const Scene2d good{{{0, 0}, {1, 0}, {0, 1}}, {{0, 0}, {1, 0}, {0, 1}}, {{0, 1}}, {2}};
  EXPECT_NO_THROW(validate(good));
  Scene2d s = good;
  s.positions_t1.pop_back();
  throws(s, "positions_t1 has 2");
  s = good;
  s.positions_t1[1].y = std::numeric_limits<double>::quiet_NaN();
  throws(s, "positions_t1[1]");
  s = good;
  s.positions_t0[2].x = std::numeric_limits<double>::infinity();
  throws(s, "positions_t0[2]");
  s = good;
  s.edges.push_back({1, 3});
  throws(s, "edge 1 has vertex index 3");
  s = good;
  s.edges.push_back({2, 2});
  throws(s, "edge 1 repeats vertex index 2");
  s = good;
  s.points.push_back(-1);
  throws(s, "point 1 has vertex index -1");
}

}  // namespace
}  // namespace exactccd
