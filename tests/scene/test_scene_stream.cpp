// The streamed scene step (lib/scene/pair_stream.hpp, streamed_step.hpp, narrow_phase.hpp's
// questions): the broad phase's pairs decided as they are found, never listed. Checked against
// brute force and against the per-pair functions over the listed candidates:
// - the shrinking time window of earliest_toi never drops the earliest pair, also when it is
//   found last (every later pair tightening the window first): a caller's candidate list in
//   that order, and scenes whose earliest pair is of the kind traversed last;
// - SceneBroadPhase's own scene functions, across the shrinking steps of a line search,
//   equal fresh calls of the free functions on the same scene, at every thread count;
// - the streamed counts per kind (exactccd scene --stats) equal the listed candidates;
// - a caller's candidate whose boxes do not overlap is not answered (the box test decides it),
//   with the answers unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "exactccd/exactccd.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/streamed_step.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

constexpr unsigned kThreadCounts[] = {1, 2, 3, 8};

Scene scene_of(const scene::MovingMesh& m) {
  Scene s;
  s.positions_t0 = m.positions_t0;
  s.positions_t1 = m.positions_t1;
  s.triangles = m.triangles;
  return s;
}

bool earlier(const TimeInterval& a, const TimeInterval& b) { return a.lo < b.lo || (a.lo == b.lo && a.hi < b.hi); }

std::optional<TimeInterval> earliest_of(const std::vector<Collision>& all) {
  std::optional<TimeInterval> e;
  for (const Collision& c : all)
    if (!e || earlier(c.toi, *e)) e = c.toi;
  return e;
}

void expect_same_collisions(const std::vector<Collision>& got, const std::vector<Collision>& want,
                            const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) EXPECT_TRUE(testing::same(got[k], want[k])) << what << " #" << k;
}

/// n crossing pairs of extra edges, pair k crossing at time 0.5 + 0.4 k / n (k = 0 the
/// earliest), far apart from each other: many edge-edge contacts, spread over the step.
void add_crossing_edges(Scene& s, int n, double x_offset) {
  for (int k = 0; k < n; ++k) {
    const double t = 0.5 + 0.4 * k / n, x = x_offset + 4.0 * k;
    const int v = static_cast<int>(s.positions_t0.size());
    // Edge a static along x at z = 0; edge b along y, falling from z = t to z = t - 1 (z = 0 at t).
    s.positions_t0.insert(s.positions_t0.end(), {{x - 1, 0, 0}, {x + 1, 0, 0}, {x, -1, t}, {x, 1, t}});
    s.positions_t1.insert(s.positions_t1.end(), {{x - 1, 0, 0}, {x + 1, 0, 0}, {x, -1, t - 1}, {x, 1, t - 1}});
    s.edges.push_back({v, v + 1});
    s.edges.push_back({v + 2, v + 3});
  }
}

/// A static triangle at z = 0 and a vertex falling through its interior at time `t` (its own
/// small triangle far above, so no edge of it meets anything before).
void add_falling_vertex(Scene& s, double t, double x) {
  const int v = static_cast<int>(s.positions_t0.size());
  s.positions_t0.insert(s.positions_t0.end(), {{x - 1, -1, 0}, {x + 1, -1, 0}, {x, 1, 0}});
  s.positions_t1.insert(s.positions_t1.end(), {{x - 1, -1, 0}, {x + 1, -1, 0}, {x, 1, 0}});
  s.triangles.push_back({v, v + 1, v + 2});
  // A thin triangle standing on its vertex v + 3, the vertex reaching z = 0 first, at t.
  s.positions_t0.insert(s.positions_t0.end(), {{x, 0, t}, {x + 0.01, 0, t + 3}, {x, 0.01, t + 3}});
  s.positions_t1.insert(s.positions_t1.end(), {{x, 0, t - 1}, {x + 0.01, 0, t + 2}, {x, 0.01, t + 2}});
  s.triangles.push_back({v + 3, v + 4, v + 5});
}

