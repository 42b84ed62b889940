// Every rigid entry point gives the same answers and TOIs whatever floating-point environment
// the calling thread is in (directed rounding, flush-to-zero and denormals-are-zero, unmasked
// exceptions), and leaves that environment as it found it, also when it throws (docs/design.md
// 8 and 9.4). The environments and the control-state check: tests/fp_environments.hpp.
#include <gtest/gtest.h>

#include <cfenv>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "exactccd/exactccd.h"
#include "exactccd/rigid.hpp"
#include "generators/rigid_families.hpp"
#include "io/rigid_csv.hpp"
#include "rigid/rigid_layout.hpp"
#include "tests/fp_environments.hpp"


namespace exactccd {
namespace {

namespace fs = std::filesystem;

using testing::control_state;
using testing::ControlState;
using testing::Environment;
using testing::install;
using testing::kEnvironments;
using testing::RestoreDefault;
using testing::supported;

/// A rigid query of either kind with its question.
struct Case {
  std::string name;
  std::variant<RigidVertexFaceQuery, RigidEdgeEdgeQuery> query;
  CcdParams params;
};

/// Every seventh query of the bundled rigid sets (at d = 0 and at d = 2^-9 with tmax 3/4), and the
/// degenerate families placed at subnormal and huge scales.
const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    std::vector<Case> out;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(EXACTCCD_SOURCE_DIR) / "data" / "rigid"))
      if (e.path().extension() == ".csv") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
      std::ifstream in(f);
      const io::RigidQueries q = io::read_rigid_csv(in, f.string());
      const bool vf = f.string().find("vertex-face") != std::string::npos;
      for (std::size_t i = 0; i < q.size(); i += 7)
        for (const CcdParams& p : {CcdParams{}, CcdParams{0x1p-9, 0.75}}) {
          Case c{f.filename().string() + "#" + std::to_string(i), RigidVertexFaceQuery{}, p};
          if (vf)
            c.query = rigid::from_numbers<RigidVertexFaceQuery>(q.numbers[i].data());
          else
            c.query = rigid::from_numbers<RigidEdgeEdgeQuery>(q.numbers[i].data());
          out.push_back(c);
        }
    }
    // The families with every length times 2^-1060 or 2^1000 (exact here: the families' numbers
    // have few bits), quaternions as they are.
    std::mt19937_64 rng(8);
    for (const rigid_families::Family& f : rigid_families::all_families())
      for (const int e : {-1060, 1000}) {
        rigid_families::Instance inst = rigid_families::make(f, 9, true, rng);
        const auto s = [&](double v) { return std::ldexp(v, e); };
        std::visit([&](auto& q) {
          for (RigidPose* p : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) p->c = {s(p->c.x), s(p->c.y), s(p->c.z)};
          rigid::set_points(q, [&](Vec3& v) { v = {s(v.x), s(v.y), s(v.z)}; });
        }, inst.query);
        out.push_back({f.name + " 2^" + std::to_string(e), inst.query, CcdParams{s(inst.min_distance), 1.0}});
      }
    return out;
  }();
  return all;
}

/// What an entry point returns for a case: the TOI (and the ccd answer's agreement).
using Answer = std::optional<TimeInterval>;

Answer cxx(const Case& c, Method m, bool with_counters) {
  StageCounters counters;
  return std::visit([&](const auto& q) {
    const Answer t = with_counters ? toi(q, c.params, m, counters) : toi(q, c.params, m);
    const bool collides = with_counters ? ccd(q, c.params, m, counters) : ccd(q, c.params, m);
    if (collides != t.has_value()) return Answer(TimeInterval{-1, -1});  // a mismatch shows as a wrong TOI
    return t;
  }, c.query);
}

Answer c_api(const Case& c) {
  const int kind = std::holds_alternative<RigidVertexFaceQuery>(c.query) ? EXACTCCD_VERTEX_FACE : EXACTCCD_EDGE_EDGE;
  const auto numbers = std::visit([](const auto& q) { return rigid::to_numbers(q); }, c.query);
  int collides = -1;
  double lo = -1, hi = -1;
  if (exactccd_rigid_toi(kind, numbers.data(), c.params.min_distance, c.params.tmax, &collides, &lo, &hi) != EXACTCCD_OK)
    return TimeInterval{-2, -2};
  int answer = -1;
  if (exactccd_rigid_ccd(kind, numbers.data(), c.params.min_distance, c.params.tmax, &answer) != EXACTCCD_OK ||
      answer != collides)
    return TimeInterval{-3, -3};
  return collides ? Answer(TimeInterval{lo, hi}) : std::nullopt;
}

bool same(const Answer& a, const Answer& b) {
  return a.has_value() == b.has_value() && (!a || (a->lo == b->lo && a->hi == b->hi));
}

class RigidEveryEnvironment : public ::testing::TestWithParam<Environment> {};

TEST_P(RigidEveryEnvironment, QueriesGiveDefaultAnswersAndLeaveTheEnvironment) {
  const Environment& e = GetParam();
  if (!supported(e)) GTEST_SKIP() << "this platform cannot set " << e.name;
  // The references, in the default environment, once (filtered equals exact: test_rigid_filtered;
  // the exact method is compared with them below on every eighth case).
  static const std::vector<Answer> reference = [] {
    std::vector<Answer> r;
    for (const Case& c : cases()) r.push_back(cxx(c, Method::filtered, false));
    return r;
  }();
  const RestoreDefault restore;
  int checked = 0;
  for (std::size_t i = 0; i < cases().size(); ++i) {
    const Case& c = cases()[i];
    install(e);
    const ControlState installed = control_state();
    const Answer answers[] = {cxx(c, Method::filtered, false), cxx(c, Method::filtered, true),
                              i % 8 == 0 ? cxx(c, Method::exact, i % 16 == 0) : reference[i], c_api(c)};
    const ControlState after = control_state();
    std::fesetenv(FE_DFL_ENV);
    EXPECT_TRUE(after == installed) << e.name << ": " << c.name << " changed the environment";
    for (const Answer& a : answers) EXPECT_TRUE(same(a, reference[i])) << e.name << ": " << c.name;
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

TEST_P(RigidEveryEnvironment, BadInputThrowsAndLeavesTheEnvironment) {
  const Environment& e = GetParam();
  if (!supported(e)) GTEST_SKIP();
  const RestoreDefault restore;
  RigidVertexFaceQuery q{{{0, 0, 0}, {1, 0, 0, 0}}, {{0, 0, 0}, {-2, 0, 0, 0}}, {{0, 0, 0}, {1, 0, 0, 0}},
                         {{0, 0, 0}, {1, 0, 0, 0}}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  install(e);
  const ControlState installed = control_state();
  bool threw = false;
  try {
    (void)rigid_vertex_face_toi(q, {});
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  const auto numbers = rigid::to_numbers(q);
  int collides = 0;
  const exactccd_status status = exactccd_rigid_ccd(EXACTCCD_VERTEX_FACE, numbers.data(), 0, 1, &collides);
  const ControlState after = control_state();
  std::fesetenv(FE_DFL_ENV);
  EXPECT_TRUE(threw);
  EXPECT_EQ(status, EXACTCCD_ERROR_ROTATION);
  EXPECT_TRUE(after == installed);
}

INSTANTIATE_TEST_SUITE_P(Environments, RigidEveryEnvironment, ::testing::ValuesIn(kEnvironments),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace exactccd
