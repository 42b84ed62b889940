// The bounding-volume-hierarchy broad phase (lib/scene/candidate_finder.hpp, box_tree.hpp) and
// the reusable exactccd::SceneBroadPhase: exactly the candidates of the serial sort-and-sweep it
// replaced (sweep_candidates) and of brute force over all pairs, at 1, 2, 3 and 8 threads, on
// random, degenerate and procedural scenes, d = 0 and d > 0, tmax = 1 and < 1; a refitted
// SceneBroadPhase gives what a new one gives; BoxTree's pair traversal (of a tree against
// itself and against another) reports every overlapping pair once, against brute force; the
// scene functions give what the per-pair functions give over the reference candidates, at every
// thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "exactccd/exactccd.hpp"
#include "scene/box_tree.hpp"
#include "scene/broad_phase.hpp"
#include "scene/float_box.hpp"
#include "scene/mesh.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

constexpr unsigned kThreadCounts[] = {1, 2, 3, 8};

/// Whether two lists of vertex boxes' hulls overlap, written out without the library's helpers.
bool hulls_overlap(const std::vector<scene::Box>& boxes, const std::vector<int>& a, const std::vector<int>& b) {
  for (int k = 0; k < 3; ++k) {
    double alo = boxes[a[0]].lo[k], ahi = boxes[a[0]].hi[k], blo = boxes[b[0]].lo[k], bhi = boxes[b[0]].hi[k];
    for (int v : a) alo = std::min(alo, boxes[v].lo[k]), ahi = std::max(ahi, boxes[v].hi[k]);
    for (int v : b) blo = std::min(blo, boxes[v].lo[k]), bhi = std::max(bhi, boxes[v].hi[k]);
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
}

bool share(const std::vector<int>& a, const std::vector<int>& b) {
  for (int x : a)
    for (int y : b)
      if (x == y) return true;
  return false;
}

/// Every pair of every kind by brute force over all pairs (sorted, as Candidates are).
scene::Candidates brute_force(const std::vector<scene::Box>& boxes, const std::vector<scene::Triangle>& triangles,
                              const std::vector<scene::Edge>& edges, const std::vector<int>& vertices,
                              const std::vector<int>& points) {
  scene::Candidates c;
  for (int v : vertices)
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      const std::vector<int> tri(triangles[t].begin(), triangles[t].end());
      if (!share({v}, tri) && hulls_overlap(boxes, {v}, tri)) c.vertex_face.push_back({v, t});
    }
  for (int i = 0; i < static_cast<int>(edges.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(edges.size()); ++j) {
      const std::vector<int> a(edges[i].begin(), edges[i].end()), b(edges[j].begin(), edges[j].end());
      if (!share(a, b) && hulls_overlap(boxes, a, b)) c.edge_edge.push_back({i, j});
    }
  for (int p : points)
    for (int e = 0; e < static_cast<int>(edges.size()); ++e)
      if (hulls_overlap(boxes, {p}, {edges[e][0], edges[e][1]})) c.point_edge.push_back({p, e});
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (hulls_overlap(boxes, {points[i]}, {points[j]})) c.point_point.push_back({points[i], points[j]});
  return c;
}

void expect_same(const scene::Candidates& got, const scene::Candidates& want, const std::string& what) {
  EXPECT_EQ(got.vertex_face, want.vertex_face) << what;
  EXPECT_EQ(got.edge_edge, want.edge_edge) << what;
  EXPECT_EQ(got.point_edge, want.point_edge) << what;
  EXPECT_EQ(got.point_point, want.point_point) << what;
}

std::size_t total(const scene::Candidates& c) {
  return c.vertex_face.size() + c.edge_edge.size() + c.point_edge.size() + c.point_point.size();
}

/// The questions tried: (d, tmax).
const std::vector<CcdParams> kParams{{0.0, 1.0}, {0.0, 0.4}, {0.05, 1.0}, {0.02, 0.7}};

/// Checks find_candidates at every thread count against sweep_candidates (and brute force when
/// `brute` is set) for the scene under every question; returns the number of candidates seen.
std::size_t check_scene(const Scene& s, bool brute, const std::string& name) {
  std::size_t seen = 0;
  for (const CcdParams& params : kParams) {
    const scene::ScenePrimitives p = scene::scene_topology(s, params);
    const auto boxes = scene::vertex_boxes(s.positions_t0, s.positions_t1, params);
    const scene::Candidates reference = scene::sweep_candidates(boxes, s.triangles, p.edges, p.vertices, p.points);
    seen += total(reference);
    const std::string what = name + " d=" + std::to_string(params.min_distance) + " tmax=" + std::to_string(params.tmax);
    if (brute) expect_same(reference, brute_force(boxes, s.triangles, p.edges, p.vertices, p.points), what + " sweep");
    for (unsigned threads : kThreadCounts)
      expect_same(scene::find_candidates(boxes, s.triangles, p.edges, p.vertices, p.points, threads), reference,
                  what + " threads=" + std::to_string(threads));
  }
  return seen;
}

Scene scene_of(const scene::MovingMesh& m) {
  Scene s;
  s.positions_t0 = m.positions_t0;
  s.positions_t1 = m.positions_t1;
  s.triangles = m.triangles;
  return s;
}

TEST(BroadPhase, RandomAndDegenerateScenesMatchSweepAndBruteForce) {
  std::mt19937_64 rng(1414);
  std::size_t seen = 0;
  for (int round = 0; round < 40; ++round) {
    const bool degenerate = round % 2 == 1;
    // Up to ~300 primitives: more than one tree leaf level, and the strips of the sweep (>= 64 boxes).
    const int n = 8 + round * 3;
    const Scene s = testing::random_scene(rng, n, n, n / 4, n / 3, degenerate);
    seen += check_scene(s, true, "round " + std::to_string(round));
  }
  EXPECT_GT(seen, 1000u);  // the comparisons were not over empty lists
}

TEST(BroadPhase, EmptyAndTinyScenes) {
  Scene empty;
  check_scene(empty, true, "empty");
  Scene one;
  one.positions_t0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}};
  one.positions_t1 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 1}};
  one.triangles = {{0, 1, 2}};
  one.points = {3};
  // By hand: point 3 crosses z = 0 at t = 0.5 inside the triangle. d = 0, tmax = 1: VF {3, 0}.
  // d = 0, tmax = 0.4: its z reaches only -0.2, nothing. d = 0.05 and d = 0.02, tmax = 0.7
  // (z up to 0.4): VF {3, 0}, and PE {3, edge (1, 2)}, whose box [0, 1]^2 x {0} grown by d holds
  // (0.2, 0.2, 0) (edges (0, 1) and (0, 2) lie at y = 0 and x = 0, 0.2 > d away): 1 + 0 + 2 + 2.
  EXPECT_EQ(check_scene(one, true, "one triangle"), 5u);
}

