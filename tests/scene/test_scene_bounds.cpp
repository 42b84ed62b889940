// The certified pieces under the scene functions: the broad phase (every overlapping pair of
// swept boxes, strips and all) and the time bounds earliest_toi prunes with (boxes over
// [0, h], volume sign over [0, h]), which must never drop a contact at or before h.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/time_bounds.hpp"
#include "tests/test_support.hpp"

namespace exactccd {
namespace {

std::optional<TimeInterval> vertex_face_or_edge_edge_toi(const VertexFaceQuery& q) { return vertex_face_toi(q); }
std::optional<TimeInterval> vertex_face_or_edge_edge_toi(const EdgeEdgeQuery& q) { return edge_edge_toi(q); }

/// The pruning bounds of earliest_toi never drop a contact at or before h: for queries with an
/// exact time of impact t <= hi, neither bound may claim "no contact in [0, h]" for h >= hi
/// (h = hi is the tightest case), nor for random h whenever hi <= h.
template <class Query>
void check_time_bounds(const Query& q, double h, const std::string& what) {
  const auto r = rows(q);
  const auto toi = vertex_face_or_edge_edge_toi(q);
  if (!toi || toi->hi > h) return;
  EXPECT_FALSE(scene::never_coplanar_until({r[0], r[1], r[2], r[3]}, {r[4], r[5], r[6], r[7]}, h)) << what;
  scene::Box first = scene::empty_box(), second = scene::empty_box();
  const int split = std::is_same_v<Query, VertexFaceQuery> ? 1 : 2;  // the first primitive's vertices
  for (int i = 0; i < 4; ++i) scene::add_vertex_until(i < split ? first : second, r[i], r[i + 4], h);
  EXPECT_TRUE(scene::overlap(first, second)) << what;
}

TEST(SceneBounds, TimeBoundsNeverDropAnEarlierContact) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  int bounded = 0;
  const auto vf = testing::degenerate_queries<VertexFaceQuery>(1, 3000);
  const auto ee = testing::degenerate_queries<EdgeEdgeQuery>(2, 3000);
  for (std::size_t i = 0; i < vf.size(); ++i) {
    if (const auto toi = vertex_face_toi(vf[i])) {
      ++bounded;
      check_time_bounds(vf[i], toi->hi, "vf" + std::to_string(i));
      check_time_bounds(vf[i], std::min(1.0, toi->hi + unit(rng)), "vf" + std::to_string(i));
    }
    if (const auto toi = edge_edge_toi(ee[i])) {
      ++bounded;
      check_time_bounds(ee[i], toi->hi, "ee" + std::to_string(i));
      check_time_bounds(ee[i], std::min(1.0, toi->hi + unit(rng)), "ee" + std::to_string(i));
    }
  }
  EXPECT_GT(bounded, 500);
  // And they do prune: a vertex falling through a triangle at t = 0.5 is certified not to touch
  // it before t = 0.25.
  const VertexFaceQuery fall{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                             {0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto r = rows(fall);
  EXPECT_TRUE(scene::never_coplanar_until({r[0], r[1], r[2], r[3]}, {r[4], r[5], r[6], r[7]}, 0.25));
  EXPECT_FALSE(scene::never_coplanar_until({r[0], r[1], r[2], r[3]}, {r[4], r[5], r[6], r[7]}, 0.5));
  // The same fall scaled by 2^-1000 (every coordinate exact): stage 1's bound does not apply to
  // such tiny entries, and the time bound retries on the points scaled back towards 1.
  std::array<Vec3, 8> tiny;
  for (int i = 0; i < 8; ++i)
    tiny[i] = {std::ldexp(r[i].x, -1000), std::ldexp(r[i].y, -1000), std::ldexp(r[i].z, -1000)};
  EXPECT_TRUE(scene::never_coplanar_until({tiny[0], tiny[1], tiny[2], tiny[3]}, {tiny[4], tiny[5], tiny[6], tiny[7]}, 0.25));
  EXPECT_FALSE(scene::never_coplanar_until({tiny[0], tiny[1], tiny[2], tiny[3]}, {tiny[4], tiny[5], tiny[6], tiny[7]}, 0.5));
  scene::Box point = scene::empty_box(), triangle = scene::empty_box();
  scene::add_vertex_until(point, r[0], r[4], 0.25);
  for (int i = 1; i < 4; ++i) scene::add_vertex_until(triangle, r[i], r[i + 4], 0.25);
  EXPECT_FALSE(scene::overlap(point, triangle));
  EXPECT_TRUE(point.lo[2] <= 0.5 && point.lo[2] > 0.5 - 1e-14);  // x(0.25) = 0.5, padded
}

// The box over [0, h] holds the exact position at h, whatever the rounding: random magnitudes
// from subnormal to 1e300, opposite signs, h near 0 and 1.
TEST(SceneBounds, BoxUntilHoldsTheExactPosition) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> exponent(-1074, 1000), sign(0, 1);
  const auto random_double = [&] { return (sign(rng) ? -1 : 1) * std::ldexp(1 + unit(rng), exponent(rng)); };
  for (int i = 0; i < 20000; ++i) {
    const double a = random_double(), b = i % 3 ? random_double() : a * (1 + unit(rng) * 0x1p-40);
    const double h = i % 5 == 0 ? std::nextafter(1.0, 0.0) : i % 5 == 1 ? unit(rng) * 1e-20 : unit(rng);
    scene::Box box = scene::empty_box();
    scene::add_vertex_until(box, {a, 0, 0}, {b, 0, 0}, h);
    const mpq_class exact = mpq_class(a) + mpq_class(h) * (mpq_class(b) - mpq_class(a));
    ASSERT_TRUE(mpq_class(box.lo[0]) <= exact && exact <= mpq_class(box.hi[0]))
        << a << " " << b << " " << h << ": [" << box.lo[0] << ", " << box.hi[0] << "]";
    ASSERT_TRUE(box.lo[0] <= a && a <= box.hi[0]);
  }
  // Overflowing differences fall back to the hull of both ends.
  scene::Box box = scene::empty_box();
  const double big = std::numeric_limits<double>::max();
  scene::add_vertex_until(box, {big, -big, 0}, {-big, big, 0}, 0.5);
  EXPECT_TRUE(box.lo[0] == -big && box.hi[0] == big && box.lo[1] == -big && box.hi[1] == big);
}

/// find_candidates against every pair of overlapping swept boxes, on scenes large enough for
/// the strips of the sweep: random small triangles, a few huge ones, flat and point-like
/// scenes, and coordinates near the overflow threshold.
TEST(SceneBounds, BroadPhaseFindsEveryOverlappingPair) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int variant = 0; variant < 5; ++variant) {
    Scene s;
    const double scale = variant == 4 ? 1e308 : 1;  // 1e308: extents overflow
    for (int i = 0; i < 300; ++i) {
      Vec3 p{unit(rng) * scale, unit(rng) * scale, variant == 2 ? 0 : unit(rng) * scale};
      if (variant == 3) p = {0.5, 0.5, 0.5};  // every box the same point
      const Vec3 d{unit(rng) * 0.05 * scale, unit(rng) * 0.05 * scale, variant == 2 ? 0 : unit(rng) * 0.05 * scale};
      s.positions_t0.push_back(p);
      s.positions_t1.push_back(variant == 3 ? p : Vec3{p.x + d.x, p.y + d.y, p.z + d.z});
    }
    std::uniform_int_distribution<int> pick(0, 299);
    for (int t = 0; t < 200; ++t) {
      const int v = pick(rng);
      // Mostly small triangles (near neighbours in index), a few spanning the scene.
      std::array<int, 3> tri{v, (v + 1 + (t % 17 == 0 ? pick(rng) : 0)) % 300, (v + 2) % 300};
      if (tri[1] == tri[0] || tri[1] == tri[2]) tri[1] = (v + 3) % 300;
      s.triangles.push_back(tri);
    }
    const scene::ScenePrimitives prim = scene::scene_primitives(s);
    std::vector<std::array<int, 2>> vf, ee;
    const auto box = [&](const int* v, int n) { return scene::swept_box(s.positions_t0, s.positions_t1, v, n); };
    for (int v : prim.vertices)
      for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
        const auto& f = s.triangles[t];
        if (f[0] != v && f[1] != v && f[2] != v && scene::overlap(box(&v, 1), box(f.data(), 3))) vf.push_back({v, t});
      }
    for (int i = 0; i < static_cast<int>(prim.edges.size()); ++i)
      for (int j = i + 1; j < static_cast<int>(prim.edges.size()); ++j) {
        const auto &a = prim.edges[i], &b = prim.edges[j];
        if (a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1] && scene::overlap(box(a.data(), 2), box(b.data(), 2)))
          ee.push_back({i, j});
      }
    EXPECT_EQ(prim.candidates.vertex_face, vf) << "variant " << variant;
    EXPECT_EQ(prim.candidates.edge_edge, ee) << "variant " << variant;
    EXPECT_GT(vf.size() + ee.size(), 100u) << "variant " << variant;
  }
}

}  // namespace
}  // namespace exactccd