// The earliest contact is a vertex-face pair; dozens of edge-edge contacts come later. The
// traversal hands out the edge-edge pieces first (candidate_finder.cpp), so on one thread the
// window has shrunk to the latest edge-edge times before the earliest pair is met; on several
// threads in any order. The answer must be the earliest pair's, as brute force says.
TEST(SceneStream, EarliestPairFoundLastIsNotDropped) {
  for (double t_first : {0.25, 0.5, 0.9}) {
    Scene s;
    add_crossing_edges(s, 40, 0.0);
    add_falling_vertex(s, t_first, -50.0);
    const std::vector<Collision> brute = testing::brute_force_collisions(s);
    const auto want = earliest_of(brute);
    ASSERT_TRUE(want.has_value());
    for (unsigned threads : kThreadCounts) {
      const SceneOptions options{threads};
      const auto got = earliest_toi(s, options);
      ASSERT_TRUE(got.has_value()) << threads;
      EXPECT_EQ(got->lo, want->lo) << "t_first " << t_first << " threads " << threads;
      EXPECT_EQ(got->hi, want->hi) << "t_first " << t_first << " threads " << threads;
      expect_same_collisions(find_collisions(s, options), brute, "find_collisions");
      EXPECT_EQ(max_collision_free_step(s, options), max_collision_free_step(want, 1.0));
    }
  }
}

// A caller's candidate list ordered by decreasing time of impact: every candidate found
// tightens the window before the next, earlier one comes; the earliest comes last. On one
// thread the order is exactly that; shuffled on several.
TEST(SceneStream, CandidateListInDecreasingTimeOrder) {
  Scene s;
  add_crossing_edges(s, 200, 0.0);
  std::vector<std::pair<TimeInterval, std::array<int, 4>>> ee;
  for (std::size_t i = 0; i < s.edges.size(); i += 2) {
    const auto& a = s.edges[i];
    const auto& b = s.edges[i + 1];
    const auto toi = edge_edge_toi(testing::ee_query(s, a, b));
    ASSERT_TRUE(toi.has_value());
    ee.push_back({*toi, {a[0], a[1], b[0], b[1]}});
  }
  std::sort(ee.begin(), ee.end(), [](const auto& x, const auto& y) { return earlier(y.first, x.first); });
  CandidateSet c;
  for (const auto& [toi, row] : ee) c.edge_edge.push_back(row);
  const TimeInterval want = ee.back().first;
  std::mt19937_64 rng(3);
  for (int round = 0; round < 3; ++round) {
    for (unsigned threads : kThreadCounts) {
      const auto got = earliest_toi(s.positions_t0, s.positions_t1, c, SceneOptions{threads});
      ASSERT_TRUE(got.has_value());
      EXPECT_EQ(got->lo, want.lo) << "round " << round << " threads " << threads;
      EXPECT_EQ(got->hi, want.hi) << "round " << round << " threads " << threads;
    }
    std::shuffle(c.edge_edge.begin(), c.edge_edge.end(), rng);
  }
}

/// s with positions at t = 1 at a fraction `step` of the way: x0 + step (x1 - x0).
std::vector<Vec3> at_step(const Scene& s, double step) {
  std::vector<Vec3> x1(s.positions_t0.size());
  for (std::size_t v = 0; v < x1.size(); ++v) {
    const Vec3 &a = s.positions_t0[v], &b = s.positions_t1[v];
    x1[v] = {a.x + step * (b.x - a.x), a.y + step * (b.y - a.y), a.z + step * (b.z - a.z)};
  }
  return x1;
}

void expect_reused_equals_fresh(const SceneBroadPhase& reused, const Scene& now, const SceneOptions& options,
                                const std::string& what) {
  const auto fresh = find_collisions(now, options);
  expect_same_collisions(reused.find_collisions(), fresh, what + " find_collisions");
  const auto e = reused.earliest_toi(), f = earliest_toi(now, options);
  ASSERT_EQ(e.has_value(), f.has_value()) << what;
  if (e) {
    EXPECT_EQ(e->lo, f->lo) << what;
    EXPECT_EQ(e->hi, f->hi) << what;
  }
  EXPECT_EQ(e.has_value(), !fresh.empty()) << what;
  EXPECT_EQ(reused.is_collision_free(), is_collision_free(now, options)) << what;
  EXPECT_EQ(reused.max_collision_free_step(), max_collision_free_step(now, options)) << what;
}

