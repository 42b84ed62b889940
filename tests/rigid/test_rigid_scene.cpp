// The rigid scene functions (docs/design.md 9.5) against brute force over every pair of
// primitives of different bodies, each answered by a primitive query: the same colliding pairs
// with the same TOIs, at d = 0 and d > 0, with tmax < 1, on 1 and 3 threads; the earliest TOI and
// the largest collision-free step derived from them; malformed bodies refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <tuple>

#include "exactccd/rigid.hpp"
#include "scenes/rigid_sim.hpp"

namespace exactccd {
namespace {

RigidBody body_of(const rigid_sim::Body& b, const RigidPose& t0, const RigidPose& t1) {
  return {b.vertices, b.triangles, t0, t1};
}

std::vector<RigidCollision> brute_force(const std::vector<RigidBody>& bodies, const CcdParams& p, Method m) {
  std::vector<RigidCollision> out;
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (a == b) continue;
      const RigidBody &A = bodies[a], &B = bodies[b];
      std::vector<int> used;
      for (const auto& t : A.triangles) used.insert(used.end(), t.begin(), t.end());
      std::sort(used.begin(), used.end());
      used.erase(std::unique(used.begin(), used.end()), used.end());
      for (const int v : used)
        for (std::size_t t = 0; t < B.triangles.size(); ++t) {
          const auto& tri = B.triangles[t];
          const auto toi = rigid_vertex_face_toi({A.t0, A.t1, B.t0, B.t1, A.vertices[v], B.vertices[tri[0]],
                                                  B.vertices[tri[1]], B.vertices[tri[2]]}, p, m);
          if (!toi) continue;
          RigidCollision c;
          c.kind = CollisionKind::vertex_face, c.body_a = int(a), c.body_b = int(b), c.vertex = v, c.triangle = int(t);
          c.toi = *toi;
          out.push_back(c);
        }
    }
  std::sort(out.begin(), out.end(), [](const RigidCollision& x, const RigidCollision& y) {
    return std::tie(x.body_a, x.vertex, x.body_b, x.triangle) < std::tie(y.body_a, y.vertex, y.body_b, y.triangle);
  });
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const auto ea = rigid_sim::unique_edges({bodies[a].vertices, bodies[a].triangles});
      const auto eb = rigid_sim::unique_edges({bodies[b].vertices, bodies[b].triangles});
      const RigidBody &A = bodies[a], &B = bodies[b];
      for (const auto& e : ea)
        for (const auto& f : eb) {
          const auto toi = rigid_edge_edge_toi({A.t0, A.t1, B.t0, B.t1, A.vertices[e[0]], A.vertices[e[1]],
                                                B.vertices[f[0]], B.vertices[f[1]]}, p, m);
          if (!toi) continue;
          RigidCollision c;
          c.kind = CollisionKind::edge_edge, c.body_a = int(a), c.body_b = int(b), c.edge_a = e, c.edge_b = f;
          c.toi = *toi;
          out.push_back(c);
        }
    }
  return out;
}

bool same(const RigidCollision& x, const RigidCollision& y) {
  return x.kind == y.kind && x.body_a == y.body_a && x.body_b == y.body_b && x.vertex == y.vertex &&
         x.triangle == y.triangle && x.edge_a == y.edge_a && x.edge_b == y.edge_b && x.toi.lo == y.toi.lo &&
         x.toi.hi == y.toi.hi;
}

