// The library's parallel loops on oneTBB (lib/scene/parallel.hpp) inside a caller's own TBB
// loops, as a simulator built on the IPC Toolkit or Scalable CCD calls them: the scene
// functions, SceneBroadPhase, the functions over a caller's candidates and intersection_free,
// called from the bodies of a tbb::parallel_for, give the answers of one thread and finish (no
// deadlock), on the caller's threads: the threads the process ran during the loop (sampled
// from /proc/self/task) stay within the caller's task arena's concurrency, where a library
// starting threads of its own per call would add new ones. A cancellation inside, or the
// caller's loop cancelled by an exception, never yields a partial answer.
#include <gtest/gtest.h>
#if defined(__x86_64__)
#include <xmmintrin.h>
#endif
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <atomic>
#include <cmath>
#include <chrono>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include "exactccd/exactccd.hpp"
#include "scene/scene_primitives.hpp"
#include "scenes/procedural_scenes.hpp"
#include "tests/scene_support.hpp"

namespace exactccd {
namespace {

/// One step of the cloth and, for a line search, its positions halfway; the candidates of its
/// broad phase as a caller's list (rows of vertex indices).
struct Fixture {
  Scene scene;
  std::vector<Vec3> halfway;
  CandidateSet candidates;
};

/// The cloth at a resolution (32: 3.3k triangles, 16: 1.8k).
Fixture make_fixture(int resolution) {
  Fixture x;
  const scene::MovingMesh m = scene::procedural_scene("cloth", resolution, 1);
  x.scene = Scene{m.positions_t0, m.positions_t1, m.triangles, {}, {}};
  for (std::size_t i = 0; i < m.positions_t0.size(); ++i) {
    const Vec3 &a = m.positions_t0[i], &b = m.positions_t1[i];
    x.halfway.push_back({a.x + 0.5 * (b.x - a.x), a.y + 0.5 * (b.y - a.y), a.z + 0.5 * (b.z - a.z)});
  }
  const scene::ScenePrimitives prim = scene::scene_primitives(x.scene);
  for (const auto& [v, t] : prim.candidates.vertex_face) {
    const auto& tri = x.scene.triangles[static_cast<std::size_t>(t)];
    x.candidates.vertex_face.push_back({v, tri[0], tri[1], tri[2]});
  }
  for (const auto& [i, j] : prim.candidates.edge_edge) {
    const auto &a = prim.edges[static_cast<std::size_t>(i)], &b = prim.edges[static_cast<std::size_t>(j)];
    x.candidates.edge_edge.push_back({a[0], a[1], b[0], b[1]});
  }
  return x;
}

const Fixture& fixture() {
  static const Fixture f = make_fixture(32);
  return f;
}

/// Every answer asked of the fixture on `threads` threads.
struct Answers {
  std::vector<Collision> collisions;
  std::optional<TimeInterval> earliest;
  bool collision_free = false;
  double step = -1, halfway_step = -1;  // the free function; SceneBroadPhase after update()
  std::vector<CandidateCollision> listed;
  std::optional<TimeInterval> listed_earliest;
  bool intersection_free_t1 = false;
};

Answers answers(const Fixture& f, unsigned threads) {
  SceneOptions o;
  o.threads = threads;
  Answers a;
  a.collisions = find_collisions(f.scene, o);
  a.earliest = earliest_toi(f.scene, o);
  a.collision_free = is_collision_free(f.scene, o);
  a.step = max_collision_free_step(f.scene, o);
  SceneBroadPhase broad(f.scene, o);
  broad.update(f.halfway);
  a.halfway_step = broad.max_collision_free_step();
  a.listed = find_collisions(f.scene.positions_t0, f.scene.positions_t1, f.candidates, o);
  a.listed_earliest = earliest_toi(f.scene.positions_t0, f.scene.positions_t1, f.candidates, o);
  a.intersection_free_t1 = intersection_free(f.scene.positions_t1, f.scene.triangles, threads);
  return a;
}

bool same_toi(const std::optional<TimeInterval>& a, const std::optional<TimeInterval>& b) {
  return a.has_value() == b.has_value() && (!a || (a->lo == b->lo && a->hi == b->hi));
}

bool same_answers(const Answers& got, const Answers& want) {
  if (got.collisions.size() != want.collisions.size() || got.listed.size() != want.listed.size()) return false;
  for (std::size_t k = 0; k < got.collisions.size(); ++k)
    if (!testing::same(got.collisions[k], want.collisions[k])) return false;
  for (std::size_t k = 0; k < got.listed.size(); ++k) {
    const CandidateCollision &g = got.listed[k], &w = want.listed[k];
    if (g.kind != w.kind || g.index != w.index || !same_toi(g.toi, w.toi)) return false;
  }
  return same_toi(got.earliest, want.earliest) && got.collision_free == want.collision_free &&
         got.step == want.step && got.halfway_step == want.halfway_step &&
         same_toi(got.listed_earliest, want.listed_earliest) && got.intersection_free_t1 == want.intersection_free_t1;
}

/// The kernel ids of the threads of this process.
std::set<std::string> process_threads() {
  std::set<std::string> ids;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task", error))
    ids.insert(entry.path().filename().string());
  return ids;
}

/// Samples the threads of this process every 50 us on a thread of its own, from construction
/// to stop(): the threads that existed before, and every thread seen since (not itself).
class ThreadSampler {
 public:
  ThreadSampler() : before_(process_threads()), sampler_([this] { run(); }) {}
  ~ThreadSampler() {
    if (sampler_.joinable()) stop();
  }