// A line search: the full step, then halved again and again (the positions at t = 1 moved
// back towards t = 0), each answered by one SceneBroadPhase refitted in place and by fresh
// calls; also after growing the step again. On 1 and 3 threads (the other tests of this file
// and test_broad_phase.cpp cover 2 and 8).
TEST(SceneStream, SceneBroadPhaseAcrossShrinkingStepsEqualsFreshCalls) {
  std::vector<std::pair<std::string, Scene>> scenes;
  for (const char* name : {"cloth", "fold", "pile"}) scenes.push_back({name, scene_of(scene::procedural_scene(name, 12, 2))});
  std::mt19937_64 rng(11);
  for (int k = 0; k < 3; ++k) {
    Scene r = testing::scene_with_points(rng, 40, 30, 10, 6, k % 2 == 1);
    scenes.push_back({"random " + std::to_string(k), r});
  }
  for (const auto& [name, s] : scenes)
    for (const CcdParams& params : {CcdParams{0.0, 1.0}, CcdParams{0.01, 0.75}})
      for (unsigned threads : {1u, 3u}) {
        const SceneOptions options{threads, params.min_distance, params.tmax};
        SceneBroadPhase reused(s, options);
        bool saw_collision = false, saw_free = false;
        for (double step : {1.0, 0.5, 0.25, 0.125, 0.0625, 0.015625, 0.0, 0.75}) {
          Scene now = s;
          now.positions_t1 = at_step(s, step);
          reused.update(now.positions_t1);
          const std::string what = name + " d=" + std::to_string(params.min_distance) +
                                   " threads=" + std::to_string(threads) + " step=" + std::to_string(step);
          expect_reused_equals_fresh(reused, now, options, what);
          (reused.is_collision_free() ? saw_free : saw_collision) = true;
          const SceneBroadPhase rebuilt(now, options);
          EXPECT_EQ(reused.candidates().vertex_face, rebuilt.candidates().vertex_face) << what;
          EXPECT_EQ(reused.candidates().edge_edge, rebuilt.candidates().edge_edge) << what;
          EXPECT_EQ(reused.candidates().point_edge, rebuilt.candidates().point_edge) << what;
          EXPECT_EQ(reused.candidates().point_point, rebuilt.candidates().point_point) << what;
        }
        if (name.rfind("random", 0) != 0 && params.min_distance == 0) {
          EXPECT_TRUE(saw_collision) << name;  // the line search met collisions and free steps
          EXPECT_TRUE(saw_free) << name;
        }
      }
}

// The streamed counts per kind equal the candidates listed by the same trees; the streamed
// collisions equal brute force; on random and degenerate scenes with isolated points, d > 0.
TEST(SceneStream, StreamedCountsAndCollisionsMatchListsAndBruteForce) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 10; ++k) {
    const bool degenerate = k % 2 == 1;
    const Scene s = testing::scene_with_points(rng, 30, 20, 8, 5, degenerate);
    for (const CcdParams& params : {CcdParams{0.0, 1.0}, CcdParams{0.05, 1.0}, CcdParams{0.02, 0.5}})
      for (unsigned threads : {1u, 3u}) {
        const SceneOptions options{threads, params.min_distance, params.tmax};
        scene::StepStats stats;
        const auto got = scene::find_collisions(s, options, &stats);
        const SceneBroadPhase listed(s, options);
        EXPECT_EQ(stats.candidates[0], listed.candidates().vertex_face.size());
        EXPECT_EQ(stats.candidates[1], listed.candidates().edge_edge.size());
        EXPECT_EQ(stats.candidates[2], listed.candidates().point_edge.size());
        EXPECT_EQ(stats.candidates[3], listed.candidates().point_point.size());
        expect_same_collisions(got, find_collisions(s, options), "stats variant");
        if (params.min_distance == 0 && params.tmax == 1)
          expect_same_collisions(got, testing::brute_force_collisions(s, Method::filtered), "brute force, scene " + std::to_string(k));
      }
  }
}

