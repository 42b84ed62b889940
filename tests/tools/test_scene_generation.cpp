// Tests of lib/scene: meshes, procedural scenes, the swept-box broad phase, the selection of
// simulation-like query sets, and the bundled data/sim sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"
#include "scene/broad_phase.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scenes/sim_queries.hpp"

#ifndef EXACTCCD_SOURCE_DIR
#define EXACTCCD_SOURCE_DIR "."
#endif

namespace exactccd::scene {
namespace {

/// The scenes with a resolution small enough for all-pairs brute force, and large enough that
/// some pairs collide during the step.
struct SmallScene {
  const char* name;
  int resolution;
};
constexpr SmallScene kSmallScenes[] = {{"cloth", 16}, {"strip", 16}, {"fold", 8}, {"pile", 4}};

std::string label(const SmallScene& s) { return std::string(s.name) + " " + std::to_string(s.resolution); }

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

bool shares_vertex(const Triangle& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }
bool shares_vertex(const Edge& a, const Edge& b) {
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

bool boxes_overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// The query with its t1 positions replaced by its t0 ones: collides iff they touch at t0.
template <class Query>
Query frozen_at_t0(const Query& q) {
  auto r = rows(q);
  for (int i = 0; i < 4; ++i) r[4 + i] = r[i];
  return from_rows<Query>(r);
}

// --- meshes ----------------------------------------------------------------------------------

TEST(Mesh, UniqueEdgesOfAGrid) {
  const MovingMesh g = grid(3, 2, 0, 3, 0, 2);
  ASSERT_EQ(g.positions_t0.size(), 12u);
  ASSERT_EQ(g.triangles.size(), 12u);
  const std::vector<Edge> edges = unique_edges(g.triangles);
  // 3 x 3 horizontal, 4 x 2 vertical, one diagonal per quad.
  EXPECT_EQ(edges.size(), 9u + 8u + 6u);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_LT(edges[i][0], edges[i][1]);
    if (i > 0) {
      EXPECT_LT(edges[i - 1], edges[i]);
    }
  }
  for (const Triangle& t : g.triangles)
    for (int k = 0; k < 3; ++k) {
      const Edge e{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])};
      EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), e));
    }
}

TEST(Mesh, IcosphereIsAClosedSphere) {
  for (int levels = 0; levels <= 3; ++levels) {
    const MovingMesh s = icosphere(levels, 0.5);
    const std::vector<Edge> edges = unique_edges(s.triangles);
    // Euler characteristic of a sphere; every edge between exactly two triangles.
    EXPECT_EQ(static_cast<long>(s.positions_t0.size()) - static_cast<long>(edges.size()) +
                  static_cast<long>(s.triangles.size()),
              2);
    std::map<Edge, int> uses;
    for (const Triangle& t : s.triangles)
      for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    for (const auto& [e, n] : uses) EXPECT_EQ(n, 2);
    for (const Vec3& p : s.positions_t0) EXPECT_NEAR(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 0.5, 1e-12);
    EXPECT_TRUE(same_bits(s.positions_t0, s.positions_t1));  // static
  }
}

TEST(Mesh, AppendShiftsIndices) {
  MovingMesh a = grid(1, 1, 0, 1, 0, 1);
  append(a, grid(1, 1, 2, 3, 0, 1));
  ASSERT_EQ(a.positions_t0.size(), 8u);
  ASSERT_EQ(a.triangles.size(), 4u);
  for (int t = 2; t < 4; ++t)
    for (int v : a.triangles[t]) EXPECT_GE(v, 4);
}

// --- scenes ----------------------------------------------------------------------------------

TEST(Scenes, SameSeedSameScene) {
  for (const char* name : {"cloth", "strip", "fold", "pile"}) {
    const MovingMesh a = procedural_scene(name, 6, 42), b = procedural_scene(name, 6, 42);
    EXPECT_TRUE(same_bits(a.positions_t0, b.positions_t0)) << name;
    EXPECT_TRUE(same_bits(a.positions_t1, b.positions_t1)) << name;
    EXPECT_EQ(a.triangles, b.triangles) << name;
    const MovingMesh c = procedural_scene(name, 6, 43);
    EXPECT_FALSE(same_bits(a.positions_t0, c.positions_t0) && same_bits(a.positions_t1, c.positions_t1))
        << name << ": another seed, the same scene";
  }
}