TEST(BroadPhase, ProceduralScenesMatchSweep) {
  std::size_t seen = 0;
  for (const char* name : {"cloth", "strip", "fold", "pile"}) {
    const Scene s = scene_of(scene::procedural_scene(name, 12, 3));
    seen += check_scene(s, false, name);
  }
  EXPECT_GT(seen, 10000u);
}

// The trees keep float boxes rounded outwards (float_box.hpp): boxes a few double ulps apart
// (far below a float's resolution), exactly touching, and overlapping by as little, at
// magnitudes from 2^-60 to 2^60, must give exactly brute force's candidates on the doubles.
TEST(BroadPhase, BelowFloatResolutionMatchesBruteForce) {
  std::mt19937_64 rng(2323);
  std::uniform_int_distribution<int> gap(-2, 2), axis(0, 2);
  // Scales of 1.1 and 3.3 times powers of two: the coordinates are doubles that no float
  // represents, so every bound of the trees is rounded.
  for (const double scale : {0x1p-60 * 1.1, 1.1, 3.3, 0x1p60 * 1.1}) {
    Scene s;
    for (int k = 0; k < 60; ++k) {
      // Edge pairs along a line: edge k ends where edge k + 1 starts, plus a few ulps of the
      // double (not of the float) apart, touching or overlapping; on a random axis.
      const int v = static_cast<int>(s.positions_t0.size());
      const int a = axis(rng);
      const double start = scale * (1 + 4 * k), end = scale * (3 + 4 * k);
      double next = end;
      for (int g = gap(rng); g != 0; g += g > 0 ? -1 : 1) next = std::nextafter(next, g > 0 ? 1e300 : -1e300);
      const auto at = [&](double x) {
        Vec3 p{scale * k, scale * 0.5, -scale * k};
        (a == 0 ? p.x : a == 1 ? p.y : p.z) = x;
        return p;
      };
      s.positions_t0.insert(s.positions_t0.end(), {at(start), at(end), at(next), at(next + scale)});
      s.positions_t1.insert(s.positions_t1.end(), {at(start), at(end), at(next), at(next + scale)});
      s.edges.push_back({v, v + 1});
      s.edges.push_back({v + 2, v + 3});
    }
    check_scene(s, true, "scale " + std::to_string(scale));
  }
}

