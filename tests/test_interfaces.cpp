// The C API (exactccd.h) and the Eigen overloads (eigen.hpp) answer exactly as the core.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exactccd/eigen.hpp"
#include "exactccd/exactccd.h"
#include "test_support.hpp"

namespace exactccd {
namespace {

template <class Query>
std::array<double, 24> flat(const Query& q) {
  std::array<double, 24> f;
  const auto r = rows(q);
  for (int i = 0; i < 8; ++i) {
    f[3 * i] = r[i].x;
    f[3 * i + 1] = r[i].y;
    f[3 * i + 2] = r[i].z;
  }
  return f;
}

Eigen::Vector3d e(const Vec3& v) { return {v.x, v.y, v.z}; }

TEST(CApi, VertexFaceMatchesCore) {
  for (const auto& q : testing::degenerate_queries<VertexFaceQuery>(1, 400)) {
    const auto f = flat(q);
    int collides = -1;
    double lo = -1, hi = -1;
    ASSERT_EQ(exactccd_vertex_face_toi(f.data(), &collides, &lo, &hi), EXACTCCD_OK);
    const auto toi = vertex_face_toi(q);
    ASSERT_EQ(collides, toi.has_value() ? 1 : 0);
    if (toi) {
      EXPECT_EQ(lo, toi->lo);
      EXPECT_EQ(hi, toi->hi);
    }
    int c2 = -1;
    ASSERT_EQ(exactccd_vertex_face_ccd(f.data(), &c2), EXACTCCD_OK);
    EXPECT_EQ(c2, collides);
  }
}

TEST(CApi, EdgeEdgeMatchesCore) {
  for (const auto& q : testing::degenerate_queries<EdgeEdgeQuery>(2, 400)) {
    const auto f = flat(q);
    int collides = -1;
    double lo = -1, hi = -1;
    ASSERT_EQ(exactccd_edge_edge_toi(f.data(), &collides, &lo, &hi), EXACTCCD_OK);
    const auto toi = edge_edge_toi(q);
    ASSERT_EQ(collides, toi.has_value() ? 1 : 0);
    if (toi) {
      EXPECT_EQ(lo, toi->lo);
      EXPECT_EQ(hi, toi->hi);
    }
    int c2 = -1;
    ASSERT_EQ(exactccd_edge_edge_ccd(f.data(), &c2), EXACTCCD_OK);
    EXPECT_EQ(c2, collides);
  }
}

TEST(CApi, RejectsNonFiniteAndNullWithoutWriting) {
  std::array<double, 24> f{};
  int collides = 7;
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    for (int i : {0, 11, 23}) {
      f.fill(0.5);
      f[i] = bad;
      EXPECT_EQ(exactccd_vertex_face_ccd(f.data(), &collides), EXACTCCD_ERROR_NON_FINITE);
      EXPECT_EQ(exactccd_edge_edge_toi(f.data(), &collides, nullptr, nullptr), EXACTCCD_ERROR_NON_FINITE);
    }
  }
  EXPECT_EQ(collides, 7);
  EXPECT_EQ(exactccd_vertex_face_ccd(nullptr, &collides), EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_edge_edge_ccd(f.data(), nullptr), EXACTCCD_ERROR_NULL);
  EXPECT_STREQ(exactccd_status_string(EXACTCCD_ERROR_NON_FINITE), "non-finite coordinate (NaN or infinity)");
}

TEST(EigenOverloads, MatchCore) {
  for (const auto& q : testing::degenerate_queries<VertexFaceQuery>(3, 300)) {
    EXPECT_EQ(vertex_face_ccd(e(q.p_t0), e(q.a_t0), e(q.b_t0), e(q.c_t0), e(q.p_t1), e(q.a_t1),
                              e(q.b_t1), e(q.c_t1)),
              vertex_face_ccd(q));
    const auto a = vertex_face_toi(e(q.p_t0), e(q.a_t0), e(q.b_t0), e(q.c_t0), e(q.p_t1), e(q.a_t1),
                                   e(q.b_t1), e(q.c_t1));
    const auto b = vertex_face_toi(q);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      EXPECT_EQ(*a, *b);
    }
  }
  for (const auto& q : testing::degenerate_queries<EdgeEdgeQuery>(4, 300)) {
    EXPECT_EQ(edge_edge_ccd(e(q.a0_t0), e(q.a1_t0), e(q.b0_t0), e(q.b1_t0), e(q.a0_t1), e(q.a1_t1),
                            e(q.b0_t1), e(q.b1_t1)),
              edge_edge_ccd(q));
    const auto a = edge_edge_toi(e(q.a0_t0), e(q.a1_t0), e(q.b0_t0), e(q.b1_t0), e(q.a0_t1), e(q.a1_t1),
                                 e(q.b0_t1), e(q.b1_t1));
    const auto b = edge_edge_toi(q);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      EXPECT_EQ(*a, *b);
    }
  }
}

TEST(CppApi, RejectsNonFiniteForEveryMethod) {
  VertexFaceQuery vf{};
  vf.b_t1.y = std::numeric_limits<double>::quiet_NaN();
  EdgeEdgeQuery ee{};
  ee.a0_t0.x = std::numeric_limits<double>::infinity();
  for (Method m : {Method::filtered, Method::exact}) {  // the baselines: test_toi
    EXPECT_THROW(vertex_face_ccd(vf, m), std::invalid_argument);
    EXPECT_THROW(vertex_face_toi(vf, m), std::invalid_argument);
    EXPECT_THROW(edge_edge_ccd(ee, m), std::invalid_argument);
    EXPECT_THROW(edge_edge_toi(ee, m), std::invalid_argument);
  }
}

}  // namespace
}  // namespace exactccd
