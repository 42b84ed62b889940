// The batch narrow phase over given candidates (exactccd/candidates.hpp) on one step of the
// cloth-on-sphere scene at resolutions 32 and 64 (Google Benchmark): the candidates are the
// scene's own broad-phase candidates, built once (as a simulator's line search reuses its
// list); compared with the scene functions, which run the broad phase on every call, and with
// the narrow phase alone over the same queries. One thread unless named. Figures: docs/scene.md.
//
//   build/candidates_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// With --frames=T0,T1 (two mesh files of one step, e.g. the Scalable CCD dataset's cloth-funnel
// frames) also BM_FramesCandidates*: the functions over that step's listed candidates on 1 and 2
// threads.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <string>

#include "exactccd/exactccd.hpp"
#include "io/mesh_file.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"

namespace {

using namespace exactccd;

/// One step of the cloth scene at a resolution and its broad-phase candidates (built once).
struct Fixture {
  Scene scene;
  CandidateSet candidates;
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
};

/// The step `scene` with its broad-phase candidates as a caller's list and as queries.
Fixture fixture_of(Scene scene) {
  Fixture f;
  f.scene = std::move(scene);
  const scene::ScenePrimitives prim = scene::scene_primitives(f.scene);
  const auto& e = prim.edges;
  for (const auto& [v, t] : prim.candidates.vertex_face) {
    const auto& tri = f.scene.triangles[t];
    f.candidates.vertex_face.push_back({v, tri[0], tri[1], tri[2]});
    f.vf.push_back(scene::vertex_face_query(f.scene, v, t));
  }
  for (const auto& [i, j] : prim.candidates.edge_edge) {
    f.candidates.edge_edge.push_back({e[i][0], e[i][1], e[j][0], e[j][1]});
    f.ee.push_back(scene::edge_edge_query(f.scene, e[i], e[j]));
  }
  return f;
}

const Fixture& fixture(int resolution) {
  static std::map<int, Fixture> cache;  // benchmark-local, filled on the main thread
  auto it = cache.find(resolution);
  if (it != cache.end()) return it->second;
  const scene::MovingMesh mesh = scene::procedural_scene("cloth", resolution, 1);
  return cache.emplace(resolution, fixture_of(Scene{mesh.positions_t0, mesh.positions_t1, mesh.triangles, {}, {}}))
      .first->second;
}

void label(benchmark::State& state, const Fixture& f) {
  state.counters["candidates"] = static_cast<double>(f.candidates.size());
}

/// The scene's max_collision_free_step (broad phase + narrow phase with pruning).
void BM_SceneMaxStep(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(max_collision_free_step(f.scene, SceneOptions{1}));
  label(state, f);
}

/// The same answer over the given candidates.
void BM_CandidatesMaxStep(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(
        max_collision_free_step(f.scene.positions_t0, f.scene.positions_t1, f.candidates, SceneOptions{1}));
  label(state, f);
}

/// The scene's find_collisions.
void BM_SceneFindCollisions(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(find_collisions(f.scene, SceneOptions{1}));
  label(state, f);
}

/// find_collisions over the given candidates on state.range(1) threads: wall time.
void BM_CandidatesFindCollisions(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  for (auto _ : state)
    benchmark::DoNotOptimize(find_collisions(f.scene.positions_t0, f.scene.positions_t1, f.candidates, options));
  label(state, f);
}

/// The narrow phase alone: every candidate's TOI by the primitive functions, in a plain loop
/// over queries built beforehand, with the CcdParams overloads the batch functions call.
void BM_PrimitiveToiLoop(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    std::size_t hits = 0;
    for (const auto& q : f.vf) hits += vertex_face_toi(q, CcdParams{}).has_value();
    for (const auto& q : f.ee) hits += edge_edge_toi(q, CcdParams{}).has_value();
    benchmark::DoNotOptimize(hits);
  }
  label(state, f);
}

/// Candidates whose boxes do not overlap (issue 23, item 5): every edge of the cloth paired with
/// an edge half the list away, kept when their swept boxes over [0, 1] are disjoint (most are),
/// rows of vertex indices; built once.
struct DisjointFixture {
  Scene scene;
  CandidateSet candidates;
};

const DisjointFixture& disjoint_fixture(int resolution) {
  static std::map<int, DisjointFixture> cache;  // benchmark-local, filled on the main thread
  auto it = cache.find(resolution);
  if (it != cache.end()) return it->second;
  DisjointFixture f;
  const scene::MovingMesh mesh = scene::procedural_scene("cloth", resolution, 1);
  f.scene = Scene{mesh.positions_t0, mesh.positions_t1, mesh.triangles, {}, {}};
  const auto edges = scene::unique_edges(f.scene.triangles);
  const auto boxes = scene::vertex_boxes(f.scene.positions_t0, f.scene.positions_t1, {});
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& a = edges[i];
    const auto& b = edges[(i + edges.size() / 2) % edges.size()];
    const auto box_a = scene::hull(boxes[a[0]], boxes[a[1]]), box_b = scene::hull(boxes[b[0]], boxes[b[1]]);
    if (!scene::overlap(box_a, box_b)) f.candidates.edge_edge.push_back({a[0], a[1], b[0], b[1]});
  }
  return cache.emplace(resolution, std::move(f)).first->second;
}

