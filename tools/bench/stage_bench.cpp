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
#include "numeric/fp_environment.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "filter/volume_exclusion.hpp"
#include "questions/contact_question.hpp"
#include "methods/methods.hpp"

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

// An edge pair of the helical strip (data/sim/sim-strip-edge-edge.csv, query 195) that the
// interval stage leaves open (a common root of V and w without an exact visible factor): it
// reaches the integer stage, fixed-width first.
const exactccd::EdgeEdgeQuery kStripCommonRoot{
    {-0x1.889e1abf495dfp-3, 0x1.d9ee6dbf18a5dp-2, 0x1.4a0711c49cf91p-2},
    {-0x1.881e2531b4d89p-3, 0x1.d953f7e1ce1a4p-2, 0x1.6e95c57706f1bp-2},
    {-0x1.879e2fa420536p-3, 0x1.d8b98204838ebp-2, 0x1.151ac0c52df8ep-2},
    {-0x1.871e3a168bce0p-3, 0x1.d81f0c2739032p-2, 0x1.3b8b825256049p-2},
    {-0x1.87d57ad855790p-3, 0x1.d8fc40dc3c22bp-2, 0x1.2ee2ec70ad8d5p-2},
    {-0x1.87db453a0e36ep-3, 0x1.d9033e40d9ee8p-2, 0x1.50ee8b1b7d975p-2},
    {-0x1.87e10f9bc6f50p-3, 0x1.d90a3ba577ba5p-2, 0x1.06344b5305ab6p-2},
    {-0x1.87e6d9fd7fb2ep-3, 0x1.d911390a15863p-2, 0x1.262178b3299a7p-2}};

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
    exactccd::filter::RootCells findings;
    benchmark::DoNotOptimize(exactccd::filter::interval_stage(q, false, findings));
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

// The integer stage in fixed-width (1024-bit, no allocation) and in GMP integers, on the query
// above and on the strip's common root (integer_stage.hpp, fixed_integer_stage).
template <class Query>
void BM_FixedIntegerStageOn(benchmark::State& state, const Query& query) {
  Query q = query;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::fixed_integer_stage(q, false));
  }
}
template <class Query>
void BM_GmpIntegerStageOn(benchmark::State& state, const Query& query) {
  Query q = query;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(exactccd::filter::integer_stage(q, false));
  }
}
BENCHMARK_CAPTURE(BM_FixedIntegerStageOn, through_vertex, kThroughVertex);
BENCHMARK_CAPTURE(BM_GmpIntegerStageOn, through_vertex, kThroughVertex);
BENCHMARK_CAPTURE(BM_FixedIntegerStageOn, strip_common_root, kStripCommonRoot);
BENCHMARK_CAPTURE(BM_GmpIntegerStageOn, strip_common_root, kStripCommonRoot);

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
    benchmark::DoNotOptimize(exactccd::questions::contact_question(q, exactccd::pipeline::Question{}, nullptr));
  }
}
BENCHMARK_CAPTURE(BM_FilteredUnguarded, filtered_miss_unguarded, kMiss);
BENCHMARK_CAPTURE(BM_FilteredUnguarded, filtered_hit_unguarded, kHit);

// The guard alone (fp_environment.hpp): in the default environment it only reads the control
// registers; in upward rounding it installs the default and restores the caller's.
void BM_FpEnvironmentGuard(benchmark::State& state, int rounding) {
  std::fesetround(rounding);
  for (auto _ : state) {
    const exactccd::numeric::DefaultFpEnvironment guard;
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
