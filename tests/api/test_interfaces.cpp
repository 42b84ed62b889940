// The C API (exactccd.h) and the Eigen overloads (eigen.hpp) answer exactly as the core.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "api/checked_query.hpp"
#include "exactccd/eigen.hpp"
#include "exactccd/exactccd.h"
#include "exactccd/rational.hpp"
#include "kinds/primitive_kinds.hpp"
#include "tests/test_support.hpp"

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

/// A query of any kind as the C API's doubles: every point's coordinates in row order.
template <class Query>
std::vector<double> flat_any(const Query& q) {
  std::vector<double> f;
  for (const auto& p : rows(q)) {
    f.push_back(p.x);
    f.push_back(p.y);
    if constexpr (kinds::kind_of<Query>::dimension == 3) f.push_back(p.z);
  }
  return f;
}

/// Queries of any kind on a small grid (0.25 steps), a point kept still now and then.
template <class Query>
std::vector<Query> grid(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> c(-2, 2);
  std::vector<Query> out;
  for (int k = 0; k < n; ++k) {
    auto r = rows(Query{});
    for (auto& p : r) {
      p.x = 0.25 * c(rng);
      p.y = 0.25 * c(rng);
      if constexpr (kinds::kind_of<Query>::dimension == 3) p.z = 0.25 * c(rng);
    }
    if (k % 3 == 0) r[kinds::kind_of<Query>::points] = r[0];
    out.push_back(from_rows<Query>(r));
  }
  return out;
}

// The question says what it is (CcdParams::contact_only, whole_step): the contact question is
// d = 0 exactly (-0 too; the least positive double is a minimum-separation question), the
// whole step is tmax = 1 exactly (the double below 1 is a part of it).
TEST(CcdParams, SaysWhichQuestionItIs) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double below_one = std::nextafter(1.0, 0.0);
  EXPECT_TRUE((CcdParams{0.0, 1.0}.contact_only()));
  EXPECT_TRUE((CcdParams{-0.0, 1.0}.contact_only()));
  EXPECT_FALSE((CcdParams{tiny, 1.0}.contact_only()));
  EXPECT_FALSE((CcdParams{1e300, 1.0}.contact_only()));
  EXPECT_TRUE((CcdParams{0.0, 1.0}.whole_step()));
  EXPECT_FALSE((CcdParams{0.0, below_one}.whole_step()));
  EXPECT_FALSE((CcdParams{0.0, tiny}.whole_step()));
  EXPECT_TRUE(CcdParams{}.contact_over_whole_step());
  EXPECT_FALSE((CcdParams{tiny, 1.0}.contact_over_whole_step()));
  EXPECT_FALSE((CcdParams{0.0, below_one}.contact_over_whole_step()));
  static_assert(CcdParams{}.contact_over_whole_step(), "the default question is contact over the whole step");
  // The rational question the same way, at values no double reaches.
  EXPECT_TRUE(RationalCcdParams{}.contact_over_whole_step());
  EXPECT_FALSE((RationalCcdParams{mpq_class(1, 3), 1}.contact_only()));
  EXPECT_FALSE((RationalCcdParams{0, mpq_class(2, 3)}.whole_step()));
  EXPECT_TRUE((RationalCcdParams{0, mpq_class(2, 3) + mpq_class(1, 3)}.whole_step()));
}

TEST(CApi, QuerySizes) {
  // 2 * points * coordinates: vf 2*4*3, ee 2*4*3, pe 2*3*3, pp 2*2*3, ee2 2*4*2, pe2 2*3*2, pp2 2*2*2.
  EXPECT_EQ(exactccd_query_size(EXACTCCD_VERTEX_FACE), 24);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_EDGE_EDGE), 24);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_POINT_EDGE), 18);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_POINT_POINT), 12);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_EDGE_EDGE_2D), 16);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_POINT_EDGE_2D), 12);
  EXPECT_EQ(exactccd_query_size(EXACTCCD_POINT_POINT_2D), 8);
  EXPECT_EQ(exactccd_query_size(7), 0);
  EXPECT_EQ(exactccd_query_size(-1), 0);
}

TEST(CApi, EveryKindWithSeparationMatchesCore) {
  int checked = 0;
  int i = 0;
  kinds::for_each_kind([&](auto k) {
    using Query = typename decltype(k)::template Query<double>;
    for (const Query& q : grid<Query>(40 + i, 60)) {
      const CcdParams p{checked % 2 ? 0.25 : 0.0, checked % 3 ? 1.0 : 0.5};
      const std::vector<double> f = flat_any(q);
      ASSERT_EQ(static_cast<int>(f.size()), exactccd_query_size(i));
      int collides = -1, c2 = -1;
      double lo = -1, hi = -1;
      ASSERT_EQ(exactccd_toi(i, f.data(), p.min_distance, p.tmax, &collides, &lo, &hi),
                EXACTCCD_OK);
      ASSERT_EQ(exactccd_ccd(i, f.data(), p.min_distance, p.tmax, &c2), EXACTCCD_OK);
      const auto t = toi(q, p);
      EXPECT_EQ(collides, t ? 1 : 0);
      EXPECT_EQ(c2, collides);
      if (t) {
        EXPECT_EQ(lo, t->lo);
        EXPECT_EQ(hi, t->hi);
      }
      ++checked;
    }
    ++i;
  });
  EXPECT_EQ(checked, kinds::kind_count() * 60);
}