TEST(Scenes, SameSeedSameQueries) {
  for (const char* name : {"cloth", "strip", "fold", "pile"}) {
    const StepQueries a = step_queries(procedural_scene(name, 8, 7));
    const StepQueries b = step_queries(procedural_scene(name, 8, 7));
    ASSERT_EQ(a.vertex_face.size(), b.vertex_face.size()) << name;
    ASSERT_EQ(a.edge_edge.size(), b.edge_edge.size()) << name;
    EXPECT_GT(a.vertex_face.size() + a.edge_edge.size(), 0u) << name;
    EXPECT_EQ(std::memcmp(a.vertex_face.data(), b.vertex_face.data(), a.vertex_face.size() * sizeof(VertexFaceQuery)), 0)
        << name;
    EXPECT_EQ(std::memcmp(a.edge_edge.data(), b.edge_edge.data(), a.edge_edge.size() * sizeof(EdgeEdgeQuery)), 0)
        << name;
  }
}

TEST(Scenes, BadNameOrResolutionThrows) {
  EXPECT_THROW(procedural_scene("teapot", 8, 1), std::invalid_argument);
  EXPECT_THROW(procedural_scene("cloth", 1, 1), std::invalid_argument);
}

TEST(Scenes, FiniteAndApartAtTheStartOfTheStep) {
  // A simulator starts each step without contact; the scenes do too (decided exactly: the
  // queries frozen at their t0 positions). Candidates suffice: the broad phase is complete.
  for (const SmallScene& s : kSmallScenes) {
    const MovingMesh m = procedural_scene(s.name, s.resolution, 1);
    for (const auto* positions : {&m.positions_t0, &m.positions_t1})
      for (const Vec3& p : *positions) ASSERT_TRUE(std::isfinite(p.x + p.y + p.z)) << label(s);
    const StepQueries q = step_queries(m);
    for (const VertexFaceQuery& x : q.vertex_face) EXPECT_FALSE(vertex_face_ccd(frozen_at_t0(x))) << label(s);
    for (const EdgeEdgeQuery& x : q.edge_edge) EXPECT_FALSE(edge_edge_ccd(frozen_at_t0(x))) << label(s);
  }
}

// --- broad phase -----------------------------------------------------------------------------

TEST(BroadPhase, NoAdjacentPairsNoDuplicatesSorted) {
  for (const SmallScene& s : kSmallScenes) {
    const MovingMesh m = procedural_scene(s.name, s.resolution, 1);
    const std::vector<Edge> edges = unique_edges(m.triangles);
    const Candidates c = find_candidates(m, edges);
    EXPECT_GT(c.vertex_face.size(), 0u) << label(s);
    EXPECT_GT(c.edge_edge.size(), 0u) << label(s);
    for (std::size_t i = 0; i < c.vertex_face.size(); ++i) {
      const auto [v, t] = c.vertex_face[i];
      EXPECT_FALSE(shares_vertex(m.triangles[t], v)) << label(s) << ": vertex " << v << " of its triangle " << t;
      if (i > 0) {
        EXPECT_LT(c.vertex_face[i - 1], c.vertex_face[i]) << label(s);  // sorted, no duplicates
      }
    }
    for (std::size_t i = 0; i < c.edge_edge.size(); ++i) {
      const auto [a, b] = c.edge_edge[i];
      EXPECT_LT(a, b) << label(s);
      EXPECT_FALSE(shares_vertex(edges[a], edges[b])) << label(s) << ": edges " << a << ", " << b;
      if (i > 0) {
        EXPECT_LT(c.edge_edge[i - 1], c.edge_edge[i]) << label(s);
      }
    }
  }
}

