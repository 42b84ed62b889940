// Minimum separation and the time limit (CcdParams): the exact path's term decomposition
// (contact/separation_terms.hpp) against the independent contact path at d = 0, and the
// filtered method against the exact one for every kind and random d. The hand-derived cases
// are in test_min_separation_catalogue.cpp, the distance checks with CGAL's constructions in
// test_min_separation_properties.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "exactccd/exactccd.hpp"
#include "exactccd/rational.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/exact_separation.hpp"
#include "tests/test_support.hpp"

namespace exactccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string show(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", t->lo, t->hi);
  return buf;
}

/// Every query of the shared sample and degenerate random ones: the separation terms at d = 0
/// give exactly the contact path's TOI (two derivations of the same answer: the terms square
/// the distances, the contact rule intersects in the plane).
template <class Query>
void expect_terms_match_contact_path(const std::vector<Query>& queries) {
  const RationalCcdParams touch;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto q = exact::to_rational(queries[i]);
    EXPECT_EQ(show(separation::exact_toi(q, touch)), show(exact::toi(q))) << "query " << i;
  }
}

TEST(MinSeparation, TermsAtZeroDistanceEqualTheContactPathOnDegenerateQueries) {
  expect_terms_match_contact_path(testing::degenerate_queries<VertexFaceQuery>(11, 400));
  expect_terms_match_contact_path(testing::degenerate_queries<EdgeEdgeQuery>(12, 400));
}

TEST(MinSeparation, TermsAtZeroDistanceEqualTheContactPathOnTheSharedSample) {
  int files = 0;
  for (const char* kind : {"vertex-face", "edge-edge"}) {
    for (const char* name : {"data_0_0.csv", "data_0_1.csv"}) {
      const auto sample = testing::load_sample(std::string("unit-tests/") + kind + "/" + name);
      if (!sample) continue;
      ++files;
      for (std::size_t i = 0; i < sample->size(); ++i) {
        const RationalCcdParams touch;
        if (std::string(kind) == "vertex-face") {
          const auto q = io::vertex_face_query(*sample, i);
          EXPECT_EQ(show(separation::exact_toi(q, touch)), show(exact::toi(q))) << kind << name << " " << i;
        } else {
          const auto q = io::edge_edge_query(*sample, i);
          EXPECT_EQ(show(separation::exact_toi(q, touch)), show(exact::toi(q))) << kind << name << " " << i;
        }
      }
    }
  }
  if (files == 0) GTEST_SKIP() << "shared sample queries absent (" << EXACTCCD_SAMPLE_QUERIES_DIR << ")";
}

/// Random points of a kind on a small grid with repeated points and planar motion mixed in.
template <class Query>
std::vector<Query> grid_queries(std::uint64_t seed, std::size_t n) {
  using Kind = kinds::kind_of<Query>;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> coord(-2, 2), choice(0, 5);
  std::vector<Query> out;
  for (std::size_t k = 0; k < n; ++k) {
    auto r = rows(Query{});
    for (auto& p : r) {
      p.x = coord(rng) * 0.25;
      p.y = coord(rng) * 0.25;
      if constexpr (Kind::dimension == 3) p.z = coord(rng) * 0.25;
    }
    const int c = choice(rng);
    if (c == 0) r[Kind::points] = r[0];                         // a point that does not move
    if (c == 1 && Kind::points > 2) r[2] = r[1];                // two points coincide at t0
    if (c == 2)
      for (int i = Kind::first_points; i < Kind::points; ++i) r[i + Kind::points] = r[i];  // B static
    out.push_back(from_rows<Query>(r));
  }
  return out;
}