/// Three small bodies (a tetrahedron, a box, a tilted square) tumbling through each other.
std::vector<RigidBody> tumbling_bodies(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const auto pose = [&](double spread) {
    Quaternion q{1 + u(rng), u(rng), u(rng), u(rng)};
    return RigidPose{{spread * u(rng), spread * u(rng), spread * u(rng)}, q};
  };
  const auto moved = [&](const RigidPose& p) {
    RigidPose r{{p.c.x + 0.6 * u(rng), p.c.y + 0.6 * u(rng), p.c.z + 0.6 * u(rng)},
                {p.q.w + 0.4 * u(rng), p.q.x + 0.4 * u(rng), p.q.y + 0.4 * u(rng), p.q.z + 0.4 * u(rng)}};
    if (p.q.w * r.q.w + p.q.x * r.q.x + p.q.y * r.q.y + p.q.z * r.q.z <= 0) r.q = p.q;
    return r;
  };
  const rigid_sim::Body tetra{{{0, 0, 0}, {0.7, 0, 0}, {0, 0.7, 0}, {0, 0, 0.7}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  rigid_sim::Body box;
  for (int i = 0; i < 8; ++i) box.vertices.push_back({i & 1 ? 0.3 : -0.3, i & 2 ? 0.3 : -0.3, i & 4 ? 0.3 : -0.3});
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) box.triangles.push_back({f[0], f[1], f[2]}), box.triangles.push_back({f[0], f[2], f[3]});
  const rigid_sim::Body square{{{-0.8, -0.8, 0}, {0.8, -0.8, 0}, {0.8, 0.8, 0}, {-0.8, 0.8, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  std::vector<RigidBody> out;
  for (const rigid_sim::Body* b : {&tetra, static_cast<const rigid_sim::Body*>(&box), &square}) {
    const RigidPose p0 = pose(0.9);
    out.push_back(body_of(*b, p0, moved(p0)));
  }
  return out;
}

TEST(RigidScene, FindCollisionsEqualsBruteForce) {
  std::mt19937_64 rng(5);
  int scenes_with_collisions = 0, total = 0;
  for (int s = 0; s < 6; ++s) {
    const std::vector<RigidBody> bodies = tumbling_bodies(rng);
    for (const CcdParams& p : {CcdParams{}, CcdParams{0.05, 1.0}, CcdParams{0.0, 0.5}}) {
      const std::vector<RigidCollision> want = brute_force(bodies, p, Method::exact);
      for (const unsigned threads : {1u, 3u}) {
        const std::vector<RigidCollision> got = rigid_find_collisions(bodies, SceneOptions{threads, p.min_distance, p.tmax});
        ASSERT_EQ(got.size(), want.size()) << "scene " << s << " d " << p.min_distance << " tmax " << p.tmax;
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], want[i])) << "scene " << s << " pair " << i;
      }
      const std::optional<TimeInterval> earliest = rigid_earliest_toi(bodies, SceneOptions{2, p.min_distance, p.tmax});
      ASSERT_EQ(earliest.has_value(), !want.empty());
      if (earliest) {
        TimeInterval best = want[0].toi;
        for (const RigidCollision& c : want)
          if (c.toi.lo < best.lo || (c.toi.lo == best.lo && c.toi.hi < best.hi)) best = c.toi;
        EXPECT_EQ(earliest->lo, best.lo);
        EXPECT_EQ(earliest->hi, best.hi);
        EXPECT_EQ(rigid_max_collision_free_step(bodies, SceneOptions{2, p.min_distance, p.tmax}),
                  best.lo <= 0 ? 0.0 : std::nextafter(best.lo, 0.0));
      } else {
        EXPECT_EQ(rigid_max_collision_free_step(bodies, SceneOptions{2, p.min_distance, p.tmax}), p.tmax);
      }
      scenes_with_collisions += !want.empty();
      ++total;
    }
  }
  EXPECT_GT(scenes_with_collisions, total / 4);
  EXPECT_LT(scenes_with_collisions, total);
}

TEST(RigidScene, TheTumblingBoxStepsEqualBruteForce) {
  // Every sixth step of the bundled box scene (tools/lib/scenes/rigid_sim.hpp), brute force by the
  // filtered method (equal to the exact one: test_rigid_filtered): the broad phase drops no pair.
  rigid_sim::Scene scene = rigid_sim::box_on_plane();
  int collisions = 0;
  for (std::size_t step = 0; step + 1 < scene.poses.size(); step += 6) {
    std::vector<RigidBody> bodies;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      bodies.push_back(body_of(scene.bodies[b], scene.poses[step][b], scene.poses[step + 1][b]));
    const auto want = brute_force(bodies, CcdParams{}, Method::filtered);
    const auto got = rigid_find_collisions(bodies, SceneOptions{2, 0.0, 1.0});
    ASSERT_EQ(got.size(), want.size()) << "step " << step;
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], want[i])) << "step " << step;
    collisions += int(want.size());
  }
  EXPECT_GT(collisions, 0);
}

TEST(RigidScene, TightSweptBoxesDropNoPair) {
  // Where the swept boxes are tight: (1) a vertex (5, 0, 0) turning about z with q(t) = (1, 0, 0,
  // t - 1/2), from -2 atan(1/2) to +2 atan(1/2) (cos = 3/5): its chord stays at x = 3, its arc
  // reaches x = 5 (at t = 1/2) and crosses the plane x = 4 of a large static triangle at y = -3
  // (inside its section |y| <= 16/3 at z = 0): a collision that a box of the chord alone misses;
  // (2) two static triangles 3/4 apart, asked with d = 1: within d though their boxes do not touch.
  const RigidBody turning{{{5, 0, 0}, {0, 0, -0.1}, {0, 0, 0.1}}, {{0, 1, 2}},
                          {{0, 0, 0}, {1, 0, 0, -0.5}}, {{0, 0, 0}, {1, 0, 0, 0.5}}};
  const RigidBody wall{{{4, -8, -1}, {4, 8, -1}, {4, 0, 2}}, {{0, 1, 2}}, {{0, 0, 0}, {1, 0, 0, 0}},
                       {{0, 0, 0}, {1, 0, 0, 0}}};
  const std::vector<RigidBody> bulge{turning, wall};
  const auto want = brute_force(bulge, CcdParams{}, Method::exact);
  ASSERT_FALSE(want.empty());
  const auto got = rigid_find_collisions(bulge);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], want[i]));
  const RigidBody low{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{0, 0, 0}, {1, 0, 0, 0}}, {{0, 0, 0}, {1, 0, 0, 0}}};
  const RigidBody high{{{0, 0, 0.75}, {1, 0, 0.75}, {0, 1, 0.75}}, {{0, 1, 2}}, {{0, 0, 0}, {1, 0, 0, 0}},
                       {{0, 0, 0}, {1, 0, 0, 0}}};
  const std::vector<RigidBody> near{low, high};
  const auto want_near = brute_force(near, CcdParams{1.0, 1.0}, Method::exact);
  ASSERT_FALSE(want_near.empty());
  EXPECT_EQ(rigid_find_collisions(near, SceneOptions{1, 1.0, 1.0}).size(), want_near.size());
  EXPECT_TRUE(rigid_find_collisions(near, SceneOptions{1, 0.5, 1.0}).empty());
}

