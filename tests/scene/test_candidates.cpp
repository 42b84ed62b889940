// The batch narrow phase over the caller's candidates (exactccd/candidates.hpp) and its C API:
// fed the candidates of the scene's own broad phase (scene_primitives -> find_candidates), it
// gives exactly the pairs and TOIs of the scene functions (find_collisions, earliest_toi,
// is_collision_free, max_collision_free_step) on random, degenerate and procedural scenes at
// 1, 2, 3 and 8 threads, d = 0 and d > 0, tmax = 1 and < 1; on candidates in the caller's own
// order (shuffled, repeated, pairs the broad phase would drop) it gives exactly the per-pair
// answers of the primitive functions of ccd.hpp; bad input throws, naming the element; the
// C API answers as C++ and returns its status codes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "exactccd/exactccd.h"
#include "exactccd/exactccd.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

using testing::random_scene;
using testing::scene_with_points;

/// The candidates of the scene's own broad phase for the question {d, tmax}, as a CandidateSet
/// (vertex indices), and the scene's primitives they come from.
struct SceneCandidates {
  scene::ScenePrimitives prim;
  CandidateSet set;
};

SceneCandidates scene_candidates(const Scene& s, const SceneOptions& o) {
  SceneCandidates c{scene::scene_primitives(s, CcdParams{o.min_distance, o.tmax}), {}};
  const auto& e = c.prim.edges;
  for (const auto& [v, t] : c.prim.candidates.vertex_face)
    c.set.vertex_face.push_back({v, s.triangles[t][0], s.triangles[t][1], s.triangles[t][2]});
  for (const auto& [i, j] : c.prim.candidates.edge_edge) c.set.edge_edge.push_back({e[i][0], e[i][1], e[j][0], e[j][1]});
  for (const auto& [p, i] : c.prim.candidates.point_edge) c.set.point_edge.push_back({p, e[i][0], e[i][1]});
  for (const auto& [p, q] : c.prim.candidates.point_point) c.set.point_point.push_back({p, q});
  return c;
}

/// A CandidateCollision of the scene's candidates as the scene's Collision.
Collision as_collision(const SceneCandidates& c, const CandidateCollision& x) {
  Collision r;
  r.kind = x.kind;
  r.toi = x.toi;
  const auto& cand = c.prim.candidates;
  switch (x.kind) {
    case CollisionKind::vertex_face:
      r.vertex = cand.vertex_face[x.index][0];
      r.triangle = cand.vertex_face[x.index][1];
      break;
    case CollisionKind::edge_edge:
      r.edge_a = c.prim.edges[cand.edge_edge[x.index][0]];
      r.edge_b = c.prim.edges[cand.edge_edge[x.index][1]];
      break;
    case CollisionKind::point_edge:
      r.vertex = cand.point_edge[x.index][0];
      r.edge_a = c.prim.edges[cand.point_edge[x.index][1]];
      break;
    case CollisionKind::point_point:
      r.vertex = cand.point_point[x.index][0];
      r.vertex_b = cand.point_point[x.index][1];
      break;
  }
  return r;
}

std::string at(const std::string& what, const SceneOptions& o) {
  return what + " (d " + std::to_string(o.min_distance) + ", tmax " + std::to_string(o.tmax) + ", " +
         std::to_string(o.threads) + " threads)";
}

/// The batch functions on the scene's own candidates against the scene functions, at 1, 2, 3
/// and 8 threads; counts the collisions per kind in `kinds`.
void check_against_scene(const Scene& s, double d, double tmax, const std::string& what,
                         std::array<std::size_t, 4>& kinds) {
  const SceneOptions base{1, d, tmax};
  const SceneCandidates c = scene_candidates(s, base);
  const std::vector<Collision> want = find_collisions(s, base);
  const std::optional<TimeInterval> want_earliest = earliest_toi(s, base);
  const double want_step = max_collision_free_step(s, base);
  for (const Collision& x : want) ++kinds[static_cast<int>(x.kind)];
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    const SceneOptions o{threads, d, tmax};
    const std::string where = at(what, o);
    const std::vector<CandidateCollision> got = find_collisions(s.positions_t0, s.positions_t1, c.set, o);
    ASSERT_EQ(got.size(), want.size()) << where;
    for (std::size_t i = 0; i < got.size(); ++i)
      EXPECT_TRUE(testing::same(as_collision(c, got[i]), want[i])) << where << ": #" << i;
    const auto earliest = earliest_toi(s.positions_t0, s.positions_t1, c.set, o);
    ASSERT_EQ(earliest.has_value(), want_earliest.has_value()) << where;
    if (earliest) {
      EXPECT_TRUE(*earliest == *want_earliest) << where << ": [" << earliest->lo << ", " << earliest->hi << "]";
    }
    EXPECT_EQ(is_collision_free(s.positions_t0, s.positions_t1, c.set, o), want.empty()) << where;
    EXPECT_EQ(max_collision_free_step(s.positions_t0, s.positions_t1, c.set, o), want_step) << where;
  }
}