template <class Query>
void expect_filtered_equals_exact(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::vector<double> fixed_d{0.0, 0.25, 0.5, std::ldexp(1.0, -1074), 1e300};
  std::size_t i = 0;
  for (const Query& q : grid_queries<Query>(seed, n)) {
    const double d = i % 3 == 0 ? fixed_d[i / 3 % fixed_d.size()] : unit(rng) * 0.75;
    const double tmax = i % 4 == 0 ? 1.0 : unit(rng) > 0.5 ? 0.5 : std::nextafter(unit(rng), 2.0);
    const CcdParams p{d, tmax};
    const auto f = toi(q, p, Method::filtered), e = toi(q, p, Method::exact);
    EXPECT_EQ(show(f), show(e)) << kinds::kind_of<Query>::name << " query " << i << " d " << d << " tmax " << tmax;
    EXPECT_EQ(ccd(q, p, Method::filtered), e.has_value()) << kinds::kind_of<Query>::name << " query " << i;
    ++i;
  }
}

TEST(MinSeparation, FilteredEqualsExactForEveryKind) {
  expect_filtered_equals_exact<VertexFaceQuery>(21, 120);
  expect_filtered_equals_exact<EdgeEdgeQuery>(22, 120);
  expect_filtered_equals_exact<PointEdgeQuery>(23, 250);
  expect_filtered_equals_exact<PointPointQuery>(24, 300);
  expect_filtered_equals_exact<EdgeEdge2dQuery>(25, 150);
  expect_filtered_equals_exact<PointEdge2dQuery>(26, 250);
  expect_filtered_equals_exact<PointPoint2dQuery>(27, 300);
}

/// Queries in one plane of 3D space (every point at y = 0.375, as the bundled fold set; and in
/// the plane x = z) whose triangle or edges turn through degenerate or parallel positions in
/// [0, 1]: the interval stage walks them again without the point-triangle and edge-edge terms
/// (separation_walk.cpp, step 5: planar_walk). Filtered against exact, answers and TOIs.
template <class Query>
void expect_filtered_equals_exact_in_a_plane(std::uint64_t seed, int n, StageCounters& stages) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < n; ++i) {
    std::array<Vec3, 8> r{};
    for (Vec3& p : r) {
      const double u = unit(rng) * 0.5, v = unit(rng) * 0.5;
      p = i % 2 == 0 ? Vec3{u, 0.375, v} : Vec3{u, v, u};
    }
    const double d = std::ldexp(std::abs(unit(rng)), -2 - i % 8);
    const CcdParams p{d, i % 3 == 0 ? 0.625 : 1.0};
    const Query q = from_rows<Query>(r);
    const auto exact = toi(q, p, Method::exact);
    EXPECT_EQ(show(toi(q, p, Method::filtered, stages)), show(exact))
        << kinds::kind_of<Query>::name << " query " << i << " d " << d;
    EXPECT_EQ(ccd(q, p, Method::filtered), exact.has_value()) << kinds::kind_of<Query>::name << " query " << i << " d " << d;
  }
}

TEST(MinSeparation, FilteredEqualsExactInAPlane) {
  StageCounters stages;
  expect_filtered_equals_exact_in_a_plane<VertexFaceQuery>(41, 300, stages);
  expect_filtered_equals_exact_in_a_plane<EdgeEdgeQuery>(42, 300, stages);
  // Decided without the exact path (when written: 102 separated, 343 interval, 155 integer
  // (the exact plane test of step 5), 0 exact).
  EXPECT_GT(stages.interval + stages.integer, 100u);
  EXPECT_LE(stages.exact, 3u);
  std::printf("in a plane: %llu separated, %llu interval, %llu integer, %llu exact\n",
              static_cast<unsigned long long>(stages.separating_direction),
              static_cast<unsigned long long>(stages.interval), static_cast<unsigned long long>(stages.integer),
              static_cast<unsigned long long>(stages.exact));
}