  /// Stops sampling; the threads seen that did not exist before the sampler.
  std::set<std::string> stop() {
    done_ = true;
    sampler_.join();
    std::set<std::string> added;
    for (const std::string& id : seen_)
      if (!before_.count(id) && id != own_) added.insert(id);
    return added;
  }

 private:
  void run() {
    own_ = std::to_string(gettid());
    while (!done_.load()) {
      for (const std::string& id : process_threads()) seen_.insert(id);
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
  }

  std::set<std::string> before_, seen_;
  std::string own_;
  std::atomic<bool> done_{false};
  std::thread sampler_;
};

constexpr int kIterations = 12;

// In a caller's arena of two threads, calls asking for 0 (every hardware thread), 2 and 3
// threads run on the caller's threads: at most one thread besides the caller's own is ever
// added to the process (the arena's worker), while the calls give one thread's answers.
TEST(CallerParallelFor, CallsRunOnTheCallersThreadsWithOneThreadsAnswers) {
  if (process_threads().empty()) GTEST_SKIP() << "no /proc/self/task to count the threads";
  const Fixture& f = fixture();
  const Answers want = answers(f, 1);
  ASSERT_FALSE(want.collisions.empty());
  ASSERT_FALSE(want.listed.empty());
  constexpr int kCallerThreads = 2;
  tbb::task_arena caller(kCallerThreads);
  std::vector<Answers> got(kIterations);
  ThreadSampler sampler;
  caller.execute([&] {
    tbb::parallel_for(0, kIterations, [&](int i) {
      constexpr unsigned kThreads[] = {0, 2, 3};
      got[static_cast<std::size_t>(i)] = answers(f, kThreads[i % 3]);
    });
  });
  const std::set<std::string> added = sampler.stop();
  for (int i = 0; i < kIterations; ++i) EXPECT_TRUE(same_answers(got[static_cast<std::size_t>(i)], want)) << i;
  EXPECT_LE(added.size(), static_cast<std::size_t>(kCallerThreads - 1))
      << "threads added to the process while the caller's arena of " << kCallerThreads << " ran the calls";
}

// In a caller's arena of three threads, calls asking for two run in task arenas of two (one
// per call; SceneBroadPhase lends its kept arena to one call at a time): a broad phase shared
// by every iteration answers concurrent const calls, nothing deadlocks, the answers are one
// thread's, and the process never runs more than the caller's threads times two.
TEST(CallerParallelFor, CallsWithFewerThreadsThanTheCallerShareAKeptBroadPhase) {
  if (process_threads().empty()) GTEST_SKIP() << "no /proc/self/task to count the threads";
  const Fixture& f = fixture();
  const Answers want = answers(f, 1);
  SceneOptions two;
  two.threads = 2;
  const SceneBroadPhase shared(f.scene, two);
  constexpr int kCallerThreads = 3;
  tbb::task_arena caller(kCallerThreads);
  std::vector<Answers> got(kIterations);
  std::vector<std::vector<Collision>> shared_collisions(kIterations);
  std::vector<double> shared_steps(kIterations);
  ThreadSampler sampler;
  caller.execute([&] {
    tbb::parallel_for(0, kIterations, [&](int i) {
      const auto k = static_cast<std::size_t>(i);
      shared_collisions[k] = shared.find_collisions();
      shared_steps[k] = shared.max_collision_free_step();
      got[k] = answers(f, 2);
    });
  });
  const std::set<std::string> added = sampler.stop();
  for (std::size_t k = 0; k < static_cast<std::size_t>(kIterations); ++k) {
    EXPECT_TRUE(same_answers(got[k], want)) << k;
    EXPECT_EQ(shared_steps[k], want.step) << k;
    ASSERT_EQ(shared_collisions[k].size(), want.collisions.size()) << k;
    for (std::size_t c = 0; c < want.collisions.size(); ++c)
      EXPECT_TRUE(testing::same(shared_collisions[k][c], want.collisions[c])) << k << " #" << c;
  }
  EXPECT_LE(added.size(), static_cast<std::size_t>(2 * kCallerThreads - 1));
}

/// Sets flush-to-zero and denormals-are-zero on this thread (x86-64 MXCSR bits 15 and 6).
void set_ftz_daz(bool on) {
#if defined(__x86_64__)
  const unsigned bits = 0x8040u;
  _mm_setcsr(on ? (_mm_getcsr() | bits) : (_mm_getcsr() & ~bits));
#else
  (void)on;
#endif
}

// A caller's task arena made while its thread flushed subnormals to zero (FTZ and DAZ, as a
// program linked with -ffast-math runs): oneTBB runs every task of that arena in the
// floating-point environment it captured then, the library's loop bodies in their own (the
// default one, installed per task body), so a scene of subnormal coordinates (the cloth scaled
// by 2^-1060) gets the default environment's answers.
TEST(CallerParallelFor, AnArenaMadeInAnotherFpEnvironmentChangesNoAnswer) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "FTZ/DAZ are set through x86-64's MXCSR here";
#endif
  Fixture tiny = make_fixture(16);
  for (std::vector<Vec3>* x : {&tiny.scene.positions_t0, &tiny.scene.positions_t1, &tiny.halfway})
    for (Vec3& p : *x) p = {std::ldexp(p.x, -1060), std::ldexp(p.y, -1060), std::ldexp(p.z, -1060)};
  const Answers want = answers(tiny, 1);
  ASSERT_FALSE(want.collisions.empty());
  set_ftz_daz(true);
  tbb::task_arena caller(2);
  caller.initialize();  // captures FTZ and DAZ for the tasks run in it
  set_ftz_daz(false);
  std::vector<Answers> got(2);
  caller.execute(
      [&] { tbb::parallel_for(0, 2, [&](int i) { got[static_cast<std::size_t>(i)] = answers(tiny, 2); }); });
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same_answers(got[i], want)) << i;
}

// A set cancellation flag inside the caller's loop: every call throws Cancelled, which reaches
// the caller's parallel_for.
TEST(CallerParallelFor, CancellationReachesTheCallersLoop) {
  const Fixture& f = fixture();
  std::atomic<bool> cancel{true};
  tbb::task_arena caller(2);
  EXPECT_THROW(caller.execute([&] {
    tbb::parallel_for(0, 4, [&](int i) {
      SceneOptions o;
      o.threads = i % 2 == 0 ? 0 : 2;
      o.cancel = &cancel;
      find_collisions(f.scene, o);
    });
  }),
               Cancelled);
}

// The caller's loop cancelled by an exception while other iterations are inside scene calls:
// their loops, which run in the caller's task group, stop; each call then throws rather than
// return what it had found so far, and the caller gets its own exception.
TEST(CallerParallelFor, ACancelledCallersLoopGetsNoPartialAnswer) {
  const Fixture& f = fixture();
  const Answers want = answers(f, 1);
  std::atomic<int> wrong{0}, answered{0};
  tbb::task_arena caller(2);
  EXPECT_THROW(caller.execute([&] {
    tbb::parallel_for(
        0, 8,
        [&](int i) {
          if (i == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            throw std::runtime_error("the caller's own failure");
          }
          SceneOptions o;
          o.threads = 2;
          for (int k = 0; k < 50; ++k) {
            const std::vector<Collision> c = find_collisions(f.scene, o);
            const std::vector<CandidateCollision> listed =
                find_collisions(f.scene.positions_t0, f.scene.positions_t1, f.candidates, o);
            ++answered;
            if (c.size() != want.collisions.size() || listed.size() != want.listed.size()) ++wrong;
          }
        },
        tbb::simple_partitioner());
  }),
               std::runtime_error);
  EXPECT_EQ(wrong.load(), 0) << "of " << answered.load() << " answers";
}

}  // namespace
}  // namespace exactccd