TEST(BroadPhase, ProceduralSceneMatchesBruteForce) {
  const Scene s = scene_of(scene::procedural_scene("fold", 6, 2));
  EXPECT_GT(check_scene(s, true, "fold 6"), 100u);
}

/// A copy of the scene with its positions at t = 1 moved: `shift` added to every other vertex's.
std::vector<Vec3> moved(const Scene& s, double shift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(-shift, shift);
  std::vector<Vec3> x1 = s.positions_t1;
  for (std::size_t v = 0; v < x1.size(); v += 2) x1[v] = {x1[v].x + jitter(rng), x1[v].y + jitter(rng), x1[v].z + jitter(rng)};
  return x1;
}

TEST(SceneBroadPhase, RefitGivesTheCandidatesOfARebuild) {
  std::mt19937_64 rng(77);
  for (const char* name : {"cloth", "fold", "pile"}) {
    Scene s = scene_of(scene::procedural_scene(name, 10, 5));
    s.points = {0, 1, 2};
    for (const CcdParams& params : kParams)
      for (unsigned threads : kThreadCounts) {
        const SceneOptions options{threads, params.min_distance, params.tmax};
        SceneBroadPhase reused(s, options);
        // A line search: shorter and shorter steps from the same t = 0, then a far jump (the
        // tree order of the first fit is now poor: still exact).
        for (double shift : {0.05, 0.01, 0.0, 0.3}) {
          Scene now = s;
          now.positions_t1 = moved(s, shift, rng);
          const auto before = reused.candidates();
          reused.update(now.positions_t1);
          const SceneBroadPhase rebuilt(now, options);
          const std::string what = std::string(name) + " shift=" + std::to_string(shift) +
                                   " threads=" + std::to_string(threads);
          expect_same(reused.candidates(), rebuilt.candidates(), what + " vs rebuild");
          // And both against the serial sweep of the new positions.
          const scene::ScenePrimitives p = scene::scene_topology(now, params);
          expect_same(reused.candidates(),
                      scene::sweep_candidates(scene::vertex_boxes(now.positions_t0, now.positions_t1, params),
                                              now.triangles, p.edges, p.vertices, p.points),
                      what + " vs sweep");
          EXPECT_EQ(reused.edges(), p.edges);
          ASSERT_EQ(reused.scene().positions_t1.size(), now.positions_t1.size());
          for (std::size_t v = 0; v < now.positions_t1.size(); ++v)
            EXPECT_TRUE(reused.scene().positions_t1[v].x == now.positions_t1[v].x &&
                        reused.scene().positions_t1[v].y == now.positions_t1[v].y &&
                        reused.scene().positions_t1[v].z == now.positions_t1[v].z);
          if (shift >= 0.05) {
            EXPECT_NE(before.edge_edge, reused.candidates().edge_edge) << what;  // the update mattered
          }
        }
      }
  }
}

TEST(SceneBroadPhase, RejectsBadInput) {
  Scene s = scene_of(scene::procedural_scene("fold", 4, 1));
  SceneBroadPhase b(s);
  const auto before = b.candidates();
  EXPECT_THROW(b.update(std::vector<Vec3>(3)), std::invalid_argument);
  std::vector<Vec3> bad = s.positions_t1;
  bad[1].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(b.update(bad), std::invalid_argument);
  expect_same(b.candidates(), before, "unchanged after a refused update");
  EXPECT_THROW(SceneBroadPhase(s, SceneOptions{1, -1.0, 1.0}), std::invalid_argument);
  s.triangles[0][1] = s.triangles[0][0];
  EXPECT_THROW(SceneBroadPhase{s}, std::invalid_argument);
}