TEST(BroadPhase, SweepFindsExactlyTheOverlappingBoxes) {
  // Sort-and-sweep against all pairs: the same set of non-adjacent pairs with overlapping boxes.
  for (const SmallScene& s : {SmallScene{"fold", 6}, SmallScene{"pile", 3}, SmallScene{"strip", 8}}) {
    const MovingMesh m = procedural_scene(s.name, s.resolution, 3);
    const std::vector<Edge> edges = unique_edges(m.triangles);
    const Candidates c = find_candidates(m, edges);
    Candidates all;
    for (int v = 0; v < static_cast<int>(m.positions_t0.size()); ++v)
      for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
        if (!shares_vertex(m.triangles[t], v) && boxes_overlap(swept_box(m, &v, 1), swept_box(m, m.triangles[t].data(), 3)))
          all.vertex_face.push_back({v, t});
    for (int a = 0; a < static_cast<int>(edges.size()); ++a)
      for (int b = a + 1; b < static_cast<int>(edges.size()); ++b)
        if (!shares_vertex(edges[a], edges[b]) && boxes_overlap(swept_box(m, edges[a].data(), 2), swept_box(m, edges[b].data(), 2)))
          all.edge_edge.push_back({a, b});
    EXPECT_EQ(c.vertex_face, all.vertex_face) << label(s);
    EXPECT_EQ(c.edge_edge, all.edge_edge) << label(s);
  }
}

TEST(BroadPhase, CompleteAgainstAllPairs) {
  // Every pair that collides during the step is a candidate: all non-adjacent pairs are
  // answered by the public API (the filtered method, exact and fast); a colliding pair that is
  // not a candidate is confirmed by the slow exact method before it counts as a miss, and a
  // disagreement between the two is reported on its own (a CCD bug, not a broad-phase one).
  for (const SmallScene& s : kSmallScenes) {
    const MovingMesh m = procedural_scene(s.name, s.resolution, 1);
    const std::vector<Edge> edges = unique_edges(m.triangles);
    const Candidates c = find_candidates(m, edges);
    const std::set<std::array<int, 2>> vf(c.vertex_face.begin(), c.vertex_face.end());
    const std::set<std::array<int, 2>> ee(c.edge_edge.begin(), c.edge_edge.end());
    std::size_t vf_hits = 0, ee_hits = 0, filtered_only = 0;
    std::string example;
    for (int v = 0; v < static_cast<int>(m.positions_t0.size()); ++v)
      for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
        if (shares_vertex(m.triangles[t], v)) continue;
        const VertexFaceQuery q = vertex_face_query(m, v, t);
        if (!vertex_face_ccd(q)) continue;
        ++vf_hits;
        if (vf.count({v, t})) continue;
        if (vertex_face_ccd(q, Method::exact))
          ADD_FAILURE() << label(s) << ": colliding vertex " << v << ", triangle " << t << " missed";
        else if (filtered_only++ == 0)
          example = "vertex " + std::to_string(v) + ", triangle " + std::to_string(t);
      }
    for (int a = 0; a < static_cast<int>(edges.size()); ++a)
      for (int b = a + 1; b < static_cast<int>(edges.size()); ++b) {
        if (shares_vertex(edges[a], edges[b])) continue;
        const EdgeEdgeQuery q = edge_edge_query(m, edges[a], edges[b]);
        if (!edge_edge_ccd(q)) continue;
        ++ee_hits;
        if (ee.count({a, b})) continue;
        if (edge_edge_ccd(q, Method::exact))
          ADD_FAILURE() << label(s) << ": colliding edges " << a << ", " << b << " missed";
        else if (filtered_only++ == 0)
          example = "edges " + std::to_string(a) + ", " + std::to_string(b);
      }
    EXPECT_GT(vf_hits + ee_hits, 0u) << label(s) << ": nothing collides, the test proves nothing";
    EXPECT_EQ(filtered_only, 0u) << label(s) << ": not a broad-phase miss but a CCD bug: on " << filtered_only
                                 << " pairs the filtered method says collision and the exact one does not (e.g. "
                                 << example << ")";
  }
}