TEST(Candidates, RandomScenesMatchSceneFunctions) {
  std::mt19937_64 rng(20261202);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 12; ++i) {
    const Scene s = scene_with_points(rng, 9, 4, 2, 5, false);
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.0, 0.5}, {0.05, 1.0}, {0.3, 0.6}})
      check_against_scene(s, d, tmax, "random scene " + std::to_string(i), kinds);
  }
  for (std::size_t n : kinds)  // every kind collides somewhere
    EXPECT_GE(n, 3u) << kinds[0] << " " << kinds[1] << " " << kinds[2] << " " << kinds[3];
}

TEST(Candidates, DegenerateScenesMatchSceneFunctions) {
  std::mt19937_64 rng(41);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 12; ++i) {
    const Scene s = scene_with_points(rng, 8, 3, 2, 3, true);
    // d = 0.25: grid points exactly d apart; tmax = 0.5: contacts exactly at tmax.
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.0, 0.5}, {0.25, 1.0}, {0.1, 0.5}})
      check_against_scene(s, d, tmax, "degenerate scene " + std::to_string(i), kinds);
  }
  for (std::size_t n : kinds) EXPECT_GE(n, 3u) << kinds[0] << " " << kinds[1] << " " << kinds[2] << " " << kinds[3];
}

TEST(Candidates, ProceduralScenesMatchSceneFunctions) {
  std::array<std::size_t, 4> kinds{};
  for (const auto& [name, resolution] : {std::pair<const char*, int>{"cloth", 10}, {"strip", 8}, {"fold", 8}, {"pile", 2}}) {
    const scene::MovingMesh m = scene::procedural_scene(name, resolution, 3);
    const Scene s{m.positions_t0, m.positions_t1, m.triangles, {}, {}};
    const std::size_t before = kinds[0] + kinds[1];
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.0, 0.7}, {1e-3, 1.0}, {1e-3, 0.5}})
      check_against_scene(s, d, tmax, name, kinds);
    EXPECT_GT(kinds[0] + kinds[1], before) << name;  // the scene collides
  }
}

/// The per-pair answer of the primitive functions of ccd.hpp (an independent path: no range,
/// no threads, no pruning).
std::optional<TimeInterval> primitive_toi(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                          const CandidateSet& set, CollisionKind kind, std::size_t i,
                                          const CcdParams& params) {
  switch (kind) {
    case CollisionKind::vertex_face: {
      const auto& r = set.vertex_face[i];
      return vertex_face_toi({x0[r[0]], x0[r[1]], x0[r[2]], x0[r[3]], x1[r[0]], x1[r[1]], x1[r[2]], x1[r[3]]}, params);
    }
    case CollisionKind::edge_edge: {
      const auto& r = set.edge_edge[i];
      return edge_edge_toi({x0[r[0]], x0[r[1]], x0[r[2]], x0[r[3]], x1[r[0]], x1[r[1]], x1[r[2]], x1[r[3]]}, params);
    }
    case CollisionKind::point_edge: {
      const auto& r = set.point_edge[i];
      return point_edge_toi({x0[r[0]], x0[r[1]], x0[r[2]], x1[r[0]], x1[r[1]], x1[r[2]]}, params);
    }
    case CollisionKind::point_point: break;
  }
  const auto& r = set.point_point[i];
  return point_point_toi({x0[r[0]], x0[r[1]], x1[r[0]], x1[r[1]]}, params);
}

