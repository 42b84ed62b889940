// Scene-level CCD (exactccd/scene.hpp): find_collisions against the brute-force all-pairs exact
// reference on random and degenerate scenes (serial and threaded), adjacency exclusion,
// codimensional edges and points, earliest_toi, is_collision_free, max_collision_free_step
// (checked exactly with rational sub-motions), and malformed scenes. The broad phase and the
// time bounds of earliest_toi: test_scene_bounds.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "scenes/procedural_scenes.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

using testing::brute_force_collisions;
using testing::random_scene;
using testing::same;

std::string describe(const Collision& c) {
  std::ostringstream s;
  if (c.kind == CollisionKind::vertex_face)
    s << "vf " << c.vertex << " " << c.triangle;
  else
    s << "ee " << c.edge_a[0] << "-" << c.edge_a[1] << " " << c.edge_b[0] << "-" << c.edge_b[1];
  s << " [" << c.toi.lo << ", " << c.toi.hi << "]";
  return s.str();
}

void expect_same(const std::vector<Collision>& got, const std::vector<Collision>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_TRUE(same(got[i], want[i])) << what << ": #" << i << " got " << describe(got[i]) << ", want "
                                       << describe(want[i]);
}

/// find_collisions (1 and 4 threads), earliest_toi and is_collision_free against the brute force.
void check_scene(const Scene& s, const std::string& what) {
  const auto want = brute_force_collisions(s);
  expect_same(find_collisions(s, SceneOptions{1}), want, what + " (1 thread)");
  expect_same(find_collisions(s, SceneOptions{4}), want, what + " (4 threads)");
  const auto earliest = earliest_toi(want);
  for (unsigned threads : {1u, 4u}) {
    const auto got = earliest_toi(s, SceneOptions{threads});
    ASSERT_EQ(got.has_value(), earliest.has_value()) << what;
    if (got) {
      EXPECT_TRUE(*got == *earliest) << what << ": earliest [" << got->lo << ", " << got->hi << "]";
    }
    EXPECT_EQ(is_collision_free(s, SceneOptions{threads}), want.empty()) << what;
  }
}

TEST(Scene, RandomScenesMatchBruteForce) {
  std::mt19937_64 rng(20261124);
  int colliding = 0;
  for (int i = 0; i < 30; ++i) {
    const Scene s = random_scene(rng, 10, 5, 2, 2, false);
    check_scene(s, "random scene " + std::to_string(i));
    colliding += !brute_force_collisions(s).empty();
  }
  EXPECT_GT(colliding, 10);  // the test exercises collisions, not only misses
}

TEST(Scene, DegenerateScenesMatchBruteForce) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 30; ++i) check_scene(random_scene(rng, 9, 5, 2, 2, true), "degenerate scene " + std::to_string(i));
}

// Procedural scenes with a few to a hundred collisions: every thread count gives the serial
// result, which is the all-pairs reference (filtered, exact; no broad-phase candidate lost).
TEST(Scene, ProceduralScenesMatchAllPairs) {
  for (const auto& [name, resolution] : {std::pair<const char*, int>{"cloth", 12}, {"strip", 8}, {"fold", 8}}) {
    const scene::MovingMesh m = scene::procedural_scene(name, resolution, 3);
    const Scene s{m.positions_t0, m.positions_t1, m.triangles, {}, {}};
    const auto serial = find_collisions(s, SceneOptions{1});
    EXPECT_FALSE(serial.empty()) << name;
    expect_same(serial, brute_force_collisions(s, Method::filtered), name);
    expect_same(find_collisions(s, SceneOptions{4}), serial, name + std::string(", 4 threads"));
    expect_same(find_collisions(s, SceneOptions{0}), serial, name + std::string(", all cores"));
    const auto earliest = earliest_toi(serial);
    for (unsigned threads : {1u, 3u}) {
      const auto e = earliest_toi(s, SceneOptions{threads});
      ASSERT_TRUE(e.has_value()) << name;
      EXPECT_TRUE(*e == *earliest) << name << ": [" << e->lo << ", " << e->hi << "]";
      EXPECT_FALSE(is_collision_free(s, SceneOptions{threads}));
    }
  }
}

TEST(Scene, OrderAndEdgeOrientation) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 10; ++i) {
    Scene s = random_scene(rng, 10, 5, 3, 1, false);
    for (auto& e : s.edges) std::swap(e[0], e[1]);  // descending input edges are normalised
    const auto got = find_collisions(s);
    for (std::size_t k = 0; k < got.size(); ++k) {
      const Collision& c = got[k];
      if (c.kind == CollisionKind::edge_edge) {
        EXPECT_LT(c.edge_a[0], c.edge_a[1]);
        EXPECT_LT(c.edge_b[0], c.edge_b[1]);
        EXPECT_LT(c.edge_a, c.edge_b);
      }
      if (k == 0) continue;
      const Collision& p = got[k - 1];
      const bool ordered = p.kind == CollisionKind::vertex_face
                               ? (c.kind == CollisionKind::edge_edge ||
                                  std::make_pair(p.vertex, p.triangle) < std::make_pair(c.vertex, c.triangle))
                               : (c.kind == CollisionKind::edge_edge &&
                                  std::make_pair(p.edge_a, p.edge_b) < std::make_pair(c.edge_a, c.edge_b));
      EXPECT_TRUE(ordered) << describe(p) << " before " << describe(c);
    }
  }
}

