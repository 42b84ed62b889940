// Scene-level CCD per time step of the cloth-on-sphere scene (tools/lib/scenes/procedural_scenes.hpp)
// at resolutions 16, 32 and 64 (Google Benchmark): the broad phase, the narrow phase over the
// same candidates with the filtered (exact) and the naive (textbook doubles, not robust)
// methods, and the whole scene functions on one thread (find_collisions also on two, by wall
// time). Figures: docs/scene.md.
//
//   build/scene_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// The scaling set (BM_Step*, cloth at resolutions 16, 64, 220, 708: 1.8k to 1.0M triangles, on
// 1 and 2 threads, wall time): the broad phase (built, and refitted by SceneBroadPhase), the
// old serial sweep, the narrow phase over its candidates with the
// filtered method (certified TOIs, as find_collisions) and the naive one, and the whole
// find_collisions step. Run by tools/plot/scene_step.sh, which also runs
//
//   build/scene_bench --peak_memory=RESOLUTION
//
// (one find_collisions step on 2 threads in a fresh process; prints JSON with getrusage's
// ru_maxrss, the process's peak resident set, after building the scene and after the step).
// The streamed step (issue 23): BM_StepBroadStream (the broad phase as the scene functions now
// run it, pairs streamed and counted), BM_StepEarliest, and a line search on SceneBroadPhase
// (BM_LineSearchFirst: built on the full step and asked max_collision_free_step; Next: the
// same object updated to the steps 1/2, 1/4, 1/8, 1/16 in turn; Fresh: the free function on
// those steps). With --frames=T0,T1 (two mesh files of one step, e.g. the Scalable CCD
// dataset's cloth-ball frames) also BM_Frames*: the whole find_collisions and earliest_toi, the
// streamed broad phase, and the narrow phase over its listed candidates (filtered, naive), on 1
// and 2 threads. BM_StepGrid and BM_FramesGrid: the uniform grid broad phase of
// tools/lib/broad_phase on one thread, at three cell sides, against BM_StepBroadStream/BM_FramesBroadStream
// on one thread (and BM_StepSweep, the serial sort and sweep, which lists its candidates).
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "exactccd/exactccd.hpp"
#include "numeric/fp_environment.hpp"
#include "io/mesh_file.hpp"
#include "scene/parallel.hpp"
#include "scene/pair_stream.hpp"
#include "scenes/procedural_scenes.hpp"
#include "scene/scene_primitives.hpp"
#include "scene/streamed_step.hpp"
#include "broad_phase/uniform_grid.hpp"
#include "methods/methods.hpp"

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

/// One step of the cloth scene at a resolution and its candidates (1 thread; built once, no
/// prebuilt queries: at 1M triangles they would not fit in memory).
struct StepFixture {
  Scene scene;
  scene::ScenePrimitives prim;
};

Scene cloth_scene(int resolution) {
  const scene::MovingMesh mesh = scene::procedural_scene("cloth", resolution, 1);
  Scene s;
  s.positions_t0 = mesh.positions_t0;
  s.positions_t1 = mesh.positions_t1;
  s.triangles = mesh.triangles;
  return s;
}

const StepFixture& step_fixture(int resolution) {
  static std::map<int, StepFixture> cache;  // benchmark-local, filled on the main thread
  auto it = cache.find(resolution);
  if (it != cache.end()) return it->second;
  // Only one large scene at a time.
  for (auto k = cache.begin(); k != cache.end();) k = k->first >= 128 ? cache.erase(k) : std::next(k);
  StepFixture f;
  f.scene = cloth_scene(resolution);
  f.prim = scene::scene_primitives(f.scene);
  return cache.emplace(resolution, std::move(f)).first->second;
}

void step_label(benchmark::State& state, const StepFixture& f) {
  state.counters["triangles"] = static_cast<double>(f.scene.triangles.size());
  state.counters["candidates"] = static_cast<double>(f.prim.candidates.vertex_face.size() +
                                                     f.prim.candidates.edge_edge.size());
  state.counters["threads"] = static_cast<double>(state.range(1));
}

/// The serial sort-and-sweep broad phase the tree replaced (sweep_candidates), from the same
/// vertex boxes: the reference for the choice of the tree.
void BM_StepSweep(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto boxes = scene::vertex_boxes(f.scene.positions_t0, f.scene.positions_t1, {});
    benchmark::DoNotOptimize(
        scene::sweep_candidates(boxes, f.scene.triangles, f.prim.edges, f.prim.vertices, f.prim.points));
  }
  step_label(state, f);
}

/// The broad phase of find_collisions (scene_primitives) on state.range(1) threads.
void BM_StepBroad(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const unsigned threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(scene::scene_primitives(f.scene, {}, threads));
  step_label(state, f);
}

