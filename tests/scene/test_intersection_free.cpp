// exactccd::intersection_free: hand-made touching, crossing, coplanar and disjoint triangle
// pairs, the adjacency rule, degenerate triangles, and a cross-check of CGAL's exact tests
// against the project's own exact queries (an edge meets a static triangle iff a vertex
// sweeping the edge over [0, 1] hits it).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exactccd/exactccd.hpp"
#include "scenes/procedural_scenes.hpp"

namespace exactccd {
namespace {

using Tri = std::array<int, 3>;

/// Two triangles over six vertices (no shared index): a0 a1 a2 and b0 b1 b2.
bool pair_free(const std::vector<Vec3>& six) { return intersection_free(six, {Tri{0, 1, 2}, Tri{3, 4, 5}}); }

TEST(IntersectionFree, DisjointCrossingTouching) {
  const Vec3 a0{0, 0, 0}, a1{1, 0, 0}, a2{0, 1, 0};
  // Parallel planes.
  EXPECT_TRUE(pair_free({a0, a1, a2, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));
  // Nearly touching from above: a vertex at z = 2^-60 over the interior.
  EXPECT_TRUE(pair_free({a0, a1, a2, {0.25, 0.25, 0x1p-60}, {0.25, 0.25, 1}, {1, 1, 1}}));
  // Crossing: a vertical triangle pierces the interior.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.25, 0.25, -1}, {0.25, 0.25, 1}, {2, 2, 0.5}}));
  // Touching: a vertex exactly on the interior.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.25, 0.25, 0}, {0.25, 0.25, 1}, {1, 1, 1}}));
  // Touching: a vertex exactly on an edge, and exactly on a vertex.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.5, 0, 0}, {0.5, -1, 1}, {0.5, -1, -1}}));
  EXPECT_FALSE(pair_free({a0, a1, a2, {1, 0, 0}, {2, 0, 1}, {2, 1, -1}}));
  // Edge against edge in a single point, (0.5, 0, 0), the triangles in the planes z = 0 and x = 0.5.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, {0.5, -1, 1}}));
  // The same, moved off by 2^-40 along y.
  EXPECT_TRUE(pair_free({a0, a1, a2, {0.5, -0.5 - 0x1p-40, -0.5}, {0.5, 0.5 - 0x1p-40, 0.5}, {0.5, -1, 1}}));
}

TEST(IntersectionFree, Coplanar) {
  const Vec3 a0{0, 0, 0}, a1{1, 0, 0}, a2{0, 1, 0};
  // Overlapping, with no vertex inside the other triangle (a star of David).
  EXPECT_FALSE(pair_free({{0, 0, 0}, {1, 0, 0}, {0.5, 0.9, 0}, {0, 0.6, 0}, {1, 0.6, 0}, {0.5, -0.3, 0}}));
  // One inside the other.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.1, 0.1, 0}, {0.2, 0.1, 0}, {0.1, 0.2, 0}}));
  // Disjoint, across the hypotenuse.
  EXPECT_TRUE(pair_free({a0, a1, a2, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}}));
  // Touching the hypotenuse exactly at one point, and along a segment.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.5, 0.5, 0}, {2, 1, 0}, {1, 2, 0}}));
  EXPECT_FALSE(pair_free({a0, a1, a2, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
}

TEST(IntersectionFree, DegenerateTriangles) {
  const Vec3 a0{0, 0, 0}, a1{1, 0, 0}, a2{0, 1, 0};
  // A collinear "triangle" (a segment) piercing the interior, then beside it.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.25, 0.25, -1}, {0.25, 0.25, 0.5}, {0.25, 0.25, 1}}));
  EXPECT_TRUE(pair_free({a0, a1, a2, {2, 2, -1}, {2, 2, 0.5}, {2, 2, 1}}));
  // Its middle vertex is the extreme one: the hull is [-1, 1], which still pierces.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.25, 0.25, 0.5}, {0.25, 0.25, -1}, {0.25, 0.25, 1}}));
  // A point "triangle" (three equal positions) on the interior, then off it.
  EXPECT_FALSE(pair_free({a0, a1, a2, {0.25, 0.25, 0}, {0.25, 0.25, 0}, {0.25, 0.25, 0}}));
  EXPECT_TRUE(pair_free({a0, a1, a2, {0.25, 0.25, 1}, {0.25, 0.25, 1}, {0.25, 0.25, 1}}));
  // Two point triangles at the same position, and two crossing segments.
  EXPECT_FALSE(pair_free({a0, a0, a0, a0, a0, a0}));
  EXPECT_FALSE(pair_free({{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0.5, 0}}));
  EXPECT_TRUE(pair_free({{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}, {0, 0.5, 1}}));
}

TEST(IntersectionFree, AdjacentTriangles) {
  // A fan around vertex 0: triangles sharing only vertex 0 that meet only there are fine.
  const std::vector<Vec3> fan = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0.5}};
  EXPECT_TRUE(intersection_free(fan, {Tri{0, 1, 2}, Tri{0, 3, 4}}));
  // Sharing vertex 0, with the other triangle's opposite edge (3, 4) through the interior.
  const std::vector<Vec3> through = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, -1}, {0.25, 0.25, 1}};
  EXPECT_FALSE(intersection_free(through, {Tri{0, 1, 2}, Tri{0, 3, 4}}));
  // Sharing vertex 0, coplanar and overlapping near it.
  const std::vector<Vec3> overlap = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0.5, 0}, {0.5, 1, 0}};
  EXPECT_FALSE(intersection_free(overlap, {Tri{0, 1, 2}, Tri{0, 3, 4}}));
  // Sharing an edge: never checked, even folded flat onto each other.
  const std::vector<Vec3> fold = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  EXPECT_TRUE(intersection_free(fold, {Tri{0, 1, 2}, Tri{0, 1, 3}}));
  // The same positions under distinct indices do count: vertex 4 duplicates vertex 2's position.
  const std::vector<Vec3> dup = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0, 1, 0}, {2, 2, 2}};
  EXPECT_FALSE(intersection_free(dup, {Tri{0, 1, 2}, Tri{3, 4, 5}}));
}

