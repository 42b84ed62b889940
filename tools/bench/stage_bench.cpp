// Micro-costs of each stage of the filtered method, and of the naive (tools) and exact methods, on
// representative single queries (Google Benchmark). Whole-dataset figures: `exactccd bench`.
//
//   build/stage_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cfenv>
#if defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "exactccd/exactccd.hpp"
#include "filter/filtered_ccd.hpp"
#include "filter/fp_environment.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "filter/volume_exclusion.hpp"
#include "tools/methods.hpp"

namespace {

using exactccd::Method;
using exactccd::VertexFaceQuery;

// A vertex passing well above a moving triangle: V(t) keeps its sign (stage 1 decides).
const VertexFaceQuery kMiss{{0.3, 0.2, 1.0},  {0.0, 0.0, 0.0}, {1.0, 0.1, 0.0}, {0.1, 1.0, 0.05},
                            {0.35, 0.25, 0.8}, {0.0, 0.0, 0.1}, {1.0, 0.1, 0.1}, {0.1, 1.0, 0.1}};
// A vertex falling through the triangle interior at an irrational-looking time (stage 2).
const VertexFaceQuery kHit{{0.3, 0.2, 1.0},  {0.0, 0.0, 0.0}, {1.0, 0.1, 0.0}, {0.1, 1.0, 0.05},
                           {0.31, 0.21, -0.7}, {0.0, 0.0, 0.1}, {1.0, 0.1, 0.1}, {0.1, 1.0, 0.1}};
// A vertex hitting a triangle vertex exactly (a sign vanishes at the root: stage 3).
const VertexFaceQuery kThroughVertex{{0.0, 0.0, 1.0},  {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                     {0.0, 0.0, -2.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};

// Each benchmark copies its query and hides it from the optimiser (DoNotOptimize on the copy),
// so that no part of the computation is folded at compile time.
void BM_VolumeExclusion(benchmark::State& state) {
  VertexFaceQuery q = kMiss;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::volume_excluded(q));
  }
}
BENCHMARK(BM_VolumeExclusion);

void BM_IntervalStage(benchmark::State& state) {
  VertexFaceQuery q = kHit;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::interval_stage(q, false));
  }
}
BENCHMARK(BM_IntervalStage);

void BM_IntegerStage(benchmark::State& state) {
  VertexFaceQuery q = kThroughVertex;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::integer_stage(q, false));
  }
}
BENCHMARK(BM_IntegerStage);

// M: exactccd::Method (the public entry point) or exactccd::tools::Method (the baselines,
// which the installed library does not hold); ccd() is the overload of M's namespace.
template <class M>
void BM_Method(benchmark::State& state, const VertexFaceQuery& query, M m) {
  VertexFaceQuery q = query;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(ccd(q, m));
  }
}
// The filter stages without the public entry point (no finiteness check, no floating-point
// environment guard): the difference to filtered_miss is what the entry point costs.
void BM_FilteredUnguarded(benchmark::State& state, const VertexFaceQuery& query) {
  VertexFaceQuery q = query;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::filtered(q, false, nullptr));
  }
}
BENCHMARK_CAPTURE(BM_FilteredUnguarded, filtered_miss_unguarded, kMiss);
BENCHMARK_CAPTURE(BM_FilteredUnguarded, filtered_hit_unguarded, kHit);

// The guard alone (fp_environment.hpp): in the default environment it only reads the control
// registers; in upward rounding it installs the default and restores the caller's.
void BM_FpEnvironmentGuard(benchmark::State& state, int rounding) {
  std::fesetround(rounding);
  for (auto _ : state) {
    const exactccd::filter::DefaultFpEnvironment guard;
    benchmark::DoNotOptimize(guard.changed());
  }
  std::fesetenv(FE_DFL_ENV);
}
BENCHMARK_CAPTURE(BM_FpEnvironmentGuard, caller_default, FE_TONEAREST);
BENCHMARK_CAPTURE(BM_FpEnvironmentGuard, caller_upward, FE_UPWARD);

// The same query with the caller's thread in a non-default floating-point environment: the
// entry point's guard saves it, installs the default and restores it (fp_environment.hpp).
void BM_MethodInEnvironment(benchmark::State& state, const VertexFaceQuery& query, Method m, int rounding,
                            bool ftz_daz) {
  std::fesetround(rounding);
#if defined(__x86_64__)
  if (ftz_daz) _mm_setcsr(_mm_getcsr() | 0x8040u);
#else
  (void)ftz_daz;
#endif
  VertexFaceQuery q = query;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::vertex_face_ccd(q, m));
  }
  std::fesetenv(FE_DFL_ENV);
}
BENCHMARK_CAPTURE(BM_MethodInEnvironment, filtered_miss_upward, kMiss, Method::filtered, FE_UPWARD, false);
BENCHMARK_CAPTURE(BM_MethodInEnvironment, filtered_miss_ftz_daz, kMiss, Method::filtered, FE_TONEAREST, true);
BENCHMARK_CAPTURE(BM_MethodInEnvironment, filtered_hit_ftz_daz, kHit, Method::filtered, FE_TONEAREST, true);
BENCHMARK_CAPTURE(BM_MethodInEnvironment, filtered_hit_upward, kHit, Method::filtered, FE_UPWARD, false);

BENCHMARK_CAPTURE(BM_Method, naive_miss, kMiss, exactccd::tools::Method::naive);
BENCHMARK_CAPTURE(BM_Method, filtered_miss, kMiss, Method::filtered);
BENCHMARK_CAPTURE(BM_Method, exact_miss, kMiss, Method::exact);
BENCHMARK_CAPTURE(BM_Method, naive_hit, kHit, exactccd::tools::Method::naive);
BENCHMARK_CAPTURE(BM_Method, filtered_hit, kHit, Method::filtered);
BENCHMARK_CAPTURE(BM_Method, exact_hit, kHit, Method::exact);
BENCHMARK_CAPTURE(BM_Method, filtered_through_vertex, kThroughVertex, Method::filtered);
BENCHMARK_CAPTURE(BM_Method, exact_through_vertex, kThroughVertex, Method::exact);

}  // namespace

BENCHMARK_MAIN();
