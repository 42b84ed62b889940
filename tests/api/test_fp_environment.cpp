// Every public entry point gives the same answers and TOIs whatever floating-point environment
// the calling thread is in (directed rounding, flush-to-zero and denormals-are-zero, unmasked
// exceptions), and leaves that environment as it found it, also when it throws (design.md, 8).
//
// The references are computed once under the default environment; each environment then
// re-answers every query of the shared sample and of the bundled data through every entry point
// (C++ with and without counters, both exact methods and the tools library's naive baseline,
// rational queries, the C API, the Eigen overloads) and every scene function on the bundled
// scenes (and the batch functions over their broad-phase candidates). After every call the
// control state (MXCSR control bits, x87 control word, fegetround) must be the one the test
// installed. A fault-injection test throws std::bad_alloc from every allocation a query makes
// in turn, and checks the caller's environment after each throw.
#include <gtest/gtest.h>

#include <cfenv>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "exactccd/eigen.hpp"
#include "exactccd/exactccd.h"
#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "numeric/fp_environment.hpp"
#include "io/benchmark_csv.hpp"
#include "io/obj.hpp"
#include "methods/methods.hpp"
#include "generators/families.hpp"
#include "kinds/primitive_kinds.hpp"
#include "scene/scene_primitives.hpp"
#include "tests/fp_environments.hpp"


// ---- fault injection: operator new throws on the n-th allocation of this thread when armed ----
namespace {
thread_local long allocations_until_failure = -1;  // -1: disarmed
thread_local int rounding_at_failure = -1;          // fegetround() when it threw
}  // namespace

// GCC takes the replaced operator delete's free() for a mismatch with operator new (it is the
// matching pair here: both replaced, malloc and free).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t size) {
  if (allocations_until_failure >= 0 && allocations_until_failure-- == 0) {
    rounding_at_failure = std::fegetround();
    throw std::bad_alloc();
  }
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
// The nothrow forms must be replaced too: the standard library allocates with them (for example
// std::stable_sort's temporary buffer) and frees with the plain operator delete below, so a
// sanitizer's own nothrow new would be paired with our free() (ASan: alloc-dealloc-mismatch).
// An injected failure returns null here, which those callers handle by design.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (allocations_until_failure >= 0 && allocations_until_failure-- == 0) {
    rounding_at_failure = std::fegetround();
    return nullptr;
  }
  return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

// LeakSanitizer: CGAL's algebraic kernel is not exception safe when an allocation fails inside
// it (Handle_with_policy allocates a rep and then constructs it in place with no guard, and
// Descartes holds new[] arrays in raw pointers), so the injected bad_alloc leaks inside CGAL's
// own frames. Those two CGAL frames alone are suppressed; a leak in exactccd's code on any
// exception path is still reported.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:CGAL::Handle_with_policy\nleak:CGAL::internal::Descartes\n";
}
#endif

