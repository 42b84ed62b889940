// Rigid scenes against linear ones over the same vertices (Google Benchmark; issue 35, item 4):
// 27 ellipsoid-like bodies (icospheres of 320 triangles, radii 1, 0.7 and 0.5; 8 640 triangles
// in all) on a 3 x 3 x 3 grid 2.0 apart, each tumbling (a random start rotation, then 0.6 rad
// about a random axis) and moving towards the grid's centre by 0.3 to 0.9, so that neighbours
// meet during the step. The rigid functions (exactccd/rigid.hpp) decide the bodies' true
// motion; the linear ones (exactccd/scene.hpp) the scene of the same vertices at the same start
// and end positions moving on straight lines (a different motion, with other collisions: the
// comparison is of cost, not of answers). One thread, at d = 0 and at d = 1e-3.
//
//   build/rigid_scene_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Callgrind counts (repeatable where seconds are not) of one function:
//   valgrind --tool=callgrind build/rigid_scene_bench --benchmark_filter='RigidEarliestToi/0'
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"
#include "rigid/quaternion.hpp"
#include "scene/mesh.hpp"
#include "scenes/procedural_scenes.hpp"

namespace {

using namespace exactccd;

Vec3 unit(const Vec3& v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / n, v.y / n, v.z / n};
}

/// A double in [0, 1) from the generator's raw output (fully specified by the standard, unlike
/// the distributions: the same bodies with every standard library, as procedural_scenes.hpp).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

/// The rotation by `angle` about a random axis.
Quaternion random_rotation(std::mt19937_64& rng, double angle) {
  const Vec3 axis = unit({2 * uniform(rng) - 1, 2 * uniform(rng) - 1, 2 * uniform(rng) - 1});
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * axis.x, s * axis.y, s * axis.z};
}

/// The 27 tumbling bodies of the header.
std::vector<RigidBody> tumbling_bodies() {
  std::mt19937_64 rng(35);
  scene::MovingMesh shape = scene::icosphere(2, 1.0);  // 320 triangles
  for (Vec3& v : shape.positions_t0) v = {v.x, 0.7 * v.y, 0.5 * v.z};
  std::vector<RigidBody> bodies;
  for (int i = 0; i < 27; ++i) {
    const Vec3 c0{2.0 * (i % 3 - 1), 2.0 * (i / 3 % 3 - 1), 2.0 * (i / 9 - 1)};
    const Quaternion q0 = random_rotation(rng, 3.0);
    const double v = 0.3 + 0.6 * uniform(rng);  // towards the centre (the centre body along (1, 1, 1))
    const Vec3 towards = i == 13 ? unit({1, 1, 1}) : unit({-c0.x, -c0.y, -c0.z});
    const RigidPose t0{c0, q0};
    const RigidPose t1{{c0.x + v * towards.x, c0.y + v * towards.y, c0.z + v * towards.z},
                       rigid::product(random_rotation(rng, 0.6), q0)};
    bodies.push_back({shape.positions_t0, shape.triangles, t0, t1});
  }
  return bodies;
}

/// The body point p at the pose: c + M(q) p / |q|^2, rounded as written.
Vec3 placed(const RigidPose& pose, const Vec3& p) {
  const Vec3 m = rigid::rotate_scaled(pose.q, p);
  const double n = rigid::squared_norm(pose.q);
  return {pose.c.x + m.x / n, pose.c.y + m.y / n, pose.c.z + m.z / n};
}

/// The linear scene of the bodies' vertices at their start and end positions.
Scene linear_scene(const std::vector<RigidBody>& bodies) {
  scene::MovingMesh all;
  for (const RigidBody& b : bodies) {
    scene::MovingMesh one{{}, {}, b.triangles};
    for (const Vec3& p : b.vertices) {
      one.positions_t0.push_back(placed(b.t0, p));
      one.positions_t1.push_back(placed(b.t1, p));
    }
    scene::append(all, one);
  }
  Scene s;
  s.positions_t0 = all.positions_t0;
  s.positions_t1 = all.positions_t1;
  s.triangles = all.triangles;
  return s;
}

const std::vector<RigidBody>& bodies() {
  static const std::vector<RigidBody> b = tumbling_bodies();
  return b;
}

const Scene& scene() {
  static const Scene s = linear_scene(bodies());
  return s;
}

/// One thread, d = 0 (argument 0) or 1e-3 (argument 1).
SceneOptions options_of(const benchmark::State& state) {
  SceneOptions o;
  o.threads = 1;
  o.min_distance = state.range(0) == 0 ? 0.0 : 1e-3;
  return o;
}

void BM_RigidEarliestToi(benchmark::State& state) {
  std::optional<TimeInterval> toi;
  for (auto _ : state) benchmark::DoNotOptimize(toi = rigid_earliest_toi(bodies(), options_of(state)));
  state.counters["toi_lo"] = toi ? toi->lo : -1;
}

void BM_LinearEarliestToi(benchmark::State& state) {
  std::optional<TimeInterval> toi;
  for (auto _ : state) benchmark::DoNotOptimize(toi = earliest_toi(scene(), options_of(state)));
  state.counters["toi_lo"] = toi ? toi->lo : -1;
}

void BM_RigidFindCollisions(benchmark::State& state) {
  std::size_t pairs = 0;
  for (auto _ : state) benchmark::DoNotOptimize(pairs = rigid_find_collisions(bodies(), options_of(state)).size());
  state.counters["pairs"] = static_cast<double>(pairs);
}

void BM_LinearFindCollisions(benchmark::State& state) {
  std::size_t pairs = 0;
  for (auto _ : state) benchmark::DoNotOptimize(pairs = find_collisions(scene(), options_of(state)).size());
  state.counters["pairs"] = static_cast<double>(pairs);
}

BENCHMARK(BM_RigidEarliestToi)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinearEarliestToi)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RigidFindCollisions)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinearFindCollisions)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
