// The degenerate families produce what they claim: the exact path finds contact in every
// unperturbed configuration and the constructed answer for every perturbation that stayed
// exact; the filtered method agrees with the exact path on all of them.
#include "fuzz/families.hpp"

#include <gtest/gtest.h>

#include "exactccd/exactccd.hpp"

namespace exactccd::families {
namespace {

bool exact_answer(const AnyQuery& q) {
  return std::visit([](const auto& x) {
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, VertexFaceQuery>)
      return vertex_face_ccd(x, Method::exact);
    else
      return edge_edge_ccd(x, Method::exact);
  }, q);
}

bool filtered_answer(const AnyQuery& q) {
  return std::visit([](const auto& x) {
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, VertexFaceQuery>)
      return vertex_face_ccd(x, Method::filtered);
    else
      return edge_edge_ccd(x, Method::filtered);
  }, q);
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
        EXPECT_EQ(std::holds_alternative<VertexFaceQuery>(inst.query), f->vertex_face);
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