// A caller's candidates whose boxes do not overlap: never colliding, and the answers over a
// list mixing them with real ones equal those over the real ones alone.
TEST(SceneStream, CandidatesWithDisjointBoxesChangeNothing) {
  Scene s;
  add_crossing_edges(s, 20, 0.0);
  CandidateSet real, mixed;
  for (std::size_t i = 0; i < s.edges.size(); i += 2) {
    const auto &a = s.edges[i], &b = s.edges[i + 1];
    real.edge_edge.push_back({a[0], a[1], b[0], b[1]});
    mixed.edge_edge.push_back({a[0], a[1], b[0], b[1]});
    if (i + 2 < s.edges.size()) mixed.edge_edge.push_back({a[0], a[1], s.edges[i + 3][0], s.edges[i + 3][1]});  // 4 apart
  }
  for (unsigned threads : kThreadCounts)
    for (double d : {0.0, 0.1}) {
      const SceneOptions options{threads, d, 1.0};
      const auto r = find_collisions(s.positions_t0, s.positions_t1, real, options);
      const auto m = find_collisions(s.positions_t0, s.positions_t1, mixed, options);
      ASSERT_EQ(r.size(), real.edge_edge.size());
      ASSERT_EQ(m.size(), r.size());
      for (std::size_t k = 0; k < r.size(); ++k) {
        EXPECT_EQ(m[k].index, 2 * r[k].index);
        EXPECT_EQ(m[k].toi.lo, r[k].toi.lo);
        EXPECT_EQ(m[k].toi.hi, r[k].toi.hi);
      }
    }
}

// Bad rows are refused also when their boxes are disjoint (the box test comes before the check
// of shared indices, and a degenerate side far from the other one): no answer is given.
TEST(SceneStream, BadRowsRefusedWhateverTheirBoxes) {
  Scene s;
  add_crossing_edges(s, 4, 0.0);  // vertices 4k .. 4k + 3 near x = 4k
  const auto& x0 = s.positions_t0;
  const auto& x1 = s.positions_t1;
  for (unsigned threads : {1u, 2u}) {
    const SceneOptions options{threads};
    CandidateSet degenerate_far;  // triangle (0, 0, 1) far from vertex 12: disjoint boxes
    degenerate_far.vertex_face = {{12, 0, 0, 1}};
    EXPECT_THROW(find_collisions(x0, x1, degenerate_far, options), std::invalid_argument);
    EXPECT_THROW(earliest_toi(x0, x1, degenerate_far, options), std::invalid_argument);
    EXPECT_THROW(is_collision_free(x0, x1, degenerate_far, options), std::invalid_argument);
    CandidateSet degenerate_edge;  // edge (4, 4) far from edge (12, 13)
    degenerate_edge.edge_edge = {{0, 1, 2, 3}, {4, 4, 12, 13}};
    EXPECT_THROW(find_collisions(x0, x1, degenerate_edge, options), std::invalid_argument);
    CandidateSet shared;  // edges (0, 1) and (1, 2): share vertex 1
    shared.edge_edge = {{8, 9, 12, 13}, {0, 1, 1, 2}};
    EXPECT_THROW(find_collisions(x0, x1, shared, options), std::invalid_argument);
    EXPECT_THROW(max_collision_free_step(x0, x1, shared, options), std::invalid_argument);
    CandidateSet out_of_range;
    out_of_range.point_point = {{0, 99}};
    EXPECT_THROW(find_collisions(x0, x1, out_of_range, options), std::invalid_argument);
  }
}

}  // namespace
}  // namespace exactccd
