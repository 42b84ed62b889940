// The degenerate rigid families (fuzz/rigid_families.hpp): every exact method gives the answer
// and the time of impact known by construction, in every exact placement (a common rigid change
// of frame, power-of-two scale and translation: docs/design.md 9.6), at every perturbation
// 2^-k towards and away from the degeneracy and at the degeneracy itself.
#include <gtest/gtest.h>

#include <random>

#include "exactccd/rigid.hpp"
#include "fuzz/rigid_families.hpp"

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

}  // namespace
}  // namespace exactccd
