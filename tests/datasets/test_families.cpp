// The degenerate families produce what they claim: the exact path finds contact in every
// unperturbed configuration and the constructed answer and time of impact for every
// perturbation that stayed exact; the filtered method agrees with the exact path on all of
// them. (Their wide-exponent placements: test_wide_exponents.cpp.)
#include "generators/families.hpp"

#include <gtest/gtest.h>

#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"

namespace exactccd::families {
namespace {

// One call for either kind: the ccd()/toi() overloads on the query type.
bool exact_answer(const AnyQuery& q) {
  return std::visit([](const auto& x) { return ccd(x, Method::exact); }, q);
}

std::optional<TimeInterval> toi(const AnyQuery& q, Method m) {
  return std::visit([m](const auto& x) { return exactccd::toi(x, m); }, q);
}

bool filtered_answer(const AnyQuery& q) {
  return std::visit([](const auto& x) { return ccd(x, Method::filtered); }, q);
}

class FamilyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(FamilyTest, ProducesWhatItClaims) {
  const Family* f = find_family(GetParam());
  ASSERT_NE(f, nullptr);
  std::mt19937_64 rng(std::hash<std::string>{}(f->name));
  int checked = 0;
  for (int k = kUnperturbed; k <= 60; k += (k < 8 ? 1 : 4)) {
    for (bool toward : {false, true}) {
      for (int rep = 0; rep < 3; ++rep) {
        const Instance inst = f->make(k, toward, rng);
        EXPECT_EQ(kind_name(inst.query), f->kind);
        const bool exact = exact_answer(inst.query);
        // Offsets of 2^20..2^60 round a scene of scale 1 (the point of those families): only
        // their exactly placed instances carry a constructed answer.
        const bool rounds = f->name.find("large_offset") != std::string::npos;
        if (k == kUnperturbed && !rounds) {
          ASSERT_TRUE(inst.expected.has_value()) << "placement must keep the degeneracy exact";
        }
        if (k == kUnperturbed && inst.expected) {
          EXPECT_TRUE(exact) << f->name << " unperturbed must be in contact";
        }
        if (inst.expected) {
          EXPECT_EQ(exact, *inst.expected) << f->name << " k=" << k << " toward=" << toward;
          ASSERT_EQ(inst.toi.has_value(), *inst.expected) << "a constructed TOI exactly when it collides";
          for (Method m : {Method::exact, Method::filtered}) {
            const auto t = toi(inst.query, m);
            if (inst.toi && t) {
              EXPECT_TRUE(is_tightest_enclosure(*inst.toi, *t))
                  << f->name << " k=" << k << " toward=" << toward << ": [" << t->lo << ", " << t->hi
                  << "] does not enclose " << to_string(*inst.toi) << " tightly";
            }
          }
          ++checked;
        }
        EXPECT_EQ(filtered_answer(inst.query), exact) << f->name << " k=" << k << " toward=" << toward;
      }
    }
  }
  EXPECT_GT(checked, f->name.find("large_offset") != std::string::npos ? 5 : 40)
      << "too few instances with a constructed answer";
}

std::vector<std::string> family_names() {
  std::vector<std::string> names;
  for (const Family& f : all_families()) names.push_back(f.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Families, FamilyTest, ::testing::ValuesIn(family_names()),
                         [](const auto& info) { return info.param; });

TEST(Families, CoverEveryRequiredDegeneracy) {
  for (const char* name :
       {"vf_vertex_through_vertex", "vf_vertex_through_edge", "ee_edge_through_endpoint",
        "vf_coplanar_sliding", "ee_coplanar_sliding", "ee_parallel", "ee_collinear", "vf_grazing",
        "ee_grazing", "vf_contact_at_t0", "vf_contact_at_t1", "ee_contact_at_t0", "ee_contact_at_t1",
        "vf_degenerate_triangle", "ee_zero_length_edge", "vf_nearly_static", "ee_nearly_static",
        "vf_large_offset", "ee_large_offset"})
    EXPECT_NE(find_family(name), nullptr) << name;
}

// The TOI check itself: it accepts exactly the tightest enclosures.
TEST(Families, TightestEnclosureCheck) {
  const double third_lo = 1.0 / 3;  // round to nearest: below 1/3
  const double third_hi = std::nextafter(third_lo, 1.0);
  ASSERT_LT(mpq_class(third_lo), mpq_class(1, 3));
  ASSERT_GT(mpq_class(third_hi), mpq_class(1, 3));
  const KnownToi third = rational_toi(mpq_class(1, 3));
  EXPECT_TRUE(is_tightest_enclosure(third, {third_lo, third_hi}));
  EXPECT_FALSE(is_tightest_enclosure(third, {third_lo, third_lo}));
  EXPECT_FALSE(is_tightest_enclosure(third, {std::nextafter(third_lo, 0.0), third_hi}));
  const KnownToi half = rational_toi(mpq_class(1, 2));
  EXPECT_TRUE(is_tightest_enclosure(half, {0.5, 0.5}));
  EXPECT_FALSE(is_tightest_enclosure(half, {0.5, std::nextafter(0.5, 1.0)}));
  EXPECT_FALSE(is_tightest_enclosure(half, {std::nextafter(0.5, 0.0), 0.5}));
  // 1/2 - sqrt(1/8), the root of t^2 - t + 1/8 in [0, 1/2]: 0.14644660940672624 = 1/2 - 0.3535...
  const KnownToi irrational{{mpq_class(1, 8), mpq_class(-1), mpq_class(1)}, mpq_class(0), mpq_class(1, 2)};
  const double r = 0.5 - std::sqrt(0.125);  // within an ulp or two of the root
  int accepted = 0;
  for (double lo = std::nextafter(r, 0.0) - 2e-17; lo < r + 4e-17; lo = std::nextafter(lo, 1.0)) {
    accepted += is_tightest_enclosure(irrational, {lo, std::nextafter(lo, 1.0)});
    EXPECT_FALSE(is_tightest_enclosure(irrational, {lo, lo}));  // the root is not a double
  }
  EXPECT_EQ(accepted, 1);
}

// disagreement() (generate families' check against Method::exact) reports every contradiction.
TEST(Families, DisagreementNamesEveryContradiction) {
  const Family* f = find_family("vf_vertex_through_edge");
  ASSERT_NE(f, nullptr);
  const Instance hit = f->local(kUnperturbed, true);  // collides at t = 1/2
  ASSERT_EQ(hit.expected, std::optional<bool>(true));
  EXPECT_FALSE(disagreement(hit, true, TimeInterval{0.5, 0.5}));
  EXPECT_TRUE(disagreement(hit, false, std::nullopt));
  EXPECT_TRUE(disagreement(hit, true, std::nullopt));
  EXPECT_TRUE(disagreement(hit, true, TimeInterval{0.5, std::nextafter(0.5, 1.0)}));
  EXPECT_TRUE(disagreement(hit, true, TimeInterval{0.25, 0.25}));
  const Instance miss = f->local(10, false);
  ASSERT_EQ(miss.expected, std::optional<bool>(false));
  EXPECT_FALSE(disagreement(miss, false, std::nullopt));
  EXPECT_TRUE(disagreement(miss, true, TimeInterval{0.5, 0.5}));
  Instance unknown = miss;
  unknown.expected.reset();
  EXPECT_FALSE(disagreement(unknown, true, TimeInterval{0.5, 0.5})) << "nothing constructed, nothing to contradict";
}

TEST(Families, RandomInstancesAreDeterministicPerSeed) {
  std::mt19937_64 a(42), b(42);
  for (int i = 0; i < 50; ++i) {
    const Instance x = random_instance(a), y = random_instance(b);
    ASSERT_EQ(x.query.index(), y.query.index());
    const auto rx = std::visit([](const auto& q) { return rows(q); }, x.query);
    const auto ry = std::visit([](const auto& q) { return rows(q); }, y.query);
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(rx[k].x, ry[k].x);
      EXPECT_EQ(rx[k].y, ry[k].y);
      EXPECT_EQ(rx[k].z, ry[k].z);
    }
  }
}

}  // namespace
}  // namespace exactccd::families