/// The reused broad phase: SceneBroadPhase::update() (refit of the hierarchies built once
/// outside the timed loop, then the candidates) with the step's positions at t = 1, as a line
/// search calls it, on state.range(1) threads.
void BM_StepRefit(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  SceneBroadPhase broad(f.scene, SceneOptions{static_cast<unsigned>(state.range(1))});
  for (auto _ : state) {
    broad.update(f.scene.positions_t1);
    benchmark::DoNotOptimize(broad.candidates().edge_edge.data());
  }
  step_label(state, f);
}

/// The narrow phase over the broad phase's candidates on state.range(1) threads, as
/// find_collisions runs it (chunks of 64 candidates, the query built from the indices, its time
/// of impact), with one method.
template <class M>
void BM_StepNarrow(benchmark::State& state, M method) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const unsigned threads = static_cast<unsigned>(state.range(1));
  const auto& vf = f.prim.candidates.vertex_face;
  const auto& ee = f.prim.candidates.edge_edge;
  std::size_t total = 0;
  for (auto _ : state) {
    total = scene::with_threads(threads, [&] {
      std::vector<scene::PerWorker<std::size_t>> hits(scene::worker_slots(threads));
      scene::parallel_chunks(vf.size() + ee.size(), threads, 64, [&](std::size_t begin, std::size_t end, unsigned w) {
        for (std::size_t k = begin; k < end; ++k) {
          if (k < vf.size())
            hits[w].value += toi(scene::vertex_face_query(f.scene, vf[k][0], vf[k][1]), method).has_value();
          else {
            const auto& pair = ee[k - vf.size()];
            hits[w].value += toi(scene::edge_edge_query(f.scene, f.prim.edges[pair[0]], f.prim.edges[pair[1]]), method)
                                 .has_value();
          }
        }
        return true;
      });
      std::size_t sum = 0;
      for (const auto& h : hits) sum += h.value;
      return sum;
    });
    benchmark::DoNotOptimize(total);
  }
  step_label(state, f);
  state.counters["collisions"] = static_cast<double>(total);
}

/// The whole step: find_collisions (broad and exact narrow phase) on state.range(1) threads.
void BM_StepWhole(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  std::size_t found = 0;
  for (auto _ : state) {
    const auto c = find_collisions(f.scene, options);
    found = c.size();
    benchmark::DoNotOptimize(c.data());
  }
  step_label(state, f);
  state.counters["collisions"] = static_cast<double>(found);
}

/// The streamed broad phase alone as the scene functions run it (topology, vertex boxes, trees
/// built, then every pair streamed to a narrow phase that only counts it), on state.range(1)
/// threads.
void BM_StepBroadStream(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const unsigned threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state)
    scene::with_threads(threads, [&] {
      std::vector<scene::PerWorker<std::size_t>> seen(scene::worker_slots(threads));
      scene::StreamBuffers buffers;
      const scene::SceneTrees trees(f.scene, CcdParams{}, threads);
      scene::stream_pairs(
          trees.trees(), threads, [&](const scene::FoundPair&, unsigned w) { return ++seen[w].value > 0; }, buffers);
      benchmark::DoNotOptimize(seen.data());
    });
  step_label(state, f);
}

/// The uniform grid's broad phase (tools/lib/broad_phase/uniform_grid.hpp, one thread): the
/// same work as BM_StepBroadStream on one thread (topology, vertex boxes, the structure built,
/// every pair reported and counted), cell side state.range(1) / 4 times the mean edge box
/// extent: issue 23's comparison of the broad-phase structures.
void grid_step(const Scene& scene, double factor, std::size_t& seen) {
  const scene::ScenePrimitives topology = scene::scene_topology(scene, CcdParams{});
  const std::vector<scene::Box> boxes = scene::vertex_boxes(scene.positions_t0, scene.positions_t1, CcdParams{});
  const tools::UniformGrid grid(boxes, scene.triangles, topology.edges, topology.vertices,
                                factor * tools::UniformGrid::mean_edge_extent(boxes, topology.edges));
  seen += grid.pairs([](const scene::FoundPair&) {});
}

void BM_StepGrid(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  std::size_t seen = 0;
  for (auto _ : state) grid_step(f.scene, static_cast<double>(state.range(1)) / 4, seen);
  benchmark::DoNotOptimize(seen);
  step_label(state, f);
  state.counters["threads"] = 1;
}

/// The whole earliest_toi step (broad phase and exact narrow phase with the shrinking window)
/// on state.range(1) threads.
void BM_StepEarliest(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  for (auto _ : state) benchmark::DoNotOptimize(earliest_toi(f.scene, options));
  step_label(state, f);
}

