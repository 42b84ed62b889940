// A line search on SceneBroadPhase (update() and max_collision_free_step() for shrinking trial
// steps, what a simulator calls thousands of times) allocates nothing per call once warmed up:
// the vertex and float boxes, the streams' pieces of work and the workers' batches are kept
// (lib/scene), on one thread and on two, in the caller's task arena and in the broad phase's
// kept arena. Its own test program: it replaces the global operator new and delete to count.
//
// Counted: every global operator new (all forms: what the library's, CGAL's and the standard
// library's containers use) and GMP's allocations (mp_set_memory_functions: CGAL's exact path
// and MPFR allocate through them). Not counted: direct malloc calls (the library makes none)
// and oneTBB's own allocator (libtbbmalloc: its task objects come from per-thread pools; its
// count over a steady line search was measured once by hand, docs/scene.md).
//
// One exception, outside the scene code: a query that reaches the filtered method's integer
// stage (lib/filter/integer_stage, its root isolation in lib/exact/integer_poly: a std::deque
// and std::vectors of 1024-bit integers) allocates while it is answered. On the cloth-funnel
// step a few edge-edge queries of the trial steps 1 and 1/2 do (234 and 180 allocations per
// call, every one of them in that stage: found once with a backtrace per allocation); there
// only update() is checked, and max_collision_free_step() on the shorter trial steps.
#include <gmp.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "exactccd/exactccd.hpp"
#include "io/mesh_file.hpp"
#include "scenes/procedural_scenes.hpp"

namespace {

std::atomic<long> g_allocations{0};  // the counter of this test program (the point of the test)

void* counted(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* counted_aligned(std::size_t size, std::align_val_t align) {
  ++g_allocations;
  const std::size_t a = static_cast<std::size_t>(align);
  if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}

void* gmp_allocate(std::size_t size) {
  ++g_allocations;
  return std::malloc(size);
}
void* gmp_reallocate(void* p, std::size_t, std::size_t size) {
  ++g_allocations;
  return std::realloc(p, size);
}
void gmp_free(void* p, std::size_t) { std::free(p); }

}  // namespace

void* operator new(std::size_t size) { return counted(size); }
void* operator new[](std::size_t size) { return counted(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new(std::size_t size, std::align_val_t align) { return counted_aligned(size, align); }
void* operator new[](std::size_t size, std::align_val_t align) { return counted_aligned(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace exactccd {
namespace {

constexpr double kTrialSteps[] = {1.0, 0.5, 0.25, 0.125, 0.0625};

/// A step and the trial positions of a line search over it: x0 + alpha (x1 - x0) for every
/// alpha of kTrialSteps; max_collision_free_step() is checked from the trial `first_checked` on
/// (the earlier ones ask queries that reach the integer stage, see above).
struct LineSearch {
  std::string name;
  Scene scene;
  std::vector<std::vector<Vec3>> trials;
  std::size_t first_checked = 0;
};

LineSearch line_search(std::string name, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                       const std::vector<std::array<int, 3>>& triangles) {
  LineSearch l{std::move(name), Scene{x0, x1, triangles, {}, {}}, {}, 0};
  for (double alpha : kTrialSteps) {
    std::vector<Vec3> x(x0.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = {x0[i].x + alpha * (x1[i].x - x0[i].x), x0[i].y + alpha * (x1[i].y - x0[i].y),
              x0[i].z + alpha * (x1[i].z - x0[i].z)};
    l.trials.push_back(std::move(x));
  }
  return l;
}

/// The procedural cloth falling on a sphere (13k triangles) and, when the shared data is
/// there, the Scalable CCD dataset's cloth-funnel step (18k triangles).
std::vector<LineSearch> line_searches() {
  std::vector<LineSearch> all;
  const scene::MovingMesh cloth = scene::procedural_scene("cloth", 64, 1);
  all.push_back(line_search("cloth 64", cloth.positions_t0, cloth.positions_t1, cloth.triangles));
  const std::filesystem::path funnel = std::filesystem::path(EXACTCCD_SCALABLE_SAMPLE_DIR) / "cloth-funnel/frames";
  if (std::filesystem::exists(funnel / "227.ply")) {
    const io::TriangleMesh m0 = io::read_mesh((funnel / "227.ply").string());
    const io::TriangleMesh m1 = io::read_mesh((funnel / "228.ply").string());
    all.push_back(line_search("cloth-funnel 227", m0.vertices, m1.vertices, m0.triangles));
    all.back().first_checked = 2;  // the steps 1 and 1/2 reach the integer stage (see above)
  }
  return all;
}

/// Runs the line search twice on one SceneBroadPhase; every call of the second pass must
/// allocate nothing and answer as in the first.
void expect_no_allocation_after_warm_up(const LineSearch& l, unsigned threads, const std::string& where) {
  SceneOptions options;
  options.threads = threads;
  SceneBroadPhase broad(l.scene, options);
  std::vector<double> first;
  for (const auto& x : l.trials) {
    broad.update(x);
    first.push_back(broad.max_collision_free_step());
  }
  for (std::size_t k = 0; k < l.trials.size(); ++k) {
    const long before = g_allocations.load();
    broad.update(l.trials[k]);
    const long after_update = g_allocations.load();
    const double step = broad.max_collision_free_step();
    const long after_step = g_allocations.load();
    const std::string what = l.name + ", " + std::to_string(threads) + " threads, " + where + ", trial " + std::to_string(k);
    EXPECT_EQ(after_update - before, 0) << "allocations in update(): " << what;
    if (k >= l.first_checked)
      EXPECT_EQ(after_step - after_update, 0) << "allocations in max_collision_free_step(): " << what;
    else
      std::cout << what << ": " << after_step - after_update << " allocations in the integer stage's queries\n";
    EXPECT_EQ(step, first[k]) << what;
  }
}

TEST(LineSearchAllocations, NoneInTheSteadyState) {
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
  const std::vector<LineSearch> searches = line_searches();
  if (searches.size() < 2) std::cout << "(the cloth-funnel step is absent: EXACTCCD_SCALABLE_SAMPLE_DIR)\n";
  // The counter counts (a call of operator new, which the compiler may not elide).
  const long before = g_allocations.load();
  ::operator delete(::operator new(16));
  ASSERT_EQ(g_allocations.load(), before + 1);
  for (const LineSearch& l : searches)
    for (unsigned threads : {1u, 2u}) {
      expect_no_allocation_after_warm_up(l, threads, "caller's arena");
      // From a caller's arena of more threads than the broad phase's: its kept arena.
      tbb::task_arena larger(4);
      larger.execute([&] { expect_no_allocation_after_warm_up(l, threads, "kept arena"); });
    }
}

}  // namespace
}  // namespace exactccd
