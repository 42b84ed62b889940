// The degenerate rigid families (tools/lib/generators/rigid_families.hpp): every exact method gives the answer
// and the time of impact known by construction, in every exact placement (a common rigid change
// of frame, power-of-two scale and translation: docs/design.md 9.6), at every perturbation
// 2^-k towards and away from the degeneracy and at the degeneracy itself.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <variant>

#include "exactccd/rigid.hpp"
#include "generators/rigid_families.hpp"
#include "rigid/rigid_layout.hpp"

namespace exactccd {
namespace {

TEST(RigidFamilies, EveryMethodGivesTheConstructedAnswerAndToi) {
  std::mt19937_64 rng(24);
  int checked = 0, collisions = 0;
  for (const rigid_families::Family& family : rigid_families::all_families())
    for (const int k : {-1, 4, 9, 16, 27, 40, 52})
      for (const bool toward : {true, false}) {
        if (k < 0 && !toward) continue;  // unperturbed: one instance
        for (int placement = 0; placement < 3; ++placement) {
          const rigid_families::Instance inst = rigid_families::make(family, k, toward, rng);
          ASSERT_TRUE(inst.expected.has_value()) << family.name;
          for (const Method m : {Method::filtered, Method::exact}) {
            const CcdParams p{inst.min_distance, 1.0};
            const auto t = std::visit([&](const auto& q) { return toi(q, p, m); }, inst.query);
            const std::string what = family.name + " k=" + std::to_string(k) + (toward ? " toward" : " away") +
                                     " placement " + std::to_string(placement) + " method " + std::to_string(int(m));
            ASSERT_EQ(t.has_value(), *inst.expected) << what;
            if (t && inst.toi) {
              EXPECT_TRUE(families::is_tightest_enclosure(*inst.toi, *t))
                  << what << ": [" << t->lo << ", " << t->hi << "] against " << families::to_string(*inst.toi);
            }
            EXPECT_EQ(std::visit([&](const auto& q) { return ccd(q, p, m); }, inst.query), *inst.expected) << what;
            ++checked;
            collisions += t.has_value();
          }
        }
      }
  EXPECT_GT(checked, 300);
  EXPECT_GT(collisions, checked / 3);
}

TEST(RigidFamilies, MotionInOnePlaneIsAnsweredWithoutTheExactPath) {
  // The edge-edge family "motion in one plane" (the volume vanishes for all t): the filtered
  // method's answer and its TOI (asked separately) come from the plane's candidates
  // (rigid/coplanar_walk.hpp), not from the exact path, and are the constructed ones (the TOI
  // narrowed by exact signs at doubles: double-double, GMP at an exact root such as 1/2).
  // Before coplanar_walk every instance went exact.
  std::mt19937_64 rng(2024);
  int checked = 0;
  for (const rigid_families::Family& family : rigid_families::all_families()) {
    if (family.name != "rigid_ee_planar_motion") continue;
    for (const int k : {-1, 0, 4, 9, 16, 27, 40, 52})
      for (const bool toward : {true, false}) {
        if (k < 0 && !toward) continue;
        for (int placement = 0; placement < 3; ++placement) {
          const rigid_families::Instance inst = rigid_families::make(family, k, toward, rng);
          const auto& q = std::get<RigidEdgeEdgeQuery>(inst.query);
          const std::string what = "k=" + std::to_string(k) + (toward ? " toward" : " away") + " placement " +
                                   std::to_string(placement);
          StageCounters counters;
          EXPECT_EQ(rigid_edge_edge_ccd(q, CcdParams{}, Method::filtered, counters), *inst.expected) << what;
          EXPECT_EQ(counters.exact, 0u) << what;
          EXPECT_EQ(counters.interval, 1u) << what;
          StageCounters toi_counters;
          const auto t = rigid_edge_edge_toi(q, CcdParams{}, Method::filtered, toi_counters);
          ASSERT_TRUE(t.has_value()) << what;
          EXPECT_TRUE(families::is_tightest_enclosure(*inst.toi, *t)) << what;
          EXPECT_EQ(toi_counters.exact, 0u) << what;
          ++checked;
        }
      }
  }
  EXPECT_EQ(checked, 45);
}

}  // namespace
}  // namespace exactccd

#include <pthread.h>

#include <functional>

namespace exactccd {
namespace {

/// Runs `work` on a new thread whose whole stack is 256 KB (a stack overflow kills the process).
void run_on_small_stack(const std::function<void()>& work) {
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, std::size_t{256} << 10), 0);
  pthread_t thread;
  auto body = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attr, body, const_cast<std::function<void()>*>(&work)), 0);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  pthread_attr_destroy(&attr);
}

TEST(RigidFamilies, WideInstancesOnASmallStack) {
  // The families with every length times 2^-1060 (coordinates near the subnormal range) and body
  // B's quaternions times 2^1000: coefficients of thousands of bits, CGAL's recursion bounded by
  // descartes_depth_bound(bits, degree) (docs/design.md 9.3) and run on a helper thread when it
  // does not fit; on a 256 KB thread, both methods still give the constructed answers.
  std::mt19937_64 rng(9);
  int checked = 0;
  run_on_small_stack([&] {
    for (const rigid_families::Family& family : rigid_families::all_families()) {
      rigid_families::Instance inst = rigid_families::make(family, 12, true, rng);
      bool exact = true;  // every scaled number exactly representable (else another question)
      const auto x2 = [&](double v, int k) {
        const double r = std::ldexp(v, k);
        exact = exact && std::ldexp(r, -k) == v;
        return r;
      };
      std::visit([&](auto& q) {
        const auto s = [&](double v) { return x2(v, -1060); };
        for (RigidPose* p : {&q.a_t0, &q.a_t1, &q.b_t0, &q.b_t1}) p->c = {s(p->c.x), s(p->c.y), s(p->c.z)};
        rigid::set_points(q, [&](Vec3& v) { v = {s(v.x), s(v.y), s(v.z)}; });
        for (RigidPose* p : {&q.b_t0, &q.b_t1})
          p->q = {x2(p->q.w, 1000), x2(p->q.x, 1000), x2(p->q.y, 1000), x2(p->q.z, 1000)};
      }, inst.query);
      const double d = x2(inst.min_distance, -1060);
      if (!exact) continue;
      const CcdParams p{d, 1.0};
      for (const Method m : {Method::filtered, Method::exact}) {
        const auto t = std::visit([&](const auto& q) { return toi(q, p, m); }, inst.query);
        EXPECT_EQ(t.has_value(), *inst.expected) << family.name << " method " << int(m);
        if (t && inst.toi) {
          EXPECT_TRUE(families::is_tightest_enclosure(*inst.toi, *t)) << family.name;
        }
        ++checked;
      }
    }
  });
  EXPECT_GE(checked, int(rigid_families::all_families().size()));  // at least half of them exact
}

}  // namespace
}  // namespace exactccd