/// The scene with its positions at t = 1 a fraction `step` of the way: x0 + step (x1 - x0),
/// the trial positions of a line search.
std::vector<Vec3> at_step(const Scene& s, double step) {
  std::vector<Vec3> x1(s.positions_t0.size());
  for (std::size_t v = 0; v < x1.size(); ++v) {
    const Vec3 &a = s.positions_t0[v], &b = s.positions_t1[v];
    x1[v] = {a.x + step * (b.x - a.x), a.y + step * (b.y - a.y), a.z + step * (b.z - a.z)};
  }
  return x1;
}

constexpr double kLineSearchSteps[] = {0.5, 0.25, 0.125, 0.0625};

/// A line search's first call: SceneBroadPhase built on the full step, then
/// max_collision_free_step(), on state.range(1) threads.
void BM_LineSearchFirst(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  for (auto _ : state) {
    const SceneBroadPhase broad(f.scene, options);
    benchmark::DoNotOptimize(broad.max_collision_free_step());
  }
  step_label(state, f);
}

/// The line search's later calls: one SceneBroadPhase (built outside the timed loop), each
/// iteration update() to the trial positions of the next shorter step (1/2, 1/4, 1/8, 1/16 in
/// turn) and max_collision_free_step().
void BM_LineSearchNext(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  std::vector<std::vector<Vec3>> trials;
  for (double step : kLineSearchSteps) trials.push_back(at_step(f.scene, step));
  SceneBroadPhase broad(f.scene, options);
  std::size_t k = 0;
  for (auto _ : state) {
    broad.update(trials[k++ % trials.size()]);
    benchmark::DoNotOptimize(broad.max_collision_free_step());
  }
  step_label(state, f);
}

/// The same trial steps answered by the free function (a fresh broad phase per call).
void BM_LineSearchFresh(benchmark::State& state) {
  const StepFixture& f = step_fixture(static_cast<int>(state.range(0)));
  const SceneOptions options{static_cast<unsigned>(state.range(1))};
  std::vector<Scene> trials;
  for (double step : kLineSearchSteps) {
    trials.push_back(f.scene);
    trials.back().positions_t1 = at_step(f.scene, step);
  }
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(max_collision_free_step(trials[k++ % trials.size()], options));
  step_label(state, f);
}

/// Peak resident memory of one 2-thread find_collisions step at `resolution` in this process:
/// getrusage's ru_maxrss (KiB on Linux) after building the scene and after the step.
int peak_memory(int resolution) {
  const auto max_rss_kb = [] {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<long>(usage.ru_maxrss);
  };
  const Scene s = cloth_scene(resolution);
  const long before = max_rss_kb();
  const auto collisions = find_collisions(s, SceneOptions{2});
  const long after = max_rss_kb();
  std::printf("{\"resolution\": %d, \"triangles\": %zu, \"vertices\": %zu, \"collisions\": %zu, "
              "\"max_rss_kb_scene\": %ld, \"max_rss_kb_step\": %ld}\n",
              resolution, s.triangles.size(), s.positions_t0.size(), collisions.size(), before, after);
  return 0;
}

#define EXACTCCD_STEP_SIZES                                                                                 \
  ->ArgsProduct({{16, 64, 220, 708}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3)
BENCHMARK(BM_StepSweep)->ArgsProduct({{16, 64, 220, 708}, {1}})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
BENCHMARK(BM_StepBroad) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_StepRefit) EXACTCCD_STEP_SIZES;
BENCHMARK_CAPTURE(BM_StepNarrow, filtered, Method::filtered) EXACTCCD_STEP_SIZES;
BENCHMARK_CAPTURE(BM_StepNarrow, naive, tools::Method::naive) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_StepWhole) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_StepBroadStream) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_StepGrid)->ArgsProduct({{16, 64, 220, 708}, {2, 4, 8, 16}})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
BENCHMARK(BM_StepEarliest) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_LineSearchFirst) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_LineSearchNext) EXACTCCD_STEP_SIZES;
BENCHMARK(BM_LineSearchFresh) EXACTCCD_STEP_SIZES;

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

/// One step given as two mesh files (--frames=T0,T1: e.g. the Scalable CCD dataset's cloth-ball
/// frames), its topology and listed candidates (for the narrow-phase baselines).
struct FramesFixture {
  Scene scene;
  scene::ScenePrimitives prim;
};

FramesFixture& frames() {
  static FramesFixture f;
  return f;
}