// Two triangles sharing the edge (0, 1) fold through each other: vertex 3 crosses triangle 0
// and vertex 2 crosses triangle 1, while every vertex always lies on its own triangle and the
// edges at vertices 0 and 1 always touch. Only pairs without a common vertex may be reported.
TEST(Scene, AdjacentPairsAreNeverReported) {
  Scene s;
  s.positions_t0 = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
  s.positions_t1 = s.positions_t0;
  s.positions_t0[3] = {0.5, 1, 1};  // vertex 3 swings from above triangle 0 to below it
  s.positions_t1[3] = {0.5, 0.5, -1};
  s.triangles = {{0, 1, 2}, {0, 1, 3}};
  const auto got = find_collisions(s);
  for (const Collision& c : got) {
    if (c.kind == CollisionKind::vertex_face) {
      const auto& t = s.triangles[c.triangle];
      EXPECT_TRUE(t[0] != c.vertex && t[1] != c.vertex && t[2] != c.vertex) << describe(c);
    } else {
      for (int a : c.edge_a)
        for (int b : c.edge_b) EXPECT_NE(a, b) << describe(c);
    }
  }
  expect_same(got, brute_force_collisions(s), "fold");
  ASSERT_FALSE(got.empty());  // vertex 3 does cross triangle 0
  EXPECT_EQ(got[0].vertex, 3);
  EXPECT_EQ(got[0].triangle, 0);
  // A single moving triangle never collides with itself.
  Scene one{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}, {{0, 1, 2}}, {}, {}};
  EXPECT_TRUE(find_collisions(one).empty());
  EXPECT_TRUE(is_collision_free(one));
  EXPECT_EQ(max_collision_free_step(one), 1.0);
  EXPECT_FALSE(earliest_toi(one).has_value());
}

TEST(Scene, CodimensionalPointsAndEdges) {
  // Triangle 0-1-2 in z = 0; vertex 3 falls through it (t = 0.5); vertex 4 too, but is
  // referenced by nothing until listed as a point; edge 5-6 sweeps through edge 0-1.
  Scene s;
  s.positions_t0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1}, {0.2, 0.2, 1}, {0.5, -1, 1}, {0.5, 1, 1}};
  s.positions_t1 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, -1}, {0.2, 0.2, -3}, {0.5, -1, -1}, {0.5, 1, -1}};
  s.triangles = {{0, 1, 2}};
  s.points = {3};
  auto got = find_collisions(s);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].vertex, 3);
  EXPECT_TRUE(got[0].toi == (TimeInterval{0.5, 0.5}));
  s.points = {3, 4, 3};  // duplicates are harmless
  s.edges = {{6, 5}};
  got = find_collisions(s);
  expect_same(got, brute_force_collisions(s), "codimensional");
  // Vertex 4 at t = 0.25; the edge crosses the triangle's edges 0-1 and 1-2 at t = 0.5; its
  // own endpoints (now vertices too) pass outside the triangle.
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[1].vertex, 4);
  EXPECT_TRUE(got[1].toi == (TimeInterval{0.25, 0.25}));
  EXPECT_EQ(got[2].kind, CollisionKind::edge_edge);
  EXPECT_EQ(got[2].edge_a, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(got[2].edge_b, (std::array<int, 2>{5, 6}));
  EXPECT_TRUE(got[2].toi == (TimeInterval{0.5, 0.5}));
  EXPECT_EQ(got[3].edge_a, (std::array<int, 2>{1, 2}));
  EXPECT_EQ(got[3].edge_b, (std::array<int, 2>{5, 6}));
  EXPECT_TRUE(*earliest_toi(s) == (TimeInterval{0.25, 0.25}));
  EXPECT_EQ(max_collision_free_step(s), std::nextafter(0.25, 0.0));
}

TEST(Scene, ContactAtTimeZeroAllowsNoStep) {
  Scene s{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}},
          {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1}},
          {{0, 1, 2}}, {}, {3}};
  EXPECT_TRUE(*earliest_toi(s) == (TimeInterval{0, 0}));
  EXPECT_EQ(max_collision_free_step(s), 0.0);
  EXPECT_EQ(max_collision_free_step(std::optional<TimeInterval>{}), 1.0);
  EXPECT_EQ(max_collision_free_step(TimeInterval{0.75, 0.75}), std::nextafter(0.75, 0.0));
  EXPECT_EQ(max_collision_free_step(TimeInterval{0, 0x1p-1074}), 0.0);
}