/// Queries in the tilted plane x + y + z = 0 (dyadic coordinates: every point exactly in it),
/// touching at t = 0 (the point inside the triangle, or the edges crossing), at tiny d: the
/// interval stage cannot decide t = 0 there (h's enclosure is wider than d |n|), and must not
/// walk on without the point-triangle and edge-edge terms (step 5 needs t = 0 ruled out). A
/// review found filtered "none" against exact [0, 0] on the first query below.
TEST(MinSeparation, FilteredEqualsExactInATiltedPlaneTouchingAtZero) {
  const CcdParams tiny{1e-16, 1.0};
  const VertexFaceQuery found = from_rows<VertexFaceQuery>(std::array<Vec3, 8>{
      Vec3{0.5, 0.5, -1.0}, Vec3{0.1, 0.1, -0.2}, Vec3{0.9, 0.4, -1.3}, Vec3{0.4, 0.9, -1.3},
      Vec3{0.5, 0.5, -1.0}, Vec3{0.1, 0.1, -0.2}, Vec3{0.9, 0.4, -1.3}, Vec3{0.4, 0.9, -1.3}});
  EXPECT_EQ(show(toi(found, tiny, Method::filtered)), show(toi(found, tiny, Method::exact)));
  EXPECT_EQ(show(toi(found, tiny, Method::exact)), "[0, 0]");
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> grid(-1024, 1024);
  const auto in_plane = [&] {
    const double x = grid(rng) / 1024.0, y = grid(rng) / 1024.0;
    return Vec3{x, y, -(x + y)};
  };
  const auto plus = [](const Vec3& u, const Vec3& v, double s) { return Vec3{u.x + s * v.x, u.y + s * v.y, u.z + s * v.z}; };
  const std::vector<double> distances{1e-16, 1e-30, std::ldexp(1.0, -1074), 0x1p-20};
  int compared = 0;
  for (int i = 0; i < 120; ++i) {
    const Vec3 a = in_plane(), b = in_plane(), c = in_plane();
    const Vec3 ab{b.x - a.x, b.y - a.y, b.z - a.z}, ac{c.x - a.x, c.y - a.y, c.z - a.z};
    const Vec3 inside = plus(plus(a, ab, 0.25), ac, 0.25);  // exact: dyadic with few bits
    const bool moving = i % 2 == 1;
    const Vec3 shift = moving ? in_plane() : Vec3{};
    const auto moved = [&](const Vec3& v) { return plus(v, shift, 1.0); };
    const CcdParams p{distances[i % distances.size()], i % 3 == 0 ? 0.5 : 1.0};
    const VertexFaceQuery vf = from_rows<VertexFaceQuery>(
        std::array<Vec3, 8>{inside, a, b, c, moved(inside), a, b, c});
    // Edges crossing at t0: a-b against the segment from c through the point inside.
    const Vec3 far = plus(c, Vec3{inside.x - c.x, inside.y - c.y, inside.z - c.z}, 4.0);
    const EdgeEdgeQuery ee = from_rows<EdgeEdgeQuery>(std::array<Vec3, 8>{a, b, c, far, a, b, moved(c), moved(far)});
    for (const auto& [name, f, e] : {std::tuple{"vf", toi(vf, p, Method::filtered), toi(vf, p, Method::exact)},
                                     std::tuple{"ee", toi(ee, p, Method::filtered), toi(ee, p, Method::exact)}}) {
      EXPECT_EQ(show(f), show(e)) << name << " query " << i << " d " << p.min_distance;
      ++compared;
    }
    EXPECT_EQ(ccd(vf, p, Method::filtered), toi(vf, p, Method::exact).has_value()) << "vf query " << i;
    EXPECT_EQ(ccd(ee, p, Method::filtered), toi(ee, p, Method::exact).has_value()) << "ee query " << i;
  }
  EXPECT_EQ(compared, 240);
}

