// Degeneracy categories (tools/lib/degeneracy/degeneracy): each label on a catalogue case built to have it.
#include "degeneracy/degeneracy.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "generators/catalogue.hpp"

namespace exactccd {
namespace {

template <class Entries>
std::vector<std::string> labels_of(const Entries& entries, const std::string& name) {
  for (const auto& e : entries)
    if (e.name == name) return exact::degeneracy_categories(e.query);
  ADD_FAILURE() << "no catalogue case " << name;
  return {};
}

bool has(const std::vector<std::string>& labels, const std::string& l) {
  return std::find(labels.begin(), labels.end(), l) != labels.end();
}

TEST(DegeneracyCategories, VertexFace) {
  const auto vf = catalogue::vertex_face_base_cases();
  EXPECT_EQ(exact::join_categories(labels_of(vf, "vf_interior_fall")), "generic");
  EXPECT_TRUE(has(labels_of(vf, "vf_coplanar_slide_into"), "coplanar_for_all_t"));
  EXPECT_TRUE(has(labels_of(vf, "vf_contact_at_t0"), "root_at_t0"));
  EXPECT_TRUE(has(labels_of(vf, "vf_contact_at_t1"), "root_at_t1"));
  EXPECT_TRUE(has(labels_of(vf, "vf_grazing_inside"), "multiple_root"));
  EXPECT_FALSE(has(labels_of(vf, "vf_interior_fall"), "multiple_root"));
  EXPECT_TRUE(has(labels_of(vf, "vf_collinear_triangle_hit"), "degenerate_triangle"));
  EXPECT_TRUE(has(labels_of(vf, "vf_static_apart"), "static"));
}

TEST(DegeneracyCategories, EdgeEdge) {
  const auto ee = catalogue::edge_edge_base_cases();
  EXPECT_EQ(exact::join_categories(labels_of(ee, "ee_crossing")), "generic");
  EXPECT_TRUE(has(labels_of(ee, "ee_parallel_static_apart"), "parallel_edges"));
  EXPECT_TRUE(has(labels_of(ee, "ee_parallel_static_apart"), "coplanar_for_all_t"));
  EXPECT_TRUE(has(labels_of(ee, "ee_point_hits_edge"), "zero_length_edge"));
  EXPECT_TRUE(has(labels_of(ee, "ee_grazing_inside"), "multiple_root"));
  EXPECT_TRUE(has(labels_of(ee, "ee_contact_at_t0"), "root_at_t0"));
}

}  // namespace
}  // namespace exactccd