namespace exactccd {
namespace {

namespace fs = std::filesystem;

// ---- environments (tests/fp_environments.hpp) ----------------------------------------------

using testing::control_state;
using testing::ControlState;
using testing::describe;
using testing::Environment;
using testing::install;
using testing::kEnvironments;
using testing::RestoreDefault;
using testing::supported;

// ---- the data -----------------------------------------------------------------------------

struct Query {
  std::string where;  ///< file and index, for messages
  bool vertex_face;
  std::array<RationalVec3, 8> rational;
  std::optional<std::array<Vec3, 8>> doubles;  ///< when every coordinate is a double
};

void load_csv(const fs::path& path, std::vector<Query>& out) {
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  const io::BenchmarkQueries q = io::read_benchmark_csv(in, path.string());
  const bool vf = path.string().rfind("vertex-face") != std::string::npos;
  for (std::size_t i = 0; i < q.size(); ++i)
    out.push_back({path.filename().string() + "#" + std::to_string(i), vf, q.rows[i], io::exact_double_rows(q.rows[i])});
}

/// All shared and bundled benchmark files, and a few wide-exponent queries.
const std::vector<Query>& all_queries() {
  static const std::vector<Query> queries = [] {
    std::vector<Query> out;
    std::vector<fs::path> files;
    for (const char* dir : {"sim", "catalogue", "families"})
      for (const auto& e : fs::directory_iterator(fs::path(EXACTCCD_SOURCE_DIR) / "data" / dir))
        if (e.path().extension() == ".csv") files.push_back(e.path());
    const fs::path sample = fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / "unit-tests";
    if (fs::exists(sample))
      for (const char* kind : {"vertex-face", "edge-edge"})
        for (const auto& e : fs::directory_iterator(sample / kind))
          if (e.path().extension() == ".csv") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) load_csv(f, out);
    // The wide-exponent query of issue 10 (collides at t = 1/2; the static volume filter once
    // answered no), and its edge-edge analogue built from the same points.
    const std::array<Vec3, 8> wide{Vec3{0x1p-360, 0x1p-539, 0}, Vec3{0, 0, 0}, Vec3{0x1p200, 0, 1},
                                   Vec3{0, 0x1p-538, 0},        Vec3{0x1p-360, 0x1p-539, 0x1p-559},
                                   Vec3{0, 0, 0},               Vec3{0x1p200, 0, 1},
                                   Vec3{0, 0x1p-538, 0}};
    std::array<RationalVec3, 8> rational;
    for (std::size_t i = 0; i < 8; ++i) rational[i] = {wide[i].x, wide[i].y, wide[i].z};
    out.push_back({"wide vertex-face", true, rational, wide});
    out.push_back({"wide edge-edge", false, rational, wide});
    // Wide-exponent degenerate families (families::make_wide: per-axis scales from the
    // subnormal to the overflow end, translations, shears), every family and style, both
    // directions, k = 8 and 52: where FTZ/DAZ and directed rounding broke most answers.
    std::mt19937_64 rng(20261202);
    for (const families::Family& f : families::all_families())
      for (int style = 0; style < families::kWideStyleCount; ++style)
        for (int k : {8, 52})
          for (bool toward : {true, false}) {
            const auto inst = families::make_wide(f, k, toward, static_cast<families::WideStyle>(style), rng);
            if (!inst) continue;
            std::visit([&](const auto& q) {
              const auto d = rows(q);
              std::array<RationalVec3, 8> r;
              for (std::size_t i = 0; i < 8; ++i) r[i] = {d[i].x, d[i].y, d[i].z};
              out.push_back({f.name + " wide " + families::wide_style_name(static_cast<families::WideStyle>(style)) +
                                 " k=" + std::to_string(k) + (toward ? " toward" : " away"),
                             std::is_same_v<std::decay_t<decltype(q)>, VertexFaceQuery>, r, d});
            }, inst->query);
          }
    return out;
  }();
  return queries;
}

bool have_shared_data() { return fs::exists(fs::path(EXACTCCD_SAMPLE_QUERIES_DIR) / "unit-tests"); }

// ---- answering a query through every entry point ------------------------------------------

/// The answers of one query through every entry point, as a flat list of TOIs (nullopt: no
/// collision; a boolean answer is recorded as [0, 0] or nullopt). Checks the control state after
/// every call against `expected`.
std::vector<std::optional<TimeInterval>> answers(const Query& q, bool with_exact, const ControlState& expected) {
  std::vector<std::optional<TimeInterval>> out;
  const auto boolean = [](bool b) { return b ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt; };
  const auto check = [&](const char* entry) {
    const ControlState now = control_state();
    EXPECT_TRUE(now == expected) << q.where << ": " << entry << " left " << describe(now) << ", expected "
                                 << describe(expected);
  };
  // Rational entry points (every query; the CGAL path, so only with_exact for doubles).
  if (!q.doubles || with_exact) {
    if (q.vertex_face) {
      const auto r = from_rows<RationalVertexFaceQuery>(q.rational);
      out.push_back(boolean(vertex_face_ccd(r)));
      check("vertex_face_ccd(rational)");
      out.push_back(vertex_face_toi(r));
      check("vertex_face_toi(rational)");
    } else {
      const auto r = from_rows<RationalEdgeEdgeQuery>(q.rational);
      out.push_back(boolean(edge_edge_ccd(r)));
      check("edge_edge_ccd(rational)");
      out.push_back(edge_edge_toi(r));
      check("edge_edge_toi(rational)");
    }
  }
  if (!q.doubles) return out;
  const std::array<Vec3, 8>& d = *q.doubles;
  // Every method by tools::Method: the library's through its entry points, and the naive
  // baseline (tools library), which installs the default environment alike.
  std::vector<tools::Method> methods{tools::Method::filtered, tools::Method::naive};
  if (with_exact) methods.push_back(tools::Method::exact);
  double flat[24];
  for (int i = 0; i < 8; ++i) flat[3 * i] = d[i].x, flat[3 * i + 1] = d[i].y, flat[3 * i + 2] = d[i].z;
  const auto e = [&](int i) { return Eigen::Vector3d(d[i].x, d[i].y, d[i].z); };
  int collides = -1;
  double lo = -1, hi = -1;
  if (q.vertex_face) {
    const auto v = from_rows<VertexFaceQuery>(d);
    out.push_back(boolean(vertex_face_ccd(v)));
    check("vertex_face_ccd");
    out.push_back(vertex_face_toi(v));
    check("vertex_face_toi");
    for (tools::Method m : methods) {
      StageCounters c;
      out.push_back(boolean(tools::ccd(v, m)));
      check("vertex_face_ccd(method)");
      out.push_back(boolean(tools::ccd(v, m, c)));
      check("vertex_face_ccd(method, counters)");
      out.push_back(tools::toi(v, m));
      check("vertex_face_toi(method)");
      out.push_back(tools::toi(v, m, c));
      check("vertex_face_toi(method, counters)");
    }
    EXPECT_EQ(exactccd_vertex_face_ccd(flat, &collides), EXACTCCD_OK);
    out.push_back(boolean(collides == 1));
    check("exactccd_vertex_face_ccd");
    EXPECT_EQ(exactccd_vertex_face_toi(flat, &collides, &lo, &hi), EXACTCCD_OK);
    out.push_back(collides ? std::optional<TimeInterval>(TimeInterval{lo, hi}) : std::nullopt);
    check("exactccd_vertex_face_toi");
    out.push_back(boolean(vertex_face_ccd(e(0), e(1), e(2), e(3), e(4), e(5), e(6), e(7))));
    check("vertex_face_ccd(Eigen)");
    out.push_back(vertex_face_toi(e(0), e(1), e(2), e(3), e(4), e(5), e(6), e(7)));
    check("vertex_face_toi(Eigen)");
  } else {
    const auto v = from_rows<EdgeEdgeQuery>(d);
    out.push_back(boolean(edge_edge_ccd(v)));
    check("edge_edge_ccd");
    out.push_back(edge_edge_toi(v));
    check("edge_edge_toi");
    for (tools::Method m : methods) {
      StageCounters c;
      out.push_back(boolean(tools::ccd(v, m)));
      check("edge_edge_ccd(method)");
      out.push_back(boolean(tools::ccd(v, m, c)));
      check("edge_edge_ccd(method, counters)");
      out.push_back(tools::toi(v, m));
      check("edge_edge_toi(method)");
      out.push_back(tools::toi(v, m, c));
      check("edge_edge_toi(method, counters)");
    }
    EXPECT_EQ(exactccd_edge_edge_ccd(flat, &collides), EXACTCCD_OK);
    out.push_back(boolean(collides == 1));
    check("exactccd_edge_edge_ccd");
    EXPECT_EQ(exactccd_edge_edge_toi(flat, &collides, &lo, &hi), EXACTCCD_OK);
    out.push_back(collides ? std::optional<TimeInterval>(TimeInterval{lo, hi}) : std::nullopt);
    check("exactccd_edge_edge_toi");
    out.push_back(boolean(edge_edge_ccd(e(0), e(1), e(2), e(3), e(4), e(5), e(6), e(7))));
    check("edge_edge_ccd(Eigen)");
    out.push_back(edge_edge_toi(e(0), e(1), e(2), e(3), e(4), e(5), e(6), e(7)));
    check("edge_edge_toi(Eigen)");
  }
  return out;
}

/// The CGAL path costs ~100 us per query: every 7th double query takes it in every environment.
bool with_exact(std::size_t i) { return i % 7 == 0; }

std::string describe(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  char buf[80];
  std::snprintf(buf, sizeof buf, "[%a, %a]", t->lo, t->hi);
  return buf;
}

class EveryEnvironment : public ::testing::TestWithParam<Environment> {};

TEST_P(EveryEnvironment, QueriesGiveDefaultAnswersAndLeaveTheEnvironment) {
  const Environment env = GetParam();
  if (!supported(env)) GTEST_SKIP() << "cannot install " << env.name << " on this platform";
  if (!have_shared_data())
    std::cout << "[ note     ] shared sample not found under " << EXACTCCD_SAMPLE_QUERIES_DIR
              << ": bundled data only\n";
  const std::vector<Query>& queries = all_queries();
  ASSERT_GT(queries.size(), 3000u);
  std::vector<std::vector<std::optional<TimeInterval>>> reference;
  {
    const RestoreDefault restore;
    std::fesetenv(FE_DFL_ENV);
    const ControlState dfl = control_state();
    for (std::size_t i = 0; i < queries.size(); ++i) reference.push_back(answers(queries[i], with_exact(i), dfl));
  }
  const RestoreDefault restore;
  install(env);
  const ControlState installed = control_state();
  std::size_t differences = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto got = answers(queries[i], with_exact(i), installed);
    ASSERT_EQ(got.size(), reference[i].size());
    for (std::size_t k = 0; k < got.size(); ++k)
      if (got[k].has_value() != reference[i][k].has_value() || (got[k] && !(*got[k] == *reference[i][k]))) {
        if (++differences <= 10)
          ADD_FAILURE() << env.name << ": " << queries[i].where << " answer " << k << ": " << describe(got[k])
                        << " instead of " << describe(reference[i][k]);
      }
  }
  EXPECT_EQ(differences, 0u);
  EXPECT_TRUE(control_state() == installed);
}