/// find_collisions at every thread count equals the per-pair functions over the reference
/// (sweep) candidates: same pairs, same times of impact.
TEST(BroadPhase, SceneFunctionsUnchangedAtEveryThreadCount) {
  for (const char* name : {"cloth", "fold", "pile"}) {
    const Scene s = scene_of(scene::procedural_scene(name, 16, 1));
    for (const CcdParams& params : {CcdParams{0.0, 1.0}, CcdParams{0.001, 0.8}}) {
      const scene::ScenePrimitives p = scene::scene_topology(s, params);
      const scene::Candidates ref = scene::sweep_candidates(scene::vertex_boxes(s.positions_t0, s.positions_t1, params),
                                                            s.triangles, p.edges, p.vertices, p.points);
      std::vector<Collision> want;
      for (const auto& [v, t] : ref.vertex_face)
        if (const auto toi = vertex_face_toi(scene::vertex_face_query(s, v, t), params)) {
          Collision c;
          c.kind = CollisionKind::vertex_face;
          c.vertex = v;
          c.triangle = t;
          c.toi = *toi;
          want.push_back(c);
        }
      for (const auto& [i, j] : ref.edge_edge)
        if (const auto toi = edge_edge_toi(scene::edge_edge_query(s, p.edges[i], p.edges[j]), params)) {
          Collision c;
          c.kind = CollisionKind::edge_edge;
          c.edge_a = p.edges[i];
          c.edge_b = p.edges[j];
          c.toi = *toi;
          want.push_back(c);
        }
      ASSERT_FALSE(want.empty()) << name;
      std::optional<TimeInterval> earliest;
      for (const Collision& c : want)
        if (!earliest || c.toi.lo < earliest->lo || (c.toi.lo == earliest->lo && c.toi.hi < earliest->hi)) earliest = c.toi;
      for (unsigned threads : kThreadCounts) {
        const SceneOptions options{threads, params.min_distance, params.tmax};
        const std::vector<Collision> got = find_collisions(s, options);
        ASSERT_EQ(got.size(), want.size()) << name << " threads " << threads;
        for (std::size_t k = 0; k < got.size(); ++k) {
          EXPECT_EQ(got[k].kind, want[k].kind);
          EXPECT_EQ(got[k].vertex, want[k].vertex);
          EXPECT_EQ(got[k].triangle, want[k].triangle);
          EXPECT_EQ(got[k].edge_a, want[k].edge_a);
          EXPECT_EQ(got[k].edge_b, want[k].edge_b);
          EXPECT_EQ(got[k].toi.lo, want[k].toi.lo);
          EXPECT_EQ(got[k].toi.hi, want[k].toi.hi);
        }
        const auto e = earliest_toi(s, options);
        ASSERT_TRUE(e.has_value());
        EXPECT_EQ(e->lo, earliest->lo);
        EXPECT_EQ(e->hi, earliest->hi);
        EXPECT_FALSE(is_collision_free(s, options));
      }
    }
  }
}


/// unique_edges (a counting sort by the lower index) against sorting every edge of the
/// triangles, on random meshes: dense and sparse index ranges, repeated and degenerate
/// triangles, no triangles.
TEST(Mesh, UniqueEdgesEqualSortingEveryEdge) {
  std::mt19937 rng(5);
  for (int n = 0; n < 300; ++n) {
    const int vertices = 1 + n % 40 * (n % 7 == 0 ? 100 : 1);
    std::uniform_int_distribution<int> index(0, vertices - 1);
    std::vector<scene::Triangle> triangles(static_cast<std::size_t>(n % 50));
    for (scene::Triangle& t : triangles) t = {index(rng), index(rng), index(rng)};
    if (n % 5 == 0 && !triangles.empty()) triangles.push_back(triangles.front());
    std::vector<scene::Edge> want;
    for (const scene::Triangle& t : triangles)
      for (int i = 0; i < 3; ++i) want.push_back({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());
    EXPECT_EQ(scene::unique_edges(triangles), want) << "mesh " << n;
  }
}

/// float_down / float_up against std::nextafter, and float_below / float_above bracketing
/// doubles: zeros, subnormals, the normal range's ends, infinities and random floats.
TEST(FloatBox, NeighboursAndOutwardRoundingMatchTheLibrary) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values{0.0f, -0.0f, std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::min(), -std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), 1.0f, -1.0f};
  std::mt19937 rng(8);
  std::uniform_int_distribution<std::uint32_t> bits;
  while (values.size() < 200000) {
    const std::uint32_t b = bits(rng);
    float f = 0;
    std::memcpy(&f, &b, sizeof f);
    if (!std::isnan(f) && std::isfinite(f)) values.push_back(f);
  }
  const auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (const float f : values) {
    ASSERT_TRUE(same(scene::float_down(f), std::nextafter(f, -inf))) << f;
    ASSERT_TRUE(same(scene::float_up(f), std::nextafter(f, inf))) << f;
  }
  EXPECT_TRUE(same(scene::float_down(inf), std::numeric_limits<float>::max()));
  EXPECT_TRUE(same(scene::float_up(-inf), -std::numeric_limits<float>::max()));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-160, 140);
  for (int n = 0; n < 200000; ++n) {
    const double x = std::ldexp(unit(rng), exponent(rng));
    const float below = scene::float_below(x), above = scene::float_above(x);
    ASSERT_LE(static_cast<double>(below), x) << x;
    ASSERT_GE(static_cast<double>(above), x) << x;
    ASSERT_GT(static_cast<double>(std::nextafter(below, inf)), x) << x;  // the largest float <= x
    ASSERT_LT(static_cast<double>(std::nextafter(above, -inf)), x) << x;  // the smallest float >= x
  }
}

