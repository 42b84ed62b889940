// Scene-level CCD per time step of the cloth-on-sphere scene (lib/scene/procedural_scenes.hpp)
// at resolutions 16, 32 and 64 (Google Benchmark): the broad phase, the narrow phase over the
// same candidates with the filtered (exact) and the naive (textbook doubles, not robust)
// methods, and the whole scene functions on one thread (find_collisions also on two, by wall
// time). Figures: docs/scene.md.
//
//   build/scene_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <map>

#include "exactccd/exactccd.hpp"
#include "scene/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "tools/methods.hpp"

namespace {

using namespace exactccd;

/// One step of the cloth scene at a resolution, its candidates and their queries (built once).
struct Fixture {
  Scene scene;
  scene::ScenePrimitives prim;
  std::vector<VertexFaceQuery> vf;
  std::vector<EdgeEdgeQuery> ee;
};

const Fixture& fixture(int resolution) {
  static std::map<int, Fixture> cache;  // benchmark-local, filled on the main thread
  auto it = cache.find(resolution);
  if (it != cache.end()) return it->second;
  Fixture f;
  const scene::MovingMesh mesh = scene::procedural_scene("cloth", resolution, 1);
  f.scene.positions_t0 = mesh.positions_t0;
  f.scene.positions_t1 = mesh.positions_t1;
  f.scene.triangles = mesh.triangles;
  f.prim = scene::scene_primitives(f.scene);
  for (const auto& [v, t] : f.prim.candidates.vertex_face) f.vf.push_back(scene::vertex_face_query(f.scene, v, t));
  for (const auto& [i, j] : f.prim.candidates.edge_edge)
    f.ee.push_back(scene::edge_edge_query(f.scene, f.prim.edges[i], f.prim.edges[j]));
  return cache.emplace(resolution, std::move(f)).first->second;
}

void label(benchmark::State& state, const Fixture& f) {
  state.counters["vertices"] = static_cast<double>(f.scene.positions_t0.size());
  state.counters["candidates"] = static_cast<double>(f.vf.size() + f.ee.size());
}

void BM_BroadPhase(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(scene::scene_primitives(f.scene));
  label(state, f);
}

/// The narrow phase over every candidate with one method (collision answers only). M:
/// exactccd::Method (the public entry points) or tools::Method (the naive baseline, tools
/// library); ccd() and toi() are the overloads of M's namespace.
template <class M>
void BM_Narrow(benchmark::State& state, M method) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (const auto& q : f.vf) hits += ccd(q, method);
    for (const auto& q : f.ee) hits += ccd(q, method);
    benchmark::DoNotOptimize(hits);
  }
  label(state, f);
  state.counters["collisions"] = static_cast<double>(hits);
}

/// The narrow phase with times of impact, as find_collisions runs it.
template <class M>
void BM_NarrowToi(benchmark::State& state, M method) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    std::size_t hits = 0;
    for (const auto& q : f.vf) hits += toi(q, method).has_value();
    for (const auto& q : f.ee) hits += toi(q, method).has_value();
    benchmark::DoNotOptimize(hits);
  }
  label(state, f);
}

void BM_FindCollisions(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(find_collisions(f.scene, SceneOptions{1}));
  label(state, f);
}

/// find_collisions on state.range(1) threads: wall time (the narrow phase is parallel).
void BM_FindCollisionsThreads(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  for (auto _ : state) benchmark::DoNotOptimize(find_collisions(f.scene, options));
  label(state, f);
}

void BM_EarliestToi(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(earliest_toi(f.scene, SceneOptions{1}));
  label(state, f);
}

void BM_IntersectionFree(benchmark::State& state) {
  const Fixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(intersection_free(f.scene.positions_t0, f.scene.triangles));
  label(state, f);
}

#define EXACTCCD_SCENE_SIZES ->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_BroadPhase) EXACTCCD_SCENE_SIZES;
BENCHMARK_CAPTURE(BM_Narrow, filtered, Method::filtered) EXACTCCD_SCENE_SIZES;
BENCHMARK_CAPTURE(BM_Narrow, naive, tools::Method::naive) EXACTCCD_SCENE_SIZES;
BENCHMARK_CAPTURE(BM_NarrowToi, filtered, Method::filtered) EXACTCCD_SCENE_SIZES;
BENCHMARK_CAPTURE(BM_NarrowToi, naive, tools::Method::naive) EXACTCCD_SCENE_SIZES;
BENCHMARK(BM_FindCollisions) EXACTCCD_SCENE_SIZES;
BENCHMARK(BM_FindCollisionsThreads)->Args({64, 1})->Args({64, 2})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EarliestToi) EXACTCCD_SCENE_SIZES;
BENCHMARK(BM_IntersectionFree) EXACTCCD_SCENE_SIZES;

}  // namespace

BENCHMARK_MAIN();