/// find_collisions over candidates whose boxes do not overlap (validation, box test, nothing
/// else), one thread: the cost per such candidate (counter ns_per_candidate).
void BM_DisjointCandidatesFindCollisions(benchmark::State& state) {
  const DisjointFixture& f = disjoint_fixture(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(
        find_collisions(f.scene.positions_t0, f.scene.positions_t1, f.candidates, SceneOptions{1}));
  state.counters["candidates"] = static_cast<double>(f.candidates.size());
  state.counters["ns_per_candidate"] = benchmark::Counter(
      static_cast<double>(f.candidates.size()) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// The box test alone over the same rows, written as a simulator's broad phase would: the
/// swept box of each edge from its two vertices' positions at t0 and t1, then the overlap test.
void BM_DisjointCandidatesBoxTest(benchmark::State& state) {
  const DisjointFixture& f = disjoint_fixture(static_cast<int>(state.range(0)));
  const auto& x0 = f.scene.positions_t0;
  const auto& x1 = f.scene.positions_t1;
  const auto box = [&](int a, int b) {
    scene::Box r;
    const Vec3* p[4] = {&x0[a], &x1[a], &x0[b], &x1[b]};
    r.lo = r.hi = {p[0]->x, p[0]->y, p[0]->z};
    for (const Vec3* q : p) {
      const double c[3] = {q->x, q->y, q->z};
      for (int k = 0; k < 3; ++k) r.lo[k] = std::min(r.lo[k], c[k]), r.hi[k] = std::max(r.hi[k], c[k]);
    }
    return r;
  };
  for (auto _ : state) {
    std::size_t overlapping = 0;
    for (const auto& row : f.candidates.edge_edge) overlapping += scene::overlap(box(row[0], row[1]), box(row[2], row[3]));
    benchmark::DoNotOptimize(overlapping);
  }
  state.counters["candidates"] = static_cast<double>(f.candidates.size());
  state.counters["ns_per_candidate"] = benchmark::Counter(
      static_cast<double>(f.candidates.size()) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_DisjointCandidatesFindCollisions)->Arg(64)->Arg(220)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DisjointCandidatesBoxTest)->Arg(64)->Arg(220)->Unit(benchmark::kMillisecond);

#define EXACTCCD_SIZES ->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_SceneMaxStep) EXACTCCD_SIZES;
BENCHMARK(BM_CandidatesMaxStep) EXACTCCD_SIZES;
BENCHMARK(BM_SceneFindCollisions) EXACTCCD_SIZES;
BENCHMARK(BM_CandidatesFindCollisions)
    ->Args({32, 1})->Args({64, 1})->Args({64, 2})->Args({220, 1})->Args({220, 2})->UseRealTime()->Unit(
    benchmark::kMillisecond);
BENCHMARK(BM_PrimitiveToiLoop) EXACTCCD_SIZES;

/// The step of two mesh files (--frames) and its broad-phase candidates.
Fixture& frames() {
  static Fixture f;  // benchmark-local, filled on the main thread before the benchmarks run
  return f;
}

/// find_collisions over the frames' listed candidates on state.range(0) threads (wall time):
/// what a simulator with its own broad phase calls.
void BM_FramesCandidates(benchmark::State& state) {
  const Fixture& f = frames();
  const SceneOptions options{static_cast<unsigned>(state.range(0))};
  for (auto _ : state)
    benchmark::DoNotOptimize(find_collisions(f.scene.positions_t0, f.scene.positions_t1, f.candidates, options));
  label(state, f);
}

/// max_collision_free_step over the same list (the earliest TOI, pruned as it goes).
void BM_FramesCandidatesMaxStep(benchmark::State& state) {
  const Fixture& f = frames();
  const SceneOptions options{static_cast<unsigned>(state.range(0))};
  for (auto _ : state)
    benchmark::DoNotOptimize(max_collision_free_step(f.scene.positions_t0, f.scene.positions_t1, f.candidates, options));
  label(state, f);
}

/// --frames=T0,T1: the step of two mesh files (e.g. the Scalable CCD dataset's cloth-funnel
/// frames), its candidates listed once; registers BM_FramesCandidates* on 1 and 2 threads.
void register_frames(const std::string& spec) {
  const std::size_t comma = spec.find(',');
  const io::TriangleMesh m0 = io::read_mesh(spec.substr(0, comma)), m1 = io::read_mesh(spec.substr(comma + 1));
  frames() = fixture_of(Scene{m0.vertices, m1.vertices, m0.triangles, {}, {}});
  benchmark::RegisterBenchmark("BM_FramesCandidates", BM_FramesCandidates)
      ->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
  benchmark::RegisterBenchmark("BM_FramesCandidatesMaxStep", BM_FramesCandidatesMaxStep)
      ->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--frames=", 9) == 0) {
      register_frames(argv[i] + 9);
      for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      --i;
    }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