void frames_label(benchmark::State& state) {
  const FramesFixture& f = frames();
  state.counters["triangles"] = static_cast<double>(f.scene.triangles.size());
  state.counters["candidates"] =
      static_cast<double>(f.prim.candidates.vertex_face.size() + f.prim.candidates.edge_edge.size());
}

/// The narrow phase over the frames' listed candidates with one method (as BM_StepNarrow).
template <class M>
void BM_FramesNarrow(benchmark::State& state, M method) {
  const FramesFixture& f = frames();
  const unsigned threads = static_cast<unsigned>(state.range(0));
  const auto& vf = f.prim.candidates.vertex_face;
  const auto& ee = f.prim.candidates.edge_edge;
  for (auto _ : state)
    scene::with_threads(threads, [&] {
      std::vector<scene::PerWorker<std::size_t>> hits(scene::worker_slots(threads));
      scene::parallel_chunks(vf.size() + ee.size(), threads, 64, [&](std::size_t begin, std::size_t end, unsigned w) {
        for (std::size_t k = begin; k < end; ++k) {
          const auto query = k < vf.size() ? toi(scene::vertex_face_query(f.scene, vf[k][0], vf[k][1]), method)
                                           : toi(scene::edge_edge_query(f.scene, f.prim.edges[ee[k - vf.size()][0]],
                                                                        f.prim.edges[ee[k - vf.size()][1]]),
                                                 method);
          hits[w].value += query.has_value();
        }
        return true;
      });
      benchmark::DoNotOptimize(hits.data());
    });
  frames_label(state);
}

void BM_FramesWhole(benchmark::State& state) {
  const SceneOptions options{static_cast<unsigned>(state.range(0))};
  for (auto _ : state) benchmark::DoNotOptimize(find_collisions(frames().scene, options));
  frames_label(state);
}

void BM_FramesEarliest(benchmark::State& state) {
  const SceneOptions options{static_cast<unsigned>(state.range(0))};
  for (auto _ : state) benchmark::DoNotOptimize(earliest_toi(frames().scene, options));
  frames_label(state);
}

void BM_FramesBroadStream(benchmark::State& state) {
  const unsigned threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state)
    scene::with_threads(threads, [&] {
      std::vector<scene::PerWorker<std::size_t>> seen(scene::worker_slots(threads));
      scene::StreamBuffers buffers;
      const scene::SceneTrees trees(frames().scene, CcdParams{}, threads);
      scene::stream_pairs(
          trees.trees(), threads, [&](const scene::FoundPair&, unsigned w) { return ++seen[w].value > 0; }, buffers);
      benchmark::DoNotOptimize(seen.data());
    });
  frames_label(state);
}

/// BM_StepGrid on the frames: cell side state.range(0) / 4 times the mean edge box extent.
void BM_FramesGrid(benchmark::State& state) {
  std::size_t seen = 0;
  for (auto _ : state) grid_step(frames().scene, static_cast<double>(state.range(0)) / 4, seen);
  benchmark::DoNotOptimize(seen);
  frames_label(state);
}


/// --frames=T0,T1: registers the BM_Frames* benchmarks on that step (1 and 2 threads).
void register_frames(const std::string& spec) {
  const std::size_t comma = spec.find(',');
  const io::TriangleMesh m0 = io::read_mesh(spec.substr(0, comma)), m1 = io::read_mesh(spec.substr(comma + 1));
  FramesFixture& f = frames();
  f.scene = Scene{m0.vertices, m1.vertices, m0.triangles, {}, {}};
  f.prim = scene::scene_primitives(f.scene, {}, 2);
  for (const auto* name : {"BM_FramesWhole", "BM_FramesEarliest", "BM_FramesBroadStream"}) {
    auto* b = benchmark::RegisterBenchmark(name, std::string(name) == "BM_FramesWhole"      ? BM_FramesWhole
                                                 : std::string(name) == "BM_FramesEarliest" ? BM_FramesEarliest
                                                                                             : BM_FramesBroadStream);
    b->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
  }
  benchmark::RegisterBenchmark("BM_FramesGrid", BM_FramesGrid)
      ->Arg(2)->Arg(4)->Arg(8)->Arg(16)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
  benchmark::RegisterBenchmark("BM_FramesNarrow/filtered", BM_FramesNarrow<Method>, Method::filtered)
      ->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
  benchmark::RegisterBenchmark("BM_FramesNarrow/naive", BM_FramesNarrow<tools::Method>, tools::Method::naive)
      ->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(0.3);
}

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--peak_memory=", 14) == 0) return peak_memory(std::stoi(argv[i] + 14));
    if (std::strncmp(argv[i], "--frames=", 9) == 0) {
      register_frames(argv[i] + 9);
      for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      --i;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
