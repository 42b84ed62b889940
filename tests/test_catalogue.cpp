// The hand-derived degenerate catalogue (fuzz/catalogue.cpp): every method that claims
// exactness, through the rational and the double API, gives the derived answer and TOI.
#include "fuzz/catalogue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "exactccd/exactccd.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::catalogue {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

// Short test descriptions (gtest prints parameters in test lists; the coordinates are
// printed on failure by describe()).
template <class Query>
void PrintTo(const Entry<Query>& e, std::ostream* os) {
  *os << e.name;
}

template <class Query>
std::string describe(const Entry<Query>& e) {
  std::string s = e.name + " (" + e.category + "):";
  for (const auto& p : rows(e.query)) s += " [" + p.x.get_str() + " " + p.y.get_str() + " " + p.z.get_str() + "]";
  return s;
}

namespace {

template <class Query>
auto to_doubles(const Query& q) {
  const auto rows_d = io::exact_double_rows(rows(q));
  EXPECT_TRUE(rows_d.has_value()) << "a coordinate is not exactly a double";
  using DoubleQuery = std::conditional_t<std::is_same_v<Query, RationalVertexFaceQuery>,
                                         VertexFaceQuery, EdgeEdgeQuery>;
  return from_rows<DoubleQuery>(rows_d.value_or(std::array<Vec3, 8>{}));
}

/// Every zero coordinate replaced by -0.0: the same geometry, so the same answers.
template <class Query>
Query with_negative_zeros(Query q) {
  std::array<Vec3, 8> r = rows(q);
  for (Vec3& p : r)
    for (double* x : {&p.x, &p.y, &p.z})
      if (*x == 0) *x = -0.0;
  return from_rows<Query>(r);
}

mpq_class evaluate(const std::vector<mpq_class>& c, double t) {
  mpq_class v = 0, x(t), power = 1;
  for (const mpq_class& k : c) {
    v += k * power;
    power *= x;
  }
  return v;
}

template <class E>
void check_toi(const E& e, const std::optional<TimeInterval>& toi, const char* how) {
  SCOPED_TRACE(how);
  ASSERT_EQ(toi.has_value(), e.collides);
  if (!toi) return;
  ASSERT_LE(toi->lo, toi->hi);
  const bool point = toi->lo == toi->hi;
  if (!point) {
    EXPECT_EQ(std::nextafter(toi->lo, kInf), toi->hi) << "not the tightest interval";
  }
  if (e.toi) {
    const mpq_class& t = *e.toi;
    EXPECT_LE(mpq_class(toi->lo), t);
    EXPECT_GE(mpq_class(toi->hi), t);
    const bool t_is_double = io::exact_double(t).has_value();
    EXPECT_EQ(point, t_is_double) << "[" << toi->lo << ", " << toi->hi << "] for " << t.get_str();
  }
  if (!e.toi_polynomial.empty()) {  // irrational: the polynomial changes sign on (lo, hi)
    EXPECT_FALSE(point);
    const int s_lo = sgn(evaluate(e.toi_polynomial, toi->lo));
    const int s_hi = sgn(evaluate(e.toi_polynomial, toi->hi));
    EXPECT_NE(s_lo, 0);
    EXPECT_EQ(s_lo, -s_hi) << "the TOI root is not inside [" << toi->lo << ", " << toi->hi << "]";
  }
}

class VertexFaceCatalogue : public ::testing::TestWithParam<VertexFaceEntry> {};
class EdgeEdgeCatalogue : public ::testing::TestWithParam<EdgeEdgeEntry> {};

TEST_P(VertexFaceCatalogue, EveryExactMethodGivesTheDerivedAnswer) {
  const VertexFaceEntry& e = GetParam();
  SCOPED_TRACE(describe(e));
  EXPECT_EQ(vertex_face_ccd(e.query), e.collides) << "rational API";
  check_toi(e, vertex_face_toi(e.query), "rational toi");
  const VertexFaceQuery q = to_doubles(e.query);
  for (const VertexFaceQuery& v : {q, with_negative_zeros(q)})
    for (Method m : {Method::filtered, Method::exact}) {
      EXPECT_EQ(vertex_face_ccd(v, m), e.collides) << "method " << static_cast<int>(m);
      check_toi(e, vertex_face_toi(v, m), m == Method::filtered ? "filtered toi" : "exact toi");
    }
}

TEST_P(EdgeEdgeCatalogue, EveryExactMethodGivesTheDerivedAnswer) {
  const EdgeEdgeEntry& e = GetParam();
  SCOPED_TRACE(describe(e));
  EXPECT_EQ(edge_edge_ccd(e.query), e.collides) << "rational API";
  check_toi(e, edge_edge_toi(e.query), "rational toi");
  const EdgeEdgeQuery q = to_doubles(e.query);
  for (const EdgeEdgeQuery& v : {q, with_negative_zeros(q)})
    for (Method m : {Method::filtered, Method::exact}) {
      EXPECT_EQ(edge_edge_ccd(v, m), e.collides) << "method " << static_cast<int>(m);
      check_toi(e, edge_edge_toi(v, m), m == Method::filtered ? "filtered toi" : "exact toi");
    }
}

template <class E>
std::string entry_name(const ::testing::TestParamInfo<E>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, VertexFaceCatalogue, ::testing::ValuesIn(vertex_face_cases()),
                         entry_name<VertexFaceEntry>);
INSTANTIATE_TEST_SUITE_P(Catalogue, EdgeEdgeCatalogue, ::testing::ValuesIn(edge_edge_cases()),
                         entry_name<EdgeEdgeEntry>);

TEST(CatalogueContents, HasFortyHandMadeCasesWithUniqueNamesCoveringEveryCategory) {
  const auto vf = vertex_face_base_cases();
  const auto ee = edge_edge_base_cases();
  EXPECT_GE(vf.size() + ee.size(), 40u);
  std::set<std::string> names, categories;
  for (const auto& e : vertex_face_cases()) {
    EXPECT_TRUE(names.insert(e.name).second) << "duplicate " << e.name;
    categories.insert("vf:" + e.category);
  }
  for (const auto& e : edge_edge_cases()) {
    EXPECT_TRUE(names.insert(e.name).second) << "duplicate " << e.name;
    categories.insert("ee:" + e.category);
  }
  for (const char* c :
       {"vf:vertex_through_vertex", "vf:vertex_through_edge", "vf:vertex_through_interior",
        "vf:grazing", "vf:coplanar_sliding", "vf:degenerate_triangle", "vf:contact_at_t0",
        "vf:contact_at_t1", "vf:static", "vf:subnormal", "vf:huge_coordinates", "vf:large_offset",
        "vf:irrational_root", "ee:crossing", "ee:parallel", "ee:collinear", "ee:zero_length_edge",
        "ee:grazing", "ee:coplanar_sliding", "ee:contact_at_t0", "ee:contact_at_t1", "ee:static",
        "ee:edge_through_endpoint", "ee:subnormal", "ee:huge_coordinates", "ee:large_offset",
        "ee:irrational_root"})
    EXPECT_TRUE(categories.count(c)) << "no case of category " << c;
  std::size_t positives = 0, negatives = 0;
  for (const auto& e : vf) (e.collides ? positives : negatives)++;
  for (const auto& e : ee) (e.collides ? positives : negatives)++;
  EXPECT_GE(positives, 10u);
  EXPECT_GE(negatives, 10u);
}

}  // namespace
}  // namespace exactccd::catalogue