/// Every candidate of every kind, not only those of a broad phase: all vertex-triangle,
/// edge-edge, point-edge and point-point pairs sharing no vertex, shuffled, some repeated.
CandidateSet all_pairs_shuffled(const Scene& s, std::mt19937_64& rng) {
  CandidateSet c;
  const int n = static_cast<int>(s.positions_t0.size());
  const auto edges = testing::scene_edges(s);
  const auto disjoint = [](auto a, auto b) {
    for (int x : a)
      for (int y : b)
        if (x == y) return false;
    return true;
  };
  for (int v = 0; v < n; ++v)
    for (const auto& t : s.triangles)
      if (disjoint(std::array<int, 1>{v}, t)) c.vertex_face.push_back({v, t[0], t[1], t[2]});
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = 0; j < edges.size(); ++j)  // both orders: (a, b) and (b, a)
      if (disjoint(edges[i], edges[j])) c.edge_edge.push_back({edges[i][1], edges[i][0], edges[j][0], edges[j][1]});
  for (int v = 0; v < n; ++v)
    for (const auto& e : edges)
      if (disjoint(std::array<int, 1>{v}, e)) c.point_edge.push_back({v, e[0], e[1]});
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q)
      if (p != q) c.point_point.push_back({p, q});
  std::shuffle(c.vertex_face.begin(), c.vertex_face.end(), rng);
  std::shuffle(c.edge_edge.begin(), c.edge_edge.end(), rng);
  std::shuffle(c.point_edge.begin(), c.point_edge.end(), rng);
  std::shuffle(c.point_point.begin(), c.point_point.end(), rng);
  if (!c.vertex_face.empty()) c.vertex_face.push_back(c.vertex_face.front());  // a repeat is answered twice
  return c;
}

TEST(Candidates, AnyCandidatesMatchPrimitiveQueries) {
  std::mt19937_64 rng(77);
  std::array<std::size_t, 4> kinds{};
  for (int i = 0; i < 10; ++i) {
    const Scene s = random_scene(rng, 8, 3, 2, 0, i % 2 == 1);
    const CandidateSet c = all_pairs_shuffled(s, rng);
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.0, 0.4}, {0.1, 1.0}, {0.2, 0.7}}) {
      const CcdParams params{d, tmax};
      std::vector<CandidateCollision> want;
      const std::array<std::size_t, 4> sizes{c.vertex_face.size(), c.edge_edge.size(), c.point_edge.size(),
                                             c.point_point.size()};
      for (int k = 0; k < 4; ++k)
        for (std::size_t j = 0; j < sizes[k]; ++j)
          if (const auto t = primitive_toi(s.positions_t0, s.positions_t1, c, static_cast<CollisionKind>(k), j, params))
            want.push_back({static_cast<CollisionKind>(k), j, *t});
      for (const CandidateCollision& x : want) ++kinds[static_cast<int>(x.kind)];
      for (unsigned threads : {1u, 3u, 8u}) {
        const SceneOptions o{threads, d, tmax};
        const std::string where = at("scene " + std::to_string(i), o);
        const auto got = find_collisions(s.positions_t0, s.positions_t1, c, o);
        ASSERT_EQ(got.size(), want.size()) << where;
        for (std::size_t j = 0; j < got.size(); ++j) {
          EXPECT_EQ(got[j].kind, want[j].kind) << where << " #" << j;
          EXPECT_EQ(got[j].index, want[j].index) << where << " #" << j;
          EXPECT_TRUE(got[j].toi == want[j].toi) << where << " #" << j;
        }
        const auto e = earliest_toi(s.positions_t0, s.positions_t1, c, o), w = earliest_toi(want);
        ASSERT_EQ(e.has_value(), w.has_value()) << where;
        if (e) {
          EXPECT_TRUE(*e == *w) << where;
        }
        EXPECT_EQ(is_collision_free(s.positions_t0, s.positions_t1, c, o), want.empty()) << where;
        EXPECT_EQ(max_collision_free_step(s.positions_t0, s.positions_t1, c, o), max_collision_free_step(w, tmax))
            << where;
      }
    }
  }
  for (std::size_t n : kinds) EXPECT_GE(n, 10u) << kinds[0] << " " << kinds[1] << " " << kinds[2] << " " << kinds[3];
}