TEST(BroadPhase, TouchingOnlyOnABoxFaceIsACandidate) {
  // A vertex falling exactly onto a static triangle's plane at t = 1, and an edge doing the same
  // onto a static edge: the swept boxes share one face only (z = 0), the pairs collide.
  MovingMesh m;
  m.positions_t0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1}, {-1, 0.5, 0}, {2, 0.5, 0}, {0.5, -1, 1}, {0.5, 2, 1}};
  m.positions_t1 = m.positions_t0;
  m.positions_t1[3].z = 0;
  m.positions_t1[6].z = m.positions_t1[7].z = 0;
  m.triangles = {{0, 1, 2}, {4, 5, 6}, {5, 6, 7}};  // the last two only give edges 4-5 and 6-7
  const std::vector<Edge> edges = unique_edges(m.triangles);
  const Candidates c = find_candidates(m, edges);
  EXPECT_TRUE(std::count(c.vertex_face.begin(), c.vertex_face.end(), std::array<int, 2>{3, 0}));
  EXPECT_TRUE(vertex_face_ccd(vertex_face_query(m, 3, 0)));
  const int e45 = static_cast<int>(std::find(edges.begin(), edges.end(), Edge{4, 5}) - edges.begin());
  const int e67 = static_cast<int>(std::find(edges.begin(), edges.end(), Edge{6, 7}) - edges.begin());
  ASSERT_LT(e67, static_cast<int>(edges.size()));
  EXPECT_TRUE(std::count(c.edge_edge.begin(), c.edge_edge.end(), std::array<int, 2>{e45, e67}));
  EXPECT_TRUE(edge_edge_ccd(edge_edge_query(m, edges[e45], edges[e67])));
}

// --- query sets ------------------------------------------------------------------------------

TEST(SimQueries, QueriesAreTheCandidatesPositions) {
  const MovingMesh m = procedural_scene("fold", 6, 1);
  const std::vector<Edge> edges = unique_edges(m.triangles);
  const Candidates c = find_candidates(m, edges);
  const StepQueries q = step_queries(m);
  ASSERT_EQ(q.vertex_face.size(), c.vertex_face.size());
  ASSERT_EQ(q.edge_edge.size(), c.edge_edge.size());
  for (std::size_t i = 0; i < q.vertex_face.size(); ++i) {
    const auto [v, t] = c.vertex_face[i];
    const auto r = rows(q.vertex_face[i]);
    const int ids[4] = {v, m.triangles[t][0], m.triangles[t][1], m.triangles[t][2]};
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(std::memcmp(&r[k], &m.positions_t0[ids[k]], sizeof(Vec3)), 0);
      EXPECT_EQ(std::memcmp(&r[4 + k], &m.positions_t1[ids[k]], sizeof(Vec3)), 0);
    }
  }
  for (std::size_t i = 0; i < q.edge_edge.size(); ++i) {
    const auto [a, b] = c.edge_edge[i];
    const auto r = rows(q.edge_edge[i]);
    const int ids[4] = {edges[a][0], edges[a][1], edges[b][0], edges[b][1]};
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(std::memcmp(&r[k], &m.positions_t0[ids[k]], sizeof(Vec3)), 0);
      EXPECT_EQ(std::memcmp(&r[4 + k], &m.positions_t1[ids[k]], sizeof(Vec3)), 0);
    }
  }
}

TEST(SimQueries, SelectionKeepsEveryCollisionThenFills) {
  std::vector<bool> collides(100, false);
  for (int i : {3, 17, 50, 51, 99}) collides[i] = true;
  // Nothing to drop.
  for (std::size_t m : {0, 100, 1000}) EXPECT_EQ(select_queries(collides, m).size(), 100u);
  for (std::size_t m : {5, 6, 20, 99}) {
    const std::vector<std::size_t> kept = select_queries(collides, m);
    EXPECT_EQ(kept.size(), m);
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    EXPECT_EQ(std::adjacent_find(kept.begin(), kept.end()), kept.end());  // distinct
    for (int i : {3, 17, 50, 51, 99}) EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), std::size_t(i))) << m;
    EXPECT_EQ(kept, select_queries(collides, m));  // deterministic
  }
  // More collisions than room: evenly spaced collisions only.
  const std::vector<std::size_t> kept = select_queries(collides, 2);
  ASSERT_EQ(kept.size(), 2u);
  for (std::size_t i : kept) EXPECT_TRUE(collides[i]);
  EXPECT_TRUE(select_queries({}, 10).empty());
}