TEST(IntersectionFree, MeshesAndBadInput) {
  const scene::MovingMesh sphere = scene::icosphere(2, 1.0), grid = scene::grid(6, 4, 0, 1, 0, 1);
  EXPECT_TRUE(intersection_free(sphere.positions_t0, sphere.triangles));
  EXPECT_TRUE(intersection_free(grid.positions_t0, grid.triangles));
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(intersection_free(p, {Tri{0, 1, 3}}), std::invalid_argument);
  EXPECT_THROW(intersection_free(p, {Tri{0, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(intersection_free({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {Tri{0, 1, 2}}),
               std::invalid_argument);
  EXPECT_TRUE(intersection_free({}, {}));
}

/// Whether the closed segment [u, v] meets the closed static triangle (a, b, c): a vertex
/// sweeping the segment over t in [0, 1] against the static triangle, decided exactly.
bool segment_meets(const Vec3& u, const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c) {
  return vertex_face_ccd(VertexFaceQuery{u, a, b, c, v, a, b, c}, Method::exact);
}

/// Two closed triangles meet iff an edge of one meets the other (see intersection_free.cpp).
bool triangles_meet(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t) {
  for (int i = 0; i < 3; ++i) {
    if (segment_meets(s[i], s[(i + 1) % 3], t[0], t[1], t[2])) return true;
    if (segment_meets(t[i], t[(i + 1) % 3], s[0], s[1], s[2])) return true;
  }
  return false;
}

TEST(IntersectionFree, AgreesWithVertexSweepQueries) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> coord(-2, 2), choice(0, 4);
  int meeting = 0, shared_meeting = 0;
  for (int i = 0; i < 600; ++i) {
    const bool flat = choice(rng) == 0;
    std::vector<Vec3> p(6);
    for (auto& x : p) x = {coord(rng) * 0.5, coord(rng) * 0.5, flat ? 0.0 : coord(rng) * 0.5};
    if (choice(rng) == 0) p[4] = p[1];  // repeated positions across the triangles
    const std::array<Vec3, 3> s{p[0], p[1], p[2]}, t{p[3], p[4], p[5]};
    const bool meet = triangles_meet(s, t);
    meeting += meet;
    EXPECT_EQ(intersection_free(p, {Tri{0, 1, 2}, Tri{3, 4, 5}}), !meet) << "case " << i;
    // The same triangles sharing vertex index 0 (t's first vertex replaced): only the edges
    // opposite the shared vertex count.
    const std::array<Vec3, 3> t0{p[0], p[4], p[5]};
    const bool opposite = segment_meets(p[1], p[2], t0[0], t0[1], t0[2]) || segment_meets(p[4], p[5], p[0], p[1], p[2]);
    shared_meeting += opposite;
    EXPECT_EQ(intersection_free(p, {Tri{0, 1, 2}, Tri{0, 4, 5}}), !opposite) << "shared case " << i;
  }
  EXPECT_GT(meeting, 100);
  EXPECT_GT(shared_meeting, 50);
}

// The streamed, parallel search over the triangles' tree: at every thread count the answer of
// a pairwise check of every two triangles (each pair decided alone by intersection_free of the
// two): meshes of many small random triangles on a coarse grid (touching, coplanar, shared
// vertices), some intersection-free and some not, and a pair that meets placed anywhere.
TEST(IntersectionFree, EveryThreadCountAgreesWithPairwiseChecks) {
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> coord(0, 40), step(-1, 1);
  int free_meshes = 0, meeting_meshes = 0;
  for (int m = 0; m < 40; ++m) {
    std::vector<Vec3> p;
    std::vector<Tri> tris;
    const int n = 30 + 10 * (m % 5);
    for (int t = 0; t < n; ++t) {
      const Vec3 c{coord(rng) * 0.5, coord(rng) * 0.5, (m % 3 == 0 ? 0 : coord(rng)) * 0.5};
      const int v = static_cast<int>(p.size());
      p.push_back(c);
      p.push_back({c.x + 0.5 * step(rng) + 0.5, c.y + 0.5 * step(rng), c.z + 0.5 * step(rng)});
      p.push_back({c.x + 0.5 * step(rng), c.y + 0.5 * step(rng) + 0.5, c.z + 0.5 * step(rng)});
      tris.push_back({v, v + 1, v + 2});
      if (t % 7 == 3) tris.push_back({v, v + 2, static_cast<int>(coord(rng) % (v + 1))});  // shared vertices
    }
    for (auto it = tris.begin(); it != tris.end();)  // no repeated index
      it = ((*it)[0] == (*it)[1] || (*it)[0] == (*it)[2] || (*it)[1] == (*it)[2]) ? tris.erase(it) : it + 1;
    bool want = true;
    for (std::size_t i = 0; i < tris.size() && want; ++i)
      for (std::size_t j = i + 1; j < tris.size() && want; ++j) want = intersection_free(p, {tris[i], tris[j]});
    (want ? free_meshes : meeting_meshes) += 1;
    for (unsigned threads : {0u, 1u, 2u, 3u, 8u})
      EXPECT_EQ(intersection_free(p, tris, threads), want) << "mesh " << m << " threads " << threads;
  }
  EXPECT_GT(free_meshes, 5);
  EXPECT_GT(meeting_meshes, 5);
}

}  // namespace
}  // namespace exactccd