// Hand-derived: vertex 0 falls from z = 1 to z = -1 through the triangle (1, 2, 3) in z = 0, so
// it meets it exactly at t = 1/2 (a double); within d = 1/4 it is at t = 3/8 (z(t) = 1 - 2t).
TEST(Candidates, VertexThroughTriangle) {
  const std::vector<Vec3> x0{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Vec3> x1 = x0;
  x1[0].z = -1;
  CandidateSet c;
  c.vertex_face.push_back({0, 1, 2, 3});
  const auto got = find_collisions(x0, x1, c);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].kind, CollisionKind::vertex_face);
  EXPECT_EQ(got[0].index, 0u);
  EXPECT_TRUE((got[0].toi == TimeInterval{0.5, 0.5}));
  EXPECT_EQ(max_collision_free_step(x0, x1, c), std::nextafter(0.5, 0.0));
  const auto within = earliest_toi(x0, x1, c, SceneOptions{1, 0.25, 1.0});
  ASSERT_TRUE(within.has_value());
  EXPECT_TRUE((*within == TimeInterval{0.375, 0.375}));
  // A step of 0.4 stops before the contact: nothing collides, the whole step is safe.
  EXPECT_TRUE(is_collision_free(x0, x1, c, SceneOptions{1, 0.0, 0.4}));
  EXPECT_EQ(max_collision_free_step(x0, x1, c, SceneOptions{1, 0.0, 0.4}), 0.4);
  // Empty candidates: no collision.
  EXPECT_FALSE(earliest_toi(x0, x1, CandidateSet{}).has_value());
  EXPECT_EQ(max_collision_free_step(x0, x1, CandidateSet{}, SceneOptions{1, 0.0, 0.75}), 0.75);
}

TEST(Candidates, FromElementsEqualsVertexIndices) {
  const std::vector<std::array<int, 3>> faces{{1, 2, 3}, {2, 3, 4}};
  const std::vector<std::array<int, 2>> edges{{1, 2}, {3, 4}, {0, 5}};
  const CandidateSet c = candidates_from_elements(faces, edges, {{0, 1}, {5, 0}}, {{0, 1}, {2, 0}}, {{0, 1}}, {{0, 5}});
  EXPECT_EQ(c.vertex_face, (std::vector<std::array<int, 4>>{{0, 2, 3, 4}, {5, 1, 2, 3}}));
  EXPECT_EQ(c.edge_edge, (std::vector<std::array<int, 4>>{{1, 2, 3, 4}, {0, 5, 1, 2}}));
  EXPECT_EQ(c.point_edge, (std::vector<std::array<int, 3>>{{0, 3, 4}}));
  EXPECT_EQ(c.point_point, (std::vector<std::array<int, 2>>{{0, 5}}));
  try {
    (void)candidates_from_elements(faces, edges, {{0, 1}}, {{0, 1}, {1, 3}});
    FAIL() << "an edge index out of range was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("edge_edge candidate 1 has edge index 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)candidates_from_elements(faces, edges, {{0, 2}}, {}), std::invalid_argument);
  EXPECT_THROW((void)candidates_from_elements(faces, edges, {{0, -1}}, {}), std::invalid_argument);
  EXPECT_THROW((void)candidates_from_elements(faces, edges, {}, {}, {{0, 7}}), std::invalid_argument);
}

/// Expects validate() and every batch function to throw std::invalid_argument whose message
/// contains `needle`.
void expect_refused(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const CandidateSet& c,
                    const std::string& needle, const SceneOptions& o = {}) {
  const auto check = [&](auto&& f, const char* name) {
    try {
      f();
      ADD_FAILURE() << name << " accepted input that should fail with: " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << name << ": " << e.what();
    }
  };
  check([&] { (void)find_collisions(x0, x1, c, o); }, "find_collisions");
  check([&] { (void)earliest_toi(x0, x1, c, o); }, "earliest_toi");
  check([&] { (void)is_collision_free(x0, x1, c, o); }, "is_collision_free");
  check([&] { (void)max_collision_free_step(x0, x1, c, o); }, "max_collision_free_step");
}