/// The largest extent of a query's bounding box (all its rows).
template <class Query>
double box_size(const Query& q) {
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  for (const Vec3& p : rows(q)) {
    const double c[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

/// The bundled simulation sets at d = 1e-4 and 1e-2 of each query's box (every 8th query):
/// the stages of the filtered method (separating direction, interval stage) against the exact
/// path, and the interval stage must decide some of them (else this test would not test it).
/// The answers alone (ccd: the contact filter first, the walk stopping at a certain collision)
/// are checked too, with their own stage counts (answer_stages: one stage per call).
template <class Query>
void expect_filtered_equals_exact_on(const std::string& file, StageCounters& stages, StageCounters& answer_stages,
                                     std::uint64_t& answers) {
  std::ifstream in(std::string(EXACTCCD_SOURCE_DIR) + "/data/sim/" + file);
  ASSERT_TRUE(in) << file;
  const io::BenchmarkQueries queries = io::read_benchmark_csv(in, file);
  for (std::size_t i = 0; i < queries.size(); i += 8) {
    const Query q = from_rows<Query>(io::nearest_double_rows(queries.rows[i]));
    for (const double relative : {1e-4, 1e-2}) {
      const CcdParams p{relative * box_size(q), i % 16 == 0 ? 1.0 : 0.75};
      const auto exact = toi(q, p, Method::exact);
      EXPECT_EQ(show(toi(q, p, Method::filtered, stages)), show(exact)) << file << " " << i;
      EXPECT_EQ(ccd(q, p, Method::filtered, answer_stages), exact.has_value()) << file << " " << i;
      ++answers;
    }
  }
}

TEST(MinSeparation, FilteredEqualsExactOnSimulationSets) {
  StageCounters stages, answer_stages;
  std::uint64_t answers = 0;
  for (const char* scene : {"cloth", "fold", "pile", "strip"}) {
    expect_filtered_equals_exact_on<VertexFaceQuery>(std::string("sim-") + scene + "-vertex-face.csv", stages,
                                                     answer_stages, answers);
    expect_filtered_equals_exact_on<EdgeEdgeQuery>(std::string("sim-") + scene + "-edge-edge.csv", stages,
                                                   answer_stages, answers);
  }
  EXPECT_EQ(answer_stages.total(), answers);  // each answer counted once, at the stage deciding it
  EXPECT_LE(answer_stages.integer + answer_stages.exact, 2u);
  // 698 calls (349 queries at two distances); when this test was written: 619 separated, 49 by
  // the interval stage in intervals alone, 30 with integer signs in its narrowing, 0 exact.
  // Since the narrowing's signs are certified in double-double (separation/distance_sign.hpp):
  // 619 separated, 79 interval, 0 integer, 0 exact. The thresholds require that the interval
  // stage decides all but a few of the queries it sees without GMP (the integer signs remain
  // for exact zeros of f at a double: the catalogue's tests take that path).
  EXPECT_GT(stages.interval, 60u) << stages.exact << " exact, " << stages.separating_direction << " separated";
  EXPECT_LE(stages.integer + stages.exact, 2u);
  EXPECT_GT(stages.separating_direction, 300u);
  std::printf("stages: %llu separated, %llu interval, %llu integer, %llu exact\n",
              static_cast<unsigned long long>(stages.separating_direction),
              static_cast<unsigned long long>(stages.interval), static_cast<unsigned long long>(stages.integer),
              static_cast<unsigned long long>(stages.exact));
}

TEST(MinSeparation, DefaultParamsGiveTheContactAnswers) {
  for (const auto& q : testing::degenerate_queries<VertexFaceQuery>(31, 300))
    EXPECT_EQ(show(vertex_face_toi(q, CcdParams{})), show(vertex_face_toi(q)));
  for (const auto& q : testing::degenerate_queries<EdgeEdgeQuery>(32, 300))
    EXPECT_EQ(show(edge_edge_toi(q, CcdParams{})), show(edge_edge_toi(q)));
}

TEST(MinSeparation, BadQuestionsAreRefused) {
  const PointPointQuery q{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const CcdParams p : {CcdParams{-1e-300, 1}, CcdParams{nan, 1}, CcdParams{inf, 1}, CcdParams{0, 0},
                            CcdParams{0, -0.5}, CcdParams{0, std::nextafter(1.0, 2.0)}, CcdParams{0, nan}}) {
    EXPECT_THROW(point_point_ccd(q, p), std::invalid_argument);
    EXPECT_THROW(point_point_toi(q, p, Method::exact), std::invalid_argument);
  }
  EXPECT_THROW(point_point_ccd(q, {}, static_cast<Method>(7)), std::invalid_argument);  // no such method
  PointEdge2dQuery bad{};
  bad.b_t1.y = nan;
  EXPECT_THROW(point_edge_2d_toi(bad), std::invalid_argument);
}

}  // namespace
}  // namespace exactccd