// Status flags: a caller in a non-default environment finds its flags as it left them (the
// guard restores MXCSR and the x87 environment whole, or the whole fenv), although the
// filters raise inexact, underflow and overflow inside, and the long-double guesses raise x87
// flags. Every environment of the list is non-default.
TEST_P(EveryEnvironment, StatusFlagsAreAsTheCallerLeftThem) {
  const Environment env = GetParam();
  if (!supported(env)) GTEST_SKIP() << "cannot install " << env.name << " on this platform";
  const RestoreDefault restore;
  install(env);
  std::feclearexcept(FE_ALL_EXCEPT);
  // A query through the interval stage and the TOI narrowing (long double Newton guess), and
  // one through the integer stage (a vertex hitting a triangle vertex exactly).
  const VertexFaceQuery hit{{0.3, 0.2, 1.0},   {0.0, 0.0, 0.0}, {1.0, 0.1, 0.0}, {0.1, 1.0, 0.05},
                            {0.31, 0.21, -0.7}, {0.0, 0.0, 0.1}, {1.0, 0.1, 0.1}, {0.1, 1.0, 0.1}};
  const VertexFaceQuery through_vertex{{0.0, 0.0, 1.0},  {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                       {0.0, 0.0, -2.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
  for (Method m : {Method::filtered, Method::exact}) {
    EXPECT_TRUE(vertex_face_toi(hit, m).has_value());
    EXPECT_TRUE(vertex_face_toi(through_vertex, m).has_value());
  }
  EXPECT_EQ(std::fetestexcept(FE_ALL_EXCEPT), 0) << env.name << ": status flags raised inside were left behind";
  // A caller with flags of its own raised (in the x87 and the SSE status: a long double and a
  // double division) finds exactly those.
  volatile long double one_l = 1, three_l = 3;
  volatile double one = 1, three = 3;
  const volatile long double third_l = one_l / three_l;
  const volatile double third = one / three;
  (void)third_l;
  (void)third;
  const int raised = std::fetestexcept(FE_ALL_EXCEPT);
  EXPECT_NE(raised, 0);
  for (Method m : {Method::filtered, Method::exact}) EXPECT_TRUE(vertex_face_toi(hit, m).has_value());
  EXPECT_EQ(std::fetestexcept(FE_ALL_EXCEPT), raised) << env.name << ": the caller's own flags changed";
}

TEST_P(EveryEnvironment, ThrowingEntryPointsRestoreTheEnvironment) {
  const Environment env = GetParam();
  if (!supported(env)) GTEST_SKIP() << "cannot install " << env.name << " on this platform";
  const RestoreDefault restore;
  install(env);
  const ControlState installed = control_state();
  // A NaN coordinate: std::invalid_argument from inside the entry point's environment guard.
  VertexFaceQuery vf{};
  vf.p_t1.z = std::numeric_limits<double>::quiet_NaN();
  EdgeEdgeQuery ee{};
  ee.b1_t0.x = std::numeric_limits<double>::infinity();
  for (tools::Method m : {tools::Method::filtered, tools::Method::exact, tools::Method::naive}) {
    EXPECT_THROW(tools::ccd(vf, m), std::invalid_argument);
    EXPECT_TRUE(control_state() == installed) << env.name << " after vertex_face_ccd threw";
    EXPECT_THROW(tools::toi(ee, m), std::invalid_argument);
    EXPECT_TRUE(control_state() == installed) << env.name << " after edge_edge_toi threw";
  }
  double flat[24] = {};
  flat[7] = std::numeric_limits<double>::quiet_NaN();
  int collides = 0;
  EXPECT_EQ(exactccd_vertex_face_ccd(flat, &collides), EXACTCCD_ERROR_NON_FINITE);
  EXPECT_TRUE(control_state() == installed);
  // A malformed scene (an index out of range) throws from inside the scene functions' guard.
  Scene bad;
  bad.positions_t0 = bad.positions_t1 = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  bad.triangles = {{0, 1, 7}};
  EXPECT_THROW(find_collisions(bad), std::invalid_argument);
  EXPECT_TRUE(control_state() == installed);
  EXPECT_THROW(earliest_toi(bad), std::invalid_argument);
  EXPECT_TRUE(control_state() == installed);
  EXPECT_THROW(intersection_free(bad.positions_t0, bad.triangles), std::invalid_argument);
  EXPECT_TRUE(control_state() == installed);
}

// ---- scenes -------------------------------------------------------------------------------

Scene load_scene(const std::string& name) {
  const fs::path dir = fs::path(EXACTCCD_SOURCE_DIR) / "data" / "scenes" / name;
  std::ifstream in0(dir / "T0.obj"), in1(dir / "T1.obj");
  const io::ObjMesh m0 = io::read_obj(in0, "T0.obj"), m1 = io::read_obj(in1, "T1.obj");
  Scene s;
  s.positions_t0 = m0.vertices;
  s.positions_t1 = m1.vertices;
  s.triangles = m0.triangles;
  return s;
}

struct SceneAnswers {
  std::vector<Collision> collisions;
  std::optional<TimeInterval> earliest;
  bool collision_free = false;
  double step = -1;
  bool free0 = false, free1 = false;
  // The batch functions over the scene's own broad-phase candidates (exactccd/candidates.hpp).
  std::vector<CandidateCollision> batch;
  std::optional<TimeInterval> batch_earliest;
  bool batch_free = false;
  double batch_step = -1;
};

bool operator==(const SceneAnswers& a, const SceneAnswers& b) {
  if (a.collisions.size() != b.collisions.size()) return false;
  for (std::size_t i = 0; i < a.collisions.size(); ++i) {
    const Collision &x = a.collisions[i], &y = b.collisions[i];
    if (x.kind != y.kind || x.vertex != y.vertex || x.triangle != y.triangle || x.edge_a != y.edge_a ||
        x.edge_b != y.edge_b || !(x.toi == y.toi))
      return false;
  }
  return a.earliest.has_value() == b.earliest.has_value() && (!a.earliest || *a.earliest == *b.earliest) &&
         a.collision_free == b.collision_free && a.step == b.step && a.free0 == b.free0 && a.free1 == b.free1 &&
         a.batch.size() == b.batch.size() &&
         std::equal(a.batch.begin(), a.batch.end(), b.batch.begin(),
                    [](const CandidateCollision& x, const CandidateCollision& y) {
                      return x.kind == y.kind && x.index == y.index && x.toi == y.toi;
                    }) &&
         a.batch_earliest.has_value() == b.batch_earliest.has_value() &&
         (!a.batch_earliest || *a.batch_earliest == *b.batch_earliest) && a.batch_free == b.batch_free &&
         a.batch_step == b.batch_step;
}

/// The scene's own broad-phase candidates (d = 0, tmax = 1) as a CandidateSet of vertex indices.
CandidateSet scene_candidate_set(const Scene& s) {
  const scene::ScenePrimitives prim = scene::scene_primitives(s);
  CandidateSet c;
  for (const auto& [v, t] : prim.candidates.vertex_face)
    c.vertex_face.push_back({v, s.triangles[t][0], s.triangles[t][1], s.triangles[t][2]});
  for (const auto& [i, j] : prim.candidates.edge_edge)
    c.edge_edge.push_back({prim.edges[i][0], prim.edges[i][1], prim.edges[j][0], prim.edges[j][1]});
  return c;
}

SceneAnswers scene_answers(const Scene& s, const ControlState& expected) {
  SceneOptions two_threads;
  two_threads.threads = 2;  // workers inherit the caller's environment: they must reset it too
  SceneAnswers a;
  a.collisions = find_collisions(s, two_threads);
  EXPECT_TRUE(control_state() == expected) << "find_collisions";
  a.earliest = earliest_toi(s, two_threads);
  EXPECT_TRUE(control_state() == expected) << "earliest_toi";
  a.collision_free = is_collision_free(s, two_threads);
  EXPECT_TRUE(control_state() == expected) << "is_collision_free";
  a.step = max_collision_free_step(s, two_threads);
  EXPECT_TRUE(control_state() == expected) << "max_collision_free_step";
  EXPECT_EQ(a.step, max_collision_free_step(earliest_toi(a.collisions)));
  EXPECT_TRUE(control_state() == expected) << "earliest_toi(collisions), max_collision_free_step(toi)";
  const CandidateSet c = scene_candidate_set(s);
  a.batch = find_collisions(s.positions_t0, s.positions_t1, c, two_threads);
  EXPECT_TRUE(control_state() == expected) << "find_collisions(candidates)";
  EXPECT_EQ(a.batch.size(), a.collisions.size());
  a.batch_earliest = earliest_toi(s.positions_t0, s.positions_t1, c, two_threads);
  EXPECT_TRUE(control_state() == expected) << "earliest_toi(candidates)";
  EXPECT_TRUE(a.batch_earliest.has_value() == a.earliest.has_value() && (!a.earliest || *a.batch_earliest == *a.earliest));
  a.batch_free = is_collision_free(s.positions_t0, s.positions_t1, c, two_threads);
  EXPECT_TRUE(control_state() == expected) << "is_collision_free(candidates)";
  a.batch_step = max_collision_free_step(s.positions_t0, s.positions_t1, c, two_threads);
  EXPECT_TRUE(control_state() == expected) << "max_collision_free_step(candidates)";
  EXPECT_EQ(a.batch_step, a.step);
  a.free0 = intersection_free(s.positions_t0, s.triangles);
  a.free1 = intersection_free(s.positions_t1, s.triangles);
  EXPECT_TRUE(control_state() == expected) << "intersection_free";
  return a;
}

TEST_P(EveryEnvironment, ScenesGiveDefaultAnswersAndLeaveTheEnvironment) {
  const Environment env = GetParam();
  if (!supported(env)) GTEST_SKIP() << "cannot install " << env.name << " on this platform";
  for (const char* name : {"cloth", "strip", "fold", "pile"}) {
    const Scene s = load_scene(name);
    SceneAnswers reference;
    {
      const RestoreDefault restore;
      std::fesetenv(FE_DFL_ENV);
      reference = scene_answers(s, control_state());
    }
    EXPECT_FALSE(reference.collisions.empty()) << name << ": the bundled scenes all have contacts";
    const RestoreDefault restore;
    install(env);
    const SceneAnswers got = scene_answers(s, control_state());
    EXPECT_TRUE(got == reference) << env.name << ": scene " << name << " answers differ";
  }
}

/// The separation question's answers (CcdParams, every kind, both methods, the C API, scenes
/// with a minimum separation) on queries that reach every stage: grid queries of every kind
/// at d = 0, 1/4 and 2^-1074 with tmax 1 and 3/4, and the bundled vertex-face and edge-edge
/// simulation files at d = 2^-10 of each query's largest coordinate (the separating direction, the interval
/// stage with its long-double guess and integer signs); also checks that each call leaves the
/// environment it found.
std::vector<std::optional<TimeInterval>> separation_answers(const ControlState& expected) {
  std::vector<std::optional<TimeInterval>> out;
  const auto check_state = [&] {
    if (!(control_state() == expected)) ADD_FAILURE() << "a separation entry point left " << describe(control_state());
  };
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> c(-2, 2);
  int kind_index = 0;
  kinds::for_each_kind([&](auto k) {
    using Kind = decltype(k);
    using Q = typename Kind::template Query<double>;
    for (int i = 0; i < 18; ++i) {
      auto r = rows(Q{});
      for (auto& p : r) {
        p.x = 0.25 * c(rng);
        p.y = 0.25 * c(rng);
        if constexpr (Kind::dimension == 3) p.z = 0.25 * c(rng);
      }
      if (i % 3 == 0) r[Kind::points] = r[0];
      const Q q = from_rows<Q>(r);
      const CcdParams params{i % 3 == 0 ? 0.0 : i % 3 == 1 ? 0.25 : 0x1p-1074, i % 2 ? 1.0 : 0.75};
      for (Method m : {Method::filtered, Method::exact}) {
        out.push_back(toi(q, params, m));
        check_state();
      }
      std::vector<double> flat;
      for (const auto& p : rows(q)) {
        flat.push_back(p.x);
        flat.push_back(p.y);
        if constexpr (Kind::dimension == 3) flat.push_back(p.z);
      }
      int collides = -1;
      double lo = -1, hi = -1;
      EXPECT_EQ(exactccd_toi(kind_index, flat.data(), params.min_distance, params.tmax, &collides, &lo, &hi),
                EXACTCCD_OK);
      check_state();
      out.push_back(collides ? std::optional(TimeInterval{lo, hi}) : std::nullopt);
    }
    ++kind_index;
  });
  for (const char* file : {"sim-cloth-vertex-face.csv", "sim-fold-edge-edge.csv", "sim-strip-edge-edge.csv"}) {
    std::ifstream in(fs::path(EXACTCCD_SOURCE_DIR) / "data" / "sim" / file);
    const io::BenchmarkQueries queries = io::read_benchmark_csv(in, file);
    for (std::size_t i = 0; i < queries.size(); i += 12) {  // (sized for the sanitizer pass)
      const auto r = io::nearest_double_rows(queries.rows[i]);
      // d = 2^-10 of the largest coordinate magnitude: exact in any rounding mode (this code runs
      // in the environment under test; a rounded d would ask another question).
      double largest = 0;
      for (const Vec3& p : r) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      const CcdParams params{std::ldexp(largest, -10), 1.0};
      if (std::string(file).find("vertex-face") != std::string::npos)
        out.push_back(toi(from_rows<VertexFaceQuery>(r), params));
      else
        out.push_back(toi(from_rows<EdgeEdgeQuery>(r), params));
      check_state();
    }
  }
  return out;
}

TEST_P(EveryEnvironment, SeparationQueriesGiveDefaultAnswersAndLeaveTheEnvironment) {
  const Environment env = GetParam();
  if (!supported(env)) GTEST_SKIP() << "cannot install " << env.name << " on this platform";
  std::vector<std::optional<TimeInterval>> reference;
  SceneAnswers scene_reference;
  SceneOptions options;
  options.min_distance = 1e-3;
  options.tmax = 0.75;
  const Scene s = load_scene("fold");
  {
    const RestoreDefault restore;
    std::fesetenv(FE_DFL_ENV);
    reference = separation_answers(control_state());
    scene_reference.collisions = find_collisions(s, options);
  }
  EXPECT_GT(std::count_if(reference.begin(), reference.end(), [](const auto& t) { return t.has_value(); }), 40);
  const RestoreDefault restore;
  install(env);
  const ControlState installed = control_state();
  const auto got = separation_answers(installed);
  ASSERT_EQ(got.size(), reference.size());
  std::size_t differences = 0;
  for (std::size_t i = 0; i < got.size(); ++i)
    if (got[i].has_value() != reference[i].has_value() || (got[i] && !(*got[i] == *reference[i])))
      if (++differences <= 10)
        ADD_FAILURE() << env.name << ": separation answer " << i << ": " << describe(got[i]) << " instead of "
                      << describe(reference[i]);
  EXPECT_EQ(differences, 0u);
  const std::vector<Collision> scene_got = find_collisions(s, options);
  EXPECT_TRUE(control_state() == installed);
  ASSERT_EQ(scene_got.size(), scene_reference.collisions.size()) << env.name;
  for (std::size_t i = 0; i < scene_got.size(); ++i)
    EXPECT_TRUE(scene_got[i].toi == scene_reference.collisions[i].toi && scene_got[i].vertex == scene_reference.collisions[i].vertex)
        << env.name << ": scene collision " << i;
}

INSTANTIATE_TEST_SUITE_P(FpEnvironment, EveryEnvironment, ::testing::ValuesIn(kEnvironments),
                         [](const ::testing::TestParamInfo<Environment>& info) { return info.param.name; });

// ---- the guard itself and fault injection -------------------------------------------------

TEST(DefaultFpEnvironment, InstallsTheDefaultAndRestoresOnException) {
  const RestoreDefault restore;
  install(Environment{"downward_ftz", FE_DOWNWARD, true, false});
  const ControlState installed = control_state();
  EXPECT_FALSE(numeric::is_default_fp_environment());
  try {
    const numeric::DefaultFpEnvironment guard;
    EXPECT_TRUE(guard.changed());
    EXPECT_TRUE(numeric::is_default_fp_environment());
    EXPECT_EQ(std::fegetround(), FE_TONEAREST);
    volatile double tiny = 0x1p-1070;
    EXPECT_EQ(tiny * 0.5, 0x1p-1071) << "gradual underflow inside the guard";
    throw std::runtime_error("leaving the guard by an exception");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(control_state() == installed) << describe(control_state());
  std::fesetenv(FE_DFL_ENV);
  const numeric::DefaultFpEnvironment nested;
  EXPECT_FALSE(nested.changed()) << "a guard in the default environment changes nothing";
}

/// Calls f once per allocation it makes, making that allocation throw std::bad_alloc, until f
/// completes; after each throw the caller's control state must be unchanged. Returns the
/// number of throws and how many happened while the library had switched the rounding mode
/// (the caller's mode is downward: to nearest is the entry points' guard, upward CGAL's
/// Protect_FPU_rounding inside it).
struct Faults {
  long throws = 0, inside_guard = 0, inside_upward = 0;
};

template <class F>
Faults inject_allocation_failures(F&& f, const ControlState& expected) {
  Faults faults;
  for (long n = 0;; ++n) {
    rounding_at_failure = -1;
    allocations_until_failure = n;
    bool threw = false;
    try {
      f();
    } catch (const std::bad_alloc&) {
      threw = true;
    }
    allocations_until_failure = -1;
    if (!threw) break;
    ++faults.throws;
    faults.inside_guard += rounding_at_failure != FE_DOWNWARD;
    faults.inside_upward += rounding_at_failure == FE_UPWARD;
    EXPECT_TRUE(control_state() == expected) << "after the failure of allocation " << n << ": "
                                             << describe(control_state());
    if (n > 200000) {
      ADD_FAILURE() << "no end to the allocations";
      break;
    }
  }
  return faults;
}

TEST(DefaultFpEnvironment, RestoredWhenAnAllocationFailsAnywhere) {
  const RestoreDefault restore;
  install(Environment{"downward_ftz", FE_DOWNWARD, true, false});
  const ControlState installed = control_state();
  // Queries that reach the interval stage, the integer stage and the CGAL path.
  const VertexFaceQuery through_vertex{{0.0, 0.0, 1.0},  {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                       {0.0, 0.0, -2.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
  Faults all;
  const auto add = [&all](const Faults& f) {
    all.throws += f.throws;
    all.inside_guard += f.inside_guard;
    all.inside_upward += f.inside_upward;
  };
  for (Method m : {Method::filtered, Method::exact})
    add(inject_allocation_failures([&] { (void)vertex_face_toi(through_vertex, m); }, installed));
  Scene s;  // built outside the injection: only the library's allocations fail
  s.positions_t0 = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.25, 0.25, 1}};
  s.positions_t1 = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.25, 0.25, -1}};
  s.triangles = {{0, 1, 2}};
  s.points = {3};
  SceneOptions one_thread;
  one_thread.threads = 1;
  add(inject_allocation_failures([&] { (void)find_collisions(s, one_thread); }, installed));
  // No allocation happens inside CGAL's upward switches on these paths (the interval stage does
  // not allocate); every failure inside the library is inside the guard's switch to nearest.
  std::cout << "[ faults   ] " << all.throws << " allocation failures injected, " << all.inside_guard
            << " inside the entry points' environment switch, " << all.inside_upward
            << " inside an upward-rounding switch\n";
  EXPECT_GT(all.throws, 50);
  EXPECT_EQ(all.inside_guard, all.throws) << "a failure outside the guard: the test lost its point";
}

}  // namespace
}  // namespace exactccd