/// The rational query of the sub-motion over [0, s] (time rescaled to [0, 1]): positions at s
/// computed exactly, x0 + s (x1 - x0).
RationalVec3 at(const Vec3& p0, const Vec3& p1, double s) {
  const mpq_class t(s);
  return {mpq_class(p0.x) + t * (mpq_class(p1.x) - mpq_class(p0.x)),
          mpq_class(p0.y) + t * (mpq_class(p1.y) - mpq_class(p0.y)),
          mpq_class(p0.z) + t * (mpq_class(p1.z) - mpq_class(p0.z))};
}
RationalVec3 exact(const Vec3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

/// Whether any non-adjacent pair of the scene collides during [0, s], decided exactly.
bool collides_until(const Scene& sc, double s) {
  const auto x = [&](int v) { return exact(sc.positions_t0[v]); };
  const auto y = [&](int v) { return at(sc.positions_t0[v], sc.positions_t1[v], s); };
  for (int v : testing::scene_vertices(sc))
    for (const auto& f : sc.triangles) {
      if (f[0] == v || f[1] == v || f[2] == v) continue;
      if (vertex_face_ccd(RationalVertexFaceQuery{x(v), x(f[0]), x(f[1]), x(f[2]), y(v), y(f[0]), y(f[1]), y(f[2])}))
        return true;
    }
  const auto edges = testing::scene_edges(sc);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto &a = edges[i], &b = edges[j];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      if (edge_edge_ccd(RationalEdgeEdgeQuery{x(a[0]), x(a[1]), x(b[0]), x(b[1]), y(a[0]), y(a[1]), y(b[0]), y(b[1])}))
        return true;
    }
  return false;
}

TEST(Scene, MaxCollisionFreeStepIsSafeAndTight) {
  std::mt19937_64 rng(99);
  int checked = 0;
  for (int i = 0; i < 40 && checked < 8; ++i) {
    const Scene s = random_scene(rng, 8, 4, 1, 1, i % 2 == 1);
    const auto all = brute_force_collisions(s);
    const double step = max_collision_free_step(s, SceneOptions{2});
    if (all.empty()) {
      EXPECT_EQ(step, 1.0);
      continue;
    }
    const TimeInterval first = *earliest_toi(all);
    // Every exact contact time t >= lo > step (or step == 0 == lo).
    for (const Collision& c : all) EXPECT_TRUE(c.toi.lo > step || (step == 0 && first.lo == 0)) << describe(c);
    if (first.lo > 0) {
      EXPECT_LT(step, first.lo);
      EXPECT_EQ(std::nextafter(step, 1.0), first.lo);  // the largest double below lo
      ++checked;
      // Exactly, with rational sub-motions: [0, step] is collision-free, [0, hi] is not.
      EXPECT_FALSE(collides_until(s, step)) << "scene " << i;
      EXPECT_TRUE(collides_until(s, first.hi)) << "scene " << i;
    }
  }
  EXPECT_GE(checked, 4);
}

/// The message of the std::invalid_argument that f throws ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, MalformedScenesThrowClearErrors) {
  const Scene good{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {}, {}};
  EXPECT_EQ(error_of([&] { validate(good); }), "");
  Scene s = good;
  s.positions_t1.pop_back();
  EXPECT_NE(error_of([&] { find_collisions(s); }).find("positions_t0 has 3 vertices but positions_t1 has 2"),
            std::string::npos);
  s = good;
  s.triangles = {{0, 1, 3}};
  EXPECT_NE(error_of([&] { earliest_toi(s); }).find("triangle 0 has vertex index 3, out of range [0, 3)"),
            std::string::npos);
  s.triangles = {{0, -1, 2}};
  EXPECT_NE(error_of([&] { is_collision_free(s); }).find("out of range"), std::string::npos);
  s.triangles = {{0, 1, 2}, {2, 1, 2}};
  EXPECT_NE(error_of([&] { max_collision_free_step(s); }).find("triangle 1 repeats vertex index 2"),
            std::string::npos);
  s = good;
  s.positions_t1[1].y = std::nan("");
  EXPECT_NE(error_of([&] { find_collisions(s); }).find("positions_t1[1] has a non-finite coordinate"),
            std::string::npos);
  s = good;
  s.positions_t0[2].z = INFINITY;
  EXPECT_NE(error_of([&] { validate(s); }).find("positions_t0[2]"), std::string::npos);
  s = good;
  s.edges = {{1, 1}};
  EXPECT_NE(error_of([&] { validate(s); }).find("edge 0 repeats vertex index 1"), std::string::npos);
  s.edges = {{0, 5}};
  EXPECT_NE(error_of([&] { validate(s); }).find("edge 0 has vertex index 5"), std::string::npos);
  s = good;
  s.points = {0, 3};
  EXPECT_NE(error_of([&] { validate(s); }).find("point 1 has vertex index 3"), std::string::npos);
}

}  // namespace
}  // namespace exactccd
