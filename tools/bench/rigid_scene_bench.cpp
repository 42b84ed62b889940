// Rigid scenes against linear ones over the same vertices (Google Benchmark; issue 35, item 4):
// 27 ellipsoid-like bodies (icospheres of 320 triangles, radii 1, 0.7 and 0.5; 8 640 triangles
// in all) on a 3 x 3 x 3 grid 2.2 apart, each tumbling (a random start rotation, then 0.6 rad
// about a random axis) and moving towards the grid's centre by up to 0.35, so that neighbours
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

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "exactccd/rigid.hpp"
#include "exactccd/scene.hpp"

namespace {

using namespace exactccd;

/// A closed triangle mesh.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

Vec3 unit(const Vec3& v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / n, v.y / n, v.z / n};
}

/// The regular icosahedron on the unit sphere.
Mesh icosahedron() {
  const double g = (1 + std::sqrt(5.0)) / 2;
  Mesh m;
  for (const Vec3& v : std::vector<Vec3>{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}})
    m.vertices.push_back(unit(v));
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

/// Each triangle split into four, the new vertices pushed onto the unit sphere.
Mesh subdivided(const Mesh& m) {
  Mesh r{m.vertices, {}};
  std::map<std::pair<int, int>, int> midpoint;
  const auto middle = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    const Vec3 &p = r.vertices[static_cast<std::size_t>(a)], &q = r.vertices[static_cast<std::size_t>(b)];
    r.vertices.push_back(unit({p.x + q.x, p.y + q.y, p.z + q.z}));
    return midpoint[key] = static_cast<int>(r.vertices.size() - 1);
  };
  for (const auto& t : m.triangles) {
    const int ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
    r.triangles.insert(r.triangles.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
  }
  return r;
}

/// The ellipsoid-like body: an icosphere of 320 triangles with radii 1, 0.7 and 0.5.
Mesh ellipsoid() {
  Mesh m = subdivided(subdivided(icosahedron()));
  for (Vec3& v : m.vertices) v = {v.x, 0.7 * v.y, 0.5 * v.z};
  return m;
}

/// The quaternion product a b (the rotation b, then a).
Quaternion product(const Quaternion& a, const Quaternion& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// The rotation by `angle` about a random axis.
Quaternion random_rotation(std::mt19937_64& rng, double angle) {
  std::normal_distribution<double> normal;
  const Vec3 axis = unit({normal(rng), normal(rng), normal(rng)});
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * axis.x, s * axis.y, s * axis.z};
}

/// The 27 tumbling bodies of the header.
std::vector<RigidBody> tumbling_bodies() {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> speed(0.3, 0.9);
  const Mesh shape = ellipsoid();
  std::vector<RigidBody> bodies;
  for (int i = 0; i < 27; ++i) {
    const Vec3 c0{2.0 * (i % 3 - 1), 2.0 * (i / 3 % 3 - 1), 2.0 * (i / 9 - 1)};
    const Quaternion q0 = random_rotation(rng, 3.0);
    const double v = speed(rng);  // towards the centre (the centre body moves at random)
    const Vec3 towards = i == 13 ? unit({1, 1, 1}) : unit({-c0.x, -c0.y, -c0.z});
    const RigidPose t0{c0, q0};
    const RigidPose t1{{c0.x + v * towards.x, c0.y + v * towards.y, c0.z + v * towards.z},
                       product(random_rotation(rng, 0.6), q0)};
    bodies.push_back({shape.vertices, shape.triangles, t0, t1});
  }
  return bodies;
}

/// The body point p at the pose (c + R(q) p, rounded as written).
Vec3 placed(const RigidPose& pose, const Vec3& p) {
  const Quaternion& q = pose.q;
  const double n = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  const double m[3][3] = {{q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z, 2 * (q.x * q.y - q.w * q.z),
                           2 * (q.x * q.z + q.w * q.y)},
                          {2 * (q.x * q.y + q.w * q.z), q.w * q.w - q.x * q.x + q.y * q.y - q.z * q.z,
                           2 * (q.y * q.z - q.w * q.x)},
                          {2 * (q.x * q.z - q.w * q.y), 2 * (q.y * q.z + q.w * q.x),
                           q.w * q.w - q.x * q.x - q.y * q.y + q.z * q.z}};
  return {pose.c.x + (m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z) / n,
          pose.c.y + (m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z) / n,
          pose.c.z + (m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z) / n};
}

/// The linear scene of the bodies' vertices at their start and end positions.
Scene linear_scene(const std::vector<RigidBody>& bodies) {
  Scene s;
  for (const RigidBody& b : bodies) {
    const int offset = static_cast<int>(s.positions_t0.size());
    for (const Vec3& p : b.vertices) {
      s.positions_t0.push_back(placed(b.t0, p));
      s.positions_t1.push_back(placed(b.t1, p));
    }
    for (const auto& t : b.triangles) s.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
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