TEST(Candidates, BadInputThrowsNamingTheElement) {
  const std::vector<Vec3> x0{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const std::vector<Vec3> x1 = x0;
  CandidateSet ok;
  ok.vertex_face.push_back({4, 0, 1, 2});
  ok.edge_edge.push_back({0, 1, 2, 3});
  ok.point_edge.push_back({4, 0, 1});
  ok.point_point.push_back({3, 4});
  EXPECT_NO_THROW(validate(x0, x1, ok));

  CandidateSet c = ok;
  c.vertex_face.push_back({0, 1, 2, 5});
  expect_refused(x0, x1, c, "vertex_face candidate 1 has vertex index 5, out of range [0, 5)");
  c = ok;
  c.edge_edge.push_back({0, -1, 2, 3});
  expect_refused(x0, x1, c, "edge_edge candidate 1 has vertex index -1");
  c = ok;
  c.point_edge.push_back({4, 0, 9});
  expect_refused(x0, x1, c, "point_edge candidate 1 has vertex index 9");
  c = ok;
  c.point_point.push_back({1, 1 << 30});
  expect_refused(x0, x1, c, "point_point candidate 1 has vertex index 1073741824");
  // Sharing a vertex, and degenerate elements.
  c = ok;
  c.vertex_face.push_back({1, 0, 1, 2});
  expect_refused(x0, x1, c, "vertex_face candidate 1: its two sides share vertex index 1");
  c = ok;
  c.vertex_face.push_back({3, 0, 1, 0});
  expect_refused(x0, x1, c, "vertex_face candidate 1: its triangle repeats vertex index 0");
  c = ok;
  c.edge_edge.push_back({0, 1, 1, 2});
  expect_refused(x0, x1, c, "edge_edge candidate 1: its two sides share vertex index 1");
  c = ok;
  c.edge_edge.push_back({2, 2, 0, 1});
  expect_refused(x0, x1, c, "edge_edge candidate 1: its edge repeats vertex index 2");
  c = ok;
  c.point_edge.push_back({0, 0, 1});
  expect_refused(x0, x1, c, "point_edge candidate 1: its two sides share vertex index 0");
  c = ok;
  c.point_point.push_back({2, 2});
  expect_refused(x0, x1, c, "point_point candidate 1: its two sides share vertex index 2");
  // Coordinates and sizes.
  std::vector<Vec3> bad = x0;
  bad[3].y = std::numeric_limits<double>::quiet_NaN();
  expect_refused(bad, x1, ok, "positions_t0[3] has a non-finite coordinate");
  expect_refused(x0, bad, ok, "positions_t1[3] has a non-finite coordinate");
  bad[3].y = -std::numeric_limits<double>::infinity();
  expect_refused(x0, bad, ok, "positions_t1[3] has a non-finite coordinate");
  expect_refused(x0, std::vector<Vec3>(x0.begin(), x0.end() - 1), ok, "positions_t0 has 5 vertices but positions_t1 has 4");
  // Options.
  expect_refused(x0, x1, ok, "tmax", SceneOptions{1, 0.0, 0.0});
  expect_refused(x0, x1, ok, "min_distance", SceneOptions{1, -1.0, 1.0});
  expect_refused(x0, x1, ok, "min_distance", SceneOptions{1, std::numeric_limits<double>::quiet_NaN(), 1.0});
}

// --- the C API -----------------------------------------------------------------------------

std::vector<double> flat(const std::vector<Vec3>& x) {
  std::vector<double> f;
  for (const Vec3& p : x) f.insert(f.end(), {p.x, p.y, p.z});
  return f;
}

TEST(CandidatesCApi, AnswersAsCpp) {
  std::mt19937_64 rng(123);
  int colliding = 0;
  for (int i = 0; i < 6; ++i) {
    const Scene s = scene_with_points(rng, 9, 4, 2, 3, i % 2 == 1);
    for (const auto& [d, tmax] : {std::pair{0.0, 1.0}, {0.1, 0.6}}) {
      const SceneOptions o{2, d, tmax};
      const SceneCandidates sc = scene_candidates(s, o);
      // Repacked as contiguous int rows (std::array<int, N> rows in a vector are contiguous).
      std::vector<int> vf, ee, pe, pp;
      for (const auto& r : sc.set.vertex_face) vf.insert(vf.end(), r.begin(), r.end());
      for (const auto& r : sc.set.edge_edge) ee.insert(ee.end(), r.begin(), r.end());
      for (const auto& r : sc.set.point_edge) pe.insert(pe.end(), r.begin(), r.end());
      for (const auto& r : sc.set.point_point) pp.insert(pp.end(), r.begin(), r.end());
      const exactccd_candidates cc{vf.data(), sc.set.vertex_face.size(), ee.data(), sc.set.edge_edge.size(),
                                   pe.data(),  sc.set.point_edge.size(),  pp.data(), sc.set.point_point.size()};
      const std::vector<double> x0 = flat(s.positions_t0), x1 = flat(s.positions_t1);
      const std::size_t n = s.positions_t0.size();
      const auto want = find_collisions(s.positions_t0, s.positions_t1, sc.set, o);
      colliding += !want.empty();
      const std::size_t m = sc.set.size();
      std::vector<int> kinds(m, -7);
      std::vector<std::size_t> rows(m, 99);
      std::vector<double> lo(m), hi(m);
      std::size_t count = 12345;
      ASSERT_EQ(exactccd_candidates_find_collisions(x0.data(), x1.data(), n, &cc, d, tmax, 2, m, &count, kinds.data(),
                                                    rows.data(), lo.data(), hi.data()),
                EXACTCCD_OK);
      ASSERT_EQ(count, want.size());
      for (std::size_t j = 0; j < count; ++j) {
        EXPECT_EQ(kinds[j], static_cast<int>(want[j].kind));
        EXPECT_EQ(rows[j], want[j].index);
        EXPECT_EQ(lo[j], want[j].toi.lo);
        EXPECT_EQ(hi[j], want[j].toi.hi);
      }
      if (!want.empty()) {  // too small: only the count is written
        count = 0;
        kinds.assign(m, -7);
        EXPECT_EQ(exactccd_candidates_find_collisions(x0.data(), x1.data(), n, &cc, d, tmax, 2, want.size() - 1,
                                                      &count, kinds.data(), rows.data(), lo.data(), hi.data()),
                  EXACTCCD_ERROR_CAPACITY);
        EXPECT_EQ(count, want.size());
        EXPECT_EQ(kinds[0], -7);
      }
      int collides = -1, free = -1;
      double l = -1, h = -1, step = -1;
      ASSERT_EQ(exactccd_candidates_earliest_toi(x0.data(), x1.data(), n, &cc, d, tmax, 3, &collides, &l, &h),
                EXACTCCD_OK);
      const auto e = earliest_toi(s.positions_t0, s.positions_t1, sc.set, o);
      EXPECT_EQ(collides, e ? 1 : 0);
      if (e) {
        EXPECT_EQ(l, e->lo);
        EXPECT_EQ(h, e->hi);
      }
      ASSERT_EQ(exactccd_candidates_is_collision_free(x0.data(), x1.data(), n, &cc, d, tmax, 1, &free), EXACTCCD_OK);
      EXPECT_EQ(free, want.empty() ? 1 : 0);
      ASSERT_EQ(exactccd_candidates_max_collision_free_step(x0.data(), x1.data(), n, &cc, d, tmax, 0, &step),
                EXACTCCD_OK);
      EXPECT_EQ(step, max_collision_free_step(s, o));
    }
  }
  EXPECT_GE(colliding, 3);
}

TEST(CandidatesCApi, StatusCodes) {
  const std::vector<Vec3> p0{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Vec3> p1 = p0;
  p1[0].z = -1;
  std::vector<double> x0 = flat(p0), x1 = flat(p1);
  const int vf[4] = {0, 1, 2, 3};
  const exactccd_candidates c{vf, 1, nullptr, 0, nullptr, 0, nullptr, 0};
  int collides = -1;
  double lo = -1, hi = -1, step = -1;
  ASSERT_EQ(exactccd_candidates_earliest_toi(x0.data(), x1.data(), 4, &c, 0, 1, 1, &collides, &lo, &hi), EXACTCCD_OK);
  EXPECT_EQ(collides, 1);
  EXPECT_EQ(lo, 0.5);
  EXPECT_EQ(hi, 0.5);
  ASSERT_EQ(exactccd_candidates_max_collision_free_step(x0.data(), x1.data(), 4, &c, 0, 1, 1, &step), EXACTCCD_OK);
  EXPECT_EQ(step, std::nextafter(0.5, 0.0));
  // Every failure leaves the outputs alone (toi checks *collides).
  const auto untouched = [](exactccd_status got, exactccd_status want) {
    EXPECT_EQ(got, want) << exactccd_status_string(got);
  };
  const auto toi = [&](const double* a, const double* b, std::size_t n, const exactccd_candidates* cs, double d,
                       double tmax) {
    collides = -1;
    const exactccd_status s = exactccd_candidates_earliest_toi(a, b, n, cs, d, tmax, 1, &collides, &lo, &hi);
    EXPECT_EQ(collides, -1);
    return s;
  };
  untouched(toi(x0.data(), x1.data(), 4, &c, -1, 1), EXACTCCD_ERROR_PARAMETER);
  untouched(toi(x0.data(), x1.data(), 4, &c, 0, 0), EXACTCCD_ERROR_PARAMETER);
  untouched(toi(x0.data(), x1.data(), 4, &c, std::nan(""), 1), EXACTCCD_ERROR_PARAMETER);
  untouched(toi(nullptr, x1.data(), 4, &c, 0, 1), EXACTCCD_ERROR_NULL);
  untouched(toi(x0.data(), x1.data(), 4, nullptr, 0, 1), EXACTCCD_ERROR_NULL);
  const exactccd_candidates missing{nullptr, 1, nullptr, 0, nullptr, 0, nullptr, 0};
  untouched(toi(x0.data(), x1.data(), 4, &missing, 0, 1), EXACTCCD_ERROR_NULL);
  untouched(toi(x0.data(), x1.data(), 3, &c, 0, 1), EXACTCCD_ERROR_INDEX);  // vertex 3 out of range
  const int shared[4] = {1, 1, 2, 3};
  const exactccd_candidates adjacent{shared, 1, nullptr, 0, nullptr, 0, nullptr, 0};
  untouched(toi(x0.data(), x1.data(), 4, &adjacent, 0, 1), EXACTCCD_ERROR_INDEX);
  std::vector<double> nan = x1;
  nan[7] = std::numeric_limits<double>::quiet_NaN();
  untouched(toi(x0.data(), nan.data(), 4, &c, 0, 1), EXACTCCD_ERROR_NON_FINITE);
  EXPECT_EQ(exactccd_candidates_max_collision_free_step(x0.data(), x1.data(), 4, &c, 0, 1, 1, nullptr), EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_candidates_is_collision_free(x0.data(), x1.data(), 4, &c, 0, 1, 1, nullptr), EXACTCCD_ERROR_NULL);
  std::size_t count = 0;
  EXPECT_EQ(exactccd_candidates_find_collisions(x0.data(), x1.data(), 4, &c, 0, 1, 1, 0, nullptr, nullptr, nullptr,
                                                nullptr, nullptr),
            EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_candidates_find_collisions(x0.data(), x1.data(), 4, &c, 0, 1, 1, 0, &count, nullptr, nullptr,
                                                nullptr, nullptr),
            EXACTCCD_ERROR_CAPACITY);
  EXPECT_EQ(count, 1u);
  // No vertices and no candidates: nothing collides, the whole step is safe.
  const exactccd_candidates none{nullptr, 0, nullptr, 0, nullptr, 0, nullptr, 0};
  ASSERT_EQ(exactccd_candidates_max_collision_free_step(nullptr, nullptr, 0, &none, 0, 0.5, 1, &step), EXACTCCD_OK);
  EXPECT_EQ(step, 0.5);
  EXPECT_STREQ(exactccd_status_string(EXACTCCD_ERROR_INDEX), "a candidate's vertex index is out of range or repeated");
}

}  // namespace
}  // namespace exactccd