/// Random boxes on a small integer grid (many equal, touching and nested boxes), `n` of them;
/// every 13th unbounded on one axis, every 29th on all three (as boxes grown to infinity after
/// an overflow: they overlap every box, and must not be paired with a leaf's unused lanes).
std::vector<scene::Box> grid_boxes(std::size_t n, std::mt19937& rng) {
  std::uniform_int_distribution<int> corner(0, 12), size(0, 3);
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<scene::Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    scene::Box& b = boxes[i];
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = corner(rng);
      b.hi[k] = b.lo[k] + size(rng);
      if ((i % 13 == 5 && k == static_cast<int>(i % 3)) || i % 29 == 3) b.lo[k] = -inf, b.hi[k] = inf;
    }
  }
  return boxes;
}

/// BoxTree::pair_tasks and pairs_from, of a tree against itself and against another: every
/// overlapping pair (brute force, written out) exactly once, whatever the number of tasks.
TEST(BoxTreePairs, EveryOverlappingPairOnceWhateverTheTasks) {
  std::mt19937 rng(14);
  const auto overlapping = [](const scene::Box& a, const scene::Box& b) {
    for (int k = 0; k < 3; ++k)
      if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
  };
  for (const std::size_t na : {0u, 1u, 7u, 8u, 9u, 100u, 700u})
    for (const std::size_t nb : {0u, 3u, 64u, 333u}) {
      const std::vector<scene::Box> a = grid_boxes(na, rng), b = grid_boxes(nb, rng);
      scene::BoxTree ta, tb;
      ta.build(a.size(), [&](std::size_t i) { return a[i]; }, 2);
      tb.build(b.size(), [&](std::size_t i) { return b[i]; }, 1);
      std::vector<std::array<int, 2>> want_self, want_cross;
      for (std::size_t i = 0; i < na; ++i) {
        for (std::size_t j = i + 1; j < na; ++j)
          if (overlapping(a[i], a[j])) want_self.push_back({static_cast<int>(i), static_cast<int>(j)});
        for (std::size_t j = 0; j < nb; ++j)
          if (overlapping(a[i], b[j])) want_cross.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
      for (const std::size_t wanted : {1u, 5u, 64u, 100000u}) {
        const std::string what = std::to_string(na) + " x " + std::to_string(nb) + ", " + std::to_string(wanted);
        std::vector<std::array<int, 2>> self, cross;
        // The trees report the pairs whose float boxes overlap: here, on the integer grid, exactly
        // the overlapping ones (so a pair reported that does not overlap is an error too).
        std::size_t extra = 0;
        for (const auto& task : ta.pair_tasks(ta, wanted))
          ta.pairs_from(ta, task, [&](int i, int j) {
            ASSERT_TRUE(i >= 0 && j >= 0 && static_cast<std::size_t>(i) < na && static_cast<std::size_t>(j) < na) << what;
            if (overlapping(a[static_cast<std::size_t>(i)], a[static_cast<std::size_t>(j)])) self.push_back({i, j});
            else ++extra;
          });
        for (const auto& task : ta.pair_tasks(tb, wanted))
          ta.pairs_from(tb, task, [&](int i, int j) {
            ASSERT_TRUE(i >= 0 && j >= 0 && static_cast<std::size_t>(i) < na && static_cast<std::size_t>(j) < nb) << what;
            if (overlapping(a[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(j)])) cross.push_back({i, j});
            else ++extra;
          });
        EXPECT_EQ(extra, 0u) << what << ": pairs reported whose boxes do not overlap";
        std::sort(self.begin(), self.end());  // duplicates kept: each pair must come once
        std::sort(cross.begin(), cross.end());
        EXPECT_EQ(self, want_self) << what;
        EXPECT_EQ(cross, want_cross) << what;
      }
    }
}

/// BoxTree::set_vertices: pairs_from between trees that both have vertex indices reports every
/// overlapping pair that shares no index exactly once and no pair that shares one (brute force,
/// written out), for 1, 2 and 3 indices per primitive on either side (drawn from a few values,
/// so that many overlapping pairs share one), and again after a refit.
TEST(BoxTreePairs, SetVerticesDropsExactlyThePairsSharingAVertex) {
  std::mt19937 rng(23);
  const auto overlapping = [](const scene::Box& a, const scene::Box& b) {
    for (int k = 0; k < 3; ++k)
      if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
  };
  std::uniform_int_distribution<int> vertex(0, 40);
  const auto indices = [&](std::size_t n, int count) {
    std::vector<std::array<int, 3>> v(n);
    for (auto& x : v)
      for (int m = 0; m < 3; ++m) x[static_cast<std::size_t>(m)] = m < count ? vertex(rng) : -1;
    return v;
  };
  const auto share = [](const std::array<int, 3>& x, int nx, const std::array<int, 3>& y, int ny) {
    for (int m = 0; m < nx; ++m)
      for (int s = 0; s < ny; ++s)
        if (x[static_cast<std::size_t>(m)] == y[static_cast<std::size_t>(s)]) return true;
    return false;
  };
  for (const int ca : {1, 2, 3})
    for (const int cb : {1, 2, 3}) {
      const std::vector<scene::Box> a = grid_boxes(300, rng), b = grid_boxes(200, rng);
      const auto va = indices(a.size(), ca), vb = indices(b.size(), cb);
      scene::BoxTree ta, tb;
      ta.build(a.size(), [&](std::size_t i) { return a[i]; }, 2);
      tb.build(b.size(), [&](std::size_t i) { return b[i]; }, 1);
      for (int round = 0; round < 2; ++round) {
        if (round == 1) {  // refit keeps the indices
          ta.refit(a.size(), [&](std::size_t i) { return a[i]; }, 1);
          tb.refit(b.size(), [&](std::size_t i) { return b[i]; }, 2);
        } else {
          ta.set_vertices(ca, [&](std::size_t i) { return va[i]; }, 2);
          tb.set_vertices(cb, [&](std::size_t i) { return vb[i]; }, 1);
        }
        std::vector<std::array<int, 2>> want_self, want_cross, self, cross;
        for (std::size_t i = 0; i < a.size(); ++i) {
          for (std::size_t j = i + 1; j < a.size(); ++j)
            if (overlapping(a[i], a[j]) && !share(va[i], ca, va[j], ca)) want_self.push_back({static_cast<int>(i), static_cast<int>(j)});
          for (std::size_t j = 0; j < b.size(); ++j)
            if (overlapping(a[i], b[j]) && !share(va[i], ca, vb[j], cb)) want_cross.push_back({static_cast<int>(i), static_cast<int>(j)});
        }
        for (const auto& task : ta.pair_tasks(ta, 7)) ta.pairs_from(ta, task, [&](int i, int j) { self.push_back({i, j}); });
        for (const auto& task : ta.pair_tasks(tb, 7)) ta.pairs_from(tb, task, [&](int i, int j) { cross.push_back({i, j}); });
        std::sort(self.begin(), self.end());
        std::sort(cross.begin(), cross.end());
        const std::string what = std::to_string(ca) + " x " + std::to_string(cb) + " indices, round " + std::to_string(round);
        EXPECT_EQ(self, want_self) << what;
        EXPECT_EQ(cross, want_cross) << what;
        EXPECT_GT(want_self.size(), 0u) << what;
      }
    }
  scene::BoxTree t;
  const std::vector<scene::Box> boxes = grid_boxes(10, rng);
  t.build(boxes.size(), [&](std::size_t i) { return boxes[i]; }, 1);
  EXPECT_THROW(t.set_vertices(2, [](std::size_t) { return std::array<int, 3>{1, -1, -1}; }, 1), std::invalid_argument);
  EXPECT_THROW(t.set_vertices(4, [](std::size_t) { return std::array<int, 3>{1, 2, 3}; }, 1), std::invalid_argument);
}

}  // namespace
}  // namespace exactccd