TEST(SimQueries, SmallSetsAreMostlyNearMisses) {
  // The share of colliding queries of a small generated set (the selection as in
  // `exactccd generate sim --max-queries 400`) lies in (0, 0.2), and of the whole step in
  // (0, 0.1): a few percent, as in a simulation.
  for (const SmallScene& s : kSmallScenes) {
    const StepQueries q = step_queries(procedural_scene(s.name, s.resolution, 1));
    std::vector<bool> collides;
    for (const VertexFaceQuery& x : q.vertex_face) collides.push_back(vertex_face_ccd(x));
    for (const EdgeEdgeQuery& x : q.edge_edge) collides.push_back(edge_edge_ccd(x));
    const double step_share =
        double(std::count(collides.begin(), collides.end(), true)) / double(collides.size());
    EXPECT_GT(step_share, 0.0) << label(s);
    EXPECT_LT(step_share, 0.1) << label(s);
    std::size_t positives = 0;
    const std::vector<std::size_t> kept = select_queries(collides, 400);
    for (std::size_t i : kept) positives += collides[i];
    const double share = double(positives) / double(kept.size());
    EXPECT_GT(share, 0.0) << label(s);
    EXPECT_LT(share, 0.2) << label(s);
  }
}

// --- bundled data/sim ------------------------------------------------------------------------

/// The bundled data/sim files (kind "vertex-face" or "edge-edge", path, queries).
struct BundledFile {
  std::string kind, path;
  io::BenchmarkQueries queries;
};

std::vector<BundledFile> bundled_sim_files() {
  const std::filesystem::path dir = std::filesystem::path(EXACTCCD_SOURCE_DIR) / "data" / "sim";
  std::vector<BundledFile> files;
  for (const char* name : {"cloth", "strip", "fold", "pile"})
    for (const char* kind : {"vertex-face", "edge-edge"}) {
      const std::filesystem::path path = dir / ("sim-" + std::string(name) + "-" + kind + ".csv");
      std::ifstream in(path);
      EXPECT_TRUE(in) << path;
      if (in) files.push_back({kind, path.string(), io::read_benchmark_csv(in, path.string())});
    }
  return files;
}

/// Query i of a bundled file answered by `method` (the file's coordinates are doubles).
bool answer(const BundledFile& f, std::size_t i, Method method) {
  const auto d = io::exact_double_rows(f.queries.rows[i]);
  EXPECT_TRUE(d) << f.path << ": query " << i << " is not in doubles";
  if (!d) return f.queries.truth[i];
  return f.kind == "vertex-face" ? vertex_face_ccd(from_rows<VertexFaceQuery>(*d), method)
                                 : edge_edge_ccd(from_rows<EdgeEdgeQuery>(*d), method);
}

TEST(BundledSim, TruthIsTheExactAnswerAndSharesAreSmall) {
  // Every bundled file: doubles, the truth column is the exact method's answer, a small share
  // of collisions. (tests/cli/cli_sim_fresh.cmake checks that the generator still writes them.)
  const std::vector<BundledFile> files = bundled_sim_files();
  EXPECT_EQ(files.size(), 8u);
  for (const BundledFile& f : files) {
    ASSERT_GT(f.queries.size(), 0u) << f.path;
    std::size_t positives = 0;
    for (std::size_t i = 0; i < f.queries.size(); ++i) {
      EXPECT_EQ(answer(f, i, Method::exact), f.queries.truth[i]) << f.path << ": query " << i;
      positives += f.queries.truth[i];
    }
    EXPECT_GT(positives, 0u) << f.path;
    EXPECT_LT(double(positives) / double(f.queries.size()), 0.2) << f.path;
  }
}

TEST(BundledSim, FilteredMethodAgrees) {
  // The default (filtered) method on the simulation-like sets: the answers of the exact method.
  for (const BundledFile& f : bundled_sim_files()) {
    std::size_t wrong = 0, first = 0;
    for (std::size_t i = 0; i < f.queries.size(); ++i)
      if (answer(f, i, Method::filtered) != f.queries.truth[i] && wrong++ == 0) first = i;
    EXPECT_EQ(wrong, 0u) << f.path << ": the filtered method disagrees with the exact truth on " << wrong << " of "
                         << f.queries.size() << " queries (first: query " << first << ")";
  }
}

}  // namespace
}  // namespace exactccd::scene