// The batch entry points (answer_batch, exactccd_toi_batch: the stage lists on blocks of
// queries) answer and count every query of every kind as the one-query entry point does, at d = 0
// and d > 0, tmax 1 and 0.5, in batches that are not a whole number of blocks.
TEST(Batch, EveryKindAnswersAndCountsAsOneQueryAtATime) {
  int i = 0;
  kinds::for_each_kind([&](auto k) {
    using Query = typename decltype(k)::template Query<double>;
    const std::vector<Query> queries = grid<Query>(70 + i, 75);
    std::vector<double> flat;
    for (const Query& q : queries) {
      const std::vector<double> f = flat_any(q);
      flat.insert(flat.end(), f.begin(), f.end());
    }
    for (const CcdParams p : {CcdParams{0.0, 1.0}, CcdParams{0.0, 0.5}, CcdParams{0.25, 1.0}, CcdParams{0.25, 0.5}}) {
      for (const bool want_toi : {false, true}) {
        StageCounters one, batch;
        std::vector<std::optional<TimeInterval>> got(queries.size());
        answer_batch(queries.data(), queries.size(), p, Method::filtered, want_toi, got.data(), &batch);
        for (std::size_t j = 0; j < queries.size(); ++j)
          EXPECT_EQ(got[j], answer_query(queries[j], p, Method::filtered, want_toi, &one)) << "kind " << i << ", query " << j;
        EXPECT_EQ(batch.total(), one.total());
        EXPECT_EQ(batch.volume_exclusion, one.volume_exclusion);
        EXPECT_EQ(batch.interval, one.interval);
        EXPECT_EQ(batch.toi_refined, one.toi_refined);
      }
      std::vector<int> collides(queries.size(), -1);
      std::vector<double> lo(queries.size(), -1), hi(queries.size(), -1);
      ASSERT_EQ(exactccd_toi_batch(i, flat.data(), queries.size(), p.min_distance, p.tmax, collides.data(), lo.data(),
                                   hi.data()),
                EXACTCCD_OK);
      for (std::size_t j = 0; j < queries.size(); ++j) {
        const auto t = toi(queries[j], p);
        EXPECT_EQ(collides[j], t ? 1 : 0) << "kind " << i << ", query " << j;
        if (t) {
          EXPECT_EQ(lo[j], t->lo);
          EXPECT_EQ(hi[j], t->hi);
        }
      }
    }
    ++i;
  });
}

// A bad query anywhere in a batch is an error before anything is answered: the C++ entry point
// names its index, the C one writes nothing.
TEST(Batch, ABadQueryIsAnErrorBeforeAnyAnswer) {
  std::vector<VertexFaceQuery> queries = grid<VertexFaceQuery>(5, 20);
  queries[17].c_t1.y = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::optional<TimeInterval>> got(queries.size(), TimeInterval{-1, -1});
  try {
    answer_batch(queries.data(), queries.size(), CcdParams{}, Method::filtered, true, got.data());
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("query 17 of the batch"), std::string::npos) << e.what();
  }
  for (const auto& g : got) EXPECT_EQ(g, (TimeInterval{-1, -1}));
  std::vector<double> doubles;
  for (const auto& q : queries) {
    const auto f = flat(q);
    doubles.insert(doubles.end(), f.begin(), f.end());
  }
  std::vector<int> collides(queries.size(), -1);
  EXPECT_EQ(exactccd_toi_batch(EXACTCCD_VERTEX_FACE, doubles.data(), queries.size(), 0, 1, collides.data(), nullptr,
                               nullptr),
            EXACTCCD_ERROR_NON_FINITE);
  for (const int c : collides) EXPECT_EQ(c, -1);
  double lo = 0;
  EXPECT_EQ(exactccd_toi_batch(EXACTCCD_VERTEX_FACE, doubles.data(), 1, 0, 1, collides.data(), &lo, nullptr),
            EXACTCCD_ERROR_NULL);
  EXPECT_EQ(exactccd_toi_batch(EXACTCCD_VERTEX_FACE, nullptr, 0, 0, 1, nullptr, nullptr, nullptr), EXACTCCD_OK);
  EXPECT_EQ(exactccd_toi_batch(7, doubles.data(), 1, 0, 1, collides.data(), nullptr, nullptr), EXACTCCD_ERROR_PARAMETER);
}