TEST(RigidScene, ExtremeMagnitudesChangeNothing) {
  // Lengths times 2^-1000 or 2^900 and each body's quaternions times 2^1000 or 2^-1060 (exact):
  // the same question (docs/design.md 9.6), so the same pairs and TOIs as the plain scene; the
  // swept boxes must neither overflow nor lose the curves.
  std::mt19937_64 rng(13);
  int scenes = 0;
  for (int s = 0; s < 3; ++s) {
    const std::vector<RigidBody> bodies = tumbling_bodies(rng);
    const auto want = rigid_find_collisions(bodies, SceneOptions{2, 0.0, 1.0});
    for (const int e : {-1000, 900}) {
      std::vector<RigidBody> scaled = bodies;
      bool exact = true;
      const auto x2 = [&](double v, int k) {
        const double r = std::ldexp(v, k);
        exact = exact && std::ldexp(r, -k) == v;
        return r;
      };
      for (std::size_t b = 0; b < scaled.size(); ++b) {
        RigidBody& x = scaled[b];
        for (Vec3& v : x.vertices) v = {x2(v.x, e), x2(v.y, e), x2(v.z, e)};
        for (RigidPose* p : {&x.t0, &x.t1}) {
          p->c = {x2(p->c.x, e), x2(p->c.y, e), x2(p->c.z, e)};
          const int f = b % 2 ? 1000 : -1000;
          p->q = {x2(p->q.w, f), x2(p->q.x, f), x2(p->q.y, f), x2(p->q.z, f)};
        }
      }
      if (!exact) continue;  // only exact scalings keep the question
      const auto got = rigid_find_collisions(scaled, SceneOptions{2, 0.0, 1.0});
      ASSERT_EQ(got.size(), want.size()) << "scene " << s << " 2^" << e;
      for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same(got[i], want[i])) << "scene " << s << " 2^" << e;
    }
    scenes += !want.empty();
  }
  EXPECT_GT(scenes, 0);
}

TEST(RigidScene, MalformedBodiesAreRefused) {
  const RigidBody ok{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{0, 0, 0}, {1, 0, 0, 0}}, {{0, 0, 0}, {1, 0, 0, 0}}};
  auto bad = ok;
  bad.triangles = {{0, 1, 3}};
  EXPECT_THROW(rigid_find_collisions({ok, bad}), std::invalid_argument);
  bad = ok;
  bad.triangles = {{0, 1, 1}};
  EXPECT_THROW(rigid_earliest_toi({ok, bad}), std::invalid_argument);
  bad = ok;
  bad.vertices[1].y = std::nan("");
  EXPECT_THROW(rigid_max_collision_free_step({bad, ok}), std::invalid_argument);
  bad = ok;
  bad.t1.q = {-3, 0, 0, 0};
  EXPECT_THROW(rigid_find_collisions({ok, bad}), std::invalid_argument);
  EXPECT_THROW(rigid_find_collisions({ok, ok}, SceneOptions{1, -1.0, 1.0}), std::invalid_argument);
  EXPECT_NO_THROW(rigid_find_collisions({ok, ok}));
}

TEST(RigidScene, ASetCancellationFlagStopsEveryFunction) {
  // SceneOptions::cancel as in the linear scene functions (what Python's Ctrl-C sets): set, the
  // call throws Cancelled on one thread and on several; clear, it answers.
  rigid_sim::Scene scene = rigid_sim::box_on_plane();
  std::vector<RigidBody> bodies;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    bodies.push_back(body_of(scene.bodies[b], scene.poses[0][b], scene.poses[1][b]));
  for (const unsigned threads : {1u, 2u}) {
    std::atomic<bool> flag{true};
    SceneOptions o{threads, 0.0, 1.0};
    o.cancel = &flag;
    EXPECT_THROW(rigid_find_collisions(bodies, o), Cancelled) << threads;
    EXPECT_THROW(rigid_earliest_toi(bodies, o), Cancelled) << threads;
    EXPECT_THROW(rigid_max_collision_free_step(bodies, o), Cancelled) << threads;
    flag = false;
    EXPECT_EQ(rigid_find_collisions(bodies, o).size(), rigid_find_collisions(bodies, SceneOptions{threads, 0.0, 1.0}).size());
  }
}

}  // namespace
}  // namespace exactccd