// The scene and candidate narrow phases' entry (api/checked_query.hpp: no per-query validation
// or environment guard) answers as the public entry point, for every kind of the one list (a
// kind missing from its instantiations in api/entry_point.cpp fails to link here), under the
// default environment as its callers guarantee.
TEST(CheckedQuery, EveryKindAnswersAsThePublicEntryPoint) {
  int checked = 0, i = 0;
  kinds::for_each_kind([&](auto k) {
    using Query = typename decltype(k)::template Query<double>;
    for (const Query& q : grid<Query>(70 + i, 60)) {
      const CcdParams p{checked % 2 ? 0.25 : 0.0, checked % 3 ? 1.0 : 0.5};
      for (const bool want_toi : {false, true}) {
        const auto expected = want_toi ? toi(q, p) : (ccd(q, p) ? std::optional(TimeInterval{}) : std::nullopt);
        const auto got = answer_checked_query(q, p, want_toi);
        ASSERT_EQ(got.has_value(), expected.has_value()) << "kind " << i << " query " << checked;
        if (want_toi && got) {
          EXPECT_EQ(got->lo, expected->lo);
          EXPECT_EQ(got->hi, expected->hi);
        }
      }
      ++checked;
    }
    ++i;
  });
  EXPECT_EQ(checked, kinds::kind_count() * 60);
}

TEST(CApi, BadParametersAreRefused) {
  const double q[8] = {0, 0, 1, 0, 0, 0, 1, 0};
  int collides = -7;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, -1, 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, -std::ldexp(1.0, -1074), 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, nan, 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, 0, 0, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, 0, 1.5, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(9, q, 0, 1, &collides), EXACTCCD_ERROR_PARAMETER);
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, nullptr, 0, 1, &collides), EXACTCCD_ERROR_NULL);
  const double bad[8] = {0, 0, 1, 0, 0, nan, 1, 0};
  EXPECT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, bad, 0, 1, &collides), EXACTCCD_ERROR_NON_FINITE);
  EXPECT_EQ(collides, -7);  // nothing written on an error
  // The two points stay 1 apart: they collide exactly from d = 1 on.
  ASSERT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, std::nextafter(1.0, 0.0), 1, &collides), EXACTCCD_OK);
  EXPECT_EQ(collides, 0);
  ASSERT_EQ(exactccd_ccd(EXACTCCD_POINT_POINT_2D, q, 1.0, 1, &collides), EXACTCCD_OK);
  EXPECT_EQ(collides, 1);
}

TEST(EigenOverloads, EveryKindWithSeparationMatchesCore) {
  const CcdParams p{0.25, 0.75};
  for (const auto& q : grid<PointEdgeQuery>(50, 40))
    EXPECT_EQ(point_edge_toi(e(q.p_t0), e(q.a_t0), e(q.b_t0), e(q.p_t1), e(q.a_t1), e(q.b_t1), p), toi(q, p));
  for (const auto& q : grid<PointPointQuery>(51, 40))
    EXPECT_EQ(point_point_toi(e(q.p_t0), e(q.q_t0), e(q.p_t1), e(q.q_t1), p), toi(q, p));
  for (const auto& q : grid<VertexFaceQuery>(52, 40))
    EXPECT_EQ(vertex_face_toi(e(q.p_t0), e(q.a_t0), e(q.b_t0), e(q.c_t0), e(q.p_t1), e(q.a_t1), e(q.b_t1),
                              e(q.c_t1), p),
              toi(q, p));
  for (const auto& q : grid<EdgeEdgeQuery>(53, 40))
    EXPECT_EQ(edge_edge_toi(e(q.a0_t0), e(q.a1_t0), e(q.b0_t0), e(q.b1_t0), e(q.a0_t1), e(q.a1_t1), e(q.b0_t1),
                            e(q.b1_t1), p),
              toi(q, p));
  const auto e2 = [](const Vec2& v) { return Eigen::Vector2d(v.x, v.y); };
  for (const auto& q : grid<PointPoint2dQuery>(54, 40))
    EXPECT_EQ(point_point_2d_toi(e2(q.p_t0), e2(q.q_t0), e2(q.p_t1), e2(q.q_t1), p), toi(q, p));
  for (const auto& q : grid<PointEdge2dQuery>(55, 40))
    EXPECT_EQ(point_edge_2d_toi(e2(q.p_t0), e2(q.a_t0), e2(q.b_t0), e2(q.p_t1), e2(q.a_t1), e2(q.b_t1), p),
              toi(q, p));
  for (const auto& q : grid<EdgeEdge2dQuery>(56, 40))
    EXPECT_EQ(edge_edge_2d_toi(e2(q.a0_t0), e2(q.a1_t0), e2(q.b0_t0), e2(q.b1_t0), e2(q.a0_t1), e2(q.a1_t1),
                               e2(q.b0_t1), e2(q.b1_t1), p),
              toi(q, p));
}

}  // namespace
}  // namespace exactccd
